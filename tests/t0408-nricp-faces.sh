#!/bin/sh
test_description='nricp with known correspondence: face neutral -> smile, target remeshed'
. "$(dirname "$0")/test-lib.sh"
need_shared_data faces/smile.ply

test_expect_success 'setup: the smile remeshed hides the connectivity' '
	mesh-import "$SHARED_DATA/faces/neutral.ply" >n.mesh &&
	mesh-import "$SHARED_DATA/faces/smile.ply" >s.mesh &&
	mesh-clean --no-fill -R 0.008 s.mesh >t.mesh &&
	for v in 0 700 1400 2100 2800 3000 3500 4200 4900 5600 6300 7000; do
		awk -v v=$v "/^frame [0-9]/ { on = 1; i = 0; next } on { if (i == v) print v, \$0; i++ }" s.mesh
	done >marks.txt
'
test_expect_success 'mean correspondence error below 2% of the diagonal' '
	nricp -l marks.txt n.mesh t.mesh >r.mesh &&
	e=$(anim-diff -s s.mesh r.mesh | awk "/^mean/ { print \$2 }") &&
	d=$(mesh-info s.mesh | awk "/^diagonal/ { print \$2 }") &&
	echo "mean error $e, diagonal $d" &&
	test_le "$e" "$(awk "BEGIN { print 0.02 * $d }")"
'
test_done
