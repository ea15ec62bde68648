#!/bin/sh
test_description='compat-tri --layers on traced frames: the shared elephant walk seen from the left, its left arm drawn over the body as a layer of its own'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"
need_shared_data anim/elephant-walk-457.tar.xz

# measured (2026-11-29, two threads): frames 0000 0210 0350, no rows:
# each layer meshed on its own 20.20 deg, 209 vertices, 0.35 s wall; the
# two rings meshed jointly (--layers=joint) 18.87 deg, 313 vertices
FRAMES="0000 0210 0350"
test_expect_success 'setup: three frames, the body without its left arm and the arm, each traced' '
	elephant_walk_frames $FRAMES &&
	elephant_arm_layers $FRAMES &&
	test $(grep -c . arm.labels) = 12064 &&
	test $(grep -c "^1" arm.labels) -gt 500 &&
	for k in $FRAMES; do test $(grep -c ^ring lay$k.rings) = 2 || return 1; done
'
test_expect_success 'the arm crosses the body outline: without --layers the rings are refused' '
	test_must_fail compat-tri lay0000.rings lay0210.rings lay0350.rings >out 2>err &&
	! test -s out &&
	grep "two rings cross" err
'
test_expect_success '--layers without rows: every triangle positive, 20 degrees in every frame' '
	compat-tri -v --layers lay0000.rings lay0210.rings lay0350.rings >m.mesh 2>log &&
	grep "^compat-tri: layer 2 of 2 (ring 2 of every file): 0 correspondence rows;" log &&
	test_le 1e-12 $(min_area m.mesh) &&
	test_le 20 $(worst_angle m.mesh)
'
test_expect_success 'the arm is written after the body, and a 0 -> 2 -> 0 morph inverts nothing' '
	face_layers m.mesh >layers &&
	test "$(grep -v vertex0 layers | uniq | tr "\n" " ")" = "0 1 " &&
	grep -x "vertex0 0" layers &&
	printf "1 0 0\n0.5 0 0.5\n0 0 1\n0.5 0 0.5\n1 0 0\n" >w &&
	arap-morph -v m.mesh w >morph.mesh 2>mlog &&
	grep "arap-morph: inverted triangles: 0 in 0 of 5 frames" mlog
'
test_done
