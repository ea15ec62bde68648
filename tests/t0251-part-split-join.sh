#!/bin/sh
test_description='part-split and part-join: per-part streams, maps, seam gaps, closedness'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/seam-lib.sh"

test_expect_success 'setup: closed waving cylinder, labels by height, homogenized' '
	mesh-gen -f 10 -a wave -n 16 -m 12 --caps cylinder >cyl.mesh &&
	labels_by_z cyl.mesh 0.5 >cyl.lab &&
	test "$(closed cyl.mesh)" = closed &&
	seam-homog -l cyl.lab cyl.mesh >homog.mesh
'
test_expect_success 'part-split writes one stream and one map per part' '
	part-split -l cyl.lab -o "p_%d.mesh" -m "p_%d.map" homog.mesh &&
	test "$(count frames p_0.mesh)" = 10 && test "$(count frames p_1.mesh)" = 10 &&
	test "$(wc -l <p_0.map)" = "$(count vertices p_0.mesh)" &&
	test "$(wc -l <p_1.map)" = "$(count vertices p_1.mesh)" &&
	f0=$(count faces p_0.mesh) && f1=$(count faces p_1.mesh) &&
	test $((f0 + f1)) = "$(count faces cyl.mesh)"
'
test_expect_success 'the maps cover every input vertex; shared ones are the seam' '
	cat p_0.map p_1.map | sort -n | uniq | wc -l >nall &&
	test "$(cat nall)" = "$(count vertices cyl.mesh)" &&
	cat p_0.map p_1.map | sort -n | uniq -d | wc -l >nseam &&
	test "$(cat nseam)" = 16
'
test_expect_success 'part vertex positions are the input positions of their map' '
	awk "NR == FNR { m[FNR - 1] = \$1; next }
	     /^frame 3$/ { rd = 1; i = 0; next } /^frame / { rd = 0 }
	     rd { print m[i++], \$0 }" p_1.map p_1.mesh | sort -n >part.xyz &&
	awk "/^frame 3$/ { rd = 1; i = 0; next } /^frame / { rd = 0 }
	     rd { print i++, \$0 }" homog.mesh >all.xyz &&
	join part.xyz all.xyz | awk "\$2 != \$5 || \$3 != \$6 || \$4 != \$7 { bad++ }
	     END { exit bad > 0 }"
'
test_expect_success '--part K writes one part to stdout' '
	part-split -l cyl.lab --part 1 homog.mesh >one.mesh &&
	test_cmp p_1.mesh one.mesh
'
test_expect_success 'join top of frame 2 with bottom of frame 7: no gap, closed' '
	part-join -v --strict -f 7,2 p_0.mesh p_0.map p_1.mesh p_1.map >mix.mesh 2>mix.err &&
	grep "seam gap: max 0 " mix.err &&
	test "$(closed mix.mesh)" = closed &&
	mesh-info --check closed --check manifold mix.mesh &&
	test "$(count vertices mix.mesh)" = "$(count vertices cyl.mesh)" &&
	test "$(count faces mix.mesh)" = "$(count faces cyl.mesh)"
'
test_expect_success 'three parts with triple junctions: frames 1, 4, 7 mix without gap' '
	mesh-gen -f 8 -a wave -s 3 icosphere >ico.mesh &&
	awk "/^f /     { nf++; a[nf] = \$2; b[nf] = \$3; c[nf] = \$4; next }
	     /^frame / { if (\$2 + 0 > 0) exit; rd = 1; i = 0; next }
	     rd        { x[i] = \$1; z[i++] = \$3 }
	     END       { for (f = 1; f <= nf; f++) {
	                     cx = x[a[f]] + x[b[f]] + x[c[f]]; cz = z[a[f]] + z[b[f]] + z[c[f]]
	                     print (cz > 0 ? 0 : (cx > 0 ? 1 : 2)) } }" ico.mesh >ico.lab &&
	test "$(sort -u ico.lab | wc -l)" = 3 &&
	seam-homog -l ico.lab ico.mesh >ico.h &&
	part-split -l ico.lab -o "i_%d.mesh" -m "i_%d.map" ico.h &&
	part-join -v --strict -f 1,4,7 i_0.mesh i_0.map i_1.mesh i_1.map i_2.mesh i_2.map >ico.mix 2>ico.err &&
	grep "seam gap: max 0 " ico.err &&
	test "$(closed ico.mix)" = closed &&
	mesh-info --check closed ico.mix &&
	part-split -l ico.lab -o "u_%d.mesh" -m "u_%d.map" ico.mesh &&
	test_fails_cleanly part-join --strict -f 1,4,7 u_0.mesh u_0.map u_1.mesh u_1.map u_2.mesh u_2.map
