#!/bin/sh
# b-homog.sh -- seam-homog throughput and memory (issue 3 benchmarks).
#   1. frames/s on the elephant walk (6034 v x 457 f) and on a generated
#      100k-vertex animation, factor once (batched solves) against the
#      naive baseline that factors for every frame (--refactor-each-frame)
#   2. batched solves (--batch 8, the default) against one frame per solve
#   3. peak memory for 457 against 4570 frames (should be flat)
# Timings come from seam-homog -v (wall and process cpu seconds of the
# solve pass); OpenBLAS runs single-threaded so cpu seconds mean work.
# Writes its inputs to $BENCH_TMP (about 1 GB at peak; removed at the end
# except the converted elephant stream, which later runs reuse).
set -u
: "${ROOT:=$(cd "$(dirname "$0")/.." && pwd)}"
: "${BENCH_TMP:=$ROOT/build/bench-tmp}"
PATH="$ROOT/bin:$PATH"
export STOPMO_PROGRESS=0 OPENBLAS_NUM_THREADS=1 TMPDIR="$BENCH_TMP"
SHARED_DATA=${STOPMO_SHARED_DATA:-$ROOT/../shared/data}
T=$BENCH_TMP/homog
mkdir -p "$T"

# labels_by_axis MESH AXIS(1..3) THRESHOLD: 1 if the frame-0 centroid
# coordinate is above THRESHOLD
labels_by_axis() {
    awk -v A="$2" -v T="$3" '
        /^f /     { nf++; a[nf] = $2; b[nf] = $3; c[nf] = $4; next }
        /^frame / { if ($2 + 0 > 0) exit; rd = 1; i = 0; next }
        rd        { z[i++] = $A }
        END       { for (f = 1; f <= nf; f++) print ((z[a[f]] + z[b[f]] + z[c[f]]) / 3 > T ? 1 : 0) }' "$1"
}

