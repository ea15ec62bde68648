#!/bin/sh
test_description='lib-assemble: a labels file of the wrong length is the one named'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/seam-lib.sh"

test_expect_success 'setup: a waving tube in two parts, every frame a piece' '
	mesh-gen -f 6 -a wave -n 12 -m 8 --caps cylinder >cyl.mesh &&
	labels_by_z cyl.mesh 0.3 >cyl.lab &&
	part-split -l cyl.lab -o "p_%d.mesh" -m "p_%d.map" cyl.mesh &&
	lib-uniform -k 1 p_0.mesh >lib_0.mesh &&
	lib-uniform -k 1 p_1.mesh >lib_1.mesh &&
	seq 0 5 >six.lab && seq 0 4 >five.lab
'

test_expect_success 'part 0 too short: its file is named, against the base frames' '
	test_fails_cleanly lib-assemble cyl.mesh lib_0.mesh:five.lab:p_0.map lib_1.mesh:six.lab:p_1.map 2>err &&
	grep "cannot read .five.lab.: 5 labels, but .cyl.mesh. has 6 frames" err &&
	test_fails_cleanly lib-assemble cyl.mesh lib_0.mesh:six.lab:p_0.map lib_1.mesh:five.lab:p_1.map 2>err &&
	grep "cannot read .five.lab.: 5 labels" err
'

test_expect_success 'a one-frame base: the parts must agree, both files named' '
	mesh-export -k 0 cyl.mesh >rest.obj && mesh-import rest.obj >rest.mesh &&
	lib-assemble rest.mesh lib_0.mesh:five.lab:p_0.map lib_1.mesh:five.lab:p_1.map >ok.mesh &&
	test "$(count frames ok.mesh)" = 5 &&
	test_fails_cleanly lib-assemble rest.mesh lib_0.mesh:five.lab:p_0.map lib_1.mesh:six.lab:p_1.map 2>err &&
	grep "cannot read .six.lab.: 6 labels, but .five.lab. (part 0) has 5" err
'

test_done
