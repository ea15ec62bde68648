#!/bin/sh
test_description='nricp and procrustes on generated shapes; bad input'
. "$(dirname "$0")/test-lib.sh"

# an ellipsoid (icosphere squeezed in x and y), optionally bent along z
shape() {
	awk -v bend="$2" '/^frame [0-9]/ { on = 1; print; next }
	on && NF == 3 { x = 0.35 * $1; y = 0.35 * $2; z = $3
		if (bend) { R = 1.2; t = z / R; xx = R - (R - x) * cos(t); z = (R - x) * sin(t); x = xx }
		printf "%.17g %.17g %.17g\n", x, y, z; next }
	{ print }' "$1"
}
# rows "v x y z" of frame 0 for the vertex indices given
vertex_rows() {
	f=$1; shift
	for v in "$@"; do
		awk -v v="$v" '/^frame [0-9]/ { on = 1; i = 0; next } on { if (i == v) print v, $0; i++ }' "$f"
	done
}

test_expect_success 'setup: a bent ellipsoid at another resolution' '
	mesh-gen -s 3 icosphere >s3.mesh && mesh-gen -s 4 icosphere >s4.mesh &&
	shape s3.mesh 0 >src.mesh && shape s3.mesh 1 >truth.mesh && shape s4.mesh 1 >tgt.mesh &&
	vertex_rows truth.mesh 0 1 2 3 4 5 6 7 8 9 10 11 >marks.txt
'
test_expect_success 'nricp: Hausdorff below 1% of the diagonal, no flipped faces' '
	nricp -l marks.txt src.mesh tgt.mesh >reg.mesh &&
	mesh-metrics --no-header -r tgt.mesh reg.mesh >m.txt &&
	h=$(awk "{ print \$3 }" m.txt) && echo "hausdorff_rel $h" && test_le "$h" 0.01 &&
	test "$(awk "{ print \$5 }" m.txt)" = 0
'
test_expect_success 'nricp keeps the source connectivity' '
	head -n 1284 src.mesh | sed 1,4d >f.src && head -n 1284 reg.mesh | sed 1,4d >f.reg &&
	test_cmp f.src f.reg
'
test_expect_success 'nricp --steps-out writes steps + 1 poses that approach the target' '
	nricp -k 4 --steps-out steps.mesh -l marks.txt src.mesh tgt.mesh >reg4.mesh &&
	grep -q "^frames 5" steps.mesh &&
	mesh-metrics --no-header -r tgt.mesh steps.mesh >s.txt &&
	first=$(awk "NR == 1 { print \$2 }" s.txt) && last=$(awk "NR == 5 { print \$2 }" s.txt) &&
	test_le "$last" "$(awk "BEGIN { print $first / 4 }")"
'
test_expect_success 'nricp -v prints the time and the final Hausdorff distance' '
	nricp -v -k 2 -l marks.txt src.mesh tgt.mesh >/dev/null 2>err &&
	grep "registered in .* s: Hausdorff" err
'
test_expect_success 'nricp accepts vertex-to-vertex landmarks' '
	nricp -k 2 -l marks.txt src.mesh tgt.mesh >/dev/null &&
	printf "0 0\n1 1\n2 2\n" >vv.txt && nricp -k 2 --fit-smooth 0 -l vv.txt s3.mesh s3.mesh >same.mesh &&
	mesh-metrics --no-header -r s3.mesh same.mesh >same.txt &&
	test_le "$(awk "{ print \$3 }" same.txt)" 1e-6
'
# the smoothed rest shape of the fit lets vertices slide a little along the
# surface (measured 1.7e-4 of the diagonal on this sphere)
test_expect_success 'nricp of a mesh onto itself stays on it' '
	nricp -k 2 -l vv.txt s3.mesh s3.mesh >same1.mesh &&
	mesh-metrics --no-header -r s3.mesh same1.mesh >same1.txt &&
	test_le "$(awk "{ print \$3 }" same1.txt)" 1e-3 &&
	test "$(awk "{ print \$5 }" same1.txt)" = 0
