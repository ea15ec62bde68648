#!/bin/sh
test_description='dict-learn --stream: one pass over the frames into a low-rank sketch, same result as in memory'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/dict-lib.sh"

test_expect_success 'setup: a 200-frame head and a perturbed (full-rank) copy' '
	noisy_head 200 3 5 x
'
for lam in 0 2; do
	test_expect_success "lambda $lam: stream (frames kept in float) = in memory: same labels, energy to 1e-8" "
		dict-learn -d 12 -l $lam --stream off --report off.rep --labels-out off.lab head.mesh >off.lib &&
		dict-learn -d 12 -l $lam --stream on --report on.rep --labels-out on.lab head.mesh >on.lib &&
		test_cmp off.lab on.lab &&
		a=\$(awk '/^energy /{print \$2}' off.rep) && b=\$(awk '/^energy /{print \$2}' on.rep) &&
		test_near \"\$a\" \"\$b\" \"\$(awk -v a=\$a 'BEGIN{print 1e-8 * a}')\" &&
		anim-diff off.lib on.lib | awk '/^# rms/{ exit !(\$3 < 1e-6) }'
	"
	test_expect_success "lambda $lam: sketch only (--memory 0): same labels, pieces from the sketch within 1e-9" "
		dict-learn -d 12 -l $lam --stream on --memory 0 --labels-out sk.lab head.mesh >sk.lib &&
		test_cmp off.lab sk.lab &&
		anim-diff off.lib sk.lib | awk '/^# rms/{ exit !(\$3 < 1e-9) }'
	"
done
test_expect_success 'frames kept as integers of the input step (6 decimals): same labels, pieces = in memory to 1e-12 rms' '
	awk "/^frame /{ fr = 1 } fr && NF == 3 && \$1 != \"frame\" { printf \"%.6f %.6f %.6f\n\", \$1, \$2, \$3; next } { print }" head.mesh >head6.mesh &&
	dict-learn -v -d 12 -l 2 --stream on --labels-out i.lab head6.mesh 2>log >i.lib &&
	grep "frames kept exactly as integers of the input.s step 1e-06" log &&
	dict-learn -d 12 -l 2 --stream off --labels-out o.lab head6.mesh >o.lib &&
	test_cmp o.lab i.lab &&
	anim-diff o.lib i.lib | awk "/^# rms/{ print; exit !(\$3 < 1e-12) }"
'
test_expect_success 'a frame off the decimal grid: the kept frames turn to single precision, said with -v' '
	awk "/^frame /{ k++ } k == 150 && NF == 3 && \$1 != \"frame\" { printf \"%.9f %s %s\n\", \$1 + 1e-8, \$2, \$3; next } { print }" noisy.mesh >offgrid.mesh &&
	dict-learn -v -d 12 -l 2 --stream on offgrid.mesh 2>log >/dev/null &&
	grep "single-precision frames: largest rounding .* left the input.s decimal grid" log
