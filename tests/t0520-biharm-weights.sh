#!/bin/sh
test_description='biharm-weights: pose-space weights (N-way morphing Sec. 4.1)'
. "$(dirname "$0")/test-lib.sh"

# largest |a - b| between two column files
maxdiff() { paste "$1" "$2" | awk '{ n = NF / 2; for (i = 1; i <= n; i++) { d = $i - $(i + n); if (d < 0) d = -d; if (d > m) m = d } } END { print m + 0 }'; }

test_expect_success 'unit weights at each pose point (1e-9)' '
	printf "0 0\n1 0\n0 1\n1.2 0.9\n" >poses.txt &&
	biharm-weights poses.txt poses.txt >w.txt &&
	printf "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n" >expect &&
	test_le $(maxdiff w.txt expect) 1e-9
'
test_expect_success 'rows sum to 1 anywhere, also outside the meshed box' '
	printf "0.3 0.2\n-0.5 0.4\n2 2\n0.9 0.9\n100 -100\n" >q.txt &&
	biharm-weights poses.txt q.txt >wq.txt &&
	awk "{ s = 0; for (i = 1; i <= NF; i++) s += \$i; d = s - 1; if (d < 0) d = -d; if (d > m) m = d } END { print m + 0 }" wq.txt >dev &&
	test_le $(cat dev) 1e-9
'
test_expect_success 'two poses and three collinear poses work' '
	printf "0 0\n1 0\n" >p2.txt && printf "0 0\n" | biharm-weights p2.txt >w2.txt &&
	echo "1 0" >expect && test_cmp expect w2.txt &&
	printf "0 0\n1 0\n2 0\n" >p3.txt && printf "1 0\n1 0.5\n" | biharm-weights p3.txt >w3.txt &&
	test $(wc -l <w3.txt) -eq 2 && head -1 w3.txt >mid && echo "0 1 0" >expect && test_cmp expect mid
'
test_expect_success 'weights level out far from the data' '
	printf "1.5 0.5\n2 0.5\n2.5 0.5\n3 0.5\n" | biharm-weights poses.txt >ray.txt &&
	awk "NR == 1 { for (i = 1; i <= NF; i++) a[i] = \$i } NR == 2 { for (i = 1; i <= NF; i++) b[i] = \$i }
	     NR == 3 { for (i = 1; i <= NF; i++) c[i] = \$i } NR == 4 { for (i = 1; i <= NF; i++) d[i] = \$i }
	     END { for (i = 1; i <= 4; i++) { n += (b[i] - a[i]) ^ 2; f += (d[i] - c[i]) ^ 2 } print sqrt(f), 0.5 * sqrt(n) }" ray.txt >steps &&
	read far near <steps && test_le $far $near
'
test_expect_success '--grid dump for plotting' '
	biharm-weights -g 5 poses.txt >grid.txt && test $(grep -c . grid.txt) -eq 25 &&
	awk "NF && NF != 6 { exit 1 }" grid.txt
'
test_expect_success 'bad input: duplicate pose, junk query, wrong columns' '
	printf "0 0\n1 0\n0 0\n" >dup.txt && test_fails_cleanly biharm-weights dup.txt poses.txt &&
	printf "0 0\nx 1\n" >junk.txt && test_fails_cleanly biharm-weights poses.txt junk.txt &&
	printf "0 0 1\n" >three.txt && test_fails_cleanly biharm-weights three.txt poses.txt &&
	test_must_fail_usage biharm-weights 2>/dev/null
'
test_done
