#!/bin/sh
test_description='dict-learn: replacement library, labels, size selection, bad input'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'setup: a waving grid with two clips' '
	mesh-gen -f 80 -a wave -n 8 --cut-every 40 grid >anim.mesh
'
test_expect_success 'library has d frames, labels one per frame in [0, d)' '
	dict-learn -d 6 --labels-out lab --report rep anim.mesh >lib.mesh &&
	grep "^frames 6$" lib.mesh &&
	test $(wc -l <lab) -eq 80 &&
	awk "\$1 < 0 || \$1 > 5 || \$1 != int(\$1) { exit 1 }" lab &&
	grep "^pieces 6$" rep && grep "^clips 2$" rep
'
test_expect_success 'same --seed gives the same bytes, another seed may differ' '
	dict-learn -d 6 --seed 7 --labels-out lab1 anim.mesh >lib1.mesh &&
	dict-learn -d 6 --seed 7 --labels-out lab2 anim.mesh >lib2.mesh &&
	test_cmp lib1.mesh lib2.mesh && test_cmp lab1 lab2 &&
	dict-learn -d 6 --seed 7 -r 5 --threads 1 anim.mesh >t1.mesh &&
	dict-learn -d 6 --seed 7 -r 5 --threads 3 anim.mesh >t3.mesh &&
	test_cmp t1.mesh t3.mesh && test_cmp lib1.mesh t1.mesh
'
test_expect_success 'lambda = 0 matches a reference Lloyd loop (awk) from the same start' '
	awk "BEGIN { for (f = 0; f < 80; f++) print int(f * 4 / 80) }" >init &&
	dict-learn -d 4 --lambda 0 -r 1 --search 0 --init-labels init --report rep0 --labels-out l0 anim.mesh >/dev/null &&
	awk -v d=4 -f "$TEST_DIRECTORY/lloyd.awk" anim.mesh init >lloyd.out &&
	E=$(awk "/^energy /{print \$2}" rep0) && R=$(awk "/^energy /{print \$2}" lloyd.out) &&
	echo "dict-learn $E lloyd $R" &&
	test_near "$E" "$R" "$(awk -v r="$R" "BEGIN{print 1e-8 * r}")" &&
	grep -v "^energy" lloyd.out >lloyd.lab && test_cmp lloyd.lab l0
'
test_expect_success 'lambda > 0 lowers the velocity error of lambda = 0' '
	dict-learn -d 5 --lambda 0 --report r0 anim.mesh >/dev/null &&
	dict-learn -d 5 --lambda 4 --report r4 anim.mesh >/dev/null &&
	v0=$(awk "/^velocity /{print \$2}" r0) && v4=$(awk "/^velocity /{print \$2}" r4) &&
	echo "velocity lambda0 $v0 lambda4 $v4" && test_le "$v4" "$v0"
'
test_expect_success 'energy never increases across iterations (-vv log), DP and expansion (plain descent, --search 0)' '
	dict-learn -vv -d 6 -r 3 --search 0 anim.mesh 2>log >/dev/null &&
	dict-learn -vv -d 6 -r 3 --search 0 -m expansion anim.mesh 2>>log >/dev/null &&
	grep -c "iteration" log &&
	awk "\$2 == \"restart\" && \$4 == \"iteration\" { r = \$3; e = \$7; if (\$5 != \"0:\" && r == pr && e > pe * (1 + 1e-10)) { print \"rise\", \$0; bad = 1 } pr = r; pe = e }
	     END { exit bad }" log
'
test_expect_success 'expansion and swap label steps run and report energies' '
	dict-learn -d 5 -m expansion --report re anim.mesh >/dev/null &&
	dict-learn -d 5 -m swap --report rs anim.mesh >/dev/null &&
	grep "^energy " re && grep "^energy " rs
