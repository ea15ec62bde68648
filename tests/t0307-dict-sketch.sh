#!/bin/sh
test_description='dict-learn --stream: the sparse sign sketch, its two ways to reduced coordinates, and its determinism'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/dict-lib.sh"

test_expect_success 'setup: a 200-frame head, perturbed to full rank (6 decimals)' '
	noisy_head 200 4 7 xy
'
# With the frames kept, Zr comes from one DSYRK of the co-range sketch and
# an eigen-decomposition; without them (--memory 0), from the least-squares
# B and the QR of B^T.  Both have Zr Zr^T = Q B B^T Q^T, so the descent sees
# the same distances and picks the same labels.
for lam in 0 2; do
	test_expect_success "lambda $lam, rank 16 of a full-rank input: kept-frame and sketch-only coordinates give the same labels" "
		dict-learn -d 10 -l $lam --stream on --rank 16 --labels-out kept.lab noisy.mesh >/dev/null &&
		dict-learn -d 10 -l $lam --stream on --rank 16 --memory 0 --labels-out sk.lab noisy.mesh >/dev/null &&
		test_cmp kept.lab sk.lab
	"
done
test_expect_success 'rank 128 of the full-rank input captures |Z|^2 to 1e-4 (printed with -v)' '
	dict-learn -v -d 10 -l 2 --stream on noisy.mesh 2>log >/dev/null &&
	c=$(sed -n "s/.*sketch: rank [0-9]* captures \([^ ]*\) of.*/\1/p" log) &&
	echo "captured $c" &&
	test_le "$(awk -v c=$c "BEGIN{ d = c - 1; print d < 0 ? -d : d }")" 1e-4
'
test_expect_success 'same bytes on every run and for any --threads (the co-range thread sums in a fixed order)' '
	dict-learn -d 10 -l 2 --stream on noisy.mesh >a.lib &&
	dict-learn -d 10 -l 2 --stream on noisy.mesh >b.lib &&
	dict-learn -d 10 -l 2 --stream on --threads 1 noisy.mesh >c.lib &&
	cmp a.lib b.lib && cmp a.lib c.lib
'
test_done
