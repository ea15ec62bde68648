#!/bin/sh
test_description='dict-learn: threads with no restart left help the restarts still running, and the bytes do not change'
. "$(dirname "$0")/test-lib.sh"

# replib.c (team_run): once no restart is left to start, a worker thread
# that finished takes blocks of frames of the row-wise products of the
# restarts still running (cost and distance products, U, second-best
# scans).  A block's numbers are the same wherever it runs, so the output
# must not depend on --threads.  Help is asked from 512 frames on: a
# 1024-frame head (162 vertices, full rank: noise printed with 6 decimals).

test_expect_success 'setup: a 1024-frame head, 162 vertices, 6 decimals, with noise' '
	head-gen -f 1024 -s 2 --seed 3 >head.mesh &&
	awk "BEGIN { srand(9) } /^frame /{ fr = 1 } fr && NF == 3 && \$1 != \"frame\" { printf \"%.6f %.6f %.6f\n\", \$1 + 1e-3 * (rand() - 0.5), \$2 + 1e-3 * (rand() - 0.5), \$3; next } { print }" head.mesh >noisy.mesh &&
	mesh-info noisy.mesh | grep "^frames 1024\$"
'
for lam in 0 2; do
	test_expect_success "lambda $lam, streamed (reduced coordinates): --threads 1, 2 and 3 give the same bytes" "
		dict-learn -d 30 -l $lam --seed 4 --stream on --threads 1 --report t1.rep --labels-out t1.lab noisy.mesh >t1.lib &&
		dict-learn -v -d 30 -l $lam --seed 4 --stream on --threads 2 --report t2.rep --labels-out t2.lab noisy.mesh 2>log2 >t2.lib &&
		dict-learn -v -d 30 -l $lam --seed 4 --stream on --threads 3 --report t3.rep --labels-out t3.lab noisy.mesh 2>log3 >t3.lib &&
		test_cmp t1.lib t2.lib && test_cmp t1.lab t2.lab && test_cmp t1.rep t2.rep &&
		test_cmp t1.lib t3.lib && test_cmp t1.lab t3.lab && test_cmp t1.rep t3.rep &&
		{ grep \"idle threads\" log2 log3 | sed 's/^/# /' || echo '# no chunk was helped this time (a loaded machine)'; }
	"
	test_expect_success "lambda $lam, in memory (Gram matrix): --threads 1 and 3 give the same bytes" "
		dict-learn -d 30 -l $lam --seed 4 --stream off --threads 1 --report m1.rep --labels-out m1.lab noisy.mesh >m1.lib &&
		dict-learn -d 30 -l $lam --seed 4 --stream off --threads 3 --report m3.rep --labels-out m3.lab noisy.mesh >m3.lib &&
		test_cmp m1.lib m3.lib && test_cmp m1.lab m3.lab && test_cmp m1.rep m3.rep
	"
done
test_expect_success 'the sample (restarts on 512 of 1024 frames, --gram off): --threads 1 and 2 give the same bytes' '
	dict-learn -d 30 -l 2 --seed 4 --gram off --sample 512 --threads 1 --report a.rep --labels-out a.lab noisy.mesh >a.lib &&
	dict-learn -d 30 -l 2 --seed 4 --gram off --sample 512 --threads 2 --report b.rep --labels-out b.lab noisy.mesh >b.lib &&
	test_cmp a.lib b.lib && test_cmp a.lab b.lab && test_cmp a.rep b.rep
'
test_done
