#!/bin/sh
test_description='nricp --passes 2 on the camel scans: two keys apart below 1% of the diagonal'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/estop-lib.sh"
need_shared_data scans/camel-gallop-05.off

test_expect_success 'setup: camel scans 03 and 05' '
	camel_scans 03 05
'
# measured (shared machine): one pass 1.00% of the diagonal, 13 flipped
# faces; the second pass 0.73%, 5 flipped
test_expect_success 'camel 03 -> 05 (two keys apart): below 1% with at most 10 flipped faces' '
	nricp -v --passes 2 c03.mesh c05.mesh >r.mesh 2>err35 &&
	grep "kept the second pass" err35 &&
	mesh-metrics --no-header -r c05.mesh r.mesh >m.txt && cat m.txt &&
	test_le "$(awk "{ print \$3 }" m.txt)" 0.01 &&
	test_le "$(awk "{ print \$5 }" m.txt)" 10
'
test_done
