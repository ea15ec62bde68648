#!/bin/sh
test_description='seam-smooth: smooth seams by re-meshing along the max-vote contours'
. "$(dirname "$0")/test-lib.sh"

# labels from the centroids of frame 0: awk program text in $1 decides from x y z
label_by() {
	awk '/^f / { F[nf++] = $2 " " $3 " " $4; next }
	     /^frame 0/ { p = 1; next } /^frame [1-9]/ { exit }
	     p { V[nv++] = $0 }
	     END { for (f = 0; f < nf; f++) { split(F[f], a, " "); x = y = z = 0
	           for (k = 1; k <= 3; k++) { split(V[a[k]], q, " "); x += q[1] / 3; y += q[2] / 3; z += q[3] / 3 }
	           '"$1"' } }' "$2"
}

# every output vertex must be its map entry (a convex combination of the
# vertices of one input edge or face) in every frame: max error / bbox diagonal
on_surface() {   # in.mesh out.mesh map
	awk 'BEGIN { n = 0; err = 0; bad = 0 }
	     FILENAME == ARGV[1] {
	         if ($1 == "f") { E[$2 " " $3] = E[$3 " " $4] = E[$4 " " $2] = 1
	                          E[$3 " " $2] = E[$4 " " $3] = E[$2 " " $4] = 1
	                          T[$2 " " $3 " " $4] = T[$3 " " $4 " " $2] = T[$4 " " $2 " " $3] = 1; next }
	         if ($1 == "frame") { k = $2; i = 0; next }
	         if (k != "" && NF == 3) { X[k, i, 1] = $1; X[k, i, 2] = $2; X[k, i, 3] = $3
	             if (k == 0) for (d = 1; d <= 3; d++) { if (i == 0 || $d < lo[d]) lo[d] = $d; if (i == 0 || $d > hi[d]) hi[d] = $d }
	             i++ }
	         next }
	     FILENAME == ARGV[2] { a[n] = $1; b[n] = $2; c[n] = $3; wa[n] = $4; wb[n] = $5; wc[n] = $6
	         s = $4 + $5 + $6; if (s < 1 - 1e-12 || s > 1 + 1e-12 || $4 < 0 || $5 < 0 || $6 < 0) bad++
	         if (!($1 == $2 && $2 == $3) && $2 == $3 && !(($1 " " $2) in E)) bad++
	         if ($1 != $2 && $2 != $3 && !(($1 " " $2 " " $3) in T)) bad++
	         n++; next }
	     $1 == "frame" { k = $2; j = 0; next }
	     k != "" && NF == 3 { for (d = 1; d <= 3; d++) {
	             e = $d - (wa[j] * X[k, a[j], d] + wb[j] * X[k, b[j], d] + wc[j] * X[k, c[j], d])
	             if (e < 0) e = -e; if (e > err) err = e }
	         j++ }
	     END { dg = sqrt((hi[1]-lo[1])^2 + (hi[2]-lo[2])^2 + (hi[3]-lo[3])^2)
	           if (bad) print "bad map rows:", bad > "/dev/stderr"
	           printf "%.3g\n", bad ? 1 : err / dg }' "$1" "$3" "$2"
}
stat() { sed -n "s/.*$1 \([0-9.e+-]*\) -> \([0-9.e+-]*\) .*/\1 \2/p" "$2"; }

test_expect_success 'setup: a tube cut along a tilted plane (zig-zag seam)' '
	mesh-gen -n 32 -m 32 -f 3 -a twist --amount 0.5 cylinder >tube.mesh &&
	label_by "print (z > 0.5 + 0.6 * x) ? 1 : 0" tube.mesh >zig.labels &&
	test $(wc -l <zig.labels) = 2048 && test $(sort -u zig.labels | wc -l) = 2
'
test_expect_success 'smoothing writes a valid animation and one label per new triangle' '
	seam-smooth -v -l zig.labels -L new.labels --map map tube.mesh >out.mesh 2>err &&
	mesh-info out.mesh >info &&
	grep "^manifold yes" info && grep "^components 1" info && grep "^degenerate_faces 0" info &&
	nf=$(sed -n "s/^faces //p" info) && test $(wc -l <new.labels) = $nf &&
	test $(sed -n "s/^frames //p" info) = 3 &&
	nv=$(sed -n "s/^vertices //p" info) && test $(wc -l <map) = $nv
