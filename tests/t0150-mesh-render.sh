#!/bin/sh
test_description='mesh-render: size, coverage, shading, colours, bad input'
. "$(dirname "$0")/test-lib.sh"

# ppm_stats FILE: prints "w h coverage levels spread blue orange dark mean"
#   coverage  fraction of pixels that differ from the white background
#   levels    distinct luminance values on the object
#   spread    standard deviation of the object's luminance
#   blue, orange  fractions of object pixels clearly blue / clearly orange
#   dark      fraction of all pixels with luminance below 80
#   mean      mean luminance of the object
ppm_stats() {
	set -- "$1" $(head -c 20 "$1" | tr '\n' ' ' | cut -d' ' -f2,3)
	hdr=$(printf 'P6\n%s %s\n255\n' "$2" "$3" | wc -c)
	tail -c +$((hdr + 1)) "$1" | od -An -v -tu1 | awk -v w="$2" -v h="$3" '
	{ for (i = 1; i <= NF; i++) { c[k++] = $i; if (k == 3) { px(); k = 0 } } }
	function px(  r, g, b, l) {
		r = c[0]; g = c[1]; b = c[2]; n++
		l = int(0.299 * r + 0.587 * g + 0.114 * b)
		if (l < 80) dark++
		if (r == 255 && g == 255 && b == 255) return
		obj++; lev[l] = 1; s += l; s2 += l * l
		if (b > r + 30) blue++
		if (r > b + 60) orange++
	}
	END { nl = 0; for (x in lev) nl++
		m = obj ? s / obj : 0; v = obj ? s2 / obj - m * m : 0
		printf "%d %d %.4f %d %.2f %.4f %.4f %.4f %.2f\n", w, h, obj / n, nl, sqrt(v > 0 ? v : 0),
			obj ? blue / obj : 0, obj ? orange / obj : 0, dark / n, m }'
}
stat_field() { echo "$1" | cut -d' ' -f"$2"; }

# png_size FILE: "w h" from the IHDR chunk, after checking the signature
png_size() {
	sig=$(od -An -tx1 -N8 "$1" | tr -d ' \n')
	test "$sig" = 89504e470d0a1a0a || { echo "not a PNG: $sig" >&2; return 1; }
	od -An -tu1 -j16 -N8 "$1" | awk '{ print $1*16777216 + $2*65536 + $3*256 + $4, $5*16777216 + $6*65536 + $7*256 + $8 }'
}

test_expect_success 'setup: icosphere, labels, scalars' '
	mesh-gen -s 3 icosphere >ico.mesh &&
	nf=$(sed -n "s/^faces //p" ico.mesh) && nv=$(sed -n "s/^vertices //p" ico.mesh) &&
	awk -v n=$nf "BEGIN { for (i = 0; i < n; i++) print (i < n / 2 ? 0 : 1) }" >two.labels &&
	awk -v n=$nv "BEGIN { for (i = 0; i < n; i++) print i % 3 - 1 }" >vertex.labels &&
	awk "/^frame 0/ { go = 1; next } go { print \$2 }" ico.mesh >height.txt &&
	awk -v n=$((nf + 1)) "BEGIN { for (i = 0; i < n; i++) print 0 }" >bad.labels &&
	test $(wc -l <height.txt) -eq $nv
'
test_expect_success 'PNG output has the requested size' '
	mesh-render --size 300x200 ico.mesh >ico.png &&
	png_size ico.png >size && echo "300 200" >expect && test_cmp expect size
'
test_expect_success 'PNG by -o extension, PPM by -o extension and by --format' '
	mesh-render -s 64x48 -o a.png ico.mesh && png_size a.png >size &&
	echo "64 48" >expect && test_cmp expect size &&
	mesh-render -s 64x48 -o a.ppm ico.mesh && head -c 2 a.ppm >magic &&
	printf P6 >expect && test_cmp expect magic &&
	mesh-render -s 64x48 --format ppm ico.mesh >b.ppm && test_cmp a.ppm b.ppm
'
test_expect_success 'the sphere covers the expected fraction and is shaded' '
	mesh-render -s 120x120 -f ppm ico.mesh >ico.ppm &&
	st=$(ppm_stats ico.ppm) && echo "$st" &&
	test "$(stat_field "$st" 1) $(stat_field "$st" 2)" = "120 120" &&
	test_le 0.55 $(stat_field "$st" 3) && test_le $(stat_field "$st" 3) 0.75 &&
	test_le 20 $(stat_field "$st" 4) && test_le 15 $(stat_field "$st" 5)
