#!/bin/sh
# b-compat-quality.sh -- compat-tri's triangle quality and speed.
#
# 1. Each single pose (the shared elephant poses and the made-up creature of
#    tests/t0511-creature.awk): compat-tri --refine refine -e 0 (every input
#    point kept, so both mesh the same polygon) against CGAL's 2D Delaunay
#    mesher (refine_Delaunay_mesh_2, shape bound 0.125 = about 20.7 degrees,
#    build/bench/poly-mesh) in the same run: worst angle and vertex count as
#    ratios to CGAL's.
# 2. N poses: worst angle over every triangle of every pose for --refine
#    refine against --refine sg (the same without MIPS smoothing and edge
#    collapses: the paper's local smoothing) and --refine none (the old
#    output).
# 3. Time for six poses (elephant: 120-138 input points per pose; creature:
#    ~280), wall seconds (the refinement smooths the poses on one thread per
#    core, --threads) and CPU seconds, against the goal of 1 s.
# 4-6. Traced walk frames, the stick characters (whole and layered) and
#    layers traced from the elephant walk: see each section below.
set -u
ROOT=${ROOT:-$(cd "$(dirname "$0")/.." && pwd)}
PATH="$ROOT/bin:$ROOT/build/bench:$PATH"
T=${BENCH_TMP:-$ROOT/build/bench-tmp}/compat-quality
mkdir -p "$T"
DATA=${STOPMO_SHARED_DATA:-$ROOT/../shared/data}

for k in 0 1 2 3 4 5; do
	awk -v pose=$k -v tips="$T/tips$k" -f "$ROOT/tests/t0511-creature.awk" >"$T/creature$k.rings" || exit 1
done
cat "$T"/tips0 "$T"/tips1 "$T"/tips2 "$T"/tips3 "$T"/tips4 "$T"/tips5 |
	awk '{ for (i = 1; i <= NF; i++) r[i] = r[i] " " $i } END { for (i = 1; i <= 5; i++) print substr(r[i], 2) }' >"$T/creature.corr"

# ct LOG -> "worst vertices" from compat-tri -v
ct_stats() { sed -n 's/.*result: \([0-9]*\) vertices.*min angle \([0-9.]*\) deg.*/\2 \1/p' "$1"; }
cpu() { # LOG command... -> CPU seconds (user + sys) of the command (stderr to LOG); wall seconds in $T/wall
	log=$1; shift
	/usr/bin/time -f "%U %S %e" -o "$T/time" "$@" >/dev/null 2>"$log" || return 1
	awk '{ printf "%.3f", $3 }' "$T/time" >"$T/wall"
	awk '{ printf "%.3f", $1 + $2 }' "$T/time"
}

one_pose() { # NAME RING COL CORR
	name=$1 ring=$2 col=$3 corr=$4
	set -- $(poly-mesh "$ring") || return 1
	cv=$2 ca=$6
	grep -v '^#' "$corr" | cut -d' ' -f"$col" >"$T/one.corr"
	compat-tri -v -e 0 -c "$T/one.corr" "$ring" >/dev/null 2>"$T/one.log" || return 1
	set -- $(ct_stats "$T/one.log")
	echo "compat-tri worst angle, $name alone: $1 deg | baseline CGAL mesher 0.125: $ca deg | ratio $(awk -v a="$1" -v b="$ca" 'BEGIN { printf "%.2f", a / b }')"
	echo "compat-tri vertices, $name alone: $2 | baseline CGAL mesher 0.125: $cv | ratio $(awk -v a="$2" -v b="$cv" 'BEGIN { printf "%.2f", a / b }')"
}

P="$DATA/shapes2d/poses"
have_elephant=0
[ -e "$P/elephant-pose6.rings.txt" ] && have_elephant=1
C6="$ROOT/examples/morph2d/corr6.txt"
for k in 1 2 3 4 5 6; do
	if [ $have_elephant = 1 ]; then one_pose "elephant pose $k" "$P/elephant-pose$k.rings.txt" $k "$C6" || exit 1; fi
