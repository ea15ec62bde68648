#!/bin/sh
test_description='compat-tri refinement coarsens: on the six shared elephant poses the final edge collapses keep every triangle at 20 degrees or better with fewer vertices'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"
need_shared_data shapes2d/poses/elephant-pose6.rings.txt
P="$SHARED_DATA/shapes2d/poses"

test_expect_success 'six elephant poses, -m off (as t0571: poses 4 and 5 are mirrored views): worst angle >= 19.99 deg with <= 1000 vertices (measured 20.01, 933; split-only before: 20.01, 1150)' '
	compat-tri -m off -v -c "$STOPMO_ROOT/examples/morph2d/corr6.txt" $P/elephant-pose1.rings.txt $P/elephant-pose2.rings.txt \
		$P/elephant-pose3.rings.txt $P/elephant-pose4.rings.txt $P/elephant-pose5.rings.txt \
		$P/elephant-pose6.rings.txt >e6.mesh 2>e6.log &&
	test_le 1e-12 $(min_area e6.mesh) &&
	test_le 19.99 $(worst_angle e6.mesh) &&
	test $(under_share e6.mesh 20) = 0.0 &&
	test_le $(mesh_vertices e6.mesh) 1000
'
test_expect_success '-v counts the collapses and reports no stop below the goal' '
	grep "refinement: .* [1-9][0-9]* collapses ([1-9][0-9]* coarsening)" e6.log &&
	! grep "refinement stopped" e6.log
'
test_expect_success 'the correspondence points are mesh vertices exactly on their input points' '
	for k in 1 2 3 4 5 6; do
		grep -v "^#" "$STOPMO_ROOT/examples/morph2d/corr6.txt" | cut -d" " -f$k >idx$k &&
		awk -v fr=$k "NR == FNR { if (FNR > 1) { x[FNR - 2] = \$1; y[FNR - 2] = \$2 } next }
			\$1 == \"frame\" { f++; i = 0; next }
			f == fr && NF == 3 { X[i] = \$1; Y[i] = \$2; i++ }
			END { while ((getline v < \"idx$k\") > 0) { ok = 0; for (j in X) if (X[j] == x[v] && Y[j] == y[v]) ok = 1; if (!ok) { print \"point \" v \" of pose $k is not a vertex\"; exit 1 } } }" \
			$P/elephant-pose$k.rings.txt e6.mesh || return 1
	done
'
test_expect_success '--threads 1 and 2 give the same bytes (the poses are smoothed independently)' '
	compat-tri -m off --threads 1 -c "$STOPMO_ROOT/examples/morph2d/corr6.txt" $P/elephant-pose1.rings.txt $P/elephant-pose2.rings.txt \
		$P/elephant-pose3.rings.txt $P/elephant-pose4.rings.txt $P/elephant-pose5.rings.txt \
		$P/elephant-pose6.rings.txt >t1.mesh &&
	compat-tri -m off --threads 2 -c "$STOPMO_ROOT/examples/morph2d/corr6.txt" $P/elephant-pose1.rings.txt $P/elephant-pose2.rings.txt \
		$P/elephant-pose3.rings.txt $P/elephant-pose4.rings.txt $P/elephant-pose5.rings.txt \
		$P/elephant-pose6.rings.txt >t2.mesh &&
	cmp t1.mesh t2.mesh && cmp t1.mesh e6.mesh
'
test_expect_success 'bad --threads is a usage error' '
	test_must_fail_usage compat-tri --threads -1 $P/elephant-pose1.rings.txt $P/elephant-pose2.rings.txt >o.mesh 2>err &&
	test ! -s o.mesh && grep "threads" err
'
test_done
