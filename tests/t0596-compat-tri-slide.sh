#!/bin/sh
test_description='compat-tri --slide: in the passes run again (--split-share), outline vertices that are not given points slide along their own pose'"'"'s input outline in the max-min polish (the boundary correspondence re-matched locally), within the outline tolerance; given points stay on their input vertices (t0587 horse poses 0 2 4 and 2 4, five given rows)'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

test_expect_success 'generate: horse poses 0 2 4' '
	stick_pose horse 0 && stick_pose horse 2 && stick_pose horse 4 &&
	stick_rows horse 0 2 4 >c024 &&
	stick_rows horse 2 4 >c24
'
# measured (compat-tri(1), REFINEMENT, The outline slides): poses 0 2 4
# 15.33 deg with --slide off, 20.08 by default; poses 2 4 11.99 -> 19.04
# (--slide off with --match-polish 0: the polished matching, tried where
# the mesh is below the goal, would lift it too)
test_expect_success 'horse poses 0 2 4: the goal of 20 degrees reached (15.33 with --slide off)' '
	compat-tri -v -c c024 horse0.rings horse2.rings horse4.rings >h.mesh 2>err &&
	test_le 1e-12 $(min_area h.mesh) &&
	w=$(worst_angle h.mesh) && echo "worst $w deg" && test_le 20 $w &&
	compat-tri --slide off --match-polish 0 -c c024 horse0.rings horse2.rings horse4.rings >off.mesh &&
	w0=$(worst_angle off.mesh) && echo "--slide off: $w0 deg" && test_le $w0 16 &&
	grep -q "outline after the refinement (--slide): within" err
'
test_expect_success 'the outline within the tolerance of each input, given points on their input vertices' '
	given_on_vertices h.mesh c024 horse0.rings horse2.rings horse4.rings &&
	k=0 && for p in 0 2 4; do
		e=$(outline_error h.mesh horse$p.rings $k) && echo "pose $p: $e" &&
		test_le $e 0.005000001 && k=$((k + 1)) || return 1
	done &&
	! cmp -s h.mesh off.mesh
'
test_expect_success 'horse poses 2 4: worst angle >= 18.9 degrees (11.99 with --slide off), outline kept' '
	compat-tri -c c24 horse2.rings horse4.rings >p.mesh &&
	w=$(worst_angle p.mesh) && echo "worst $w deg" && test_le 18.9 $w &&
	given_on_vertices p.mesh c24 horse2.rings horse4.rings &&
	test_le $(outline_error p.mesh horse2.rings 0) 0.005000001 &&
	test_le $(outline_error p.mesh horse4.rings 1) 0.005000001
'
test_expect_success 'a tighter outline tolerance is kept too (-e 0.002)' '
	compat-tri -e 0.002 -c c24 horse2.rings horse4.rings >e.mesh &&
	test_le $(outline_error e.mesh horse2.rings 0) 0.002000001 &&
	test_le $(outline_error e.mesh horse4.rings 1) 0.002000001
'
test_expect_success 'the same bytes with 1 and 2 threads' '
	compat-tri --threads 1 -c c024 horse0.rings horse2.rings horse4.rings >t1.mesh &&
	compat-tri --threads 2 -c c024 horse0.rings horse2.rings horse4.rings >t2.mesh &&
	test_cmp t1.mesh t2.mesh && test_cmp t1.mesh h.mesh
'
test_expect_success '--slide all also slides in the first pass; a bad value is a usage error' '
	compat-tri --slide all -c c24 horse2.rings horse4.rings >all.mesh &&
	test_le 1e-12 $(min_area all.mesh) &&
	test_le $(outline_error all.mesh horse2.rings 0) 0.005000001 &&
	test_must_fail_usage compat-tri --slide sometimes -c c24 horse2.rings horse4.rings 2>bad &&
	grep -q "slide must be" bad
'
test_done
