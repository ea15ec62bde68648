#!/bin/sh
test_description='compat-tri on a traced character made from shared data, no given point: the shared cow walked by clay-deform (the poses of t0437), frames 0 6 8 rendered from the side and traced by img2rings (legs merged in one frame, apart in the others); the default reaches 20 deg where the race alone (--spread 0) stops below it'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"
. "$TEST_DIRECTORY/estop-lib.sh"
need_shared_data meshes/cow.off

test_expect_success 'setup: three frames of the walk, traced' '
	cow_walk &&
	for f in 0 6 8; do
		anim-slice -f $f steps.mesh | mesh-render -V front -s 300x300 -c 0,0,0 --flat -f ppm |
			img2rings -1 -s 1 >cow$f.rings || return 1
	done
'
# measured (compat-tri(1), MATCHING BETWEEN GIVEN ROWS, The spread
# candidate): 17.62 deg with --spread 0, 20.00 by default
test_expect_success 'the default reaches the goal through the spread candidate; --spread 0 does not' '
	compat-tri -v -o m.mesh cow0.rings cow6.rings cow8.rings 2>err &&
	compat-tri --spread 0 -o z.mesh cow0.rings cow6.rings cow8.rings &&
	w=$(worst_angle m.mesh) && w0=$(worst_angle z.mesh) && echo "worst $w deg, --spread 0 $w0" &&
	test_le 1e-12 $(min_area m.mesh) &&
	test_le 20 $w && ! test_le 20 $w0 2>/dev/null &&
	grep -q "kept the matching with 24 points and --spread 3: worst angle" err
'
test_expect_success 'every outline within the tolerance of its input' '
	test_le $(outline_error m.mesh cow0.rings 0) 0.005000001 &&
	test_le $(outline_error m.mesh cow6.rings 1) 0.005000001 &&
	test_le $(outline_error m.mesh cow8.rings 2) 0.005000001
'
test_done