'
test_expect_success 'Gram and direct back ends agree from the same start' '
	dict-learn -d 5 -r 1 --init-labels init --gram on --report rg anim.mesh >lg.mesh &&
	dict-learn -d 5 -r 1 --init-labels init --gram off --report rd anim.mesh >ld.mesh &&
	a=$(awk "/^energy /{print \$2}" rg) && b=$(awk "/^energy /{print \$2}" rd) &&
	test_near "$a" "$b" "$(awk -v r="$a" "BEGIN{print 1e-8 * r}")"
'
test_expect_success 'single precision Gram finds (nearly) the same energy' '
	dict-learn -d 5 -r 1 --init-labels init --gram single --report rsg anim.mesh >lsg.mesh &&
	a=$(awk "/^energy /{print \$2}" rg) && b=$(awk "/^energy /{print \$2}" rsg) &&
	test_near "$a" "$b" "$(awk -v r="$a" "BEGIN{print 1e-4 * r}")"
'
test_expect_success 'd = frames reproduces every frame' '
	dict-learn -d 80 -r 1 --report rn anim.mesh >/dev/null &&
	test_le "$(awk "/^max_error /{print \$2}" rn)" 1e-9
'
test_expect_success 'sweep prints d energy mean_err max_err, error falls with d' '
	dict-learn --sweep 2:10:4 -r 2 anim.mesh >sweep &&
	test $(grep -vc "^#" sweep) -eq 3 &&
	e2=$(awk "\$1 == 2 {print \$2}" sweep) && e10=$(awk "\$1 == 10 {print \$2}" sweep) &&
	test_le "$e10" "$e2"
'
test_expect_success '--max-error picks a library meeting the bound' '
	dict-learn --sweep 4:4 anim.mesh >s4 &&
	E=$(awk "\$1 == 4 {print \$4}" s4) &&
	dict-learn --max-error "$E" --report rm anim.mesh >lm.mesh &&
	test_le "$(awk "/^max_error /{print \$2}" rm)" "$E" &&
	test_le "$(awk "/^pieces /{print \$2}" rm)" 12
'
test_expect_success 'fixed pieces stay first and unchanged' '
	dict-learn -d 3 anim.mesh >old.mesh &&
	dict-learn -d 5 --fixed old.mesh anim.mesh >new.mesh &&
	sed -n "/^frame 0/,/^frame 3/p" old.mesh | grep -v "^frame" >a &&
	sed -n "/^frame 0/,/^frame 3/p" new.mesh | grep -v "^frame" >b &&
	test_cmp a b
'
test_expect_success 'saliency weights are accepted' '
	awk "BEGIN { for (i = 0; i < 81; i++) print (i < 40 ? 1 : 5) }" >w &&
	dict-learn -d 4 -w w --report rw anim.mesh >/dev/null && grep "^energy" rw
'
test_expect_success 'bad input: d < 1, d > frames, weight count, NaN, bad labels' '
	test_fails_cleanly dict-learn -d 0 anim.mesh &&
	test_fails_cleanly dict-learn -d 81 anim.mesh &&
	head -5 w >w5 && test_fails_cleanly dict-learn -d 3 -w w5 anim.mesh &&
	sed "/^frame 3/{n;s/.*/nan 0 0/}" anim.mesh >nan.mesh &&
	test_fails_cleanly dict-learn -d 3 nan.mesh &&
	awk "BEGIN { for (i = 0; i < 81; i++) print (i ? 1 : -1) }" >wneg &&
	test_fails_cleanly dict-learn -d 3 -w wneg anim.mesh &&
	echo 9 >badinit && test_fails_cleanly dict-learn -d 3 --init-labels badinit anim.mesh &&
	head -20 anim.mesh >trunc.mesh && test_fails_cleanly dict-learn -d 3 trunc.mesh
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage dict-learn --lambda -1 anim.mesh &&
	test_must_fail_usage dict-learn --method nope anim.mesh &&
	test_must_fail_usage dict-learn --sweep 5:2 anim.mesh
'
test_done