'
# the kept frames' encoding takes 8 coordinates at a time: one value off
# the grid or out of the int32 range in any lane, or in the coordinates
# left over past the last multiple of 8, must still turn them to floats
off_one() { # vertex coordinate(1-3) how(grid|range) -> offone.mesh (one value of frame 149 changed)
	awk -v V=$1 -v C=$2 -v H=$3 "/^frame /{ k++; v = 0; print; next }
		k == 150 && NF == 3 { if (v++ == V) { \$C = H == \"grid\" ? sprintf(\"%.9f\", \$C + 1e-8) : sprintf(\"%.6f\", \$C + 6000) }
			print; next } { print }" head6.mesh >offone.mesh
}
test_expect_success 'one value off the grid in lane 7 of a vector, or in the last coordinate (past the vectors): single precision' '
	nv=$(awk "/^vertices /{print \$2; exit}" head6.mesh) &&
	echo "3 x $nv = $((3 * nv)) coordinates, $((3 * nv % 8)) past the last vector" &&
	test $((3 * nv % 8)) -ne 0 &&
	for at in "2 2" "$((nv - 1)) 3" "100 1"; do
		off_one $at grid &&
		dict-learn -v -d 12 -l 2 --stream on offone.mesh 2>log >/dev/null &&
		grep "single-precision frames: largest rounding .* left the input.s decimal grid" log || return 1
	done
'
test_expect_success 'one value beyond 2^31 steps of its base (lane 7, and the last coordinate): single precision' '
	for at in "2 2" "$(($(awk "/^vertices /{print \$2; exit}" head6.mesh) - 1)) 3"; do
		off_one $at range &&
		dict-learn -v -d 12 -l 2 --stream on offone.mesh 2>log >/dev/null &&
		grep "single-precision frames: largest rounding .* left the input.s decimal grid or its range" log || return 1
	done
'
test_expect_success 'on the grid everywhere: integers, and the largest rounding is below the step' '
	dict-learn -v -d 12 -l 2 --stream on head6.mesh 2>log >/dev/null &&
	sed -n "s/.*frames kept exactly as integers of the input.s step 1e-06 (largest rounding \([^ ]*\) .*/\1/p" log >r &&
	test -s r && awk "{ exit !(\$1 < 1e-9) }" r
'
test_expect_success 'the range sketch by lanes of 8 frames (AVX-512, no transposition) = by transposed tiles: same bytes' '
	anim-slice -f 0:197 noisy.mesh >n197.mesh &&
	anim-slice -f 0:133 head6.mesh >h133.mesh &&
	for f in n197.mesh h133.mesh; do
		for mem in 4096 0; do
			dict-learn -d 9 -l 2 --stream on --memory $mem --labels-out lanes.lab $f >lanes.lib &&
			STOPMO_SKETCH_LANES=0 dict-learn -d 9 -l 2 --stream on --memory $mem --labels-out tiles.lab $f >tiles.lib &&
			test_cmp tiles.lib lanes.lib && test_cmp tiles.lab lanes.lab || return 1
		done
	done
'
test_expect_success 'full-rank input: the rank-16 sketch loses little (energy within 2%, printed)' '
	dict-learn -d 10 -l 0 --stream off --report f_off.rep noisy.mesh >/dev/null &&
	dict-learn -v -d 10 -l 0 --stream on --rank 16 --report f_on.rep noisy.mesh 2>log >/dev/null &&
	grep "sketch: rank 16 captures" log &&
	a=$(awk "/^energy /{print \$2}" f_off.rep) && b=$(awk "/^energy /{print \$2}" f_on.rep) &&
	echo "in memory $a, rank-16 sketch $b" &&
	test_le "$b" "$(awk -v a=$a "BEGIN{print 1.02 * a}")"
'
test_expect_success 'read once from a pipe: same bytes as from the file' '
	dict-learn -d 8 --stream on head.mesh >file.lib &&
	cat head.mesh | dict-learn -d 8 --stream on >pipe.lib &&
	test_cmp file.lib pipe.lib
'
test_expect_success 'more frames announced than --memory keeps: none kept, same bytes as a "frames ?" stream that fills the budget and drops it' '
	sed "s/^frames 200\$/frames ?/" head.mesh >unknown.mesh && grep "^frames ?\$" unknown.mesh &&
	dict-learn -v -d 12 --stream on --memory 2 head.mesh 2>a.log >ann.lib &&
	dict-learn -v -d 12 --stream on --memory 2 unknown.mesh 2>u.log >unk.lib &&
	grep "frames not kept (pieces from the sketch)" a.log && grep "frames not kept" u.log &&
	test_cmp unk.lib ann.lib
'
test_expect_success 'frames beyond --memory: said without -v (the pieces are approximate), from a file and from a pipe; not with --memory 0 or when they fit' '
	dict-learn -d 12 --stream on --memory 2 head.mesh 2>w.log >/dev/null &&
	grep "warning: the frames need [0-9]* MB in 32 bits, more than --memory 2: the pieces and the report come from the rank-128 sketch" w.log &&
	test $(wc -l <w.log) = 1 &&
	cat head.mesh | dict-learn -d 12 --stream on --memory 2 2>wp.log >/dev/null &&
	test_cmp w.log wp.log &&
	dict-learn -d 12 --stream on --memory 0 head.mesh 2>w0.log >/dev/null &&
	! test -s w0.log &&
	dict-learn -d 12 --stream on head.mesh 2>wk.log >/dev/null &&
	! test -s wk.log
'
test_expect_success 'auto switches to the sketch past 512 MB only (small input: in memory, same bytes)' '
	dict-learn -d 8 head.mesh >auto.lib && dict-learn -d 8 --stream off head.mesh >off8.lib &&
	test_cmp auto.lib off8.lib
'
test_expect_success 'bad uses fail cleanly' '
	test_fails_cleanly dict-learn -d 8 --stream on --fixed on.lib head.mesh &&
	test_fails_cleanly dict-learn --max-error 0.1 --stream on --memory 0 head.mesh &&
	head -c 300000 head.mesh >cut.mesh &&
	test_fails_cleanly dict-learn -d 4 --stream on cut.mesh &&
	test_must_fail_usage dict-learn --stream maybe head.mesh &&
	test_must_fail_usage dict-learn --rank 0 head.mesh
'
test_done
