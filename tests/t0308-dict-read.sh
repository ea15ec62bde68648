#!/bin/sh
test_description='dict-learn reads frames on a second thread (mesh_prefetch): same bytes from a file or a pipe, errors as the reader gives them'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'setup: a 300-frame head (more frames than the 8 read-ahead buffers)' '
	head-gen -f 300 --seed 4 >head.mesh &&
	mesh-info head.mesh | grep "^frames 300$"
'
for s in off on; do
	test_expect_success "--stream $s: a pipe gives the same library, labels and report as the file" "
		dict-learn -d 9 -l 2 --stream $s --report f.rep --labels-out f.lab head.mesh >f.lib &&
		cat head.mesh | dict-learn -d 9 -l 2 --stream $s --report p.rep --labels-out p.lab >p.lib &&
		test_cmp f.lib p.lib && test_cmp f.lab p.lab && test_cmp f.rep p.rep
	"
done
test_expect_success 'a bad number in frame 250: one line naming the file and line, nothing written' '
	awk "/^frame /{ k++ } k == 250 && !done && NF == 3 && \$1 != \"frame\" { print \"1.0 x 2.0\"; done = 1; next } { print }" head.mesh >bad.mesh &&
	line=$(grep -n "^1.0 x 2.0$" bad.mesh | cut -d: -f1) &&
	for s in off on; do
		test_fails_cleanly dict-learn -d 9 --stream $s bad.mesh 2>err &&
		grep "bad.mesh" err && grep "line $line" err || return 1
	done
'
test_expect_success 'a truncated stream (header says 300 frames, 120 present): refused from a pipe too' '
	n=$(grep -n "^frame " head.mesh | sed -n 121p | cut -d: -f1) &&
	head -n $((n - 1)) head.mesh >short.mesh &&
	test_fails_cleanly sh -c "cat short.mesh | dict-learn -d 9 --stream on" 2>err &&
	grep "stdin" err
'
test_done
