#!/bin/sh
test_description='piece-plug: printable pieces with magnet pockets or keyed plugs, checked with CGAL'
. "$(dirname "$0")/test-lib.sh"

# vol MESH: the volume mesh-info reports
vol() {
	mesh-info "$1" >vol.out && awk '$1 == "volume" { print $2 }' vol.out
}
# inter A B: vol(A n B) by CGAL corefinement (the overlap tool)
inter() {
	overlap -v "$1" "$2" >inter.out && awk '/intersection/ { print $NF }' inter.out
}
# away AXISMESH I J MESH: MESH moved 1e-7 model units along -(v_J - v_I) of
# AXISMESH (a connector prism: from its bottom to its top ring points into
# part 0), i.e. away from part 0: pieces that share their cap only touch,
# and CGAL cannot always close a zero-volume intersection; any real overlap
# (a plug or a wall, 1e-3 and up) survives the shift
away() {
	awk -v I="$2" -v J="$3" "/^frame [0-9]/ { rd = 1; next } rd { if (n == I) { x0 = \$1; y0 = \$2; z0 = \$3 }
		if (n == J) { print \$1 - x0, \$2 - y0, \$3 - z0; exit } n++ }" "$1" >axis.txt &&
	awk -v ax="$(cat axis.txt)" "BEGIN { split(ax, a, \" \"); l = sqrt(a[1]^2 + a[2]^2 + a[3]^2); for (i = 1; i <= 3; i++) a[i] *= 1e-7 / l }
		/^frame [0-9]/ { print; rd = 1; next } !rd { print; next }
		{ printf \"%.17g %.17g %.17g\\n\", \$1 - a[1], \$2 - a[2], \$3 - a[3] }" "$4"
}
# relerr A B: |A - B| / |B|
relerr() {
	awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; if (b < 0) b = -b; printf "%.3g\n", d / b }'
}

test_expect_success 'mesh-info --check solid: closed, and no two faces intersect' '
	cat >tet2.mesh <<-\EOF &&
	MESH 1
	vertices 8
	faces 8
	frames 1
	f 0 2 1
	f 0 1 3
	f 1 2 3
	f 0 3 2
	f 4 6 5
	f 4 5 7
	f 5 6 7
	f 4 7 6
	frame 0
	0 0 0
	1 0 0
	0 1 0
	0 0 1
	0.2 0.2 0.2
	1.2 0.2 0.2
	0.2 1.2 0.2
	0.2 0.2 1.2
	EOF
	mesh-info --check closed tet2.mesh &&
	test_fails_cleanly mesh-info --check solid tet2.mesh 2>err &&
	grep "not a solid: .* pairs of faces intersect" err &&
	sed "s/^0.2 /5.2 /; s/^1.2 0.2/6.2 0.2/" tet2.mesh >apart.mesh &&
	mesh-info --check solid apart.mesh
'
test_expect_success 'setup: talking head, two parts, seam-homog, 2 pieces per part' '
	head-gen -f 24 -s 3 >head.mesh &&
	seg-graphcut --seeds "$TEST_DIRECTORY/../examples/stopshop/head.seeds" head.mesh >seg.lab &&
	seam-smooth -l seg.lab -L smooth.lab -o smooth.mesh head.mesh &&
	seam-homog -l smooth.lab -o homog.mesh smooth.mesh &&
	part-split -l smooth.lab -o "part_%d.mesh" -m "part_%d.map" homog.mesh &&
	dict-learn -d 2 --seed 1 -o lib_0.mesh part_0.mesh &&
	dict-learn -d 2 --seed 1 -o lib_1.mesh part_1.mesh &&
	part-split -l smooth.lab -o "raw_%d.mesh" -m "raw_%d.map" smooth.mesh &&
	lib-uniform -d 2 raw_0.mesh >rawlib_0.mesh &&
	lib-uniform -d 2 raw_1.mesh >rawlib_1.mesh
'
test_expect_success 'magnets: one STL and one closed, manifold, self-intersection free solid per piece' '
	mkdir mag &&
	piece-plug --unit-mm 20 --magnet 3x2 --wall 0.8 -o "mag/p%d_%02d.stl" --mesh "mag/p%d_%02d.mesh" \
		--report mag.rep --keep-tools mag/k lib_0.mesh:part_0.map lib_1.mesh:part_1.map &&
	test "$(ls mag/*.stl | wc -l)" = 4 &&
	for f in mag/p*.mesh; do mesh-info --check solid --check manifold --check oriented "$f" || return 1; done &&
	test "$(grep -vc "^#" mag.rep)" = 4
'
test_expect_success 'the STL files are the solids (float32: volume to 1e-6)' '
	for k in 0 1; do
		mesh-import mag/p1_0$k.stl >stl.mesh &&
		mesh-info --check closed stl.mesh &&
		test_le "$(relerr "$(vol stl.mesh)" "$(vol mag/p1_0$k.mesh)")" 1e-6 || return 1
	done
