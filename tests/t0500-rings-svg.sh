#!/bin/sh
test_description='rings reader (via mesh2svg) and SVG drawing of meshes and outlines'
. "$(dirname "$0")/test-lib.sh"

square() { printf 'ring 4\n0 0\n1 0\n1 1\n0 1\n'; }

test_expect_success 'a square outline becomes one SVG path' '
	square >sq.rings &&
	mesh2svg sq.rings >sq.svg &&
	grep -c "<path" sq.svg >n && echo 1 >expect && test_cmp expect n &&
	tail -1 sq.svg >last && echo "</svg>" >expect && test_cmp expect last
'
test_expect_success 'rings on stdin with comments' '
	{ echo "# a comment"; square; } >c.rings &&
	mesh2svg <c.rings >c.svg && grep -q "<path" c.svg
'
test_expect_success 'a mesh animation as a grid and as an animated SVG' '
	mesh-gen -n 3 -f 4 -a bend grid >g.mesh &&
	mesh2svg -g g.mesh >grid.svg &&
	test $(grep -c "<text" grid.svg) -eq 4 &&
	mesh2svg -a g.mesh >anim.svg && grep -q "<animate attributeName=\"d\"" anim.svg &&
	mesh2svg -f 3 -o one.svg g.mesh && grep -q "<path" one.svg
'
test_expect_success 'bow-tie (self-intersecting) outline fails cleanly' '
	printf "ring 4\n0 0\n1 1\n1 0\n0 1\n" >bow.rings &&
	test_fails_cleanly mesh2svg bow.rings && grep -q "intersects itself" .err
' 2>/dev/null
test_expect_success 'bad rings: truncated, junk, too few points, repeated point' '
	printf "ring 4\n0 0\n1 0\n1 1\n" >t.rings && test_fails_cleanly mesh2svg t.rings &&
	grep -q "line 4: truncated" .err &&
	printf "ring 3\n0 0\n1 x\n1 1\n" >j.rings && test_fails_cleanly mesh2svg j.rings &&
	grep -q "line 3" .err &&
	printf "ring 2\n0 0\n1 0\n" >s.rings && test_fails_cleanly mesh2svg s.rings &&
	printf "ring 3\n0 0\n0 0\n1 1\n" >r.rings && test_fails_cleanly mesh2svg r.rings &&
	printf "0 0\n" >h.rings && test_fails_cleanly mesh2svg h.rings
'
test_expect_success 'frame out of range fails cleanly, usage errors exit 2' '
	mesh-gen -n 2 grid >one.mesh && test_fails_cleanly mesh2svg -f 5 one.mesh &&
	test_must_fail_usage mesh2svg -a -g one.mesh 2>/dev/null
'
need_shared_data shapes2d/poses/elephant-pose1.rings.txt
test_expect_success 'elephant poses are simple outlines' '
	for i in 1 2 3 4 5 6; do
		mesh2svg "$SHARED_DATA/shapes2d/poses/elephant-pose$i.rings.txt" >e$i.svg || return 1
	done
'
test_done
