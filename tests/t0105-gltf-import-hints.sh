#!/bin/sh
test_description='mesh-import: split-corner hint, morph targets without animation (glTF, FBX), --rest'
. "$(dirname "$0")/test-lib.sh"
DATA="$TEST_DIRECTORY/data"

test_expect_success 'a glTF split at every corner: one warning line that suggests --weld' '
	mesh-gen -s 2 -f 3 -a wave icosphere >ico.mesh &&
	awk "
		\$1 == \"vertices\" { next } \$1 == \"faces\" { nf = \$2; next } \$1 == \"frames\" { nfr = \$2; next }
		\$1 == \"MESH\" { next }
		\$1 == \"f\" { F[t++] = \$2 \" \" \$3 \" \" \$4; next }
		\$1 == \"frame\" { k = \$2; v = 0; next }
		{ P[k, v++] = \$0 }
		END {
			print \"MESH 1\"; print \"vertices \" 3 * nf; print \"faces \" nf; print \"frames \" nfr
			for (i = 0; i < nf; i++) print \"f \" 3 * i, 3 * i + 1, 3 * i + 2
			for (k = 0; k < nfr; k++) {
				print \"frame \" k
				for (i = 0; i < nf; i++) { split(F[i], c, \" \"); for (j = 1; j <= 3; j++) print P[k, c[j]] }
			}
		}" ico.mesh >soup.mesh &&
	mesh-export -o soup.glb soup.mesh &&
	mesh-import soup.glb >s.mesh 2>err && cat err &&
	test $(wc -l <err) -eq 1 && grep "warning: .soup.glb.: 798 of 960 vertices are copies" err &&
	grep -q -- "--weld" err &&
	mesh-import --weld soup.glb >w.mesh 2>err2 && test ! -s err2 &&
	grep "^vertices 162$" w.mesh
'

test_expect_success 'a few seam copies: no warning, counted with -v' '
	mesh-export -o ico.glb ico.mesh && mesh-import ico.glb >i.mesh 2>err && test ! -s err &&
	mesh-import -v ico.glb 2>log >/dev/null && ! grep copies log
'

test_expect_success 'morph targets without animation: exit 1 naming the cause and --rest' '
	mesh-export -o anim.gltf ico.mesh &&
	perl -pe "s/,\"animations\":.*?(?=,\"accessors\":)//" anim.gltf >still.gltf &&
	! grep -q animations still.gltf &&
	test_fails_cleanly mesh-import still.gltf 2>err && cat err &&
	grep "3 morph targets but the file has no animation of their weights" err && grep -q -- "--rest" err &&
	mesh-import --rest still.gltf >rest.mesh && grep "^frames 1$" rest.mesh
'

test_expect_success 'Blender FBX with shape keys but no animation (default export): the message says how' '
	test_fails_cleanly mesh-import "$DATA/cube.fbx" 2>err && cat err &&
	grep -q "2 morph targets but the file has no animation" err &&
	grep -q "All Actions" err && grep -q "glTF" err && grep -q -- "--rest" err &&
	mesh-import --rest "$DATA/cube.fbx" >rest.mesh 2>err && grep "^frames 1$" rest.mesh &&
	grep -q "warning: .*copies.*--weld" err
'

test_expect_success 'Blender FBX with curves: the constant shape key keeps its DeformPercent (assimp drops it)' '
	mesh-import -v --weld "$DATA/cube-actions.fbx" >f.mesh 2>log && cat log &&
	grep -q "weights read from the FBX blend-shape channels" log && grep "^frames 4$" f.mesh &&
	awk -f "$TEST_DIRECTORY/match-frames.awk" "$DATA/cube-blender.mesh" f.mesh >d && cat d &&
	grep -q "^frames 4 vertices 26 match [0-9.e-]* max [0-9]" d && test_le "$(cut -d" " -f8 d)" 1e-6
'

test_expect_success 'a truncated FBX fails cleanly' '
	head -c 9000 "$DATA/cube-actions.fbx" >trunc.fbx && test_fails_cleanly mesh-import trunc.fbx
'

test_expect_success 'Blender glb with corners split: --weld gives Blender frames to 1e-6' '
	mesh-import --weld "$DATA/cube.glb" >g.mesh && grep "^vertices 26$" g.mesh &&
	awk -v yup=1 -f "$TEST_DIRECTORY/match-frames.awk" "$DATA/cube-blender.mesh" g.mesh >d && cat d &&
	grep -q "^frames 4 vertices 26 match [0-9.e-]* max [0-9]" d && test_le "$(cut -d" " -f8 d)" 1e-6
'
test_done