# run NAME seam-homog-args...: seam-homog -v, output discarded; sets
# P2 (pass-2 frames/s wall), P2CPU (frames per cpu second), TOT (frames/s
# overall, both passes and the factor), MB (peak resident MB)
run() {
    name=$1; shift
    seam-homog -v ${RAW-"--raw"} "$@" >/dev/null 2>"$T/$name.err" || { echo "   seam-homog failed ($name):"; tail -2 "$T/$name.err"; return 1; }
    parse "$name"
}
parse() {
    name=$1
    P2=$(sed -n 's/.*pass 2: .*: \([0-9.]*\) frames\/s, \([0-9.]*\) frames per cpu.*/\1/p' "$T/$name.err")
    P2CPU=$(sed -n 's/.*pass 2: .*: \([0-9.]*\) frames\/s, \([0-9.]*\) frames per cpu.*/\2/p' "$T/$name.err")
    TOT=$(sed -n 's/.*total .*: \([0-9.]*\) frames\/s/\1/p' "$T/$name.err")
    TOTCPU=$(sed -n 's/.*total .*(cpu \([0-9.]*\) s).*/\1/p' "$T/$name.err")
    MB=$(sed -n 's/.*peak memory.*: \([0-9.]*\) MB/\1/p' "$T/$name.err")
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", (b > 0 ? a / b : 0) }'; }

# ---- elephant ----
if [ -e "$SHARED_DATA/anim/elephant-walk-457.tar.xz" ]; then
    E=$BENCH_TMP/elephant-457.mesh
    if [ ! -s "$E" ]; then
        tar -xJf "$SHARED_DATA/anim/elephant-walk-457.tar.xz" -C "$T" || exit 1
        f0=$T/elephant/frame_0000.obj
        { printf 'MESH 1\nvertices %d\nfaces %d\nframes %d\n' "$(grep -c '^v ' "$f0")" \
              "$(grep -c '^f ' "$f0")" "$(ls "$T"/elephant/frame_*.obj | wc -l)"
          awk '/^f / { for (c = 2; c <= 4; c++) { split($c, s, "/"); x[c] = s[1] - 1 }
                       print "f", x[2], x[3], x[4] }' "$f0"
          awk 'FNR == 1 { print "frame " k++ } /^v / { print $2, $3, $4 }' "$T"/elephant/frame_*.obj
        } >"$E.tmp" && mv "$E.tmp" "$E"
        rm -rf "$T/elephant"
    fi
    # two parts: body above y = 55 (the elephant stands about 130 tall),
    # legs below; the seam crosses the four legs
    labels_by_axis "$E" 2 55 >"$T/el.lab"
    anim-slice --raw "$E" >"$T/el.raw"
    run el -l "$T/el.lab" "$T/el.raw" || exit 1
    el_p2=$P2 el_cpu=$P2CPU el_tot=$TOT el_mb=$MB el_totcpu=$TOTCPU
    run el-refactor --refactor-each-frame -l "$T/el.lab" "$T/el.raw" || exit 1
    echo "seam-homog elephant 6034v x 457f, solve pass: $el_p2 frames/s ($el_cpu per cpu-s) | baseline refactor each frame $P2 frames/s ($P2CPU per cpu-s) | ratio $(ratio "$el_cpu" "$P2CPU")"
    run el-b1 --batch 1 -l "$T/el.lab" "$T/el.raw" || exit 1
    echo "seam-homog elephant, batched solves (8 frames): $el_cpu frames/cpu-s | baseline one frame per solve $P2CPU frames/cpu-s | ratio $(ratio "$el_cpu" "$P2CPU")"
    RAW=; run el-plain -l "$T/el.lab" "$T/el.raw" || exit 1; unset RAW
    echo "seam-homog elephant end to end (both passes + factor), raw output: $el_tot frames/s, $el_totcpu cpu-s | baseline plain text output $TOT frames/s, $TOTCPU cpu-s | ratio $(ratio "$TOTCPU" "$el_totcpu")"

    # memory: 457 against 4570 frames, both through a pipe (spooled)
    anim-cat --raw "$T/el.raw" "$T/el.raw" "$T/el.raw" "$T/el.raw" "$T/el.raw" \
        "$T/el.raw" "$T/el.raw" "$T/el.raw" "$T/el.raw" "$T/el.raw" |
        seam-homog -v --raw -l "$T/el.lab" >/dev/null 2>"$T/el-4570.err" || { tail -2 "$T/el-4570.err"; exit 1; }
    parse el-4570
    grep -q "4570 frames" "$T/el-4570.err" || { echo "   expected 4570 frames"; exit 1; }
    m4570=$MB t4570=$TOT
    run el-457 -l "$T/el.lab" <"$T/el.raw" || exit 1
    echo "seam-homog peak memory, 4570 frames from a pipe: $m4570 MB ($t4570 frames/s) | baseline 457 frames $MB MB ($TOT frames/s) | ratio $(ratio "$m4570" "$MB")"
    run el-file -l "$T/el.lab" "$T/el.raw" || exit 1
    echo "seam-homog peak memory, 457 frames from a regular file (read twice): $MB MB | baseline from a pipe (spooled) $(sed -n 's/.*peak memory.*: \([0-9.]*\) MB/\1/p' "$T/el-457.err") MB | ratio $(ratio "$MB" "$(sed -n 's/.*peak memory.*: \([0-9.]*\) MB/\1/p' "$T/el-457.err")")"
    rm -f "$T/el.raw"
else
    echo "seam-homog elephant: skipped (needs ../shared/data/anim/elephant-walk-457.tar.xz)"
fi

# ---- generated 100k-vertex animation: closed cylinder, 320 x 312 ----
mesh-gen -n 320 -m 312 --caps cylinder >"$T/c0.mesh"
labels_by_axis "$T/c0.mesh" 3 0.5 >"$T/c.lab"
mesh-gen -n 320 -m 312 --caps -f 24 -a wave --raw cylinder >"$T/c.raw"
run c -l "$T/c.lab" "$T/c.raw" || exit 1
c_p2=$P2 c_cpu=$P2CPU c_tot=$TOT c_mb=$MB
nv=$(sed -n 's/.*: \([0-9]*\) vertices,.*/\1/p' "$T/c.err")
# the baseline factors for every frame: 4 frames are enough for its rate
anim-slice -f 0:4 --raw "$T/c.raw" >"$T/c4.raw"
run c-refactor --refactor-each-frame -l "$T/c.lab" "$T/c4.raw" || exit 1
echo "seam-homog cylinder ${nv}v x 24f, solve pass: $c_p2 frames/s ($c_cpu per cpu-s; end to end $c_tot frames/s, $c_mb MB) | baseline refactor each frame $P2 frames/s ($P2CPU per cpu-s) | ratio $(ratio "$c_cpu" "$P2CPU")"
run c-b1 --batch 1 -l "$T/c.lab" "$T/c.raw" || exit 1
echo "seam-homog cylinder ${nv}v, batched solves (8 frames): $c_cpu frames/cpu-s ($c_mb MB) | baseline one frame per solve $P2CPU frames/cpu-s ($MB MB) | ratio $(ratio "$c_cpu" "$P2CPU")"
rm -f "$T/c.raw" "$T/c4.raw" "$T/c0.mesh"