'
test_expect_success 'volume = closed piece minus the pockets and the engraved id (1e-6 relative)' '
	for p in 0 1; do for k in 0 1; do
		s=$(vol mag/k-$p-$k-solid.mesh) && c=$(inter mag/k-$p-$k-solid.mesh mag/k-$p-$k-cut.mesh) &&
		test_le 0.0001 "$c" &&
		want=$(awk -v s="$s" -v c="$c" "BEGIN { printf \"%.12g\", s - c }") &&
		test_le "$(relerr "$(vol mag/p${p}_0$k.mesh)" "$want")" 1e-6 || return 1
	done; done
'
test_expect_success 'any piece of part 0 with any piece of part 1: no overlap (they meet on the cap)' '
	for a in 0 1; do for b in 0 1; do
		away mag/k-0-0-cut.mesh 0 32 mag/p1_0$b.mesh >b.mesh &&
		v=$(inter mag/p0_0$a.mesh b.mesh) && test_near "$v" 0 1e-12 || return 1
	done; done
'
test_expect_success 'the pockets are placed from the seam: the same in every piece' '
	for p in 0 1; do
		sed -n "/^frame [0-9]/,\$p" mag/k-$p-0-cut.mesh | sed -n 2,129p >c0 &&
		sed -n "/^frame [0-9]/,\$p" mag/k-$p-1-cut.mesh | sed -n 2,129p >c1 && test_cmp c0 c1 || return 1
	done
'
test_expect_success 'the id is engraved: one dot per lit font pixel of "0-1" and "1-1"' '
	# 5x7 font: "0" 19 pixels, "-" 5, "1" 10; two pockets more
	mesh-info mag/k-0-1-cut.mesh >i01 && grep "^components 36$" i01 &&
	mesh-info mag/k-1-1-cut.mesh >i11 && grep "^components 27$" i11
'
test_expect_success 'keyed plugs: male on part 0, socket in part 1, solids and volumes' '
	mkdir plug &&
	piece-plug --unit-mm 20 --plug 2x4x2 -o "plug/p%d_%02d.stl" --mesh "plug/p%d_%02d.mesh" \
		--keep-tools plug/k lib_0.mesh:part_0.map lib_1.mesh:part_1.map &&
	for f in plug/p*.mesh; do mesh-info --check solid "$f" || return 1; done &&
	test -s plug/k-0-0-add.mesh && ! test -e plug/k-1-0-add.mesh &&
	for k in 0 1; do
		s=$(vol plug/k-0-$k-solid.mesh) && a=$(vol plug/k-0-$k-add.mesh) &&
		ai=$(inter plug/k-0-$k-add.mesh plug/k-0-$k-solid.mesh) &&
		c=$(inter plug/k-0-$k-solid.mesh plug/k-0-$k-cut.mesh) &&
		test_le 0.0001 "$(awk -v a="$a" -v ai="$ai" "BEGIN { print a - ai }")" &&
		want=$(awk -v s="$s" -v a="$a" -v ai="$ai" -v c="$c" "BEGIN { printf \"%.12g\", s + a - ai - c }") &&
		test_le "$(relerr "$(vol plug/p0_0$k.mesh)" "$want")" 1e-6 || return 1
	done
'
test_expect_success 'plugged pieces overlap only where plug meets socket (nowhere, with clearance)' '
	for a in 0 1; do for b in 0 1; do
		away plug/k-0-0-add.mesh 0 4 plug/p1_0$b.mesh >b.mesh &&
		v=$(inter plug/p0_0$a.mesh b.mesh) && test_near "$v" 0 1e-12 || return 1
	done; done &&
	v=$(inter plug/p0_00.mesh plug/k-1-0-solid.mesh) &&
	a=$(vol plug/k-0-0-add.mesh) && ai=$(inter plug/k-0-0-add.mesh plug/k-0-0-solid.mesh) &&
	test_le "$(relerr "$v" "$(awk -v a="$a" -v ai="$ai" "BEGIN { print a - ai }")")" 1e-6
'
# halfturn MESH: the plugs of MESH (two prisms of 8 vertices) turned half a
# turn about the seam cap axis (their prism axis, through their midpoint)
halfturn() {
	awk '/^frame [0-9]/ { print; rd = 1; next } !rd { print; next }
	     { n++; x[n] = $1; y[n] = $2; z[n] = $3 }
	     END { for (i = 1; i <= 16; i++) { cx += x[i] / 16; cy += y[i] / 16; cz += z[i] / 16 }
	           ax = x[5] - x[1]; ay = y[5] - y[1]; az = z[5] - z[1]; l = sqrt(ax*ax + ay*ay + az*az);
	           ax /= l; ay /= l; az /= l;
	           for (i = 1; i <= n; i++) { dx = x[i] - cx; dy = y[i] - cy; dz = z[i] - cz; d = dx*ax + dy*ay + dz*az;
	               printf "%.17g %.17g %.17g\n", cx + 2*d*ax - dx, cy + 2*d*ay - dy, cz + 2*d*az - dz } }' "$1"
}
test_expect_success 'the plug is keyed: turned half a turn it does not fit the socket' '
	v=$(inter plug/k-0-0-add.mesh plug/p1_00.mesh) && test_near "$v" 0 1e-12 &&
	halfturn plug/k-0-0-add.mesh >turned.mesh &&
	v=$(inter turned.mesh plug/p1_00.mesh) &&
	test_le 0.00005 "$v"