'
test_expect_success 'joining all parts of one frame gives that frame back' '
	part-join -f 4 p_0.mesh p_0.map p_1.mesh p_1.map >j4.mesh &&
	awk "/^frame 4$/ { rd = 1; next } /^frame / { rd = 0 } rd" homog.mesh >want.xyz &&
	awk "/^frame 0$/ { rd = 1; next } rd" j4.mesh >got.xyz &&
	test_cmp want.xyz got.xyz
'
test_expect_success 'without homogenization the seam gap is reported; --strict fails' '
	part-split -l cyl.lab -o "r_%d.mesh" -m "r_%d.map" cyl.mesh &&
	part-join -f 1,4 r_0.mesh r_0.map r_1.mesh r_1.map >gap.mesh 2>gap.err &&
	grep "seam gap" gap.err &&
	test_fails_cleanly part-join --strict -f 1,4 r_0.mesh r_0.map r_1.mesh r_1.map &&
	grep "exceeds the tolerance" .err
'
test_expect_success 'streaming input: part-split reads standard input' '
	part-split -l cyl.lab -o "s_%d.mesh" <homog.mesh &&
	test_cmp p_0.mesh s_0.mesh
'
test_expect_success 'bad input: labels not matching faces' '
	sed 1d cyl.lab >short.lab &&
	test_fails_cleanly part-split -l short.lab -o "x_%d.mesh" homog.mesh &&
	test_must_fail test -e x_0.mesh
'
test_expect_success 'bad input: truncated stream leaves no part files' '
	head -n -2 homog.mesh >trunc.mesh &&
	test_fails_cleanly part-split -l cyl.lab -o "t_%d.mesh" -m "t_%d.map" trunc.mesh &&
	test_must_fail test -e t_0.mesh && test_must_fail test -e t_0.map
'
test_expect_success 'bad input: map not matching the piece, missing frame, overlap' '
	sed 1d p_0.map >short.map &&
	test_fails_cleanly part-join p_0.mesh short.map p_1.mesh p_1.map &&
	test_fails_cleanly part-join -f 10 p_0.mesh p_0.map p_1.mesh p_1.map &&
	test_fails_cleanly part-join p_0.mesh p_0.map p_0.mesh p_0.map
'
test_expect_success 'usage errors: bad patterns, odd arguments' '
	test_must_fail_usage part-split -l cyl.lab -o "p.mesh" homog.mesh 2>/dev/null &&
	test_must_fail_usage part-split -l cyl.lab -o "p_%d_%d.mesh" homog.mesh 2>/dev/null &&
	test_must_fail_usage part-split -l cyl.lab -o "p_%s.mesh" homog.mesh 2>/dev/null &&
	test_must_fail_usage part-join p_0.mesh 2>/dev/null &&
	test_must_fail_usage part-join -f 1,2,3 p_0.mesh p_0.map p_1.mesh p_1.map 2>/dev/null
'
test_expect_success 'usage errors: labels and the input (tool.h arg_labels_and_input)' '
	test_must_fail_usage part-split homog.mesh 2>err && grep -q "missing -l LABELS" err &&
	test_must_fail_usage part-split -l cyl.lab homog.mesh homog.mesh 2>err &&
	grep -q "at most one input" err &&
	test_must_fail_usage part-split -l - <homog.mesh 2>err && grep -q "both come from standard input" err &&
	test_must_fail_usage part-split -l - - <homog.mesh 2>err && grep -q "both come from standard input" err
'
test_done
