#!/bin/sh
test_description='compat-tri: the goal is --min-angle, or the outline'"'"'s sharpest corner where that is smaller; a mesh at that corner tries no further candidate, and a mesh below the goal is written with a one-line warning (a bird whose beak is sharper than 20 degrees; two W shapes held below the goal by --max-vertices)'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

test_expect_success 'generate: bird poses 0-5, two W shapes' '
	for k in 0 1 2 3 4 5; do awk -v pose=$k -f "$TEST_DIRECTORY/t0578-bird.awk" >bird$k.rings || return 1; done &&
	printf "ring 5\n0 0\n10 0\n10 10\n5 3\n0 10\n" >w0.rings &&
	printf "ring 5\n0 0\n10 0\n11 10\n5 4\n0 10\n" >w1.rings
'
# the beak's corner caps every candidate alike: before the cap was the
# goal, all six poses refined three candidates for the same mesh (0.37 s
# CPU against 0.16 s, the same bytes)
test_expect_success 'six bird poses: the worst angle is the beak, no other candidate is tried, no warning' '
	compat-tri -v --threads 1 bird0.rings bird1.rings bird2.rings bird3.rings bird4.rings bird5.rings >b.mesh 2>err &&
	cat err &&
	w=$(worst_angle b.mesh) && sharp=$(sed -n "s/.*sharpest outline corner \([0-9.]*\) deg.*/\1/p" err) &&
	echo "worst $w deg, sharpest corner $sharp deg" &&
	test_le $sharp 19 && test_le $(echo "$sharp - 0.01" | bc) $w && test_le 1e-12 $(min_area b.mesh) &&
	test $(grep -c "refinement: " err) = 1 &&
	! grep -q "too;" err && ! grep -q warning err
'
test_expect_success 'the same bytes with 2 threads and without -v' '
	compat-tri --threads 2 bird0.rings bird1.rings bird2.rings bird3.rings bird4.rings bird5.rings >b2.mesh 2>err2 &&
	test_cmp b.mesh b2.mesh && test ! -s err2
'
test_expect_success 'below the goal: one warning line, the mesh written, exit 0' '
	compat-tri -a 33 --max-vertices 6 w0.rings w1.rings >w.mesh 2>err &&
	cat err && test $(wc -l <err) = 1 &&
	grep -q "^compat-tri: warning: worst angle [0-9.]* deg, below the goal of 33 deg (--min-angle); the mesh is written anyway (-v says why)$" err &&
	test $(worst_angle w.mesh | cut -d. -f1) -lt 33 && test_le 1e-12 $(min_area w.mesh)
'
test_expect_success 'below a goal capped by the sharpest corner: the warning says so; with -v, without the pointer to -v' '
	compat-tri -a 40 --max-vertices 6 w0.rings w1.rings >/dev/null 2>err &&
	grep -q "below the goal of [0-9.]* deg (the sharpest corner of the outlines); the mesh is written anyway" err &&
	compat-tri -v -a 33 --max-vertices 6 w0.rings w1.rings >/dev/null 2>err &&
	grep -q "warning: .*the mesh is written anyway$" err &&
	grep -q "refinement stopped below the goal of 33 deg" err
'
test_expect_success 'at the goal: no warning' '
	compat-tri w0.rings w1.rings >/dev/null 2>err && test ! -s err
'
test_done
