#!/bin/sh
test_description='plot-xy: line charts of column files as PPM/PNG'
. "$(dirname "$0")/test-lib.sh"

# ppm_header FILE: the first three header fields of a P6 file, one line
ppm_header() {
	head -c 15 "$1" | tr '\n' ' ' | awk '{ print $1, $2, $3, $4 }'
}

# pixels R G B FILE: how many pixels of a P6 file (header of 3 lines, no
# comments, as plot-xy writes it) have exactly this colour
pixels() {
	hdr=$(head -n 3 "$4" | wc -c)
	tail -c +$((hdr + 1)) "$4" | od -An -v -tu1 -w3 |
		awk -v r="$1" -v g="$2" -v b="$3" '$1 == r && $2 == g && $3 == b { n++ } END { print n + 0 }'
}

# png_size FILE: "W H" from the IHDR chunk
png_size() {
	od -An -v -tu1 -j16 -N8 "$1" |
		awk '{ print $1 * 16777216 + $2 * 65536 + $3 * 256 + $4, $5 * 16777216 + $6 * 65536 + $7 * 256 + $8 }'
}

test_expect_success 'setup: a sweep with three series' '
	awk "BEGIN { print \"# d mean max neg\"; for (i = 1; i <= 20; i++) print i, 10 / i, 30 / i, -i }" >sweep.txt &&
	test "$(grep -vc "^#" sweep.txt)" = 20
'
test_expect_success 'PPM of the requested size' '
	plot-xy -f ppm -s 320x200 sweep.txt >a.ppm &&
	test "$(ppm_header a.ppm)" = "P6 320 200 255" &&
	test "$(wc -c <a.ppm)" = $((15 + 320 * 200 * 3)) &&
	plot-xy -f ppm sweep.txt >d.ppm &&
	test "$(ppm_header d.ppm)" = "P6 640 400 255" &&
	test "$(wc -c <d.ppm)" = $((15 + 640 * 400 * 3))
'
test_expect_success 'PNG by default, of the requested size' '
	plot-xy -s 500x300 sweep.txt >a.png &&
	od -An -tx1 -N8 a.png | tr -d " \n" >magic && test "$(cat magic)" = 89504e470d0a1a0a &&
	test "$(png_size a.png)" = "500 300" &&
	plot-xy sweep.txt >d.png && test "$(png_size d.png)" = "640 400"
'
test_expect_success 'one series draws in the first colour only' '
	test_le 200 "$(pixels 31 119 180 a.ppm)" &&
	test "$(pixels 255 127 14 a.ppm)" = 0 &&
	test "$(pixels 44 160 44 a.ppm)" = 0
'
test_expect_success 'several series: one colour each, with a legend' '
	plot-xy -f ppm -s 320x200 -y 2,3,4 -n mean,max,neg -t "sweep" --xlabel d --ylabel error \
		sweep.txt >three.ppm &&
	test "$(ppm_header three.ppm)" = "P6 320 200 255" &&
	test_le 200 "$(pixels 31 119 180 three.ppm)" &&
	test_le 200 "$(pixels 255 127 14 three.ppm)" &&
	test_le 200 "$(pixels 44 160 44 three.ppm)" &&
	! cmp -s a.ppm three.ppm
'
test_expect_success 'an empty name keeps its place in --names' '
	plot-xy -f ppm -y 2,3 -n ",max" sweep.txt >n1.ppm &&
	plot-xy -f ppm -y 2,3 -n "max" sweep.txt >n2.ppm &&
	plot-xy -f ppm -y 2,3 -n "column 2,max" sweep.txt >n3.ppm &&
	! cmp -s n1.ppm n2.ppm && test_cmp n1.ppm n3.ppm
'
test_expect_success 'the series is drawn where its values are: a rising line in the top right' '
	awk "BEGIN { for (i = 0; i <= 10; i++) print i, i }" >rise.txt &&
	plot-xy -f ppm -s 200x160 rise.txt >rise.ppm &&
	hdr=$(head -n 3 rise.ppm | wc -c) &&
	tail -c +$((hdr + 1)) rise.ppm | od -An -v -tu1 -w3 |
		awk "\$1 == 31 && \$2 == 119 && \$3 == 180 { x = (NR - 1) % 200; y = int((NR - 1) / 200)
		     if (x > 150 && y < 60) tr++; if (x > 150 && y > 100) br++ }
		     END { print tr + 0, br + 0 }" >quad &&
	read tr br <quad && test_le 10 "$tr" && test "$br" = 0
