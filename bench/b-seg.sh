#!/bin/sh
# b-seg.sh -- seg-graphcut and seam-smooth time (issue 3 benchmarks) on
# facecap (2694 v x 335 f) and the elephant walk (6034 v x 457 f) when
# ../shared/data has them, else on a generated 64 x 64 tube of 300 frames.
# Baseline, measured in the same run: one plain read of the same raw stream
# (anim-avg, the I/O floor of any tool that must see every frame); best of
# 3 runs each; for
# --one-pass the baseline is the default two-pass seg-graphcut.
set -u
: "${ROOT:=$(cd "$(dirname "$0")/.." && pwd)}"
: "${BENCH_TMP:=$ROOT/build/bench-tmp}"
PATH="$ROOT/bin:$PATH"
export STOPMO_PROGRESS=0 TMPDIR="$BENCH_TMP"
SHARED_DATA=${STOPMO_SHARED_DATA:-$ROOT/../shared/data}
T=$BENCH_TMP/seg
mkdir -p "$T"

now() { date +%s.%N; }
secs() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3f", b - a }'; }
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", (b > 0 ? a / b : 0) }'; }
timed() {   # timed VAR cmd...: best wall seconds of 3 runs into VAR (the
            # machine is shared), output discarded
    var=$1; shift
    best=
    for run in 1 2 3; do
        t0=$(now); "$@" >/dev/null 2>"$T/err" || { echo "   failed: $*"; tail -2 "$T/err"; return 1; }
        t=$(secs "$t0" "$(now)")
        best=$(awk -v a="$t" -v b="${best:-1e9}" 'BEGIN { print (a < b ? a : b) }')
    done
    eval "$var=$best"
}

# import NAME TARBALL: a raw MESH stream of the OBJ frames, cached in BENCH_TMP
import() {
    out=$BENCH_TMP/$1.raw
    if [ ! -s "$out" ]; then
        rm -rf "$T/x" && mkdir -p "$T/x" && tar -xJf "$2" -C "$T/x" || return 1
        d=$(dirname "$(ls "$T"/x/*/frame_0000.obj | head -1)")
        mesh-import --raw "$d/frame_*.obj" >"$out.tmp" && mv "$out.tmp" "$out" || return 1
        rm -rf "$T/x"
    fi
    echo "$out"
}

bench() {   # NAME FILE SEEDS...
    name=$1 file=$2; shift 2
    info=$(mesh-info "$file" | awk '/^vertices|^faces|^frames/ { printf "%s%s", sep, $2; sep = " " }')
    set -- "$@"
    timed base anim-avg --raw "$file" || return 1
    timed seg seg-graphcut "$@" -o "$T/$name.lab" "$file" || return 1
    seg-graphcut -v "$@" "$file" 2>"$T/$name.v" >/dev/null
    timed one seg-graphcut --one-pass "$@" "$file" || return 1
    timed smooth seam-smooth --raw -l "$T/$name.lab" -L "$T/$name.lab2" "$file" || return 1
    seam-smooth -v -l "$T/$name.lab" -L "$T/$name.lab3" "$file" 2>"$T/$name.sv" >/dev/null
    echo "   $name (v f frames = $info):"
    sed -n 's/^seg-graphcut: \(time\|energy\)/      seg-graphcut \1/p' "$T/$name.v"
    sed -n 's/^seam-smooth: \(time\|seam length\|summed\)/      seam-smooth \1/p' "$T/$name.sv"
    echo "seg-graphcut $name: $seg s | baseline one read of the stream $base s | ratio $(ratio "$seg" "$base")"
    echo "seg-graphcut --one-pass $name: $one s | baseline two passes $seg s | ratio $(ratio "$one" "$seg")"
    echo "seam-smooth $name: $smooth s | baseline one read of the stream $base s | ratio $(ratio "$smooth" "$base")"
}

ran=0
if [ -e "$SHARED_DATA/anim/facecap-335.tar.xz" ]; then
    f=$(import facecap-335 "$SHARED_DATA/anim/facecap-335.tar.xz") || exit 1
    bench facecap "$f" --seed 0:1539 --seed 1:1034 || exit 1
    ran=1
fi
if [ -e "$SHARED_DATA/anim/elephant-walk-457.tar.xz" ]; then
    f=$(import elephant-walk-457 "$SHARED_DATA/anim/elephant-walk-457.tar.xz") || exit 1
    # seeds: a point on the back and one under a front foot (snapped)
    printf '0 0 130 0\n1 0 -100 0\n' >"$T/el.seeds"
    bench elephant "$f" --seeds "$T/el.seeds" || exit 1
    ran=1
fi
if [ $ran = 0 ]; then
    echo "   (no ../shared/data: generated tube 64 x 64, 300 frames)"
    mesh-gen --raw -n 64 -m 64 -f 300 cylinder >"$T/tube.raw" || exit 1
    bench tube "$T/tube.raw" --seed 0:0 --seed 1:8191 || exit 1
fi
rm -f "$T/err"
