#!/bin/sh
test_description='seg-graphcut: parts from seeds, cut where the animation moves least'
. "$(dirname "$0")/test-lib.sh"

# A tube twisting about its middle ring: mesh-gen twists by an angle growing
# along the axis; counter-rotating every frame by half the end angle leaves
# the middle ring (z = 0.5) motionless and both ends moving.
# 16 segments x 20 rings: faces 32 r .. 32 r + 31 form ring r (z/0.05).
untwist='
/^frames / { F = $2 }
/^frame / { k = $2; th = -A / 2 * sin(2 * 3.141592653589793 * k / (F - 1)); c = cos(th); s = sin(th); inframe = 1; print; next }
inframe && NF == 3 { printf "%.17g %.17g %s\n", c * $1 - s * $2, s * $1 + c * $2, $3; next }
{ print }'
ring_of_cut() {   # labels -> "first ring of part 1" "last ring of part 0"
	awk '{ r = int((NR - 1) / 32); if ($1 == 1 && (lo == "" || r < lo)) lo = r; if ($1 == 0 && r > hi) hi = r }
	     END { print lo + 0, hi + 0 }' "$1"
}

test_expect_success 'setup: twisting tube' '
	mesh-gen -f 24 -n 16 -m 20 -a twist --amount 1.5 cylinder >tw.mesh &&
	awk -v A=1.5 "$untwist" tw.mesh >tube.mesh &&
	head -4 tube.mesh >head && printf "MESH 1\nvertices 336\nfaces 640\nframes 24\n" >expect &&
	test_cmp expect head
'
test_expect_success 'two parts, the cut is the motionless middle ring' '
	seg-graphcut -v --seed 0:0 --seed 1:608 tube.mesh >labels 2>err &&
	test $(wc -l <labels) = 640 &&
	ring_of_cut labels >actual && echo "10 9" >expect && test_cmp expect actual &&
	grep "energy .* = unary .* + binary" err
'
test_expect_success 'jittered seeds (5 placements) give the identical labeling' '
	for p in 5:615 11:622 20:630 33:600 64:576; do
		seg-graphcut --seed 0:${p%:*} --seed 1:${p#*:} tube.mesh >j || return 1
		test_cmp labels j || return 1
	done
'
test_expect_success 'stdin (spooled) gives the same labels as a file' '
	seg-graphcut --seed 0:0 --seed 1:608 <tube.mesh >stdin.labels &&
	test_cmp labels stdin.labels
'
test_expect_success '--one-pass (RMS displacement) agrees here' '
	seg-graphcut --one-pass --seed 0:0 --seed 1:608 <tube.mesh >one.labels &&
	test_cmp labels one.labels
'
test_expect_success 'raw input gives the same labels' '
	mesh-gen --raw -f 24 -n 16 -m 20 -a twist --amount 1.5 cylinder |
		seg-graphcut --seed 0:0 --seed 1:608 >raw.labels &&
	mesh-gen -f 24 -n 16 -m 20 -a twist --amount 1.5 cylinder |
		seg-graphcut --seed 0:0 --seed 1:608 >plain.labels &&
	test_cmp plain.labels raw.labels
'
test_expect_success 'seed points snap to the nearest triangle (--seeds file)' '
	printf "# part x y z\n0 0.25 0.01 0.01\n1 0.25 0.01 0.99\n" >seeds &&
	seg-graphcut --seeds seeds tube.mesh >pts.labels &&
	test_cmp labels pts.labels
'
test_expect_success 'scale does not matter (gamma is for a unit bounding box)' '
	awk "/^frame /{p=1; print; next} p && NF==3 {printf \"%.17g %.17g %.17g\n\", 1000*\$1, 1000*\$2, 1000*\$3; next} {print}" tube.mesh >big.mesh &&
	seg-graphcut --seed 0:0 --seed 1:608 big.mesh >big.labels &&
	test_cmp labels big.labels
'
test_expect_success 'three parts by alpha-expansion' '
	seg-graphcut -v --seed 0:0 --seed 1:320 --seed 2:630 tube.mesh >three 2>err &&
	test $(sort -u three | wc -l) = 3 &&
	test $(sed -n 1p three) = 0 && test $(sed -n 321p three) = 1 && test $(sed -n 631p three) = 2
'
test_expect_success 'larger gamma never gives a longer seam cost' '
	seg-graphcut -v -g 10 --seed 0:0 --seed 1:608 tube.mesh 2>e10 >/dev/null &&
	seg-graphcut -v -g 1000 --seed 0:0 --seed 1:608 tube.mesh 2>e1000 >/dev/null &&
	b10=$(sed -n "s/.*binary \([0-9.e+-]*\) (gamma.*/\1/p" e10) &&
	b1000=$(sed -n "s/.*binary \([0-9.e+-]*\) (gamma.*/\1/p" e1000) &&
	test_le $(awk "BEGIN{print $b1000 / 1000}") $(awk "BEGIN{print $b10 / 10 + 1e-9}")
'
test_expect_success '-o writes the file' '
	seg-graphcut -o out.labels --seed 0:0 --seed 1:608 tube.mesh && test_cmp labels out.labels
'
test_expect_success 'bad input: seed face out of range' '
	test_fails_cleanly seg-graphcut --seed 0:0 --seed 1:640 tube.mesh
'
test_expect_success 'bad input: a part without seeds' '
	test_fails_cleanly seg-graphcut --seed 0:0 --seed 2:600 tube.mesh
'
test_expect_success 'bad input: one face seeds two parts' '
	test_fails_cleanly seg-graphcut --seed 0:5 --seed 1:5 tube.mesh
'
test_expect_success 'bad input: bad seeds file line' '
	printf "0 1\n1 two\n" >bad.seeds &&
	test_fails_cleanly seg-graphcut --seeds bad.seeds tube.mesh
'
test_expect_success 'bad input: non-manifold mesh' '
	printf "MESH 1\nvertices 5\nfaces 3\nframes 1\nf 0 1 2\nf 1 0 3\nf 0 1 4\nframe 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n" >nm.mesh &&
	test_fails_cleanly seg-graphcut --seed 0:0 --seed 1:2 nm.mesh
'
test_expect_success 'bad input: truncated stream' '
	head -n 700 tube.mesh >trunc.mesh &&
	test_fails_cleanly seg-graphcut --seed 0:0 --seed 1:608 trunc.mesh
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage seg-graphcut tube.mesh 2>/dev/null &&
	test_must_fail_usage seg-graphcut --seed 0-1 tube.mesh 2>/dev/null &&
	test_must_fail_usage seg-graphcut -g -1 --seed 0:0 --seed 1:3 tube.mesh 2>/dev/null &&
	test_must_fail_usage seg-graphcut -b -0.1 --seed 0:0 --seed 1:3 tube.mesh 2>/dev/null &&
	test_must_fail_usage seg-graphcut -r 0.5 --seed 0:0 --seed 1:3 tube.mesh 2>/dev/null
'
test_done
