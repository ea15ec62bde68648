#!/bin/sh
test_description='mesh-export glTF passes Khronos glTF-Validator with no error and no warning'
. "$(dirname "$0")/test-lib.sh"

VALIDATE="$TEST_DIRECTORY/gltf-validate.js"
if ! command -v node >/dev/null 2>&1; then
	test_skip_all="needs node (Debian: nodejs) for glTF-Validator"
elif [ ! -f "${STOPMO_NODE_MODULES:-$STOPMO_ROOT/node_modules}/gltf-validator/package.json" ]; then
	test_skip_all="needs the npm package gltf-validator (package.json: make deps installs it; npm or its registry was unavailable)"
fi

test_expect_success 'static meshes, .glb and .gltf' '
	mesh-gen -s 4 icosphere >ico.mesh && mesh-export -o ico.glb ico.mesh && mesh-export -o ico.gltf ico.mesh &&
	node "$VALIDATE" ico.glb ico.gltf
'

test_expect_success 'animations with clips, .glb, .gltf and embedded' '
	mesh-gen -f 9 -a twist --cut-every 4 cylinder >c.mesh &&
	mesh-export -o c.glb c.mesh && mesh-export -o c.gltf c.mesh && mesh-export -f gltf c.mesh >emb.gltf &&
	node "$VALIDATE" c.glb c.gltf emb.gltf
'

test_expect_success 'a replacement animation with 2 parts' '
	mesh-gen -s 1 -f 3 -a wave icosphere >lib0.mesh && mesh-gen -n 4 -f 4 -a bend grid >lib1.mesh &&
	printf "0\n2\n1\n1\n0\n2\n" >lab0 && printf "3\n3\n0\n1\n2\n0\n" >lab1 &&
	mesh-export -o film.glb --pieces lib0.mesh:lab0 --pieces lib1.mesh:lab1 &&
	mesh-export -o film.gltf --pieces lib0.mesh:lab0 --pieces lib1.mesh:lab1 &&
	node "$VALIDATE" film.glb film.gltf
'

test_expect_success 'an unused vertex and a degenerate triangle still give unit normals' '
	cat >odd.mesh <<-\EOT &&
	MESH 1
	vertices 5
	faces 2
	frames 2
	f 0 1 2
	f 0 1 3
	frame 0
	0 0 0
	1 0 0
	0 1 0
	2 0 0
	5 5 5
	frame 1
	0 0 0.5
	1 0 0
	0 1 0
	2 0 0
	5 5 5
	EOT
	mesh-export -o odd.glb odd.mesh && node "$VALIDATE" odd.glb >report && cat report &&
	grep "0 errors, 0 warnings" report
'

test_expect_success 'the validator does report a broken file' '
	sed "s/\"max\":\[/\"max\":[9,/" ico.gltf >bad.gltf && cp ico.bin . 2>/dev/null;
	test_must_fail node "$VALIDATE" bad.gltf >report && cat report && grep -q ERROR report
'
test_done
