#!/bin/sh
test_description='mesh-import --merge: facecap.glb face + eyes + teeth as one multi-component head'
. "$(dirname "$0")/test-lib.sh"
need_shared_data anim/facecap.glb

test_expect_success '--merge appends eyes and teeth after the animated face' '
	mesh-import -v --merge "$SHARED_DATA/anim/facecap.glb" >merged.mesh 2>log &&
	cat log && grep -q "merged 3 other meshes (1674 vertices)" log &&
	mesh-info merged.mesh >info &&
	grep "^vertices 4368$" info && grep "^faces 8042$" info && grep "^frames 335$" info &&
	grep "^manifold yes$" info
'

test_expect_success 'the face is unchanged (numbers and motion), the rest is static' '
	mesh-import "$SHARED_DATA/anim/facecap.glb" >face.mesh &&
	awk "/^frame /{ print; i = 0; r = 1; next } r && i++ < 2694" merged.mesh >a &&
	awk "/^frame /{ r = 1 } r" face.mesh >b && test_cmp b a &&
	awk "/^f /" face.mesh >fa && awk "/^f / && ++n <= 5032" merged.mesh >fb && test_cmp fa fb &&
	awk "/^frame /{ fr = \$2; i = 0; r = 1; next }
	     r { if (i >= 2694) { if (fr == 0) p[i] = \$0; else if (p[i] != \$0) bad++ } i++ }
	     END { print bad + 0; exit bad > 0 }" merged.mesh
'

test_expect_success 'the eyeballs sit in the eye sockets: next to the face, above its middle (-z up)' '
	awk "/^frame 1/ { exit } /^frame 0/ { r = 1; next }
	     r { i++; if (i <= 2694) { fz += \$3; nf++ } else if (i <= 2694 + 2 * 530) { ez += \$3; ne++ } }
	     END { printf \"%.0f %.0f\\n\", fz / nf, ez / ne; exit !(ez / ne < fz / nf) }" merged.mesh
'

test_done
