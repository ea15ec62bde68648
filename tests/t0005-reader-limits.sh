#!/bin/sh
test_description='text readers hold their limits (issue 13): frames >= 1,
no NUL in a text line, lines of at most 1 MiB, header counts that do not
turn into allocations before the data are seen, columns rows with numbers,
landmark messages after the columns are freed'
. "$(dirname "$0")/test-lib.sh"


test_expect_success 'setup' '
	mesh-gen -s 1 icosphere >ico.mesh &&
	printf "MESH 1\nvertices 3\nfaces 1\nframes 0\nf 0 1 2\n" >zero.mesh &&
	echo 0 >labels
'
test_expect_success 'frames 0 is refused by every reader (not a valid empty stream)' '
	test_fails_cleanly mesh-info -q zero.mesh 2>err &&
	grep "zero.mesh.: line 4: stream has no frames (.frames 0.; at least 1)" err &&
	test_fails_cleanly anim-avg zero.mesh &&
	test_fails_cleanly anim-cat zero.mesh zero.mesh &&
	test_fails_cleanly mesh-normalize zero.mesh &&
	test_fails_cleanly part-split -l labels -o "p%d.mesh" zero.mesh &&
	test_fails_cleanly seam-homog -l labels zero.mesh &&
	test_fails_cleanly seam-smooth -l labels -L new zero.mesh &&
	test_fails_cleanly seam-smooth -l labels -L new <zero.mesh &&
	! ls p*.mesh 2>/dev/null
'
test_expect_success 'a NUL byte in a text line is an error, not the end of the line' '
	printf "MESH 1\nvertices 3\nfaces 1\nframes 1\nf 0 1 2\nframe 0\n0 0 0\n1 0 0 \0junk\n0 1 0\n" >nul.mesh &&
	test_fails_cleanly mesh-info -q nul.mesh 2>err &&
	grep "nul.mesh.: line 8: NUL byte" err &&
	test_fails_cleanly anim-slice <nul.mesh
'
test_expect_success 'a zero-filled tail (a crashed write) does not pass as blank lines' '
	cp ico.mesh tail.mesh && head -c 4096 /dev/zero >>tail.mesh &&
	test_fails_cleanly mesh-info -q tail.mesh 2>err && grep "NUL byte" err
'
test_expect_success 'a NUL in a columns or rings file is an error' '
	printf "1\n2\0\n3\n" >nul.txt &&
	test_fails_cleanly plot-xy nul.txt 2>err && grep "nul.txt.: line 2: NUL byte" err &&
	printf "ring 3\n0 0\n1 0\0 7\n0 1\n" >nul.rings &&
	test_fails_cleanly mesh2svg nul.rings 2>err &&
	grep "nul.rings.: line 3: NUL byte" err
'
test_expect_success 'a line over 1 MiB (a runaway comment) is refused in every text reader' '
	awk "BEGIN { printf \"#\"; for (i = 0; i < 1100000; i++) printf \"x\"; printf \"\n\" }" >long &&
	{ head -1 ico.mesh; cat long; tail -n +2 ico.mesh; } >long.mesh &&
	test_fails_cleanly mesh-info -q long.mesh 2>err && grep "long.mesh.: line 2: line longer than 1048576 bytes" err &&
	{ cat long; echo 1; echo 2; } >long.txt &&
	test_fails_cleanly plot-xy long.txt 2>err && grep "line 1: line longer" err &&
	{ echo "ring 3"; cat long; printf "0 0\n1 0\n0 1\n"; } >long.rings &&
	test_fails_cleanly mesh2svg long.rings 2>err && grep "line 2: line longer" err &&
	mesh-export -f obj ico.mesh >ico.obj && { cat long; cat ico.obj; } >long.obj &&
	test_fails_cleanly mesh-import long.obj 2>err && grep "long.obj.: line 1: line longer" err
