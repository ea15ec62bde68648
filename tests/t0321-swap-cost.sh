#!/bin/sh
test_description='--swap-cost in label-expand and dict-learn: fewer swaps on set, exact chain DP, swaps against error'
. "$(dirname "$0")/test-lib.sh"

# swaps inside clips of a label file, the clips starting at frames 0 and 30
count_swaps() { awk 'NR > 1 && NR != 31 && $1 != last { s++ } { last = $1 } END { print s + 0 }' "$1"; }
key() { awk -v k="$1" '$1 == k { print $2 }' "$2"; }

test_expect_success 'setup: two clips of a waving grid, a uniform library' '
	mesh-gen -f 60 -a wave -n 6 --cut-every 30 grid >anim.mesh &&
	mesh-info anim.mesh | grep "^clips 2$" &&
	lib-uniform -d 6 anim.mesh >u.lib
'
test_expect_success 'label-expand --swap-cost 0 gives the same labels and energy bit for bit' '
	label-expand -q --report r u.lib anim.mesh >l &&
	label-expand -q --swap-cost 0 --report r0 u.lib anim.mesh >l0 &&
	cmp l l0 && test "$(key energy r)" = "$(key energy r0)" &&
	test "$(key swaps r0)" = "$(count_swaps l0)"
'
test_expect_success 'a larger swap cost gives fewer swaps, at a higher Eq. 10 energy' '
	label-expand -q --swap-cost 1 --report r1 u.lib anim.mesh >l1 &&
	label-expand -q --swap-cost 100 -l 0 --report r100 u.lib anim.mesh >l100 &&
	test "$(key swaps r1)" = "$(count_swaps l1)" &&
	test "$(key swaps r1)" -lt "$(key swaps r0)" &&
	test_le "$(key energy r0)" "$(key energy r1)" &&
	test "$(key swaps r100)" = 0 && test "$(count_swaps l100)" = 0
'
test_expect_success 'the DP is exact with the swap term: expansion and swap moves never lower' '
	for m in expansion swap; do
		label-expand -q -m $m --swap-cost 0.1 --report rm u.lib anim.mesh >lm &&
		label-expand -q --swap-cost 0.1 --report rd u.lib anim.mesh >ld &&
		test_le "$(key energy_with_swaps rd)" "$(key energy_with_swaps rm)" || return 1
	done
'
test_expect_success 'label-expand --swap-sweep: one line per cost, swaps never rise, rows equal single runs' '
	label-expand --swap-sweep 0,0.01,0.1,1,10 u.lib anim.mesh >sweep &&
	test "$(grep -vc "^#" sweep)" = 5 &&
	awk "!/^#/ { if (n++ && \$2 > last) exit 1; last = \$2 }" sweep &&
	test "$(awk "\$1 == 1 { print \$2 }" sweep)" = "$(key swaps r1)" &&
	test "$(awk "\$1 == 0 { print \$3 }" sweep)" = "$(key energy r0)" &&
	test "$(awk "\$1 == 10 { print \$2 }" sweep)" -lt "$(awk "\$1 == 0 { print \$2 }" sweep)"
'
test_expect_success 'dict-learn --swap-cost 0 writes the same library and labels' '
	dict-learn -d 6 --seed 3 --labels-out dl --report dr anim.mesh >d.lib &&
	dict-learn -d 6 --seed 3 --swap-cost 0 --labels-out dl0 anim.mesh >d0.lib &&
	cmp d.lib d0.lib && cmp dl dl0 && test "$(key swaps dr)" = "$(count_swaps dl)"
'
test_expect_success 'dict-learn --swap-cost relabels its library: fewer swaps, counted in the report' '
	dict-learn -d 6 --seed 3 --swap-cost 1 --labels-out dl1 --report dr1 anim.mesh >d1.lib &&
	cmp d.lib d1.lib &&
	test "$(key swaps dr1)" = "$(count_swaps dl1)" &&
	test "$(key swaps dr1)" -lt "$(key swaps dr)" &&
	label-expand -q --swap-cost 1 --report rx d1.lib anim.mesh >lx && cmp dl1 lx
'
test_expect_success 'dict-learn --swap-sweep prints swaps against error; -v counts swaps on stderr' '
	dict-learn -d 6 --seed 3 --swap-sweep 0,1,10 anim.mesh >ds &&
	test "$(awk "\$1 == 0 { print \$3 }" ds)" = "$(key energy dr)" &&
	awk "!/^#/ { if (n++ && \$2 > last) exit 1; last = \$2 }" ds &&
	dict-learn -v -d 6 --seed 3 anim.mesh 2>err >/dev/null &&
	grep "$(key swaps dr) swaps on set inside 2 clips" err
'
test_expect_success 'bad swap costs are refused' '
	for c in -1 nan inf abc ""; do
		test_must_fail_usage label-expand --swap-cost "$c" u.lib anim.mesh &&
		test_must_fail_usage dict-learn -d 3 --swap-cost "$c" anim.mesh || return 1
	done &&
	test_must_fail_usage label-expand --swap-sweep 0,-1 u.lib anim.mesh &&
	test_must_fail_usage label-expand --swap-sweep 0,,1 u.lib anim.mesh &&
	test_must_fail_usage dict-learn --swap-sweep 1,nan anim.mesh &&
	test_must_fail_usage dict-learn --swap-cost 1 --sweep 2:4 anim.mesh &&
	test_must_fail_usage dict-learn --swap-cost 1 --max-error 0.1 anim.mesh &&
	test_must_fail_usage label-expand --swap-cost 1 --swap-sweep 1 u.lib anim.mesh &&
	test_fails_cleanly dict-learn -d 3 --stream on --swap-cost 1 anim.mesh
'
test_done
