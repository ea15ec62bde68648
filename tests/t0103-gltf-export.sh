#!/bin/sh
test_description='mesh-export glTF: static, morph animation with clips, replacement pieces; mesh-import gives the frames back'
. "$(dirname "$0")/test-lib.sh"

# largest vertex distance between two animations (same #V)
maxdiff() { anim-diff -s "$1" "$2" | awk '$1 == "max" { print $2 }'; }

test_expect_success 'a static mesh through .glb and .gltf' '
	mesh-gen -s 2 icosphere >ico.mesh &&
	mesh-export -o ico.glb ico.mesh && head -c 4 ico.glb >magic && printf glTF >expect && test_cmp expect magic &&
	mesh-import ico.glb >back.mesh && grep "^frames 1$" back.mesh &&
	head -5 ico.mesh | grep -v frames >h1 && head -5 back.mesh | grep -v frames >h2 && test_cmp h1 h2 &&
	grep "^f " ico.mesh >f1 && grep "^f " back.mesh >f2 && test_cmp f1 f2 &&
	test_le "$(maxdiff ico.mesh back.mesh)" 1e-7 &&
	mesh-export -o ico.gltf ico.mesh && test -s ico.bin && grep -q "\"uri\":\"ico.bin\"" ico.gltf &&
	mesh-import ico.gltf >back2.mesh && test_cmp back.mesh back2.mesh
'

test_expect_success 'an animation: every frame a morph target, one key per frame at --fps' '
	mesh-gen -f 7 -a wave grid >w.mesh &&
	mesh-export -o w.glb w.mesh &&
	mesh-import -v w.glb >wb.mesh 2>log && cat log &&
	grep "(7 morph targets), animation 0 .w. (7 keys, 0.250 s)" log &&
	grep "^frames 7$" wb.mesh && test_le "$(maxdiff w.mesh wb.mesh)" 1e-7 &&
	mesh-export --fps 12 -o w12.gltf w.mesh && mesh-import -v w12.gltf >w12.mesh 2>log12 &&
	grep "(7 keys, 0.500 s)" log12 && test_le "$(maxdiff w.mesh w12.mesh)" 1e-7 &&
	grep -q "\"interpolation\":\"STEP\"" w12.gltf &&
	grep -q "\"targetNames\":\[\"frame_0000\"" w12.gltf &&
	grep -q "\"count\":49,\"type\":\"SCALAR\",\"sparse\":{\"count\":7," w12.gltf
'

test_expect_success 'vertex normals: unit, and morph targets carry normal deltas' '
	grep -q "\"NORMAL\":[0-9]*},\"indices\"" w12.gltf &&
	grep -q "\"targets\":\[{\"POSITION\":[0-9]*,\"NORMAL\":[0-9]*}" w12.gltf
'

test_expect_success 'clip cuts become separate glTF animations and come back as cuts' '
	mesh-gen -f 9 -a twist --cut-every 4 cylinder >c.mesh &&
	grep "^frame.*cut" c.mesh >cuts && test $(wc -l <cuts) -eq 2 &&
	mesh-export -o c.glb c.mesh &&
	mesh-import -v c.glb >cb.mesh 2>log && cat log && grep "3 animations" log &&
	grep "^frame" c.mesh >e && grep "^frame" cb.mesh >a && test_cmp e a &&
	test_le "$(maxdiff c.mesh cb.mesh)" 1e-6 &&
	mesh-import --animation c_clip_1 c.glb >clip1.mesh && grep "^frames 4$" clip1.mesh
'

test_expect_success 'glTF on stdout embeds its buffer; the same bytes twice' '
	mesh-export -f gltf c.mesh >emb.gltf && grep -q "data:application/octet-stream;base64," emb.gltf &&
	mesh-import emb.gltf >emb.mesh && test_cmp cb.mesh emb.mesh &&
	mesh-export -f glb c.mesh >c2.glb && cmp c.glb c2.glb &&
	mesh-export -f glb <c.mesh >c3.glb && mesh-import -v c3.glb 2>log3 >/dev/null && grep "mesh 0 .mesh." log3
'

