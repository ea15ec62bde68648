#!/bin/sh
test_description='compat-tri --layers: a leg drawn over the body in one pose and apart in another, each part its own ring'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

# layer_pose K: the stick horse of pose K without its front left leg
# (body K.rings, the six other landmarks as ring indices in rowsK) and
# that leg alone (legK.rings), both traced; layersK.rings: body then leg
layer_pose() {
	awk -v char=horse -v pose=$1 -v lm=pts$1 -v omit=0 -f "$TEST_DIRECTORY/t0587-stick-character.awk" >body$1.ppm &&
	awk -v char=horse -v pose=$1 -v lm=/dev/null -v only=0 -f "$TEST_DIRECTORY/t0587-stick-character.awk" >leg$1.ppm &&
	img2rings -1 -s 1 -o body$1.rings body$1.ppm &&
	img2rings -1 -s 1 -o leg$1.rings leg$1.ppm &&
	cat body$1.rings leg$1.rings >layers$1.rings &&
	grep -v "^hoof0 " pts$1 | awk 'NR == FNR { if (FNR > 1) { x[n] = $1; y[n] = $2; n++ } next }
	{ b = -1; for (i = 0; i < n; i++) { d = ($2 - x[i]) ^ 2 + ($3 - y[i]) ^ 2; if (b < 0 || d < bd) { bd = d; b = i } }
	  if (bd > 16) { print $1 " far from the outline" >"/dev/stderr"; exit 1 } print b }' body$1.rings - >rows$1
}

# face_layers MESH: the layer (connected component, numbered by first
# appearance) of each face, one line each; then "vertex0 L", the layer
# holding vertex 0 (the first vertex of ring 1)
face_layers() {
	awk 'function find(x) { while (P[x] != x) x = P[x]; return x }
	$1 == "f" { F[nf++] = $2 " " $3 " " $4; for (k = 2; k <= 4; k++) if (!($k in P)) P[$k] = $k
		a = find($2); b = find($3); c = find($4); P[b] = a; P[find(c)] = a }
	END { for (f = 0; f < nf; f++) { split(F[f], v, " "); r = find(v[1]); if (!(r in L)) L[r] = nl++; print L[r] }
	      print "vertex0", L[find(0)] }' "$1"
}

# measured (2026-11-29): the whole silhouettes of poses 0 and 2 with all
# seven rows end at 15.91 deg (5.7 s CPU: the front legs overlap in pose
# 2, so the gap between them must go into a few pixels of its outline);
# as two layers 20.60 deg, 133 vertices, 0.04 s
test_expect_success 'setup: poses 0 and 2 (a foreleg lifted over the other) as body and leg' '
	layer_pose 0 && layer_pose 2 &&
	paste -d" " rows0 rows2 >rows &&
	test $(wc -l <rows) = 6 &&
	test $(grep -c "^ring" layers2.rings) = 2
'
test_expect_success 'without --layers the crossing rings are refused, with a pointer to it' '
	test_must_fail compat-tri -c rows layers0.rings layers2.rings >out 2>err &&
	! test -s out &&
	grep "^compat-tri: cannot read .layers0.rings.: line [0-9]*: two rings cross (edges from lines [0-9]* and [0-9]*); rings drawn over each other as layers need --layers$" err
'
test_expect_success '--layers: compatible, every triangle positive, 20 degrees in both poses' '
	compat-tri -v --layers -c rows layers0.rings layers2.rings >m.mesh 2>m.log &&
	grep "2 rings per shape: 2 layers, 0 holes" m.log &&
	test_le 1e-12 $(min_area m.mesh) &&
	test_le 20 $(worst_angle m.mesh)
'
test_expect_success 'the faces come layer by layer, the body (ring 1) first' '
	face_layers m.mesh >layers &&
	test "$(grep -v vertex0 layers | uniq | tr "\n" " ")" = "0 1 " &&
	grep -x "vertex0 0" layers
'
test_expect_success 'the same bytes on one thread and on two' '
	compat-tri --layers --threads 1 -c rows layers0.rings layers2.rings >t1.mesh &&
	compat-tri --layers --threads 2 -c rows layers0.rings layers2.rings >t2.mesh &&
	test_cmp t1.mesh t2.mesh && test_cmp m.mesh t1.mesh
'
test_expect_success 'bad input: --layers with -i is a usage error; a layer that crosses itself names its ring' '
	echo "0 0 0 0" >pts &&
	test_must_fail_usage compat-tri --layers -i pts layers0.rings layers2.rings &&
	{ cat body0.rings; printf "ring 4\n0 0\n20 10\n20 0\n0 30\n"; } >bow.rings &&
	test_must_fail compat-tri --layers bow.rings layers2.rings >out 2>err &&
	! test -s out &&
	grep "^compat-tri: cannot read .bow.rings.: line [0-9]*: ring 2 intersects itself" err
'
test_done
