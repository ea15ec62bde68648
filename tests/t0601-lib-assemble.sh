#!/bin/sh
test_description='lib-assemble: replacement animation from part libraries, labels and maps'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/seam-lib.sh"

# frame K MESH: the vertex lines of frame K of a plain stream
frame() {
	awk -v k="$1" '/^frame / { rd = ($2 + 0 == k); next } rd' "$2"
}

# gap ERRFILE: the seam gap from lib-assemble -v
gap() {
	sed -n "s/.*largest seam gap //p" "$1"
}

# maxerr A B: anim-diff's max between two streams
maxerr() {
	anim-diff -s "$1" "$2" >maxerr.out && awk '$1 == "max" { print $2 }' maxerr.out
}

test_expect_success 'setup: closed waving tube, two parts by centroid height, one piece per frame' '
	mesh-gen -f 6 -a wave -n 12 -m 8 --caps cylinder >cyl.mesh &&
	labels_by_z cyl.mesh 0.3 >cyl.lab &&
	test "$(sort -u cyl.lab | wc -l)" = 2 &&
	part-split -l cyl.lab -o "p_%d.mesh" -m "p_%d.map" cyl.mesh &&
	lib-uniform -k 1 p_0.mesh >lib_0.mesh &&
	lib-uniform -k 1 p_1.mesh >lib_1.mesh &&
	test "$(count frames lib_0.mesh)" = 6 &&
	seq 0 5 >id.lab
'
test_expect_success 'all frames as pieces with identity labels reproduce the animation' '
	lib-assemble -v cyl.mesh lib_0.mesh:id.lab:p_0.map lib_1.mesh:id.lab:p_1.map \
		>out.mesh 2>out.err &&
	test "$(maxerr cyl.mesh out.mesh)" = 0 &&
	test "$(count vertices out.mesh)" = "$(count vertices cyl.mesh)" &&
	test "$(count frames out.mesh)" = 6 &&
	grep "^f " cyl.mesh >f.in && grep "^f " out.mesh >f.out && test_cmp f.in f.out
'
test_expect_success 'the parts share the seam vertices; the seam gap is 0 and the result closed' '
	cat p_0.map p_1.map | sort -n | uniq -d >seam &&
	test_le 12 "$(wc -l <seam)" &&
	grep "6 frames, 2 parts, largest seam gap 0$" out.err &&
	test "$(gap out.err)" = 0 &&
	mesh-info --check closed --check manifold out.mesh
'
test_expect_success 'each frame mounts its labelled piece' '
	lib-uniform -d 2 p_0.mesh >two_0.mesh && lib-uniform -d 2 p_1.mesh >two_1.mesh &&
	printf "0\n0\n0\n1\n1\n1\n" >hold.lab &&
	lib-assemble cyl.mesh two_0.mesh:hold.lab:p_0.map two_1.mesh:hold.lab:p_1.map >hold.mesh &&
	frame 3 cyl.mesh >want3 && frame 0 cyl.mesh >want0 &&
	frame 4 hold.mesh >got4 && frame 2 hold.mesh >got2 &&
	test_cmp want3 got4 && test_cmp want0 got2
'
test_expect_success 'after seam-homog any mix of frames closes without gap' '
	seam-homog -l cyl.lab cyl.mesh >homog.mesh &&
	part-split -l cyl.lab -o "h_%d.mesh" -m "h_%d.map" homog.mesh &&
	lib-uniform -k 1 h_0.mesh >hl_0.mesh && lib-uniform -k 1 h_1.mesh >hl_1.mesh &&
	seq 5 -1 0 >rev.lab &&
	lib-assemble -v homog.mesh hl_0.mesh:id.lab:h_0.map hl_1.mesh:rev.lab:h_1.map \
		>mix.mesh 2>mix.err &&
	test "$(gap mix.err)" = 0 &&
	mesh-info --check closed mix.mesh &&
	awk "NR == FNR { m[\$1]; next } /^frame 1\$/ { rd = 1; i = 0; next } /^frame / { rd = 0 }
	     rd { if (i in m) print i, \$0; i++ }" h_0.map homog.mesh >want.bot &&
	awk "NR == FNR { m[\$1]; next } /^frame 1\$/ { rd = 1; i = 0; next } /^frame / { rd = 0 }
	     rd { if (i in m) print i, \$0; i++ }" h_0.map mix.mesh >got.bot &&
	test_cmp want.bot got.bot &&
	awk "NR == FNR { m[\$1]; next } /^frame 4\$/ { rd = 1; i = 0; next } /^frame / { rd = 0 }
	     rd { if (i in m) print i, \$0; i++ }" h_1.map homog.mesh >want.top &&
	awk "NR == FNR { m[\$1]; next } /^frame 1\$/ { rd = 1; i = 0; next } /^frame / { rd = 0 }
	     rd { if (i in m) print i, \$0; i++ }" h_1.map mix.mesh >got.top &&
	test_cmp want.top got.top