'
test_expect_success 'a line just under the cap still reads' '
	awk "BEGIN { printf \"#\"; for (i = 0; i < 1000000; i++) printf \"x\"; printf \"\n\" }" >ok &&
	{ head -1 ico.mesh; cat ok; tail -n +2 ico.mesh; } >ok.mesh && mesh-info -q ok.mesh
'
test_expect_success 'huge header counts fail as truncated, not out of memory (file)' '
	printf "MESH 1\nvertices 10\nfaces 0\nframes 200000000\nframe 0\n" >many.mesh &&
	for i in 0 1 2 3 4 5 6 7 8 9; do echo "0 0 0"; done >>many.mesh &&
	test_memlimit test_fails_cleanly procrustes many.mesh many.mesh 2>err &&
	grep "truncated" err &&
	printf "MESH 1\nvertices 200000000\nfaces 0\nframes 1\n" >wide.mesh &&
	test_memlimit test_fails_cleanly mesh-info -q wide.mesh 2>err && grep "truncated" err &&
	printf "MESH 1\nvertices 3\nfaces 200000000\nframes 1\nf 0 1 2\n" >faces.mesh &&
	test_memlimit test_fails_cleanly mesh-info -q faces.mesh 2>err && grep "truncated" err
'
test_expect_success 'huge header counts from a pipe: storage grows with the data' '
	cat many.mesh | test_memlimit test_fails_cleanly procrustes - many.mesh 2>err &&
	grep "truncated: expected 200000000 frames, got 1" err &&
	cat faces.mesh | test_memlimit test_fails_cleanly mesh-info -q 2>err &&
	grep "truncated: expected 200000000 faces, got 1" err &&
	printf "MESH 1 raw\nvertices 3\nfaces 200000000\nframes 1\n" >rawf.mesh &&
	cat rawf.mesh | test_memlimit test_fails_cleanly mesh-info -q 2>err && grep "truncated face block" err
'
test_expect_success 'a ring header announcing 10^8 points reserves nothing up front' '
	printf "ring 100000000\n0 0\n1 0\n0 1\n" >big.rings &&
	test_memlimit test_fails_cleanly mesh2svg big.rings 2>err &&
	grep "header says 100000000" err
'
test_expect_success 'many faces still read (storage grows past its first block)' '
	mesh-gen -n 200 grid >g.mesh && mesh-info g.mesh | grep "^faces 80000$" &&
	mesh-gen --raw -n 200 grid >gr.mesh && mesh-info gr.mesh | grep "^faces 80000$" &&
	cat gr.mesh | mesh-info | grep "^faces 80000$"
'
test_expect_success 'columns: a line of separators only is refused, not an empty row' '
	printf ",\n5 5\n40 50\n1 1\n" >sep.txt &&
	test_fails_cleanly plot-xy sep.txt 2>err &&
	grep "sep.txt.: line 1: no numbers, only separators" err &&
	printf "0,0\n1,1\n" >ok.csv && plot-xy ok.csv >/dev/null
'
# with a fixed mmap threshold the freed columns are unmapped: a read
# after free crashes even without AddressSanitizer
test_expect_success 'landmarks: an out-of-range vertex is named (not read after free)' '
	GLIBC_TUNABLES=glibc.malloc.mmap_threshold=65536 && export GLIBC_TUNABLES &&
	awk "BEGIN { print \"100000 0 0 0\"; for (i = 0; i < 20000; i++) print \"1 0 0 0\" }" >lm.txt &&
	test_fails_cleanly procrustes -l lm.txt ico.mesh ico.mesh 2>err &&
	grep "landmark 1: source vertex 100000 out of range 0..41" err &&
	awk "BEGIN { for (i = 0; i < 20000; i++) print \"1 1\"; print \"2 5000000\" }" >lm2.txt &&
	test_fails_cleanly procrustes -l lm2.txt ico.mesh ico.mesh 2>err &&
	grep "landmark 20001: target vertex 5e+06 out of range 0..41" err
'
test_done
