#!/bin/sh
test_description='compat-tri boundary matching: one or no correspondence point, the rest found (Baxter et al. elastic mapping)'
. "$(dirname "$0")/test-lib.sh"

# A three-lobed outline and a deformed copy with a known correspondence
# (tests/t0515-match-shape.awk): vertex 4k of pose 0 is vertex (3k - 17) mod
# 90 of pose 1.  arcerr RING A B: arc distance of vertices A and B of RING,
# in % of its perimeter.
arcerr() {
	awk -v a="$2" -v b="$3" '/^ring/ { next } { x[n] = $1; y[n] = $2; n++ }
	END { c[0] = 0; for (i = 0; i < n; i++) { j = (i + 1) % n; c[i + 1] = c[i] + sqrt((x[j] - x[i]) ^ 2 + (y[j] - y[i]) ^ 2) }
	      L = c[n]; d = c[a] - c[b]; if (d < 0) d = -d; if (L - d < d) d = L - d; printf "%.3f\n", 100 * d / L }' "$1"
}
# worst arc error (%) of the rows of a --points-out file against the truth
# (rows whose pose-0 vertex is a multiple of 4: their truth is a vertex)
worst() {
	grep -v "^#" "$1" | awk "\$1 % 4 == 0" | { m=0; while read a b; do
		t=$(( ( (a / 4) * 3 - 17 + 90) % 90 )); e=$(arcerr pose1.rings $b $t)
		m=$(awk -v a=$m -v b=$e "BEGIN { print (b > a) ? b : a }"); done; echo $m; }
}

test_expect_success 'setup: the two poses, points 20 48 60 76 100 picked on pose 0 only' '
	awk -v pose=0 -f "$TEST_DIRECTORY/t0515-match-shape.awk" >pose0.rings &&
	awk -v pose=1 -f "$TEST_DIRECTORY/t0515-match-shape.awk" >pose1.rings &&
	printf "20 -1\n48 -1\n60 -1\n76 -1\n100 -1\n" >picked.txt
'
# multiscale (default): one vertex of pose 1 off in the stretched lobe
# (1.5%); elastic under 1%
test_expect_success 'one given point: the picked points land within 2% of the perimeter (arc length alone: over 5%)' '
	{ echo "0 73"; cat picked.txt; } >one.txt &&
	compat-tri -c one.txt --match-points 3 --points-out m1.txt pose0.rings pose1.rings >m1.mesh &&
	test $(grep -vc "^#" m1.txt) -eq 6 &&
	grep -q "^0 73$" m1.txt &&
	w=$(worst m1.txt) && echo "multiscale worst $w%" && test_le $w 2 &&
	compat-tri -m elastic -c one.txt --match-points 3 --points-out e1.txt pose0.rings pose1.rings >e1.mesh &&
	w=$(worst e1.txt) && echo "elastic worst $w%" && test_le $w 1 &&
	compat-tri -m arclength -c one.txt --match-points 3 --points-out a1.txt pose0.rings pose1.rings >a1.mesh &&
	w=$(worst a1.txt) && echo "arc length worst $w%" && test_le 5 $w
'
test_expect_success 'no given point: the start is found too, the same points within 2% (elastic: 1%)' '
	{ echo "0 -1"; cat picked.txt; } >none.txt &&
	compat-tri -c none.txt --match-points 3 --points-out m0.txt pose0.rings pose1.rings >m0.mesh &&
	w=$(worst m0.txt) && echo "worst $w%" && test_le $w 2 &&
	compat-tri -m elastic -c none.txt --match-points 3 --points-out e0.txt pose0.rings pose1.rings >e0.mesh &&
	w=$(worst e0.txt) && echo "elastic worst $w%" && test_le $w 1
'
test_expect_success 'no -c at all: 12 points placed, the mesh is compatible, --points-out feeds -c back' '
	compat-tri -v --points-out auto.txt pose0.rings pose1.rings >auto.mesh 2>err &&
	grep "12 correspondence points placed" err &&
	test $(grep -vc "^#" auto.txt) -eq 12 &&
	mesh-info auto.mesh >info && grep -q "frames *2" info &&
	w=$(worst auto.txt) && echo "worst $w%" && test_le $w 2 &&
	compat-tri --match off -c auto.txt pose0.rings pose1.rings >again.mesh &&
	test_cmp auto.mesh again.mesh
'
test_expect_success 'reversed orientation: clockwise files give the same points (in file order)' '
	awk -v pose=1 -v reverse=1 -f "$TEST_DIRECTORY/t0515-match-shape.awk" >pose1r.rings &&
	echo "0 73" >start.txt &&
	compat-tri -c start.txt --points-out m1all.txt pose0.rings pose1.rings >/dev/null &&
	echo "0 16" >oner.txt &&
	compat-tri -v -c oner.txt --points-out r1.txt pose0.rings pose1r.rings >r1.mesh 2>err &&
	grep "clockwise outline reversed" err &&
	grep -v "^#" m1all.txt | awk "{ print \$1, 89 - \$2 }" >expect &&
	grep -v "^#" r1.txt >actual && test_cmp expect actual &&
	awk -v pose=0 -v reverse=1 -f "$TEST_DIRECTORY/t0515-match-shape.awk" >pose0r.rings &&
	echo "119 16" >onerr.txt &&
	compat-tri -c onerr.txt --points-out rr.txt pose0r.rings pose1r.rings >rr.mesh &&
	grep -v "^#" m1all.txt | awk "{ print 119 - \$1, 89 - \$2 }" | sort -n >expect &&
	grep -v "^#" rr.txt | sort -n >actual && test_cmp expect actual
'
test_expect_success 'the matched points can be drawn with mesh2svg --points-file' '
	mesh2svg --points-file auto.txt --points-column 2 pose1.rings >p1.svg &&
	grep -q ">12</text>" p1.svg
'
test_expect_success 'bad input: partly given row, --match off with one point' '
	printf "0 73\n5 -1\n" >ok.txt && printf "0 -1 4\n" >part.txt &&
	test_fails_cleanly compat-tri -c part.txt pose0.rings pose1.rings pose1.rings &&
	grep -q "in every shape, or in" .err &&
	test_fails_cleanly compat-tri --match off -c ok.txt pose0.rings pose1.rings
'
test_done
