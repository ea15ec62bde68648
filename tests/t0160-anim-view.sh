#!/bin/sh
test_description='anim-view: one self-contained HTML page, synchronized views, shown in headless chromium'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/view-lib.sh"

test_expect_success 'setup: a bending and a twisting tube (same mesh, 60 frames), part labels' '
	mesh-gen -f 60 -a bend -n 24 -m 24 cylinder >bend.mesh &&
	mesh-gen -f 60 -a twist -n 24 -m 24 cylinder >twist.mesh &&
	mesh-gen -f 30 -a twist -n 24 -m 24 cylinder >short.mesh &&
	mesh-gen -f 60 -s 2 icosphere >ball.mesh &&
	awk "/^faces/ { n = \$2 } END { for (i = 0; i < n; i++) print (i < n / 2) ? 0 : 1 }" bend.mesh >parts.txt
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage anim-view &&
	test_must_fail_usage anim-view -t a,b bend.mesh &&
	test_must_fail_usage anim-view --print-height 40 bend.mesh &&
	test_must_fail_usage anim-view --error bend.mesh --error-views 3 bend.mesh twist.mesh &&
	test_must_fail_usage anim-view --up w bend.mesh &&
	test_must_fail_usage anim-view --scan 99:ball.mesh bend.mesh &&
	test_must_fail_usage anim-view --error bend.mesh --error-max p0 twist.mesh &&
	test_must_fail_usage anim-view --error bend.mesh --error-max p101 twist.mesh &&
	test_must_fail_usage anim-view --error-max 1 twist.mesh &&
	anim-view --help >help && grep -q "^Usage: anim-view" help
'
test_expect_view 'bad input: one line naming the file, exit 1, nothing written' '
	test_fails_cleanly anim-view bend.mesh ball.mesh 2>err && grep -q "ball.mesh" err &&
	test_fails_cleanly anim-view bend.mesh short.mesh 2>err && grep -q "30 frames" err &&
	head -n 7 parts.txt >few.txt &&
	test_fails_cleanly anim-view -l few.txt bend.mesh &&
	head -n 40 bend.mesh >cut.mesh &&
	test_fails_cleanly anim-view cut.mesh &&
	test_must_fail anim-view -o page.html bend.mesh ball.mesh 2>/dev/null &&
	test ! -e page.html
'
test_expect_view 'the page embeds everything: no src, no link, only data: modules; same input, same bytes' '
	anim-view -t bend,twist,error --error bend.mesh --error-views 3 --print-height 40 \
	  -l parts.txt -a -30 -e 20 --up z -o page.html bend.mesh twist.mesh twist.mesh &&
	anim-view -t bend,twist,error --error bend.mesh --error-views 3 --print-height 40 \
	  -l parts.txt -a -30 -e 20 --up z bend.mesh twist.mesh twist.mesh >again.html &&
	test_cmp page.html again.html &&
	! grep -qi "<script[^>]* src=" page.html && ! grep -qi "<link" page.html &&
	! grep -qi "<img[^>]* src=" page.html &&
	grep -o "\"[a-z/.A-Z-]*\":\"[a-z]*:" page.html | sed "s/.*:\"//" | sort -u >schemes &&
	echo "data:" >expect && test_cmp expect schemes &&
	test $(grep -c "<script type=\"application/octet-stream\"" page.html) -eq 4
'
test_expect_view '--error-max p50: the colour scale tops at the median distance (nearest rank), max unchanged' '
	anim-view --error bend.mesh --error-max p50 -o p50.html twist.mesh &&
	anim-diff --summary bend.mesh twist.mesh >diff.txt &&
	awk "FNR == 1 { k = 0 } /^frame/ { k++; i = 0; next } /^[a-zA-Z]/ { next } FNR == NR { X[k, i++] = \$0; next }
	     { split(X[k, i++], a, \" \"); print sqrt((a[1] - \$1)^2 + (a[2] - \$2)^2 + (a[3] - \$3)^2) }" \
	  bend.mesh twist.mesh >dist.txt &&
	n=$(wc -l <dist.txt) && test "$n" -eq 36000 &&
	median=$(sort -g dist.txt | sed -n "$((n / 2))p") &&
	top=$(grep -o "\"scale_max\":[0-9.e+-]*" p50.html | cut -d: -f2) &&
	max=$(grep -o "\"max\":[0-9.e+-]*" p50.html | cut -d: -f2) &&
	echo "median $median, scale top $top, max $max" &&
	test_near "$top" "$median" 1e-6 &&
	test_near "$max" "$(awk "\$1 == \"max\" { print \$2 }" diff.txt)" 1e-5
'
test_expect_view 'twist is stored once although shown twice' '
	anim-view -o one.html twist.mesh && anim-view -o two.html twist.mesh twist.mesh &&
	a=$(wc -c <one.html) && b=$(wc -c <two.html) && test $((b - a)) -lt 400
'
test_expect_view 'chromium shows the views: the mesh covers over 10% of the stage, no console message' '
	shoot page.html s0.png && console_clean s0.png.log &&
	f=$(stage_fraction s0.png) && echo "mesh pixels: $f" && test_le 0.10 "$f"
'
test_expect_view '#frame=40 opens frame 40 and changes the picture (over 2% of the stage)' '
	shoot "page.html#frame=40" s40.png && console_clean s40.png.log &&
	grep -q "stopmo-status ready frame=40" s40.png.log &&
	d=$(picture_change s0.png s40.png) && echo "changed: $d" && test_le 0.02 "$d"
'
test_expect_view 'a static mesh is one frame: the page still loads without errors' '
	mesh-gen -s 2 icosphere >one.mesh && anim-view -o static.html one.mesh &&
	shoot static.html st.png && console_clean st.png.log &&
	f=$(stage_fraction st.png) && test_le 0.05 "$f"
'
test_done
