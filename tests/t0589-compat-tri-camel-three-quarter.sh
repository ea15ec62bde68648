#!/bin/sh
test_description='compat-tri on the camel gallop seen from a three-quarter view (legs crossing and hidden differently in each pose), traced, no point given: every pair succeeds, -v says when each stage ended'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"
need_shared_data scans/camel-gallop-05.off

# azimuth 60, elevation 15: 166-189 outline points per pose, 320 matched
# corners after simplification for all five poses
test_expect_success 'setup: poses 1, 2 and 4 rendered at azimuth 60, elevation 15, traced' '
	for i in 1 2 4; do
		mesh-import "$SHARED_DATA/scans/camel-gallop-0$i.off" |
		mesh-render -a 60 -e 15 -s 300x300 -c 0,0,0 --flat -f ppm >q$i.ppm &&
		img2rings -1 -s 1 -o q$i.rings q$i.ppm || return 1
	done
'

# measured: pairs 13.55, 9.63, 20.00 degrees; all three 10.19 (1.6 s CPU,
# long enough for the progress count, which shows every 0.1 s);
# every one of the 26 subsets of all five poses succeeds (3.09-20.05 deg)
test_expect_success 'every pair and all three without a correspondence point: positive, worst angle >= 9 degrees' '
	for set in "1 2" "1 4" "2 4" "1 2 4"; do
		files= && for i in $set; do files="$files q$i.rings"; done &&
		compat-tri -v $files >m.mesh 2>m.log &&
		test_le 1e-12 $(min_area m.mesh) &&
		test_le 9 $(worst_angle m.mesh) || { echo "poses $set: $(worst_angle m.mesh) deg" >&2; return 1; }
	done
'

test_expect_success '-v says when the triangulation and the refinement ended' '
	grep "triangulation: .*; at [0-9.]* s$" m.log &&
	grep "refinement: .*; at [0-9.]* s$" m.log
'
# the three poses end below 20 degrees (17.17, compat-tri(1)): in a pipe
# stderr holds only the warning that says so
test_expect_success 'a count of refinement rounds on a terminal (STOPMO_PROGRESS=1 forces it), none in a pipe' '
	STOPMO_PROGRESS=1 compat-tri q1.rings q2.rings q4.rings >p.mesh 2>p.err &&
	grep "compat-tri: refinement rounds [0-9]" p.err &&
	compat-tri q1.rings q2.rings q4.rings >n.mesh 2>n.err &&
	cat n.err && test $(wc -l <n.err) = 1 &&
	grep -q "^compat-tri: warning: worst angle [0-9.]* deg, below the goal of 20 deg (--min-angle)" n.err &&
	test_cmp p.mesh n.mesh
'
test_expect_success 'examples/morph2d camel34: the same three poses, the same mesh' '
	make -s -C "$STOPMO_ROOT/examples/morph2d" BIN="$STOPMO_BIN" SCANS="$SHARED_DATA/scans" \
		OUT="$TRASH/out" camel34 >log 2>&1 &&
	test -s out/camel34.svg &&
	test_cmp m.mesh out/camel34.mesh
'
test_done
