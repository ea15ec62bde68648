#!/bin/sh
test_description='mesh-import: facecap.glb morph animation matches the baked OBJ frames'
. "$(dirname "$0")/test-lib.sh"
need_shared_data anim/facecap.glb
need_shared_data anim/facecap-335.tar.xz

test_expect_success 'facecap.glb gives 335 frames of the 2694-vertex head' '
	mesh-import -v --raw "$SHARED_DATA/anim/facecap.glb" >face.mesh 2>log &&
	cat log && grep -q "head" log &&
	mesh-info face.mesh >info &&
	grep "^vertices 2694$" info && grep "^faces 5032$" info && grep "^frames 335$" info
'

test_expect_success 'it matches the baked OBJ frames to 1e-4 relative (same faces)' '
	tmp=$(mktemp -d /tmp/stopmo-t0102.XXXXXX) &&
	(
		tar -xJf "$SHARED_DATA/anim/facecap-335.tar.xz" -C "$tmp" &&
		mesh-import --raw "$tmp/*/frame_*.obj" >baked.mesh
	)
	rc=$?
	rm -rf "$tmp"
	test $rc -eq 0 &&
	mesh-export -k 0 face.mesh | grep "^f " >f1 &&
	mesh-export -k 0 baked.mesh | grep "^f " >f2 && test_cmp f1 f2 &&
	anim-diff -s baked.mesh face.mesh >diff &&
	max=$(awk "\$1 == \"max\" { print \$2 }" diff) &&
	diag=$(mesh-info baked.mesh | awk "\$1 == \"diagonal\" { print \$2 }") &&
	rel=$(awk -v m="$max" -v d="$diag" "BEGIN { print m / d }") &&
	echo "max vertex distance $max, bbox diagonal $diag, relative $rel" &&
	test_le "$rel" 1e-4
'

test_expect_success '--fps resamples, --mesh picks another mesh, --weld joins UV seams' '
	mesh-import --raw --fps 10 "$SHARED_DATA/anim/facecap.glb" >f10.mesh &&
	mesh-info f10.mesh | grep "^frames 112$" &&
	mesh-import --mesh teeth "$SHARED_DATA/anim/facecap.glb" >teeth.mesh &&
	grep "^frames 1$" teeth.mesh && grep "^vertices 614$" teeth.mesh &&
	mesh-import --raw --weld "$SHARED_DATA/anim/facecap.glb" >w.mesh &&
	head -2 w.mesh | tail -1 >nv && ! grep -q "vertices 2694" nv &&
	test_fails_cleanly mesh-import --mesh nosuch "$SHARED_DATA/anim/facecap.glb"
'
test_done
