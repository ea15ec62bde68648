#!/bin/sh
test_description='nricp --start auto: the start kept by distance, flips and stretch; --paper; bad use'
. "$(dirname "$0")/test-lib.sh"

# head-gen's head (642 vertices) at frame 0 against frame 180 remeshed by
# mesh-clean (2674 vertices): the true correspondence is frame 180 itself.
# A round head has no limbs: the automatic landmarks (geodesic extremities)
# are guesses, and the landmark start slides the face along the skull
# (measured: 2.9% of the diagonal mean distance to the truth, where the
# start without landmarks lands 0.28% off).
test_expect_success 'setup: head frame 0, frame 180 and its remeshed scan' '
	head-gen -f 181 --clips 1 -s 3 >h.mesh &&
	anim-slice -f 0 h.mesh >h0.mesh && anim-slice -f 180 h.mesh >h180.mesh &&
	mesh-clean -R 0.02 h180.mesh >scan.mesh 2>/dev/null
'
truth_err() {
	d=$(mesh-info "$2" | awk "/^diagonal/ { print \$2 }")
	anim-diff -s "$2" "$1" | awk -v d="$d" "/^mean/ { print \$2 / d }"
}
test_expect_success 'default (--start auto) keeps the start that did not slide: within 1% of the truth' '
	nricp -v h0.mesh scan.mesh >auto.mesh 2>err &&
	grep "edge stretch.*(start landmarks" err && grep "kept start" err &&
	e=$(truth_err auto.mesh h180.mesh) && echo "auto: $e of the diagonal from the truth" &&
	test_le "$e" 0.01
'
test_expect_success '--start with the kept start gives the same bytes' '
	kept=$(sed -n "s/.*kept start \([a-z]*\).*/\1/p" err) && echo "kept $kept" &&
	nricp --start "$kept" h0.mesh scan.mesh >one.mesh &&
	cmp auto.mesh one.mesh
'
# the landmark start slides along the skull (edge stretch 0.085): its
# registration scores worse than the unregistered frame 0 (Hausdorff 1.12%,
# no stretch), so the key is frame 0 itself (nricp keeps a key's start where
# it scores no worse; measured: 0.19% from the truth, the slid one 2.9%)
test_expect_success '--start landmarks (the earlier default) slides: the start is kept instead' '
	nricp -v --start landmarks h0.mesh scan.mesh >lm.mesh 2>errl &&
	grep "start landmarks" errl && grep "the start kept" errl &&
	nricp --start landmarks h0.mesh scan.mesh >lm2.mesh 2>errq &&
	cmp lm.mesh lm2.mesh && test "$(wc -l <errq)" = 1 &&
	grep "the start is written unchanged" errq &&
	m=$(anim-diff -s h0.mesh lm.mesh | awk "/^max/ { print \$2 }") && test_le "$m" 0 &&
	e=$(truth_err lm.mesh h180.mesh) && echo "landmarks: $e" && test_le "$e" 0.01
'
test_expect_success '--paper: the thesis method runs (thin shell, Amberg, no fit) and is deterministic' '
	nricp --paper -k 3 h0.mesh scan.mesh >p1.mesh && nricp --paper -k 3 h0.mesh scan.mesh >p2.mesh &&
	cmp p1.mesh p2.mesh
'
test_expect_success 'usage: --start with -l or --no-auto, an unknown start' '
	printf "0 0\n" >m.txt &&
	test_must_fail_usage nricp --start none -l m.txt h0.mesh scan.mesh &&
	test_must_fail_usage nricp --start auto --no-auto h0.mesh scan.mesh &&
	test_must_fail_usage nricp --start shell --init-model arap h0.mesh scan.mesh &&
	test_must_fail_usage nricp --start sideways h0.mesh scan.mesh &&
	test_must_fail_usage nricp --paper --start landmarks h0.mesh scan.mesh
'
test_done
