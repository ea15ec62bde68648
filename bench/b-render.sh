#!/bin/sh
# b-render.sh -- mesh-render / anim-render speed (issue 2 item 7).
#   1. an 800x800 render (2x2 supersampling) of a generated 10k-triangle mesh,
#      whole process wall time, against the 100 ms budget of the issue
#   2. the rasterizer alone (mesh-render -v) at 2x2 against 1x1 samples
#   3. PNG writing: the fast default (zlib 1, Up filter) against --compact
#      (libpng's level 6 and adaptive filters): time and size
#   4. the cow (spot.obj from ../shared/data through mesh-import), if present
#   5. an 8-tile contact sheet of a 60-frame 10k-triangle animation
# Each figure is the minimum of 7 runs (the machine is shared).
set -u
: "${ROOT:=$(cd "$(dirname "$0")/.." && pwd)}"
: "${BENCH_TMP:=$ROOT/build/bench-tmp}"
PATH="$ROOT/bin:$PATH"
SHARED_DATA=${STOPMO_SHARED_DATA:-$ROOT/../shared/data}
T=$BENCH_TMP/render
mkdir -p "$T"

ms() { date +%s%N; }
# best_wall CMD...: minimum wall milliseconds of 7 runs (output discarded)
best_wall() {
    best=
    for i in 1 2 3 4 5 6 7; do
        t0=$(ms); "$@" >/dev/null 2>&1 || { echo "   failed: $*" >&2; return 1; }
        t=$(( ($(ms) - t0) / 1000 ))
        if [ -z "$best" ] || [ "$t" -lt "$best" ]; then best=$t; fi
    done
    awk -v t="$best" 'BEGIN { printf "%.1f\n", t / 1000 }'
}
# best_field FIELD CMD...: minimum of a "<FIELD> ... <x> ms" figure of mesh-render -v
best_field() {
    field=$1; shift
    for i in 1 2 3 4 5 6 7; do "$@" 2>&1 >/dev/null; done |
        sed -n "s/.*$field[^,]* \([0-9.]*\) ms.*/\1/p" | sort -n | head -1
}
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.2f", (b > 0 ? a / b : 0) }'; }

mesh-gen -n 100 -m 50 --caps cylinder >"$T/c10k.mesh"
nf=$(sed -n 's/^faces //p' "$T/c10k.mesh")

w=$(best_wall mesh-render --up z --view iso -o "$T/c10k.png" "$T/c10k.mesh")
echo "mesh-render 800x800 of $nf triangles, whole process: $w ms | baseline budget 100 ms | ratio $(ratio "$w" 100)"

r2=$(best_field "render" mesh-render -v --up z --view iso -f ppm "$T/c10k.mesh")
r1=$(best_field "render" mesh-render -v --supersample 1 --up z --view iso -f ppm "$T/c10k.mesh")
echo "rasterize+shade 800x800, 2x2 samples: $r2 ms | baseline 1x1 samples $r1 ms | ratio $(ratio "$r2" "$r1")"

pf=$(best_field "write png" mesh-render -v --up z --view iso "$T/c10k.mesh")
pc=$(best_field "write png" mesh-render -v --compact --up z --view iso "$T/c10k.mesh")
mesh-render --up z --view iso "$T/c10k.mesh" >"$T/fast.png"
mesh-render --compact --up z --view iso "$T/c10k.mesh" >"$T/compact.png"
sf=$(wc -c <"$T/fast.png"); sc=$(wc -c <"$T/compact.png")
echo "PNG write 800x800, zlib 1 + Up: $pf ms | baseline --compact (zlib 6, adaptive) $pc ms | ratio $(ratio "$pf" "$pc")"
echo "PNG size, zlib 1 + Up: $sf bytes | baseline --compact $sc bytes | ratio $(ratio "$sf" "$sc")"

if [ -e "$SHARED_DATA/meshes/spot.obj" ] && mesh-import "$SHARED_DATA/meshes/spot.obj" >"$T/spot.mesh" 2>/dev/null; then
    w=$(best_wall mesh-render --view iso -o "$T/spot.png" "$T/spot.mesh")
    echo "mesh-render 800x800 of spot ($(sed -n 's/^faces //p' "$T/spot.mesh") triangles), whole process: $w ms | baseline budget 100 ms | ratio $(ratio "$w" 100)"
else
    echo "mesh-render of spot: skipped (needs ../shared/data/meshes/spot.obj and mesh-import)"
fi

mesh-gen -n 100 -m 50 --caps -f 60 -a twist cylinder >"$T/anim.mesh"
w=$(best_wall anim-render --count 8 --columns 4 --up z --view iso -o "$T/sheet.png" "$T/anim.mesh")
rd=$(best_wall mesh-info "$T/anim.mesh")
echo "anim-render 8 tiles of 320x320 from 60 frames x $nf triangles: $w ms | baseline mesh-info reading the stream $rd ms | ratio $(ratio "$w" "$rd")"
rm -f "$T/anim.mesh"
