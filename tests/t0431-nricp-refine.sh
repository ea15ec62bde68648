#!/bin/sh
test_description='nricp --refine: the kept key refined on every sample mesh-metrics measures, no face newly flipped'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/estop-lib.sh"

test_expect_success 'setup: a source and a pose remeshed finer' '
	egg_spheres && egg_pair 0.9
'
# the refinement is kept only where the Hausdorff distance drops, with no
# more flipped faces; --unflip 0 in both runs: its last repair refits the
# farthest place after the refinement, or without it (nricp(1) --unflip:
# here 1.81% and 1.68% of the diagonal), so the refinement is measured alone
O="$NRICP_ONE --unflip 0"
test_expect_success 'refined: closer by the Hausdorff distance, no more flipped faces' '
	nricp -v $O src.mesh g.mesh >r.mesh 2>err && cat err &&
	grep "refined: Hausdorff" err &&
	nricp $O --refine 0 src.mesh g.mesh >o.mesh &&
	mesh-metrics --no-header -r g.mesh r.mesh >mr.txt && cat mr.txt &&
	mesh-metrics --no-header -r g.mesh o.mesh >mo.txt && cat mo.txt &&
	test_le "$(awk "{ print \$5 }" mr.txt)" "$(awk "{ print \$5 }" mo.txt)" &&
	test_le "$(awk "{ print \$3 }" mr.txt)" "$(awk "{ print 0.8 * \$3 }" mo.txt)"
'
test_expect_success 'the same bytes twice; --refine 0 writes no refinement line' '
	nricp $O src.mesh g.mesh >r2.mesh && cmp r.mesh r2.mesh &&
	nricp -v $O --refine 0 src.mesh g.mesh >o2.mesh 2>err0 && cmp o.mesh o2.mesh &&
	! grep refined err0
'
test_expect_success 'usage: --refine out of range or not a number' '
	test_must_fail_usage nricp --refine -1 src.mesh g.mesh &&
	test_must_fail_usage nricp --refine 1001 src.mesh g.mesh &&
	test_must_fail_usage nricp --refine x src.mesh g.mesh
'
test_done
