#!/bin/sh
test_description='nricp --chain on the camel scans 01-05 without landmark files: every key close, few flipped faces'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/estop-lib.sh"
need_shared_data scans/camel-gallop-05.off

test_expect_success 'setup: clean scans 01-05' '
	camel_scans 01 02 03 04 05
'
# measured (shared machine): 0.34, 0.60, 0.58, 0.93% of the diagonal with 0,
# 10, 4, 5 flipped faces, the previous key kept as the rest shape every time;
# before (the rest shape SOURCE, no untangling): 0.34, 1.19, 1.55, 1.87% with
# 0, 41, 93, 102
test_expect_success 'every key within 1% of the diagonal, at most 10 flipped faces' '
	nricp -v --chain c01.mesh c02.mesh c03.mesh c04.mesh c05.mesh >keys.mesh 2>err &&
	grep "kept start" err &&
	i=1 && for k in 02 03 04 05; do
		anim-slice -f $i keys.mesh >k.mesh &&
		mesh-metrics --no-header -r c$k.mesh k.mesh >m$k.txt && cat m$k.txt &&
		test_le "$(awk "{ print \$3 }" m$k.txt)" 0.01 &&
		test_le "$(awk "{ print \$5 }" m$k.txt)" 10 || return 1
		i=$((i + 1))
	done
'
# with --refine (the default since): 0.16, 0.27, 0.57, 0.46% with no
# flipped face (before: 0.34, 0.60, 0.55, 0.75% with 0, 3, 0, 0); the last
# key is still 3 times the first, not within the issue's 1.2 times: no
# registration onto scan 05 comes below 0.31% (nricp(1), --refine).  With
# --settle (the default since: every key registered again from itself
# after the chain, kept where closer) 0.156, 0.252, 0.280, 0.359% with no
# flipped face, where the chain left 0.156, 0.273, 0.573, 0.465%
test_expect_success 'refined and settled keys: the first below 0.25%, the last below 0.45%' '
	test_le "$(awk "{ print \$3 }" m02.txt)" 0.0025 &&
	test_le "$(awk "{ print \$3 }" m05.txt)" 0.0045
'
test_done
