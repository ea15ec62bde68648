#!/bin/sh
test_description='clay-classify: Eq. 2.1 scores and the C1/C2/C3 categories; bad input'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'an almost rigid character is C2' '
	echo "rotate 1 5 0 0 4" >rigid.txt &&
	clay-classify rigid.txt >out && grep -q "^category C2" out &&
	test "$(awk "/^uniform/ { print \$2 }" out)" = 9
'
test_expect_success 'squash and stretch at large scale with salient points is C1' '
	echo "squash-stretch 1 0 1 4 3" >blob.txt &&
	clay-classify blob.txt >out && grep -q "^category C1" out &&
	test "$(awk "/^nonuniform/ { print \$2 }" out)" = 8
'
test_expect_success 'Party Onion segments (thesis Tables 2.3-2.4): Eq. 2.1 by hand' '
	printf "# body\nsquash-stretch 0.6 3 2 0 1\nfurl 0.3 0 2 3 0\ntranslate 0.1 3 1 1 2\n" >onion.txt &&
	clay-classify onion.txt >out && cat out &&
	test_near "$(awk "/^uniform/ { print \$2 }" out)" 5.72 1e-9 &&
	test_near "$(awk "/^extrinsic/ { print \$2 }" out)" 7 1e-9
'
test_expect_success 'bad input fails cleanly' '
	echo "wobble 1 1 0 0 0" >bad1.txt && test_fails_cleanly clay-classify bad1.txt &&
	echo "rotate 0.5 1 0 0 0" >bad2.txt && test_fails_cleanly clay-classify bad2.txt &&
	echo "rotate 1 1 0" >bad3.txt && test_fails_cleanly clay-classify bad3.txt &&
	echo "# nothing" >bad4.txt && test_fails_cleanly clay-classify bad4.txt &&
	test_fails_cleanly clay-classify missing.txt
'
test_done
