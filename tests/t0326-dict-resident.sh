#!/bin/sh
test_description='dict-learn --resident: a mapped raw file small enough stays mapped whole between the sketch, the pieces and the report; the same bytes as when its pages are released frame by frame, and as from a pipe'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/dict-lib.sh"

test_expect_success 'setup: a 300-frame head with 0.1% noise on the 6-decimal grid, and the exact head (binary doubles), raw' '
	head-gen -s 5 -f 300 --seed 3 |
		awk "BEGIN { srand(5) } /^frame /{ fr = 1 } fr && NF == 3 && \$1 != \"frame\" { printf \"%.6f %.6f %.6f\n\", \$1 + 1e-3 * (rand() - 0.5), \$2, \$3; next } { print }" |
		anim-slice --raw >grid.raw &&
	head-gen -f 300 --seed 4 | anim-slice --raw >exact.raw &&
	head -1 grid.raw | grep "^MESH 1 raw$"
'
# library, labels and report: kept mapped (the default: the file is far
# below 1024 MB), released (--resident 0), the limit just below and just
# above the file's size, and from a pipe (read and copied)
same4() { # tag file options...
	t=$1 f=$2; shift 2
	mb=$(wc -c <$f | awk "{ printf \"%.6f %.6f\", \$1 / 1048576 * 0.999, \$1 / 1048576 * 1.001 }") &&
	below=${mb% *} above=${mb#* } &&
	dict-learn -v "$@" --report $t.k.rep --labels-out $t.k.lab $f >$t.k.lib 2>$t.k.log &&
	dict-learn -v "$@" --resident 0 --report $t.r.rep --labels-out $t.r.lab $f >$t.r.lib 2>$t.r.log &&
	dict-learn -v "$@" --resident $below --report $t.b.rep --labels-out $t.b.lab $f >$t.b.lib 2>$t.b.log &&
	dict-learn -v "$@" --resident $above --report $t.a.rep --labels-out $t.a.lab <$f >$t.a.lib 2>$t.a.log &&
	cat $f | dict-learn -v "$@" --resident 0 --report $t.p.rep --labels-out $t.p.lab >$t.p.lib 2>$t.p.log &&
	grep "mapped: raw frames sketched where they lie in the file (kept mapped whole)" $t.k.log &&
	grep "mapped: raw frames sketched where they lie in the file (pages released once read)" $t.r.log &&
	grep "(pages released once read)" $t.b.log &&
	grep "(kept mapped whole)" $t.a.log &&
	! grep "mapped" $t.p.log &&
	for v in r b a p; do
		test_cmp $t.k.lib $t.$v.lib && test_cmp $t.k.lab $t.$v.lab && test_cmp $t.k.rep $t.$v.rep || return 1
	done
}
test_expect_success 'on the decimal grid (frames read again where they lie): kept mapped = released = pipe, lambda 2 and 0' '
	same4 a grid.raw -d 9 -l 2 --stream on &&
	grep "frames read exactly as integers" a.k.log &&
	grep "frames read exactly as integers" a.r.log &&
	same4 b grid.raw -d 12 -l 0 --stream on
'
test_expect_success 'off the grid (frames kept as floats), and the sketch only (--memory 0): kept mapped = released = pipe' '
	same4 c exact.raw -d 9 -l 2 --stream on &&
	grep "single-precision frames" c.k.log &&
	same4 d grid.raw -d 9 -l 2 --stream on --memory 0
'
# kept mapped, the frames are also summed into the sketch where they lie;
# released, each batch of 128 frames is copied first (two buffers of 128 x
# 3 #V doubles, 6 KB per vertex), since its pages may go before it is summed
test_expect_success 'kept mapped, the peak holds the file; released, it does not (only the copy buffers of the sketch)' '
	if [ -n "${STOPMO_SANITIZE:-}" ]; then echo "ASan holds freed memory in quarantine: measured in the normal build"; exit 0; fi &&
	/usr/bin/time -f %M -o k.kb dict-learn -d 8 --stream on grid.raw >k.lib &&
	/usr/bin/time -f %M -o r.kb dict-learn -d 8 --stream on --resident 0 grid.raw >r.lib &&
	test_cmp k.lib r.lib &&
	file_kb=$(wc -c <grid.raw | awk "{ print \$1 / 1024 }") &&
	zb_kb=$(sed -n "s/^vertices //p;/^frames /q" grid.raw | awk "{ print 6 * \$1 }") &&
	echo "peak $(tail -1 k.kb) KB kept mapped, $(tail -1 r.kb) KB released; file $file_kb KB, copy buffers $zb_kb KB" &&
	test_le "$(awk -v r=$(tail -1 r.kb) -v f=$file_kb -v z=$zb_kb "BEGIN { print r + 0.4 * f - z }")" "$(tail -1 k.kb)"
'
test_expect_success 'a negative or non-numeric --resident is a usage error' '
	test_must_fail_usage dict-learn --resident -1 grid.raw &&
	test_must_fail_usage dict-learn --resident x grid.raw &&
	dict-learn --help | grep -- "--resident MB"
'
test_done
