#!/bin/sh
test_description='arap-interp and lin-interp: endpoints, rigidity, distortion, bad input'
. "$(dirname "$0")/test-lib.sh"

# rotate a MESH stream by DEG degrees about the y axis and shift it by 1 in x
rotate_y() {
	awk -v deg="$1" 'BEGIN { a = deg * 3.14159265358979324 / 180; c = cos(a); s = sin(a) }
	/^frame/ { body = 1; print; next }
	body && NF == 3 { printf "%.17g %.17g %.17g\n", c * $1 + s * $3 + 1, $2, -s * $1 + c * $3; next }
	{ print }' "$2"
}

# largest |coordinate difference| between frame K of two streams with equal headers
frame_diff() {
	awk -v k="$3" 'FNR == 1 { file++ } /^frame/ { fr = $2; v = 0; next }
	NF == 3 && fr == k && $1 != "f" { if (file == 1) x[v] = $1 " " $2 " " $3;
		else { split(x[v], p, " "); for (d = 1; d <= 3; d++) { e = p[d] - $d; if (e < 0) e = -e; if (e > m) m = e } }
		v++ }
	END { printf "%.3g\n", m + 0 }' "$1" "$2"
}

test_expect_success 'setup: a closed bar and the same bar rotated by 120 degrees' '
	mesh-gen -n 8 -m 12 --caps cylinder >bar.mesh &&
	rotate_y 120 bar.mesh >rot.mesh &&
	rotate_y 0 bar.mesh >bar0.mesh
'
test_expect_success 'arap-interp reproduces both endpoints (1e-9)' '
	arap-interp --steps 4 bar.mesh rot.mesh >ai.mesh &&
	d0=$(frame_diff bar.mesh ai.mesh 0) && test_le "$d0" 1e-9 &&
	awk "/^frame 4/ { on = 1; print \"frame 0\"; next } on" ai.mesh >last.body &&
	awk "/^frame 0/ { on = 1 } on" rot.mesh >rot.body &&
	paste rot.body last.body | awk "NF == 6 { for (d = 1; d <= 3; d++) { e = \$d - \$(d + 3); if (e < 0) e = -e; if (e > m) m = e } }
		END { if (m > 1e-9) { print \"endpoint error \" m; exit 1 } }"
'
test_expect_success 'arap-interp: 120-degree rotation gives rigid in-betweens (edges within 1e-6)' '
	mesh-metrics -r bar.mesh ai.mesh >ai.txt &&
	awk "!/^#/ && \$11 > m { m = \$11 } END { print m + 0 }" ai.txt >edge &&
	test_le "$(cat edge)" 1e-6
'
test_expect_success 'lin-interp shrinks the same rotation (edges > 30% shorter at t = 1/2)' '
	lin-interp --steps 4 bar.mesh rot.mesh >li.mesh &&
	mesh-metrics -r bar.mesh li.mesh >li.txt &&
	e=$(awk "\$1 == 2 { print \$11 }" li.txt) && test_le 0.3 "$e" &&
	v=$(awk "\$1 == 2 { print \$6 }" li.txt) && test_le "$v" -0.5
'
test_expect_success 'lin-interp reproduces its endpoints exactly' '
	lin-interp --steps 3 bar.mesh rot.mesh >l3.mesh &&
	test "$(frame_diff bar.mesh l3.mesh 0)" = 0
'
test_expect_success 'arap-interp -t writes one pose; t=1 is the target' '
	arap-interp -t 1 bar.mesh rot.mesh >t1.mesh &&
	grep -q "^frames 1" t1.mesh &&
	mesh-metrics -r rot.mesh t1.mesh >t1.txt &&
	h=$(awk "!/^#/ { print \$2 }" t1.txt) && test_le "$h" 1e-9
'
test_expect_success 'bent limb: lower area and volume distortion than lin-interp' '
	mesh-gen -f 4 -a bend --amount 1.5 -n 12 -m 20 --caps cylinder >bend.mesh &&
	arap-interp bend.mesh >ab.mesh && lin-interp bend.mesh >lb.mesh &&
	mesh-metrics -r bend.mesh ab.mesh >ab.txt && mesh-metrics -r bend.mesh lb.mesh >lb.txt &&
	aa=$(awk "\$1 == 5 { x = \$7; print (x < 0 ? -x : x) }" ab.txt) &&
	la=$(awk "\$1 == 5 { x = \$7; print (x < 0 ? -x : x) }" lb.txt) &&
	av=$(awk "\$1 == 5 { x = \$6; print (x < 0 ? -x : x) }" ab.txt) &&
	lv=$(awk "\$1 == 5 { x = \$6; print (x < 0 ? -x : x) }" lb.txt) &&
	echo "area $aa vs $la, volume $av vs $lv" &&
	test_le "$aa" "$(awk "BEGIN { print $la / 10 }")" &&
	test_le "$av" "$(awk "BEGIN { print $lv / 10 }")"
'
test_expect_success 'key poses in one stream: frames = segments * steps + 1' '
	arap-interp --steps 5 bend.mesh >keys.mesh &&
	grep -q "^frames 16" keys.mesh
'
test_expect_success 'twist beyond 180 degrees stays on one branch' '
	mesh-gen -f 4 -a twist --amount 4 -n 12 -m 24 cylinder >tw.mesh &&
	arap-interp -v --steps 2 tw.mesh >tw.out 2>tw.err &&
	a=$(sed -n "s/.*segment 0: largest rotation \([0-9.]*\).*/\1/p" tw.err) &&
	test_le 185 "$a" &&
	lin-interp --steps 2 tw.mesh >twl.out &&
	mesh-metrics -r tw.mesh tw.out >tw.txt && mesh-metrics -r tw.mesh twl.out >twl.txt &&
	aa=$(awk "\$1 == 1 { x = \$7; print (x < 0 ? -x : x) }" tw.txt) &&
	la=$(awk "\$1 == 1 { x = \$7; print (x < 0 ? -x : x) }" twl.txt) &&
	echo "twist: mean area distortion arap $aa, linear $la" &&
	test_le "$aa" 0.06 && test_le 0.3 "$la"
'
test_expect_success 'different connectivity is a clean error' '
	mesh-gen -n 9 -m 12 --caps cylinder >other.mesh &&
	test_fails_cleanly arap-interp bar.mesh other.mesh &&
	test_fails_cleanly lin-interp bar.mesh other.mesh
'
test_expect_success 'a single key pose is a clean error' '
	test_fails_cleanly arap-interp bar.mesh
'
test_expect_success 'truncated input is a clean error' '
	head -n 60 bar.mesh >trunc.mesh &&
	test_fails_cleanly arap-interp bar.mesh trunc.mesh
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage arap-interp --steps 0 bar.mesh rot.mesh &&
	test_must_fail_usage arap-interp a b c
'
test_done
