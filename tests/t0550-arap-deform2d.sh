#!/bin/sh
test_description='arap-deform2d: Igarashi 2005 handle deformation of a 2D mesh'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

# a 4 x 0.8 bar, 20 x 4 cells: vertex 0 bottom left, 20 bottom right,
# 84 top left, 104 top right
bar() { mesh-gen -n 20 -m 4 grid | awk '$1 == "frame" { f = 1; print; next }
	f && NF == 3 { printf "%.17g %.17g 0\n", $1 * 4, $2 * 0.8; next } { print }'; }

test_expect_success 'handles at rest reproduce the rest shape' '
	bar >bar.mesh &&
	printf "0 0 0\n20 4 0\n104 4 0.8\n" >h.txt &&
	arap-deform2d bar.mesh h.txt >same.mesh &&
	anim-diff bar.mesh same.mesh >d.txt && awk "/^# max/ { print \$3 }" d.txt >max &&
	test_le $(cat max) 1e-9
'
test_expect_success 'rigidly moved handles give the rigidly moved shape' '
	printf "0 1 2 0 0\n20 1 6 -2.828427124746190 2.828427124746190\n" >r.txt &&
	arap-deform2d -r bar.mesh r.txt >rot.mesh && grep -q "^frames 3" rot.mesh &&
	awk "\$1 == \"frame\" { f++; n = 0; next } f && NF == 3 { x[f, n] = \$1; y[f, n] = \$2; n++ }
	     END { for (k = 1; k <= f; k++) { d = sqrt((x[k,104] - x[k,84]) ^ 2 + (y[k,104] - y[k,84]) ^ 2) - 4; if (d < 0) d = -d; if (d > m) m = d }; print m }" rot.mesh >dev &&
	test_le $(cat dev) 1e-9
'
test_expect_success 'bending: the far end follows, no triangle inverts, result feeds arap-morph' '
	printf "0 0 0\n84 0 0.8\n20 3 2\n104 2.4 2.5\n" >b.txt &&
	arap-deform2d -r bar.mesh b.txt >bend.mesh &&
	test_le 1e-9 $(min_area bend.mesh) &&
	echo "0.5 0.5" | arap-morph bend.mesh >mid.mesh && test_le 1e-9 $(min_area mid.mesh)
'
test_expect_success 'bad input: one handle, index out of range, even column count' '
	printf "0 0 0\n" >one.txt && test_fails_cleanly arap-deform2d bar.mesh one.txt &&
	printf "0 0 0\n999 1 1\n" >oor.txt && test_fails_cleanly arap-deform2d bar.mesh oor.txt &&
	printf "0 0 0 1\n20 4 0 1\n" >even.txt && test_fails_cleanly arap-deform2d bar.mesh even.txt &&
	printf "0 0 0\n0 1 1\n" >dup.txt && test_fails_cleanly arap-deform2d bar.mesh dup.txt &&
	test_must_fail_usage arap-deform2d bar.mesh 2>/dev/null
'
test_done
