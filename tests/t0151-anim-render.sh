#!/bin/sh
test_description='anim-render: contact sheets, one image per frame, several inputs'
. "$(dirname "$0")/test-lib.sh"

png_size() {
	sig=$(od -An -tx1 -N8 "$1" | tr -d ' \n')
	test "$sig" = 89504e470d0a1a0a || { echo "not a PNG: $sig" >&2; return 1; }
	od -An -tu1 -j16 -N8 "$1" | awk '{ print $1*16777216 + $2*65536 + $3*256 + $4, $5*16777216 + $6*65536 + $7*256 + $8 }'
}

test_expect_success 'setup: two animations of different lengths' '
	mesh-gen -f 10 -a twist -n 8 -m 6 cylinder >a.mesh &&
	mesh-gen -f 7 -a bend -n 8 -m 6 cylinder >b.mesh
'
test_expect_success 'grid layout: --count 4 --columns 2' '
	anim-render --count 4 --columns 2 -s 100x80 --gap 4 a.mesh >s.png &&
	png_size s.png >size && echo "212 172" >expect && test_cmp expect size
'
test_expect_success '--frames and --every choose the tiles (default columns = tiles)' '
	anim-render --frames 0,3,-1 -s 50x50 --gap 2 a.mesh >f.png &&
	png_size f.png >size && echo "158 54" >expect && test_cmp expect size &&
	anim-render --every 4 -s 50x50 --gap 2 a.mesh >e.png &&
	png_size e.png >size && test_cmp expect size
'
test_expect_success 'two inputs are two rows; titles add a left margin' '
	anim-render --count 3 -s 60x60 --gap 0 a.mesh b.mesh >two.png &&
	png_size two.png >size && echo "180 120" >expect && test_cmp expect size &&
	anim-render --count 3 -s 60x60 --gap 0 -t input,result a.mesh b.mesh >t.png &&
	png_size t.png | awk "{ exit !(\$1 > 180 && \$2 == 120) }"
'
test_expect_success 'frames missing from the shorter input leave empty tiles' '
	anim-render --frames 0,8 -s 40x40 --gap 0 -f ppm a.mesh b.mesh >m.ppm &&
	head -c 20 m.ppm | sed -n 2p >dim && echo "80 80" >expect && test_cmp expect dim
'
test_expect_success 'frame stamps change the image; --no-stamp removes them' '
	anim-render --count 2 -s 64x64 -f ppm a.mesh >st.ppm &&
	anim-render --count 2 -s 64x64 -f ppm --no-stamp a.mesh >ns.ppm &&
	! cmp -s st.ppm ns.ppm
'
test_expect_success '--each writes one image per chosen frame' '
	anim-render --every 3 -s 32x32 --each "fr_%03d.png" a.mesh >out &&
	test ! -s out && ls fr_*.png >list &&
	printf "fr_000.png\nfr_003.png\nfr_006.png\nfr_009.png\n" >expect && test_cmp expect list &&
	png_size fr_003.png >size && echo "32 32" >expect && test_cmp expect size
'
test_expect_success '--each with two inputs puts them side by side' '
	anim-render --count 2 -s 32x32 --gap 2 --each "pair_%d.ppm" a.mesh b.mesh &&
	head -c 20 pair_9.ppm | sed -n 2p >dim && echo "70 36" >expect && test_cmp expect dim
'
test_expect_success 'reads stdin and the same labels for every input' '
	nf=$(sed -n "s/^faces //p" a.mesh) &&
	awk -v n=$nf "BEGIN { for (i = 0; i < n; i++) print i % 4 }" >parts.labels &&
	anim-render --count 2 -s 40x40 --labels parts.labels <a.mesh >l.png && png_size l.png &&
	anim-render --count 2 -s 40x40 --labels parts.labels a.mesh b.mesh >l2.png
'
test_expect_success 'streams without a frame count (two passes) give the same sheet' '
	sed "s/^frames .*/frames ?/" a.mesh >a-unknown.mesh &&
	anim-render --count 4 -s 48x48 a.mesh >mem.png &&
	anim-render --count 4 -s 48x48 a-unknown.mesh >stream.png && test_cmp mem.png stream.png &&
	anim-render --count 4 -s 48x48 <a-unknown.mesh >stdin.png && test_cmp mem.png stdin.png &&
	anim-render --frames 5,0,-1,3 -s 48x48 a.mesh >mem2.png &&
	anim-render --frames 5,0,-1,3 -s 48x48 <a-unknown.mesh >stream2.png && test_cmp mem2.png stream2.png
'
test_expect_success '--each from stdin matches --each from a file' '
	mkdir -p e1 e2 &&
	anim-render --every 4 -s 32x32 --each "e1/%d.png" a.mesh &&
	anim-render --every 4 -s 32x32 --each "e2/%d.png" <a.mesh &&
	for f in 0 4 8; do test_cmp e1/$f.png e2/$f.png || return 1; done
'
test_expect_success 'bad input: clean errors' '
	test_fails_cleanly anim-render --frames 0,99 a.mesh &&
	mesh-gen -s 1 icosphere >ico.mesh &&
	test_fails_cleanly anim-render --labels parts.labels a.mesh ico.mesh &&
	head -c 1500 a.mesh >trunc.mesh &&
	test_fails_cleanly anim-render trunc.mesh &&
	mkdir -p none && test_fails_cleanly anim-render --each "none/%d.png" trunc.mesh &&
	test_fails_cleanly anim-render --each "none/%d.png" <trunc.mesh && ls none >list && test ! -s list &&
	test_fails_cleanly anim-render -o out.png a.mesh no-such.mesh && test ! -e out.png
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage anim-render --each "x.png" a.mesh &&
	test_must_fail_usage anim-render --each "x_%d_%d.png" a.mesh &&
	test_must_fail_usage anim-render --each "x_%s.png" a.mesh &&
	test_must_fail_usage anim-render -t one,two a.mesh &&
	test_must_fail_usage anim-render --count 0 a.mesh &&
	test_must_fail_usage anim-render --columns 0 a.mesh &&
	test_must_fail_usage anim-render --every 2 --count 3 a.mesh &&
	test_must_fail_usage anim-render --size 5 a.mesh &&
	test_must_fail_usage anim-render --view nowhere a.mesh
'
test_expect_success '--help and --version' '
	anim-render --help >help && grep -q "^Usage: anim-render" help &&
	anim-render --version >v && grep -q stopmo v
'
test_done
