#!/bin/sh
test_description='dict-learn: threads with no restart left help the restarts still running, and the bytes do not change'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/dict-lib.sh"

# replib.c (team_run): once no restart is left to start, a worker thread
# that finished takes blocks of frames of the row-wise products of the
# restarts still running (cost and distance products, U, second-best
# scans).  A block's numbers are the same wherever it runs, so the output
# must not depend on --threads.  Help is asked from 512 frames on: a
# 1024-frame head (162 vertices, full rank: noise printed with 6 decimals).

test_expect_success 'setup: a 1024-frame head, 162 vertices, 6 decimals, with noise' '
	noisy_head 1024 3 9 xy "-s 2"
'
for lam in 0 2; do
	test_expect_success "lambda $lam, streamed (reduced coordinates): --threads 1, 2 and 3 give the same bytes" "
		threads_agree t \"-v -d 30 -l $lam --seed 4 --stream on\" 1 2 3 &&
		{ grep \"idle threads\" t2.log t3.log | sed 's/^/# /' || echo '# no chunk was helped this time (a loaded machine)'; }
	"
	test_expect_success "lambda $lam, in memory (Gram matrix): --threads 1 and 3 give the same bytes" "
		threads_agree m \"-d 30 -l $lam --seed 4 --stream off\" 1 3
	"
done
test_expect_success 'the sample (restarts on 512 of 1024 frames, --gram off): --threads 1 and 2 give the same bytes' '
	threads_agree a "-d 30 -l 2 --seed 4 --gram off --sample 512" 1 2
'
test_done
