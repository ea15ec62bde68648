#!/bin/sh
test_description='dict-learn maps a raw stream in a regular file (frames sketched, and read again for the pieces, where they lie): same bytes as from a pipe, errors as the reader gives them'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/dict-lib.sh"

test_expect_success 'setup: a 300-frame head, a full-rank copy on the 6-decimal grid, both raw' '
	noisy_head 300 4 7 xy &&
	anim-slice --raw head.mesh >head.raw && anim-slice --raw noisy.mesh >noisy.raw &&
	head -1 noisy.raw | grep "^MESH 1 raw$" &&
	mesh-info head.mesh | awk "/^vertices /{ for (i = 0; i < \$2; i++) print 1 + i % 3 }" >w.txt
'
# same library, labels and report: file (mapped; frames read again where
# they lie), stdin redirected from the file (mapped too), the file mapped
# with its frames kept in 32 bits (as a file above half the memory is),
# pipe (read and copied)
same3() { # tag file options...
	t=$1 f=$2; shift 2
	dict-learn -v "$@" --report $t.f.rep --labels-out $t.f.lab $f >$t.f.lib 2>$t.f.log &&
	dict-learn -v "$@" --report $t.r.rep --labels-out $t.r.lab <$f >$t.r.lib 2>$t.r.log &&
	STOPMO_DICT_KEEP_MAPPED=1 dict-learn -v "$@" --report $t.k.rep --labels-out $t.k.lab $f >$t.k.lib 2>$t.k.log &&
	cat $f | dict-learn -v "$@" --report $t.p.rep --labels-out $t.p.lab >$t.p.lib 2>$t.p.log &&
	grep "mapped: raw frames sketched where they lie" $t.f.log &&
	grep "mapped: raw frames sketched where they lie" $t.r.log &&
	grep "mapped: raw frames sketched where they lie" $t.k.log &&
	! grep "frames read" $t.k.log &&
	! grep "mapped" $t.p.log &&
	for v in r k p; do
		test_cmp $t.f.lib $t.$v.lib && test_cmp $t.f.lab $t.$v.lab && test_cmp $t.f.rep $t.$v.rep || return 1
	done
}
test_expect_success 'on the decimal grid (frames read again where they lie as the integers a pipe keeps): file = pipe, lambda 0 and 2, weights' '
	same3 a noisy.raw -d 9 -l 2 --stream on &&
	grep "frames read exactly as integers" a.f.log &&
	grep "frames read exactly as integers" a.r.log &&
	grep "frames kept exactly as integers" a.p.log &&
	grep "frames kept exactly as integers" a.k.log &&
	same3 b noisy.raw -d 12 -l 0 --stream on &&
	same3 c noisy.raw -d 9 -l 2 --stream on -w w.txt
'
test_expect_success 'off the grid (binary doubles: frames kept as floats): file = pipe' '
	same3 d head.raw -d 9 -l 2 --stream on &&
	grep "single-precision frames" d.f.log
'
test_expect_success 'sketch only (--memory 0, or a budget below the announced frames): file = pipe' '
	same3 e noisy.raw -d 9 -l 2 --stream on --memory 0 &&
	same3 f noisy.raw -d 9 -l 2 --stream on --memory 3
'
test_expect_success 'a frame off the grid after 150 on it (the kept integers turn to floats): file = pipe' '
	awk "/^frame /{ k++ } k == 151 && NF == 3 && \$1 != \"frame\" && !d { printf \"%.9f %s %s\n\", \$1 + 1e-8, \$2, \$3; d = 1; next } { print }" noisy.mesh |
		anim-slice --raw >off.raw &&
	same3 g off.raw -d 9 -l 2 --stream on &&
	grep "single-precision frames: largest rounding .* left the input.s decimal grid" g.f.log
'
test_expect_success 'comment lines (10 KB) between raw frames, a clip cut: file = pipe' '
	awk "/^frame 100\$/{ print \"frame 100 cut\"; next } { print }" noisy.mesh | anim-slice --raw >cut.raw &&
	grep -a "^frame 100 cut" cut.raw &&
	o=$(grep -abo "frame 200" cut.raw | head -1 | cut -d: -f1) && test -n "$o" &&
	awk "BEGIN { s = \"#\"; for (i = 0; i < 10000; i++) s = s \"x\"; print s }" >c.txt &&
	{ head -c $o cut.raw && cat c.txt && tail -c +$((o + 1)) cut.raw; } >com.raw &&
	same3 h com.raw -d 9 -l 2 --stream on &&
	test $(awk "/^clips /{ print \$2 }" h.f.rep) -eq $(($(awk "/^clips /{ print \$2 }" a.f.rep) + 1))
'
test_expect_success 'frames read again where they lie: the peak is below that of the kept frames by most of their size' '
	if [ -n "${STOPMO_SANITIZE:-}" ]; then echo "ASan holds freed memory in quarantine: measured in the normal build"; exit 0; fi &&
	head-gen -s 5 -f 300 --seed 3 |
		awk "BEGIN { srand(5) } /^frame /{ fr = 1 } fr && NF == 3 && \$1 != \"frame\" { printf \"%.6f %.6f %.6f\n\", \$1 + 1e-3 * (rand() - 0.5), \$2, \$3; next } { print }" |
		anim-slice --raw >big.raw &&
	/usr/bin/time -f %M -o read.kb dict-learn -v -d 8 --stream on big.raw 2>read.log >read.lib &&
	STOPMO_DICT_KEEP_MAPPED=1 /usr/bin/time -f %M -o kept.kb dict-learn -v -d 8 --stream on big.raw 2>kept.log >kept.lib &&
	grep "frames read exactly" read.log && grep "frames kept exactly" kept.log &&
	test_cmp kept.lib read.lib &&
	kept_mb=$(awk "/^vertices /{ v = \$2 } /^frames /{ f = \$2 } END { print 12 * v * f / 1048576 }" big.raw) &&
	echo "peak $(cat read.kb) KB read again, $(cat kept.kb) KB kept; kept frames $kept_mb MB" &&
	test_le "$(awk -v r=$(tail -1 read.kb) -v k=$kept_mb "BEGIN { print r / 1024 + 0.4 * k }")" "$(awk -v k=$(tail -1 kept.kb) "BEGIN { print k / 1024 }")"
'
test_expect_success 'a non-finite coordinate in frame 250, a truncated last block (not caught by the size check at open): the messages of the pipe' '
	o=$(grep -abo "frame 250" noisy.raw | head -1 | cut -d: -f1) &&
	{ head -c $((o + 10 + 8 * 7)) noisy.raw && printf "\000\000\000\000\000\000\360\177" &&
	  tail -c +$((o + 10 + 8 * 8 + 1)) noisy.raw; } >nan.raw &&
	test $(wc -c <nan.raw) -eq $(wc -c <noisy.raw) &&
	size=$(wc -c <noisy.raw) &&
	head -c $((size - 100)) noisy.raw >trunc.raw &&
	for f in nan trunc; do
		test_fails_cleanly dict-learn -d 9 --stream on $f.raw &&
		sed "s/$f.raw/X/" "$TRASH/.err" >$f.ferr &&
		test_fails_cleanly sh -c "cat $f.raw | dict-learn -d 9 --stream on" &&
		sed "s/<stdin>/X/" "$TRASH/.err" >$f.perr &&
		cat $f.ferr && test_cmp $f.ferr $f.perr || return 1
	done &&
	grep "frame 250: vertex 2: non-finite" nan.ferr &&
	grep "frame 299 (header line [0-9]*): truncated vertex block" trunc.ferr
'
test_done
