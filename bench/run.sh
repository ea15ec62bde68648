#!/bin/sh
# bench/run.sh -- run every bench/b-*.sh.  Each prints lines of the form
#   NAME: <measured> <unit> | baseline <what> <value> <unit> | ratio <r>
# measured in the same run, so the ratios mean something on any machine.
# Timings are never asserted; see the closing notes of the issues.
set -u
ROOT=$(cd "$(dirname "$0")/.." && pwd)
PATH="$ROOT/bin:$ROOT/build/bench:$PATH"
export PATH ROOT
export STOPMO_PROGRESS=0
BENCH_TMP=${BENCH_TMP:-$ROOT/build/bench-tmp}
mkdir -p "$BENCH_TMP"
export BENCH_TMP
status=0
for b in "$ROOT"/bench/b-*.sh; do
    [ -e "$b" ] || continue
    echo "== $(basename "$b" .sh)"
    sh "$b" || { echo "   (failed: $b)"; status=1; }
done
exit $status
