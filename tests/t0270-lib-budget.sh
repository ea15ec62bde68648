#!/bin/sh
test_description='lib-budget: one print budget split across parts from their error-vs-size curves'
. "$(dirname "$0")/test-lib.sh"

# brute A B BUDGET [CA CB]: the least summed error (column 2) over every pair
# of rows with CA dA + CB dB <= BUDGET, by exhaustive search
brute() {
	awk -v B="$3" -v ca="${4:-1}" -v cb="${5:-1}" '
		FNR == 1 { f++ } /^#/ { next }
		f == 1 { na++; da[na] = $1; ea[na] = $2 } f == 2 { nb++; db[nb] = $1; eb[nb] = $2 }
		END { best = -1; for (i = 1; i <= na; i++) for (j = 1; j <= nb; j++)
			if (ca * da[i] + cb * db[j] <= B + 1e-9 && (best < 0 || ea[i] + eb[j] < best)) best = ea[i] + eb[j];
			printf "%.10g\n", best }' "$1" "$2"
}
total() {
	awk '$1 == "total" { print $3 }' "$1"
}

test_expect_success 'setup: a convex curve and one with a kink' '
	awk "BEGIN { print \"# d energy\"; for (d = 1; d <= 12; d++) printf \"%d %.10g\\n\", d, 8 / d }" >convex.txt &&
	printf "1 10\n2 9.5\n3 9\n4 2\n5 1.9\n6 1.8\n7 1.75\n" >kink.txt
'
test_expect_success 'convex curves: greedy and exact agree, and both are optimal' '
	awk "BEGIN { for (d = 1; d <= 12; d++) printf \"%d %.10g\\n\", d, 3 / d }" >convex2.txt &&
	lib-budget -n 10 convex.txt convex2.txt >ex.out &&
	lib-budget --method greedy -n 10 convex.txt convex2.txt >gr.out &&
	grep "curve convex" ex.out && grep "the same" ex.out &&
	test "$(total ex.out)" = "$(total gr.out)" &&
	test_near "$(total ex.out)" "$(brute convex.txt convex2.txt 10)" 1e-9 &&
	test "$(awk "\$1 == \"total\" { print \$2 }" ex.out)" = 10
'
test_expect_success 'a curve that is not convex: said so; greedy is worse, exact is optimal' '
	lib-budget -n 6 kink.txt convex.txt >ex.out &&
	lib-budget --method greedy -n 6 kink.txt convex.txt >gr.out &&
	grep "part 0: curve NOT convex" ex.out && grep "greedy would give .* (worse)" ex.out &&
	test_near "$(total ex.out)" "$(brute kink.txt convex.txt 6)" 1e-9 &&
	test_le "$(total ex.out)" "$(total gr.out)" &&
	! test_near "$(total ex.out)" "$(total gr.out)" 1e-6 &&
	test "$(awk "\$1 == 0 { print \$2 }" ex.out)" = 4
'
test_expect_success 'every budget from 2 to 19 pieces: exact = exhaustive search' '
	for b in 2 3 5 8 11 13 17 19; do
		lib-budget -n $b kink.txt convex.txt >b.out &&
		test_near "$(total b.out)" "$(brute kink.txt convex.txt $b)" 1e-9 || return 1
	done
'
test_expect_success 'a budget in grams: pieces of different weight' '
	lib-budget -g 20 --piece-grams 3.5,1.25 --names upper,lower kink.txt convex.txt >g.out &&
	test_near "$(total g.out)" "$(brute kink.txt convex.txt 20 3.5 1.25)" 1e-9 &&
	awk "\$1 == \"total\" { exit !(\$4 <= 20) }" g.out &&
	grep "^upper " g.out && grep "^lower " g.out
'
test_expect_success 'real curves: dict-learn sweeps of the talking head' '
	head-gen -f 36 -s 3 >head.mesh &&
	seg-graphcut --seeds "$TEST_DIRECTORY/../examples/stopshop/head.seeds" head.mesh >seg.lab &&
	part-split -l seg.lab -o "part_%d.mesh" head.mesh &&
	dict-learn --sweep 1:14 --seed 1 part_0.mesh >s0.txt &&
	dict-learn --sweep 1:14 --seed 1 part_1.mesh >s1.txt &&
	lib-budget -n 12 s0.txt s1.txt >r.out &&
	test_near "$(total r.out)" "$(brute s0.txt s1.txt 12)" 1e-9 &&
	lib-budget --method greedy -n 12 s0.txt s1.txt >rg.out &&
	test_le "$(total r.out)" "$(total rg.out)" &&
	d1=$(awk "\$1 == 1 { print \$2 }" r.out) &&
	dict-learn -d "$d1" --seed 1 --report rep1.txt part_1.mesh >/dev/null &&
	e1=$(awk "\$1 == \"energy\" { print \$2 }" rep1.txt) &&
	test_near "$e1" "$(awk "\$1 == 1 { print \$3 }" r.out)" 1e-9
'
test_expect_success 'a budget below the number of parts: clear error' '
	test_fails_cleanly lib-budget -n 1 kink.txt convex.txt 2>err &&
	grep "budget of 1 pieces is below the number of parts (2)" err
'
test_expect_success 'a budget below the smallest libraries: clear error' '
	printf "5 1\n6 0.5\n" >from5.txt &&
	test_fails_cleanly lib-budget -n 5 from5.txt convex.txt 2>err &&
	grep "smallest library of every part already costs 6, over the budget 5 pieces" err &&
	test_fails_cleanly lib-budget -g 1.5 --piece-grams 1,1 kink.txt convex.txt 2>err &&
	grep "costs 2, over the budget 1.5 g" err
'
test_expect_success 'bad curves and usage' '
	printf "1 2\n1 1\n" >dup.txt && test_fails_cleanly lib-budget -n 4 dup.txt 2>err && grep "must increase" err &&
	printf "1.5 2\n" >frac.txt && test_fails_cleanly lib-budget -n 4 frac.txt 2>err && grep "not a positive integer" err &&
	printf "1 nan\n" >nan.txt && test_fails_cleanly lib-budget -n 4 nan.txt 2>err &&
	test_must_fail_usage lib-budget kink.txt 2>err &&
	test_must_fail_usage lib-budget -n 3 -g 3 kink.txt 2>err &&
	test_must_fail_usage lib-budget -g 3 kink.txt 2>err &&
	test_must_fail_usage lib-budget -g 3 --piece-grams 1 kink.txt convex.txt 2>err &&
	test_must_fail_usage lib-budget -n 3 --method fast kink.txt 2>err
'
test_done
