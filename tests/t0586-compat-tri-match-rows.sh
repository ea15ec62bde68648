#!/bin/sh
test_description='compat-tri with 3 or more given rows: the outline between them is matched (multiscale dynamic program through the rows), so held-out landmarks land on their feature'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"
need_shared_data scans/camel-gallop-05.off

# The traced camel gallop of t0585 and its seven hand landmarks (ear tip,
# snout, neck-hump notch, first and second hoof, rear hoof, tail tip).
# held A B GIVEN [compat-tri options]: the landmarks whose numbers are in
# GIVEN are given in both poses, the others picked on pose A only; prints
# the worst arc error (% of B's perimeter) of where the held-out ones land
held() {
	a=$1 b=$2 g=$3 && shift 3 &&
	camel_vertices camel$a.rings $a >va && camel_vertices camel$b.rings $b >vb &&
	paste -d" " va vb | awk -v g=" $g " "{ if (index(g, \" \" NR \" \")) print; else print \$1, -1 }" >c &&
	compat-tri "$@" --refine none -c c --points-out got camel$a.rings camel$b.rings >m.mesh &&
	paste -d" " va vb | awk -v g=" $g " "!index(g, \" \" NR \" \")" >truth &&
	grep -v "^#" got | awk "NR == FNR { t[\$1] = \$2; next } (\$1 in t) { print t[\$1], \$2 }" - truth >placed &&
	test $(wc -l <placed) -eq $(wc -l <truth) &&
	arc_error_max camel$b.rings placed
}

test_expect_success 'generate five camel poses: mesh-import | mesh-render | img2rings' '
	camel_traced_poses
'
# Three landmarks given (ear tip, snout, first hoof), the other four picked
# on pose A only and placed by the matching.  Measured: default 0.89, 1.14,
# 0.00, 0.56; -m arclength (the points placed by arc length between the
# rows, as -m off pairs the outline) 5.46, 5.49, 5.02, 6.38.
test_expect_success 'three rows given: held-out landmarks within 1.5% (arc length between the rows: 5-6.4%)' '
	for p in "1 2" "2 3" "2 5" "4 5"; do
		w=$(held $p "1 2 4") && echo "poses $p: worst $w%" && test_le $w 1.5 &&
		e=$(held $p "1 2 4" -m arclength) && echo "poses $p, -m arclength: worst $e%" && test_le 3 $e || return 1
	done
'
test_expect_success 'five rows given: held-out notch and second hoof within 1.5% (measured 0.00-1.14)' '
	for p in "1 2" "2 3" "1 4" "2 5" "4 5" "3 5"; do
		w=$(held $p "2 4 5 6 7" -m multiscale) && echo "poses $p: worst $w%" && test_le $w 1.5 || return 1
	done
'
test_expect_success '-m off keeps the earlier behaviour: rows picked on one pose only are refused' '
	camel_vertices camel1.rings 1 >va && camel_vertices camel2.rings 2 >vb &&
	paste -d" " va vb | awk "{ if (NR <= 4) print; else print \$1, -1 }" >c &&
	test_must_fail compat-tri -m off -c c camel1.rings camel2.rings >o.mesh 2>err &&
	test $(wc -l <err) = 1 && test ! -s o.mesh
'

need_shared_data shapes2d/poses/elephant-pose6.rings.txt
P="$SHARED_DATA/shapes2d/poses"
# before the overlay's exact images and sliver collapses (and the stage II
# rule against Steiner points within rounding of an edge) the matched points
# gave "a 36-gon piece is too thin" here and the given rows were used
test_expect_success 'elephant poses 1 2 3 5 6: the matched points triangulate (no fallback to the given rows)' '
	grep -v "^#" "$STOPMO_ROOT/examples/morph2d/corr6.txt" | cut -d" " -f1,2,3,5,6 >c5 &&
	compat-tri --refine none -c c5 --points-out used $P/elephant-pose1.rings.txt $P/elephant-pose2.rings.txt \
		$P/elephant-pose3.rings.txt $P/elephant-pose5.rings.txt $P/elephant-pose6.rings.txt >e.mesh 2>err &&
	! grep "warning" err &&
	test $(grep -vc "^#" used) -gt 5 &&
	test_le 1e-12 $(min_area e.mesh)
'
test_done
