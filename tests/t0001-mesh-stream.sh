#!/bin/sh
test_description='MESH stream: plain and raw round trips, bad input'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'generated grid is a valid plain stream' '
	mesh-gen -n 3 grid >grid.mesh &&
	head -1 grid.mesh >magic && echo "MESH 1" >expect && test_cmp expect magic
'
test_expect_success 'plain -> raw -> plain is bit-exact' '
	mesh-gen -f 5 -a twist -n 7 cylinder >a.mesh &&
	STOPMO_RAW=1 mesh-gen -f 5 -a twist -n 7 cylinder >a.raw &&
	head -1 a.raw >magic && echo "MESH 1 raw" >expect && test_cmp expect magic
'
test_expect_success '-o to a FIFO writes through it and leaves it a FIFO' '
	mkfifo fifo && printf "1 2\n2 3\n" >d &&
	{ plot-xy -f ppm -o fifo d & } &&
	head -c 2 fifo >magic && wait &&
	printf P6 >expect && test_cmp expect magic && test -p fifo
'
test_expect_success 'raw stream: text lines longer than what a raw stream reads at a time (10 KB comments before frames 0 and 3), from a file and a pipe' '
	head-gen -f 5 --seed 1 >h5.mesh && anim-slice --raw h5.mesh >h5r.mesh &&
	o0=$(grep -abo "frame 0" h5r.mesh | head -1 | cut -d: -f1) &&
	o3=$(grep -abo "frame 3" h5r.mesh | head -1 | cut -d: -f1) &&
	test -n "$o0" && test "$o3" -gt "$o0" &&
	awk "BEGIN { s = \"#\"; for (i = 0; i < 10000; i++) s = s \"x\"; print s }" >c.txt &&
	{ head -c $o0 h5r.mesh && cat c.txt && tail -c +$((o0 + 1)) h5r.mesh | head -c $((o3 - o0)) &&
	  cat c.txt && tail -c +$((o3 + 1)) h5r.mesh; } >h5rc.mesh &&
	test $(wc -c <h5rc.mesh) -eq $(($(wc -c <h5r.mesh) + 2 * $(wc -c <c.txt))) &&
	anim-slice h5.mesh >want.mesh &&
	anim-slice h5rc.mesh >got.mesh && test_cmp want.mesh got.mesh &&
	cat h5rc.mesh | anim-slice >got2.mesh && test_cmp want.mesh got2.mesh
'
test_done
