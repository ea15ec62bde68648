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
	clay-deform -v -k k.txt -l marks.txt --poses poses.mesh cyl.mesh >bent.mesh 2>log.txt &&
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
	clay-deform -l marks.txt cyl.mesh >global.mesh &&
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
test_expect_success 'shell: only the shape of the stiffness map matters, not its scale' '
	awk "{ print 10 * \$1 }" k.txt >k10.txt &&
	clay-deform -k k10.txt -l marks.txt cyl.mesh >bent10.mesh &&
	mesh-metrics --no-header -r cyl.mesh bent10.mesh >m10.txt &&
	a=$(awk "{ print \$12 }" m.txt) && a10=$(awk "{ print \$12 }" m10.txt) &&
	echo "mean |d_A| with k $a, with 10 k $a10" && test_near "$a10" "$a" 0.002 &&
	mesh-metrics --no-header -r bent.mesh bent10.mesh >d10.txt &&
	h=$(awk "{ print \$3 }" d10.txt) && echo "Hausdorff k vs 10 k: $h diagonals" && test_le "$h" 0.005
'
test_expect_success 'shell: landmarks that move rigidly move the cylinder rigidly (volume terms included)' '
	awk "BEGIN { c = cos(0.5236); s = sin(0.5236) }
	     /^frame [0-9]/ { on = 1; i = 0; next }
	     on { if (i == 0 || i == 100 || i == 200 || i == 300 || i == 401)
	          printf \"%d %.9g %.9g %.9g\\n\", i, c * \$1 - s * \$2 + 0.3, s * \$1 + c * \$2 + 0.2, \$3 + 0.1; i++ }" \
	    cyl.mesh >rigid.txt &&
	test "$(wc -l <rigid.txt)" -eq 5 &&
	clay-deform -k k.txt -l rigid.txt cyl.mesh >rigid.mesh &&
	mesh-metrics --no-header -r cyl.mesh rigid.mesh >r.txt &&
	e=$(awk "{ print \$11 }" r.txt) && a=$(awk "{ print \$12 }" r.txt) &&
	echo "rigid motion: max edge strain $e, mean |d_A| $a" && test_le "$e" 0.03 && test_le "$a" 0.01
'
# Why the per-face term matters for the local map (clay-deform(1)): the map
# is soft only around the pulled vertex, so without it the spokes from that
# vertex take the pull (strain ~0.75) while the rest of the body strains
# less than with uniform stiffness.  If the stiffness acted inversely the
# spokes would be the stiffest edges and this would fail.
test_expect_success 'shell, --face-volume 0: the local map localizes the strain at the soft vertex' '
	cat >spoke.awk <<\EOF &&
# spoke.awk P REF DEF: largest |l/L - 1| on edges at vertex P, and elsewhere
FNR == 1 { fi++ }
/^f / { if (fi == 1) { a[nf] = $2; b[nf] = $3; c[nf] = $4; nf++ }; next }
/^frame [0-9]/ { on = 1; n = 0; next }
on && NF == 3 { if (fi == 1) { X[n] = $1; Y[n] = $2; Z[n] = $3 } else { x[n] = $1; y[n] = $2; z[n] = $3 }; n++ }
function strain(i, j,   L, l) {
	L = sqrt((X[i]-X[j])^2 + (Y[i]-Y[j])^2 + (Z[i]-Z[j])^2)
	l = sqrt((x[i]-x[j])^2 + (y[i]-y[j])^2 + (z[i]-z[j])^2)
	return l / L - 1 < 0 ? 1 - l / L : l / L - 1
}
function edge(i, j,   s) { s = strain(i, j); if (i == P || j == P) { if (s > sp) sp = s } else if (s > so) so = s }
END { for (f = 0; f < nf; f++) { edge(a[f], b[f]); edge(b[f], c[f]); edge(c[f], a[f]) }; print sp, so }
EOF
	p=$(awk "/^vertices/ { print \$2 - 1 }" cyl.mesh) &&
	clay-deform --face-volume 0 --volume-weight 1 -k k.txt -l marks.txt cyl.mesh >s0l.mesh &&
	clay-deform --face-volume 0 --volume-weight 1 -l marks.txt cyl.mesh >s0g.mesh &&
	set -- $(awk -v P=$p -f spoke.awk cyl.mesh s0l.mesh) $(awk -v P=$p -f spoke.awk cyl.mesh s0g.mesh) &&
	echo "spokes local $1 global $3; elsewhere local $2 global $4" &&
	test_le "$3" "$1" && test_le "$2" "$4" && test_le "$2" "$1" &&
	set -- $(awk -v P=$p -f spoke.awk cyl.mesh bent.mesh) &&
	echo "default (per-face term): spokes $1, elsewhere $2" && test_le "$1" "$2"
'
test_expect_success 'shell: per-face volume term and open meshes run' '
	clay-deform -n 2 --face-volume 1 --volume-weight 0 -k k.txt -l marks.txt cyl.mesh >fv.mesh &&
	mesh-metrics --no-header -r cyl.mesh fv.mesh >/dev/null &&
	mesh-gen -n 16 -m 24 cylinder >open.mesh &&
	echo "399 0.6 0 0.75" >open-marks.txt && echo "0 0.25 0 0" >>open-marks.txt &&
	test_fails_cleanly clay-deform -l open-marks.txt open.mesh &&
	clay-deform --no-volume -n 2 -l open-marks.txt open.mesh >/dev/null
'
test_expect_success 'usage errors exit 2' '
	test_must_fail_usage clay-deform -m clay -l marks.txt cyl.mesh &&
	test_must_fail_usage clay-deform -m shell --bend -1 -l marks.txt cyl.mesh
'
test_done
