#!/bin/sh
test_description='compat-tri --slide: in the passes run again (--split-share), outline vertices that are not given points slide along their own pose'"'"'s input outline in the max-min polish (the boundary correspondence re-matched locally), within the outline tolerance; given points stay on their input vertices (t0587 horse poses 0 2 4 and 2 4, five given rows)'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

# outline_error MESH RING POSE: two-sided Hausdorff distance between frame
# POSE's boundary polygon (edges in one triangle only) and RING, over the
# ring's bounding-box diagonal (the ring's vertices to the polygon; the
# polygon's vertices and 16 points on each of its edges to the ring)
outline_error() {
	awk -v pose=$3 'BEGIN { n = 0 } function sd(px, py, ax, ay, bx, by,  dx, dy, l, t) {
		dx = bx - ax; dy = by - ay; l = dx * dx + dy * dy; t = l > 0 ? ((px - ax) * dx + (py - ay) * dy) / l : 0
		if (t < 0) t = 0; if (t > 1) t = 1; return sqrt((ax + t * dx - px) ^ 2 + (ay + t * dy - py) ^ 2) }
	FILENAME == ARGV[1] {
		if ($1 == "f") { for (k = 0; k < 3; k++) E[$(2 + k) " " $(2 + (k + 1) % 3)] = 1; next }
		if ($1 == "frame") { fr = $2; k = 0; next }
		if (fr == pose && NF == 3) { X[k] = $1; Y[k] = $2; k++ }
		next }
	FNR == 1 { next }
	{ PX[n] = $1; PY[n] = $2; n++ }
	END { for (e in E) { split(e, v, " "); if (!((v[2] " " v[1]) in E)) S[v[1]] = v[2] }
		lx = hx = PX[0]; ly = hy = PY[0]
		for (i = 0; i < n; i++) { if (PX[i] < lx) lx = PX[i]; if (PX[i] > hx) hx = PX[i]; if (PY[i] < ly) ly = PY[i]; if (PY[i] > hy) hy = PY[i] }
		h = 0
		for (i = 0; i < n; i++) { d = 1e300; for (a in S) { b = S[a]; x = sd(PX[i], PY[i], X[a], Y[a], X[b], Y[b]); if (x < d) d = x } if (d > h) h = d }
		for (a in S) { b = S[a]; for (t = 0; t < 16; t++) { qx = X[a] + t / 16 * (X[b] - X[a]); qy = Y[a] + t / 16 * (Y[b] - Y[a]); d = 1e300
			for (i = 0; i < n; i++) { j = (i + 1) % n; x = sd(qx, qy, PX[i], PY[i], PX[j], PY[j]); if (x < d) d = x } if (d > h) h = d } }
		printf "%.9f\n", h / sqrt((hx - lx) ^ 2 + (hy - ly) ^ 2) }' "$1" "$2"
}
# given_on_vertices MESH CORR RING...: every given row a vertex at its input point in every frame
given_on_vertices() {
	gm=$1 gc=$2; shift 2
	awk -v nr=$# 'FILENAME == ARGV[1] { if ($1 == "frame") { fr = $2; k = 0; next }
		if (fr != "" && NF == 3) { X[fr, k] = $1; Y[fr, k] = $2; k++ } next }
	FILENAME == ARGV[2] { for (s = 0; s < NF; s++) C[FNR - 1, s] = $(s + 1); nc = FNR; next }
	FNR == 1 { ri++; next }
	{ PX[ri - 1, FNR - 2] = $1; PY[ri - 1, FNR - 2] = $2 }
	END { for (s = 0; s < nr; s++) for (c = 0; c < nc; c++) { i = C[c, s]; f = 0
		for (w = 0; (s, w) in X; w++) if (X[s, w] == PX[s, i] && Y[s, w] == PY[s, i]) f = 1
		if (!f) { print "pose " s ": given row " c + 1 " is not a vertex at its point"; bad = 1 } }
		exit bad }' "$gm" "$gc" "$@"
}

test_expect_success 'generate: horse poses 0 2 4' '
	stick_pose horse 0 && stick_pose horse 2 && stick_pose horse 4 &&
	paste -d" " horselm0 horselm2 horselm4 | sed -n "1p;3p;5p;6p;7p" >c024 &&
	paste -d" " horselm2 horselm4 | sed -n "1p;3p;5p;6p;7p" >c24
'
# measured (compat-tri(1), REFINEMENT, The outline slides): poses 0 2 4
# 15.33 deg with --slide off, 20.08 by default; poses 2 4 11.99 -> 19.04
test_expect_success 'horse poses 0 2 4: the goal of 20 degrees reached (15.33 with --slide off)' '
	compat-tri -v -c c024 horse0.rings horse2.rings horse4.rings >h.mesh 2>err &&
	test_le 1e-12 $(min_area h.mesh) &&
	w=$(worst_angle h.mesh) && echo "worst $w deg" && test_le 20 $w &&
	compat-tri --slide off -c c024 horse0.rings horse2.rings horse4.rings >off.mesh &&
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
