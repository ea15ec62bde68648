#!/bin/sh
test_description='mesh-metrics --per-face, mesh-render --scalars --column: where a registration went wrong'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'setup: a sphere, a copy with one dent, a copy with three faces turned over' '
	mesh-gen -s 3 icosphere >sphere.mesh &&
	awk "/^frame/ { body = 1; print; next } body && NF == 3 { n++; s = (n == 11) ? 1.3 : 1; printf \"%.17g %.17g %.17g\n\", s * \$1, s * \$2, s * \$3; next } { print }" sphere.mesh >bump.mesh &&
	awk "/^f / && ++k <= 3 { print \"f\", \$2, \$4, \$3; next } { print }" sphere.mesh >turned.mesh
'
test_expect_success 'per-face rows: one per face, the far faces are the bumped vertex fan' '
	mesh-metrics -r sphere.mesh --per-face pf.txt bump.mesh >m.txt &&
	nf=$(awk "/^faces/ { print \$2 }" sphere.mesh) &&
	test "$(grep -vc "^#" pf.txt)" = "$nf" &&
	head -n 1 pf.txt | grep -q "^# frame face flipped distance distance_rel" &&
	h=$(awk "!/^#/ { print \$2 }" m.txt) &&
	far=$(awk -v h="$h" "!/^#/ && \$4 > 0.25 * h { n++ } END { print n + 0 }" pf.txt) &&
	test "$far" -ge 5 && test "$far" -le 6 &&
	mx=$(awk "!/^#/ && \$4 > m { m = \$4 } END { printf \"%.9g\", m }" pf.txt) &&
	test_near "$mx" "$h" 1e-9
'
test_expect_success 'per-face flipped flags name exactly the turned faces' '
	mesh-metrics --no-header -r sphere.mesh --per-face pt.txt turned.mesh >t.txt &&
	test "$(awk "{ print \$5 }" t.txt)" = 3 &&
	test "$(awk "\$3 == 1 { printf \"%s \", \$2 }" pt.txt)" = "0 1 2 "
'
test_expect_success 'an animation: one block of rows per frame, and the same numbers as without hints' '
	mesh-gen -f 4 -a wave grid >wave.mesh &&
	anim-slice -f 0 wave.mesh >w0.mesh &&
	mesh-metrics --no-header -r w0.mesh --per-face pw.txt wave.mesh >w.txt &&
	nf=$(awk "/^faces/ { print \$2 }" w0.mesh) &&
	test "$(wc -l <pw.txt)" = "$((4 * nf))" &&
	for k in 1 2 3; do
		anim-slice -f $k wave.mesh >wk.mesh &&
		mesh-metrics --no-header -r w0.mesh wk.mesh | cut -d" " -f2- >one.txt &&
		awk -v k=$k "\$1 == k" w.txt | cut -d" " -f2- >all.txt &&
		test_cmp one.txt all.txt || return 1
	done
'
test_expect_success 'mesh-render --scalars --column: the distance column, the frame block' '
	mesh-render -s 64x64 --scalars pf.txt --column 4 bump.mesh >d.png &&
	mesh-render -s 64x64 --scalars pw.txt --column 4 -k 2 wave.mesh >w2.png &&
	mesh-render -s 64x64 bump.mesh >plain.png &&
	! cmp -s d.png plain.png
'
test_expect_success 'bad uses fail cleanly' '
	test_fails_cleanly mesh-render -s 64x64 --scalars pf.txt --column 9 bump.mesh &&
	test_fails_cleanly mesh-render -s 64x64 --scalars pw.txt --column 4 -k 7 wave.mesh &&
	test_fails_cleanly mesh-render -s 64x64 --scalars pw.txt --column 4 sphere.mesh &&
	test_must_fail_usage mesh-render --column 2 bump.mesh &&
	test_must_fail_usage mesh-metrics -r sphere.mesh --per-face x.txt -o x.txt bump.mesh &&
	test_fails_cleanly mesh-metrics -r sphere.mesh --per-face nodir/x.txt bump.mesh &&
	! test -e x.txt
'
test_done
