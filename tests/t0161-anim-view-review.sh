#!/bin/sh
test_description='anim-view: StopShop pieces (labels per frame, library thumbnails) and E-StopMotion scans under registered poses'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/view-lib.sh"

test_expect_success 'setup: two tube animations, a 5- and a 4-piece library with per-frame labels, a scan' '
	mesh-gen -f 60 -a bend -n 24 -m 24 cylinder >bend.mesh &&
	mesh-gen -f 60 -a twist -n 24 -m 24 cylinder >twist.mesh &&
	dict-learn -d 5 --seed 1 --labels-out lab_0.txt -o lib_0.mesh bend.mesh &&
	dict-learn -d 4 --seed 1 --labels-out lab_1.txt -o lib_1.mesh twist.mesh &&
	mesh-gen -s 3 icosphere >scan.mesh &&
	mesh-gen -f 2 -s 3 icosphere >scan2.mesh
'
test_expect_success 'bad uses exit 2' '
	test_must_fail_usage anim-view --part-names a,b --pieces lab_0.txt bend.mesh &&
	test_must_fail_usage anim-view --part-names a bend.mesh &&
	test_must_fail_usage anim-view --scan scan.mesh bend.mesh &&
	test_must_fail_usage anim-view --scan -1:scan.mesh bend.mesh
'
test_expect_view 'bad pieces and scans: one line naming the file, exit 1' '
	head -n 30 lab_0.txt >short.txt &&
	test_fails_cleanly anim-view --pieces short.txt bend.mesh 2>err && grep -q short.txt err &&
	sed "1s/.*/7/" lab_0.txt >big.txt &&
	test_fails_cleanly anim-view --pieces big.txt:lib_0.mesh bend.mesh 2>err && grep -q big.txt err &&
	test_fails_cleanly anim-view --scan 3:scan2.mesh bend.mesh 2>err && grep -q "scan2.mesh" err
'
test_expect_view 'pieces: the panel names the mounted piece of every part in the frame of #frame=N, no console message' '
	anim-view --pieces lab_0.txt:lib_0.mesh --pieces lab_1.txt:lib_1.mesh --part-names bend,twist \
	  -o pieces.html bend.mesh twist.mesh &&
	for k in 17 45; do
		shoot "pieces.html#frame=$k" p$k.png && console_clean p$k.png.log && d=p$k.png.dom &&
		l0=$(sed -n "$((k + 1))p" lab_0.txt) && l1=$(sed -n "$((k + 1))p" lab_1.txt) &&
		grep -q "bend: piece $l0<" $d && grep -q "twist: piece $l1<" $d &&
		grep -q "data-frame=\"$k\"" $d || return 1
	done
'
test_expect_view 'pieces: one thumbnail per library piece, the mounted one outlined' '
	n=$(grep -o "class=\"th[ \"]" p17.png.dom | wc -l) && test "$n" -eq 9 &&
	test $(grep -o "class=\"th on\"" p17.png.dom | wc -l) -eq 2
'
test_expect_view 'pieces: the thumbnails are drawn (the strip is not blank)' '
	f=$(box_fraction p17.png 430,360,1000,500 29,32,38) && echo "strip pixels: $f" && test_le 0.05 "$f"
'
test_expect_view 'scans: the scan shows at its frame, transparent and wireframe differ' '
	anim-view --scan 20:scan.mesh -o scans.html bend.mesh &&
	shoot "scans.html#frame=20" t20.png && console_clean t20.png.log &&
	shoot "scans.html#frame=20&scan=off" o20.png && console_clean o20.png.log &&
	shoot "scans.html#frame=20&scan=wireframe" w20.png && console_clean w20.png.log &&
	d=$(picture_change t20.png o20.png) && echo "scan shown: $d" && test_le 0.05 "$d" &&
	d=$(picture_change t20.png w20.png) && echo "wireframe vs transparent: $d" && test_le 0.02 "$d" &&
	grep -q "data-scan=\"1\"" t20.png.dom && grep -q "data-scan=\"0\"" o20.png.dom &&
	shoot "scans.html#frame=21" t21.png && grep -q "data-scan=\"0\"" t21.png.dom
'
test_done
