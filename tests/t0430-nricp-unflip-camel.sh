#!/bin/sh
test_description='nricp --unflip on the camel scans: the fetlock pleats laid flat'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/estop-lib.sh"
need_shared_data scans/camel-gallop-04.off

test_expect_success 'setup: clean camel scans 01, 03 and 04' '
	camel_scans 01 03 04
'
# measured (thin-shell start, one pass, as t0421): 0.92% of the diagonal
# with 8 flipped faces after the untangling (--unflip 0, the earlier
# bytes); unflipped 8 -> 1, 0.68%: laying the pleat flat also covers the
# crease it had bridged
test_expect_success 'camel 03 -> 04: fewer flipped faces, no farther' '
	nricp -v --refine 0 --passes 1 --fit-release stay --start shell c03.mesh c04.mesh >u34.mesh 2>err && cat err &&
	grep "unflipped: 8 -> [0-2] faces flipped against the target" err &&
	nricp --refine 0 --unflip 0 --passes 1 --fit-release stay --start shell c03.mesh c04.mesh >o34.mesh &&
	mesh-metrics --no-header -r c04.mesh u34.mesh >mu.txt && cat mu.txt &&
	mesh-metrics --no-header -r c04.mesh o34.mesh >mo.txt && cat mo.txt &&
	test_le "$(awk "{ print \$5 }" mu.txt)" 2 &&
	test_le 8 "$(awk "{ print \$5 }" mo.txt)" &&
	test_le "$(awk "{ print \$3 }" mu.txt)" "$(awk "{ printf \"%.12g\", \$3 + 1e-9 }" mo.txt)"
'
# the issue's goal for key poses three apart, with the default options:
# below 2% with at most 10 flipped faces (measured 1.17% with 3 at stop
# 33, 1.072% with none since the guarded projection and the last repair;
# 37 flipped before --unflip, the fetlock pleats); about 40 s of CPU
test_expect_success 'camel 01 -> 04 by default: below 2% with at most 10 flipped faces' '
	nricp c01.mesh c04.mesh >d14.mesh &&
	mesh-metrics --no-header -r c04.mesh d14.mesh >m14.txt && cat m14.txt &&
	test_le "$(awk "{ print \$3 }" m14.txt)" 0.02 &&
	test_le "$(awk "{ print \$5 }" m14.txt)" 10
'
# the issue's goal for key poses two apart: below 1% with no flipped face,
# by default (before --refine: 1.01% with 1 flipped face, a face standing
# off the target at a fetlock; measured with it 0.89% and none, since the
# guarded projection and the last repair 0.617% and none; t0435: the
# other kernels); about 20 s of CPU
test_expect_success 'camel 01 -> 03 by default: below 1% with no flipped face' '
	nricp c01.mesh c03.mesh >d13.mesh &&
	mesh-metrics --no-header -r c03.mesh d13.mesh >m13.txt && cat m13.txt &&
	test_le "$(awk "{ print \$3 }" m13.txt)" 0.0099 &&
	test "$(awk "{ print \$5 }" m13.txt)" = 0
'
test_done
