#!/bin/sh
test_description='mesh-info: counts, topology, genus, checks'
. "$(dirname "$0")/test-lib.sh"

# value KEY FILE: the value of a "key value" line
value() { sed -n "s/^$1 //p" "$2"; }

test_expect_success 'grid: one boundary loop, genus 0, open' '
	mesh-gen -n 4 -m 3 grid >g.mesh &&
	mesh-info g.mesh >info &&
	test "$(value vertices info)" = 20 && test "$(value faces info)" = 24 &&
	test "$(value edges info)" = 43 && test "$(value boundary_loops info)" = 1 &&
	test "$(value euler info)" = 1 && test "$(value genus info)" = 0 &&
	test "$(value closed info)" = no && test "$(value manifold info)" = yes &&
	test "$(value oriented info)" = yes && test "$(value components info)" = 1
'
test_expect_success 'grid: unit area, diagonal sqrt 2, no volume line' '
	mesh-gen -n 7 grid | mesh-info >info &&
	test_near "$(value area info)" 1 1e-12 &&
	test_near "$(value diagonal info)" 1.4142135623730951 1e-12 &&
	test -z "$(value volume info)"
'
test_expect_success 'icosphere: closed, genus 0, chi 2, volume near 4/3 pi' '
	mesh-gen -s 3 icosphere >s.mesh &&
	mesh-info s.mesh >info &&
	test "$(value closed info)" = yes && test "$(value boundary_loops info)" = 0 &&
	test "$(value euler info)" = 2 && test "$(value genus info)" = 0 &&
	test_near "$(value volume info)" 4.18879 0.05
'
test_expect_success 'open cylinder: two boundary loops, chi 0, genus 0' '
	mesh-gen -n 6 -m 3 cylinder | mesh-info >info &&
	test "$(value boundary_loops info)" = 2 && test "$(value euler info)" = 0 &&
	test "$(value genus info)" = 0 && test "$(value closed info)" = no
'
test_expect_success 'capped cylinder: closed, volume near pi r^2 h' '
	mesh-gen -n 64 --caps cylinder | mesh-info >info &&
	test "$(value closed info)" = yes && test "$(value genus info)" = 0 &&
	test_near "$(value volume info)" 0.19635 0.001
'
test_expect_success 'frames and clips of an animation' '
	mesh-gen -f 12 --cut-every 5 -n 3 grid | mesh-info >info &&
	test "$(value frames info)" = 12 && test "$(value clips info)" = 3
'
test_expect_success 'bounding box spans all frames' '
	mesh-gen -f 9 -a wave -n 5 grid | mesh-info >info &&
	mesh-gen -n 5 grid | mesh-info >info0 &&
	test "$(value bbox_max info)" != "$(value bbox_max info0)" &&
	test_le "$(value diagonal info0)" "$(value diagonal info)"
'
test_expect_success 'two components counted, genus per surface' '
	cat >two.mesh <<-\EOT &&
	MESH 1
	vertices 6
	faces 2
	frames 1
	f 0 1 2
	f 3 4 5
	frame 0
	0 0 0
	1 0 0
	0 1 0
	5 0 0
	6 0 0
	5 1 0
	EOT
	mesh-info two.mesh >info &&
	test "$(value components info)" = 2 && test "$(value boundary_loops info)" = 2 &&
	test "$(value euler info)" = 2 && test "$(value genus info)" = 0
'
test_expect_success 'raw input reports the same as plain' '
	mesh-gen -f 3 -n 5 cylinder >p.mesh &&
	STOPMO_RAW=1 mesh-gen -f 3 -n 5 cylinder >r.mesh &&
	mesh-info p.mesh | grep -v ^format >ip &&
	mesh-info r.mesh | grep -v ^format >ir &&
	test_cmp ip ir && mesh-info r.mesh | grep -q "^format raw"
'
test_expect_success '--check closed passes on a sphere, prints nothing' '
	mesh-info --check closed s.mesh >out && test ! -s out &&
	mesh-info --check manifold --check oriented s.mesh
'
test_expect_success '--check closed fails cleanly on a grid' '
	test_fails_cleanly mesh-info --check closed g.mesh 2>err &&
	grep -q "not closed" err
'
test_expect_success '--check manifold fails on a fin (edge with three faces)' '
	cat >fin.mesh <<-\EOT &&
	MESH 1
	vertices 5
	faces 3
	frames 1
	f 0 1 2
	f 1 0 3
	f 0 1 4
	frame 0
	0 0 0
	1 0 0
	0 1 0
	0 -1 0
	0 0 1
	EOT
	mesh-info fin.mesh >info &&
	test "$(value nonmanifold_edges info)" = 1 && test "$(value manifold info)" = no &&
	test "$(value genus info)" = - &&
	test_fails_cleanly mesh-info --check manifold fin.mesh 2>err &&
	grep -q "not manifold" err
'
test_expect_success 'bow-tie vertex is non-manifold' '
	cat >bow.mesh <<-\EOT &&
	MESH 1
	vertices 5
	faces 2
	frames 1
	f 0 1 2
	f 0 3 4
	frame 0
	0 0 0
	1 0 0
	1 1 0
	-1 0 0
	-1 -1 0
	EOT
	mesh-info bow.mesh >info &&
	test "$(value nonmanifold_vertices info)" = 1 && test "$(value manifold info)" = no
'
test_expect_success 'a flipped face makes the mesh unoriented' '
	mesh-gen -n 2 grid | awk "NR==5 { print \"f\", \$2, \$4, \$3; next } { print }" >flip.mesh &&
	mesh-info flip.mesh >info && test "$(value oriented info)" = no &&
	test_fails_cleanly mesh-info --check oriented flip.mesh
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage mesh-info --check round s.mesh 2>err &&
	test_must_fail_usage mesh-info a b 2>err &&
	mesh-info --help >out && grep -q Usage out
'
test_done
