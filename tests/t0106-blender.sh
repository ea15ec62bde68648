#!/bin/sh
test_description='round trips with real Blender: shape keys in (glb, FBX), mesh-export glb back into Blender'
. "$(dirname "$0")/test-lib.sh"

# Blender is not a build dependency (Debian: apt-get install blender); the
# scripts are in examples/blender.  Runs where it is installed.
BL="$STOPMO_ROOT/examples/blender"
if ! command -v blender >/dev/null 2>&1; then
	test_skip_all="needs blender (apt-get install blender), which is absent"
fi
blender_run() { blender -b --factory-startup --python-exit-code 1 -P "$@" >blender.log 2>&1 || { tail -20 blender.log; return 1; }; }
# prints the largest distance (a number), or nothing on failure (test_num then fails)
match() { awk -f "$TEST_DIRECTORY/match-frames.awk" "$@" >match.out; cat match.out >&2; cut -d" " -f8 match.out; }
test_num() { case "$1" in [0-9]*) return 0;; esac; echo "not a number: '$1'" >&2; return 1; }

test_expect_success 'Blender: Suzanne, one subdivision, 2 shape keys, 48 keyed frames, exported as glb and FBX' '
	blender_run "$BL/shapekeys.py" -- out 48 &&
	test -s out/suzanne.glb && test -s out/suzanne.fbx && test -s out/suzanne-actions.fbx &&
	grep "^vertices 2012$" out/suzanne-blender.mesh
'

test_expect_success 'glb: split corners are reported; --weld gives Blender frames to float precision' '
	mesh-import out/suzanne.glb >split.mesh 2>err && cat err &&
	grep "warning: .*5860 of 7872 vertices are copies.*--weld" err &&
	mesh-import --weld out/suzanne.glb >glb.mesh &&
	grep "^vertices 2012$" glb.mesh && grep "^frames 48$" glb.mesh &&
	d=$(match -v yup=1 out/suzanne-blender.mesh glb.mesh) && test_num "$d" && test_le "$d" 1e-6
'

test_expect_success 'FBX, default export: no shape-key animation in it; exit 1 says how' '
	test_fails_cleanly mesh-import out/suzanne.fbx 2>err && grep -q "All Actions" err
'

test_expect_success 'FBX with All Actions off: the 48 frames to float precision' '
	mesh-import --weld out/suzanne-actions.fbx >fbx.mesh && grep "^frames 48$" fbx.mesh &&
	d=$(match out/suzanne-blender.mesh fbx.mesh) && test_num "$d" && test_le "$d" 1e-6
'

test_expect_success 'mesh-export glb opened in Blender plays the same frames' '
	mesh-export -o back.glb glb.mesh &&
	blender_run "$BL/import-gltf.py" -- back.glb back.mesh && grep "48 shape keys, frames 0..47" blender.log &&
	grep "^vertices 2012$" back.mesh &&
	anim-diff -s glb.mesh back.mesh >d && cat d && test_le "$(awk "\$1 == \"max\" { print \$2 }" d)" 1e-6
'

test_expect_success 'a replacement animation of 2 parts opened in Blender: one object per part' '
	mesh-gen -s 1 -f 3 -a wave icosphere >lib0.mesh && mesh-gen -n 4 -f 4 -a bend grid >lib1.mesh &&
	printf "0\n2\n1\n1\n0\n2\n" >lab0 && printf "3\n3\n0\n1\n2\n0\n" >lab1 &&
	mesh-export -o film.glb --pieces lib0.mesh:lab0 --pieces lib1.mesh:lab1 &&
	blender_run "$BL/import-gltf.py" -- film.glb film1.mesh part_1 &&
	grep "1 mesh objects, 4 shape keys, frames 0..5" blender.log &&
	seq 0 $(( $(sed -n 2p lib1.mesh | cut -d" " -f2) - 1 )) >id1 &&
	lib-assemble lib1.mesh lib1.mesh:lab1:id1 >ref1.mesh &&
	anim-diff -s ref1.mesh film1.mesh >d && cat d && test_le "$(awk "\$1 == \"max\" { print \$2 }" d)" 1e-6
'
test_done
