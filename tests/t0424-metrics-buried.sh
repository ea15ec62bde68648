#!/bin/sh
test_description='mesh-metrics --buried: a scan'"'"'s own buried skin reported apart (flipped faces, cover)'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/estop-lib.sh"

# two unit spheres, the second centred at (1.2, 0, 0), stored as one mesh
# that passes through itself: the skin of each inside the other is buried
test_expect_success 'setup: two spheres passing through each other, one mesh' '
	mesh-gen -s 3 icosphere >s.mesh &&
	awk "/^vertices/ { n = \$2 } /^faces/ { m = \$2 }
	/^f / { f[++nf] = \$0; next } /^frame [0-9]/ { body = 1; next }
	body && NF == 3 { v[++nv] = \$0; next }
	END { print \"MESH 1\"; print \"vertices\", 2 * n; print \"faces\", 2 * m; print \"frames 1\"
		for (i = 1; i <= nf; i++) print f[i]
		for (i = 1; i <= nf; i++) { split(f[i], a, \" \"); print \"f\", a[2] + n, a[3] + n, a[4] + n }
		print \"frame 0\"
		for (i = 1; i <= nv; i++) print v[i]
		for (i = 1; i <= nv; i++) { split(v[i], a, \" \"); printf \"%.17g %.17g %.17g\n\", a[1] + 1.2, a[2], a[3] } }" \
	    s.mesh >two.mesh &&
	mesh-info -q two.mesh
'
# faces of either sphere whose centroid lies within radius r of the other centre
inside() {
	awk -v r="$2" "/^f / { f[++nf] = \$2 \" \" \$3 \" \" \$4; next } /^frame [0-9]/ { body = 1; next }
	body && NF == 3 { x[nv + 0] = \$1; y[nv + 0] = \$2; z[nv + 0] = \$3; nv++ }
	END { h = nf / 2
		for (i = 1; i <= nf; i++) { split(f[i], a, \" \")
			cx = (x[a[1]] + x[a[2]] + x[a[3]]) / 3; cy = (y[a[1]] + y[a[2]] + y[a[3]]) / 3
			cz = (z[a[1]] + z[a[2]] + z[a[3]]) / 3; ox = i <= h ? 1.2 : 0
			if ((cx - ox)^2 + cy^2 + cz^2 < r * r) n++ }
		print n + 0 }" "$1"
}
test_expect_success 'buried: the faces of each sphere inside the other, none on a clean sphere' '
	mesh-metrics --buried --no-header -r two.mesh two.mesh >m.txt && cat m.txt &&
	test "$(awk "{ print NF }" m.txt)" = 17 &&
	n=$(awk "{ print \$(NF - 2) }" m.txt) && lo=$(inside two.mesh 0.98) && hi=$(inside two.mesh 1.0) &&
	echo "buried $n, between $lo and $hi" && test "$lo" -gt 0 &&
	test "$n" -ge "$lo" && test "$n" -le "$hi" &&
	test "$(awk "{ print \$(NF - 1), \$NF == \$(NF - 3) }" m.txt)" = "0 1" &&
	mesh-metrics --buried --no-header -r s.mesh s.mesh >c.txt &&
	test "$(awk "{ print \$5, \$(NF - 2), \$(NF - 1), \$NF == \$(NF - 3) }" c.txt)" = "0 0 0 1" &&
	mesh-metrics -r two.mesh two.mesh | head -n 1 >h0.txt &&
	mesh-metrics --buried -r two.mesh two.mesh | head -n 1 >h1.txt &&
	grep -q "cover_rel$" h0.txt && grep -q "cover_rel buried flipped_buried cover_clear_rel$" h1.txt
'
test_expect_success 'flipped_buried: turned faces on the buried skin counted apart, not the others' '
	nf=$(awk "/^faces/ { print \$2 / 2 }" two.mesh) &&
	awk -v h="$nf" "/^f / && ++k <= h { print \"f\", \$2, \$4, \$3; next } { print }" two.mesh >turned.mesh &&
	mesh-metrics --buried --no-header -r two.mesh turned.mesh >t.txt && cat t.txt &&
	fl=$(awk "{ print \$5 }" t.txt) && fb=$(awk "{ print \$(NF - 1) }" t.txt) &&
	lo=$(inside two.mesh 0.98) && test "$fl" -ge $((nf - 40)) &&
	test "$fb" -ge $((lo / 2)) && test "$fb" -lt $((fl / 2))
'
test_expect_success 'cover_clear_rel: buried skin left uncovered does not count, the rest does' '
	awk "/^f / { f[++nf] = \$0; next } /^frame [0-9]/ { body = 1; next }
	body && NF == 3 { x[nv + 0] = \$1; y[nv + 0] = \$2; z[nv + 0] = \$3; nv++; next } !body { hd[++nh] = \$0 }
	END { for (i = 1; i <= nf; i++) { split(f[i], a, \" \")
			cx = (x[a[2]] + x[a[3]] + x[a[4]]) / 3; cy = (y[a[2]] + y[a[3]] + y[a[4]]) / 3
			cz = (z[a[2]] + z[a[3]] + z[a[4]]) / 3
			if (i > nf / 2 && cx^2 + cy^2 + cz^2 < 0.98^2) continue; keep[++k] = f[i] }
		for (i = 1; i <= nh; i++) print (hd[i] ~ /^faces/ ? \"faces \" k : hd[i])
		for (i = 1; i <= k; i++) print keep[i]
		print \"frame 0\"; for (i = 0; i < nv; i++) printf \"%.17g %.17g %.17g\n\", x[i], y[i], z[i] }" \
	    two.mesh >open.mesh &&
	mesh-metrics --buried --no-header -r two.mesh open.mesh >o.txt && cat o.txt &&
	test_le 0.05 "$(awk "{ print \$(NF - 3) }" o.txt)" &&
	test_le "$(awk "{ print \$NF }" o.txt)" 1e-9 &&
	awk "/^f / && ++k <= 7 { next } { print }" s.mesh | awk "/^faces/ { \$2 -= 7 } { print }" >holed.mesh &&
	mesh-metrics --buried --no-header -r s.mesh holed.mesh >p.txt &&
	test_le 0.01 "$(awk "{ print \$NF }" p.txt)"
'
test_expect_success 'bad input: --buried takes no argument' '
	test_must_fail_usage mesh-metrics --buried=1 -r two.mesh two.mesh
'

# the shared camel scans: 03 is a clean solid, 05 passes through itself at
# the groin (mesh-info -c solid: 131 pairs of faces intersect)
need_shared_data scans/camel-gallop-05.off
test_expect_success 'camel scans: none of 03 buried, 212 of 05' '
	camel_scans 03 05 &&
	mesh-metrics --buried --no-header -r c03.mesh c03.mesh >b3.txt &&
	mesh-metrics --buried --no-header -r c05.mesh c05.mesh >b5.txt &&
	test "$(awk "{ print \$NF - \$(NF - 3), \$(NF - 2) }" b3.txt)" = "0 0" &&
	test_le 100 "$(awk "{ print \$(NF - 2) }" b5.txt)"
'
test_done
