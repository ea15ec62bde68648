#!/bin/sh
test_description='compat-tri --spread S: the boundary matching prices each step by how far its stretch ratio is from its segment'"'"'s mean ratio; it changes the matched points and the mesh, keeps the given points on their input vertices and the outline within -e, gives the same bytes at 1 and 2 threads, and rejects a negative weight (t0587 horse poses 2 5, five given rows, 24 matched points: with 12 the matched points of this pair are the same)'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

test_expect_success 'generate: horse poses 2 5' '
	stick_pose horse 2 && stick_pose horse 5 &&
	stick_rows horse 2 5 >c25
'
test_expect_success '--spread 3 changes the matched points and the mesh' '
	compat-tri --threads 1 -c c25 -m multiscale --match-points 24 --points-out p0 horse2.rings horse5.rings >m0.mesh &&
	compat-tri --spread 3 --threads 1 -c c25 -m multiscale --match-points 24 --points-out p3 horse2.rings horse5.rings >m3.mesh &&
	test_le 1e-12 $(min_area m3.mesh) &&
	echo "worst $(worst_angle m3.mesh) deg, without --spread $(worst_angle m0.mesh)" &&
	! cmp -s p0 p3 && ! cmp -s m0.mesh m3.mesh
'
test_expect_success 'the given points on their input vertices, the outline within the tolerance' '
	given_on_vertices m3.mesh c25 horse2.rings horse5.rings &&
	test_le $(outline_error m3.mesh horse2.rings 0) 0.005000001 &&
	test_le $(outline_error m3.mesh horse5.rings 1) 0.005000001
'
test_expect_success 'the same bytes with 2 threads' '
	compat-tri --spread 3 --threads 2 -c c25 -m multiscale --match-points 24 horse2.rings horse5.rings >t2.mesh &&
	test_cmp m3.mesh t2.mesh
'
test_expect_success '--spread 0 is the default; a negative or non-numeric weight is a usage error' '
	compat-tri --spread 0 --threads 1 -c c25 -m multiscale --match-points 24 horse2.rings horse5.rings >z.mesh &&
	test_cmp m0.mesh z.mesh &&
	test_must_fail_usage compat-tri --spread -1 -c c25 horse2.rings horse5.rings 2>bad &&
	grep -q "spread must be >= 0" bad &&
	test_must_fail_usage compat-tri --spread x -c c25 horse2.rings horse5.rings
'
test_done
