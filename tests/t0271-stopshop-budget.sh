#!/bin/sh
test_description='examples/stopshop: one print budget, pieces with connectors, swaps and grams in the summary'
. "$(dirname "$0")/test-lib.sh"

run_recipe() {
	make -s -C "$STOPMO_ROOT/examples/stopshop" BIN="$STOPMO_BIN" OUT="$TRASH/out" \
		FRAMES=36 SWEEP=2:6:2 "$@"
}

test_expect_success 'make BUDGET=9: the libraries add up to the budget' '
	run_recipe BUDGET=9 >log 2>&1 &&
	awk "\$1 == \"total\" { exit !(\$2 <= 9 && \$2 >= 8) }" out/budget.txt &&
	d0=$(awk "\$1 == \"pieces\" { print \$2 }" out/report_0.txt) &&
	d1=$(awk "\$1 == \"pieces\" { print \$2 }" out/report_1.txt) &&
	test "$d0" = "$(awk "\$1 == 0 { print \$2 }" out/budget.txt)" &&
	test "$d1" = "$(awk "\$1 == 1 { print \$2 }" out/budget.txt)" &&
	test "$(ls out/pieces/*.stl | wc -l)" = "$((d0 + d1))"
'
test_expect_success 'the summary prints the swaps on set and the grams to print' '
	grep "swaps on set: *[0-9]" out/summary.txt &&
	grep "grams to print: *[0-9.]* g" out/summary.txt &&
	swaps=$(awk "/swaps on set/ { print \$4 }" out/summary.txt) &&
	want=$(cat out/labels_0.txt out/labels_1.txt | awk "FNR == 1 { n = 0 } { if (n++ && \$1 != last) s++; last = \$1 } END { print s + 0 }") &&
	test "$swaps" -ge 1 &&
	g=$(awk "/grams to print/ { print \$4 }" out/summary.txt) &&
	want=$(awk "!/^#/ { g += \$4 } END { printf \"%.1f\", g }" out/pieces.txt) && test "$g" = "$want"
'
test_expect_success 'the pieces carry magnet pockets and are solid' '
	mesh-import out/pieces/part1_piece000.stl >p.mesh &&
	mesh-info --check closed p.mesh &&
	grep -c "^1 " out/pieces.txt >n1 && test "$(cat n1)" -ge 1 &&
	awk -F, "NR > 1 && \$6 == \"\" { exit 1 }" out/catalogue.csv
'
test_expect_success 'another budget redoes the libraries, not the parts' '
	cp out/part_0.mesh part0.before &&
	run_recipe BUDGET=6 >log2 2>&1 &&
	cmp part0.before out/part_0.mesh &&
	awk "\$1 == \"total\" { exit !(\$2 <= 6) }" out/budget.txt
'
test_expect_success 'a budget below the number of parts: clear error, make stops' '
	{ run_recipe BUDGET=1 >log3 2>&1; test $? = 2; } &&
	grep "budget of 1 pieces is below the number of parts (2)" log3
'
test_done
