#!/bin/sh
test_description='nricp --chain on a cow walking a step (clay-deform poses, each key remeshed: true correspondence known): no build-up over the direct registration'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/estop-lib.sh"
need_shared_data meshes/cow.off

# the shared cow (2763 vertices, closed) pulled by clay-deform -m arap in 8
# steps: a front hoof forward and up, a hind hoof back, the snout down, the
# tail out, the other two hooves and the middle of the back held; keys are
# steps 2, 4, 6, 8, each remeshed by mesh-clean -R 0.015 (3992-4140
# vertices), their truth the step itself (SOURCE's connectivity)
test_expect_success 'setup: the source, four keys remeshed, their true places' '
	cow_walk &&
	for f in 2 4 6 8; do
		anim-slice -f $f steps.mesh >w$f.mesh &&
		mesh-clean -R 0.015 w$f.mesh >r$f.mesh 2>/dev/null || return 1
	done
'
# mean distance of each registered vertex to its true place, over the diagonal
truth_err() {
	d=$(mesh-info "$2" | awk "/^diagonal/ { print \$2 }")
	anim-diff -s "$2" "$1" | awk -v d="$d" "/^mean/ { print \$2 / d }"
}
# measured (shared machine): keys 0.491, 0.365, 0.542, 0.658% of the
# diagonal from the truth (SOURCE itself 1.457, 3.100, 4.688, 6.172%),
# Hausdorff 0.501, 0.408, 0.288, 0.364%, no flipped face, 42 s CPU; the
# direct registration 0 -> 8 0.624% from the truth (settled 0.700%): the
# last key 1.05 times it.  By the first key the last is 1.34 times: the
# poses move away from SOURCE (direct 0 -> 2 0.398%, 0 -> 8 0.624%), so
# the issue's yardstick is not met here either (nricp(1), --chain).
# OPENBLAS_CORETYPE=SandyBridge: 0.490, 0.450, 0.645, 0.691%, direct 0.625%
# (1.11 times); SkylakeX: 0.398, 0.365, 0.366, 0.427%, direct 0.624% (0.68)
test_expect_success 'every key near its truth, no flipped face, the last within 1.2 times the direct registration' '
	nricp --chain w0.mesh r2.mesh r4.mesh r6.mesh r8.mesh >keys.mesh &&
	for i in 1 2 3 4; do
		f=$((2 * i)) &&
		anim-slice -f $i keys.mesh >k$f.mesh &&
		e=$(truth_err k$f.mesh w$f.mesh) && echo "key $f: $e of the diagonal from the truth" &&
		test_le "$e" 0.01 &&
		mesh-metrics --no-header -r r$f.mesh k$f.mesh >m$f.txt && cat m$f.txt &&
		test_le "$(awk "{ print \$5 }" m$f.txt)" 0 || return 1
	done &&
	nricp w0.mesh r8.mesh >d8.mesh &&
	a=$(truth_err d8.mesh w8.mesh) && b=$(truth_err k8.mesh w8.mesh) &&
	echo "last key $b, direct $a of the diagonal from the truth" &&
	test_le "$b" "$(awk "BEGIN { print 1.2 * $a }")"
'
test_done
