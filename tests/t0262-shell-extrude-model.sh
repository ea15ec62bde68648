#!/bin/sh
test_description='shell-extrude: one wall thickness for the whole model (--model, --thickness-mm)'
. "$(dirname "$0")/test-lib.sh"

# thick LOG: the thickness shell-extrude -v reports
thick() { sed -n 's/.*pieces, thickness \([^,]*\),.*/\1/p' "$1"; }

test_expect_success 'setup: the demo head in two parts of different size, a library each' '
	head-gen -f 12 -s 3 >head.mesh &&
	seg-graphcut --seeds "$STOPMO_ROOT/examples/stopshop/head.seeds" head.mesh >parts &&
	part-split -l parts -o "p_%d.mesh" head.mesh &&
	lib-uniform -k 4 p_0.mesh >lib_0.mesh && lib-uniform -k 4 p_1.mesh >lib_1.mesh
'

test_expect_success '--model: both parts get the same wall, relative to the whole head' '
	shell-extrude -v -m head.mesh -r 0.02 lib_0.mesh >s0 2>e0 &&
	shell-extrude -v -m head.mesh -r 0.02 lib_1.mesh >s1 2>e1 &&
	! grep -q warning e0 e1 &&
	test "$(thick e0)" = "$(thick e1)" &&
	diag=$(mesh-info head.mesh | awk "\$1 == \"diagonal\" { print \$2 }") &&
	echo "thickness $(thick e0), diagonal $diag" &&
	test_le "$(thick e0)" 0.1 && test_le 0.01 "$(thick e0)"
'

test_expect_success 'without --model the walls differ per part, and it says so' '
	shell-extrude -v -r 0.02 lib_0.mesh >t0 2>f0 && shell-extrude -v -r 0.02 lib_1.mesh >t1 2>f1 &&
	grep -q "warning: thickness .* relative to this library" f0 &&
	test "$(thick f0)" != "$(thick f1)"
'

test_expect_success '--thickness-mm 1 --height 40: 1/40 of the head height (head-gen: y in [-1, 1])' '
	shell-extrude -v -m head.mesh --thickness-mm 1 --height 40 lib_1.mesh >m1 2>g1 &&
	ext=$(anim-slice -f 0:1 head.mesh | mesh-info | awk "\$1 == \"bbox_min\" { lo = \$3 } \$1 == \"bbox_max\" { hi = \$3 } END { print hi - lo }") &&
	test_near "$(thick g1)" "$(awk -v e="$ext" "BEGIN { print e / 40 }")" 1e-6 &&
	shell-extrude -v -m head.mesh --thickness-mm 1 --height 40 --axis x lib_1.mesh >m2 2>g2 &&
	test "$(thick g1)" != "$(thick g2)"
'

test_expect_success 'bad combinations are usage errors, a bad model is bad input' '
	test_must_fail_usage shell-extrude --thickness-mm 1 lib_0.mesh >out &&
	test_must_fail_usage shell-extrude -m head.mesh --thickness-mm 1 lib_0.mesh >>out &&
	test_must_fail_usage shell-extrude -t 0.1 -r 0.02 lib_0.mesh >>out &&
	test_must_fail_usage shell-extrude -m head.mesh -t 0.1 lib_0.mesh >>out &&
	test_must_fail_usage shell-extrude -m head.mesh --thickness-mm 1 --height 40 --axis w lib_0.mesh >>out &&
	test ! -s out &&
	test_fails_cleanly shell-extrude -m nosuch.mesh -r 0.02 lib_0.mesh
'

test_done
