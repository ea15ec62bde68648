#!/bin/sh
test_description='examples/stopshop: the whole StopShop recipe on a small generated head'
. "$(dirname "$0")/test-lib.sh"

run_recipe() {
	make -s -C "$STOPMO_ROOT/examples/stopshop" BIN="$STOPMO_BIN" OUT="$TRASH/out" \
		FRAMES=36 PIECES=4 BUDGET= SWEEP=2:6:2 "$@"
}

test_expect_success 'the recipe runs end to end' '
	run_recipe >log 2>&1 &&
	grep "savings:" out/summary.txt &&
	grep "seam-homog drift:    still vertices ([0-9]*) max 0\.[0-4]" out/summary.txt
'
test_expect_success 'every piece is a closed STL and the sheet covers every frame' '
	n=$(ls out/pieces/*.stl | wc -l) && test "$n" -eq 8 &&
	for f in out/pieces/part1_piece000.stl out/pieces/part0_piece003.stl; do
		mesh-import "$f" >solid.mesh && mesh-info solid.mesh >info &&
		grep "^closed yes" info || return 1
	done &&
	lines=$(wc -l <out/assembly.csv) && test "$lines" -eq 37
'
test_expect_success 'the assembled film matches the seam-constant frames at the seam' '
	lib-assemble -v -o film.mesh out/homog.mesh \
		out/lib_0.mesh:out/labels_0.txt:out/part_0.map \
		out/lib_1.mesh:out/labels_1.txt:out/part_1.map 2>err &&
	gap=$(sed -n "s/.*largest seam gap //p" err) &&
	test_le "$gap" 1e-9
'
test_expect_success 'stop-motion error is small at a 40 mm print height' '
	max=$(awk "\$1 == \"max\" { print \$2 }" out/error.txt) &&
	mean=$(awk "\$1 == \"mean\" { print \$2 }" out/error.txt) &&
	test_le "$mean" 0.2 && test_le "$max" 2.0
'
test_expect_success 'make rebuilds nothing when nothing changed' '
	touch stamp &&
	run_recipe >log3 2>&1 &&
	find out -newer stamp -type f >changed &&
	: >empty && test_cmp empty changed
'
test_expect_success 'a different library size redoes only the libraries' '
	cp out/labels.txt labels.before &&
	run_recipe PIECES=3 >log2 2>&1 &&
	test_cmp labels.before out/labels.txt &&
	n=$(ls out/pieces/*.stl | wc -l) && test "$n" -eq 6
'
test_done
