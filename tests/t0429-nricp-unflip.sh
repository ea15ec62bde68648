#!/bin/sh
test_description='nricp --unflip: the patches left flipped against the target laid flat by a foldover-free solve'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/estop-lib.sh"

test_expect_success 'setup: a source and a pose remeshed finer' '
	egg_spheres && egg_pair 0.9
'
# the unflipping can only lower the flipped faces and cannot lengthen the
# Hausdorff distance, and where nothing is flipped it changes no byte
O=$NRICP_ONE
test_expect_success 'one registration: no more flipped faces, no farther; same bytes when none flipped' '
	nricp $O src.mesh g.mesh >u.mesh &&
	nricp $O --unflip 0 src.mesh g.mesh >o.mesh &&
	mesh-metrics --no-header -r g.mesh u.mesh >mu.txt && cat mu.txt &&
	mesh-metrics --no-header -r g.mesh o.mesh >mo.txt && cat mo.txt &&
	test_le "$(awk "{ print \$5 }" mu.txt)" "$(awk "{ print \$5 }" mo.txt)" &&
	test_le "$(awk "{ print \$3 }" mu.txt)" "$(awk "{ printf \"%.12g\", \$3 + 1e-9 }" mo.txt)" &&
	if test "$(awk "{ print \$5 }" mo.txt)" = 0; then cmp u.mesh o.mesh; fi
'
test_expect_success 'usage: --unflip out of range or not a number' '
	test_must_fail_usage nricp --unflip -1 src.mesh g.mesh &&
	test_must_fail_usage nricp --unflip 21 src.mesh g.mesh &&
	test_must_fail_usage nricp --unflip x src.mesh g.mesh
'
test_expect_success 'bad input: a truncated target fails cleanly with --unflip' '
	head -n 20 g.mesh >bad.mesh &&
	test_must_fail nricp --unflip 3 src.mesh bad.mesh >out.mesh &&
	test ! -s out.mesh
'
test_done
