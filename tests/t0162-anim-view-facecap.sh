#!/bin/sh
test_description='anim-view: page size and quantisation error on facecap (335 frames), alone and as a 26,940-vertex merge of ten heads'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/view-lib.sh"
need_shared_data anim/facecap.glb

test_expect_view 'setup: facecap, and ten copies side by side, each 33 frames later' '
	mesh-import "$SHARED_DATA/anim/facecap.glb" >face.mesh &&
	perl "$TEST_DIRECTORY/merge-copies.pl" 10 33 <face.mesh >face10.mesh &&
	mesh-info face10.mesh >info && grep -q "^vertices 26940" info && grep -q "^frames 335" info
'
test_expect_view '26,940 vertices x 335 frames: the page is under 60 MB, error below 1e-4 of the diagonal' '
	anim-view -v -o big.html face10.mesh 2>log && cat log &&
	size=$(wc -c <big.html) && echo "page: $size bytes" && test "$size" -lt 60000000 &&
	rel=$(sed -n "s/.*quantisation error [^ ]* (\([^ ]*\) of the bounding box diagonal.*/\1/p" log) &&
	test -n "$rel" && test_le "$rel" 1e-4
'
test_expect_view 'the big page loads in chromium and shows the heads' '
	shoot "big.html#frame=100" big.png && console_clean big.png.log &&
	f=$(stage_fraction big.png) && echo "head pixels: $f" && test_le 0.05 "$f"
'
test_expect_view 'facecap against itself 20 frames later: error view, legend in mm' '
	perl "$TEST_DIRECTORY/merge-copies.pl" 1 20 <face.mesh >late.mesh &&
	anim-view -t input,later,error --error face.mesh --error-views 3 --print-height 40 \
	  -o err.html face.mesh late.mesh late.mesh &&
	size=$(wc -c <err.html) && echo "page: $size bytes" &&
	shoot "err.html#frame=100" err.png && console_clean err.png.log &&
	grep -q "mm on a print 40 mm tall" err.png.dom
'
test_done
