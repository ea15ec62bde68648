#!/bin/sh
test_description='piece-plug caps: loops not star-shaped about their centroid, seams where three parts meet'
. "$(dirname "$0")/test-lib.sh"

# face labels of an icosphere frame 0 by the face centroids: c (a C-shaped
# patch on the upper half, open towards +x) or sectors (three by angle)
labels() {
	awk -v mode="$1" 'BEGIN { nv = 0; nf = 0 }
		/^f / { F[nf++] = $2 " " $3 " " $4; next }
		/^frame 0/ { rd = 1; next } /^frame/ { rd = 0 }
		rd && NF == 3 { X[nv] = $1; Y[nv] = $2; Z[nv] = $3; nv++ }
		END { for (f = 0; f < nf; f++) { split(F[f], t, " ");
			x = (X[t[1]] + X[t[2]] + X[t[3]]) / 3; y = (Y[t[1]] + Y[t[2]] + Y[t[3]]) / 3; z = (Z[t[1]] + Z[t[2]] + Z[t[3]]) / 3;
			r = sqrt(x * x + y * y)
			if (mode == "c") print (z > 0 && r > 0.3 && r < 0.75 && !(x > 0 && y < 0.1 && y > -0.1)) ? 1 : 0
			else { a = atan2(y, x); print a < -1.0472 ? 0 : a < 1.0472 ? 1 : 2 } } }' "$2"
}

test_expect_success 'setup: an icosphere cut into a C-shaped patch and the rest' '
	mesh-gen -f 2 -a wave -s 4 icosphere >sph.mesh &&
	labels c sph.mesh >c.lab &&
	part-split -l c.lab -o "c_%d.mesh" -m "c_%d.map" sph.mesh &&
	mesh-info c_1.mesh | grep "^boundary_loops 1$" &&
	lib-uniform -d 1 c_0.mesh >cl_0.mesh && lib-uniform -d 1 c_1.mesh >cl_1.mesh
'
test_expect_success 'a C-shaped seam: not a fan; the triangulated cap would reuse a piece edge: clear error' '
	mkdir out &&
	test_fails_cleanly piece-plug --no-label -o "out/p%d_%d.stl" cl_0.mesh:c_0.map cl_1.mesh:c_1.map &&
	grep "not star-shaped about its centroid and its triangulated cap would reuse the interior edge" "$TRASH/.err" &&
	test -z "$(ls out)"
'
# the same patch with its ears flipped to the other side (faces with all
# three corners on the seam), one at a time until none is left
unear() {
	awk 'NR == FNR { if ($1 == "f") F[nf++] = $2 " " $3 " " $4; next } { L[n++] = $1 }
		END { for (it = 0; it < 200; it++) {
			delete s0; delete s1
			for (f = 0; f < nf; f++) { split(F[f], t, " "); for (j = 1; j <= 3; j++) if (L[f]) s1[t[j]] = 1; else s0[t[j]] = 1 }
			ch = 0
			for (f = 0; f < nf && !ch; f++) { split(F[f], t, " "); b = 0
				for (j = 1; j <= 3; j++) if ((t[j] in s0) && (t[j] in s1)) b++
				if (b == 3) { L[f] = 1 - L[f]; ch = 1 } }
			if (!ch) break }
		for (f = 0; f < nf; f++) print L[f] }' "$1" "$2"
}
test_expect_success 'the C without ears: a triangulated cap, the same in both parts; solids check; volumes add up' '
	unear sph.mesh c.lab >u.lab &&
	part-split -l u.lab -o "u_%d.mesh" -m "u_%d.map" sph.mesh &&
	lib-uniform -d 1 u_0.mesh >ul_0.mesh && lib-uniform -d 1 u_1.mesh >ul_1.mesh &&
	piece-plug -v --no-label -o "u%d_%d.stl" --mesh "u%d_%d.solid" ul_0.mesh:u_0.map ul_1.mesh:u_1.map 2>err &&
	grep "not star-shaped about its centroid: capped by a constrained Delaunay triangulation" err &&
	mesh-info --check solid u0_0.solid && mesh-info --check solid u1_0.solid &&
	v0=$(mesh-info u0_0.solid | awk "\$1 == \"volume\" { print \$2 }") &&
	v1=$(mesh-info u1_0.solid | awk "\$1 == \"volume\" { print \$2 }") &&
	v=$(anim-slice -f 0 sph.mesh | mesh-info - | awk "\$1 == \"volume\" { print \$2 }") &&
	test_near "$(awk -v a="$v0" -v b="$v1" "BEGIN { printf \"%.17g\", a + b }")" "$v" "$(awk -v v="$v" "BEGIN { print 1e-12 * v }")"
'
test_expect_success 'three parts meeting at the poles: clear error' '
	labels sectors sph.mesh >s.lab &&
	part-split -l s.lab -o "s_%d.mesh" -m "s_%d.map" sph.mesh &&
	for p in 0 1 2; do lib-uniform -d 1 s_$p.mesh >sl_$p.mesh || return 1; done &&
	test_fails_cleanly piece-plug --no-label -o "out/s%d_%d.stl" sl_0.mesh:s_0.map sl_1.mesh:s_1.map sl_2.mesh:s_2.map &&
	grep "three parts meet are not supported" "$TRASH/.err" &&
	test -z "$(ls out)"
'
test_done
