#!/bin/sh
test_description='dict-learn: the distance columns of the greedy start and the split/merge proposals come from its own kernel on every FMA CPU, whatever OpenBLAS kernel runs; its AVX2 twin gives the same bytes as the AVX-512 one'
. "$(dirname "$0")/test-lib.sh"

# twin TITLE BODY: BODY where the CPU has AVX-512 and FMA (two kernels to
# compare), else skipped
twin() {
	if grep -qw avx512f /proc/cpuinfo && grep -qw fma /proc/cpuinfo; then
		test_expect_success "$1" "$2"
	else
		test_count=$((test_count + 1))
		say "ok $test_count # skip $1 (the CPU has no AVX-512: one kernel only)"
	fi
}

test_expect_success 'setup: a 600-frame head with noise, raw (the sketch: the columns from reduced coordinates, helped past 512 frames)' '
	head-gen -s 3 -f 600 --seed 7 |
		awk "BEGIN { srand(9) } /^frame /{ fr = 1 } fr && NF == 3 && \$1 != \"frame\" { printf \"%.6f %.6f %.6f\n\", \$1 + 1e-2 * (rand() - 0.5), \$2, \$3; next } { print }" |
		anim-slice --raw >h.raw
'
run() { # tag "VAR=value ..." options...
	t=$1 e=$2; shift 2
	env $e dict-learn -v --stream on "$@" --report $t.rep --labels-out $t.lab h.raw >$t.lib 2>$t.log
}
for k in Haswell SkylakeX; do
	twin "OpenBLAS $k: AVX2 twin = AVX-512 kernel (library, labels, report), lambda 2 and 0" '
		run w2$k "OPENBLAS_CORETYPE=$k" -d 40 -l 2 &&
		run n2$k "OPENBLAS_CORETYPE=$k STOPMO_NO_AVX512=1" -d 40 -l 2 &&
		run w0$k "OPENBLAS_CORETYPE=$k" -d 25 -l 0 &&
		run n0$k "OPENBLAS_CORETYPE=$k STOPMO_NO_AVX512=1" -d 25 -l 0 &&
		grep "direct back end (sketch) (OpenBLAS $k)" w2$k.log &&
		test_cmp w2$k.lib n2$k.lib && test_cmp w2$k.lab n2$k.lab && test_cmp w2$k.rep n2$k.rep &&
		test_cmp w0$k.lib n0$k.lib && test_cmp w0$k.lab n0$k.lab && test_cmp w0$k.rep n0$k.rep
	'
done

test_done
