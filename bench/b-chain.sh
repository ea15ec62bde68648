#!/bin/sh
# b-chain.sh -- build-up along a chain of keys (nricp --chain, issue 14).
#
# Chains whose true correspondence is known: frames of an animation, the
# first kept as SOURCE and every later key remeshed by mesh-clean -R 0.015
# (a scan of a new connectivity); the truth of key k is the animation's own
# vertices of that frame.  And the camel scans 01..05 (no truth: Hausdorff).
#   elephant    elephant-walk frames 0, 40, 80, 120, 160 (t0417's chain)
#   elephant20  elephant-walk frames 0, 20, 40, 60, 80 (keys closer)
#   facecap     facecap frames 0, 80, 160, 240, 320 (17 parts: eyes, teeth)
#   camel       camel-gallop scans 01..05, cleaned (t0422's chain)
# For every key: symmetric Hausdorff distance in % of the diagonal and
# flipped faces (mesh-metrics -r scan key), the mean distance of each
# vertex from its true place in % of the diagonal (truth), then the last
# key over the first (truth where known, else Hausdorff) and the CPU of the
# whole chain.  The baseline is the same chain with BASE_OPTS (default
# "--settle 0": the chain as before, no key settled), in the same run.
#   CASES="elephant facecap" OPTS="..." BASE_OPTS="..." sh bench/b-chain.sh
# (each chain takes 1-8 CPU minutes; CASES picks which run).
set -u
T=${BENCH_TMP:-/tmp}/b-chain.$$
mkdir -p "$T"
trap 'rm -rf "$T"' EXIT INT TERM
ROOT=${ROOT:-$(cd "$(dirname "$0")/.." && pwd)}
DATA=${STOPMO_SHARED_DATA:-$ROOT/../shared/data}
CASES=${CASES:-elephant elephant20 facecap camel}
OPTS=${OPTS:-}
BASE_OPTS=${BASE_OPTS---settle 0}

ratio() { awk -v a="$1" -v b="$2" 'BEGIN { printf "%.3g", (b > 0 ? a / b : 0) }'; }
# truth KEY TRUE: mean distance of KEY's vertices from TRUE's, % of TRUE's diagonal
truth() {
    d=$(mesh-info "$2" | awk '/^diagonal/ { print $2 }')
    anim-diff -s "$2" "$1" | awk -v d="$d" '/^mean/ { printf "%.3f", 100 * $2 / d }'
}
hf() { mesh-metrics --no-header -r "$1" "$2" | awk '{ printf "%.3f/%d", 100 * $3, $5 }'; }
cput() { bash -c 'TIMEFORMAT="%U %S"; o=$1; shift; { time "$@" >"$o" 2>/dev/null; } 2>&1' t "$@" | awk '{ print $1 + $2 }'; }

# anim_keys NAME TARBALL DIR FRAME...: $T/NAME-FRAME.mesh (the frame) and
# $T/NAME-FRAME-r.mesh (remeshed), every frame
anim_keys() {
    n=$1 tb=$2 dir=$3; shift 3
    for k in "$@"; do
        tar -xJf "$tb" -O "$dir/frame_$k.obj" >"$T/f.obj" &&
        mesh-import "$T/f.obj" >"$T/$n-$k.mesh" &&
        mesh-clean -R 0.015 "$T/$n-$k.mesh" >"$T/$n-$k-r.mesh" 2>/dev/null || return 1
    done
}

# run_chain NAME LABEL OPTS SOURCE TRUTHS|- TARGETS...: one line per chain
run_chain() {
    n=$1 lab=$2 opts=$3 src=$4 truths=$5; shift 5
    t=$(cput "$T/$n.keys" nricp --chain $opts "$src" "$@")
    [ -s "$T/$n.keys" ] || { echo "$n $lab: nricp failed"; return 1; }
    line="" i=1 first="" last=""
    for tg in "$@"; do
        anim-slice -f $i "$T/$n.keys" >"$T/k.mesh" || return 1
        h=$(hf "$tg" "$T/k.mesh")
        if [ "$truths" != - ]; then
            tr=$(echo "$truths" | cut -d, -f$i)
            e=$(truth "$T/k.mesh" "$tr")
            line="$line $h ($e)"
            v=$e
        else
            line="$line $h"
            v=${h%/*}
        fi
        [ -z "$first" ] && first=$v
        last=$v
        i=$((i + 1))
    done
    echo "$lab:$line; last/first $(ratio "$last" "$first"); $t s CPU"
}

case_run() {
    n=$1; shift
    echo "nricp --chain $n, keys Hausdorff %/flipped (truth %):"
    run_chain "$n" "  new (${OPTS:-default})" "$OPTS" "$@"
    run_chain "$n" "  baseline ($BASE_OPTS)" "$BASE_OPTS" "$@"
}

# anim_case CASE TARBALL NAME KEY...: the chain over an animation's key
# frames (the first the source, the others remeshed scans with their truth)
anim_case() {
    c=$1 tb=$2 nm=$3
    shift 3
    [ -e "$tb" ] || { echo "$c: skipped (needs $tb)"; return 0; }
    anim_keys $c "$tb" $nm "$@" || exit 1
    src=$T/$c-$1.mesh; shift
    tr="" tg=""
    for k in "$@"; do tr="$tr${tr:+,}$T/$c-$k.mesh"; tg="$tg $T/$c-$k-r.mesh"; done
    case_run $c "$src" "$tr" $tg
}

for c in $CASES; do
    case $c in
    elephant) anim_case $c "$DATA/anim/elephant-walk-457.tar.xz" elephant 0000 0040 0080 0120 0160 ;;
    elephant20) anim_case $c "$DATA/anim/elephant-walk-457.tar.xz" elephant 0000 0020 0040 0060 0080 ;;
    facecap) anim_case $c "$DATA/anim/facecap-335.tar.xz" facecap 0000 0080 0160 0240 0320 ;;
    camel)
        [ -e "$DATA/scans/camel-gallop-05.off" ] || { echo "camel: skipped (needs $DATA/scans)"; continue; }
        for k in 01 02 03 04 05; do
            mesh-import "$DATA/scans/camel-gallop-$k.off" | mesh-clean >"$T/c$k.mesh" 2>/dev/null || exit 1
        done
        case_run camel "$T/c01.mesh" - "$T/c02.mesh" "$T/c03.mesh" "$T/c04.mesh" "$T/c05.mesh" ;;
    *) echo "b-chain.sh: unknown case '$c'" >&2; exit 2 ;;
    esac
done
