#!/bin/sh
test_description='anim-diff: per-frame mean/max vertex error, summary, --height scaling'
. "$(dirname "$0")/test-lib.sh"

# shift DX DY DZ STEP MESH: add (DX, DY, DZ) * (1 + STEP * frame) to every
# vertex of a plain stream
shift_mesh() {
	awk -v dx="$1" -v dy="$2" -v dz="$3" -v s="$4" '
	    /^frame / { k = $2 + 0; print; next }
	    /^[A-Za-z]/ { print; next }
	    { f = 1 + s * k; printf "%.17g %.17g %.17g\n", $1 + dx * f, $2 + dy * f, $3 + dz * f }' "$5"
}

# val KEY FILE: the value of a summary line ("key value" or "# key value")
val() {
	awk -v k="$1" '$1 == k { print $2 } $1 == "#" && $2 == k { print $3 }' "$2"
}

test_expect_success 'setup: a static 5-frame unit grid and a waving tube' '
	mesh-gen -f 5 -a none -n 6 grid >grid.mesh &&
	mesh-gen -f 4 -a wave -n 10 -m 6 cylinder >cyl.mesh
'
test_expect_success 'identical inputs: every error is 0' '
	anim-diff cyl.mesh cyl.mesh >same.txt &&
	grep -v "^#" same.txt >rows &&
	printf "0 0 0\n1 0 0\n2 0 0\n3 0 0\n" >expect && test_cmp expect rows &&
	test "$(val mean same.txt)" = 0 && test "$(val max same.txt)" = 0 &&
	test "$(val rms same.txt)" = 0 && test "$(val frames same.txt)" = 4
'
test_expect_success 'a copy translated by (0.3, 0.4, 0): every distance is 0.5' '
	shift_mesh 0.3 0.4 0 0 cyl.mesh >moved.mesh &&
	anim-diff cyl.mesh moved.mesh >moved.txt &&
	awk "/^#/ { next } { print \$1 }" moved.txt >idx && printf "0\n1\n2\n3\n" >expect &&
	test_cmp expect idx &&
	awk "/^#/ { next } { print \$2; print \$3 }" moved.txt >vals &&
	while read v; do test_near "$v" 0.5 1e-6 || return 1; done <vals &&
	test_near "$(val mean moved.txt)" 0.5 1e-6 &&
	test_near "$(val max moved.txt)" 0.5 1e-6 &&
	test_near "$(val rms moved.txt)" 0.5 1e-6
'
test_expect_success 'a growing shift: per-frame rows, mean, max and rms over all frames' '
	shift_mesh 0 0 0.1 1 grid.mesh >grow.mesh &&
	anim-diff grid.mesh grow.mesh >grow.txt &&
	awk "/^#/ { next } { print \$1, \$2 - 0.1 * (\$1 + 1), \$3 - 0.1 * (\$1 + 1) }" grow.txt >dev &&
	awk "{ if (\$2 > 1e-6 || \$2 < -1e-6 || \$3 > 1e-6 || \$3 < -1e-6) exit 1 }" dev &&
	test_near "$(val mean grow.txt)" 0.3 1e-6 &&
	test_near "$(val max grow.txt)" 0.5 1e-6 &&
	test_near "$(val rms grow.txt)" "$(awk "BEGIN { print 0.1 * sqrt(11) }")" 1e-6
'
test_expect_success 'one vertex moved: mean is distance / #V, max is the distance' '
	awk "/^frame 2\$/ { print; rd = 1; i = 0; next } /^frame / { rd = 0 }
	     rd && i++ == 7 { print \$1, \$2, \$3 + 2; next } { print }" grid.mesh >one.mesh &&
	anim-diff grid.mesh one.mesh >one.txt &&
	grep "^2 " one.txt >row2 &&
	read k mean max <row2 &&
	test_near "$max" 2 1e-9 && test_near "$mean" "$(awk "BEGIN { print 2 / 49 }")" 1e-6 &&
	grep "^1 0 0\$" one.txt &&
	test_near "$(val rms one.txt)" "$(awk "BEGIN { print sqrt(4 / 245) }")" 1e-6
'
test_expect_success 'the distance is symmetric in its two inputs' '
	anim-diff moved.mesh cyl.mesh >back.txt &&
	test_cmp moved.txt back.txt
'
test_expect_success '--summary prints only "key value" lines' '
	anim-diff -s cyl.mesh moved.mesh >sum.txt &&
	awk "{ print \$1 }" sum.txt >keys &&
	printf "mean\nmax\nrms\nframes\n" >expect && test_cmp expect keys &&
	grep "^#" moved.txt | sed "s/^# //" >long && test_cmp long sum.txt