done
[ $have_elephant = 1 ] || echo "compat-tri elephant: skipped (no $P)"
for k in 0 1 2; do
	one_pose "creature pose $k" "$T/creature$k.rings" $((k + 1)) "$T/creature.corr" || exit 1
done

multi() { # NAME CORR RING... : worst angle of refine vs sg (old smoothing) and none, CPU time
	name=$1 corr=$2; shift 2
	tn=$(cpu "$T/n.log" compat-tri -v --refine none -c "$corr" "$@") || return 1
	ts=$(cpu "$T/s.log" compat-tri -v --refine sg -c "$corr" "$@") || return 1
	tr=$(cpu "$T/r.log" compat-tri -v --refine refine -c "$corr" "$@") || return 1
	wr=$(cat "$T/wall")
	set -- $(ct_stats "$T/n.log"); an=$1 vn=$2
	set -- $(ct_stats "$T/s.log"); as=$1 vs=$2
	set -- $(ct_stats "$T/r.log"); ar=$1 vr=$2
	ur=$(sed -n 's/.*pose [0-9]* .*, \([0-9.]*\)% under 20.*/\1/p' "$T/r.log" | sort -n | tail -1)
	echo "compat-tri --refine refine, $name: worst $ar deg ($vr vertices, up to $ur% of a pose's triangles under 20 deg, $tr s CPU) | baseline --refine sg: $as deg ($vs vertices, $ts s CPU) | ratio $(awk -v a="$ar" -v b="$as" 'BEGIN { printf "%.1f", a / (b > 0 ? b : 0.01) }')"
	echo "compat-tri --refine refine, $name: worst $ar deg | baseline --refine none: $an deg ($vn vertices, $tn s CPU) | ratio $(awk -v a="$ar" -v b="$an" 'BEGIN { printf "%.1f", a / (b > 0 ? b : 0.01) }')"
	echo "compat-tri --refine refine time, $name: $wr s wall ($tr s CPU, load $(cut -d' ' -f1 /proc/loadavg)) | baseline goal: 1 s | ratio $(awk -v a="$wr" 'BEGIN { printf "%.2f", a }')"
}

if [ $have_elephant = 1 ]; then
	for cols in 1,2 3,5,6 1,2,3,4,5,6; do
		grep -v '^#' "$C6" | cut -d' ' -f$cols >"$T/e.corr"
		files=
		for k in $(echo $cols | tr , ' '); do files="$files $P/elephant-pose$k.rings.txt"; done
		multi "elephant poses $cols" "$T/e.corr" $files || exit 1
	done
fi
for cols in 1,2 1,2,3 1,2,3,4,5,6; do
	cut -d' ' -f$cols "$T/creature.corr" >"$T/c.corr"
	files=
	for k in $(echo $cols | tr , ' '); do files="$files $T/creature$((k - 1)).rings"; done
	multi "creature poses $cols" "$T/c.corr" $files || exit 1
done

