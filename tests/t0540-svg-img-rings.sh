#!/bin/sh
test_description='svg2rings and img2rings: outlines from vector drawings and bitmaps'
. "$(dirname "$0")/test-lib.sh"

# signed area of every ring of a rings file, one per line
areas() {
	awk '$1 == "ring" { if (n) print a / 2; n = $2; a = 0; i = 0; next }
	     { x[i] = $1; y[i] = $2; i++; if (i == n) { for (k = 0; k < n; k++) { j = (k + 1) % n; a += x[k] * y[j] - x[j] * y[k] } } }
	     END { print a / 2 }' "$1"
}

test_expect_success 'svg: square with a hole (M H V Z, relative v h), y flipped' '
	cat >sq.svg <<-\EOF &&
	<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">
	  <path d="M10 10 H 90 V 90 H 10 Z M 30 30 v 40 h 40 v-40z"/>
	</svg>
	EOF
	svg2rings sq.svg >sq.rings && areas sq.rings >a &&
	printf "6400\n-1600\n" >expect && test_cmp expect a
'
test_expect_success 'svg: arcs and curves are flattened within the tolerance' '
	cat >c.svg <<-\EOF &&
	<svg xmlns="http://www.w3.org/2000/svg"><path d="M0,0 a50,50 0 1,0 100,0 a50 50 0 1 0 -100 0z"/></svg>
	EOF
	svg2rings -t 0.01 c.svg >c.rings && areas c.rings >a &&
	test_near $(cat a) 7853.98 3 &&
	awk "NR > 1 { d = sqrt((\$1 - 50) ^ 2 + \$2 ^ 2) - 50; if (d < 0) d = -d; if (d > m) m = d } END { print m }" c.rings >dev &&
	test_le $(cat dev) 1e-9 &&
	cat >q.svg <<-\EOF &&
	<svg><path d="M0 0 C 0 50 100 50 100 0 S 0 -50 0 0 Z"/><polygon points="200,0 240,0 220,30"/>
	<path d="M300 0 Q 350 80 400 0 T 500 0 L 500 -60 L 300 -60 z"/></svg>
	EOF
	svg2rings -t 0.05 q.svg >q.rings && test $(grep -c ring q.rings) -eq 3
'
test_expect_success 'svg: compact numbers and arc flags without separators' '
	printf "<svg><path d=\"M0-0L10,0l0-10-10.5.5zM20 0a5 5 0 1020 0 5 5 0 10-20 0\"/></svg>\n" >k.svg &&
	svg2rings k.svg >k.rings && test $(grep -c ring k.rings) -eq 2
'
test_expect_success 'svg: bad input fails cleanly' '
	printf "<svg><path d=\"M0 0 L 10 10 L 10 0 L 0 10 Z\"/></svg>\n" >bow.svg &&
	test_fails_cleanly svg2rings bow.svg &&
	printf "<svg><path d=\"M0 0 L 10 x\"/></svg>\n" >junk.svg && test_fails_cleanly svg2rings junk.svg &&
	grep -q "line 1" .err &&
	printf "not svg\n" >no.svg && test_fails_cleanly svg2rings no.svg &&
	printf "<svg><rect width=\"1\" height=\"1\"/></svg>\n" >none.svg && test_fails_cleanly svg2rings none.svg
'
# Font Awesome's dragon (../shared/data/shapes2d/fa_dragon.rings.txt) has
# such a subpath: 17 points on the line x = 512
test_expect_success 'svg: a subpath on one line is dropped with a warning naming its line; none left: an error' '
	printf "<svg>\n<path d=\"M0 0 L10 0 L10 10 L0 10 Z M20 0 V5 V8 Z\"/></svg>\n" >dg.svg &&
	svg2rings dg.svg >dg.rings 2>err && cat err &&
	test $(wc -l <err) = 1 &&
	grep -q "^svg2rings: warning: .dg.svg.: line 2: dropped a subpath of 3 points on one line (it encloses no area" err &&
	test $(grep -c ring dg.rings) = 1 && areas dg.rings >a && echo 100 >expect && test_cmp expect a &&
	! grep -q -- "-0\$" dg.rings &&
	printf "<svg><path d=\"M20 0 V5 V8 Z\"/></svg>\n" >dg2.svg &&
	test_fails_cleanly svg2rings dg2.svg && grep -q "line 1: no closed outline encloses any area" .err