'
test_expect_success '--height H scales every error by H / reference height' '
	shift_mesh 0.3 0.4 0 0 grid.mesh >gmoved.mesh &&
	anim-diff --height 40 grid.mesh gmoved.mesh >h40.txt &&
	test_near "$(val max h40.txt)" 20 1e-5 && test_near "$(val mean h40.txt)" 20 1e-5 &&
	grep "^0 20 20\$" h40.txt &&
	anim-diff --height 10 --axis z -s cyl.mesh moved.mesh >hz.txt &&
	test_near "$(val max hz.txt)" 5 1e-5 &&
	test_near "$(val rms hz.txt)" 5 1e-5 &&
	test "$(val frames hz.txt)" = 4
'
test_expect_success '--height measures the reference over all frames, along --axis' '
	shift_mesh 0 0 0.5 1 grid.mesh >tall.mesh &&
	anim-diff --height 6 --axis z -s tall.mesh grid.mesh >tall.txt &&
	test_near "$(val max tall.txt)" 7.5 1e-9 &&
	test_near "$(val mean tall.txt)" 4.5 1e-9 &&
	anim-diff --height 2 --axis x -s grid.mesh tall.mesh >ax.txt &&
	test_near "$(val max ax.txt)" 5 1e-9
'
test_expect_success 'either input may be standard input, also with --height' '
	anim-diff --height 40 - gmoved.mesh <grid.mesh >p1.txt && test_cmp h40.txt p1.txt &&
	anim-diff --height 40 grid.mesh - <gmoved.mesh >p2.txt && test_cmp h40.txt p2.txt
'
test_expect_success 'raw and plain versions of one animation do not differ' '
	anim-slice --raw cyl.mesh >cyl.raw &&
	anim-diff -s cyl.mesh cyl.raw >raw.txt &&
	test "$(val max raw.txt)" = 0
'
test_expect_success 'bad input fails cleanly with nothing on stdout' '
	mesh-gen -n 5 grid >small.mesh &&
	test_fails_cleanly anim-diff grid.mesh small.mesh &&
	grep "36 vertices" .err &&
	anim-slice -f 0:3 grid.mesh >three.mesh &&
	test_fails_cleanly anim-diff grid.mesh three.mesh &&
	grep "three.mesh. has 3 frames" .err &&
	test_fails_cleanly anim-diff three.mesh grid.mesh &&
	test_fails_cleanly anim-diff grid.mesh nosuch.mesh &&
	test_fails_cleanly anim-diff nosuch.mesh grid.mesh &&
	head -n 150 grid.mesh >trunc.mesh &&
	test_fails_cleanly anim-diff grid.mesh trunc.mesh &&
	sed "s/^0 0 0\$/0 nan 0/" grid.mesh >nan.mesh && ! cmp -s grid.mesh nan.mesh &&
	test_fails_cleanly anim-diff grid.mesh nan.mesh &&
	echo "not a mesh" >junk.mesh &&
	test_fails_cleanly anim-diff junk.mesh grid.mesh &&
	test_fails_cleanly anim-diff --height 10 --axis z grid.mesh grid.mesh &&
	grep "zero height" .err
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage anim-diff grid.mesh >u.out 2>u.err &&
	test_must_fail_usage anim-diff >>u.out 2>>u.err &&
	test_must_fail_usage anim-diff a b c >>u.out 2>>u.err &&
	test_must_fail_usage anim-diff - - <grid.mesh >>u.out 2>>u.err &&
	test_must_fail_usage anim-diff --height 0 grid.mesh grid.mesh >>u.out 2>>u.err &&
	test_must_fail_usage anim-diff --height -1 grid.mesh grid.mesh >>u.out 2>>u.err &&
	test_must_fail_usage anim-diff --height mm grid.mesh grid.mesh >>u.out 2>>u.err &&
	test_must_fail_usage anim-diff --axis w grid.mesh grid.mesh >>u.out 2>>u.err &&
	test_must_fail_usage anim-diff --axis xy grid.mesh grid.mesh >>u.out 2>>u.err &&
	test_must_fail_usage anim-diff --bogus grid.mesh grid.mesh >>u.out 2>>u.err &&
	test ! -s u.out
'
test_expect_success '--help and --version' '
	anim-diff --help >help && grep "^Usage: anim-diff" help && grep "Example" help &&
	anim-diff --version >v && grep "^anim-diff (stopmo)" v
'
test_done
