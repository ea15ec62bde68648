#!/bin/sh
test_description='seam-homog on facecap cut by its seeds: still skin stays still, paper model for comparison'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/seam-lib.sh"
. "$TEST_DIRECTORY/drift-lib.sh"
need_shared_data anim/facecap.glb

test_expect_success 'setup: every 4th frame, seg-graphcut with the recipe seeds, seam-smooth' '
	mesh-import --raw "$SHARED_DATA/anim/facecap.glb" >all.raw &&
	anim-slice -f 0:335:4 all.raw >face.mesh &&
	seg-graphcut --seeds "$STOPMO_ROOT/examples/stopshop/facecap.seeds" face.mesh >parts &&
	seam-smooth -l parts -L smooth.lab -o smooth.mesh face.mesh
'

test_expect_success 'band: still < 0.5%, mean < 0.1%, seam identical; paper: still skin moves' '
	seam-homog -l smooth.lab --report rep smooth.mesh >band.mesh &&
	seam-homog -m paper -l smooth.lab smooth.mesh >paper.mesh &&
	test "$(fixed_drift band.mesh smooth.lab)" = 0 &&
	test "$(fixed_drift paper.mesh smooth.lab)" = 0 &&
	set -- $(drift smooth.mesh band.mesh) && echo "band: still $1, still max $2, mean $3, max $4" &&
	test $1 -gt 300 && test_le "$2" 0.005 && test_le "$3" 0.001 && band_still=$2 &&
	set -- $(drift smooth.mesh paper.mesh) && echo "paper: still $1, still max $2, mean $3, max $4" &&
	test_le 0.005 "$2" && test_le "$band_still" "$2"
'

test_done