# two parts: an icosphere with 3 pieces and a grid with 4
test_expect_success 'a replacement animation with 2 parts: one mesh per part, pieces as targets' '
	mesh-gen -s 1 -f 3 -a wave icosphere >lib0.mesh &&
	mesh-gen -n 4 -f 4 -a bend grid >lib1.mesh &&
	printf "0\n2\n1\n1\n0\n2\n" >lab0 && printf "3\n3\n0\n1\n2\n0\n" >lab1 &&
	mesh-export -v -o film.glb --pieces lib0.mesh:lab0 --pieces lib1.mesh:lab1 2>log && cat log &&
	mesh-import -v --mesh part_0 film.glb >p0.mesh 2>l0 && grep "(3 morph targets)" l0 &&
	mesh-import -v --mesh part_1 film.glb >p1.mesh 2>l1 && grep "(4 morph targets)" l1 &&
	grep "^frames 6$" p0.mesh && grep "^frames 6$" p1.mesh &&
	seq 0 $(( $(sed -n 2p lib0.mesh | cut -d" " -f2) - 1 )) >id0 &&
	seq 0 $(( $(sed -n 2p lib1.mesh | cut -d" " -f2) - 1 )) >id1 &&
	lib-assemble lib0.mesh lib0.mesh:lab0:id0 >film0.mesh &&
	lib-assemble lib1.mesh lib1.mesh:lab1:id1 >film1.mesh &&
	test_le "$(maxdiff film0.mesh p0.mesh)" 1e-7 &&
	test_le "$(maxdiff film1.mesh p1.mesh)" 1e-7 &&
	mesh-import film.glb >any.mesh 2>err && cat err &&
	grep "warning: .film.glb.: 2 meshes have morph targets; took mesh 0 .part_0. (choose with --mesh)" err &&
	mesh-export -o film.gltf --pieces lib0.mesh:lab0 --pieces lib1.mesh:lab1 &&
	mesh-import --mesh part_1 film.gltf >q1.mesh && test_cmp p1.mesh q1.mesh
'

test_expect_success 'the one-hot weights show exactly one piece per frame' '
	mesh-export -f gltf --pieces lib0.mesh:lab0 >one.gltf &&
	mesh-import --mesh part_0 one.gltf >one.mesh && test_cmp p0.mesh one.mesh
'

test_expect_success 'bad pieces and labels fail cleanly, nothing written' '
	printf "0\n3\n" >bad && test_fails_cleanly mesh-export -o x.glb --pieces lib0.mesh:bad &&
	printf "0\n1\n" >short && test_fails_cleanly mesh-export -o x.glb --pieces lib0.mesh:lab0 --pieces lib1.mesh:short &&
	test_fails_cleanly mesh-export -o x.glb --pieces nope.mesh:lab0 &&
	test ! -e x.glb && ! ls x.glb.tmp* 2>/dev/null &&
	test_must_fail_usage mesh-export -o x.obj --pieces lib0.mesh:lab0 &&
	test_must_fail_usage mesh-export -o x.glb --pieces lib0.mesh &&
	test_must_fail_usage mesh-export -o x.glb --pieces lib0.mesh:lab0 w.mesh &&
	test_must_fail_usage mesh-export -o x.glb --fps 0 w.mesh
'

test_expect_success 'a stream broken midway writes no glTF' '
	head -n $(( $(wc -l <w.mesh) - 3 )) w.mesh >broken.mesh &&
	test_fails_cleanly mesh-export -o br.glb broken.mesh &&
	test_fails_cleanly mesh-export -o br.gltf broken.mesh &&
	test ! -e br.glb && test ! -e br.gltf && test ! -e br.bin && ! ls br.*tmp* 2>/dev/null
'

test_expect_success '--frame K and %d patterns write static glTF files' '
	mesh-export -k 3 -o f3.glb w.mesh && mesh-import f3.glb >f3.mesh && grep "^frames 1$" f3.mesh &&
	mkdir g && mesh-export -o "g/w_%d.glb" w.mesh && test $(ls g | wc -l) -eq 7 &&
	mesh-import g/w_3.glb >g3.mesh && test_cmp f3.mesh g3.mesh
'
test_done
