#!/bin/sh
test_description='head-gen: closed genus-0 talking head, frames, clips, seeds, where it moves'
. "$(dirname "$0")/test-lib.sh"

# info KEY MESH: one value of mesh-info's report
info() {
	mesh-info "$2" >info.out && awk -v k="$1" '$1 == k { print $2 }' info.out
}

# motion MESH > "nback backmax njaw jawmax": the largest displacement from
# frame 0 of the vertices on the back of the head (rest z < -0.4) and of
# the chin below the mouth (rest y < -0.6, z > 0.3)
motion() {
	awk '/^MESH|^vertices|^faces|^frames|^f / { next }
	     /^frame / { fr = $2 + 0; i = 0; next }
	     { if (fr == 0) { x[i] = $1; y[i] = $2; z[i] = $3; m[i] = 0 }
	       else { d = sqrt(($1 - x[i])^2 + ($2 - y[i])^2 + ($3 - z[i])^2); if (d > m[i]) m[i] = d }
	       i++ }
	     END { for (v in x) {
	               if (z[v] < -0.4) { nb++; if (m[v] > b) b = m[v] }
	               if (y[v] < -0.6 && z[v] > 0.3) { nj++; if (m[v] > j) j = m[v] } }
	           printf "%d %.6g %d %.6g\n", nb, b, nj, j }' "$1"
}

test_expect_success 'setup: a 24-frame head at subdivision 3' '
	head-gen -f 24 -s 3 >head.mesh
'
test_expect_success 'the head is a closed, oriented, genus-0 manifold' '
	mesh-info --check closed --check manifold --check oriented head.mesh &&
	test "$(info genus head.mesh)" = 0 &&
	test "$(info euler head.mesh)" = 2 &&
	test "$(info components head.mesh)" = 1 &&
	test "$(info degenerate_faces head.mesh)" = 0 &&
	test_le 0.5 "$(info volume head.mesh)"
'
test_expect_success 'icosphere sizes: 10*4^K+2 vertices, 20*4^K faces' '
	test "$(info vertices head.mesh)" = 642 &&
	test "$(info faces head.mesh)" = 1280 &&
	head-gen -f 1 -s 1 >s1.mesh &&
	test "$(info vertices s1.mesh)" = 42 &&
	head-gen -f 2 >s4.mesh &&
	test "$(info vertices s4.mesh)" = 2562 &&
	mesh-info --check closed s4.mesh
'
test_expect_success 'the requested frame count; two clips by default, one cut mark' '
	test "$(info frames head.mesh)" = 24 &&
	test "$(info clips head.mesh)" = 2 &&
	grep "^frame " head.mesh >frames &&
	test "$(wc -l <frames)" = 24 &&
	grep -c " cut$" frames >ncut && test "$(cat ncut)" = 1 &&
	grep -x "frame 12 cut" frames
'
test_expect_success '--clips C: C clips of nearly equal length' '
	head-gen -f 10 -s 1 --clips 3 >c3.mesh &&
	test "$(info clips c3.mesh)" = 3 &&
	grep " cut$" c3.mesh >cuts &&
	printf "frame 4 cut\nframe 7 cut\n" >expect &&
	test_cmp expect cuts &&
	head-gen -f 5 -s 1 --clips 5 >c5.mesh &&
	test "$(info clips c5.mesh)" = 5
'
test_expect_success 'one frame is one clip' '
	head-gen -f 1 -s 2 >one.mesh &&
	test "$(info frames one.mesh)" = 1 &&
	test "$(info clips one.mesh)" = 1 &&
	! grep -q cut one.mesh
'
test_expect_success 'the head spans y in [-1, 1] at rest and looks along +z' '
	mesh-info one.mesh >one.info &&
	ymin=$(awk "\$1 == \"bbox_min\" { print \$3 }" one.info) &&
	ymax=$(awk "\$1 == \"bbox_max\" { print \$3 }" one.info) &&
	zmin=$(awk "\$1 == \"bbox_min\" { print \$4 }" one.info) &&
	zmax=$(awk "\$1 == \"bbox_max\" { print \$4 }" one.info) &&
	test_near "$ymax" 1 0.01 && test_near "$ymin" -1 0.05 &&
	test_le 0.9 "$zmax" && test_le "$zmin" -0.8 &&
	test_le "$(echo "$zmin" | tr -d -)" "$zmax"
