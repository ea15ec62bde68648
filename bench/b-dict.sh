#!/bin/sh
# b-dict.sh -- dict-learn at the sizes of the paper's Table 1 on real
# full-rank data: bench/dict-tile builds Monkey (9,971 v x 2,653 frames,
# 150 pieces) and Bunny (17,260 v x 5,177 frames, 200 pieces) animations from
# the elephant walk and facecap OBJ frames (vertex blocks side by side; the
# performances repeated back and forth with 0.1% noise, 6 decimals), lambda
# = 2.  The whole tool is timed (read, sketch or Gram matrix, learn, write),
# wall and CPU seconds and peak memory (/usr/bin/time; the machine may be
# shared: CPU is the honest number); the current build and the release
# before are run BENCH_DICT_REPS times (default 3), alternated, and the run
# of the median wall of each is printed, with every wall.  Baselines in the same run: the
# paper's reported time (Xeon 2.4 GHz, "labeling and update steps": compare
# it with "learning alone", replib_learn's wall time), the release before
# the current speed work (dict-learn at $PREREV, same options) and the one
# before issue 12 (dict-learn at commit $OLDREV, built here from git, run
# with the same options; it has no --search: its method is the plain
# descent).  Lines: default options (5 restarts,
# greedy start, local search) and -r 1 --search 0 (one plain descent, the
# cheapest run); after each default run a "kept frames" line gives the
# largest rounding of the frames kept beside the sketch (int32 of the
# input's decimal step, or floats) against half that step.  BENCH_FULL=1 adds the Bunny under the old release (4.3 GB,
# about a minute) and the film-scale stream (100,000 frames of a
# 10,000-vertex part piped from dict-tile, against 5,000 frames and against
# the search on all frames; about 15 min on 2 shared cores).
set -u
OLDREV=361189f
PREREV=aa20334
SHARED=${SHARED_DATA:-$ROOT/../shared/data}
T=$BENCH_TMP/dict
mkdir -p "$T"
TILE=$ROOT/build/bench/dict-tile
[ -x "$TILE" ] || { echo "b-dict: $TILE not built (make bench)"; exit 1; }
for a in facecap-335 elephant-walk-457; do
    [ -r "$SHARED/anim/$a.tar.xz" ] || { echo "table1: skipped (no $SHARED/anim/$a.tar.xz)"; exit 0; }