'
test_expect_success 'without seam-homog the mix has a seam gap, reported with -v' '
	lib-assemble -v cyl.mesh lib_0.mesh:id.lab:p_0.map lib_1.mesh:rev.lab:p_1.map \
		>gap.mesh 2>gap.err &&
	test_le 0.01 "$(gap gap.err)" &&
	lib-assemble cyl.mesh lib_0.mesh:id.lab:p_0.map lib_1.mesh:rev.lab:p_1.map \
		>quiet.mesh 2>quiet.err &&
	test ! -s quiet.err && test_cmp gap.mesh quiet.mesh
'
test_expect_success 'three parts with triple junctions (labels by face index): no gap' '
	mesh-gen -f 5 -a twist -s 2 icosphere >ico.mesh &&
	awk "/^faces / { nf = \$2 } END { for (f = 0; f < nf; f++) print int(3 * f / nf) }" \
		ico.mesh >ico.lab &&
	test "$(sort -u ico.lab | wc -l)" = 3 &&
	seam-homog -l ico.lab ico.mesh >ico.h &&
	part-split -l ico.lab -o "i_%d.mesh" -m "i_%d.map" ico.h &&
	for p in 0 1 2; do lib-uniform -k 1 i_$p.mesh >il_$p.mesh || return 1; done &&
	printf "0\n1\n2\n3\n4\n" >i0.lab && printf "4\n3\n2\n1\n0\n" >i1.lab &&
	printf "2\n2\n2\n0\n0\n" >i2.lab &&
	lib-assemble -v ico.h il_0.mesh:i0.lab:i_0.map il_1.mesh:i1.lab:i_1.map \
		il_2.mesh:i2.lab:i_2.map >imix.mesh 2>imix.err &&
	test "$(gap imix.err)" = 0 &&
	mesh-info --check closed imix.mesh &&
	lib-assemble ico.h il_0.mesh:i0.lab:i_0.map il_1.mesh:i0.lab:i_1.map \
		il_2.mesh:i0.lab:i_2.map >iid.mesh &&
	test "$(maxerr ico.h iid.mesh)" = 0
'
test_expect_success 'vertices no part covers keep the base frame 0 position' '
	lib-assemble cyl.mesh lib_0.mesh:id.lab:p_0.map >half.mesh &&
	awk "NR == FNR { m[\$1]; next } /^frame 0\$/ { rd = 1; i = 0; next } /^frame / { rd = 0 }
	     rd { if (!(i in m)) print i, \$0; i++ }" p_0.map cyl.mesh >want.rest &&
	awk "NR == FNR { m[\$1]; next } /^frame 4\$/ { rd = 1; i = 0; next } /^frame / { rd = 0 }
	     rd { if (!(i in m)) print i, \$0; i++ }" p_0.map half.mesh >got.rest &&
	test -s want.rest && test_cmp want.rest got.rest
'
test_expect_success '-o writes the file atomically; --raw; BASE from standard input' '
	lib-assemble -o o.mesh cyl.mesh lib_0.mesh:id.lab:p_0.map lib_1.mesh:id.lab:p_1.map >o.stdout &&
	test ! -s o.stdout && test_cmp out.mesh o.mesh &&
	lib-assemble --raw cyl.mesh lib_0.mesh:id.lab:p_0.map lib_1.mesh:id.lab:p_1.map >raw.mesh &&
	head -c 10 raw.mesh >magic && printf "MESH 1 raw" >expect && test_cmp expect magic &&
	test "$(maxerr out.mesh raw.mesh)" = 0 &&
	lib-assemble - lib_0.mesh:id.lab:p_0.map lib_1.mesh:id.lab:p_1.map <cyl.mesh >in.mesh &&
	test_cmp out.mesh in.mesh
