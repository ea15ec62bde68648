#!/bin/sh
test_description='arap-morph: N-way rigid blending of compatible 2D meshes (Sec. 4.2)'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

# direction (degrees) and length of the bar axis vertex 0 -> vertex RES, and
# the length of the diagonal 0 -> last, in frame 0 of a stream
axis() {
	awk -v r="$2" '$1 == "frame" { f++; next } f == 1 && NF == 3 { x[n] = $1; y[n] = $2; n++ }
	END { printf "%.9f %.9f %.9f\n", atan2(y[r] - y[0], x[r] - x[0]) * 45 / atan2(1, 1),
	      sqrt((y[r] - y[0]) ^ 2 + (x[r] - x[0]) ^ 2), sqrt((y[n-1] - y[0]) ^ 2 + (x[n-1] - x[0]) ^ 2) }' "$1"
}

test_expect_success 'weights e_i reproduce shape i (1e-9)' '
	bar_pair 10 >bar.mesh &&
	printf "1 0\n0 1\n" | arap-morph bar.mesh >rep.mesh &&
	anim-diff bar.mesh rep.mesh >d.txt && awk "/^# max/ { print \$3 }" d.txt >max &&
	test_le $(cat max) 1e-9
'
test_expect_success 'three compatible shapes: e_i reproduce each (up to translation)' '
	printf "ring 5\n0 0\n2 0\n2 1\n1 1.5\n0 1\n" >a.rings &&
	printf "ring 5\n0 0\n2 0.5\n2.2 1.5\n1 2.5\n-0.2 1\n" >b.rings &&
	printf "ring 5\n0 0\n1 -1\n2 0\n1.5 1.5\n0 1\n" >c.rings &&
	printf "0 0 0\n1 1 1\n3 3 3\n" >corr.txt &&
	compat-tri -c corr.txt a.rings b.rings c.rings >abc.mesh &&
	printf "1 0 0\n0 1 0\n0 0 1\n" | arap-morph -b 1 abc.mesh >rep3.mesh &&
	anim-diff abc.mesh rep3.mesh >d3.txt && awk "/^# max/ { print \$3 }" d3.txt >max3 &&
	test_le $(cat max3) 1e-9
'
test_expect_success 'bar rotated by 90 degrees: rigid 45-degree half-way pose' '
	echo "0.5 0.5" | arap-morph bar.mesh >half.mesh &&
	axis half.mesh 10 >ax && read ang len dia <ax &&
	test_near $ang 45 1e-6 && test_near $len 1 1e-6 && test_near $dia 1.019803903 1e-6
'
test_expect_success 'linear baseline shrinks the half-way bar (cos 45)' '
	echo "0.5 0.5" | arap-morph --linear bar.mesh >lin.mesh &&
	axis lin.mesh 10 >ax && read ang len dia <ax && test_near $len 0.707106781 1e-6
'
test_expect_success 'extrapolation: shear limiting keeps every triangle, linear inverts some' '
	bend_pair 1.5707963 0.3 >bend.mesh &&
	echo "-1 2" | arap-morph --linear bend.mesh >lx.mesh &&
	echo "-1 2" | arap-morph -l bend.mesh >sx.mesh &&
	test_le $(min_area lx.mesh) -1e-6 && test_le 1e-6 $(min_area sx.mesh) &&
	echo "-1 2" | arap-morph -v -l bend.mesh 2>log >/dev/null && grep -q "inverted triangles: 0 in 0" log
'
test_expect_success 'texture weights: sharpened, sum to 1, frame count' '
	printf "0.5 0.5\n0.2 0.8\n-0.3 1.3\n" | arap-morph --sigma 0.8 --texture-weights tw.txt bar.mesh >tw.mesh &&
	test $(wc -l <tw.txt) -eq 3 &&
	awk "{ d = \$1 + \$2 - 1; if (d < 0) d = -d; if (d > m) m = d } END { print m + 0 }" tw.txt >s && test_le $(cat s) 1e-12 &&
	sed -n 3p tw.txt >last && echo "0 1" >expect && test_cmp expect last
'
test_expect_success 'bad input: weight count does not match the frame count' '
	printf "0.2 0.3 0.5\n" >w3.txt &&
	test_fails_cleanly arap-morph bar.mesh w3.txt && grep -q "3 weights per row, but the mesh has 2 frames" .err &&
	printf "0.5 x\n" >wj.txt && test_fails_cleanly arap-morph bar.mesh wj.txt &&
	test_fails_cleanly arap-morph -b 5 bar.mesh w3.txt &&
	test_must_fail_usage arap-morph 2>/dev/null
'
test_done
