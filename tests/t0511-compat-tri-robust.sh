#!/bin/sh
test_description='compat-tri: every subset of 2..6 poses, outline kept, order and orientation detected'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

# check a plain MESH stream of N frames against the input rings:
# every triangle positive in every frame (> 0, exactly as printed), and
# every correspondence point (rows of CORR) a vertex at its input position
check_mesh() {   # check_mesh MESH CORR RING...
	cm_mesh=$1 cm_corr=$2; shift 2
	awk -v nr=$# 'BEGIN { ri = -1 } FILENAME == ARGV[1] {
		if ($1 == "f") { F[nf++] = $2 " " $3 " " $4; next }
		if ($1 == "frame") { fr = $2; k = 0; next }
		if (fr != "" && NF == 3) { X[fr, k] = $1; Y[fr, k] = $2; k++ }
		next }
	FILENAME == ARGV[2] { for (s = 0; s < NF; s++) C[FNR - 1, s] = $(s + 1); nc = FNR; next }
	FNR == 1 { ri++ }
	{ if ($1 == "ring") { pi = 0; next }
	  PX[ri, pi] = $1; PY[ri, pi] = $2; pi++ }
	END { bad = 0
		for (s = 0; s < nr; s++) for (t = 0; t < nf; t++) { split(F[t], v, " ")
			a = (X[s,v[2]]-X[s,v[1]])*(Y[s,v[3]]-Y[s,v[1]]) - (Y[s,v[2]]-Y[s,v[1]])*(X[s,v[3]]-X[s,v[1]])
			if (!(a > 0)) { print "frame " s ": triangle " t " has area " a; bad = 1 } }
		for (s = 0; s < nr; s++) for (c = 0; c < nc; c++) { i = C[c, s]; found = 0
			for (w = 0; (s, w) in X; w++) if (X[s, w] == PX[s, i] && Y[s, w] == PY[s, i]) found = 1
			if (!found) { print "shape " s ": correspondence " c " (vertex " i ") is not a mesh vertex"; bad = 1 } }
		exit bad }' "$cm_mesh" "$cm_corr" "$@"
}

# every subset of >= 2 of the N shapes: columns of CORR, compat-tri, check
all_subsets() {  # all_subsets CORR RING...
	corr=$1; shift
	n=$# ok=0 tot=0 mask=3
	while [ $mask -lt $((1 << n)) ]; do
		cols= files= i=0
		for f in "$@"; do
			if [ $(((mask >> i) & 1)) = 1 ]; then cols="$cols,$((i + 1))"; files="$files $f"; fi
			i=$((i + 1))
		done
		case $cols in ,*,*)
			tot=$((tot + 1))
			grep -v '^#' "$corr" | cut -d' ' -f"${cols#,}" >sub.corr
			if compat-tri --refine none -l 0 -s 0 -c sub.corr $files >sub.mesh 2>sub.err &&
			   check_mesh sub.mesh sub.corr $files >sub.check; then ok=$((ok + 1))
			else echo "subset $cols: $(cat sub.err sub.check | head -2)" >&2; fi ;;
		esac
		mask=$((mask + 1))
	done
	echo "$ok of $tot"
}

test_expect_success 'setup: six poses of a made-up character, five limb tips as correspondences' '
	creature_poses &&
	test $(wc -l <corr.txt) = 5
'
test_expect_success 'every subset of 2..6 poses is triangulated compatibly, correspondences exact' '
	all_subsets corr.txt p0.rings p1.rings p2.rings p3.rings p4.rings p5.rings >result &&
	echo "57 of 57" >expect && test_cmp expect result
'
test_expect_success 'all six with refinement and smoothing: still positive everywhere' '
	compat-tri -v -c corr.txt p0.rings p1.rings p2.rings p3.rings p4.rings p5.rings >all.mesh 2>log &&
	check_mesh all.mesh corr.txt p0.rings p1.rings p2.rings p3.rings p4.rings p5.rings
