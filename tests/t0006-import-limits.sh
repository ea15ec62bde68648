#!/bin/sh
test_description='mesh-import refuses hostile files cleanly (issue 13):
glTF accessor bounds without overflow, PLY headers checked before OpenMesh,
reservations capped by the file size, a missing file named as missing'
. "$(dirname "$0")/test-lib.sh"


test_expect_success 'setup: the small glTF morph animation imports' '
	perl "$TEST_DIRECTORY/gltf-morph.pl" >ok.gltf &&
	mesh-import -v ok.gltf >ok.mesh 2>log && cat log &&
	grep "weights decoded from the glTF accessor" log &&
	mesh-info ok.mesh | grep "^frames 3$" &&
	tail -3 ok.mesh >last && printf "0 0 0.5019607843137255\n1 0 0.5019607843137255\n0 1 0.5019607843137255\n" >expect &&
	test_cmp expect last
'
test_expect_success 'glTF: a byteStride of 2^63 + 2048 does not wrap the bounds check' '
	perl "$TEST_DIRECTORY/gltf-morph.pl" 9223372036854777856 5000 >wrap.gltf &&
	test_fails_cleanly mesh-import -v wrap.gltf 2>log &&
	grep "wrap.gltf.: accessor [0-9]* reaches outside its buffer" log
'
test_expect_success 'glTF: negative, fractional and huge sizes are not cast blindly' '
	for s in -4 4.5 1e300 253; do
		perl "$TEST_DIRECTORY/gltf-morph.pl" $s 5000 >s.gltf &&
		mesh-import -v s.gltf >s.mesh 2>log
		rc=$? && cat log && test $rc -le 1 && ! grep "weights decoded" log || return 1
	done
'
test_expect_success 'PLY: a property before any element (OpenMesh 9 crashed)' '
	printf "ply\nformat ascii 1.0\nproperty float x\nend_header\n" >p1.ply &&
	test_fails_cleanly mesh-import p1.ply 2>err &&
	grep "p1.ply.: not a valid PLY file (header line 3: a property before any element)" err
'
test_expect_success 'PLY: a header without end_header (OpenMesh 9 looped forever)' '
	printf "ply\nformat ascii 1.0\n" >p2.ply &&
	test_fails_cleanly timeout 20 mesh-import p2.ply 2>err && grep "no end_header" err
'
test_expect_success 'PLY: counts beyond the file size, unknown types, missing x y z' '
	printf "ply\nformat binary_little_endian 1.0\nelement vertex 100000000\nproperty float x\nproperty float y\nproperty float z\nend_header\n" >p3.ply &&
	test_memlimit test_fails_cleanly mesh-import p3.ply 2>err && grep "truncated: the PLY header announces at least 1200000000 bytes" err &&
	printf "ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n0\n" >p4.ply &&
	test_fails_cleanly mesh-import p4.ply 2>err && grep "bad property line" err &&
	printf "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n" >p5.ply &&
	test_fails_cleanly mesh-import p5.ply 2>err && grep "vertex element without x, y, z" err
'
test_expect_success 'PLY: a value that is not a number in an ascii body (OpenMesh grew without bound)' '
	printf "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1\377\377 2\n" >p9.ply &&
	test_fails_cleanly timeout 60 mesh-import p9.ply 2>err &&
	grep "p9.ply.: not a valid PLY file (line 13: a value that is not a number)" err
'
test_expect_success 'PLY: ascii list counts must fit their type and be followed by their values (OpenMesh read past EOF)' '
	h="ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n" &&
	printf "${h}365080832 0 1 2\n" >l1.ply &&
	test_fails_cleanly timeout 60 mesh-import l1.ply 2>err &&
	grep "l1.ply.: not a valid PLY file (line 13: face 0: list count of type uchar: an integer out of the range of its type)" err &&
	printf "${h}-3 0 1 2\n" >l2.ply &&
	test_fails_cleanly mesh-import l2.ply 2>err && grep "line 13: face 0: list count of type uchar" err &&
	printf "${h}4 0 1 2\n" >l3.ply &&
	test_fails_cleanly mesh-import l3.ply 2>err && grep "l3.ply.: truncated: the PLY file ends at line 14 inside face 0 of 1" err &&
	printf "${h}3 0 1.5 2\n" >l4.ply &&
	test_fails_cleanly mesh-import l4.ply 2>err && grep "line 13: a value of an integer type that is not an integer" err &&
	printf "${h}3 0 1 2\n7\n" >l5.ply &&
	test_fails_cleanly mesh-import l5.ply 2>err && grep "line 14: data after the last element" err &&
	printf "${h}3 0 1 2\n" >l6.ply && mesh-import l6.ply | mesh-info | grep "^faces 1$"
