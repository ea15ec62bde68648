#!/bin/sh
test_description='nricp on the camel gallop scans (different connectivity)'
. "$(dirname "$0")/test-lib.sh"
need_shared_data scans/camel-gallop-02.off

EX="$STOPMO_ROOT/examples/clay"
test_expect_success 'setup: import the scans' '
	mesh-import "$SHARED_DATA/scans/camel-gallop-01.off" >c1.mesh &&
	mesh-import "$SHARED_DATA/scans/camel-gallop-02.off" >c2.mesh
'
test_expect_success 'camel 01 -> 02 with 14 landmarks: Hausdorff below 1% of the diagonal' '
	nricp -v --init-deform -l "$EX/landmarks-01-02.txt" c1.mesh c2.mesh >r.mesh 2>err &&
	cat err &&
	mesh-metrics --no-header -r c2.mesh r.mesh >m.txt &&
	h=$(awk "{ print \$3 }" m.txt) && echo "hausdorff_rel $h" && test_le "$h" 0.01
'
test_done
