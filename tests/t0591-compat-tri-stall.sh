#!/bin/sh
test_description='compat-tri: a refinement that stalls below the goal goes back to its best round, polishes it and refines again from there (t0587 horse poses 0 2 4 and flamingo poses 1 2 3 5, five given rows; pose 2 of the horse hides a front leg)'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

test_expect_success 'generate: horse poses 0 2 4, flamingo poses 1 2 3 5' '
	stick_pose horse 0 && stick_pose horse 2 && stick_pose horse 4 &&
	stick_pose flamingo 1 && stick_pose flamingo 2 && stick_pose flamingo 3 && stick_pose flamingo 5
'
# measured (compat-tri(1), REFINEMENT): horse 0 2 4 8.70 deg before (it
# stopped at the first stall), 10.85 after; flamingo 1 2 3 5 4.17 before,
# 7.25 after
test_expect_success 'horse poses 0 2 4, five rows: worst angle >= 10.5 degrees (stopped at 8.70 before)' '
	stick_rows horse 0 2 4 >c &&
	compat-tri -c c horse0.rings horse2.rings horse4.rings >h.mesh &&
	test_le 1e-12 $(min_area h.mesh) &&
	w=$(worst_angle h.mesh) && echo "worst $w deg" && test_le 10.5 $w
'
test_expect_success 'flamingo poses 1 2 3 5, five rows: worst angle >= 6.5 degrees (stopped at 4.17 before)' '
	stick_rows flamingo 1 2 3 5 >c &&
	compat-tri -c c flamingo1.rings flamingo2.rings flamingo3.rings flamingo5.rings >f.mesh &&
	test_le 1e-12 $(min_area f.mesh) &&
	w=$(worst_angle f.mesh) && echo "worst $w deg" && test_le 6.5 $w
'
test_expect_success 'the same bytes with 1, 2 and 3 threads' '
	stick_rows horse 0 2 4 >c &&
	same_bytes_threads -c c horse0.rings horse2.rings horse4.rings
'
test_done