'
test_expect_success '--compact writes a smaller PNG of the same size' '
	mesh-render -s 200x200 ico.mesh >fast.png &&
	mesh-render -s 200x200 --compact ico.mesh >small.png &&
	png_size small.png >size && echo "200 200" >expect && test_cmp expect size &&
	test_le $(wc -c <small.png) $(wc -c <fast.png)
'
test_expect_success 'same input, same bytes' '
	mesh-render -s 100x100 --view iso -w ico.mesh >r1.png &&
	mesh-render -s 100x100 --view iso -w ico.mesh >r2.png && test_cmp r1.png r2.png
'
test_expect_success 'two face labels give two distinct colours' '
	mesh-render -s 120x120 -f ppm --labels two.labels --view iso ico.mesh >lab.ppm &&
	st=$(ppm_stats lab.ppm) && echo "$st" &&
	test_le 0.2 $(stat_field "$st" 6) && test_le 0.2 $(stat_field "$st" 7)
'
test_expect_success 'per-vertex labels (-1 grey) are accepted' '
	mesh-render -s 80x80 --labels vertex.labels ico.mesh >vl.png && png_size vl.png
'
test_expect_success 'per-vertex scalars span the colormap; --range clamps' '
	mesh-render -s 120x120 -f ppm --scalars height.txt ico.mesh >sc.ppm &&
	st=$(ppm_stats sc.ppm) && echo "$st" && test_le 0.1 $(stat_field "$st" 6) &&
	mesh-render -s 120x120 -f ppm --scalars height.txt --range 5,6 ico.mesh >sc2.ppm &&
	st=$(ppm_stats sc2.ppm) && echo "$st" && test_le $(stat_field "$st" 6) 0.01
'
test_expect_success 'the wireframe darkens edges' '
	mesh-render -s 120x120 -f ppm -s 120x120 --flat ico.mesh >f.ppm &&
	mesh-render -s 120x120 -f ppm -s 120x120 --flat -w ico.mesh >fw.ppm &&
	a=$(stat_field "$(ppm_stats f.ppm)" 9) && b=$(stat_field "$(ppm_stats fw.ppm)" 9) &&
	echo "$a $b" && test_le $b $(awk "BEGIN { print $a - 10 }")
'
test_expect_success 'two-sided lighting: the back of an open grid is darker' '
	mesh-gen -n 4 grid >grid.mesh &&
	mesh-render -s 60x60 -f ppm --view front grid.mesh >front.ppm &&
	mesh-render -s 60x60 -f ppm --view back grid.mesh >back.ppm &&
	a=$(stat_field "$(ppm_stats front.ppm)" 9) && b=$(stat_field "$(ppm_stats back.ppm)" 9) &&
	echo "$a $b" && test_le $b $(awk "BEGIN { print $a * 0.7 }") && test_le 30 $b
'
test_expect_success 'views, up axis and perspective all render' '
	for v in front back left right top bottom iso; do
		mesh-render -s 40x40 --view $v --up z --perspective ico.mesh >v.png || return 1
	done &&
	for u in x y z -x -y -z +z; do
		mesh-render -s 40x40 --up $u --view iso ico.mesh >v.png || return 1
	done &&
	test_must_fail_usage mesh-render --up w ico.mesh &&
	mesh-render -s 40x40 -a 30 -e -20 ico.mesh >v.png
'
test_expect_success 'a later frame and --fit-all' '
	mesh-gen -f 5 -a bend -n 8 cylinder >bend.mesh &&
	mesh-render -s 50x50 --frame 4 bend.mesh >k4.png &&
	mesh-render -s 50x50 --frame 4 --fit-all bend.mesh >k4a.png &&
	mesh-render -s 50x50 --frame 2 <bend.mesh >k2.png && png_size k2.png &&
	mesh-render -s 50x50 --frame -1 bend.mesh >last.png && test_cmp k4.png last.png &&
	sed "s/^frames .*/frames ?/" bend.mesh >unknown.mesh &&
	mesh-render -s 50x50 --frame -1 <unknown.mesh >last2.png && test_cmp k4.png last2.png &&
	mesh-render -s 50x50 --frame -3 <unknown.mesh >m3.png && test_cmp k2.png m3.png &&
	mesh-render -s 50x50 --frame -1 --fit-all <unknown.mesh >la.png && test_cmp k4a.png la.png
