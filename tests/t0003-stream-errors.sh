#!/bin/sh
test_description='MESH reader: every kind of bad input fails cleanly (exit 1,
one stderr line naming file and line, nothing on stdout)'
. "$(dirname "$0")/test-lib.sh"

# a valid 3-vertex, 1-face, 1-frame stream, with the header lines given
tri() {
	printf 'MESH 1\nvertices 3\nfaces 1\nframes %s\nf 0 1 2\nframe 0\n0 0 0\n1 0 0\n0 1 0\n' "${1:-1}"
}

test_expect_success 'setup: the valid triangle reads' '
	tri >ok.mesh && mesh-info -q ok.mesh
'
test_expect_success 'missing file' '
	test_fails_cleanly mesh-info nosuch.mesh 2>err &&
	grep -q "cannot read .nosuch.mesh.: No such file" err
'
test_expect_success 'empty input' '
	: >empty.mesh &&
	test_fails_cleanly mesh-info empty.mesh 2>err && grep -q "empty" err
'
test_expect_success 'unknown magic (an OBJ file)' '
	printf "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err &&
	grep -q "bad.mesh.: line 1: not a MESH stream" err
'
test_expect_success 'unsupported version' '
	tri | sed "1s/MESH 1/MESH 2/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "version" err
'
test_expect_success 'truncated header' '
	printf "MESH 1\nvertices 3\n" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "truncated header" err
'
test_expect_success 'header count is not a number' '
	tri | sed "3s/faces 1/faces one/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "line 3: bad faces count" err
'
test_expect_success 'header count negative' '
	tri | sed "2s/vertices 3/vertices -3/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "line 2" err
'
test_expect_success 'header keys out of order' '
	tri | sed -e "2s/vertices/faces/" -e "3s/faces/vertices/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "expected .vertices N." err
'
test_expect_success 'truncated faces' '
	printf "MESH 1\nvertices 3\nfaces 2\nframes 1\nf 0 1 2\n" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err &&
	grep -q "truncated: expected 2 faces, got 1" err
'
test_expect_success 'face count too small (a frame line where a face should be)' '
	tri | sed "3s/faces 1/faces 2/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "line 6: expected face" err
'
test_expect_success 'face with four indices' '
	tri | sed "5s/f 0 1 2/f 0 1 2 0/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "line 5: a face needs exactly 3" err
'
test_expect_success 'face with two indices' '
	tri | sed "5s/f 0 1 2/f 0 1/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "line 5" err
'
test_expect_success 'vertex index out of range' '
	tri | sed "5s/f 0 1 2/f 0 1 3/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err &&
	grep -q "line 5: vertex index 3 out of range (0..2)" err
'
test_expect_success 'negative vertex index' '
	tri | sed "5s/f 0 1 2/f 0 -1 2/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "line 5: vertex index -1" err
'
test_expect_success 'truncated frame' '
	tri | sed "\$d" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err &&
	grep -q "truncated: frame 0 has 2 of 3 vertices" err
'
test_expect_success 'missing frames (header announces more)' '
	tri 3 >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "expected 3 frames, got 1" err
'
test_expect_success 'too many frames' '
	{ tri; printf "frame 1\n0 0 0\n1 0 0\n0 1 0\n"; } >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err &&
	grep -q "line 10: more frames than the 1 announced" err
'
test_expect_success 'no frames at all' '
	tri "?" | head -5 >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "no frames" err
'
test_expect_success 'frames ? reads to the end' '
	{ tri "?"; printf "frame 1 cut\n0 0 0\n1 0 0\n0 1 0\n"; } >q.mesh &&
	mesh-info q.mesh >info && grep -q "^frames 2" info && grep -q "^clips 2" info
'
test_expect_success 'frame numbers out of sequence' '
	{ tri 2; printf "frame 2\n0 0 0\n1 0 0\n0 1 0\n"; } >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "expected frame 1, got frame 2" err
