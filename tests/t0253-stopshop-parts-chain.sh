#!/bin/sh
test_description='seg-graphcut -> seam-homog -> part-split -> part-join on a generated animation'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/seam-lib.sh"

# closed waving tube, 16 segments x 12 rings: side faces 0..383, face 0 at
# the bottom ring, face 352 in the top ring
test_expect_success 'setup: seg-graphcut labels with a seed at each end' '
	mesh-gen -f 12 -a wave -n 16 -m 12 --caps cylinder >cyl.mesh &&
	seg-graphcut --seed 0:0 --seed 1:352 cyl.mesh >seg.lab &&
	test "$(wc -l <seg.lab)" = "$(count faces cyl.mesh)" &&
	test "$(sort -u seg.lab | wc -l)" = 2
'
test_expect_success 'seam-homog from stdin (spooled): seam constant, energy minimal' '
	seam-homog --check 10 -l seg.lab <cyl.mesh >homog.mesh &&
	test "$(count frames homog.mesh)" = 12 &&
	d=$(fixed_drift homog.mesh seg.lab) && echo "drift $d" && test_le "$d" 1e-12
'
test_expect_success 'every pair of frames assembles without a gap into a closed mesh' '
	part-split -l seg.lab -o "p_%d.mesh" -m "p_%d.map" homog.mesh &&
	for i in 0 5 11; do
		for j in 0 3 8; do
			part-join --strict -f $i,$j p_0.mesh p_0.map p_1.mesh p_1.map >mix.mesh &&
			mesh-info --check closed --check oriented mix.mesh || return 1
		done
	done
'
test_done
