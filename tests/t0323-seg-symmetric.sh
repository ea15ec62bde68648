#!/bin/sh
test_description='seg-graphcut --symmetric: mirror plane given or found, a seam symmetric about it'
. "$(dirname "$0")/test-lib.sh"

# seam asymmetry (% of the bbox diagonal) from seg-graphcut -v
asym() { sed -n 's/.*seam asymmetry: Hausdorff distance to its mirror \([^%]*\)%.*/\1/p' "$1"; }

test_expect_success 'setup: the demo head (symmetric about x = 0), seeds off the middle' '
	head-gen -f 12 --seed 1 --raw >head.mesh &&
	printf "0 0.35 0.7 0.5\n0 -0.2 0.2 -0.8\n1 0.3 -0.8 0.4\n1 0.15 -0.5 -0.75\n" >asym.seeds &&
	seg-graphcut --seeds asym.seeds head.mesh >plain.lab
'
test_expect_success '--mirror alone only measures: same labels, asymmetry printed' '
	seg-graphcut -v --seeds asym.seeds --mirror 1,0,0,0 head.mesh >m.lab 2>m.err &&
	cmp plain.lab m.lab &&
	a=$(asym m.err) && test -n "$a" && test_le 1 "$a"
'
test_expect_success '--symmetric finds the plane x = 0 and cuts a symmetric seam' '
	seg-graphcut -v --seeds asym.seeds --symmetric head.mesh >s.lab 2>s.err &&
	grep "mirror plane .*(found)" s.err &&
	sed -n "s/.*mirror plane \([^ ]*\) (found).*/\1/p" s.err | tr , " " >plane &&
	awk "{ exit !(\$1 > 0.999999 && \$2 < 1e-6 && \$2 > -1e-6 && \$3 < 1e-6 && \$3 > -1e-6 && \$4 < 1e-6 && \$4 > -1e-6) }" plane &&
	test_le "$(asym s.err)" 1e-6 &&
	grep "0 of [0-9]* triangles labelled unlike their mirror" s.err &&
	test "$(wc -l <s.lab)" = "$(wc -l <plain.lab)"
'
test_expect_success '--symmetric with the plane given gives the same cut; --sym-weight 0 averages costs only' '
	seg-graphcut --seeds asym.seeds --symmetric --mirror 2,0,0,0 head.mesh >g.lab &&
	cmp s.lab g.lab &&
	seg-graphcut -v --seeds asym.seeds --symmetric --sym-weight 0 head.mesh >w0.lab 2>w0.err &&
	test_le "$(asym w0.err)" "$(asym m.err)"
'
test_expect_success 'symmetric seeds on a symmetric head: --symmetric changes nothing' '
	seg-graphcut --seeds "$STOPMO_ROOT/examples/stopshop/head.seeds" head.mesh >h.lab &&
	seg-graphcut --seeds "$STOPMO_ROOT/examples/stopshop/head.seeds" --symmetric head.mesh >hs.lab &&
	cmp h.lab hs.lab
'
test_expect_success 'bad planes and weights are refused' '
	test_must_fail_usage seg-graphcut --seeds asym.seeds --mirror 1,0,0 head.mesh &&
	test_must_fail_usage seg-graphcut --seeds asym.seeds --mirror 0,0,0,1 head.mesh &&
	test_must_fail_usage seg-graphcut --seeds asym.seeds --mirror 1,nan,0,0 head.mesh &&
	test_must_fail_usage seg-graphcut --seeds asym.seeds --mirror 1,0,0,0,5 head.mesh &&
	test_must_fail_usage seg-graphcut --seeds asym.seeds --symmetric --sym-weight -1 head.mesh &&
	test_fails_cleanly seg-graphcut --seeds asym.seeds --symmetric --mirror 1,0,0,0.3 head.mesh &&
	grep "not mirror symmetric" "$TRASH/.err"
'
test_done
