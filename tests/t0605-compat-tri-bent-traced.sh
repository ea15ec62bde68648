#!/bin/sh
test_description='compat-tri: bent cuts on real drawings where no two straight cuts fit: the shared Font Awesome hippo bent hard, traced elephant frames (skips without ../shared/data)'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"
need_shared_data anim/elephant-walk-457.tar.xz
need_shared_data shapes2d/fa_hippo.rings.txt

# the -v line of the bent cuts -> "N K" (cuts, bend points)
bent_counts() {
	sed -n "s/.* \([0-9]*\) cuts\{0,1\} joining holes to their pieces bends\{0,1\} (no two straight cuts fit): \([0-9]*\) bend points/\1 \2/p" "$1"
}
worst() {
	sed -n "s/.*result: .*min angle \([0-9.]*\) deg.*/\1/p" "$1"
}

# t0581-warp.awk at 12 times its default bend (t0582 uses 2): of the
# subsets 01, 12, 0123, 234, 01234 of the hippo, 0123, 234 and 01234 failed
# before the cuts could bend ("hole ring K: no two straight cuts"); the
# frog, cat, dog and horse at this bend need no bent cut
test_expect_success 'the hippo bent hard, poses 2 3 4: a mesh through bent cuts (measured 16.99 deg, 1502 vertices)' '
	for k in 2 3 4; do
		awk -v seed=$((13 + k)) -v amp=12 -f "$TEST_DIRECTORY/t0581-warp.awk" "$SHARED_DATA/shapes2d/fa_hippo.rings.txt" \
			>h$k.rings || return 1
	done &&
	compat-tri -v h2.rings h3.rings h4.rings >h.mesh 2>err &&
	bent_counts err >n && read nb np <n && test "$nb" -ge 1 &&
	: >nocorr &&
	check_holes h.mesh nocorr nocorr 0.02 1 1 h2.rings h3.rings h4.rings &&
	test_le 15 $(worst err)
'
# the elephant walk from the front, traced: frames with an outer ring and
# two holes; with --match-rings nearest, of the 238 subsets (2 to 6) of
# frames 0, 60, 80, 180, 200, 300, 360 and 380 only 60 180 200 360 380
# failed ("hole ring 2: no two straight cuts"): frame 380's second hole is
# a gap between the legs, paired with an ear's in the others
test_expect_success 'traced elephant frames 60 180 200 360 380 with two holes each: a mesh, positive everywhere' '
	elephant_walk_frames 0060 0180 0200 0360 0380 &&
	for k in 0060 0180 0200 0360 0380; do
		mesh-import elephant/frame_$k.obj >e$k.mesh &&
		mesh-render -V front -s 400x400 -c 0,0,0 --supersample 1 -f ppm e$k.mesh >f$k.ppm &&
		img2rings -s 1 f$k.ppm >f$k.rings &&
		test $(grep -c ^ring f$k.rings) = 3 || return 1
	done &&
	compat-tri -v --match-rings nearest f0060.rings f0180.rings f0200.rings f0360.rings f0380.rings >e.mesh 2>err &&
	bent_counts err >n && read nb np <n && test "$nb" -ge 1 &&
	test_le 0 $(min_area e.mesh) && test $(min_area e.mesh) != 0
'
test_done
