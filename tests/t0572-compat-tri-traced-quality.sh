#!/bin/sh
test_description='compat-tri quality on traced silhouettes: elephant walk frames rendered from the side and from a three-quarter view (mesh-render), traced (img2rings), no point given; worst angle over every triangle of every pose >= 20 degrees'
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
# other frames from a three-quarter view (azimuth 60, elevation 15): the
# trunk, the ears and the far legs overlap the body differently in every
# frame (88-118 outline points); measured 20.01 deg, 610 vertices, 0.8 s
# CPU, and every subset of 2-5 of these frames at 20.00 deg or more
FRAMES34="0020 0090 0160 0230 0300 0370"
test_expect_success 'setup: six other walk frames traced from a three-quarter view' '
	elephant_walk_frames $FRAMES34 &&
	for k in $FRAMES34; do
		mesh-import elephant/frame_$k.obj |
		mesh-render -a 60 -e 15 -s 300x300 -c 0,0,0 --flat -f ppm >q$k.ppm &&
		img2rings -1 -s 1 -o q$k.rings q$k.ppm || return 1
	done
'
test_expect_success 'six three-quarter frames: positive, worst angle >= 19.99 degrees in every pose' '
	compat-tri -v q0020.rings q0090.rings q0160.rings q0230.rings q0300.rings q0370.rings >q.mesh 2>q.log &&
	test_le 1e-12 $(min_area q.mesh) &&
	test_le 19.99 $(worst_angle q.mesh) &&
	test $(grep -c "pose [0-5] (q[0-9]*.rings): worst angle [0-9.]* deg, 0.0% of triangles under 10 deg, 0.0% under 20" q.log) = 6
'
test_done
