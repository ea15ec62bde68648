#!/bin/sh
# b-laplacian.sh -- cot Laplacian assembly and CHOLMOD factor + 3-RHS solve
# on a 100k-vertex mesh (a bent 316 x 316 grid from mesh-gen), against
# Eigen's SimplicialLLT on the same matrix when a C++ compiler and Eigen are
# there.  CPU seconds, best of 3, single-threaded BLAS (OPENBLAS_NUM_THREADS
# =1) so both sides do the same work on one core of a shared machine.
set -u
T=${BENCH_TMP:-/tmp}/b-laplacian.$$
mkdir -p "$T"
trap 'rm -rf "$T"' EXIT INT TERM
N=${B_LAP_N:-316}
OPENBLAS_NUM_THREADS=1
export OPENBLAS_NUM_THREADS

mesh-gen -n "$N" -f 2 -a bend --amount 2 grid | anim-slice -f 1 >"$T/m.mesh" || exit 1
lap-solve "$T/m.mesh" "$T/A.bin" >"$T/cholmod" || exit 1
v() { sed -n "s/^$1 //p" "$2"; }
ms() { awk -v t="$1" 'BEGIN { printf "%.1f ms", 1000 * t }'; }

echo "   mesh: $(v vertices "$T/cholmod") vertices, $(v faces "$T/cholmod") faces; A = M - t L, $(v nnz_upper "$T/cholmod") nonzeros in the upper triangle"
echo "cot Laplacian assembly (triplets -> CHOLMOD sparse): $(ms "$(v cot_laplacian "$T/cholmod")")"
echo "A = M - t L assembly (Laplacian + Voronoi mass): $(ms "$(v assembly "$T/cholmod")")"

EIGEN=
ROOT=${ROOT:-$(cd "$(dirname "$0")/.." && pwd)}
if [ -d /usr/include/eigen3 ] && command -v c++ >/dev/null 2>&1; then
    mkdir -p "$ROOT/build/bench"
    if [ ! -x "$ROOT/build/bench/lap-eigen" ] || [ "$ROOT/bench/lap-eigen.cpp" -nt "$ROOT/build/bench/lap-eigen" ]; then
        c++ -O2 -I/usr/include/eigen3 -o "$ROOT/build/bench/lap-eigen" "$ROOT/bench/lap-eigen.cpp" 2>"$T/cxx.log" ||
            { echo "   (Eigen baseline not built: $(head -1 "$T/cxx.log"))"; }
    fi
    [ -x "$ROOT/build/bench/lap-eigen" ] && "$ROOT/build/bench/lap-eigen" "$T/A.bin" >"$T/eigen" && EIGEN=1
fi
line() {    # line NAME KEY
    a=$(v "$2" "$T/cholmod")
    if [ -n "$EIGEN" ]; then
        b=$(v "$2" "$T/eigen")
        awk -v n="$1" -v a="$a" -v b="$b" 'BEGIN {
            printf "%s: %.1f ms | baseline Eigen SimplicialLLT %.1f ms | ratio %.2f (>1: CHOLMOD faster)\n",
                n, 1000 * a, 1000 * b, b / a }'
    else
        echo "$1: $(ms "$a") | baseline Eigen: not available"
    fi
}
line "CHOLMOD analyze + factor" factor
line "CHOLMOD solve, 3 right-hand sides" solve3
echo "   residual |A X - B| / |B|: CHOLMOD $(v residual "$T/cholmod")${EIGEN:+, Eigen $(v residual "$T/eigen")}"
