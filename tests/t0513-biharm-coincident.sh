#!/bin/sh
test_description='biharm-weights: coincident poses named in the user'"'"'s terms; many queries in one run equal single runs'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'two poses at the same place: the message names them and says what to do' '
	printf "0 0\n1 0\n0 1\n1 0\n" >same.txt &&
	echo "0.3 0.3" >q.txt &&
	test_fails_cleanly biharm-weights same.txt q.txt 2>err &&
	grep "poses 2 and 4 are at the same place" err &&
	grep "drop one of them" err &&
	! grep -i "positive definite" err
'
test_expect_success 'two poses 1e-7 apart (CHOLMOD found them singular): nearly coincide, not a matrix message' '
	printf "0 0\n1 0\n1.0000001 0\n0 1\n" >near.txt &&
	test_fails_cleanly biharm-weights near.txt q.txt 2>err &&
	grep "poses 2 and 3 nearly coincide" err &&
	grep "move them at least" err &&
	! grep -i "positive definite\|quadratic" err
'
test_expect_success 'poses a hundredth of the extent apart still work' '
	printf "0 0\n1 0\n1.01 0\n0 1\n" >close.txt &&
	biharm-weights close.txt q.txt >w.txt && test $(wc -w <w.txt) -eq 4
'
test_expect_success 'many queries in one run equal one run per query, bit for bit' '
	printf "0 0\n1 0\n0 1\n1.2 0.9\n0.4 1.6\n" >poses.txt &&
	awk "BEGIN { for (i = 0; i < 40; i++) printf \"%.6f %.6f\n\", -0.7 + 0.061 * i, 1.9 - 0.07 * i }" >many.txt &&
	biharm-weights poses.txt many.txt >all.txt &&
	: >one.txt &&
	while read x y; do echo "$x $y" | biharm-weights poses.txt >>one.txt || return 1; done <many.txt &&
	test $(wc -l <all.txt) -eq 40 &&
	test_cmp one.txt all.txt
'
test_done
