#!/bin/sh
test_description='dict-learn low-rank test: tolerance from the input decimal step (OBJ data fires, full-rank data falls back after one try)'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/dict-lib.sh"
need_shared_data anim/facecap-335.tar.xz

test_expect_success 'setup: facecap lower part (OBJ, 6 decimals) repeated to 1675 frames; a noisy copy' '
	facecap_parts && mv part_1.mesh lower.mesh &&
	anim-cat lower.mesh lower.mesh lower.mesh lower.mesh lower.mesh >long.mesh &&
	awk "BEGIN { srand(2) } /^frame /{ fr = 1 } fr && NF == 3 && \$1 != \"frame\" { printf \"%.6f %.6f %.6f\n\", \$1 + 0.5 * (rand() - 0.5), \$2, \$3; next } { print }" long.mesh >noisy.mesh
'
test_expect_success 'OBJ frames: step 1e-06 detected, low rank accepted, same energy as the full Gram matrix' '
	dict-learn -v -d 20 -l 0 --report lr.rep long.mesh 2>log >/dev/null &&
	grep "low-rank test: input step 1e-06.*accepted" log &&
	dict-learn -d 20 -l 0 --gram full --report full.rep long.mesh >/dev/null &&
	a=$(awk "/^energy /{print \$2}" lr.rep) && b=$(awk "/^energy /{print \$2}" full.rep) &&
	test_near "$a" "$b" "$(awk -v a=$a "BEGIN{print 1e-8 * a}")"
'
test_expect_success 'noise above the step: rejected (full Gram matrix)' '
	dict-learn -v -d 20 -l 0 noisy.mesh 2>log >/dev/null &&
	grep "low-rank test: input step 1e-06.*rejected" log && grep "Gram back end" log
'
test_done
