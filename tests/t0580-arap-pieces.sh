#!/bin/sh
test_description='arap-morph and arap-deform2d on a mesh of separate pieces (compat-tri with several rings: a square and a triangle): arap-morph fixes one vertex per piece at the blend of its positions (it failed with "matrix is not positive definite"); arap-deform2d names a piece with fewer than 2 handles'
. "$(dirname "$0")/test-lib.sh"

# frame_dist A FA B FB [K0 DX DY K1]: max distance between frame FA of mesh
# A plus (DX, DY) and frame FB of mesh B over the vertices K0 .. K1-1
# (default: all)
frame_dist() {
	awk -v fa=$2 -v fb=$4 -v k0=${5:-0} -v dx=${6:-0} -v dy=${7:-0} -v k1=${8:-1e9} '
	FNR == 1 { fi++ } $1 == "frame" { fr = $2; k = 0; next }
	fr != "" && NF == 3 { if (fi == 1 && fr == fa) { X[k] = $1 + dx; Y[k] = $2 + dy }
		if (fi == 2 && fr == fb && k >= k0 && k < k1) { d = sqrt(($1 - X[k]) ^ 2 + ($2 - Y[k]) ^ 2); if (d > m) m = d } k++ }
	END { printf "%.3g\n", m }' "$1" "$3"
}

test_expect_success 'two poses of two pieces: the square turns, the triangle moves by (2, 5)' '
	printf "ring 4\n0 0\n10 0\n10 10\n0 10\nring 3\n20 0\n30 0\n25 8\n" >a.rings &&
	printf "ring 4\n0 0\n10 1\n9 11\n-1 10\nring 3\n22 5\n32 5\n27 13\n" >b.rings &&
	printf "0 0\n1 1\n2 2\n" >c &&
	compat-tri -v -c c a.rings b.rings >p.mesh 2>err &&
	grep -q "2 rings per shape: 2 pieces, 0 holes" err &&
	test $(sed -n "s/^vertices //p" p.mesh) = 7
'
test_expect_success 'arap-morph: each pose reproduced, the triangle halfway at (1, 2.5), nothing inverted' '
	printf "1 0\n0.5 0.5\n0 1\n1.5 -0.5\n" >w &&
	arap-morph -v p.mesh w >m.mesh 2>err && cat err &&
	grep -q "inverted triangles: 0 in 0 of 4 frames" err &&
	test_le $(frame_dist p.mesh 0 m.mesh 0) 1e-9 &&
	test_le $(frame_dist p.mesh 1 m.mesh 2) 1e-9 &&
	test_le $(frame_dist p.mesh 0 m.mesh 1 4 1 2.5) 1e-9 &&
	test_le $(frame_dist p.mesh 0 m.mesh 3 4 -1 -2.5) 1e-9
'
test_expect_success 'arap-morph -l and --shear-hermite on the pieces' '
	arap-morph -l p.mesh w >l.mesh && test_le $(frame_dist p.mesh 1 l.mesh 2) 1e-9 &&
	arap-morph --shear-hermite p.mesh w >h.mesh && test_le $(frame_dist p.mesh 0 h.mesh 0) 1e-9
'
test_expect_success 'arap-deform2d: a piece without 2 handles is named, exit 1, nothing written' '
	awk "\$1 == \"frame\" && \$2 == 1 { exit } { print }" p.mesh | sed "s/^frames 2/frames 1/" >a.mesh &&
	printf "0 0 0\n2 12 10\n" >h1 &&
	test_fails_cleanly arap-deform2d a.mesh h1 &&
	grep -q "piece 2 of 2 (3 vertices, the first 4) has 0 handles: each separate piece needs 2" .err &&
	printf "0 0 0\n2 12 10\n4 20 0\n" >h2 &&
	test_fails_cleanly arap-deform2d a.mesh h2 &&
	grep -q "piece 2 of 2 (3 vertices, the first 4) has 1 handle: each" .err
'
test_expect_success 'arap-deform2d: 2 handles on each piece place both (the square where it was, the triangle 3 up)' '
	printf "0 0 0\n2 10 10\n4 20 3\n5 30 3\n" >h4 &&
	arap-deform2d a.mesh h4 >d.mesh &&
	test_le $(frame_dist a.mesh 0 d.mesh 0 4 0 3) 1e-9 &&
	test_le $(frame_dist a.mesh 0 d.mesh 0 0 0 0 4) 1e-9
'
test_done
