# t0511-creature.awk -- a made-up 2D character for the compat-tri tests:
# a round body with five bent, straight-sided limbs (their densely sampled
# sides are long runs of collinear points), moved by the pose.
#   awk -v pose=K -v tips=FILE -f t0511-creature.awk >poseK.rings
# prints the ring; writes the five limb-tip vertex indices (0-based) to FILE.
function rnd() { seed = (seed * 16807) % 2147483647; return seed / 2147483647 }
function emit(x, y) { X[n] = x; Y[n] = y; n++ }
function side(x0, y0, x1, y1, k,   i) { for (i = 0; i < k; i++) emit(x0 + (x1 - x0) * i / k, y0 + (y1 - y0) * i / k) }
BEGIN {
	pi = 3.141592653589793; n = 0; R = 1; w = 0.16
	seed = 1000 + 7 * pose
	for (j = 0; j < 5; j++) {
		base[j] = 2 * pi * j / 5 + 0.25 * (rnd() - 0.5)
		len1[j] = 0.7 + 0.5 * rnd(); len2[j] = 0.4 + 0.5 * rnd()
		bend[j] = (rnd() - 0.5) * 1.6
	}
	dens = 10 + int(6 * rnd())        # points per unit length, varies per pose
	for (j = 0; j < 5; j++) {
		a = base[j]; ha = w / R
		# body arc from the previous limb to this limb's right side
		an = base[(j + 1) % 5] + (j == 4 ? 2 * pi : 0)
		ca = cos(a); sa = sin(a); nx = -sa; ny = ca
		# limb: right side out, around the tip, left side back (a bent bar)
		bx = R * ca; by = R * sa
		jx = bx + len1[j] * ca; jy = by + len1[j] * sa
		b2 = a + bend[j]; c2 = cos(b2); s2 = sin(b2)
		tx = jx + len2[j] * c2; ty = jy + len2[j] * s2
		# offsets: the joint corner uses the bisector so the sides stay parallel
		m2x = -s2; m2y = c2
		bisx = nx + m2x; bisy = ny + m2y; bl = sqrt(bisx * bisx + bisy * bisy); h = w / (bl / 2) / 2
		bisx *= h / bl * 2; bisy *= h / bl * 2
		k1 = int(len1[j] * dens) + 1; k2 = int(len2[j] * dens) + 1
		side(bx - w * nx, by - w * ny, jx - bisx, jy - bisy, k1)
		side(jx - bisx, jy - bisy, tx - w * m2x, ty - w * m2y, k2)
		emit(tx - w * m2x + 0.0 * c2, ty - w * m2y)
		tip[j] = n; emit(tx + 0.05 * c2, ty + 0.05 * s2)
		side(tx + w * m2x, ty + w * m2y, jx + bisx, jy + bisy, k2)
		side(jx + bisx, jy + bisy, bx + w * nx, by + w * ny, k1)
		# body arc to the next limb
		a0 = a + 1.15 * ha; a1 = an - 1.15 * ha; karc = int((a1 - a0) * R * dens) + 2
		for (i = 0; i <= karc; i++) { t = a0 + (a1 - a0) * i / karc; emit(R * cos(t), R * sin(t)) }
	}
	print "ring " n
	for (i = 0; i < n; i++) printf "%.9g %.9g\n", X[i], Y[i]
	printf "%d %d %d %d %d\n", tip[0], tip[1], tip[2], tip[3], tip[4] > tips
}
