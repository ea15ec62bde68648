#!/bin/sh
test_description='mesh-clean: fins, duplicates, degenerate faces, holes, remeshing'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'an open tube gets closed' '
	mesh-gen -n 12 cylinder >tube.mesh &&
	mesh-clean tube.mesh >closed.mesh &&
	mesh-info closed.mesh >info.txt &&
	grep -q "^closed yes" info.txt && grep -q "^manifold yes" info.txt
'
test_expect_success 'fins, duplicates and degenerate faces are removed, the hole closed' '
	mesh-gen -s 1 icosphere >s.mesh &&
	awk "/^faces/ { print \"faces\", \$2 + 3; next }
	     /^f / && n == 0 { print; print; print \"f\", \$2, \$2, \$3; n++; next }
	     /^f / && n == 1 { print; print \"f\", \$2, \$4, \$3; n++; next } { print }" s.mesh >dirty.mesh &&
	mesh-clean -v dirty.mesh >c.mesh 2>err &&
	cat err && grep -q "1 degenerate, 1 duplicate, 2 fin faces, 0 small pieces; filled 1 holes, 0 left" err &&
	mesh-info c.mesh >info.txt && grep -q "^closed yes" info.txt && grep -q "^manifold yes" info.txt
'
test_expect_success '--no-fill keeps holes, --max-hole bounds them' '
	mesh-clean --no-fill tube.mesh >open.mesh &&
	mesh-info open.mesh | grep -q "^boundary_loops 2" &&
	mesh-clean --max-hole 3 tube.mesh >still.mesh &&
	mesh-info still.mesh | grep -q "^boundary_loops 2"
'
test_expect_success 'isotropic remeshing reaches the target edge length' '
	mesh-gen -s 3 icosphere >ico.mesh &&
	mesh-clean -r 0.25 ico.mesh >re.mesh &&
	n=$(awk "/^faces/ { print \$2 }" re.mesh) && echo "faces $n" &&
	test_le "$n" 600 && test_le 150 "$n" &&
	mesh-metrics --no-header -r ico.mesh re.mesh >m.txt &&
	test_le "$(awk "{ print \$3 }" m.txt)" 0.02
'
test_expect_success 'bad input fails cleanly' '
	mesh-gen -f 3 grid >anim.mesh &&
	test_fails_cleanly mesh-clean anim.mesh &&
	head -n 20 ico.mesh >trunc.mesh && test_fails_cleanly mesh-clean trunc.mesh &&
	test_must_fail_usage mesh-clean -r -1 ico.mesh
'
test_done
