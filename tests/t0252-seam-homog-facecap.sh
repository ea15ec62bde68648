#!/bin/sh
test_description='seam-homog on facecap: UV-seam duplicates stay joined, seams constant'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/seam-lib.sh"
need_shared_data anim/facecap.glb

test_expect_success 'setup: every 10th facecap frame, labels above/below y = 10500' '
	mesh-import --raw "$SHARED_DATA/anim/facecap.glb" >all.raw &&
	anim-slice -f 0:335:10 all.raw >face.mesh &&
	test "$(count frames face.mesh)" = 34 &&
	labels_by_axis() { awk -v T="$2" "
	    /^f /     { nf++; a[nf] = \$2; b[nf] = \$3; c[nf] = \$4; next }
	    /^frame / { if (\$2 + 0 > 0) exit; rd = 1; i = 0; next }
	    rd        { y[i++] = \$2 }
	    END       { for (f = 1; f <= nf; f++) print ((y[a[f]] + y[b[f]] + y[c[f]]) / 3 > T ? 1 : 0) }" "$1"; } &&
	labels_by_axis face.mesh 10500 >face.lab &&
	test "$(sort -u face.lab | wc -l)" = 2 &&
	test_le 1 "$(coincident_count face.mesh)" &&
	d=$(fixed_drift face.mesh face.lab) && echo "input drift $d" && test_le 1e-3 "$d"
'
test_expect_success 'seam and one-ring identical in every frame, UV duplicates stay joined' '
	seam-homog -v -l face.lab face.mesh >h.mesh 2>h.err &&
	grep "joined [0-9]* vertices that coincide" h.err &&
	d=$(fixed_drift h.mesh face.lab) && echo "drift $d" && test_le "$d" 1e-12 &&
	test "$(coincident_count h.mesh)" = "$(coincident_count face.mesh)"
'
test_expect_success '--no-weld tears the UV seams open (why welding is the default)' '
	seam-homog --no-weld -l face.lab face.mesh >nw.mesh &&
	test_le "$(coincident_count nw.mesh)" "$(($(coincident_count face.mesh) - 1))"
'
test_expect_success 'upper face of frame 30 on lower face of frame 5: no seam gap' '
	part-split -l face.lab -o "p_%d.mesh" -m "p_%d.map" h.mesh &&
	part-join -v --strict -f 5,30 p_0.mesh p_0.map p_1.mesh p_1.map >mix.mesh 2>mix.err &&
	grep "seam gap: max 0 " mix.err
'
test_done