'
test_expect_success 'junk after the frame number' '
	tri | sed "6s/frame 0/frame 0 cutt/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "line 6" err
'
test_expect_success 'NaN coordinate' '
	tri | sed "8s/1 0 0/1 nan 0/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "line 8: non-finite" err
'
test_expect_success 'infinite coordinate' '
	tri | sed "8s/1 0 0/1 0 -inf/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "line 8: non-finite" err
'
test_expect_success 'overflowing coordinate (1e999)' '
	tri | sed "8s/1 0 0/1e999 0 0/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "line 8" err
'
test_expect_success 'two numbers on a vertex line' '
	tri | sed "8s/1 0 0/1 0/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "line 8: expected 3 numbers" err
'
test_expect_success 'four numbers on a vertex line' '
	tri | sed "8s/1 0 0/1 0 0 0/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "line 8: expected 3 numbers" err
'
test_expect_success 'junk instead of a number' '
	tri | sed "8s/1 0 0/1 0 zero/" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "line 8" err
'
test_expect_success 'comments and blank lines are allowed anywhere' '
	tri | sed -e "1a# made by hand" -e "5a\\
" -e "7s/\$/  # first vertex/" >c.mesh &&
	mesh-info -q c.mesh
'
test_expect_success 'CRLF line ends are accepted' '
	tri | sed "s/\$/\r/" >crlf.mesh && mesh-info -q crlf.mesh
'
test_expect_success 'bad input on stdin is named <stdin>' '
	tri | sed "8s/1 0 0/1 0/" >bad.mesh &&
	test_fails_cleanly mesh-info <bad.mesh 2>err && grep -q "<stdin>.: line 8" err
'

# raw variant
test_expect_success 'setup: a raw stream' '
	STOPMO_RAW=1 mesh-gen -f 3 -n 2 grid >r.mesh && mesh-info -q r.mesh &&
	size=$(wc -c <r.mesh) && echo $size >size
'
test_expect_success 'raw truncated in the face block' '
	head -c 60 r.mesh >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "truncated face block" err
'
test_expect_success 'raw truncated in a vertex block' '
	head -c $(($(cat size) - 20)) r.mesh >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "frame 2.*truncated vertex block" err
'
test_expect_success 'raw truncated after the last block (missing newline)' '
	head -c $(($(cat size) - 1)) r.mesh >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "missing newline" err
'
test_expect_success 'raw frame missing at the end' '
	mesh-gen -f 2 -n 2 grid | STOPMO_RAW=1 anim-slice -f 0 >one.raw &&
	sed "s/^frames 1\$/frames 2/" one.raw >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "expected 2 frames, got 1" err
'
test_expect_success 'raw vertex index out of range' '
	printf "MESH 1 raw\nvertices 3\nfaces 1\nframes 1\n\000\000\000\000\001\000\000\000\007\000\000\000" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "face 0: vertex index 7 out of range" err
'
test_expect_success 'raw NaN coordinate' '
	printf "MESH 1 raw\nvertices 1\nfaces 0\nframes 1\nframe 0\n\000\000\000\000\000\000\370\177\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\000\n" >bad.mesh &&
	test_fails_cleanly mesh-info bad.mesh 2>err && grep -q "non-finite" err
'

# tools that stream fail cleanly too when the problem is in the header
test_expect_success 'anim-slice and anim-avg on bad input: nothing on stdout' '
	tri | sed "5s/f 0 1 2/f 0 1 9/" >bad.mesh &&
	test_fails_cleanly anim-slice bad.mesh &&
	test_fails_cleanly anim-avg bad.mesh &&
	tri | sed "\$d" >bad2.mesh &&
	test_fails_cleanly anim-avg bad2.mesh &&
	test_fails_cleanly mesh-normalize bad2.mesh &&
	test_fails_cleanly mesh-normalize <bad2.mesh
'
test_done
