#!/bin/sh
test_description='nricp --coarse: the stiff steps on a coarser remeshing of SOURCE; --rigid-const'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/estop-lib.sh"

test_expect_success 'setup: a source, a pose remeshed finer, the pose in the source connectivity (truth)' '
	egg_spheres &&
	nosed_egg s3.mesh 0 >src.mesh && nosed_egg s4.mesh 0.6 >g.mesh && nosed_egg s3.mesh 0.6 >truth.mesh &&
	echo "543 0.16886181253629701 0 0.62540417412539229" >nose.txt
'
truth_err() {
	anim-diff -s truth.mesh "$1" | awk "/^mean/ { print \$2 }"
}
test_expect_success '--coarse 0 is the single level: the same bytes as without' '
	nricp --no-auto -k 4 --fit 6 src.mesh g.mesh >one.mesh &&
	nricp --no-auto -k 4 --fit 6 --coarse 0 src.mesh g.mesh >zero.mesh &&
	cmp one.mesh zero.mesh
'
# measured: 131 coarse vertices; Hausdorff 0.0436 against 0.0445 on one level
test_expect_success '--coarse: the stiff steps on a coarse level, as close to the target as one level' '
	nricp -v --no-auto -k 4 --fit 6 --coarse 0.08 src.mesh g.mesh >c.mesh 2>err && cat err &&
	n=$(sed -n "s/.*coarse level: \([0-9]*\) vertices.*/\1/p" err | head -n 1) && test "$n" -gt 20 && test "$n" -lt 642 &&
	grep "the last 2 steps on the source" err &&
	mesh-metrics --no-header -r g.mesh one.mesh >m1.txt && mesh-metrics --no-header -r g.mesh c.mesh >mc.txt &&
	cat m1.txt mc.txt &&
	test_le "$(awk "{ print \$2 }" mc.txt)" "$(awk "{ print 1.25 * \$2 }" m1.txt)" &&
	test "$(awk "{ print \$5 }" mc.txt)" -le 2 &&
	! cmp -s one.mesh c.mesh
'
# measured: 0.1071 from the truth with the coarse level, 0.1142 without
test_expect_success '--coarse with a landmark: carried to the coarse level, as near the truth' '
	nricp -l nose.txt -k 4 --fit 6 src.mesh g.mesh >l1.mesh &&
	nricp -l nose.txt -k 4 --fit 6 --coarse 0.08 src.mesh g.mesh >lc.mesh &&
	a=$(truth_err l1.mesh) && b=$(truth_err lc.mesh) && echo "truth: one level $a, coarse $b" &&
	test_le "$b" "$(awk "BEGIN { print 1.1 * $a }")"
'
test_expect_success '--coarse --steps-out: one frame per step, the coarse steps carried to SOURCE' '
	nricp --no-auto -k 4 --fit 6 --coarse 0.08 --steps-out st.mesh src.mesh g.mesh >c2.mesh &&
	cmp c.mesh c2.mesh &&
	test "$(mesh-info st.mesh | awk "/^frames/ { print \$2 }")" = 5 &&
	test "$(mesh-info st.mesh | awk "/^vertices/ { print \$2 }")" = 642
'
test_expect_success '--fine-steps: as many steps on SOURCE (0: the fit refines), at least one on the coarse level' '
	nricp -v --no-auto -k 4 --fit 6 --coarse 0.08 --fine-steps 3 src.mesh g.mesh >/dev/null 2>err3 &&
	grep "the last 3 steps on the source" err3 &&
	nricp -v --no-auto -k 4 --fit 6 --coarse 0.08 --fine-steps 0 src.mesh g.mesh >f0.mesh 2>err0 &&
	grep "the last 0 steps on the source" err0 &&
	mesh-metrics --no-header -r g.mesh f0.mesh >m0.txt && cat m0.txt &&
	test_le "$(awk "{ print \$3 }" m0.txt)" 0.03 &&
	nricp -v --no-auto -k 4 --fit 6 --coarse 0.08 --fine-steps 9 src.mesh g.mesh >/dev/null 2>err9 &&
	grep "the last 3 steps on the source" err9
'
test_expect_success '--rigid-const: nothing without --rigid; with it, not the fading term' '
	nricp --no-auto -k 4 --fit 6 --rigid-const src.mesh g.mesh >rc0.mesh &&
	cmp one.mesh rc0.mesh &&
	nricp --no-auto -k 4 --fit 6 --rigid 10 src.mesh g.mesh >rf.mesh &&
	nricp --no-auto -k 4 --fit 6 --rigid 10 --rigid-const src.mesh g.mesh >rc.mesh &&
	! cmp -s rf.mesh rc.mesh &&
	mesh-metrics --no-header -r g.mesh rc.mesh >mr.txt && cat mr.txt &&
	test_le "$(awk "{ print \$3 }" mr.txt)" 0.03
'
test_expect_success 'usage: --coarse in [0, 0.5], --fine-steps >= 0' '
	test_must_fail_usage nricp --coarse -0.1 src.mesh g.mesh &&
	test_must_fail_usage nricp --coarse 0.6 src.mesh g.mesh &&
	test_must_fail_usage nricp --coarse x src.mesh g.mesh &&
	test_must_fail_usage nricp --fine-steps -1 src.mesh g.mesh
'
test_done
