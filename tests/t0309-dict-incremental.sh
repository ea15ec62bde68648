#!/bin/sh
test_description='dict-learn incremental descent (reduced coordinates): same bytes on 1 and 2 threads, energies never above the release before it (c460fba) on fixed seeds'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/dict-lib.sh"

# The sketch and the exact low-rank paths hand replib_learn reduced
# coordinates: its label steps then update the library and the costs
# incrementally when few labels change (replib.c costs_incremental), label
# on 8 candidates per frame and keep them while the costs move little.

test_expect_success 'setup: a 240-frame head, 6 decimals, with noise (full rank)' '
	noisy_head 240 7 9 xy
'
for lam in 0 2; do
	test_expect_success "lambda $lam, streamed: --threads 1 and --threads 2 give the same bytes" "
		threads_agree t \"-d 24 -l $lam --seed 4 --stream on\" 1 2
	"
done
test_expect_success 'lambda 2, streamed: the search never ends above the plain descent from the same seed' '
	dict-learn -d 24 -l 2 --seed 4 --stream on --report s.rep noisy.mesh >/dev/null &&
	dict-learn -d 24 -l 2 --seed 4 --stream on --start kmeans++ --search 0 --report p.rep noisy.mesh >/dev/null &&
	test_le "$(awk "/^energy /{print \$2}" s.rep)" "$(awk "/^energy /{print \$2}" p.rep)"
'

need_shared_data anim/facecap-335.tar.xz

test_expect_success 'setup: facecap parts' '
	facecap_parts --raw
'
# energies of c460fba (before the incremental descent), same options and seeds
while read file d lam seed opts old; do
	test_expect_success "$file d=$d lambda=$lam seed=$seed $opts: energy <= c460fba's $old" "
		dict-learn -d $d -l $lam --seed $seed $opts --report n.rep $file >/dev/null &&
		e=\$(awk '/^energy /{print \$2}' n.rep) && echo \"energy \$e (c460fba $old)\" &&
		test_le \"\$e\" \"$old\"
	"
done <<EOF
part_1.mesh 20 2 5 --stream=on 76083692.04
face.mesh 60 2 1 --stream=on 148504288.3
part_0.mesh 150 2 1 --stream=off 7269583.528
part_1.mesh 50 2 1 --stream=off 15394034.3
EOF
test_done
