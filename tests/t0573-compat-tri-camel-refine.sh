#!/bin/sh
test_description='compat-tri refinement on traced camel poses with hand landmarks: where a leg must map to a sliver (camel2 shows the rear legs as one blob) the refinement stops when it stalls and goes back to its best round, instead of splitting up to --max-vertices'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"
need_shared_data scans/camel-gallop-05.off

# Seven hand landmarks per pose (vertex indices into the traced outlines,
# one row per landmark, one column per pose 1..5, in outline order): neck
# notch, ear tip, snout, hoof 1, hoof 2, rear hoof, tail tip.
cat >lm.txt <<\LM
88 125 135 80 54
95 133 148 89 65
102 142 153 96 71
128 169 181 131 106
147 31 17 162 140
53 80 79 26 1
71 103 107 55 26
LM
# corr ROWS POSES: the -c file for those landmark rows and poses
corr() {
	awk -v r="$1" -v p="$2" 'BEGIN { n = split(r, R, " "); for (i = 1; i <= n; i++) k[R[i]] = 1; m = split(p, P, " ") }
	(NR in k) { s = ""; for (i = 1; i <= m; i++) s = s (i > 1 ? " " : "") $(P[i]); print s }' lm.txt
}

test_expect_success 'setup: five gallop frames traced from the side (camel_traced_poses)' '
	camel_traced_poses
'
test_expect_success 'poses 1 2, seven landmarks, -m off (the given rows, arc length between): worst angle >= 12 deg with <= 700 vertices (measured 12.66 deg, 679, by the third --split-share pass, which ends at its vertex cap; before it 9.96 deg, 374; before the stall detection 8.98 deg, 1277 vertices, 65% of the triangles under 20 deg)' '
	corr "1 2 3 4 5 6 7" "1 2" >c12 &&
	compat-tri -m off -v -c c12 camel1.rings camel2.rings >m12.mesh 2>m12.log &&
	test_le 1e-12 $(min_area m12.mesh) &&
	test_le 12 $(worst_angle m12.mesh) &&
	test_le $(mesh_vertices m12.mesh) 700
'
test_expect_success '-v says why the refinement stopped below the goal (a stall or the vertex cap, and what ended the rounds after it; which --split-share pass was kept, what the global max-min polish raised), where, and how stretched the maps are there' '
	grep -E "refinement stopped below the goal of 20 deg: (neither the worst angle nor the number of triangles below the goal improved in [0-9]+ rounds|--max-vertices [0-9]+ reached)(, then the best round polished and refined again: [^;(]*)? ?(\(back to the best round.s mesh\))?( in the (first|second|third) pass[^;]*)?(; the global max-min polish raised the worst angle from [0-9.]+ deg)?(, then with the outline sliding \(--slide\) from [0-9.]+ to [0-9.]+ deg|; the global max-min polish with the outline sliding \(--slide\) raised the worst angle from [0-9.]+ to [0-9.]+ deg)?; worst angle [0-9.]+ deg; the poses. maps are stretched [0-9.]+x at \(" m12.log
'
# camel 5's outline has one diagonal pixel contact, which img2rings chamfers
# since 2026-11-26 (one point 0.25 px lower): measured 20.01 deg, 491
# vertices (with the old tracing 20.04, 387; before the stall detection
# 20.08, 441): the vertex count of a refinement this close to its goal
# moves with small changes of the input
test_expect_success 'poses 2 5, seven landmarks, -m off: the goal is reached, worst angle >= 19.99 deg with <= 600 vertices' '
	corr "1 2 3 4 5 6 7" "2 5" >c25 &&
	compat-tri -m off -v -c c25 camel2.rings camel5.rings >m25.mesh 2>m25.log &&
	test_le 1e-12 $(min_area m25.mesh) &&
	test_le 19.99 $(worst_angle m25.mesh) &&
	test_le $(mesh_vertices m25.mesh) 600 &&
	! grep "refinement stopped" m25.log
'
# the final polish goes on while it raises the worst angle (it stopped after
# four sweeps): poses 2-5 with landmarks 2-6, default options, 10.39 deg
# (before 7.90; over 12 camel subsets mean 12.59 -> 12.92, horse and
# flamingo of t0587 likewise)
test_expect_success 'poses 2 3 4 5, five landmarks, default: the final polish goes on while it gains (worst angle >= 10 deg; before 7.90)' '
	corr "2 3 4 5 6" "2 3 4 5" >c2345 &&
	compat-tri -c c2345 camel2.rings camel3.rings camel4.rings camel5.rings >m2345.mesh &&
	test_le 1e-12 $(min_area m2345.mesh) &&
	w=$(worst_angle m2345.mesh) && echo "worst $w deg" && test_le 10 $w
'
test_done