'
test_expect_success '-o picks the format from the extension and writes atomically' '
	plot-xy -o out.ppm sweep.txt >o.stdout && test ! -s o.stdout &&
	test "$(ppm_header out.ppm)" = "P6 640 400 255" &&
	plot-xy -o out.png sweep.txt && test "$(png_size out.png)" = "640 400" &&
	plot-xy -f png -o forced.ppm sweep.txt && test "$(png_size forced.ppm)" = "640 400"
'
test_expect_success 'standard input; same input, same bytes; --logy' '
	plot-xy -y 2,3 --logy <sweep.txt >s1.png &&
	plot-xy -y 2,3 --logy - <sweep.txt >s2.png &&
	plot-xy -y 2,3 --logy sweep.txt >s3.png &&
	test_cmp s1.png s2.png && test_cmp s1.png s3.png &&
	plot-xy -y 2,3 sweep.txt >lin.png && ! cmp -s s1.png lin.png
'
test_expect_success 'degenerate data still plots: one row, a constant, huge values' '
	echo "3 7" >one.txt && plot-xy -f ppm -s 160x120 one.txt >one.ppm &&
	test "$(ppm_header one.ppm)" = "P6 160 120 255" &&
	printf "1 5\n2 5\n3 5\n" >flat.txt && plot-xy flat.txt >flat.png &&
	printf "1e16 1\n10000000000000002 2\n1e16 3\n" >huge.txt &&
	plot-xy -f ppm huge.txt >huge.ppm && test "$(ppm_header huge.ppm)" = "P6 640 400 255" &&
	printf "1 1e-300\n2 1e300\n" >span.txt && plot-xy --logy span.txt >span.png
'
test_expect_success 'bad input fails cleanly: nothing on stdout, no file left' '
	printf "1 2\n2 x\n" >word.txt &&
	test_fails_cleanly plot-xy word.txt &&
	grep "line 2" .err &&
	printf "1 2\n2 3 4\n" >ragged.txt &&
	test_fails_cleanly plot-xy ragged.txt &&
	test_fails_cleanly plot-xy -y 5 sweep.txt &&
	grep "column 5" .err &&
	test_fails_cleanly plot-xy -x 9 -y 2 sweep.txt &&
	test_fails_cleanly plot-xy -y 4 --logy sweep.txt &&
	grep "log axis" .err &&
	printf "1 1\n2 0\n" >zero.txt &&
	test_fails_cleanly plot-xy --logy zero.txt &&
	test_fails_cleanly plot-xy nosuch.txt &&
	printf "# only a comment\n\n" >empty.txt &&
	test_fails_cleanly plot-xy empty.txt &&
	printf "1 inf\n" >inf.txt &&
	test_fails_cleanly plot-xy inf.txt &&
	test_fails_cleanly plot-xy -o bad.png word.txt &&
	test_fails_cleanly plot-xy -o bad.png --logy zero.txt &&
	ls >files && ! grep -q "bad.png" files
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage plot-xy -x 0 sweep.txt >u.out 2>u.err &&
	test_must_fail_usage plot-xy -y 0 sweep.txt >>u.out 2>>u.err &&
	test_must_fail_usage plot-xy -y 2,a sweep.txt >>u.out 2>>u.err &&
	test_must_fail_usage plot-xy -s 100x100 sweep.txt >>u.out 2>>u.err &&
	test_must_fail_usage plot-xy -s big sweep.txt >>u.out 2>>u.err &&
	test_must_fail_usage plot-xy -f gif sweep.txt >>u.out 2>>u.err &&
	test_must_fail_usage plot-xy sweep.txt sweep.txt >>u.out 2>>u.err &&
	test_must_fail_usage plot-xy --bogus sweep.txt >>u.out 2>>u.err &&
	test ! -s u.out
'
test_expect_success '--help and --version' '
	plot-xy --help >help && grep "^Usage: plot-xy" help && grep "Example" help &&
	plot-xy --version >v && grep "^plot-xy (stopmo)" v
'
test_done
