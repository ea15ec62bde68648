#!/bin/sh
test_description='compat-tri: holes (eyes, the gap between the legs), several pieces, interior points'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

# poses K..: rings pK.rings, columns of the tips and points of those poses
make_inputs() {   # make_inputs NAME K...
	mi=$1; shift
	: >"$mi.corr.tmp"; : >"$mi.pts.tmp"; mi_files=
	for k in "$@"; do
		if [ -s "$mi.corr.tmp" ]; then
			paste -d" " "$mi.corr.tmp" "tips$k.col" >"$mi.c2" && mv "$mi.c2" "$mi.corr.tmp"
			paste -d" " "$mi.pts.tmp" "pts$k" >"$mi.p2" && mv "$mi.p2" "$mi.pts.tmp"
		else cp "tips$k.col" "$mi.corr.tmp" && cp "pts$k" "$mi.pts.tmp"; fi
		mi_files="$mi_files p$k.rings"
	done
	mv "$mi.corr.tmp" "$mi.corr" && mv "$mi.pts.tmp" "$mi.pts"
}

test_expect_success 'setup: six poses of a character with two eyes and a gap between its legs' '
	for k in 0 1 2 3 4 5; do
		awk -v pose=$k -v tips=tips$k -v pts=pts$k -f "$TEST_DIRECTORY/t0513-holey.awk" >p$k.rings &&
		tr " " "\n" <tips$k >tips$k.col || return 1
	done &&
	test $(grep -c ring p0.rings) = 4 && test $(wc -l <tips0.col) = 4
'
test_expect_success 'pose subsets (2..6 poses): positive, corners and interior points exact, holes kept open' '
	for set in "0 1" "0 2" "0 3" "0 4" "0 5" "1 4" "0 1 2" "3 4 5" "0 1 2 3" "1 2 3 4 5" "0 1 2 3 4 5"; do
		make_inputs sub $set &&
		compat-tri -l 0 -s 0 -c sub.corr -i sub.pts $mi_files >sub.mesh 2>sub.err &&
		check_holes sub.mesh sub.corr sub.pts 0.02 1 1 $mi_files || { echo "poses $set: $(cat sub.err)"; return 1; }
	done
'
test_expect_success 'all six with refinement and smoothing: positive, interior points still exact' '
	make_inputs all 0 1 2 3 4 5 &&
	compat-tri -v -c all.corr -i all.pts $mi_files >all.mesh 2>log &&
	check_holes all.mesh all.corr all.pts 0.02 1 1 $mi_files &&
	grep -q "1 piece, 3 holes" log && test $(grep -c "(a hole): [0-9]* correspondence points placed by the boundary matching (0 given)" log) = 2 &&
	grep -q "2 interior points" log
'
test_expect_success 'holes and interior points are refined too: worst angle >= 18 degrees over all six poses (measured 20.1; --refine none 0.02)' '
	make_inputs q 0 1 2 3 4 5 &&
	compat-tri -v -c q.corr -i q.pts $mi_files >q.mesh 2>q.log &&
	compat-tri -v --refine none -c q.corr -i q.pts $mi_files >qn.mesh 2>qn.log &&
	check_holes q.mesh q.corr q.pts 0.02 1 1 $mi_files &&
	! grep -q "one outer ring only" q.log &&
	w=$(sed -n "s/.*result: .* min angle \([0-9.]*\) deg.*/\1/p" q.log) &&
	wn=$(sed -n "s/.*result: .* min angle \([0-9.]*\) deg.*/\1/p" qn.log) &&
	echo "refine $w deg, none $wn deg" && test_le 18 $w && test_le $wn $w
'
test_expect_success '-e 0: every input vertex of every ring is a mesh vertex, areas exact' '
	make_inputs e0 0 3 5 &&
	compat-tri -e 0 -l 0 -s 0 -c e0.corr -i e0.pts $mi_files >e0.mesh &&
	check_holes e0.mesh e0.corr e0.pts 0 1 1 $mi_files
'
test_expect_success 'two pieces (a separate tail): one mesh of two components' '
	for k in 0 1 2 3; do
		awk -v pose=$k -v tail=1 -v tips=tips$k -v pts=pts$k -f "$TEST_DIRECTORY/t0513-holey.awk" >p$k.rings &&
		tr " " "\n" <tips$k >tips$k.col || return 1
	done &&
	make_inputs tail 0 1 2 3 &&
	for k in 0 1 2 3; do mv p$k.rings tail$k.rings || return 1; done &&
	mi_files="tail0.rings tail1.rings tail2.rings tail3.rings" &&
	compat-tri -v -c tail.corr -i tail.pts $mi_files >tail.mesh 2>log &&
	grep -q "2 pieces, 3 holes" log &&
	check_holes tail.mesh tail.corr tail.pts 0.02 2 "1 5" $mi_files &&
	compat-tri -e 0 -l 0 -s 0 -c tail.corr $mi_files >tail0.mesh &&
	: >nopts && check_holes tail0.mesh tail.corr nopts 0 2 "1 5" $mi_files
'
test_expect_success 'hole counts differ: one-line error naming the file, the pieces and holes of each, and the remedy' '
	for k in 0 1 2 3; do
		awk -v pose=$k -v tips=tips$k -v pts=pts$k -f "$TEST_DIRECTORY/t0513-holey.awk" >p$k.rings &&
		tr " " "\n" <tips$k >tips$k.col || return 1
	done &&
	awk -v pose=2 -v eyes=1 -v tips=t2 -v pts=q2 -f "$TEST_DIRECTORY/t0513-holey.awk" >oneeye.rings &&
	cut -d" " -f1,2 all.corr >c01 &&
	test_fails_cleanly compat-tri -c c01 p0.rings oneeye.rings &&
	grep -q "cannot read .oneeye.rings.: 3 rings (1 piece, 2 holes), but .p0.rings. has 4 (1 piece, 3 holes)" .err &&
	grep -q "trace the outer outlines alone (img2rings -1)" .err
'
test_expect_success 'an interior point outside its outline or in an eye: error naming file and line' '
	make_inputs two 0 1 &&
	{ echo "# nose, navel, then a point off the body"; cat two.pts; echo "9 9 9 9"; } >out.pts &&
	test_fails_cleanly compat-tri -c two.corr -i out.pts p0.rings p1.rings &&
	grep -q "cannot read .out.pts.: line 4: point (9, 9) of shape 0 lies outside its outline" .err &&
	x=$(awk "/^ring/ { r++; next } r == 3 { print \$1 - 0.05, \$2; exit }" p0.rings) &&
	{ head -1 two.pts; echo "$x $(head -1 two.pts | cut -d" " -f3,4)"; } >eye.pts &&
	test_fails_cleanly compat-tri -c two.corr -i eye.pts p0.rings p1.rings &&
	grep -q "line 2: .* lies outside its outline (in a hole)" .err
'
test_expect_success 'a correspondence row on different rings in two shapes: error' '
	printf "0 0\n28 19\n87 130\n" >mixed.corr &&
	test_fails_cleanly compat-tri -c mixed.corr p0.rings p1.rings && grep -q "line 3: .*ring" .err
'
test_expect_success 'rings nested differently (an eye outside the head): error' '
	awk "/^ring/ { r++ } r == 3 && !/^ring/ { \$1 += 3 } { print }" p1.rings >moved.rings &&
	test_fails_cleanly compat-tri -c two.corr p0.rings moved.rings && grep -q "ring 3 lies in no ring" .err
'
test_done
