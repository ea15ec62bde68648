#!/bin/sh
test_description='examples/stopshop writes out/review.html: input | stop-motion | error, parts, pieces'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/view-lib.sh"

run_recipe() {
	make -s -C "$STOPMO_ROOT/examples/stopshop" BIN="$STOPMO_ROOT/bin" OUT="$TRASH/out" \
		FRAMES=36 PIECES=4 BUDGET= SWEEP=2:6:2 "$@"
}

test_expect_view 'the recipe writes out/review.html and says so' '
	run_recipe >log 2>&1 && grep "review: .*review.html" log && test -s out/review.html
'
test_expect_view 'the review shows input, stop-motion and error views with the error legend in mm' '
	shoot "out/review.html#frame=20" r.png && console_clean r.png.log &&
	for t in input stop-motion error; do grep -q "class=\"vtitle\"[^>]*>$t<" r.png.dom || return 1; done &&
	grep -q "mm on a print 40 mm tall along y" r.png.dom &&
	f=$(stage_fraction r.png) && echo "mesh pixels: $f" && test_le 0.05 "$f"
'
test_expect_view 'the panel shows the pieces of frame 20 from the recipe labels, 4 thumbnails per part' '
	u=$(sed -n 21p out/labels_0.txt) && l=$(sed -n 21p out/labels_1.txt) &&
	grep -q "upper: piece $u<" r.png.dom && grep -q "lower: piece $l<" r.png.dom &&
	test $(grep -o "class=\"th[ \"]" r.png.dom | wc -l) -eq 8
'
test_expect_view 'the legend maximum is anim-diff'"'"'s maximum at the same print height' '
	max=$(awk "\$1 == \"max\" { print \$2 }" out/error.txt) &&
	shown=$(sed -n "s/.*, max [^ ]* (\([^ ]*\) mm).*/\1/p" r.png.dom) && echo "anim-diff $max, page $shown" &&
	test_near "$shown" "$max" 0.01
'
test_expect_view 'make rebuilds nothing when nothing changed' '
	touch stamp && run_recipe >log2 2>&1 &&
	find out -newer stamp -type f >changed && : >empty && test_cmp empty changed
'
test_done