'
test_expect_success 'another character: a waving tube cut across, plugs in model units' '
	. "$TEST_DIRECTORY/seam-lib.sh" &&
	mesh-gen -f 6 -a wave -n 24 -m 16 --caps cylinder >cyl.mesh && labels_by_z cyl.mesh 0.3 >cyl.lab &&
	seam-homog -l cyl.lab -o cylh.mesh cyl.mesh &&
	part-split -l cyl.lab -o "cp_%d.mesh" -m "cp_%d.map" cylh.mesh &&
	lib-uniform -d 2 cp_0.mesh >clib_0.mesh && lib-uniform -d 2 cp_1.mesh >clib_1.mesh &&
	piece-plug --plug 0.04x0.08x0.05 --wall 0.02 --clearance 0.005 --mesh "t%d_%d.mesh" -o "t%d_%d.stl" \
		clib_0.mesh:cp_0.map clib_1.mesh:cp_1.map &&
	for f in t*_*.mesh; do mesh-info --check solid "$f" || return 1; done &&
	piece-plug --plug 0.04x0.08x0.05 --wall 0.02 --clearance 0.005 -o "u%d_%d.stl" --keep-tools tk \
		clib_0.mesh:cp_0.map clib_1.mesh:cp_1.map &&
	away tk-0-0-add.mesh 0 4 t1_1.mesh >b1.mesh && away tk-0-0-add.mesh 0 4 t1_0.mesh >b0.mesh &&
	v=$(inter t0_0.mesh b1.mesh) && test_near "$v" 0 1e-12 &&
	v=$(inter t0_1.mesh b0.mesh) && test_near "$v" 0 1e-12
'
test_expect_success 'same input, same bytes' '
	mkdir again &&
	piece-plug --unit-mm 20 --magnet 3x2 -o "again/p%d_%02d.stl" lib_0.mesh:part_0.map lib_1.mesh:part_1.map &&
	for f in mag/p*.stl; do cmp "$f" "again/${f#mag/}" || return 1; done
'
test_expect_success 'a wall thinner than asked: error saying by how much, nothing written' '
	mkdir thin &&
	test_fails_cleanly piece-plug --unit-mm 20 --magnet 3x2 --wall 6 -o "thin/p%d_%d.stl" \
		lib_0.mesh:part_0.map lib_1.mesh:part_1.map 2>err &&
	grep "the wall around magnet pocket .* is .* mm, --wall asks 6 mm: the piece is .* mm too thin" err &&
	test -z "$(ls thin)"
'
test_expect_success 'pockets deeper than the piece: error' '
	test_fails_cleanly piece-plug --unit-mm 20 --magnet 3x40 -o "thin/p%d_%d.stl" \
		lib_0.mesh:part_0.map lib_1.mesh:part_1.map 2>err &&
	test -z "$(ls thin)" &&
	grep "breaks through" err && test -z "$(ls thin)"
'
test_expect_success 'pockets past the cap edge: error' '
	test_fails_cleanly piece-plug --magnet 0.1x0.05 --radius 0.99 --count 7 -o "thin/p%d_%d.stl" \
		lib_0.mesh:part_0.map lib_1.mesh:part_1.map 2>err &&
	grep "seam cap" err
'
test_expect_success 'a seam that moves between pieces (no seam-homog): error' '
	test_fails_cleanly piece-plug --magnet 0.1x0.05 -o "thin/p%d_%d.stl" \
		rawlib_0.mesh:raw_0.map rawlib_1.mesh:raw_1.map 2>err &&
	grep "seam-homog" err
'
test_expect_success 'one part alone has no seam: error' '
	test_fails_cleanly piece-plug --magnet 0.1x0.05 -o "thin/p%d_%d.stl" lib_0.mesh:part_0.map 2>err &&
	grep "share a seam" err
'
test_expect_success 'usage errors' '
	test_must_fail_usage piece-plug --magnet 3x2 lib_0.mesh:part_0.map 2>err &&
	test_must_fail_usage piece-plug --magnet 3 -o "p%d_%d.stl" lib_0.mesh:part_0.map 2>err &&
	test_must_fail_usage piece-plug --magnet 3x2 --plug 1x2x3 -o "p%d_%d.stl" lib_0.mesh:part_0.map 2>err &&
	test_must_fail_usage piece-plug --magnet 3x2 -o "p%d.stl" lib_0.mesh:part_0.map 2>err &&
	test_must_fail_usage piece-plug --magnet 3x2 -o "p%d_%s.stl" lib_0.mesh:part_0.map 2>err &&
	test_must_fail_usage piece-plug --magnet 3x2 -o "p%d_%d.stl" lib_0.mesh 2>err &&
	test_must_fail piece-plug --magnet 3x2 -o "p%d_%d.stl" lib_0.mesh:part_1.map 2>err
'
test_done