'
test_expect_success 'PLY: binary list counts checked against the bytes that follow' '
	printf "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list int int vertex_indices\nend_header\n" >b.ply &&
	head -c 36 /dev/zero >>b.ply && cp b.ply b2.ply &&
	printf "\000\000\000\100\000\000\000\000\001\000\000\000\002\000\000\000" >>b.ply &&
	test_fails_cleanly timeout 60 mesh-import b.ply 2>err &&
	grep "b.ply.: truncated: the PLY list at byte [0-9]* (face 0) announces 1073741824 values, the file has 12 bytes left" err &&
	printf "\375\377\377\377\000\000\000\000\001\000\000\000\002\000\000\000" >>b2.ply &&
	test_fails_cleanly mesh-import b2.ply 2>err && grep "b2.ply.: not a valid PLY file (byte [0-9]*: face 0: negative list count -3)" err
'
test_expect_success 'PLY: a valid file still imports (binary and ascii round trip)' '
	mesh-gen -s 1 icosphere >ico.mesh &&
	mesh-export -o ico.ply ico.mesh && mesh-import ico.ply | mesh-info | grep "^faces 80$" &&
	mesh-export --ascii -o icoa.ply ico.mesh && mesh-import icoa.ply | mesh-info | grep "^faces 80$"
'
test_expect_success 'OFF/OBJ: a header of 2*10^8 vertices reserves by the file size' '
	printf "OFF\n200000000 0 0\n" >big.off &&
	test_memlimit test_fails_cleanly mesh-import big.off 2>err &&
	grep "big.off.: line 2: expected 200000000 vertices, found 0" err
'
test_expect_success 'a missing file is named as missing, whatever its extension' '
	test_fails_cleanly mesh-import nope.mesh 2>err &&
	grep "cannot read .nope.mesh.: No such file or directory" err &&
	test_fails_cleanly mesh-import nope.obj 2>err && grep "No such file" err &&
	test_fails_cleanly mesh-import ico.ply nope.ply 2>err && grep "nope.ply.: No such file" err
'
test_expect_success 'glTF/FBX: content that is not the named format never reaches another assimp importer' '
	cp "$STOPMO_ROOT/tests/fuzz/regress/gltf/quick3d-2tb-alloc" q.gltf &&
	test_fails_cleanly mesh-import q.gltf 2>err &&
	grep "q.gltf.: not a glTF, GLB or FBX file" err &&
	cp q.gltf q.glb && test_fails_cleanly mesh-import q.glb 2>err && grep "q.glb.: not a glTF" err &&
	printf "{\"asset\":{\"version\":\"2.0\"}}" >j.fbx &&
	test_fails_cleanly mesh-import j.fbx 2>err && grep "j.fbx.: the file is glTF, not FBX" err
'
test_expect_success 'glTF: an animation channel without a target, or a target without a node, is refused before assimp crashes on it' '
	cp "$STOPMO_ROOT/tests/fuzz/regress/gltf/channel-without-target" c.gltf &&
	test_fails_cleanly mesh-import c.gltf 2>err &&
	grep "c.gltf.: animation 0 channel 0: it has no target" err &&
	cp "$STOPMO_ROOT/tests/fuzz/regress/gltf/target-without-node" n.gltf &&
	test_fails_cleanly mesh-import n.gltf 2>err && grep "n.gltf.: animation 0 channel 0: its target names no node" err
'
test_expect_success 'glTF: a sampler whose input accessor has no elements is refused before assimp divides by its count (SIGFPE)' '
	cp "$STOPMO_ROOT/tests/fuzz/regress/gltf/sampler-input-count-zero" z.gltf &&
	test_fails_cleanly mesh-import z.gltf 2>err &&
	grep "z.gltf.: animation 0 sampler 0: its input or output accessor has no elements (count 0" err
'
test_done
