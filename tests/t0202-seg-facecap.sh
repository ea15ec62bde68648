#!/bin/sh
test_description='seg-graphcut and seam-smooth on the facecap performance (shared data)'
. "$(dirname "$0")/test-lib.sh"
need_shared_data anim/facecap-335.tar.xz

# facecap: +y is the front of the face, -z is up (forehead z ~ 6000, chin z ~ 12500).
# Seeds: face 1539 on the forehead, face 1034 on the chin.
test_expect_success 'setup: import the 335 OBJ frames' '
	tar xJf "$SHARED_DATA/anim/facecap-335.tar.xz" &&
	mesh-import "facecap/frame_*.obj" >face.mesh &&
	head -4 face.mesh >head && printf "MESH 1\nvertices 2694\nfaces 5032\nframes 335\n" >expect &&
	test_cmp expect head
'
test_expect_success 'two parts from a forehead seed and a chin seed' '
	seg-graphcut -v --seed 0:1539 --seed 1:1034 face.mesh >labels 2>err &&
	cat err && test $(wc -l <labels) = 5032 && test $(sort -u labels | wc -l) = 2
'
# front-most triangle centroids in a column through one eye: the label must
# flip once, from 0 above to 1 below, at eye height (z 7000..9000)
eye_flip() {   # x-range of the column
	awk -v x0=$1 -v x1=$2 'NR == FNR { L[FNR - 1] = $1; next }
	     /^f / { F[nf++] = $2 " " $3 " " $4; next } /^frame 0/ { p = 1; next } /^frame 1$/ { exit }
	     p { V[nv++] = $0 }
	     END { for (f = 0; f < nf; f++) { split(F[f], a, " "); cx = cy = cz = 0
	             for (k = 1; k <= 3; k++) { split(V[a[k]], q, " "); cx += q[1] / 3; cy += q[2] / 3; cz += q[3] / 3 }
	             if (cx < x0 || cx > x1 || cz < 5000 || cz > 13000) continue
	             b = int(cz / 250); if (!(b in by) || cy > by[b]) { by[b] = cy; lab[b] = L[f]; zz[b] = cz } }
	           lo0 = -1; hi1 = 1e9
	           for (b in lab) { if (lab[b] == 0 && zz[b] > lo0) lo0 = zz[b]; if (lab[b] == 1 && zz[b] < hi1) hi1 = zz[b] }
	           printf "%d %d\n", lo0, hi1 }' labels face.mesh
}
test_expect_success 'the seam crosses the face at eye height, through both eyes' '
	eye_flip 3800 4300 >right && eye_flip 6900 7400 >left && cat right left &&
	read a b <right && test $a -lt $b && test $a -gt 7000 && test $b -lt 9000 &&
	read a b <left && test $a -lt $b && test $a -gt 7000 && test $b -lt 9000
'
test_expect_success 'forehead and top of the head above, nose tip and mouth below' '
	test $(sed -n 1456p labels) = 0 && test $(sed -n 2376p labels) = 1 &&
	test $(sed -n 4725p labels) = 1 && test $(sed -n 1035p labels) = 1
'
# Fig. 4: the seeds only pick the sides.  5 placements (each seed moved
# within two rings), then 10 more pairs of nearby triangles: the same labels.
test_expect_success 'jittered seeds (5 placements) give the identical labeling' '
	for p in 1806:1032 1531:1024 1541:1036 1809:1040 1544:1043; do
		seg-graphcut --seed 0:${p%:*} --seed 1:${p#*:} face.mesh >j || return 1
		test_cmp labels j || return 1
	done
'
test_expect_success 'and 10 more nearby seed pairs too' '
	for p in 1454:1018 1456:1020 1527:1022 1533:1030 1536:1032 1795:1042 1804:1051 1811:1082 1844:1186 1543:1020; do
		seg-graphcut --seed 0:${p%:*} --seed 1:${p#*:} face.mesh >j || return 1
		test_cmp labels j || return 1
	done
'
test_expect_success 'the paper literal Eq. 2 (-b 0 -r 0) moves an ear with seeds 1541/1036' '
	seg-graphcut -b 0 -r 0 --seed 0:1539 --seed 1:1034 face.mesh >lit0 &&
	seg-graphcut -b 0 -r 0 --seed 0:1541 --seed 1:1036 face.mesh >lit1 &&
	d=$(paste lit0 lit1 | awk "\$1 != \$2" | wc -l) && echo "$d triangles differ" && test $d -gt 100
'
test_expect_success 'seam-smooth: valid, same area, shorter seam' '
	seam-smooth -v --raw -l labels -L smooth.labels face.mesh >smooth.mesh 2>err &&
	cat err && mesh-info smooth.mesh >info && grep "^manifold yes" info &&
	test $(sed -n "s/^faces //p" info) = $(wc -l <smooth.labels) &&
	test_near $(mesh-info face.mesh | sed -n "s/^area //p") $(sed -n "s/^area //p" info) 1e-3 &&
	r=$(sed -n "s/.*seam length .*(ratio \([0-9.]*\),.*/\1/p" err) && test_le $r 0.97
'
test_done
