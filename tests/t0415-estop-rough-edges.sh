#!/bin/sh
test_description='rough edges of issue 14: anim-render -C with one-frame inputs, mesh-clean(1), nricp --help'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'anim-render -C 4 with four one-frame inputs: one row of four tiles' '
	for k in 1 2 3 4; do mesh-gen -s $k icosphere >s$k.mesh || return 1; done &&
	anim-render -C 4 -s 50x40 --gap 2 -f ppm s1.mesh s2.mesh s3.mesh s4.mesh >four.ppm &&
	test "$(head -c 20 four.ppm | tr "\n" " " | cut -d" " -f2,3)" = "210 44" &&
	anim-render -C 2 -s 50x40 --gap 2 -f ppm -t a,b,c,d s1.mesh s2.mesh s3.mesh s4.mesh >two.ppm &&
	test "$(head -c 20 two.ppm | tr "\n" " " | cut -d" " -f2,3)" = "106 86"
'
test_expect_success 'anim-render: inputs of several frames still start a row each' '
	mesh-gen -f 3 -a wave grid >w.mesh &&
	anim-render -C 4 -s 50x40 --gap 2 -f ppm --all w.mesh w.mesh >rows.ppm &&
	test "$(head -c 20 rows.ppm | tr "\n" " " | cut -d" " -f2,3)" = "210 86"
'
test_expect_success 'mesh-clean(1) lists --no-unfold once' '
	test "$(grep -c "^\.B \\\\-\\\\-no\\\\-unfold" "$STOPMO_ROOT/man/man1/mesh-clean.1")" = 1
'
test_expect_success 'nricp --help: -l is optional' '
	nricp --help >h.txt &&
	grep -q "^Usage: nricp \[options\] \[-l LANDMARKS\] SOURCE TARGET" h.txt &&
	grep -A1 "^  -l, --landmarks" h.txt | grep -q optional
'
test_done
