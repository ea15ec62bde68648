#!/bin/sh
test_description='seam-homog: still geometry stays still (band model), the seam is identical in every frame'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/seam-lib.sh"
. "$TEST_DIRECTORY/drift-lib.sh"

test_expect_success 'setup: the demo head, cut by the demo seeds, seams smoothed' '
	head-gen -f 48 -s 3 >head.mesh &&
	seg-graphcut --seeds "$STOPMO_ROOT/examples/stopshop/head.seeds" head.mesh >parts &&
	seam-smooth -l parts -L smooth.lab -o smooth.mesh head.mesh
'

test_expect_success 'band (default): still vertices move < 0.5% of the diagonal, mean < 0.1%' '
	seam-homog -v -l smooth.lab --report rep smooth.mesh >band.mesh 2>err &&
	cat err rep && grep -q "^model band$" rep &&
	d=$(fixed_drift band.mesh smooth.lab) && echo "seam drift $d" && test "$d" = 0 &&
	set -- $(drift smooth.mesh band.mesh) && echo "still $1, still max $2, mean $3, max $4" &&
	test $1 -gt 100 && test_le "$2" 0.005 && test_le "$3" 0.001 &&
	test_near "$(awk "\$1 == \"still_max_change\" { print \$2 }" rep)" "$2" 1e-5 &&
	test_near "$(awk "\$1 == \"mean_change\" { print \$2 }" rep)" "$3" 1e-5
'

test_expect_success 'the paper model (Eq. 4-9 over the whole part) moves still geometry more' '
	seam-homog -m paper -l smooth.lab --report prep smooth.mesh >paper.mesh &&
	grep -q "^model paper$" prep &&
	d=$(fixed_drift paper.mesh smooth.lab) && test "$d" = 0 &&
	set -- $(drift smooth.mesh band.mesh) && band_still=$2 band_mean=$3 &&
	set -- $(drift smooth.mesh paper.mesh) && echo "paper: still max $2, mean $3 (band $band_still, $band_mean)" &&
	test_le "$band_still" "$2" && test_le "$band_mean" "$3"
'

test_expect_success 'a wider band moves more, a band of the whole mesh is the paper model' '
	seam-homog -w 0.3 -l smooth.lab smooth.mesh >wide.mesh &&
	set -- $(drift smooth.mesh wide.mesh) && wide_mean=$3 &&
	set -- $(drift smooth.mesh band.mesh) && test_le "$3" "$wide_mean" &&
	seam-homog -w 10 -l smooth.lab smooth.mesh >all.mesh &&
	test_cmp paper.mesh all.mesh
'

test_expect_success 'bad --model and --width are usage errors' '
	test_must_fail_usage seam-homog -m nosuch -l smooth.lab smooth.mesh >out &&
	test_must_fail_usage seam-homog -w 0 -l smooth.lab smooth.mesh >>out &&
	test_must_fail_usage seam-homog --report r -o r -l smooth.lab smooth.mesh >>out &&
	test ! -s out
'

test_done