'
test_expect_success 'every output vertex lies on the input surface of its frame' '
	e=$(on_surface tube.mesh out.mesh map) && echo "max error $e bbox diagonals" &&
	test_le $e 1e-9
'
test_expect_success 'the surface area is unchanged' '
	a0=$(mesh-info tube.mesh | sed -n "s/^area //p") &&
	a1=$(mesh-info out.mesh | sed -n "s/^area //p") &&
	test_near $a0 $a1 1e-9
'
test_expect_success 'the seam is shorter and turns less than the zig-zag' '
	stat "seam length" err >len && stat "summed turning angle" err >turn &&
	cat len turn &&
	test_le $(awk "{print \$2 / \$1}" len) 0.9 &&
	test_le $(awk "{print \$2 / \$1}" turn) 0.5
'
test_expect_success 'more smoothing is not longer than no smoothing (straight cuts only)' '
	seam-smooth -v -a 0 -l zig.labels -L a0.labels tube.mesh 2>err0 >/dev/null &&
	stat "seam length" err0 >len0 && cat len0 &&
	test_le $(awk "{print \$2}" len) $(awk "{print \$2 * 1.001}" len0)
'
test_expect_success 'pipe input gives the same bytes as a file' '
	seam-smooth -l zig.labels -L new2.labels <tube.mesh >out2.mesh &&
	test_cmp out.mesh out2.mesh && test_cmp new.labels new2.labels
'
test_expect_success 'a clean straight cut is kept: no new vertices' '
	label_by "print (z > 0.5) ? 1 : 0" tube.mesh >ring.labels &&
	seam-smooth -a 0 -l ring.labels -L ring2.labels tube.mesh >ring.mesh &&
	test_cmp ring.labels ring2.labels
'
test_expect_success 'three parts meet: triple junction gets a centre vertex' '
	mesh-gen -n 24 -f 2 -a wave grid >grid.mesh &&
	label_by "ang = atan2(y - 0.5, x - 0.5); print (ang < -1) ? 0 : (ang < 1.1 ? 1 : 2)" grid.mesh >three.labels &&
	seam-smooth -v -l three.labels -L three2.labels --map map3 grid.mesh >three.mesh 2>err3 &&
	grep "[1-9][0-9]* triangle centres" err3 &&
	test $(sort -u three2.labels | wc -l) = 3 &&
	mesh-info three.mesh | grep "^manifold yes" &&
	e=$(on_surface grid.mesh three.mesh map3) && test_le $e 1e-9 &&
	stat "seam length" err3 >len3 && test_le $(awk "{print \$2 / \$1}" len3) 0.95
'
test_expect_success 'seg-graphcut | seam-smooth pipeline' '
	seg-graphcut --seed 0:0 --seed 1:2047 tube.mesh >p &&
	seam-smooth -l p -L q tube.mesh >pq.mesh &&
	mesh-info pq.mesh | grep "^manifold yes"
'
test_expect_success 'bad input: labels not matching the faces' '
	head -n 100 zig.labels >short.labels &&
	test_fails_cleanly seam-smooth -l short.labels -L x tube.mesh &&
	test ! -e x
'
test_expect_success 'bad input: negative label' '
	sed "1s/.*/-1/" zig.labels >neg.labels &&
	test_fails_cleanly seam-smooth -l neg.labels -L x tube.mesh
'
test_expect_success 'bad input: non-manifold edge on the seam' '
	printf "MESH 1\nvertices 5\nfaces 3\nframes 1\nf 0 1 2\nf 1 0 3\nf 0 1 4\nframe 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n" >nm.mesh &&
	printf "0\n1\n1\n" >nm.labels &&
	test_fails_cleanly seam-smooth -l nm.labels -L x nm.mesh
'
test_expect_success 'bad input: truncated stream' '
	head -n 3000 tube.mesh >trunc.mesh &&
	test_fails_cleanly seam-smooth -l zig.labels -L x trunc.mesh &&
	test ! -e x
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage seam-smooth -L x tube.mesh 2>/dev/null &&
	test_must_fail_usage seam-smooth -l zig.labels tube.mesh 2>/dev/null &&
	test_must_fail_usage seam-smooth -a -1 -l zig.labels -L x tube.mesh 2>/dev/null
'
test_done
