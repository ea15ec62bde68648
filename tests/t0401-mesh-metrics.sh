#!/bin/sh
test_description='mesh-metrics: Hausdorff, RMS, distortion; bad input'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'setup' '
	mesh-gen -s 3 icosphere >sphere.mesh &&
	awk "/^frame/ { body = 1; print; next } body && NF == 3 { printf \"%.17g %.17g %.17g\n\", 1.1 * \$1, 1.1 * \$2, 1.1 * \$3; next } { print }" sphere.mesh >big.mesh &&
	mesh-gen -s 2 icosphere >coarse.mesh
'
test_expect_success 'identical meshes: zero distance and zero distortion' '
	mesh-metrics -r sphere.mesh sphere.mesh >same.txt &&
	awk "!/^#/ { for (i = 2; i <= NF; i++) if (\$i > 1e-12 || \$i < -1e-12) exit 1 }" same.txt
'
test_expect_success 'scaled sphere: Hausdorff 0.1, area +21%, volume +33.1%' '
	mesh-metrics -r sphere.mesh big.mesh >big.txt &&
	test_near "$(awk "!/^#/ { print \$2 }" big.txt)" 0.1 1e-9 &&
	test_near "$(awk "!/^#/ { print \$4 }" big.txt)" 0.1 1e-3 &&
	test_near "$(awk "!/^#/ { print \$6 }" big.txt)" 0.331 1e-9 &&
	test_near "$(awk "!/^#/ { print \$7 }" big.txt)" 0.21 1e-9 &&
	test_near "$(awk "!/^#/ { print \$9 }" big.txt)" 0.331 1e-9 &&
	test_near "$(awk "!/^#/ { print \$11 }" big.txt)" 0.1 1e-9
'
test_expect_success 'different connectivity: surface columns only, small distance' '
	mesh-metrics -r sphere.mesh coarse.mesh >c.txt &&
	test "$(awk "!/^#/ { print NF }" c.txt)" = 7 &&
	h=$(awk "!/^#/ { print \$3 }" c.txt) && test_le "$h" 0.02 &&
	test "$(awk "!/^#/ { print \$5 }" c.txt)" = 0 &&
	awk "!/^#/ { m = \$6 > \$7 ? \$6 : \$7; d = m - \$3; exit !(d < 1e-15 && d > -1e-15) }" c.txt
'
test_expect_success 'one-sided distances: a half sphere fits the sphere but does not cover it' '
	awk "/^frame/ { body = 1; print; next } body && NF == 3 { z = \$3 > 0 ? \$3 : 0; print \$1, \$2, z; next } { print }" sphere.mesh >half.mesh &&
	mesh-metrics --no-header -r sphere.mesh half.mesh >hm.txt && cat hm.txt &&
	fit=$(awk "{ print \$(NF - 1) }" hm.txt) && cover=$(awk "{ print \$NF }" hm.txt) &&
	test_le "$fit" 0.6 && test_le 0.2 "$cover" && test_le "$fit" "$cover"
'
test_expect_success 'an inside-out copy has every face flipped' '
	awk "/^f / { print \"f\", \$2, \$4, \$3; next } { print }" sphere.mesh >inv.mesh &&
	mesh-metrics --no-header -r sphere.mesh inv.mesh >inv.txt &&
	test "$(awk "{ print \$5 }" inv.txt)" = 1280
'
test_expect_success 'one row per frame of an animation' '
	mesh-gen -f 6 -a wave grid >wave.mesh &&
	mesh-metrics --no-header -r wave.mesh wave.mesh >w.txt &&
	test "$(wc -l <w.txt)" -eq 6
'
test_expect_success 'bad input fails cleanly' '
	test_fails_cleanly mesh-metrics -r nonexistent.mesh sphere.mesh &&
	head -n 40 sphere.mesh >trunc.mesh &&
	test_fails_cleanly mesh-metrics -r sphere.mesh trunc.mesh &&
	test_fails_cleanly mesh-metrics --ref-frame 3 -r sphere.mesh sphere.mesh &&
	test_must_fail_usage mesh-metrics sphere.mesh
'
test_done