'
test_expect_success 'bad input: map count, vertex indices, labels, missing files' '
	test_fails_cleanly lib-assemble cyl.mesh lib_1.mesh:id.lab:p_0.map &&
	grep "rows, but there are 85 vertices in the library" .err &&
	mesh-gen -s 1 icosphere >small.mesh &&
	test_fails_cleanly lib-assemble small.mesh lib_1.mesh:id.lab:p_1.map &&
	grep "has 42 vertices" .err &&
	printf "0\n1\n2\n3\n4\n6\n" >oor.lab &&
	test_fails_cleanly lib-assemble cyl.mesh lib_0.mesh:oor.lab:p_0.map &&
	grep "row 6" .err &&
	printf "0\n-1\n2\n3\n4\n5\n" >neg.lab &&
	test_fails_cleanly lib-assemble cyl.mesh lib_0.mesh:neg.lab:p_0.map &&
	seq 0 4 >five.lab &&
	test_fails_cleanly lib-assemble cyl.mesh lib_0.mesh:id.lab:p_0.map lib_1.mesh:five.lab:p_1.map &&
	grep ".five.lab.: 5 labels, but .cyl.mesh. has 6 frames" .err &&
	printf "0\n1.5\n2\n3\n4\n5\n" >frac.lab &&
	test_fails_cleanly lib-assemble cyl.mesh lib_0.mesh:frac.lab:p_0.map &&
	printf "0\nabc\n" >word.lab &&
	test_fails_cleanly lib-assemble cyl.mesh lib_0.mesh:word.lab:p_0.map &&
	: >empty.lab &&
	test_fails_cleanly lib-assemble cyl.mesh lib_0.mesh:empty.lab:p_0.map &&
	awk "NR == 3 { print 0; next } { print }" p_0.map >dup.map &&
	test_fails_cleanly lib-assemble cyl.mesh lib_0.mesh:id.lab:dup.map &&
	grep "both name vertex 0" .err &&
	test_fails_cleanly lib-assemble nosuch.mesh lib_0.mesh:id.lab:p_0.map &&
	test_fails_cleanly lib-assemble cyl.mesh nosuch.mesh:id.lab:p_0.map &&
	test_fails_cleanly lib-assemble cyl.mesh lib_0.mesh:nosuch.lab:p_0.map &&
	test_fails_cleanly lib-assemble cyl.mesh lib_0.mesh:id.lab:nosuch.map &&
	grep "nosuch.map" .err
'
test_expect_success 'bad input: broken streams, nothing left behind with -o' '
	printf "MESH 1\nvertices 3\nfaces 1\nframes 0\nf 0 1 2\n" >noframes.mesh &&
	test_fails_cleanly lib-assemble noframes.mesh lib_0.mesh:id.lab:p_0.map &&
	grep "no frames" .err &&
	head -n 200 lib_0.mesh >trunc.mesh &&
	test_fails_cleanly lib-assemble cyl.mesh trunc.mesh:id.lab:p_0.map &&
	test_fails_cleanly lib-assemble -o bad.mesh cyl.mesh lib_0.mesh:oor.lab:p_0.map &&
	test ! -e bad.mesh && ls >files && ! grep -q "bad.mesh" files
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage lib-assemble >u.out 2>u.err &&
	test_must_fail_usage lib-assemble cyl.mesh >>u.out 2>>u.err &&
	test_must_fail_usage lib-assemble cyl.mesh lib_0.mesh:id.lab >>u.out 2>>u.err &&
	test_must_fail_usage lib-assemble cyl.mesh lib_0.mesh::p_0.map >>u.out 2>>u.err &&
	test_must_fail_usage lib-assemble cyl.mesh :id.lab:p_0.map >>u.out 2>>u.err &&
	test_must_fail_usage lib-assemble - lib_0.mesh:-:p_0.map <cyl.mesh >>u.out 2>>u.err &&
	test_must_fail_usage lib-assemble --bogus cyl.mesh lib_0.mesh:id.lab:p_0.map >>u.out 2>>u.err &&
	test ! -s u.out
'
test_expect_success '--help and --version' '
	lib-assemble --help >help && grep "^Usage: lib-assemble" help && grep "Example" help &&
	lib-assemble --version >v && grep "^lib-assemble (stopmo)" v
'
test_done
