#!/bin/sh
test_description='examples/morph2d: elephant poses -> compat-tri -> pose-space path -> arap-morph -> SVG'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"
need_shared_data shapes2d/poses/elephant-pose6.rings.txt

test_expect_success 'the recipe runs and every frame is valid' '
	make -s -C "$STOPMO_ROOT/examples/morph2d" BIN="$STOPMO_BIN" DATA="$SHARED_DATA/shapes2d/poses" \
		OUT="$TRASH/out" FRAMES=12 >log 2>&1 &&
	for f in poses.svg morph.svg morph-grid.svg linear-grid.svg weights.txt; do test -s out/$f || return 1; done &&
	grep -q "^frames 12" out/morph.mesh && grep -q "<animate" out/morph.svg &&
	test_le 1e-12 $(min_area out/morph.mesh)
'
test_expect_success 'base poses are reproduced by their unit weights' '
	printf "1 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n" | arap-morph out/poses.mesh >rep.mesh &&
	anim-diff out/poses.mesh rep.mesh >d.txt && awk "/^# max/ { print \$3 }" d.txt >max &&
	test_le $(cat max) 1e-9
'
test_expect_success 'a coarser simplification reaches the paper Steiner count (7)' '
	P="$SHARED_DATA/shapes2d/poses" &&
	compat-tri -v -e 0.008 -c "$STOPMO_ROOT/examples/morph2d/corr4.txt" "$P/elephant-pose1.rings.txt" \
		"$P/elephant-pose2.rings.txt" "$P/elephant-pose3.rings.txt" "$P/elephant-pose6.rings.txt" >e.mesh 2>log &&
	sed -n "s/.*triangulation: .* \([0-9]*\) Steiner points.*/\1/p" log >n && cat n && test $(cat n) -le 10 &&
	test_le 1e-12 $(min_area e.mesh)
'
test_expect_success 'make person: two Font Awesome drawings of three pieces each, morphed with no triangle inverted' '
	make -s -C "$STOPMO_ROOT/examples/morph2d" BIN="$STOPMO_BIN" FA="$SHARED_DATA/shapes2d" \
		OUT="$TRASH/out" FRAMES=12 person >plog 2>&1 &&
	test -s out/person.svg && grep -q "<animate" out/person-morph.svg &&
	grep -q "^frames 12" out/person-morph.mesh &&
	grep -q "inverted triangles: 0 in 0 of 12 frames" plog &&
	test_le 1e-12 $(min_area out/person-morph.mesh) &&
	test_le 20 $(worst_angle out/person.mesh)
'
test_done
