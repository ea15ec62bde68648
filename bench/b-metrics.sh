#!/bin/sh
# b-metrics.sh -- mesh-metrics time per frame against the implementation
# before the wide-tree batch search (issue 14), built from git in this run.
#
#   baseline: tools/mesh-metrics.c, libcommon/mesh_distance.*,
#     libcommon/closest_point.* of commit $MM_BASE (default 60be16e: one
#     process for all frames, hinted walks of the binary AABB tree), linked
#     with this tree's libcommon.a.
#   cases: a generated bending tube of 10k faces, 21 frames, against its
#     frame 0 (same connectivity) and against a tube meshed otherwise
#     (different connectivity): runs in a fresh clone; the camel gallop
#     scans 01 and 02 of the shared data (cleaned by mesh-clean, 10k faces,
#     registered by nricp as examples/clay does): 21 ARAP in-betweens
#     against scan 01 (the examples/clay interp-metrics case) and the
#     registered pose against scan 02 (one cold frame).
#   Goal: <= 0.05 s per frame at 10k faces.  The outputs of both must be
#   the same bytes ("same output").
# Times are CPU seconds (user + sys), best of 3; wall seconds best of 3
# beside them (the search runs on two threads; the machine may be shared).
set -u
T=${BENCH_TMP:-/tmp}/b-metrics.$$
mkdir -p "$T"
trap 'rm -rf "$T"' EXIT INT TERM
ROOT=${ROOT:-$(cd "$(dirname "$0")/.." && pwd)}
DATA=${STOPMO_SHARED_DATA:-$ROOT/../shared/data}
BASE=${MM_BASE:-60be16e}

best3() {   # CPU and wall seconds, each the best of 3 runs
    bash -c 'cmd=("$@") bc= bw=
        for i in 1 2 3; do
            t=$( { TIMEFORMAT="%U %S %R"; time "${cmd[@]}" >/dev/null 2>&1; } 2>&1 ) || exit 1
            bc=$(echo "$t" | awk -v b="$bc" "{ t = \$1 + \$2; print (b == \"\" || t < b) ? t : b }")
            bw=$(echo "$t" | awk -v b="$bw" "{ print (b == \"\" || \$3 < b) ? \$3 : b }")
        done
        echo "$bc $bw"' best3 "$@"
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3g", (b > 0 ? a / b : 0) }'; }
per() { awk -v t="$1" -v n="$2" 'BEGIN { printf "%.3g", t / n }'; }

# ---- the baseline binary, from git
OLD=
if git -C "$ROOT" cat-file -e "$BASE^{commit}" 2>/dev/null && [ -e "$ROOT/build/libcommon.a" ]; then
    mkdir -p "$T/old/libcommon" "$T/old/tools"
    for f in tools/mesh-metrics.c libcommon/mesh_distance.c libcommon/mesh_distance.h \
             libcommon/closest_point.cpp libcommon/closest_point.h; do
        git -C "$ROOT" show "$BASE:$f" >"$T/old/$f" || exit 1
    done
    INC="-I$T/old/libcommon -I$ROOT/libcommon -I/usr/include/suitesparse -I/usr/include/eigen3 -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE"
    if ${CC:-cc} -O2 -std=c11 -pthread $INC -c -o "$T/old/mm.o" "$T/old/tools/mesh-metrics.c" &&
       ${CC:-cc} -O2 -std=c11 -pthread $INC -c -o "$T/old/md.o" "$T/old/libcommon/mesh_distance.c" &&
       ${CXX:-c++} -O2 -std=c++17 -pthread -frounding-math -DCGAL_DISABLE_GMP=0 $INC -c \
           -o "$T/old/cp.o" "$T/old/libcommon/closest_point.cpp" &&
       ${CC:-cc} -pthread -o "$T/mesh-metrics-old" "$T/old/mm.o" "$T/old/md.o" "$T/old/cp.o" \
           "$ROOT/build/libcommon.a" -lcholmod -lsuitesparseconfig -lopenblas -llapack -lmaxflow \
           -lOpenMeshCore -lassimp -lpng -lz -lgmp -lmpfr -lfmt -lstdc++ -lm; then
        OLD="$T/mesh-metrics-old"
    fi
fi
[ -n "$OLD" ] || { echo "mesh-metrics: skipped (cannot build the baseline from git commit $BASE)"; exit 0; }

# one case: NAME REFERENCE ANIM
one() {
    nfr=$(mesh-info "$3" | awk '$1 == "frames" { print $2 }')
    nf=$(mesh-info "$2" | awk '$1 == "faces" { print $2 }')
    mesh-metrics -r "$2" "$3" >"$T/new.txt" && "$OLD" -r "$2" "$3" >"$T/old.txt" || exit 1
    same=no; cmp -s "$T/new.txt" "$T/old.txt" && same=yes
    set -- "$1" $(best3 mesh-metrics -r "$2" "$3") $(best3 "$OLD" -r "$2" "$3")
    echo "mesh-metrics $1 ($nf faces, $nfr frames): $(per "$2" "$nfr") s CPU per frame ($(per "$3" "$nfr") s wall) | baseline $BASE $(per "$4" "$nfr") s CPU ($(per "$5" "$nfr") s wall) | ratio $(ratio "$2" "$4") in CPU, $(ratio "$3" "$5") in wall; same output: $same (goal <= 0.05 s per frame)"
}

# ---- generated: a bending closed tube, 10200 faces, 21 frames
mesh-gen -n 100 -m 50 --caps -f 21 -a bend --amount 1.5 cylinder >"$T/tube.mesh" &&
anim-slice -f 0 "$T/tube.mesh" >"$T/tube0.mesh" &&
mesh-gen -n 90 -m 56 --caps cylinder >"$T/other.mesh" || exit 1
one "bending tube vs its frame 0" "$T/tube0.mesh" "$T/tube.mesh"
one "bending tube vs a tube meshed otherwise" "$T/other.mesh" "$T/tube.mesh"

# ---- the camel scans
if [ -e "$DATA/scans/camel-gallop-02.off" ]; then
    for k in 01 02; do
        mesh-import "$DATA/scans/camel-gallop-$k.off" >"$T/raw$k.mesh" &&
        mesh-clean "$T/raw$k.mesh" >"$T/c$k.mesh" || exit 1
    done
    nricp --init-deform -l "$ROOT/examples/clay/landmarks-01-02.txt" --landmark-mesh "$T/raw02.mesh" \
        "$T/c01.mesh" "$T/c02.mesh" >"$T/r.mesh" &&
    anim-cat "$T/c01.mesh" "$T/r.mesh" | arap-interp --steps 20 >"$T/ib.mesh" || exit 1
    one "camel 01->02 ARAP in-betweens vs scan 01" "$T/c01.mesh" "$T/ib.mesh"
    one "camel registered 02 vs scan 02 (one cold frame)" "$T/c02.mesh" "$T/r.mesh"
else
    echo "mesh-metrics camel: skipped (needs ../shared/data/scans)"
fi
