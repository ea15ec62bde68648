#!/bin/sh
test_description='assembly-sheet --changes: per frame only what the animator swaps; --volumes from piece-plug'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'setup' '
	printf "0\n0\n1\n1\n1\n2\n" >up.lab &&
	printf "3\n4\n4\n4\n0\n0\n" >low.lab
'
test_expect_success 'only the frames and parts that change, frame 0 in full' '
	assembly-sheet -v --changes -n upper,lower up.lab low.lab >sheet.csv 2>err &&
	cat >expect <<-\EOF &&
	frame,upper,lower
	0,0,3
	1,,4
	2,1,
	4,,0
	5,2,
	EOF
	test_cmp expect sheet.csv &&
	grep "4 swaps on set" err
'
test_expect_success 'without --changes every frame is listed' '
	assembly-sheet up.lab low.lab >full.csv &&
	test "$(wc -l <full.csv)" = 7
'
test_expect_success '--volumes: grams from a piece-plug report' '
	printf "# part piece volume grams\n0 0 1 0\n0 1 2 0\n0 2 1.5 0\n1 0 0.5 0\n1 1 0.5 0\n1 2 0.5 0\n1 3 1 0\n1 4 1 0\n" >vol.txt &&
	assembly-sheet --volumes vol.txt --unit-mm 10 --density 1 -c cat.csv up.lab low.lab >/dev/null &&
	grep "^part0,1,3,2-4,2,2$" cat.csv &&
	grep "^part1,3,1,0,1,1$" cat.csv
'
test_expect_success '--volumes: a missing piece or a label past the pieces is an error' '
	printf "0 0 1\n0 2 1\n1 0 1\n" >holes.txt &&
	test_fails_cleanly assembly-sheet --volumes holes.txt up.lab low.lab 2>err && grep "no volume for part 0 piece 1" err &&
	printf "0 0 1\n0 1 1\n0 2 1\n1 0 1\n" >few.txt &&
	test_fails_cleanly assembly-sheet --volumes few.txt up.lab low.lab 2>err &&
	test_must_fail_usage assembly-sheet --volumes vol.txt -s a,b up.lab low.lab 2>err
'
test_done
