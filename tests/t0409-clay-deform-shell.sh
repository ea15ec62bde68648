#!/bin/sh
test_description='clay-deform --model shell: Froehlich-Botsch thin shell (Gauss-Newton)'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'setup: a closed cylinder, its top pulled sideways and down' '
	mesh-gen -n 16 -m 24 --caps cylinder >cyl.mesh &&
	nv=$(awk "/^vertices/ { print \$2 }" cyl.mesh) &&
	{ echo "$((nv - 2)) 0 0 0"; echo "$((nv - 1)) 0.6 0 0.75";
	  for v in 0 16 32 48; do
		awk -v v=$v "/^frame [0-9]/ { on = 1; i = 0; next } on { if (i == v) print v, \$0; i++ }" cyl.mesh
	  done; } >marks.txt &&
	stiffness -l marks.txt cyl.mesh >k.txt
'
test_expect_success 'shell: bends toward the landmarks, volume within 2%, energy never rises' '
	clay-deform -v -m shell -k k.txt -l marks.txt --poses poses.mesh cyl.mesh >bent.mesh 2>log.txt &&
	mesh-metrics --no-header -r cyl.mesh bent.mesh >m.txt &&
	v=$(awk "{ x = \$6; print (x < 0 ? -x : x) }" m.txt) && echo "volume change $v" &&
	test_le "$v" 0.02 &&
	grep -q "^frames 11" poses.mesh &&
	top=$(awk "/^frame [0-9]/ { on = 1; i = 0; next } on { if (i == $(awk "/^vertices/ { print \$2 - 1 }" cyl.mesh)) print; i++ }" bent.mesh) &&
	echo "top $top" && test_near "$(echo $top | cut -d" " -f1)" 0.6 0.05 &&
	grep "shell energy" log.txt &&
	awk "/shell energy/ { if (\$(NF) + 0 > \$(NF - 2) + 0) bad = 1 } END { exit bad }" log.txt
'
test_expect_success 'shell: local stiffness gives lower mean |area distortion| than global' '
	clay-deform -m shell -l marks.txt cyl.mesh >global.mesh &&
	mesh-metrics --no-header -r cyl.mesh global.mesh >g.txt &&
	v=$(awk "{ x = \$6; print (x < 0 ? -x : x) }" g.txt) && test_le "$v" 0.02 &&
	al=$(awk "{ print \$12 }" m.txt) && ag=$(awk "{ print \$12 }" g.txt) &&
	echo "mean |d_A| local $al global $ag" && test_le "$al" "$ag"
'
test_expect_success 'shell: without volume terms the bend loses more volume' '
	clay-deform -m shell --no-volume -k k.txt -l marks.txt cyl.mesh >novol.mesh &&
	mesh-metrics --no-header -r cyl.mesh novol.mesh >n.txt &&
	vn=$(awk "{ x = \$6; print (x < 0 ? -x : x) }" n.txt) &&
	v=$(awk "{ x = \$6; print (x < 0 ? -x : x) }" m.txt) && echo "no volume $vn, volume kept $v" &&
	test_le "$v" "$vn"
'
test_expect_success 'shell: per-face volume term and open meshes run' '
	clay-deform -m shell -n 2 --face-volume 0.1 -k k.txt -l marks.txt cyl.mesh >fv.mesh &&
	mesh-metrics --no-header -r cyl.mesh fv.mesh >/dev/null &&
	mesh-gen -n 16 -m 24 cylinder >open.mesh &&
	echo "399 0.6 0 0.75" >open-marks.txt && echo "0 0.25 0 0" >>open-marks.txt &&
	test_fails_cleanly clay-deform -m shell -l open-marks.txt open.mesh &&
	clay-deform -m shell --no-volume -n 2 -l open-marks.txt open.mesh >/dev/null
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage clay-deform -m clay -l marks.txt cyl.mesh &&
	test_must_fail_usage clay-deform -m shell --bend -1 -l marks.txt cyl.mesh
'
test_done