'
# "largest two-sided Hausdorff distance X" from -v
hausdorff() { sed -n "s/.*Hausdorff distance \([0-9.e+-]*\).*/\1/p" "$1"; }
test_expect_success 'the simplified outline stays within the tolerance (default 0.5% of the diagonal)' '
	h=$(hausdorff log) && test -n "$h" && test_le "$h" 0.005 &&
	cut -d" " -f1,4,6 corr.txt >c035 &&
	compat-tri -v -e 0.02 -c c035 p0.rings p3.rings p5.rings 2>log2 >/dev/null &&
	h2=$(hausdorff log2) && test_le "$h2" 0.02 &&
	compat-tri -v -e 0.001 -l 0 -s 0 -c c035 p0.rings p3.rings p5.rings 2>log1 >e1.mesh &&
	test_le "$(hausdorff log1)" 0.001 &&
	check_mesh e1.mesh c035 p0.rings p3.rings p5.rings
'
test_expect_success 'correspondences listed in the reverse cyclic order: same mesh' '
	cut -d" " -f1,2,3 corr.txt >c3 && tac c3 >c3rev &&
	compat-tri -c c3 p0.rings p1.rings p2.rings >fwd.mesh &&
	compat-tri -v -c c3rev p0.rings p1.rings p2.rings >rev.mesh 2>revlog &&
	grep -q "reverse order" revlog && test_cmp fwd.mesh rev.mesh
'
test_expect_success 'a clockwise ring (indices in its file order) is accepted' '
	n=$(sed -n "s/ring //p" p1.rings) &&
	{ echo "ring $n"; sed 1d p1.rings | tac; } >p1cw.rings &&
	awk -v n=$n "{ print \$1, n - 1 - \$2, \$3 }" c3 >c3cw &&
	compat-tri -c c3cw p0.rings p1cw.rings p2.rings >cw.mesh &&
	check_mesh cw.mesh c3 p0.rings p1.rings p2.rings
'
test_expect_success 'shapes whose points run in opposite directions: one-line error' '
	awk -v n=$(sed -n "s/ring //p" p1.rings) "{ print \$1, (n - \$2) % n, \$3 }" c3 >c3mixed &&
	test_fails_cleanly compat-tri -c c3mixed p0.rings p1.rings p2.rings && grep -q "other way round" .err
'
test_expect_success 'a zero-area outline: "degenerate outline"' '
	printf "ring 4\n0 0\n1 0\n3 0\n2 0\n" >flat.rings && printf "0 0\n1 1\n2 2\n" >cf &&
	test_fails_cleanly compat-tri -c cf p0.rings flat.rings && grep -q "degenerate outline" .err
'
test_expect_success 'the paper-style link paths stay available (--split linkpath)' '
	compat-tri --split linkpath -c c3 p0.rings p1.rings p2.rings >lp.mesh &&
	check_mesh lp.mesh c3 p0.rings p1.rings p2.rings
'
test_expect_success 'the overlay of the fewest crossings (--split overlay-fewest): a valid mesh, no more Steiner points before refinement' '
	compat-tri -v --split overlay-fewest -c c3 p0.rings p1.rings p2.rings >of.mesh 2>of.log &&
	check_mesh of.mesh c3 p0.rings p1.rings p2.rings &&
	compat-tri -v -c c3 p0.rings p1.rings p2.rings >od.mesh 2>od.log &&
	nf=$(sed -n "s/.*triangulation: [0-9]* triangles, \([0-9]*\) Steiner.*/\1/p" of.log) &&
	nd=$(sed -n "s/.*triangulation: [0-9]* triangles, \([0-9]*\) Steiner.*/\1/p" od.log) &&
	echo "Steiner points: $nf fewest, $nd Delaunay" && test "$nf" -le "$nd"
'
test_expect_success 'an unknown --split mode: usage error naming the modes' '
	test_must_fail_usage compat-tri --split fewest -c c3 p0.rings p1.rings p2.rings >/dev/null 2>err &&
	grep -q "overlay-fewest" err
'
test_done
