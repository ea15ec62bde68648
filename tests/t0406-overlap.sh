#!/bin/sh
test_description='overlap: intersection volume over source volume, deformation scale'
. "$(dirname "$0")/test-lib.sh"

shift_x() {
	awk -v dx="$1" '/^frame [0-9]/ { on = 1; print; next }
	on && NF == 3 { printf "%.17g %.17g %.17g\n", $1 + dx, $2, $3; next } { print }' "$2"
}

test_expect_success 'setup: unit spheres' '
	mesh-gen -s 3 icosphere >a.mesh && shift_x 1 a.mesh >b.mesh && shift_x 0.1 a.mesh >c.mesh
'
test_expect_success 'identical meshes overlap fully: small deformation' '
	overlap a.mesh a.mesh >o.txt && test "$(cut -d" " -f3 o.txt)" = small &&
	test_near "$(cut -d" " -f2 o.txt)" 1 1e-9
'
test_expect_success 'spheres one radius apart: the lens, 5/16 of a sphere: large' '
	overlap a.mesh b.mesh >o.txt && cat o.txt &&
	test_near "$(cut -d" " -f2 o.txt)" 0.3125 0.01 && test "$(cut -d" " -f3 o.txt)" = large
'
test_expect_success 'a small shift: small deformation; --sample agrees with the exact volume' '
	overlap a.mesh c.mesh >o.txt && test "$(cut -d" " -f3 o.txt)" = small &&
	overlap -s 30 a.mesh b.mesh >s.txt && cat s.txt &&
	test_near "$(cut -d" " -f2 s.txt)" 0.3125 0.03
'
test_expect_success 'open mesh where a volume is needed fails cleanly' '
	mesh-gen -n 12 cylinder >open.mesh &&
	test_fails_cleanly overlap a.mesh open.mesh &&
	test_fails_cleanly overlap open.mesh a.mesh
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage overlap a.mesh &&
	test_must_fail_usage overlap -s 0x a.mesh b.mesh
'
test_done
