#!/bin/sh
test_description='compat-tri: holes and interior points joined to their piece by bent cuts where no two straight cuts fit in every pose'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

# the -v line of the bent cuts: "N cuts ... bend ...: K bend points" -> "N K"
bent_counts() {
	sed -n "s/.* \([0-9]*\) cuts\{0,1\} joining holes to their pieces bends\{0,1\} (no two straight cuts fit): \([0-9]*\) bend points/\1 \2/p" "$1"
}

test_expect_success 'setup: a U whose interior point walks from the left arm into the right one' '
	awk -v g=1 -f "$TEST_DIRECTORY/t0604-u.awk" >u0.rings &&
	cp u0.rings u1.rings &&
	awk -v g=2 -f "$TEST_DIRECTORY/t0604-u.awk" >u2.rings &&
	echo "0.5 3 2.5 3 3.5 2" >pts &&
	: >nocorr
'
# no outline vertex sees the point in the left arm and in the right one:
# before the cuts could bend this failed with "interior point 1: no two
# straight cuts to the outline lie inside the shape in every pose"
test_expect_success 'the point travels: its cuts bend round the notch, every triangle positive, the point a vertex' '
	compat-tri -v -i pts u0.rings u1.rings u2.rings >u.mesh 2>err &&
	bent_counts err >n &&
	read nb np <n && test "$nb" = 2 && test "$np" -ge 1 &&
	check_holes u.mesh nocorr pts 0.02 1 1 u0.rings u1.rings u2.rings &&
	grep -q "result: .* 3 shapes" err
'
test_expect_success 'with --refine none too: the cut pieces triangulated as they are' '
	compat-tri -v --refine none -i pts u0.rings u1.rings u2.rings >n.mesh 2>err &&
	bent_counts err >n && read nb np <n && test "$nb" = 2 &&
	check_holes n.mesh nocorr pts 0.02 1 1 u0.rings u1.rings u2.rings &&
	# the bend points are counted with the Steiner points: the vertices add up
	sed -n "s/.*result: \([0-9]*\) vertices (\([0-9]*\) boundary, \([0-9]*\) Steiner, \([0-9]*\) refinement).*/\1 \2 \3 \4/p" err >v &&
	read a b c d <v && test $a = $((b + c + d))
'
test_expect_success 'the same bytes on 1, 2 and 3 threads' '
	same_bytes_threads -i pts u0.rings u1.rings u2.rings
'
test_expect_success 'where the point sees the same outline vertices in every pose the cuts stay straight' '
	echo "0.5 3 0.5 2.5 0.6 3" >near &&
	compat-tri -v -i near u0.rings u1.rings u2.rings >s.mesh 2>err &&
	! grep -q "bend" err &&
	check_holes s.mesh nocorr near 0.02 1 1 u0.rings u1.rings u2.rings
'

# t0581's face: five poses turning 8 degrees each, two round eyes; with -m
# off every eye starts at its first vertex, so the eyes turn by 26-125
# degrees between the poses, and before the cuts could bend this failed
# with "hole ring 2: no two straight cuts to its outline lie inside the
# shape in every pose"
test_expect_success 'eyes turned against the face (-m off): bent cuts, a mesh positive in every pose (measured 19.66 deg)' '
	for p in 0 1 2 3 4; do awk -v pose=$p -v x=0 -f "$TEST_DIRECTORY/t0581-face.awk" >f$p.rings || return 1; done &&
	printf "0 0 0 0 0\n21 22 23 24 25\n42 44 46 48 50\n" >thirds.txt &&
	compat-tri -v -m off -c thirds.txt f0.rings f1.rings f2.rings f3.rings f4.rings >f.mesh 2>err &&
	bent_counts err >n && read nb np <n && test "$nb" -ge 1 &&
	check_holes f.mesh thirds.txt nocorr 0.02 1 1 f0.rings f1.rings f2.rings f3.rings f4.rings &&
	sed -n "s/.*result: .*min angle \([0-9.]*\) deg.*/\1/p" err >q &&
	test_le 15 $(cat q)
'
test_expect_success 'the same eyes matched as the face turns (the default): straight cuts, nothing bends' '
	compat-tri -v f0.rings f1.rings f2.rings f3.rings f4.rings >g.mesh 2>err &&
	! grep -q "bend" err
'
test_done
