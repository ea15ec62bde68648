#!/bin/sh
# b-morph2d.sh -- N-way 2D morphing (compat-tri, arap-morph).
#
# compat-tri wall time against the number of shapes N and the outline size
# (generated wobbly ellipses, 5 correspondence points; baseline: N = 2 at the
# same outline size, measured in the same run), and on the elephant poses of
# ../shared/data (N = 2, 3, 4; baseline N = 2).
# arap-morph blending rate on a 2k-triangle mesh (a 40 x 25 bar and the bar
# bent by 90 degrees with its thickness squashed, 2000 weight rows along a
# path that extrapolates): frames/s of the blending alone (arap-morph -v,
# output formatting excluded) and with output, against linear blending
# (--linear) in the same run.  Goal: > 100 frames/s.
set -u
ROOT=${ROOT:-$(cd "$(dirname "$0")/.." && pwd)}
PATH="$ROOT/bin:$PATH"
T=${BENCH_TMP:-$ROOT/build/bench-tmp}/morph2d
mkdir -p "$T"
DATA=${STOPMO_SHARED_DATA:-$ROOT/../shared/data}

now() { date +%s.%N; }

shape() { # n seed -> ring of n points: ellipse with a seeded wobble
	awk -v n="$1" -v s="$2" 'BEGIN { print "ring " n;
		a = 1 + 0.3 * sin(s); b = 0.7 + 0.2 * cos(3 * s);
		for (i = 0; i < n; i++) { t = 6.283185307179586 * i / n;
			r = 1 + 0.15 * sin(3 * t + s) + 0.1 * sin(5 * t - 2 * s);
			printf "%.9g %.9g\n", a * r * cos(t), b * r * sin(t) } }'
}

CT_OPTS=""
ct_time() { # N n -> seconds for compat-tri on N generated shapes of n points
	files=""
	for k in $(seq 1 "$1"); do shape "$2" "$k" >"$T/s$k-$2.rings"; files="$files $T/s$k-$2.rings"; done
	awk -v N="$1" -v n="$2" 'BEGIN { for (c = 0; c < 5; c++) { line = "";
		for (k = 0; k < N; k++) line = line (k ? " " : "") int(c * n / 5); print line } }' >"$T/corr-$1-$2.txt"
	t0=$(now)
	compat-tri -v $CT_OPTS -c "$T/corr-$1-$2.txt" $files >"$T/ct.mesh" 2>"$T/ct.log" || { echo "compat-tri failed" >&2; cat "$T/ct.log" >&2; return 1; }
	t1=$(now)
	awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }'
	sed -n 's/.*result: \([0-9]*\) vertices.* \([0-9]*\) triangles, min angle \([0-9.]*\) deg.*/ (\1 vertices, \2 triangles, min angle \3 deg/p' "$T/ct.log" | tr -d '\n'
	sed -n 's/.*triangulation: .*, \([0-9]*\) Steiner points.*/, \1 Steiner)/p' "$T/ct.log"
}

for n in 100 200 400; do
	base=$(ct_time 2 $n) || exit 1
	bt=${base%% *}
	for N in 4 8; do
		r=$(ct_time $N $n) || exit 1
		rt=${r%% *}
		echo "compat-tri N=$N, $n-point outlines: $r s | baseline N=2: $base s | ratio $(awk -v a="$rt" -v b="$bt" 'BEGIN { printf "%.2f", a / (b > 0 ? b : 1e-3) }')"
	done
done

# without simplification and refinement (-e 0 -l 0): the stage I-III cost
# against the outline size itself (baseline: 100-point outlines)
CT_OPTS="-e 0 -l 0 -s 0"
# (about n^3: 400-point outlines take ~40 s, left out)
b100=$(ct_time 4 100) || exit 1
for n in 200; do
	r=$(ct_time 4 $n) || exit 1
	echo "compat-tri -e 0 -l 0, N=4, $n-point outlines: $r s | baseline 100-point outlines: $b100 s | ratio $(awk -v a="${r%% *}" -v b="${b100%% *}" 'BEGIN { printf "%.2f", a / (b > 0 ? b : 1e-3) }')"
done
CT_OPTS=""

