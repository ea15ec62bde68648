#!/bin/sh
test_description='seam-homog: constant seams, minimal energy, streaming, bad input'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/seam-lib.sh"

test_expect_success 'setup: waving closed cylinder and icosphere, labels by height' '
	mesh-gen -f 12 -a wave -n 16 -m 12 --caps cylinder >cyl.mesh &&
	labels_by_z cyl.mesh 0.5 >cyl.lab &&
	mesh-gen -f 9 -a wave -s 3 icosphere >ico.mesh &&
	labels_by_z ico.mesh 0.2 >ico.lab &&
	test "$(sort -u cyl.lab | wc -l)" = 2 &&
	test "$(wc -l <cyl.lab)" = "$(count faces cyl.mesh)"
'
test_expect_success 'the input seam moves (otherwise the test proves nothing)' '
	d=$(fixed_drift cyl.mesh cyl.lab) && echo "input drift $d" &&
	test_le 1e-3 "$d"
'
test_expect_success 'seam and one-ring vertices identical in every frame (cylinder)' '
	seam-homog -l cyl.lab cyl.mesh >cyl.out &&
	test "$(count frames cyl.out)" = 12 &&
	test "$(count vertices cyl.out)" = "$(count vertices cyl.mesh)" &&
	d=$(fixed_drift cyl.out cyl.lab) && echo "output drift $d" &&
	test_le "$d" 1e-12
'
test_expect_success 'seam and one-ring vertices identical in every frame (icosphere)' '
	seam-homog -l ico.lab -o ico.out ico.mesh &&
	d=$(fixed_drift ico.out ico.lab) && echo "output drift $d" &&
	test_le "$d" 1e-12 &&
	test_le 1e-3 "$(max_motion ico.out)"
'
test_expect_success 'the solution is minimal: perturbations raise the energy (--check)' '
	seam-homog -v --check 30 --seed 3 -l cyl.lab cyl.mesh >chk.out 2>chk.err &&
	grep "smallest relative energy increase" chk.err &&
	test_cmp cyl.out chk.out
'
test_expect_success '--energy writes one energy per frame, -v prints the same and frames/s' '
	seam-homog -v --energy e.txt -l cyl.lab cyl.mesh >/dev/null 2>v.err &&
	test "$(wc -l <e.txt)" = 12 &&
	grep "frames/s" v.err &&
	test "$(grep -c "frame [0-9]*: energy" v.err)" = 12 &&
	e0=$(sed -n 1p e.txt) && v0=$(sed -n "s/.*frame 0: energy //p" v.err) &&
	test_near "$e0" "$v0" "$(awk -v e="$e0" "BEGIN{print 1e-8*e}")"
'
test_expect_success 'standard input (spooled) gives the same bytes as a file' '
	seam-homog -l cyl.lab <cyl.mesh >stdin.out &&
	test_cmp cyl.out stdin.out
'
test_expect_success 'a streamed header (frames ?) on stdin: the real count is written' '
	sed "s/^frames .*/frames ?/" cyl.mesh >q.mesh &&
	seam-homog -l cyl.lab <q.mesh >q.out &&
	test_cmp cyl.out q.out
'
test_expect_success 'raw input and output give the same numbers' '
	STOPMO_RAW=1 mesh-gen -f 12 -a wave -n 16 -m 12 --caps cylinder >cyl.raw &&
	seam-homog -l cyl.lab --raw cyl.raw >out.raw &&
	head -1 out.raw >magic && echo "MESH 1 raw" >expect && test_cmp expect magic &&
	seam-homog -l cyl.lab cyl.raw >out.plain &&
	test_cmp cyl.out out.plain
