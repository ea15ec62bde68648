#!/bin/sh
test_description='nricp default start on shared data: a face expression (truth known) and camel keys 3 apart'
. "$(dirname "$0")/test-lib.sh"
need_shared_data faces/disgust.ply
need_shared_data scans/camel-gallop-05.off

truth_err() {
	d=$(mesh-info "$2" | awk "/^diagonal/ { print \$2 }")
	anim-diff -s "$2" "$1" | awk -v d="$d" "/^mean/ { print \$2 / d }"
}
test_expect_success 'setup: neutral face, disgust remeshed; camel scans 02 and 05 cleaned' '
	mesh-import "$SHARED_DATA/faces/neutral.ply" >neutral.mesh &&
	mesh-import "$SHARED_DATA/faces/disgust.ply" >disgust.mesh &&
	mesh-clean --no-fill -R 0.01 disgust.mesh >scan.mesh 2>/dev/null &&
	for k in 02 05; do
		mesh-import "$SHARED_DATA/scans/camel-gallop-$k.off" | mesh-clean >c$k.mesh 2>/dev/null || return 1
	done
'
# measured: 1.16% mean from the truth, Hausdorff 1.56%, no flipped face
# (the landmark start, the earlier default: 4.59%, 5.35%, 529 flipped)
test_expect_success 'neutral -> disgust: within 1.5% of the truth, no flipped face' '
	nricp neutral.mesh scan.mesh >reg.mesh &&
	e=$(truth_err reg.mesh disgust.mesh) && echo "mean distance to the truth: $e" &&
	test_le "$e" 0.015 &&
	mesh-metrics --no-header -r scan.mesh reg.mesh >m.txt && cat m.txt &&
	test "$(awk "{ print \$5 }" m.txt)" -le 10
'
# measured: Hausdorff 1.78%, 34 flipped (the earlier default: 3.52%, 397)
test_expect_success 'camel 02 -> 05 (three keys apart): Hausdorff below 2%, fewer than 50 flipped' '
	nricp c02.mesh c05.mesh >r05.mesh &&
	mesh-metrics --no-header -r c05.mesh r05.mesh >m.txt && cat m.txt &&
	test_le "$(awk "{ print \$3 }" m.txt)" 0.02 &&
	test "$(awk "{ print \$5 }" m.txt)" -lt 50
'
test_done