'
test_expect_success 'degenerate meshes render: empty, no faces, one point, a line' '
	printf "MESH 1\nvertices 0\nfaces 0\nframes 1\nframe 0\n" >empty.mesh &&
	mesh-render -s 20x10 empty.mesh >e.png && png_size e.png >size &&
	echo "20 10" >expect && test_cmp expect size &&
	printf "MESH 1\nvertices 3\nfaces 0\nframes 1\nframe 0\n0 0 0\n1 0 0\n0 1 0\n" >nof.mesh &&
	mesh-render -s 20x20 nof.mesh >n.png &&
	printf "MESH 1\nvertices 3\nfaces 1\nframes 1\nf 0 1 2\nframe 0\n1 1 1\n1 1 1\n1 1 1\n" >pt.mesh &&
	mesh-render -s 20x20 --perspective pt.mesh >p.png &&
	printf "MESH 1\nvertices 3\nfaces 1\nframes 1\nf 0 1 2\nframe 0\n0 0 0\n1 0 0\n2 0 0\n" >line.mesh &&
	mesh-render -s 20x20 -w line.mesh >l.png
'
test_expect_success 'bad label count: clean error' '
	test_fails_cleanly mesh-render --labels bad.labels ico.mesh 2>err &&
	grep "faces and" err
'
test_expect_success 'non-integer label: clean error' '
	sed "1s/.*/0.5/" two.labels >frac.labels &&
	test_fails_cleanly mesh-render --labels frac.labels ico.mesh
'
test_expect_success 'missing frame: clean error, no -o file left' '
	test_fails_cleanly mesh-render --frame 5 bend.mesh &&
	test_fails_cleanly mesh-render --frame -6 bend.mesh &&
	test_fails_cleanly mesh-render --frame -6 <unknown.mesh &&
	test_fails_cleanly mesh-render --frame 9 -o out.png bend.mesh && test ! -e out.png
'
test_expect_success 'truncated or missing input: clean error' '
	head -c 2000 ico.mesh >trunc.mesh &&
	test_fails_cleanly mesh-render trunc.mesh &&
	test_fails_cleanly mesh-render no-such.mesh
'
test_expect_success 'bad --size is a usage error' '
	for s in 0x10 10x0 abc 10x 100000x10 10x10x10 -5x5; do
		test_must_fail_usage mesh-render --size $s ico.mesh >out || return 1
		test ! -s out || return 1
	done
'
test_expect_success 'unknown view and other usage errors exit 2' '
	test_must_fail_usage mesh-render --view sideways ico.mesh >out && test ! -s out &&
	test_must_fail_usage mesh-render --color 1,2 ico.mesh &&
	test_must_fail_usage mesh-render --format gif ico.mesh &&
	test_must_fail_usage mesh-render --labels two.labels --scalars height.txt ico.mesh &&
	test_must_fail_usage mesh-render --elevation 100 ico.mesh &&
	test_must_fail_usage mesh-render a.mesh b.mesh
'
test_expect_success '--only K: the faces labelled K in the uniform colour, the camera of the whole frame' '
	mesh-render -s 120x120 -f ppm -c 0,0,0 ico.mesh >all.ppm &&
	mesh-render -s 120x120 -f ppm -c 0,0,0 -l two.labels --only 0 ico.mesh >h0.ppm &&
	mesh-render -s 120x120 -f ppm -c 0,0,0 -l two.labels --only 1 ico.mesh >h1.ppm &&
	c0=$(ppm_stats h0.ppm | cut -d" " -f3) && c1=$(ppm_stats h1.ppm | cut -d" " -f3) &&
	ca=$(ppm_stats all.ppm | cut -d" " -f3) &&
	test_le 0.05 $c0 && test_le 0.05 $c1 && test_le $c0 $ca && test_le $c1 $ca &&
	test_le $ca $(awk -v a=$c0 -v b=$c1 "BEGIN { print a + b + 0.02 }") &&
	test "$(ppm_stats h0.ppm | cut -d" " -f6,7)" = "0.0000 0.0000"
'
test_expect_success '--only: bad input' '
	test_must_fail_usage mesh-render --only 1 ico.mesh >out && test ! -s out &&
	test_fails_cleanly mesh-render -l two.labels --only 7 ico.mesh &&
	head -3 two.labels >short.labels &&
	test_fails_cleanly mesh-render -l short.labels --only 1 ico.mesh &&
	test_must_fail mesh-render -l two.labels --only 7 ico.mesh 2>err &&
	grep "^mesh-render: cannot read .two.labels.: no face is labelled 7 (--only)$" err
'
test_expect_success '--help and --version' '
	mesh-render --help >help && grep -q "^Usage: mesh-render" help &&
	mesh-render --version >v && grep -q stopmo v
'
test_done