done
src() { # name archive
    [ -s "$T/$1.mesh" ] && return 0
    rm -rf "$T/x" && mkdir "$T/x" && tar -xJf "$SHARED/anim/$2.tar.xz" -C "$T/x" &&
    mesh-import --raw "$T/x/*/frame_*.obj" >"$T/$1.mesh" && rm -rf "$T/x"
}
src elephant elephant-walk-457 && src facecap facecap-335 || exit 1
# earlier releases, from git: dict-learn and replib as they were, built over
# today's libcommon (their own headers first).  $OLDREV: before issue 12;
# $PREREV: the release before the threaded library, report, sketch and
# text writer (the "current release" of the speed lines; its MESH writer
# and number formatter are its own too; "energy vs $PREREV" compares the
# energies of the same options and seed: 1 when they are identical).
build_rev() { # rev [more libcommon files of that rev] -> path of the binary, or empty
    r=$1; shift
    b=$T/dict-learn-$r
    if [ ! -x "$b" ] && git -C "$ROOT" cat-file -e $r 2>/dev/null; then
        mkdir -p "$T/src-$r" &&
        for f in tools/dict-learn.c libcommon/replib.c libcommon/replib.h libcommon/replib_sketch.c libcommon/replib_sketch.h "$@"; do
            git -C "$ROOT" show $r:$f >"$T/src-$r/$(basename $f)" 2>/dev/null || rm -f "$T/src-$r/$(basename $f)"
        done &&
        ${CC:-cc} -O2 -std=c11 -pthread -D_POSIX_C_SOURCE=200809L -D_DEFAULT_SOURCE -I"$T/src-$r" -I"$ROOT/libcommon" \
            -o "$b" $(ls "$T/src-$r"/*.c) "$ROOT/build/libcommon.a" \
            -lcholmod -lsuitesparseconfig -lopenblas -llapack -lmaxflow -lOpenMeshCore -lassimp -lpng -lz \
            -lgmp -lmpfr -lfmt -lstdc++ -lm >&2 || { echo "b-dict: cannot build release $r" >&2; b=; }
    fi
    [ -x "$b" ] && echo "$b"
}
OLD=$(build_rev $OLDREV)
PRE=$(build_rev $PREREV libcommon/mesh.c libcommon/mesh.h libcommon/numparse.c libcommon/numparse.h \
    libcommon/mesh_prefetch.c libcommon/mesh_prefetch.h)
timed() { # prints "wall cpu peak_MB energy learn_wall" of dict-learn-like command "$@" --report
    /usr/bin/time -f "%e %U %S %M" -o "$T/time" "$@" -v --report "$T/rep" >/dev/null 2>"$T/err" ||
        { sed 's/^/   /' "$T/err" | tail -3 >&2; return 1; }
    e=$(awk '/^energy /{print $2}' "$T/rep")
    l=$(sed -n 's/.*best restart [0-9]*, \([0-9.]*\) s$/\1/p' "$T/err" | tail -1)
    awk -v e="$e" -v l="${l:--}" '{ printf "%s %.2f %.0f %s %s", $1, $2 + $3, $4 / 1024, e, l }' "$T/time"
}
median() { # "wall ..." lines on stdin -> the line of the median wall, then the walls
    sort -n | awk '{ l[NR] = $0; w[NR] = $1 } END { if (!NR) exit 1; printf "%s", l[int((NR + 1) / 2)]; printf " walls"; for (i = 1; i <= NR; i++) printf " %s", w[i]; printf "\n" }'
}
REPS=${BENCH_DICT_REPS:-3}
line() { # name V F d paper_s old(0/1) file
    name=$1 V=$2 F=$3 d=$4 paper=$5 runold=$6 f=$7
    for opts in "" "-r 1 --search 0"; do
        # the current and the release before, alternated $REPS times: the
        # run of the median wall of each (a 2-s run on a shared machine
        # varies by 20%)
        : >"$T/new.runs"; : >"$T/pre.runs"
        for i in $(seq $REPS); do
            timed dict-learn -d $d -l 2 $opts "$f" >>"$T/new.runs" && echo >>"$T/new.runs" || break
            [ $i = 1 ] && cp "$T/err" "$T/err1"
            [ -n "$PRE" ] && { timed "$PRE" -d $d -l 2 $opts "$f" >>"$T/pre.runs" && echo >>"$T/pre.runs"; }
        done
        new=$(median <"$T/new.runs") || { echo "table1 $name: dict-learn failed"; continue; }
        newwalls=${new#* walls }; new=${new% walls *}
        cp "$T/err1" "$T/err"
        # the frames kept beside the sketch: their largest rounding against
        # half the input's decimal step (what the input can represent)
        [ -z "$opts" ] && sed -n 's/.*frames [kepread]* exactly as integers of the input.s step \([^ ]*\) (largest rounding \([^ ]*\) .*/\1 \2/p; s/.*single-precision frames: largest rounding \([^ ]*\) .*/0 \1 float/p' "$T/err" |
            awk -v n="$name" '{ kind = NF == 3 ? "floats" : "int32 of the input step " $1;
                printf "kept frames %s (stream): largest rounding %.3g model units (%s) | baseline half the input step %s | ratio %.3g\n",
                    n, $2, kind, ($1 > 0 ? $1 / 2 : "-"), ($1 > 0 ? ($1 / 2) / ($2 > 0 ? $2 : 1e-300) : 0) }'
        pre="- - - - -" prewalls=-
        if [ -s "$T/pre.runs" ]; then
            pre=$(median <"$T/pre.runs") && prewalls=${pre#* walls } && pre=${pre% walls *} || pre="- - - - -"
        fi
        old="- - - - -"
        if [ -n "$OLD" ] && [ "$runold" = 1 ]; then
            old=$(timed "$OLD" -d $d -l 2 ${opts%--search 0} "$f") || old="- - - - -"
        fi
        echo "$new $pre $old" | awk -v n="$name" -v V=$V -v F=$F -v d=$d -v p=$paper -v o="${opts:-defaults}" -v rev=$OLDREV -v prev=$PREREV \
            -v nw="$newwalls" -v pw="$prewalls" -v reps=$REPS '
            function r(a, b) { return (a == "-" || b == "-" || b == 0) ? "-" : sprintf("%.2f", a / b) }
            {
            printf "table1 %s (%s v x %s f x %d pieces, lambda 2, %s; median wall of %d runs: %s against %s): %.2f s wall (%.2f s cpu, %d MB, energy %.6g; learning alone %s s wall) | baseline paper %s s (learning alone); release %s %s s wall (%s s cpu, %s MB, energy %s; learning %s s); release %s %s s wall (%s s cpu, %s MB, energy %s) | ratio paper %.1f (cpu-based %.1f; learning alone %s), release %s %s (cpu %s), release %s %s (cpu %s), energy vs %s %s\n",
                n, V, F, d, o, reps, nw, pw, $1, $2, $3, $4, $5, p, prev, $6, $7, $8, $9, $10, rev, $11, $12, $13, $14,
                p / $1, p / ($2 / 2), r(p, $5), prev, r($6, $1), r($7, $2), rev, r($11, $1), r($12, $2),
                prev, ($9 == "-" ? "-" : sprintf("%.4f", $4 / $9)) }'
    done
}
[ -s "$T/monkey.mesh" ] || "$TILE" 9971 2653 1 "$T/elephant.mesh" "$T/facecap.mesh" >"$T/monkey.mesh" || exit 1
line monkey 9971 2653 150 39 1 "$T/monkey.mesh"
[ -s "$T/bunny.mesh" ] || "$TILE" 17260 5177 2 "$T/elephant.mesh" "$T/facecap.mesh" >"$T/bunny.mesh" || exit 1
line bunny 17260 5177 200 152 "${BENCH_FULL:-0}" "$T/bunny.mesh"
rm -f "$T/bunny.mesh"    # 2.1 GB
if [ "${BENCH_FULL:-0}" = 1 ]; then
    # film scale: a 10,000-vertex part read once from a pipe (dict-tile
    # writes it; only dict-learn is timed: CPU seconds and peak RSS of its
    # process).  5,000 frames (all frames searched), 100,000 frames with
    # the defaults (restarts and search on a sample of 16,384 frames, then
    # one restart on all frames) and with --sample 0 (the search on all
    # frames, the method before --sample) in the same run; energies in the
    # sketch's coordinates (same sketch maps: same seed).  Then 5,000
    # frames held in memory (--stream off, 1.2 GB as doubles) against the
    # streamed run: what the sketch costs where both fit.
    film() { # frames tag [options]
        F=$1 tag=$2; shift 2
        "$TILE" 10000 $F 3 "$T/elephant.mesh" "$T/facecap.mesh" |
            /usr/bin/time -f "%e %U %S %M" -o "$T/time" dict-learn -v -d 50 -l 2 --report "$T/rep" "$@" >/dev/null 2>"$T/err" ||
            { echo "film $F $tag: failed"; tail -2 "$T/err"; return 1; }
        e=$(awk '/^energy /{print $2}' "$T/rep")
        l=$(sed -n 's/.*time: learn + evaluate [0-9.]* s wall, \([0-9.]*\) s cpu/\1/p' "$T/err")
        kept=$(grep -c "frames kept" "$T/err")
        awk -v F=$F -v t=$tag -v e="$e" -v l="$l" -v k=$kept '{ printf "%s %s %s %.2f %.0f %s %s %s\n", t, F, $1, $2 + $3, $4 / 1024, e, l, k }' "$T/time" >>"$T/film"
    }
    rm -f "$T/film"
    load=$(cut -d" " -f1-3 /proc/loadavg)
    film 5000 s5k --stream on && film 100000 s100k --stream on && film 100000 all100k --stream on --sample 0
    film 5000 mem5k --stream off
    awk -v load="$load" '{ t[$1] = $1; F[$1] = $2; w[$1] = $3; c[$1] = $4; m[$1] = $5; e[$1] = $6; l[$1] = $7; k[$1] = $8 }
        END {
            if (("s5k" in t) && ("s100k" in t))
                printf "film 100000 frames x 10000 v (pipe, d 50, lambda 2, defaults: sample 16384, %s): %.3f ms/frame cpu (dict-learn alone; learning %.3f), peak %d MB, energy %.6g | baseline 5000 frames (all searched, %s) %.3f ms/frame cpu (learning %.3f), peak %d MB | ratio %.2f (learning %.2f; load %s)\n",
                    (k["s100k"] ? "frames kept" : "sketch only"), c["s100k"] / 100, l["s100k"] / 100, m["s100k"], e["s100k"],
                    (k["s5k"] ? "frames kept" : "sketch only"), c["s5k"] / 5, l["s5k"] / 5, m["s5k"],
                    (c["s5k"] / 5) / (c["s100k"] / 100), (l["s5k"] / 5) / (l["s100k"] / 100), load
            if (("s100k" in t) && ("all100k" in t))
                printf "film 100000 frames, sample 16384: %.1f s cpu (learning %.1f), energy %.10g | baseline --sample 0 (search on all frames) %.1f s cpu (learning %.1f), energy %.10g | ratio cpu %.2f, energy %.5f\n",
                    c["s100k"], l["s100k"], e["s100k"], c["all100k"], l["all100k"], e["all100k"], c["all100k"] / c["s100k"], e["s100k"] / e["all100k"]
            if (("s5k" in t) && ("mem5k" in t))
                printf "film 5000 frames streamed (sketch rank 128): energy %.10g, %.1f s cpu, peak %d MB | baseline in memory (--stream off) energy %.10g, %.1f s cpu, peak %d MB | ratio energy %.6f\n",
                    e["s5k"], c["s5k"], m["s5k"], e["mem5k"], c["mem5k"], m["mem5k"], e["s5k"] / e["mem5k"]
        }' "$T/film"
    rm -f "$T/film"
fi
# OpenBLAS kernel: Debian's 0.3.21 falls back to Prescott on this CPU; dict-learn
# re-executes itself with OPENBLAS_CORETYPE set (libcommon/blas_tune.h)
B=$ROOT/build/bench/dict-bench
if [ -x "$B" ]; then
    t1=$(STOPMO_BLAS_TUNE=0 DICT_BENCH_FULLRANK=1 "$B" 9585 1200 50 1 20 1 | awk -F'[ =]' '/^blas=/{for(i=1;i<NF;i++) if($i=="cpu_s") print $(i+1)}')
    t2=$(DICT_BENCH_FULLRANK=1 "$B" 9585 1200 50 1 20 1 | awk -F'[ =]' '/^blas=/{for(i=1;i<NF;i++) if($i=="cpu_s") print $(i+1)}')
    core=$("$B" 30 10 2 1 1 1 | sed -n 's/^blas=\([^ ]*\).*/\1/p')
    echo "openblas kernel, full DSYRK (9585 v x 1200 f x 50): $core $t2 s cpu | baseline Prescott $t1 s cpu | ratio $(awk -v a="$t1" -v b="$t2" 'BEGIN{printf "%.2f", a/b}')"
fi