'
test_expect_success 'same seed, same bytes; the default seed is 1' '
	head-gen -f 6 -s 2 --seed 7 >a.mesh &&
	head-gen -f 6 -s 2 --seed 7 >b.mesh &&
	test_cmp a.mesh b.mesh &&
	head-gen -f 6 -s 2 >d.mesh &&
	head-gen -f 6 -s 2 --seed 1 >d1.mesh &&
	test_cmp d.mesh d1.mesh
'
test_expect_success 'a different seed gives different motion (same rest topology)' '
	head-gen -f 6 -s 2 --seed 8 >c.mesh &&
	! cmp -s a.mesh c.mesh &&
	grep "^f " a.mesh >fa && grep "^f " c.mesh >fc && test_cmp fa fc &&
	anim-diff -s a.mesh c.mesh >ac.txt &&
	test_le 0.001 "$(awk "\$1 == \"max\" { print \$2 }" ac.txt)"
'
test_expect_success 'the back of the head barely moves; the jaw moves a lot' '
	head-gen -f 48 -s 3 >talk.mesh &&
	motion talk.mesh >motion.txt &&
	cat motion.txt &&
	read nb back nj jaw <motion.txt &&
	test_le 50 "$nb" && test_le 10 "$nj" &&
	test_le 0.05 "$jaw" &&
	test_le "$back" 0.005 &&
	test_le "$(awk -v b="$back" "BEGIN { print 20 * b }")" "$jaw"
'
test_expect_success '--fps: the same motion sampled twice as densely' '
	head-gen -f 9 -s 1 --clips 1 --fps 12 >f12.mesh &&
	head-gen -f 17 -s 1 --clips 1 --fps 24 >f24.mesh &&
	anim-slice -f 0::2 f24.mesh >even.mesh &&
	anim-diff -s f12.mesh even.mesh >fps.txt &&
	test_near "$(awk "\$1 == \"max\" { print \$2 }" fps.txt)" 0 1e-9
'
test_expect_success '--raw writes the same animation in the raw variant' '
	head-gen -f 4 -s 2 --raw >r.mesh &&
	head -c 10 r.mesh >magic && printf "MESH 1 raw" >expect && test_cmp expect magic &&
	STOPMO_RAW=1 head-gen -f 4 -s 2 >r2.mesh && test_cmp r.mesh r2.mesh &&
	head-gen -f 4 -s 2 >p.mesh &&
	anim-diff -s p.mesh r.mesh >rp.txt &&
	test_near "$(awk "\$1 == \"max\" { print \$2 }" rp.txt)" 0 1e-12
'
test_expect_success '-o FILE writes the same bytes as standard output' '
	head-gen -f 3 -s 2 -o o.mesh >o.stdout &&
	test ! -s o.stdout &&
	head-gen -f 3 -s 2 >o.expect &&
	test_cmp o.expect o.mesh
'
test_expect_success 'usage errors exit 2 and write nothing' '
	test_must_fail_usage head-gen -f 0 >u.out 2>u.err &&
	test_must_fail_usage head-gen -f -3 >>u.out 2>>u.err &&
	test_must_fail_usage head-gen -f 4294967297 >>u.out 2>>u.err &&
	test_must_fail_usage head-gen -f 3 --clips 4 >>u.out 2>>u.err &&
	test_must_fail_usage head-gen -f 3 --clips 0 >>u.out 2>>u.err &&
	test_must_fail_usage head-gen -f 3 --clips -1 >>u.out 2>>u.err &&
	test_must_fail_usage head-gen -s 0 >>u.out 2>>u.err &&
	test_must_fail_usage head-gen -s 8 >>u.out 2>>u.err &&
	test_must_fail_usage head-gen --fps 0 >>u.out 2>>u.err &&
	test_must_fail_usage head-gen --seed x >>u.out 2>>u.err &&
	test_must_fail_usage head-gen -f 2x >>u.out 2>>u.err &&
	test_must_fail_usage head-gen extra >>u.out 2>>u.err &&
	test_must_fail_usage head-gen --bogus >>u.out 2>>u.err &&
	test_must_fail_usage head-gen -f 0 -o never.mesh 2>>u.err &&
	test ! -s u.out && test ! -e never.mesh &&
	grep -c "Try .head-gen --help." u.err >n && test "$(cat n)" = 14
'
test_expect_success 'an unwritable -o is a clean failure' '
	test_fails_cleanly head-gen -f 2 -s 1 -o no/such/dir/h.mesh
'
test_expect_success '--help and --version' '
	head-gen --help >help && grep "^Usage: head-gen" help && grep -- "--seed" help &&
	head-gen --version >v && grep "^head-gen (stopmo)" v
'
test_done
