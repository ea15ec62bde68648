#!/bin/sh
test_description='compat-tri --layers: a leg drawn over the body in one pose and apart in another, each part its own ring'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

# measured (2026-11-29): the whole silhouettes of poses 0 and 2 with all
# seven rows end at 15.91 deg (5.7 s CPU: the front legs overlap in pose
# 2, so the gap between them must go into a few pixels of its outline);
# as two layers each meshed on its own 20.23 deg, 116 vertices, 0.10 s;
# meshed jointly 20.60 deg, 133 vertices, 0.08 s
test_expect_success 'setup: poses 0 and 2 (a foreleg lifted over the other) as body and leg' '
	stick_layer_pose horse 0 hoof0 && stick_layer_pose horse 2 hoof0 &&
	paste -d" " rows0 rows2 >rows &&
	test $(wc -l <rows) = 6 &&
	test $(grep -c "^ring" layers2.rings) = 2
'
test_expect_success 'without --layers the crossing rings are refused, with a pointer to it' '
	test_must_fail compat-tri -c rows layers0.rings layers2.rings >out 2>err &&
	! test -s out &&
	grep "^compat-tri: cannot read .layers0.rings.: line [0-9]*: two rings cross (edges from lines [0-9]* and [0-9]*); rings drawn over each other as layers need --layers$" err
'
test_expect_success '--layers: each layer meshed on its own, every triangle positive, 20 degrees in both poses' '
	compat-tri -v --layers -c rows layers0.rings layers2.rings >m.mesh 2>m.log &&
	grep "^compat-tri: layer 1 of 2 (ring 1 of every file): 6 correspondence rows;" m.log &&
	grep "^compat-tri: layer 2 of 2 (ring 2 of every file): 1 correspondence row (its start, as the layers around it turn);" m.log &&
	! grep "lies inside" m.log &&
	test_le 1e-12 $(min_area m.mesh) &&
	test_le 20 $(worst_angle m.mesh)
'
test_expect_success '--layers=joint: one matching and refinement of both rings, 20 degrees too' '
	compat-tri -v --layers=joint -c rows layers0.rings layers2.rings >j.mesh 2>j.log &&
	grep "2 rings per shape: 2 layers, 0 holes" j.log &&
	! grep "^compat-tri: layer 1 of 2" j.log &&
	test_le 1e-12 $(min_area j.mesh) &&
	test_le 20 $(worst_angle j.mesh) &&
	test_must_fail_usage compat-tri --layers=both -c rows layers0.rings layers2.rings
'
test_expect_success 'the faces come layer by layer, the body (ring 1) first (each and joint)' '
	for m in m j; do
		face_layers $m.mesh >layers &&
		test "$(grep -v vertex0 layers | uniq | tr "\n" " ")" = "0 1 " &&
		grep -x "vertex0 0" layers || return 1
	done
'
# measured (2026-11-29, one thread): poses 0 1 2 5 with the tests' five
# rows less the leg's (four on the body): meshed jointly 18.65 deg (one
# matching of both rings), each layer with the race 20.01 deg, 290
# vertices, 0.22 s; 51 of the 57 subsets reached 20 deg jointly, 57 of 57
# each layer on its own
test_expect_success 'four rows on the body, poses 0 1 2 5: each layer reaches 20 degrees' '
	mkdir four && (cd four &&
	for k in 0 1 2 5; do stick_layer_pose horse $k hoof0 || exit 1; done &&
	paste -d" " rows50 rows51 rows52 rows55 >rows &&
	test $(wc -l <rows) = 4 &&
	compat-tri --layers --points-out used -c rows layers0.rings layers1.rings layers2.rings layers5.rings >m.mesh) &&
	test_le 1e-12 $(min_area four/m.mesh) &&
	test_le 20 $(worst_angle four/m.mesh)
'
test_expect_success '--points-out: the rows of every layer, numbered over both rings, usable as -c' '
	n0=$(awk "/^ring/ { print \$2; exit }" four/layers0.rings) &&
	awk -v n0=$n0 "!/^#/ { if (\$1 < n0) a++; else b++ } END { exit !(a >= 4 && b >= 1) }" four/used &&
	(cd four && compat-tri --layers -m off -c used layers0.rings layers1.rings layers2.rings layers5.rings >off.mesh) &&
	test_le 1e-12 $(min_area four/off.mesh)
