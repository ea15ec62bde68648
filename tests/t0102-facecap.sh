#!/bin/sh
test_description='mesh-import: facecap.glb morph animation matches the baked OBJ frames'
. "$(dirname "$0")/test-lib.sh"
need_shared_data anim/facecap.glb
need_shared_data anim/facecap-335.tar.xz

# max deviation over the vertex lines of two plain MESH streams, relative to
# the bounding-box diagonal of the second; prints "dev reldev"
dev_rel() {
	paste -d' ' "$1" "$2" | awk 'NF == 6 && $1 != "f" {
		for (i = 1; i <= 3; i++) { d = $i - $(i + 3); if (d < 0) d = -d; if (d > m) m = d;
			b = $(i + 3); if (!n || b < lo[i]) lo[i] = b; if (!n || b > hi[i]) hi[i] = b }
		n = 1
	} END { diag = sqrt((hi[1]-lo[1])^2 + (hi[2]-lo[2])^2 + (hi[3]-lo[3])^2);
		printf "%.3g %.3g\n", m, m / diag }'
}

test_expect_success 'facecap.glb gives 335 frames of the 2694-vertex head' '
	mesh-import -v "$SHARED_DATA/anim/facecap.glb" >face.mesh 2>log &&
	cat log &&
	head -4 face.mesh >actual &&
	printf "MESH 1\nvertices 2694\nfaces 5032\nframes 335\n" >expect &&
	test_cmp expect actual &&
	grep -q "head" log
'

test_expect_success 'it matches the baked OBJ frames to 1e-4 relative (same faces)' '
	tmp=$(mktemp -d /tmp/stopmo-t0102.XXXXXX) &&
	(
		tar -xJf "$SHARED_DATA/anim/facecap-335.tar.xz" -C "$tmp" &&
		mesh-import "$tmp/*/frame_*.obj" >baked.mesh
	)
	rc=$?
	rm -rf "$tmp"
	test $rc -eq 0 &&
	grep "^f " face.mesh >f1 && grep "^f " baked.mesh >f2 && test_cmp f1 f2 &&
	r=$(dev_rel face.mesh baked.mesh) && echo "max deviation, relative to bbox diagonal: $r" &&
	test_le "${r#* }" 1e-4
'

test_expect_success '--fps resamples, --mesh picks another mesh, --weld joins UV seams' '
	mesh-import --fps 10 "$SHARED_DATA/anim/facecap.glb" >f10.mesh &&
	grep "^frames 112$" f10.mesh &&
	mesh-import --mesh teeth "$SHARED_DATA/anim/facecap.glb" >teeth.mesh &&
	grep "^frames 1$" teeth.mesh &&
	mesh-import --raw --weld "$SHARED_DATA/anim/facecap.glb" >w.mesh &&
	head -2 w.mesh | tail -1 >nv && ! grep -q "vertices 2694" nv &&
	test_fails_cleanly mesh-import --mesh nosuch "$SHARED_DATA/anim/facecap.glb"
'
test_done
