#!/bin/sh
test_description='compat-tri --slide rerun (the default) leaves a mesh that reaches the goal in its first pass alone: the six shared elephant poses (corr6.txt) and poses 1 4 5 give the same bytes as --slide off; --slide all changes the elephant and still keeps the outline and the goal'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

need_shared_data shapes2d/poses/elephant-pose6.rings.txt
P="$SHARED_DATA/shapes2d/poses"
test_expect_success 'six elephant poses: the same bytes with --slide off, at the goal (20.02 deg measured)' '
	grep -v "^#" "$STOPMO_ROOT/examples/morph2d/corr6.txt" >c6 &&
	compat-tri -c c6 $P/elephant-pose1.rings.txt $P/elephant-pose2.rings.txt $P/elephant-pose3.rings.txt \
		$P/elephant-pose4.rings.txt $P/elephant-pose5.rings.txt $P/elephant-pose6.rings.txt >d.mesh &&
	compat-tri --slide off -c c6 $P/elephant-pose1.rings.txt $P/elephant-pose2.rings.txt $P/elephant-pose3.rings.txt \
		$P/elephant-pose4.rings.txt $P/elephant-pose5.rings.txt $P/elephant-pose6.rings.txt >off.mesh &&
	test_cmp off.mesh d.mesh &&
	test_le 20 $(worst_angle d.mesh)
'
test_expect_success 'poses 1 4 5: the same bytes with --slide off' '
	cut -d" " -f1,4,5 c6 >c145 &&
	compat-tri -c c145 $P/elephant-pose1.rings.txt $P/elephant-pose4.rings.txt $P/elephant-pose5.rings.txt >d145.mesh &&
	compat-tri --slide off -c c145 $P/elephant-pose1.rings.txt $P/elephant-pose4.rings.txt $P/elephant-pose5.rings.txt >o145.mesh &&
	test_cmp o145.mesh d145.mesh
'
test_expect_success '--slide all slides in the first pass too: other bytes, still at the goal and positive' '
	compat-tri --slide all -c c145 $P/elephant-pose1.rings.txt $P/elephant-pose4.rings.txt $P/elephant-pose5.rings.txt >a145.mesh &&
	! cmp -s a145.mesh d145.mesh &&
	test_le 1e-12 $(min_area a145.mesh) &&
	test_le 20 $(worst_angle a145.mesh)
'
test_done
