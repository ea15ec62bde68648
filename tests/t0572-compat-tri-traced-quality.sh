#!/bin/sh
test_description='compat-tri quality on traced silhouettes: elephant walk frames rendered from the side (mesh-render), traced (img2rings), no point given; worst angle over every triangle of every pose >= 20 degrees'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"
need_shared_data anim/elephant-walk-457.tar.xz

FRAMES="0000 0140 0210 0280"
test_expect_success 'setup: four walk frames traced from the side (78-123 outline points)' '
	elephant_walk_frames $FRAMES &&
	for k in $FRAMES; do
		mesh-import elephant/frame_$k.obj |
		mesh-render -V right -s 300x300 -c 0,0,0 --flat -f ppm >w$k.ppm &&
		img2rings -1 -s 1 -o w$k.rings w$k.ppm || return 1
	done
'
test_expect_success 'four traced poses: positive, worst angle >= 19.99 degrees (measured 20.01; before the max-min polish 11.3)' '
	compat-tri -v w0000.rings w0140.rings w0210.rings w0280.rings >w.mesh 2>w.log &&
	test_le 1e-12 $(min_area w.mesh) &&
	test_le 19.99 $(worst_angle w.mesh)
'
test_expect_success 'every pose reported with -v: no triangle under 20 degrees' '
	test $(grep -c "pose [0-3] (w[0-9]*.rings): worst angle [0-9.]* deg, 0.0% of triangles under 10 deg, 0.0% under 20" w.log) = 4
'
test_done
