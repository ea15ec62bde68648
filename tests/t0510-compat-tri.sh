#!/bin/sh
test_description='compat-tri: N-way compatible triangulation of outlines'
. "$(dirname "$0")/test-lib.sh"

# ring of n points on an ellipse (a, b) with a bump of height h near angle 0
ellipse() {
	awk -v n="$1" -v a="$2" -v b="$3" -v h="$4" 'BEGIN { print "ring " n;
		for (i = 0; i < n; i++) { t = 6.283185307179586 * i / n;
			r = 1 + h * exp(-((t - 1.5) ^ 2) * 8);
			printf "%.9g %.9g\n", a * r * cos(t), b * r * sin(t) } }'
}
# smallest signed triangle area over all frames of a plain MESH stream
min_area() {
	awk 'NR == 2 { nv = $2 } NR == 3 { nf = $2 } $1 == "f" { F[nfa++] = $2 " " $3 " " $4 }
	     $1 == "frame" { k = 0; fr++; next }
	     fr > 0 && NF == 3 { X[fr, k] = $1; Y[fr, k] = $2; k++ }
	     END { m = 1e300; for (f = 1; f <= fr; f++) for (t = 0; t < nfa; t++) {
		split(F[t], v, " "); a = v[1]; b = v[2]; c = v[3];
		s = (X[f,b]-X[f,a])*(Y[f,c]-Y[f,a]) - (Y[f,b]-Y[f,a])*(X[f,c]-X[f,a]);
		if (s < m) m = s }; print m }' "$1"
}

test_expect_success 'setup: three outlines and correspondences' '
	ellipse 40 1 1 0 >a.rings && ellipse 55 2 0.7 0.6 >b.rings && ellipse 31 1 1.5 -0.3 >c.rings &&
	printf "0 0 0\n10 14 8\n20 27 15\n30 41 23\n" >corr.txt
'
test_expect_success 'one face list, N frames, every triangle positive in every shape' '
	compat-tri -v -c corr.txt a.rings b.rings c.rings >abc.mesh 2>log &&
	grep -q "Steiner" log && grep -q "min angle" log &&
	sed -n 4p abc.mesh >frames && echo "frames 3" >expect && test_cmp expect frames &&
	test_le 1e-12 $(min_area abc.mesh)
'
# the bar shows every 0.1 s and at its end, so even this quick run ends
# with a full one; the mesh does not change with it
test_expect_success 'a triangulation bar on a terminal (STOPMO_PROGRESS=1 forces it), none in a pipe' '
	STOPMO_PROGRESS=1 compat-tri -c corr.txt a.rings b.rings c.rings >p.mesh 2>p.err &&
	tr "\r" "\n" <p.err >p.lines &&
	grep "^compat-tri: triangulation \[#*\] 1000/1000 [0-9.]*s$" p.lines &&
	test_cmp abc.mesh p.mesh &&
	compat-tri -c corr.txt a.rings b.rings c.rings >n.mesh 2>n.err &&
	! test -s n.err
'
test_expect_success 'without refinement and simplification it still is compatible' '
	compat-tri -e 0 -l 0 -s 0 -c corr.txt a.rings b.rings c.rings >raw.mesh &&
	test_le 1e-12 $(min_area raw.mesh)
'
test_expect_success 'a clockwise outline is reversed, same result' '
	{ echo "ring 55"; sed 1d b.rings | tac; } >bcw.rings &&
	awk "{ print \$1, (\$2 == 0 ? 0 : 55 - \$2), \$3 }" corr.txt >corrcw.txt &&
	compat-tri -c corrcw.txt a.rings bcw.rings c.rings >cw.mesh &&
	test_le 1e-12 $(min_area cw.mesh)
'
test_expect_success 'bad input: self-intersecting outline' '
	printf "ring 4\n0 0\n1 1\n1 0\n0 1\n" >bow.rings &&
	printf "0 0\n1 1\n2 2\n" >c3.txt &&
	test_fails_cleanly compat-tri -c c3.txt a.rings bow.rings
'
test_expect_success 'bad input: correspondence columns do not match shape count' '
	test_fails_cleanly compat-tri -c corr.txt a.rings b.rings && grep -q "3 columns, but there are 2 shapes" .err
'
test_expect_success 'bad input: fewer than 3 correspondence points with --match off' '
	printf "0 0 0\n10 14 8\n" >two.txt &&
	test_fails_cleanly compat-tri --match off -c two.txt a.rings b.rings c.rings && grep -q "at least 3" .err
'
test_expect_success 'bad input: index out of range, order not consistent' '
	printf "0 0 0\n10 99 8\n20 27 15\n" >oor.txt && test_fails_cleanly compat-tri -c oor.txt a.rings b.rings c.rings &&
	printf "0 0 0\n20 14 8\n10 27 15\n" >ord.txt && test_fails_cleanly compat-tri -c ord.txt a.rings b.rings c.rings
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage compat-tri --match off a.rings 2>/dev/null &&
	test_must_fail_usage compat-tri --match arclength a.rings b.rings 2>/dev/null &&
	test_must_fail_usage compat-tri --match-points 2 a.rings b.rings 2>/dev/null &&
	test_must_fail_usage compat-tri -c corr.txt 2>/dev/null &&
	test_must_fail_usage compat-tri -c - - <corr.txt 2>err && grep -q "stdin (.-.) can be only one of" err
'
need_shared_data shapes2d/poses/elephant-pose6.rings.txt
test_expect_success 'elephant poses 1 2 3 6: compatible, Steiner count and min angle printed' '
	P="$SHARED_DATA/shapes2d/poses" &&
	compat-tri -v -c "$STOPMO_ROOT/examples/morph2d/corr4.txt" "$P/elephant-pose1.rings.txt" \
		"$P/elephant-pose2.rings.txt" "$P/elephant-pose3.rings.txt" "$P/elephant-pose6.rings.txt" \
		>e.mesh 2>log && cat log &&
	grep -q "Steiner points" log && test_le 1e-12 $(min_area e.mesh)
'
test_done
