#!/bin/sh
test_description='nricp --untangle on the camel gallop scans: fewer flipped faces, same distance'
. "$(dirname "$0")/test-lib.sh"
need_shared_data scans/camel-gallop-02.off

EX="$STOPMO_ROOT/examples/clay"
test_expect_success 'setup: import the scans' '
	mesh-import "$SHARED_DATA/scans/camel-gallop-01.off" >c1.mesh &&
	mesh-import "$SHARED_DATA/scans/camel-gallop-02.off" >c2.mesh
'
# measured: --untangle 0: 0.877%, 20 flipped faces; default: 0.847%, 14
test_expect_success 'camel 01 -> 02: untangling leaves at most 15 flipped faces, Hausdorff below 1%' '
	nricp --init-deform -l "$EX/landmarks-01-02.txt" c1.mesh c2.mesh >r.mesh &&
	mesh-metrics --no-header -r c2.mesh r.mesh >m.txt && cat m.txt &&
	test_le "$(awk "{ print \$3 }" m.txt)" 0.01 &&
	test_le "$(awk "{ print \$5 }" m.txt)" 15
'
test_expect_success 'without untangling there are more flipped faces' '
	nricp --untangle 0 --init-deform -l "$EX/landmarks-01-02.txt" c1.mesh c2.mesh >r0.mesh &&
	mesh-metrics --no-header -r c2.mesh r0.mesh >m0.txt && cat m0.txt &&
	test_le "$(awk "{ print \$5 + 1 }" m.txt)" "$(awk "{ print \$5 }" m0.txt)"
'
test_done
