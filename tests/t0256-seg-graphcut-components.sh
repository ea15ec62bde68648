#!/bin/sh
test_description='seg-graphcut on a multi-component head: bridges, collapsed parts, far seeds'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/merged-head-lib.sh"

# part_counts LABELS FROM TO: "n0 n1" labels 0 and 1 among faces FROM..TO
part_counts() {
	awk -v a="$2" -v b="$3" 'NR - 1 >= a && NR - 1 <= b { n[$1 + 0]++ } END { print n[0] + 0, n[1] + 0 }' "$1"
}

test_expect_success 'the eyeballs (no seed) follow the skin they sit in: upper part' '
	merged_head 24 head.mesh &&
	seg-graphcut -v --seeds "$STOPMO_ROOT/examples/stopshop/head.seeds" head.mesh >labels 2>log &&
	cat log && grep -q "3 components, [0-9]* bridges" log &&
	! grep -q "straight-line" log && ! grep -q warning log &&
	test "$(part_counts labels 1280 1919)" = "640 0" &&
	set -- $(part_counts labels 0 1279) && test $1 -gt 640 && test $2 -gt 320
'

test_expect_success '--bridge 0: each eye is still bridged to its nearest component' '
	seg-graphcut -v --bridge 0 --seeds "$STOPMO_ROOT/examples/stopshop/head.seeds" head.mesh >b0 2>log &&
	grep -q "3 components, [1-9][0-9]* bridges (--bridge 0;" log &&
	test "$(part_counts b0 1280 1919)" = "640 0"
'

test_expect_success 'forehead + chin alone: the collapse is caught, a narrower band cuts upper/lower' '
	printf "0 0 0.75 0.55\n1 0 -0.85 0.45\n" >two.seeds &&
	seg-graphcut --seeds two.seeds head.mesh >two 2>err &&
	cat err && test $(wc -l <err) -eq 1 &&
	grep -q "warning: part 0 collapsed to its seed with band 0.6 .*cut with --band 0.4 instead" err &&
	test "$(part_counts two 1280 1919)" = "640 0" &&
	set -- $(part_counts two 0 1279) && test $1 -gt 640 && test $2 -gt 320
'

test_expect_success 'with --band given, a collapsed part is only reported, with the fix' '
	seg-graphcut --band 0.6 --seeds two.seeds head.mesh >two6 2>err &&
	cat err && test $(wc -l <err) -eq 1 &&
	grep -q "warning: part 0 collapsed to its seed: " err && grep -q "back of the skull" err &&
	set -- $(part_counts two6 0 1279) && test $1 -lt 320
'

test_expect_success 'a seed point far from the surface is an error naming the line' '
	printf "0 0 0.75 0.55\n1 0 -0.85 1e9\n" >far.seeds &&
	test_fails_cleanly seg-graphcut --seeds far.seeds head.mesh 2>err &&
	grep -q "far.seeds.*line 2:.*bbox diagonals from the surface" err &&
	printf "0 0 0.75 0.55\n1 0 -0.85 1.1\n" >near.seeds &&
	test_must_fail seg-graphcut --seeds near.seeds head.mesh >out 2>err && test ! -s out &&
	seg-graphcut --seed-snap 0.4 --seeds near.seeds head.mesh >out &&
	test_must_fail_usage seg-graphcut --seed-snap 0 --seeds near.seeds head.mesh &&
	test_must_fail_usage seg-graphcut --bridge -1 --seeds near.seeds head.mesh
'

test_expect_success 'the seam-smooth line of the seg-graphcut(1) example runs as written' '
	line=$(sed -n "/^seam-smooth /p" "$STOPMO_ROOT/man/man1/seg-graphcut.1" | sed "s/\\\\-/-/g") &&
	echo "$line" && test -n "$line" &&
	mesh-gen -f 12 -m 20 cylinder >face.mesh &&
	seg-graphcut --seed 0:0 --seed 1:390 face.mesh >parts.txt &&
	eval "$line" && test -s smooth.mesh && test -s smooth-parts.txt &&
	mesh-info smooth.mesh >info && grep "^frames 12$" info
'

test_done
