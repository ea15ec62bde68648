#!/bin/sh
test_description='anim-slice, anim-cat, anim-avg, mesh-normalize; plain <-> raw round trips'
. "$(dirname "$0")/test-lib.sh"

value() { sed -n "s/^$1 //p" "$2"; }
# frame headers of a plain stream, one per line
headers() { grep "^frame " "$1"; }

test_expect_success 'setup' '
	mesh-gen -f 10 -n 3 --cut-every 4 -a wave grid >a.mesh &&
	mesh-gen -f 4 -n 3 -a twist grid >b.mesh
'
test_expect_success 'plain -> raw -> plain is bit-exact (anim-slice)' '
	mesh-gen -f 6 -a twist -n 7 cylinder >p.mesh &&
	STOPMO_RAW=1 anim-slice p.mesh >r.mesh &&
	head -1 r.mesh >magic && echo "MESH 1 raw" >expect && test_cmp expect magic &&
	anim-slice r.mesh >p2.mesh && test_cmp p.mesh p2.mesh
'
test_expect_success 'raw -> plain -> raw is bit-exact, awkward numbers included' '
	mesh-gen -f 3 -a bend -s 2 icosphere | mesh-normalize -q >odd.mesh &&
	anim-slice --raw odd.mesh >odd.raw &&
	anim-slice odd.raw | anim-slice --raw >odd2.raw && test_cmp odd.raw odd2.raw
'
test_expect_success 'round trip of a stream larger than the reader buffer (several MB)' '
	mesh-gen -n 150 -f 3 -a twist cylinder >big.mesh &&
	test $(wc -c <big.mesh) -gt 3000000 &&
	anim-slice --raw big.mesh >big.raw && anim-slice big.raw >big2.mesh &&
	test_cmp big.mesh big2.mesh && rm -f big.mesh big.raw big2.mesh
'
test_expect_success 'tabs, leading blanks, CR and trailing comments read like plain lines' '
	mesh-gen -n 3 -f 2 -a wave grid >w.mesh &&
	awk "/^[-0-9]/ { printf \"  %s\t%s  %s # v\r\n\", \$1, \$2, \$3; next } { print }" w.mesh >w2.mesh &&
	! cmp -s w.mesh w2.mesh && anim-slice w2.mesh >w3.mesh && test_cmp w.mesh w3.mesh
'
test_expect_success 'raw writer equals mesh-gen --raw' '
	STOPMO_RAW=1 mesh-gen -f 6 -a twist -n 7 cylinder >g.raw && test_cmp g.raw r.mesh
'
test_expect_success 'anim-slice START:STOP:STEP keeps cut marks' '
	anim-slice -f 1:10:3 a.mesh >s.mesh &&
	test "$(value frames s.mesh)" = 3 &&
	printf "frame 0\nframe 1 cut\nframe 2\n" >expect && headers s.mesh >actual &&
	test_cmp expect actual
'
test_expect_success 'anim-slice list with a negative index, stream order' '
	anim-slice -f 9,0,-2 a.mesh >s.mesh &&
	test "$(value frames s.mesh)" = 3 &&
	anim-slice -f 0 a.mesh >f0 && anim-slice -f 0 s.mesh >g0 && test_cmp f0 g0 &&
	anim-slice -f 9 a.mesh | tail -n +5 >x && anim-slice -f 2 s.mesh | tail -n +5 >y &&
	test_cmp x y
'
test_expect_success 'anim-slice open ranges' '
	anim-slice -f 7: a.mesh >s.mesh && test "$(value frames s.mesh)" = 3 &&
	anim-slice -f :3 a.mesh >s.mesh && test "$(value frames s.mesh)" = 3 &&
	anim-slice -f ::5 a.mesh >s.mesh && test "$(value frames s.mesh)" = 2 &&
	anim-slice -f -3: a.mesh >s.mesh && test "$(value frames s.mesh)" = 3
'
test_expect_success 'anim-slice --clip selects one clip, frames ? header' '
	anim-slice --clip 1 a.mesh >c1.mesh &&
	test "$(value frames c1.mesh)" = "?" && mesh-info c1.mesh >info &&
	test "$(value frames info)" = 4 && test "$(value clips info)" = 1 &&
	anim-slice -f 4:8 a.mesh | tail -n +5 >x && tail -n +5 c1.mesh | sed "s/^frame 0 cut/frame 0/" >y &&
	test_cmp x y &&
	anim-slice --clip 2 -f 1 a.mesh >c2.mesh && mesh-info c2.mesh | grep -q "^frames 1"
'
test_expect_success 'anim-slice errors: missing frame, missing clip, bad spec' '
	test_fails_cleanly anim-slice -f 10 a.mesh 2>err && grep -q "frame 10 does not exist" err &&
	test_fails_cleanly anim-slice --clip 3 a.mesh 2>err && grep -q "no clip 3" err &&
	test_fails_cleanly anim-slice -f 20:30 a.mesh 2>err && grep -q "no frames" err &&
	test_must_fail_usage anim-slice -f 1:2:0 a.mesh 2>err &&
	test_must_fail_usage anim-slice -f x a.mesh 2>err
'
test_expect_success 'anim-slice on a frames ? stream' '
	anim-slice --clip 0 a.mesh >q.mesh && anim-slice -f 1:3 q.mesh >q2.mesh &&
	mesh-info q2.mesh | grep -q "^frames 2" &&
	test_fails_cleanly anim-slice -f -1 q.mesh 2>err && grep -q "frames ?" err
