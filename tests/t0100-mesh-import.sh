#!/bin/sh
test_description='mesh-import: OBJ, OFF, PLY, STL, OBJ frame sequences, welding, bad input'
. "$(dirname "$0")/test-lib.sh"

# max |a - b| / max |b| over the vertex lines of two MESH streams
# (plain, same header); prints the relative deviation
rel_dev() {
	paste -d' ' "$1" "$2" | awk 'NF == 6 && $1 != "f" {
		for (i = 1; i <= 3; i++) { d = $i - $(i + 3); if (d < 0) d = -d; if (d > m) m = d;
			a = $(i + 3); if (a < 0) a = -a; if (a > s) s = a }
	} END { printf "%.3g\n", s > 0 ? m / s : m }'
}

test_expect_success 'OBJ -> MESH -> OBJ keeps faces exactly and positions to 1e-9' '
	mesh-gen -s 2 icosphere >ico.mesh &&
	mesh-export -o a.obj ico.mesh &&
	mesh-import a.obj >a.mesh &&
	mesh-export -o b.obj a.mesh &&
	grep "^f" a.obj >fa && grep "^f" b.obj >fb && test_cmp fa fb &&
	mesh-import b.obj >b.mesh &&
	test_le "$(rel_dev ico.mesh b.mesh)" 1e-9 &&
	test_le "$(rel_dev a.mesh b.mesh)" 1e-9
'

test_expect_success 'OBJ with digits beyond float precision survives the round trip' '
	cat >p.obj <<-\EOT &&
	v 0.1234567890123456 1e-300 -123456.7890123456
	v 1 0 0
	v 0 1 0
	f 1 2 3
	EOT
	mesh-import p.obj >p.mesh &&
	mesh-export p.mesh >q.obj &&
	mesh-import q.obj >q.mesh &&
	test_cmp p.mesh q.mesh &&
	grep -q "^0.1234567890123456 1e-300 -123456.7890123456$" p.mesh
'

test_expect_success 'quads and polygons are fan-triangulated, orientation kept' '
	cat >quad.obj <<-\EOT &&
	# a unit square and a pentagon, with texture coordinates and normals
	mtllib none.mtl
	o square
	v 0 0 0
	v 1 0 0
	v 1 1 0
	v 0 1 0
	v 2 0 0
	vt 0 0
	vn 0 0 1
	usemtl skin
	s off
	f 1/1/1 2/1/1 3/1/1 4/1/1
	f -4//1 -1//1 -3//1
	EOT
	mesh-import quad.obj >quad.mesh &&
	cat >expect <<-\EOT &&
	MESH 1
	vertices 5
	faces 3
	frames 1
	f 0 1 2
	f 0 2 3
	f 1 4 2
	EOT
	head -7 quad.mesh >actual && test_cmp expect actual
'

test_expect_success 'OFF with a quad and comments' '
	cat >sq.off <<-\EOT &&
	OFF
	# a square
	4 1 0
	0 0 0
	1 0 0
	1 1 0
	0 1 0
	4 0 1 2 3 255 0 0
	EOT
	mesh-import sq.off >sq.mesh &&
	grep "^f [0-9]" sq.mesh >actual &&
	printf "f 0 1 2\nf 0 2 3\n" >expect && test_cmp expect actual
'

test_expect_success 'STL import/export round trip (binary and ASCII)' '
	mesh-gen -s 2 icosphere >s.mesh &&
	mesh-export -o s.stl s.mesh &&
	test $(wc -c <s.stl) -eq $((84 + 50 * 320)) &&
	mesh-import s.stl >s2.mesh &&
	head -4 s2.mesh >h2 && head -4 s.mesh >h1 && test_cmp h1 h2 &&
	mesh-export --ascii -o sa.stl s.mesh &&
	head -c 5 sa.stl >magic && printf solid >expect && test_cmp expect magic &&
	mesh-import sa.stl >s3.mesh &&
	head -4 s3.mesh >h3 && test_cmp h1 h3
'