# 4. Six frames of the shared elephant walk rendered and traced (no point
#    given: the automatic boundary matching places them), default options:
#    wall and CPU against 1 s.  From the side (frames 0-350, 79-124 outline
#    points) and from a three-quarter view (azimuth 60, elevation 15; frames
#    20-370, 88-118 points), where the legs and the trunk overlap the body
#    differently in every frame.  The side view also at 600 by 600 pixels
#    (157-235 outline points per pose, 198 after simplification: the
#    goal's six poses of about 200 points).
W="$DATA/anim/elephant-walk-457.tar.xz"
walk() { # NAME "FRAMES" SIZE mesh-render view options...
	name=$1 frames=$2 size=$3; shift 3
	wf=
	for k in $frames; do
		tar -xJf "$W" -C "$T" elephant/frame_$k.obj || return 1
		mesh-import "$T/elephant/frame_$k.obj" | mesh-render "$@" -s ${size}x$size -c 0,0,0 --flat -f ppm >"$T/w$k.ppm" &&
			img2rings -1 -s 1 -o "$T/w$k-$size.rings" "$T/w$k.ppm" || return 1
		wf="$wf $T/w$k-$size.rings"
	done
	tw=$(cpu "$T/w.log" compat-tri -v $wf) || return 1
	set -- $(ct_stats "$T/w.log")
	echo "compat-tri default, six traced elephant walk frames, $name (automatic matching): $(cat "$T/wall") s wall ($tw s CPU, worst $1 deg, $2 vertices, load $(cut -d' ' -f1 /proc/loadavg)) | baseline goal: 1 s | ratio $(awk -v a="$(cat "$T/wall")" 'BEGIN { printf "%.2f", a }')"
}
if [ -e "$W" ]; then
	walk "side view" "0000 0070 0140 0210 0280 0350" 300 -V right || exit 1
	walk "side view at 600 pixels" "0000 0070 0140 0210 0280 0350" 600 -V right || exit 1
	walk "three-quarter view" "0020 0090 0160 0230 0300 0370" 300 -a 60 -e 15 || exit 1
else
	echo "compat-tri traced walk: skipped (no $W)"
fi

# 5. The stretched characters of tests/t0587-stick-character.awk (a horse
#    and a flamingo whose thin legs, neck and tail bend from pose to pose;
#    traced by img2rings, 70-132 outline points per pose), all six poses
#    with the five given rows of the tests (feet, head, neck, tail), default
#    options: wall and CPU against 1 s, and the worst angle.  The horse
#    reaches 20 degrees; the flamingo does not (its pose 0 hides a leg in a
#    slit, compat-tri(1) BUGS).  Then the same poses with leg 0 drawn as a
#    layer of its own (--layers), against the whole silhouettes.
TEST_DIRECTORY="$ROOT/tests"
. "$ROOT/tests/morph2d-lib.sh"
mkdir -p "$T/stick"
for ch in horse flamingo; do
	(cd "$T/stick" && stick_poses $ch 0 1 2 3 4 5 && stick_rows $ch 0 1 2 3 4 5 >$ch.corr) || exit 1
	tw=$(cpu "$T/k.log" compat-tri -v -c "$T/stick/$ch.corr" "$T/stick/${ch}0.rings" "$T/stick/${ch}1.rings" \
		"$T/stick/${ch}2.rings" "$T/stick/${ch}3.rings" "$T/stick/${ch}4.rings" "$T/stick/${ch}5.rings") || exit 1
	set -- $(ct_stats "$T/k.log")
	echo "compat-tri default, six stick-$ch poses (t0587, five rows): $(cat "$T/wall") s wall ($tw s CPU, worst $1 deg, $2 vertices, load $(cut -d' ' -f1 /proc/loadavg)) | baseline goal: 1 s | ratio $(awk -v a="$(cat "$T/wall")" 'BEGIN { printf "%.2f", a }')"
	# the same six poses drawn as two layers (compat-tri --layers): the
	# body without leg 0, and that leg; the five rows less the leg's
	wall0=$(cat "$T/wall") q0=$1
	leg=hoof0; [ $ch = flamingo ] && leg=toe0
	(cd "$T/stick" && for k in 0 1 2 3 4 5; do stick_layer_pose $ch $k $leg || exit 1; done &&
		paste -d" " rows50 rows51 rows52 rows53 rows54 rows55 >$ch-layers.corr) || exit 1
	tw=$(cpu "$T/k.log" compat-tri -v --layers -c "$T/stick/$ch-layers.corr" "$T/stick/layers0.rings" \
		"$T/stick/layers1.rings" "$T/stick/layers2.rings" "$T/stick/layers3.rings" "$T/stick/layers4.rings" \
		"$T/stick/layers5.rings") || exit 1
	set -- $(ct_stats "$T/k.log")
	echo "compat-tri --layers worst angle, six stick-$ch poses, leg 0 a layer (four rows): $1 deg ($2 vertices) | baseline the whole silhouettes (five rows): $q0 deg | ratio $(awk -v a="$1" -v b="$q0" 'BEGIN { printf "%.2f", a / b }')"
	echo "compat-tri --layers time, six stick-$ch poses, leg 0 a layer (four rows): $(cat "$T/wall") s wall ($tw s CPU) | baseline the whole silhouettes: $wall0 s | ratio $(awk -v a="$(cat "$T/wall")" -v b="$wall0" 'BEGIN { printf "%.3f", a / b }')"
	# each layer meshed on its own (the default) against one joint
	# matching and refinement of both rings (--layers=joint)
	wl=$(cat "$T/wall") ql=$1
	tj=$(cpu "$T/k.log" compat-tri -v --layers=joint -c "$T/stick/$ch-layers.corr" "$T/stick/layers0.rings" \
		"$T/stick/layers1.rings" "$T/stick/layers2.rings" "$T/stick/layers3.rings" "$T/stick/layers4.rings" \
		"$T/stick/layers5.rings") || exit 1
	set -- $(ct_stats "$T/k.log")
	echo "compat-tri --layers (each) worst angle, six stick-$ch poses (four rows): $ql deg | baseline --layers=joint: $1 deg ($2 vertices) | ratio $(awk -v a="$ql" -v b="$1" 'BEGIN { printf "%.2f", a / b }')"
	echo "compat-tri --layers (each) time, six stick-$ch poses (four rows): $wl s wall | baseline --layers=joint: $(cat "$T/wall") s ($tj s CPU) | ratio $(awk -v a="$wl" -v b="$(cat "$T/wall")" 'BEGIN { printf "%.3f", a / b }')"