'
test_expect_success 'factor once, refactor each frame, any batch size agree' '
	seam-homog -l cyl.lab --refactor-each-frame cyl.mesh >re.out &&
	d=$(max_diff cyl.out re.out) && echo "refactor: $d" && test_le "$d" 1e-13 &&
	seam-homog -l cyl.lab --batch 1 cyl.mesh >b1.out &&
	d=$(max_diff cyl.out b1.out) && echo "batch 1: $d" && test_le "$d" 1e-13 &&
	seam-homog -l cyl.lab --batch 5 cyl.mesh >b5.out &&
	d=$(max_diff cyl.out b5.out) && echo "batch 5: $d" && test_le "$d" 1e-13 &&
	d=$(fixed_drift b5.out cyl.lab) && test_le "$d" 1e-12
'
test_expect_success 'clip cut marks pass through' '
	mesh-gen -f 12 -a wave -n 16 -m 12 --caps --cut-every 5 cylinder >cut.mesh &&
	seam-homog -l cyl.lab cut.mesh >cut.out &&
	grep "^frame" cut.mesh >expect && grep "^frame" cut.out >actual &&
	test_cmp expect actual && grep -q "frame 5 cut" actual
'
test_expect_success '--rings 2 fixes a larger set, still constant; --rings 0 lets the ring move' '
	seam-homog -l cyl.lab --rings 2 cyl.mesh >r2.out &&
	test_le "$(fixed_drift r2.out cyl.lab)" 1e-12 &&
	seam-homog -l cyl.lab --rings 0 cyl.mesh >r0.out &&
	test_le 1e-9 "$(fixed_drift r0.out cyl.lab)"
'
test_expect_success 'one label only: the animation passes unchanged, with a warning' '
	awk "{print 0}" cyl.lab >one.lab &&
	seam-homog -l one.lab cyl.mesh >one.out 2>one.err &&
	grep "no seam" one.err &&
	test_cmp cyl.mesh one.out
'
test_expect_success 'bad input: labels not matching faces' '
	sed 1d cyl.lab >short.lab &&
	test_fails_cleanly seam-homog -l short.lab cyl.mesh
'
test_expect_success 'bad input: negative or fractional label' '
	sed "1s/.*/-1/" cyl.lab >neg.lab &&
	test_fails_cleanly seam-homog -l neg.lab cyl.mesh &&
	sed "1s/.*/0.5/" cyl.lab >frac.lab &&
	test_fails_cleanly seam-homog -l frac.lab cyl.mesh
'
test_expect_success 'bad input: non-manifold edge on the seam' '
	cat >fin.mesh <<-\EOT &&
	MESH 1
	vertices 5
	faces 3
	frames 2
	f 0 1 2
	f 1 0 3
	f 0 1 4
	frame 0
	0 0 0
	1 0 0
	0.5 1 0
	0.5 -1 0
	0.5 0 1
	frame 1
	0 0 0.1
	1 0 0
	0.5 1 0
	0.5 -1 0
	0.5 0 1
	EOT
	printf "0\n1\n1\n" >fin.lab &&
	test_fails_cleanly seam-homog -l fin.lab fin.mesh &&
	grep "non-manifold edge 0-1" .err
'
test_expect_success 'bad input: truncated stream fails before any output' '
	head -n -3 cyl.mesh >trunc.mesh &&
	test_fails_cleanly seam-homog -l cyl.lab trunc.mesh &&
	test_fails_cleanly seam-homog -l cyl.lab <trunc.mesh
'
test_expect_success 'usage errors' '
	test_must_fail_usage seam-homog cyl.mesh 2>/dev/null &&
	test_must_fail_usage seam-homog -l cyl.lab --rings -1 cyl.mesh 2>/dev/null &&
	seam-homog --help >help.txt && grep Usage help.txt
'
test_expect_success 'usage errors: labels and the input (tool.h arg_labels_and_input)' '
	test_must_fail_usage seam-homog cyl.mesh 2>err && grep -q "missing -l LABELS" err &&
	test_must_fail_usage seam-homog -l cyl.lab cyl.mesh cyl.mesh 2>err &&
	grep -q "at most one input" err &&
	test_must_fail_usage seam-homog -l - <cyl.mesh 2>err && grep -q "both come from standard input" err &&
	test_must_fail_usage seam-homog -l - - <cyl.mesh 2>err && grep -q "both come from standard input" err
'
test_done
