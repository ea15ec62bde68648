#!/bin/sh
test_description='part-split --part K: plain output and map names, no %d needed'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/seam-lib.sh"

test_expect_success 'setup: a bending tube in two parts' '
	mesh-gen -f 4 -n 12 -m 8 cylinder >cyl.mesh &&
	labels_by_z cyl.mesh 0.5 >cyl.lab &&
	part-split -l cyl.lab -o "p_%d.mesh" -m "p_%d.map" cyl.mesh
'

test_expect_success '-p 1 -o x.mesh -m x.map writes that part under those names' '
	part-split -l cyl.lab -p 1 -o x.mesh -m x.map cyl.mesh >out &&
	test ! -s out && test_cmp p_1.mesh x.mesh && test_cmp p_1.map x.map &&
	test ! -e x.mesh.tmp
'

test_expect_success 'a pattern still works with --part; without --part a plain name is refused' '
	part-split -l cyl.lab -p 0 -o "y_%d.mesh" cyl.mesh && test_cmp p_0.mesh y_0.mesh &&
	test_must_fail_usage part-split -l cyl.lab -o x.mesh cyl.mesh 2>err &&
	grep -q "needs exactly one %d" err &&
	test_must_fail_usage part-split -l cyl.lab -p 1 -o "x_%d_%d.mesh" cyl.mesh &&
	test_must_fail_usage part-split -l cyl.lab -p 1 -o "x_%s.mesh" cyl.mesh
'

test_done