done

# 6. Layers traced from a 3D animation (tests/t0607): the shared elephant
#    walk seen from the left, its left arm a layer (elephant_arm_layers:
#    the arm's faces drawn with mesh-render --only), six frames without
#    rows.  Each layer meshed on its own against the two rings meshed
#    jointly, and the wall time against the whole silhouettes.
if [ -e "$W" ]; then
	mkdir -p "$T/arm"
	(cd "$T/arm" && SHARED_DATA=$DATA && elephant_walk_frames 0000 0070 0140 0210 0280 0350 &&
		elephant_arm_layers 0000 0070 0140 0210 0280 0350 &&
		for k in 0000 0070 0140 0210 0280 0350; do
			mesh-render -V left -s 300x300 -c 0,0,0 --flat -f ppm e$k.mesh | img2rings -1 -s 1 -o whole$k.rings || exit 1
		done) || exit 1
	lay= whole=
	for k in 0000 0070 0140 0210 0280 0350; do lay="$lay $T/arm/lay$k.rings" whole="$whole $T/arm/whole$k.rings"; done
	te=$(cpu "$T/a.log" compat-tri -v --layers $lay) || exit 1
	set -- $(ct_stats "$T/a.log"); qe=$1 we=$(cat "$T/wall")
	tj=$(cpu "$T/a.log" compat-tri -v --layers=joint $lay) || exit 1
	set -- $(ct_stats "$T/a.log"); qj=$1 wj=$(cat "$T/wall")
	tw=$(cpu "$T/a.log" compat-tri -v $whole) || exit 1
	set -- $(ct_stats "$T/a.log"); qw=$1 ww=$(cat "$T/wall")
	echo "compat-tri --layers (each) worst angle, six traced elephant walk frames, left arm a layer: $qe deg | baseline --layers=joint: $qj deg | ratio $(awk -v a="$qe" -v b="$qj" 'BEGIN { printf "%.2f", a / b }')"
	echo "compat-tri --layers (each) time, six traced elephant walk frames, left arm a layer: $we s wall ($te s CPU) | baseline the whole silhouettes: $ww s ($tw s CPU, $qw deg) | ratio $(awk -v a="$we" -v b="$ww" 'BEGIN { printf "%.2f", a / b }')"
else
	echo "compat-tri traced layers: skipped (no $W)"
fi
