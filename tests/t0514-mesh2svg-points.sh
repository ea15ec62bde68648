#!/bin/sh
test_description='mesh2svg --points labels vertex indices, --points-file numbers given points'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'outline: every vertex labelled with its 0-based index' '
	printf "ring 5\n0 0\n2 0\n2 1\n1 2\n0 1\n" >pent.rings &&
	mesh2svg --points pent.rings >p.svg &&
	test $(grep -c "<circle" p.svg) -eq 5 &&
	for i in 0 1 2 3 4; do grep -q ">$i</text>" p.svg || return 1; done &&
	! grep -q ">5</text>" p.svg
'
test_expect_success 'outline with two rings: labels are ring:index' '
	printf "ring 4\n0 0\n4 0\n4 4\n0 4\nring 3\n1 1\n2 2\n2 1\n" >hole.rings &&
	mesh2svg --points hole.rings >h.svg &&
	grep -q ">0:3</text>" h.svg && grep -q ">1:2</text>" h.svg
'
test_expect_success 'mesh: grid of frames, every vertex of every frame labelled' '
	printf "MESH 1\nvertices 4\nfaces 2\nframes 2\nf 0 1 2\nf 0 2 3\nframe 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\nframe 1\n0 0 0\n2 0 0\n2 1 0\n0 1 0\n" >sq.mesh &&
	mesh2svg -g --points sq.mesh >g.svg &&
	test $(grep -c ">3</text>" g.svg) -eq 2
'
test_expect_success '--points-file: numbered markers at the listed vertices, column chosen' '
	printf "4 0\n1 2\n" >pts.txt &&
	mesh2svg --points-file pts.txt pent.rings >f1.svg &&
	grep -c "#d01c1c" f1.svg >n && test $(cat n) -eq 4 &&
	grep -q "#d01c1c.*>1</text>" f1.svg && grep -q "#d01c1c.*>2</text>" f1.svg &&
	mesh2svg --points-file pts.txt --points-column 2 pent.rings >f2.svg &&
	! cmp -s f1.svg f2.svg
'
test_expect_success 'bad input: index out of range, missing column, --points with --animate' '
	echo 7 >bad.txt &&
	test_fails_cleanly mesh2svg --points-file bad.txt pent.rings &&
	test_fails_cleanly mesh2svg --points-file pts.txt --points-column 3 pent.rings &&
	test_fails_cleanly mesh2svg --points-file pts.txt hole.rings &&
	test_must_fail_usage mesh2svg -a --points sq.mesh 2>/dev/null
'
test_done
