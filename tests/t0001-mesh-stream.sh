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
test_done