'
test_expect_success 'one ring per file: --layers changes nothing (the race of a single outline)' '
	compat-tri --layers -c rows body0.rings body2.rings >b1.mesh &&
	compat-tri -c rows body0.rings body2.rings >b2.mesh &&
	test_cmp b1.mesh b2.mesh
'
test_expect_success 'the same bytes on one thread and on two' '
	compat-tri --layers --threads 1 -c rows layers0.rings layers2.rings >t1.mesh &&
	compat-tri --layers --threads 2 -c rows layers0.rings layers2.rings >t2.mesh &&
	test_cmp t1.mesh t2.mesh && test_cmp m.mesh t1.mesh
'
test_expect_success 'examples/morph2d layers: the same mesh, and a 0 -> 2 -> 0 morph with no triangle inverted' '
	make -s -C "$STOPMO_ROOT/examples/morph2d" BIN="$STOPMO_BIN" OUT="$TRASH/ex" layers >log 2>&1 || { cat log >&2; false; } &&
	test_cmp m.mesh ex/layers.mesh &&
	test -s ex/layers.svg && test -s ex/layers-morph.svg &&
	grep "arap-morph: inverted triangles: 0 in 0 of 24 frames" log
'
# measured (2026-11-29, one thread): the flamingo's six whole
# silhouettes (five rows) end at 6.06 deg with 4069 vertices in 137 s of
# CPU -- pose 0 hides a leg in a slit of the body's outline; with that leg
# a layer, all six reach 20.02 deg with 1130 vertices in 0.88 s.  Every
# one of the 57 subsets of the six poses reaches 20 deg that way, for the
# flamingo (at most 0.88 s CPU each) and for the horse (0.45 s; its whole
# silhouettes with seven rows: 31 of 57 below 20 deg, up to 105 s)
test_expect_success 'the flamingo, six poses, the leg hidden in pose 0 as a layer: 20 degrees' '
	mkdir fl && (cd fl &&
	for k in 0 1 2 3 4 5; do stick_layer_pose flamingo $k toe0 || exit 1; done &&
	paste -d" " rows0 rows1 rows2 rows3 rows4 rows5 >rows &&
	compat-tri --layers -c rows layers0.rings layers1.rings layers2.rings layers3.rings layers4.rings \
		layers5.rings >m.mesh) &&
	test_le 1e-12 $(min_area fl/m.mesh) &&
	test_le 20 $(worst_angle fl/m.mesh)
'
test_expect_success 'bad input: a row on the body in one pose and on the leg in the other is named by its line' '
	n2=$(awk "/^ring/ { print \$2; exit }" layers2.rings) &&
	{ cat rows; echo "1 $((n2 + 2))"; } >cross &&
	test_must_fail compat-tri --layers -c cross layers0.rings layers2.rings >out 2>err &&
	! test -s out &&
	grep "^compat-tri: cannot read .cross.: line 7: the point is on ring 1 of .layers0.rings. but on ring 2 of .layers2.rings.; with --layers a row is one point of one layer in every shape$" err
'
test_expect_success 'bad input: -m off with a layer of fewer than 3 rows names the ring' '
	test_must_fail compat-tri --layers -m off -c rows layers0.rings layers2.rings >out 2>err &&
	! test -s out &&
	grep "^compat-tri: cannot read .rows.: 0 rows on ring 2; with -m off every layer needs at least 3 (without -m off the matching finds the rest)$" err
'
test_expect_success 'bad input: --layers with -i is a usage error; a layer that crosses itself names its ring' '
	echo "0 0 0 0" >pts &&
	test_must_fail_usage compat-tri --layers -i pts layers0.rings layers2.rings &&
	{ cat body0.rings; printf "ring 4\n0 0\n20 10\n20 0\n0 30\n"; } >bow.rings &&
	test_must_fail compat-tri --layers bow.rings layers2.rings >out 2>err &&
	! test -s out &&
	grep "^compat-tri: cannot read .bow.rings.: line [0-9]*: ring 2 intersects itself" err
'
test_done
