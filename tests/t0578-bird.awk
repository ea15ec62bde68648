# t0578-bird.awk -v pose=K (0-5): outline of a bird seen from the side, an
# egg-shaped body with a beak of 6.5-12 degrees at its tip and a forked tail,
# the beak and the tail turning with the pose (compat-tri's goal capped by
# the sharpest outline corner, t0578)
BEGIN {
	pi = 3.141592653589793; a = 0.25 * (pose - 1.5); t = 0.2 * (pose % 3) - 0.2
	n = 0
	# body from the beak's lower root around to its upper root (ccw)
	for (i = 0; i <= 70; i++) {
		u = 0.12 + (2 * pi - 0.24) * i / 70
		r = 1 + 0.15 * cos(u) + 0.05 * sin(3 * u + pose)
		x = r * cos(u) * 1.3; y = r * sin(u) * 0.8
		# forked tail at the back (u near pi)
		d = u - pi
		if (d > -0.35 && d < 0.35) { w = 0.35 - (d < 0 ? -d : d); x -= 2.2 * w * (1 + 0.3 * sin(6 * d / 0.35 + t)); y += w * t }
		X[n] = x; Y[n] = y; n++
	}
	# the beak tip: 1.1 ahead of the roots, turned by a
	rx = X[n - 1]; ry = 0.5 * (Y[0] + Y[n - 1])
	X[n] = rx + 1.1 * cos(a); Y[n] = ry + 1.1 * sin(a); n++
	printf "ring %d\n", n
	for (i = 0; i < n; i++) printf "%.6f %.6f\n", 100 * X[i], 100 * Y[i]
}
