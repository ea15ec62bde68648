# test-lib.sh -- TAP test harness for stopmo shell tests (after git's t/).
#
#   . ./test-lib.sh            (from tests/tNNNN-name.sh)
#   test_expect_success 'title' 'commands'
#   test_must_fail tool args   (exit 1 expected, not a crash, not 0, not 2)
#   test_must_fail_usage tool  (exit 2 expected)
#   test_expect_failure_clean 'title' 'cmd > out'  the command must fail with
#                               exit 1, one line on stderr, and empty stdout
#   test_cmp expect actual
#   test_near A B TOL          |A - B| <= TOL (numbers)
#   test_le A B                A <= B (numbers)
#   test_memlimit cmd...       run cmd with 1 GB of address space (ulimit -v;
#                              not under make check-sanitize: ASan's shadow
#                              memory needs terabytes of address space)
#   need_shared_data PATH      skip all tests with a reason if ../shared/data lacks PATH
#   test_done
#
# Each test runs in a fresh trash directory; tools are on PATH from bin/.
set -u
TEST_DIRECTORY=$(cd "$(dirname "$0")" && pwd)
STOPMO_ROOT=$(cd "$TEST_DIRECTORY/.." && pwd)
# STOPMO_BIN: the tools to test (make check-sanitize sets bin-asan)
STOPMO_BIN=${STOPMO_BIN:-$STOPMO_ROOT/bin}
export STOPMO_BIN
PATH="$STOPMO_BIN:$PATH"
export PATH
SHARED_DATA=${STOPMO_SHARED_DATA:-$STOPMO_ROOT/../shared/data}
# the object tree the tools were built from, and the flags to link against
# it (make check-sanitize: build-asan and the sanitizer flags)
STOPMO_BUILD=${STOPMO_BUILD:-$STOPMO_ROOT/build}
STOPMO_LINKFLAGS=${STOPMO_LINKFLAGS:-}
export STOPMO_PROGRESS=0
unset STOPMO_RAW
# One OpenBLAS kernel on every machine: the registrations (nricp) can turn
# the last bits in which OpenBLAS's CPU kernels round differently into
# other flipped faces (nricp(1) REPRODUCIBILITY: camel 01 -> 03 0.910% of
# the diagonal with no flipped face with the Haswell kernel, 1.065% with 2
# with SkylakeX), and the suite's figures hold with the Haswell kernel.
# Only where the CPU runs it (AVX2 and FMA), and unless the caller chose.
if [ -z "${OPENBLAS_CORETYPE:-}" ] && grep -qw avx2 /proc/cpuinfo 2>/dev/null &&
	grep -qw fma /proc/cpuinfo 2>/dev/null; then
	OPENBLAS_CORETYPE=Haswell
	export OPENBLAS_CORETYPE
fi
test_count=0
test_failed=0
test_skip_all=
TRASH="${STOPMO_TRASH:-$STOPMO_ROOT/build/trash}/$(basename "$0" .sh)"
rm -rf "$TRASH"
mkdir -p "$TRASH"
cd "$TRASH" || exit 1

say() { printf '%s\n' "$*"; }

test_expect_success() {
    test_count=$((test_count + 1))
    if [ -n "$test_skip_all" ]; then
        say "ok $test_count # skip $1 ($test_skip_all)"
        return 0
    fi
    if (eval "$2") >"$TRASH/.log" 2>&1; then
        say "ok $test_count - $1"
    else
        test_failed=$((test_failed + 1))
        say "not ok $test_count - $1"
        sed -e 's/^/#   /' "$TRASH/.log" | tail -n 30
        say "#   commands:"
        printf '%s\n' "$2" | sed -e 's/^/#   /'
    fi
}

# exit status must be exactly 1 (bad input), not a crash or a usage error
test_must_fail() {
    "$@"
    rc=$?
    if [ $rc -eq 1 ]; then return 0; fi
    echo "test_must_fail: '$*' exited $rc, expected 1" >&2
    return 1
}

test_must_fail_usage() {
    "$@"
    rc=$?
    if [ $rc -eq 2 ]; then return 0; fi
    echo "test_must_fail_usage: '$*' exited $rc, expected 2" >&2
    return 1
}

# run "$@" expecting exit 1, exactly one line on stderr naming the program,
# and nothing on stdout (nothing half-written)
test_fails_cleanly() {
    "$@" >"$TRASH/.out" 2>"$TRASH/.err"
    rc=$?
    if [ $rc -ne 1 ]; then
        echo "expected exit 1, got $rc from: $*" >&2; cat "$TRASH/.err" >&2; return 1
    fi
    if [ -s "$TRASH/.out" ]; then
        echo "stdout not empty after failure of: $*" >&2; head -3 "$TRASH/.out" >&2; return 1
    fi
    n=$(wc -l <"$TRASH/.err")
    if [ "$n" -ne 1 ]; then
        echo "expected one line on stderr, got $n:" >&2; cat "$TRASH/.err" >&2; return 1
    fi
    cat "$TRASH/.err" >&2
    return 0
}

test_cmp() {
    cmp -s "$1" "$2" && return 0
    echo "test_cmp: $1 and $2 differ:" >&2
    diff -u "$1" "$2" | head -20 >&2
    return 1
}

test_near() {
    awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d;
        if (d <= t + 0) exit 0; printf "test_near: |%s - %s| = %g > %s\n", a, b, d, t > "/dev/stderr"; exit 1 }'
}

test_le() {
    awk -v a="$1" -v b="$2" 'BEGIN { if (a + 0 <= b + 0) exit 0;
        printf "test_le: %s > %s\n", a, b > "/dev/stderr"; exit 1 }'
}

test_memlimit() {
    if [ -n "${STOPMO_SANITIZE:-}" ]; then "$@"; else (ulimit -v 1000000 && "$@"); fi
}

need_shared_data() {
    if [ ! -e "$SHARED_DATA/$1" ]; then
        test_skip_all="needs ../shared/data/$1, which is absent"
    fi
}

test_done() {
    if [ $test_count -eq 0 ] && [ -n "$test_skip_all" ]; then
        say "1..0 # SKIP $test_skip_all"
        exit 0
    fi
    say "1..$test_count"
    [ $test_failed -eq 0 ] && rm -rf "$TRASH"
    [ $test_failed -eq 0 ]
}
