#!/bin/sh
test_description='integer options are range-checked (no silent wrap),
mesh-render --frame from the end in memory O(frames read), extreme extents
in mesh-info and mesh-normalize, dict-learn names a worker thread error'
. "$(dirname "$0")/test-lib.sh"

scale() {
	awk -v s="$1" "/^[-0-9]/ && NF == 3 { printf \"%.17g %.17g %.17g\n\", \$1 * s, \$2 * s, \$3 * s; next } { print }"
}

test_expect_success 'setup' '
	mesh-gen -s 1 icosphere >ico.mesh &&
	mesh-gen -f 3 -n 4 cylinder >cyl.mesh
'
test_expect_success 'integer options out of the range of int are usage errors, not wrapped' '
	test_must_fail_usage mesh-gen -n 4294967298 grid 2>err && grep "out of range" err &&
	test_must_fail_usage seam-homog --batch 4294967304 -l x cyl.mesh 2>err && grep "out of range" err &&
	test_must_fail_usage dict-learn -d 4294967298 cyl.mesh 2>err && grep "out of range" err &&
	test_must_fail_usage mesh-gen -n 99999999999999999999 grid 2>err && grep "out of range" err &&
	test_must_fail_usage mesh-gen -n 12x grid 2>err && grep "not an integer" err
'
test_expect_success 'mesh-render --frame: INT_MIN is a usage error (was a negation overflow)' '
	anim-slice cyl.mesh | sed "4s/frames 3/frames ?/" >q.mesh && grep "^frames ?$" q.mesh &&
	test_must_fail_usage mesh-render --frame -2147483648 q.mesh 2>err && grep "out of range" err
'
test_expect_success 'mesh-render --frame -200000000 keeps only the frames it read' '
	test_memlimit test_fails_cleanly mesh-render --frame -200000000 q.mesh 2>err &&
	grep "no frame -200000000 (the stream has 3 frames)" err &&
	mesh-render --frame -1 -o last.ppm q.mesh && mesh-render --frame 2 -o two.ppm cyl.mesh &&
	test_cmp last.ppm two.ppm
'
test_expect_success 'mesh-info: extents near 1e308 and 1e-300 give finite, nonzero figures' '
	scale 1e308 <ico.mesh >huge.mesh && mesh-info huge.mesh >info &&
	grep "^diagonal 3.46410161513775[0-9]*e+308$" info &&
	grep "^area [0-9.]*e+617$" info && ! grep -i "nan\|inf" info &&
	scale 1e-300 <ico.mesh >tiny.mesh && mesh-info tiny.mesh >info &&
	grep "^diagonal 3.46410161513775[0-9]*e-300$" info &&
	grep "^area [0-9.]*e-599$" info && grep "^volume [0-9.]*e-900$" info
'
test_expect_success 'mesh-info: ordinary figures are unchanged (double arithmetic)' '
	mesh-info ico.mesh >info && grep "^diagonal 3.4641016151377" info &&
	grep "^area 11.66593139171830" info
'
test_expect_success 'mesh-normalize refuses an extent whose scale it cannot undo' '
	test_fails_cleanly mesh-normalize huge.mesh 2>err &&
	grep "extent 2e+308 cannot be scaled to 1 in double precision" err &&
	scale 1e-310 <ico.mesh >sub.mesh &&
	test_fails_cleanly mesh-normalize sub.mesh 2>err && grep "cannot be scaled" err
'
test_expect_success 'mesh-normalize: 1e-300 extents normalize and undo' '
	mesh-normalize -t xf tiny.mesh >unit.mesh && mesh-info unit.mesh | grep "^diagonal 1.73" &&
	mesh-normalize --undo xf unit.mesh >back.mesh &&
	anim-diff -s tiny.mesh back.mesh >d && cat d
'
test_expect_success 'mesh-normalize: a transform that overflows an output coordinate is refused' '
	printf "scale 1e308 translate 0 0 0\n" >xf2 && scale 10 <ico.mesh >ten.mesh &&
	test_must_fail mesh-normalize --apply xf2 -o o.mesh ten.mesh 2>err && grep "overflows" err && ! test -e o.mesh
'
test_expect_success 'dict-learn: the worker thread says what went wrong' '
	mesh-gen -f 6 -n 4 cylinder | scale 1e300 >big.mesh &&
	test_fails_cleanly dict-learn -d 2 big.mesh 2>err &&
	grep "energy is not a number" err &&
	test_fails_cleanly dict-learn --threads 2 -r 2 -d 2 big.mesh 2>err &&
	grep "energy is not a number" err
'
test_done