'
test_expect_success 'pbm: ring with a hole, counter-clockwise outer, clockwise hole' '
	printf "P1\n8 6\n0 0 0 0 0 0 0 0\n0 1 1 1 1 1 0 0\n0 1 0 0 0 1 0 0\n0 1 1 1 1 1 1 0\n0 0 0 0 0 0 1 0\n0 0 0 0 0 0 0 0\n" >a.pbm &&
	img2rings -s 0 -a 0 a.pbm >a.rings && areas a.rings >ar &&
	printf "17\n-3\n" >expect && test_cmp expect ar
'
test_expect_success 'pgm (plain and raw) with threshold, PBM raw, invert' '
	printf "P2\n3 2\n255\n0 0 255\n0 255 255\n" >p.pgm && img2rings -s 0 -a 0 p.pgm >p.rings &&
	areas p.rings >pa && echo 3 >expect && test_cmp expect pa &&
	{ printf "P5\n3 2\n255\n"; printf "\000\000\377\000\377\377"; } >r.pgm && img2rings -s 0 -a 0 r.pgm >r.rings &&
	test_cmp p.rings r.rings &&
	{ printf "P4\n3 2\n"; printf "\300\200"; } >r.pbm && img2rings -s 0 -a 0 r.pbm >rb.rings && test_cmp p.rings rb.rings &&
	img2rings -i -s 0 -a 0 p.pgm >inv.rings && areas inv.rings >ia && echo 3 >expect && test_cmp expect ia
'
test_expect_success 'bitmap disc -> rings -> compat-tri with a traced ellipse' '
	awk "BEGIN { print \"P1\"; print 40, 40; for (r = 0; r < 40; r++) { l = \"\";
		for (c = 0; c < 40; c++) l = l ((((c - 19.5) / 15) ^ 2 + ((r - 19.5) / 15) ^ 2 < 1) ? \"1 \" : \"0 \"); print l } }" >disc.pbm &&
	awk "BEGIN { print \"P1\"; print 40, 40; for (r = 0; r < 40; r++) { l = \"\";
		for (c = 0; c < 40; c++) l = l ((((c - 19.5) / 18) ^ 2 + ((r - 19.5) / 9) ^ 2 < 1) ? \"1 \" : \"0 \"); print l } }" >ell.pbm &&
	img2rings disc.pbm >disc.rings && img2rings ell.pbm >ell.rings &&
	n1=$(head -1 disc.rings | cut -d" " -f2) && n2=$(head -1 ell.rings | cut -d" " -f2) &&
	printf "0 0\n$((n1 / 3)) $((n2 / 3))\n$((2 * n1 / 3)) $((2 * n2 / 3))\n" >corr.txt &&
	compat-tri -c corr.txt disc.rings ell.rings >de.mesh && grep -q "^frames 2" de.mesh
'
test_expect_success 'bitmap bad input fails cleanly' '
	printf "P1\n3 3\n0 1 0\n1 0\n" >t.pbm && test_fails_cleanly img2rings t.pbm &&
	printf "P2\n2 1\n255\n0 300\n" >big.pgm && test_fails_cleanly img2rings big.pgm &&
	printf "P1\n2 2\n0 0\n0 0\n" >empty.pbm && test_fails_cleanly img2rings empty.pbm &&
	printf "GIF89a" >g.gif && test_fails_cleanly img2rings g.gif &&
	printf "P1\n4 4\n1 0 0 0\n0 1 0 0\n0 0 0 0\n0 0 0 0\n" >diag.pbm && img2rings -1 -s 0 -a 0 diag.pbm >one.rings
'
# before 2026-11-26 pixels touching at a corner made rings that touch, and
# img2rings refused them (a render of an elephant walk frame with legs
# touching diagonally could not be traced at all)
test_expect_success 'pixels touching at a corner: separate rings, kept apart by a quarter-pixel chamfer' '
	img2rings -s 0 -a 0 diag.pbm >two.rings &&
	test $(grep -c "^ring" two.rings) = 2 &&
	test $(grep -v "^ring" two.rings | sort -u | wc -l) = 10
'
test_expect_success 'an outline that touches itself at a corner (a U whose arms meet diagonally) traces as one simple ring' '
	printf "P1\n5 4\n1 1 1 0 0\n1 0 0 1 0\n1 1 1 1 0\n0 0 0 0 0\n" >u.pbm &&
	img2rings -1 -s 0 -a 0 u.pbm >u.rings &&
	compat-tri --refine none u.rings >u.mesh &&
	img2rings -1 -s 1 -a 0 u.pbm >u1.rings && compat-tri --refine none u1.rings >/dev/null
'
test_done
