#!/bin/sh
test_description='compat-tri: the matching with twice --match-points and the spread term (--spread 3) is one of the candidates of the default, raced with the others (the first at the goal kept); a mesh at the goal, an explicit --spread or -m leaves it out (t0587 horse poses 2 5 below the goal, 0 1 at it; five given rows)'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

test_expect_success 'generate: horse poses 0 1 2 5' '
	stick_poses horse 0 1 2 5 &&
	stick_rows horse 2 5 >c25 &&
	stick_rows horse 0 1 >c01
'
# measured (compat-tri(1), MATCHING BETWEEN GIVEN ROWS, The spread
# candidate): poses 2 5 16.17 deg without it, 20.01 with it
test_expect_success 'horse poses 2 5: the spread candidate is tried, kept, and reaches the goal' '
	compat-tri -v --threads 1 -c c25 --points-out p.txt horse2.rings horse5.rings >h.mesh 2>err &&
	compat-tri --spread 0 --threads 1 -c c25 horse2.rings horse5.rings >z.mesh &&
	w=$(worst_angle h.mesh) && w0=$(worst_angle z.mesh) && echo "worst $w deg, --spread 0 $w0" &&
	test_le 1e-12 $(min_area h.mesh) &&
	test_le $w0 $w && test_le 20 $w &&
	grep -q "no first pass at the goal ([0-9.]* deg kept so far): the matching with 24 points; the matching with 24 points and --spread 3 too" err &&
	grep -q "kept the matching with 24 points and --spread 3: worst angle" err
'
test_expect_success 'the given points on their input vertices, the outline within the tolerance, the rows of the kept matching written' '
	given_on_vertices h.mesh c25 horse2.rings horse5.rings &&
	outline_within h.mesh horse2.rings horse5.rings &&
	compat-tri -m multiscale --match-points 24 --spread 3 --refine none -c c25 --points-out p3.txt \
		horse2.rings horse5.rings >/dev/null &&
	test_cmp p3.txt p.txt && test $(grep -cFxf c25 p.txt) = 5
'
test_expect_success 'the same bytes with 2 threads' '
	compat-tri --threads 2 -c c25 horse2.rings horse5.rings >t2.mesh &&
	test_cmp h.mesh t2.mesh
'
test_expect_success 'an explicit --spread, -m or --match-points: no such candidate, or with the given count' '
	compat-tri -v --spread 0 -c c25 horse2.rings horse5.rings >/dev/null 2>e0 &&
	! grep -q "and --spread" e0 &&
	compat-tri -v -m multiscale -c c25 horse2.rings horse5.rings >/dev/null 2>em &&
	! grep -q "and --spread" em &&
	compat-tri -v --match-points 12 -c c25 horse2.rings horse5.rings >/dev/null 2>ek &&
	grep -q "the matching with 12 points and --spread 3 too" ek
'
test_expect_success 'horse poses 0 1, at the goal: no candidate, the bytes of --spread 0' '
	compat-tri -v -c c01 horse0.rings horse1.rings >g.mesh 2>gerr &&
	! grep -q "and --spread" gerr &&
	compat-tri --spread 0 -c c01 horse0.rings horse1.rings >g0.mesh &&
	test_cmp g0.mesh g.mesh
'
test_done