'
test_expect_success 'nricp --init-deform: known correspondence, mean error below 2% of the diagonal' '
	nricp --init-deform -l marks.txt src.mesh tgt.mesh >regi.mesh &&
	anim-diff -s truth.mesh regi.mesh >d.txt &&
	e=$(awk "/^mean/ { print \$2 }" d.txt) &&
	diag=$(mesh-info truth.mesh | awk "/^diagonal/ { print \$2 }") &&
	echo "mean error $e, diagonal $diag" && echo "$diag" >diag.txt &&
	test_le "$e" "$(awk "BEGIN { print 0.02 * $diag }")" &&
	mesh-metrics --no-header -r tgt.mesh regi.mesh >mi.txt &&
	test_le "$(awk "{ print \$3 }" mi.txt)" 0.01
'
# measured: mean error 2.0% of the diagonal (the arap model above: less)
test_expect_success 'nricp --init-model shell: the thin shell first, mean error below 3%' '
	nricp -v --init-model shell -l marks.txt src.mesh tgt.mesh >regs.mesh 2>err &&
	grep -q "clay deformation (thin shell)" err &&
	anim-diff -s truth.mesh regs.mesh >ds.txt &&
	e=$(awk "/^mean/ { print \$2 }" ds.txt) &&
	test_le "$e" "$(awk "BEGIN { print 0.03 * $(cat diag.txt) }")" &&
	test_must_fail_usage nricp --init-model clay -l marks.txt src.mesh tgt.mesh
'
test_expect_success 'procrustes recovers a rigid motion and --apply aligns' '
	awk "/^frame [0-9]/ { on = 1; print; next } on && NF == 3 { printf \"%.17g %.17g %.17g\n\", -\$2 + 3, \$1, \$3 - 1; next } { print }" src.mesh >moved.mesh &&
	procrustes src.mesh moved.mesh >T.txt &&
	test_near "$(awk "!/^#/ && NR == 4 { print \$4 }" T.txt)" 3 1e-9 &&
	test_near "$(grep rms T.txt | awk "{ print \$3 }")" 0 1e-9 &&
	procrustes -a src.mesh moved.mesh >al.mesh &&
	mesh-metrics --no-header -r moved.mesh al.mesh >al.txt &&
	test_le "$(awk "{ print \$2 }" al.txt)" 1e-9
'
test_expect_success 'procrustes --scale finds a uniform scale' '
	awk "/^frame [0-9]/ { on = 1; print; next } on && NF == 3 { printf \"%.17g %.17g %.17g\n\", 2 * \$1, 2 * \$2, 2 * \$3; next } { print }" src.mesh >big.mesh &&
	procrustes -s src.mesh big.mesh >S.txt &&
	test_near "$(grep scale S.txt | awk "{ print \$3 }")" 2 1e-9
'
test_expect_success 'landmark index out of range fails cleanly' '
	printf "0 0 0 0\n99999 1 1 1\n" >bad.txt &&
	test_fails_cleanly nricp -l bad.txt src.mesh tgt.mesh &&
	printf "0 99999\n" >bad2.txt &&
	test_fails_cleanly nricp -l bad2.txt src.mesh tgt.mesh &&
	test_fails_cleanly procrustes -l bad.txt src.mesh tgt.mesh
'
test_expect_success 'malformed landmark files fail cleanly' '
	printf "0 1 2\n" >three.txt && test_fails_cleanly nricp -l three.txt src.mesh tgt.mesh &&
	printf "0.5 1 2 3\n" >frac.txt && test_fails_cleanly nricp -l frac.txt src.mesh tgt.mesh &&
	test_fails_cleanly nricp -l missing.txt src.mesh tgt.mesh
'
test_expect_success 'procrustes without landmarks needs equal vertex counts' '
	test_fails_cleanly procrustes src.mesh tgt.mesh
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage nricp src.mesh &&
	test_must_fail_usage nricp --align sideways src.mesh tgt.mesh &&
	test_must_fail_usage nricp -k 0 src.mesh tgt.mesh &&
	test_must_fail_usage nricp --fit -1 src.mesh tgt.mesh &&
	test_must_fail_usage nricp --fit-weight 0 src.mesh tgt.mesh
'
test_done