'
test_expect_success 'anim-cat: counts add, a cut at each join' '
	anim-cat a.mesh b.mesh a.mesh >j.mesh &&
	mesh-info j.mesh >info &&
	test "$(value frames info)" = 24 && test "$(value clips info)" = 7 &&
	anim-slice -f 10 j.mesh | grep -q "^frame 0" &&
	grep -q "^frame 10 cut" j.mesh && grep -q "^frame 14 cut" j.mesh
'
test_expect_success 'anim-cat --no-cut; mixed plain and raw inputs; stdin' '
	anim-cat --no-cut b.mesh b.mesh >j.mesh && mesh-info j.mesh | grep -q "^clips 1" &&
	STOPMO_RAW=1 anim-slice b.mesh >b.raw &&
	anim-cat b.mesh - <b.raw >j2.mesh && anim-cat b.mesh b.mesh >j3.mesh && test_cmp j3.mesh j2.mesh
'
test_expect_success 'anim-cat then anim-slice --clip gives back the parts' '
	anim-cat b.mesh a.mesh >j.mesh && anim-slice --clip 0 j.mesh | tail -n +5 >x &&
	tail -n +5 b.mesh >y && test_cmp y x
'
test_expect_success 'anim-cat: mismatched connectivity fails cleanly' '
	mesh-gen -n 4 grid >c.mesh &&
	test_fails_cleanly anim-cat a.mesh c.mesh 2>err && grep -q "different connectivity" err &&
	grep -q "c.mesh" err
'
test_expect_success 'anim-cat: same sizes, different faces fails cleanly' '
	awk "NR==5 { print \"f\", \$2, \$4, \$3; next } { print }" b.mesh >flip.mesh &&
	test_fails_cleanly anim-cat b.mesh flip.mesh 2>err && grep -q "face 0 differs" err
'
test_expect_success 'anim-cat: stdin twice is a usage error' '
	test_must_fail_usage anim-cat - - </dev/null
'
test_expect_success 'anim-avg: one frame, the mean of the frames' '
	anim-avg a.mesh >avg.mesh && test "$(value frames avg.mesh)" = 1 &&
	mesh-gen -n 3 grid | anim-avg | tail -n +5 >x &&
	mesh-gen -n 3 grid | tail -n +5 >y && test_cmp y x
'
test_expect_success 'anim-avg of two frames is their midpoint' '
	printf "MESH 1\nvertices 1\nfaces 0\nframes 2\nframe 0\n0 0 0\nframe 1\n1 -2 4\n" >two.mesh &&
	anim-avg two.mesh | tail -1 >x && echo "0.5 -1 2" >y && test_cmp y x
'
test_expect_success 'anim-avg -o writes nothing on failure' '
	printf "MESH 1\nvertices 1\nfaces 0\nframes 2\nframe 0\n0 0 0\n" >bad.mesh &&
	test_must_fail anim-avg -o out.mesh bad.mesh 2>err && test ! -e out.mesh &&
	ls >list && ! grep -q tmp list
'
test_expect_success 'mesh-normalize: unit longest side, centred, all frames' '
	mesh-gen -f 5 -a bend -n 6 -m 12 cylinder >cyl.mesh &&
	mesh-normalize -t xf cyl.mesh >n.mesh && mesh-info n.mesh >info &&
	set -- $(value bbox_min info) $(value bbox_max info) &&
	lo=$(awk "BEGIN { m = $1; if ($2 < m) m = $2; if ($3 < m) m = $3; print m }") &&
	hi=$(awk "BEGIN { m = $4; if ($5 > m) m = $5; if ($6 > m) m = $6; print m }") &&
	test_near "$(awk "BEGIN { print $hi - $lo }")" 1 1e-12 &&
	for d in "$1 + $4" "$2 + $5" "$3 + $6"; do
		test_near "$(awk "BEGIN { print $d }")" 0 1e-12 || return 1
	done &&
	grep -q "^scale .* translate .* .* .*$" xf
'
test_expect_success 'mesh-normalize: stdin gives the same as a file' '
	mesh-normalize <cyl.mesh >n2.mesh 2>xf2 && test_cmp n.mesh n2.mesh &&
	test_cmp xf xf2
'
test_expect_success 'mesh-normalize --undo restores the positions' '
	mesh-normalize --undo xf n.mesh >back.mesh &&
	anim-slice --raw cyl.mesh >c.raw && anim-slice --raw back.mesh >b.raw &&
	mesh-info back.mesh | grep -v -e ^bbox -e ^diagonal -e ^area -e ^volume >i1 &&
	mesh-info cyl.mesh | grep -v -e ^bbox -e ^diagonal -e ^area -e ^volume >i2 &&
	test_cmp i2 i1 &&
	paste cyl.mesh back.mesh | awk "NF == 6 { for (i = 1; i <= 3; i++) { d = \$i - \$(i+3); if (d < 0) d = -d; if (d > m) m = d } } END { print m + 0 }" >maxerr &&
	test_le "$(cat maxerr)" 1e-14
'
test_expect_success 'mesh-normalize --apply repeats a transform' '
	mesh-normalize --apply xf cyl.mesh >n3.mesh && test_cmp n.mesh n3.mesh
'
test_expect_success 'mesh-normalize: bad transform file fails cleanly' '
	echo "scale 0 translate 1 2 3" >bad.xf &&
	test_fails_cleanly mesh-normalize --undo bad.xf cyl.mesh 2>err && grep -q "line 1" err &&
	echo "rotate 1" >bad.xf && test_fails_cleanly mesh-normalize --apply bad.xf cyl.mesh
'
test_expect_success 'help and version of every tool' '
	for t in anim-slice anim-cat anim-avg mesh-normalize mesh-info; do
		$t --help >out && grep -q "^Usage: $t" out && $t --version >out || return 1
	done
'
test_done
