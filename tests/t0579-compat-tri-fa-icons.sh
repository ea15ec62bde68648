#!/bin/sh
test_description='compat-tri on the shared Font Awesome drawings: the running and walking person (head, body with legs, arm: three pieces; the walking one stored clockwise), the bodies matched with no point given, then all three pieces from rows the matching wrote; the hippo (four holes) against a bent copy of itself; the dragon, whose second ring is a line, refused (skips without ../shared/data)'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"
need_shared_data shapes2d/fa_person-walking.rings.txt
S="$SHARED_DATA/shapes2d"

# ring 2 of FILE (the body) on stdout
body() { awk '/^ring/ { r++ } r == 2' "$1"; }

test_expect_success 'the bodies: no point given, at 20 degrees, on the outline, nothing on stderr' '
	body "$S/fa_person-running.rings.txt" >run.rings &&
	body "$S/fa_person-walking.rings.txt" >walk.rings &&
	compat-tri -v --points-out p.txt run.rings walk.rings >b.mesh 2>err &&
	grep -q "walk.rings: clockwise outline reversed" err &&
	w=$(worst_angle b.mesh) && echo "worst $w deg" && test_le 20 $w &&
	test_le 1e-12 $(min_area b.mesh) &&
	outline_within b.mesh run.rings walk.rings &&
	compat-tri run.rings walk.rings 2>err2 >b2.mesh && test ! -s err2 && test_cmp b.mesh b2.mesh
'
# measured: 58 vertices, 20.52 deg (bodies); 104 vertices, 21.69 deg
# (three pieces), 0.06 s each
test_expect_success 'head, body and arm: the rows the matching wrote (every other one, on ring 2) triangulate the three pieces compatibly at 20 degrees' '
	grep -v "^#" p.txt | awk "NR % 2 == 1 { print \$1 + 32, \$2 + 32 }" >c3 &&
	test $(wc -l <c3) = 6 &&
	compat-tri -v -c c3 "$S/fa_person-running.rings.txt" "$S/fa_person-walking.rings.txt" >p3.mesh 2>err &&
	grep -q "3 rings per shape: 3 pieces, 0 holes" err && ! grep -q warning err &&
	w=$(worst_angle p3.mesh) && echo "worst $w deg" && test_le 20 $w &&
	test_le 1e-12 $(min_area p3.mesh)
'
# measured: 12, 12 and 9 points placed, 93 vertices, 21.50 deg, 0.07 s
test_expect_success 'head, body and arm with no -c: every ring matched on its own, the rows written, the same mesh from them' '
	compat-tri -v --points-out pa.txt "$S/fa_person-running.rings.txt" "$S/fa_person-walking.rings.txt" >pa.mesh 2>err &&
	test $(grep -c "ring [123] (a piece): [0-9]* correspondence points placed by the boundary matching (0 given)" err) = 3 &&
	! grep -q warning err &&
	w=$(worst_angle pa.mesh) && echo "worst $w deg" && test_le 20 $w && test_le 1e-12 $(min_area pa.mesh) &&
	compat-tri -c pa.txt "$S/fa_person-running.rings.txt" "$S/fa_person-walking.rings.txt" >pb.mesh &&
	test_cmp pa.mesh pb.mesh
'
test_expect_success 'one given row on the body: kept among the matched rows; -m off: the rings without rows from their first vertex' '
	printf "103 79\n" >c1 &&
	compat-tri -v -c c1 --points-out p1.txt "$S/fa_person-running.rings.txt" "$S/fa_person-walking.rings.txt" >p1.mesh 2>err &&
	grep -q "ring 2 (a piece): [0-9]* correspondence points placed by the boundary matching (1 given)" err &&
	grep -qx "103 79" p1.txt &&
	test_le 20 $(worst_angle p1.mesh) &&
	compat-tri -v -m off -c c3 "$S/fa_person-running.rings.txt" "$S/fa_person-walking.rings.txt" >/dev/null 2>err &&
	grep -q "2 rings without a correspondence row: matched from the first vertex" err && ! grep -q "placed by" err
'
# bend X: the rings of X moved by a smooth warp (x + 40 sin(y / 90),
# y + 30 sin(x / 120)), the same vertices in the same order
bend() {
	awk '/^ring/ { print; next } { printf "%.6f %.6f\n", $1 + 40 * sin($2 / 90), $2 + 30 * sin($1 / 120) }' "$1"
}
# measured: 20.01 deg, 0.02 s
test_expect_success 'the hippo and a bent copy: one piece with four holes (eyes, nostrils), four rows on its outline' '
	bend "$S/fa_hippo.rings.txt" >hippo2.rings &&
	printf "0 0\n72 72\n144 144\n216 216\n" >ch &&
	compat-tri -v -c ch "$S/fa_hippo.rings.txt" hippo2.rings >h.mesh 2>err &&
	grep -q "5 rings per shape: 1 piece, 4 holes" err && ! grep -q warning err &&
	w=$(worst_angle h.mesh) && echo "worst $w deg" && test_le 20 $w &&
	test_le 1e-12 $(min_area h.mesh)
'
test_expect_success 'the hippo and its bent copy with no -c: all five rings matched' '
	compat-tri -v "$S/fa_hippo.rings.txt" hippo2.rings >h0.mesh 2>err &&
	test $(grep -c "placed by the boundary matching" err) = 5 &&
	grep -q "ring 2 (a hole)" err &&
	test_le 20 $(worst_angle h0.mesh) && test_le 1e-12 $(min_area h0.mesh)
'
test_expect_success 'the dragon: its ring 2 (17 points on the line x = 512) is refused with its file and line' '
	bend "$S/fa_dragon.rings.txt" >dragon2.rings &&
	printf "0 0\n40 40\n80 80\n" >cd &&
	test_must_fail compat-tri -c cd "$S/fa_dragon.rings.txt" dragon2.rings >d.mesh 2>err &&
	cat err && test $(wc -l <err) = 1 && test ! -s d.mesh &&
	grep -q "fa_dragon.rings.txt.: line 176: degenerate outline (ring 2 encloses no area)" err
'
test_done