P="$DATA/shapes2d/poses"
if [ -e "$P/elephant-pose6.rings.txt" ]; then
	C="$ROOT/examples/morph2d/corr4.txt"
	el() { # columns... -> seconds
		cut_cols=$(echo "$@" | tr ' ' ',')
		grep -v '^#' "$C" | cut -d' ' -f"$cut_cols" >"$T/ecorr.txt"
		files=""
		for c in "$@"; do files="$files $P/elephant-pose$(echo 1 2 3 6 | cut -d' ' -f$c).rings.txt"; done
		t0=$(now)
		compat-tri -v -c "$T/ecorr.txt" $files >"$T/e.mesh" 2>"$T/e.log" || return 1
		t1=$(now)
		awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.3f", b - a }'
		sed -n 's/.*triangulation: .*, \([0-9]*\) Steiner points.*/ (\1 Steiner/p' "$T/e.log" | tr -d '\n'
		sed -n 's/.*result: \([0-9]*\) vertices.* \([0-9]*\) triangles, min angle \([0-9.]*\) deg.*/, \2 triangles, min angle \3 deg)/p' "$T/e.log"
	}
	b2=$(el 1 2) || exit 1
	for cols in "1 2 3" "1 2 3 4"; do
		r=$(el $cols) || exit 1
		N=$(echo $cols | wc -w)
		echo "compat-tri elephant N=$N: $r s | baseline N=2: $b2 s | ratio $(awk -v a="${r%% *}" -v b="${b2%% *}" 'BEGIN { printf "%.2f", a / b }')"
	done
else
	echo "compat-tri elephant: skipped (no $P)"
fi

# arap-morph on a 2k-triangle mesh
mesh-gen -n 40 -m 25 grid | awk -v th=1.5707963 -v sq=0.5 '
	/^frames /{ print "frames 2"; next }
	/^frame /{ print "frame 0"; inframe = 1; next }
	inframe && NF == 3 { X[n] = $1 * 4; Y[n] = $2 * 0.5; printf "%.17g %.17g 0\n", X[n], Y[n]; n++; next }
	{ print }
	END { print "frame 1"; r = 4 / th;
	      for (i = 0; i < n; i++) printf "%.17g %.17g 0\n", (r - sq * Y[i]) * sin(X[i] / r), r - (r - sq * Y[i]) * cos(X[i] / r) }' >"$T/bar.mesh"
awk 'BEGIN { for (k = 0; k < 2000; k++) { t = -0.5 + 2 * k / 1999; print 1 - t, t } }' >"$T/bar.w"
rate() { # mode -> "blend_fps total_fps"
	t0=$(now)
	arap-morph -v $1 "$T/bar.mesh" "$T/bar.w" >"$T/out.mesh" 2>"$T/am.log" || return 1
	t1=$(now)
	f=$(sed -n 's/.*= \([0-9.]*\) frames\/s.*/\1/p' "$T/am.log")
	inv=$(sed -n 's/.*inverted triangles: \([0-9]*\) in \([0-9]*\) of.*/\1 inverted in \2 frames/p' "$T/am.log")
	tri=$(sed -n 's/.* \([0-9]*\) triangles,.*/\1/p' "$T/am.log")
	awk -v f="$f" -v a="$t0" -v b="$t1" -v inv="$inv" -v tri="$tri" 'BEGIN { printf "%.0f %.0f %s triangles, %s\n", f, 2000 / (b - a), tri, inv }'
}
a=$(rate -l) || exit 1
l=$(rate --linear) || exit 1
set -- $a; af=$1; at=$2; ainfo="$3 $4 $5 $6 $7 $8 $9"
set -- $l; lf=$1; lt=$2; linfo="$5 $6 $7 $8 $9"
echo "arap-morph -l blending ($ainfo): $af frames/s | baseline linear blending: $lf frames/s ($linfo) | ratio $(awk -v a="$af" -v b="$lf" 'BEGIN { printf "%.3f", a / b }')"
echo "arap-morph -l with MESH output: $at frames/s | baseline linear with output: $lt frames/s | ratio $(awk -v a="$at" -v b="$lt" 'BEGIN { printf "%.3f", a / b }')"
echo "arap-morph -l blending vs goal: $af frames/s | baseline goal 100 frames/s | ratio $(awk -v a="$af" 'BEGIN { printf "%.1f", a / 100 }')"
