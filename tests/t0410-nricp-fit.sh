#!/bin/sh
test_description='nricp ARAP fit on the cleaned camel gallop scans: fewer flipped faces, closer; 01 -> 05 coverage'
. "$(dirname "$0")/test-lib.sh"
need_shared_data scans/camel-gallop-02.off
need_shared_data scans/camel-gallop-05.off

EX="$STOPMO_ROOT/examples/clay"
# mesh-clean keeps the vertex order of these two scans (it only removes
# fins and turns one fold-over back), so the landmark files still apply
test_expect_success 'setup: import and clean the scans (scan 01 has a fold-over)' '
	mesh-import "$SHARED_DATA/scans/camel-gallop-01.off" >s1.mesh &&
	mesh-clean -v s1.mesh >c1.mesh 2>err && cat err &&
	grep -q "fold-overs: 1 found, 0 left" err &&
	mesh-clean --no-unfold -v s1.mesh >k1.mesh 2>err2 && ! grep -q fold-overs err2 &&
	! cmp -s c1.mesh k1.mesh &&
	mesh-import "$SHARED_DATA/scans/camel-gallop-02.off" | mesh-clean >c2.mesh &&
	test "$(awk "/^vertices/ { print \$2 }" c1.mesh)" = 4999
'
# measured: --fit 0 (pure Amberg): 0.79%, 14 flipped faces; default: 0.41%, 6
# (all on the thin ears, whose rims are knife edges in both scans)
test_expect_success 'camel 01 -> 02: Hausdorff below 0.6%, at most 8 flipped faces' '
	nricp --init-deform -l "$EX/landmarks-01-02.txt" c1.mesh c2.mesh >r.mesh &&
	mesh-metrics --no-header -r c2.mesh r.mesh >m.txt && cat m.txt &&
	test_le "$(awk "{ print \$3 }" m.txt)" 0.006 &&
	test_le "$(awk "{ print \$5 }" m.txt)" 8
'
test_expect_success 'without the ARAP fit: farther, and more flipped faces' '
	nricp --fit 0 --init-deform -l "$EX/landmarks-01-02.txt" c1.mesh c2.mesh >r0.mesh &&
	mesh-metrics --no-header -r c2.mesh r0.mesh >m0.txt && cat m0.txt &&
	test_le "$(awk "{ print \$5 + 4 }" m.txt)" "$(awk "{ print \$5 }" m0.txt)" &&
	test_le "$(awk "{ print \$3 + 0.002 }" m.txt)" "$(awk "{ print \$3 }" m0.txt)"
'
# the legs swap places; the landmark file names vertices of the raw scan 05,
# whose indices mesh-clean shifts: pass them as points
# measured: cover 1.65% of the diagonal, fit 5.0% (a fold of chest skin stays
# inside the body at the front armpit: the issue's 2% is not reached)
test_expect_success 'camel 01 -> 05 directly: every part of the target covered to 2%' '
	mesh-import "$SHARED_DATA/scans/camel-gallop-05.off" >s5.mesh &&
	mesh-clean s5.mesh >c5.mesh &&
	awk "NR == FNR { if (\$1 == \"frame\") on = 1; else if (on && NF == 3) v[n++] = \$0; next }
	     /^#/ || NF == 0 { next } NF == 2 { print \$1, v[\$2] }" s5.mesh "$EX/landmarks-01-05-direct.txt" >m5.txt &&
	test "$(wc -l <m5.txt)" = 15 &&
	nricp --init-deform -l m5.txt c1.mesh c5.mesh >r5.mesh &&
	mesh-metrics --no-header -r c5.mesh r5.mesh >d5.txt && cat d5.txt &&
	test_le "$(awk "{ print \$NF }" d5.txt)" 0.02
'
test_done