test_expect_success 'STL round trip keeps every triangle (as a position set, float precision)' '
	mesh-export -f obj s2.mesh >s2.obj &&
	awk "/^v /{ v[++n] = sprintf(\"%.5f %.5f %.5f\", \$2, \$3, \$4) }
	     /^f /{ print v[\$2] \"|\" v[\$3] \"|\" v[\$4] }" s2.obj | sort >tri2 &&
	mesh-export -f obj s.mesh >s.obj &&
	awk "/^v /{ v[++n] = sprintf(\"%.5f %.5f %.5f\", \$2, \$3, \$4) }
	     /^f /{ print v[\$2] \"|\" v[\$3] \"|\" v[\$4] }" s.obj | sort >tri1 &&
	test_cmp tri1 tri2
'

test_expect_success 'PLY import/export round trip (binary and ASCII)' '
	mesh-export -o s.ply s.mesh && mesh-import s.ply >p2.mesh &&
	head -4 p2.mesh >hp && test_cmp h1 hp &&
	grep "^f" p2.mesh >fp && grep "^f" s.mesh >fs && test_cmp fs fp &&
	test_le "$(rel_dev s.mesh p2.mesh)" 1e-6 &&
	mesh-export --ascii -o sa.ply s.mesh && mesh-import sa.ply >p3.mesh &&
	head -2 sa.ply | tail -1 >fmt && echo "format ascii 1.0" >expect && test_cmp expect fmt &&
	grep "^f" p3.mesh >fp3 && test_cmp fs fp3
'

test_expect_success 'OBJ frames (glob, list, arguments) -> animation' '
	mesh-gen -f 6 -a twist -n 6 cylinder >anim.mesh &&
	mkdir fr && mesh-export -o "fr/frame_%03d.obj" anim.mesh &&
	mesh-import "fr/frame_*.obj" >glob.mesh &&
	test_le "$(rel_dev anim.mesh glob.mesh)" 1e-9 &&
	grep "^frames 6$" glob.mesh &&
	ls fr/*.obj >list && mesh-import --list list >list.mesh && test_cmp glob.mesh list.mesh &&
	mesh-import fr/frame_000.obj fr/frame_001.obj >two.mesh && grep "^frames 2$" two.mesh
'

test_expect_success 'a frame with different connectivity is an error naming that file' '
	mesh-gen -n 5 cylinder >other.mesh && mesh-export -o fr/frame_003.obj other.mesh &&
	test_fails_cleanly mesh-import "fr/frame_*.obj" &&
	grep "fr/frame_003.obj" "$TRASH/.err" &&
	mesh-gen -f 6 -a twist -n 6 -m 7 cylinder | mesh-export -k 2 -o fr/frame_004.obj &&
	mesh-export -k 3 -o fr/frame_003.obj anim.mesh &&
	test_fails_cleanly mesh-import "fr/frame_*.obj" &&
	grep "fr/frame_004.obj" "$TRASH/.err"
'

test_expect_success '--weld merges vertices split at a seam' '
	cat >seam.obj <<-\EOT &&
	v 0 0 0
	v 1 0 0
	v 1 1 0
	v 0 0 0
	v 1 1 0
	v 0 1 0
	f 1 2 3
	f 4 5 6
	EOT
	mesh-import --weld seam.obj >w.mesh &&
	grep "^vertices 4$" w.mesh && grep "^f 0 2 3$" w.mesh &&
	mesh-import seam.obj >nw.mesh && grep "^vertices 6$" nw.mesh &&
	sed "s/^v 0 1 0$/v 0 1 0/; 4s/.*/v 0 0 1e-7/" seam.obj >seam2.obj &&
	mesh-import --weld seam2.obj >w0.mesh && grep "^vertices 5$" w0.mesh &&
	mesh-import --weld 1e-6 seam2.obj >w1.mesh && grep "^vertices 4$" w1.mesh &&
	mesh-import --weld=1e-6 seam2.obj >w2.mesh && test_cmp w1.mesh w2.mesh
'

test_expect_success 'stdin with --format' '
	mesh-import --format obj - <a.obj >stdin.mesh && test_cmp a.mesh stdin.mesh &&
	mesh-import -F stl - <s.stl >stdin2.mesh && test_cmp s2.mesh stdin2.mesh &&
	test_must_fail_usage mesh-import - <a.obj
'

test_expect_success 'raw output' '
	mesh-import --raw a.obj >a.raw && head -1 a.raw >magic &&
	echo "MESH 1 raw" >expect && test_cmp expect magic
'

test_expect_success 'missing file, unknown extension, garbage are clean errors' '
	test_fails_cleanly mesh-import nope.obj &&
	echo "x" >x.xyz && test_fails_cleanly mesh-import x.xyz &&
	printf "hello world\n" >t.obj && test_fails_cleanly mesh-import t.obj &&
	printf "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n" >r.obj && test_fails_cleanly mesh-import r.obj &&
	grep "line 4" "$TRASH/.err" &&
	printf "v 0 0 nan\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" >n.obj && test_fails_cleanly mesh-import n.obj &&
	printf "v 0 0 0\n" >nf.obj && test_fails_cleanly mesh-import nf.obj &&
	printf "OFF\n3 1 0\n0 0 0\n1 0 0\n" >tr.off && test_fails_cleanly mesh-import tr.off &&
	printf "hello world\n" >t.stl && test_fails_cleanly mesh-import t.stl &&
	awk "BEGIN { for (i = 0; i < 3000; i++) printf \"%c\", (i * 7919) % 251 }" >g.stl &&
	test_fails_cleanly mesh-import g.stl &&
	cp g.stl g.ply && test_fails_cleanly mesh-import g.ply &&
	cp g.stl g.glb && test_fails_cleanly mesh-import g.glb &&
	cp g.stl g.obj && test_fails_cleanly mesh-import g.obj &&
	test_fails_cleanly mesh-import "nomatch_*.obj"
'

test_expect_success 'usage errors exit 2' '
	test_must_fail_usage mesh-import &&
	test_must_fail_usage mesh-import --fps -1 a.obj &&
	test_must_fail_usage mesh-import --format xyz a.obj &&
	test_must_fail_usage mesh-import --bogus a.obj &&
	mesh-import --help >help && grep -q "^Usage: mesh-import" help &&
	mesh-import --version >v && grep -q "stopmo" v
'
test_done
