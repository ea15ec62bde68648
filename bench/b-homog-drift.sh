#!/bin/sh
# b-homog-drift.sh -- does seam-homog move geometry the input keeps still?
# (issue 11).  For facecap, the elephant walk and the demo head, cut as the
# StopShop recipe cuts them, seam-homog's default band model against the
# paper's Eq. 4-9 over the whole part, in the same run:
#   seam     largest distance of a seam vertex from its average (0: the
#            seam is the same in every frame)
#   still    vertices moving < 0.1% of the diagonal in the input: their
#            largest change (target < 0.5%)
#   mean/max change of all vertices over all frames (target mean < 0.1%)
# all relative to the bbox diagonal of the average mesh (seam-homog --report).
# Lines: NAME: <band> | baseline paper <paper> | ratio paper/band.
set -u
: "${ROOT:=$(cd "$(dirname "$0")/.." && pwd)}"
: "${BENCH_TMP:=$ROOT/build/bench-tmp}"
PATH="$ROOT/bin:$PATH"
export STOPMO_PROGRESS=0 OPENBLAS_NUM_THREADS=1
SHARED_DATA=${STOPMO_SHARED_DATA:-$ROOT/../shared/data}
T=$BENCH_TMP/drift
mkdir -p "$T"
X=$ROOT/examples/stopshop

key() { awk -v k="$2" '$1 == k { print $2 }' "$1"; }
pct() { awk -v a="$1" 'BEGIN { printf "%.3f%%", 100 * a }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (b > 0) printf "%.1f", a / b; else print (a > 0 ? "inf" : "1") }'; }

# compare NAME MESH LABELS
compare() {
    name=$1 mesh=$2 lab=$3
    /usr/bin/time -f %U -o "$T/$name.tb" seam-homog --raw -l "$lab" --report "$T/$name.band" "$mesh" >/dev/null || return 1
    /usr/bin/time -f %U -o "$T/$name.tp" seam-homog --raw -m paper -l "$lab" --report "$T/$name.paper" "$mesh" >/dev/null || return 1
    b=$T/$name.band p=$T/$name.paper
    echo "seam-homog drift $name ($(key "$b" vertices) v x $(key "$b" frames) f, band width $(awk -v w="$(key "$b" width)" 'BEGIN { printf "%.3g", w }') diagonals, cpu $(cat "$T/$name.tb") s | paper $(cat "$T/$name.tp") s):"
    echo "  seam deviation: $(key "$b" seam_max_deviation) | baseline paper $(key "$p" seam_max_deviation)"
    echo "  still vertices ($(key "$b" still_vertices)) max change: $(pct "$(key "$b" still_max_change)") | baseline paper $(pct "$(key "$p" still_max_change)") | ratio $(ratio "$(key "$p" still_max_change)" "$(key "$b" still_max_change)")"
    echo "  mean change: $(pct "$(key "$b" mean_change)") | baseline paper $(pct "$(key "$p" mean_change)") | ratio $(ratio "$(key "$p" mean_change)" "$(key "$b" mean_change)")"
    echo "  max change: $(pct "$(key "$b" max_change)") | baseline paper $(pct "$(key "$p" max_change)") | ratio $(ratio "$(key "$p" max_change)" "$(key "$b" max_change)")"
}

# the recipe's first stages: seg-graphcut with the seeds, seam-smooth
cut() {
    seg-graphcut --seeds "$2" "$T/$1.mesh" >"$T/$1.lab" &&
    seam-smooth --raw -l "$T/$1.lab" -L "$T/$1.slab" -o "$T/$1.smooth" "$T/$1.mesh"
}

head-gen -f 240 --raw >"$T/head.mesh" && cut head "$X/head.seeds" && compare demo-head "$T/head.smooth" "$T/head.slab"

if [ -e "$SHARED_DATA/anim/facecap.glb" ]; then
    mesh-import --raw "$SHARED_DATA/anim/facecap.glb" >"$T/facecap.mesh" &&
    cut facecap "$X/facecap.seeds" && compare facecap "$T/facecap.smooth" "$T/facecap.slab"
else
    echo "seam-homog drift facecap: skipped (no $SHARED_DATA/anim/facecap.glb)"
fi

if [ -e "$SHARED_DATA/anim/elephant-walk-457.tar.xz" ]; then
    rm -rf "$T/el" && mkdir -p "$T/el" && tar -xJf "$SHARED_DATA/anim/elephant-walk-457.tar.xz" -C "$T/el" &&
    mesh-import --raw "$T/el/*/frame_*.obj" >"$T/elephant.mesh" && rm -rf "$T/el" &&
    # body above y = 55, legs below (as b-homog.sh): the seam crosses the legs
    anim-slice -f 0:1 "$T/elephant.mesh" | awk '
        /^f /     { nf++; a[nf] = $2; b[nf] = $3; c[nf] = $4; next }
        /^frame / { rd = 1; i = 0; next }
        rd        { y[i++] = $2 }
        END       { for (f = 1; f <= nf; f++) print ((y[a[f]] + y[b[f]] + y[c[f]]) / 3 > 55 ? 1 : 0) }' >"$T/elephant.lab" &&
    compare elephant "$T/elephant.mesh" "$T/elephant.lab"
else
    echo "seam-homog drift elephant: skipped (no $SHARED_DATA/anim/elephant-walk-457.tar.xz)"
fi
rm -rf "$T"
