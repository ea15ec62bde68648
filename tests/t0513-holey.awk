# t0513-holey.awk -- a made-up 2D character with holes for the compat-tri
# tests: a round head on a trapezoid body whose two legs stand on a base
# (the gap between the legs is a hole), two eyes (holes), optionally a
# separate tail piece; the pose moves the legs, the eyes (blinking) and
# shears the whole figure.  Point density varies per pose.
#   awk -v pose=K -v tips=FILE -v pts=FILE [-v tail=1] [-v eyes=N] -f t0513-holey.awk >poseK.rings
# prints the rings (odd poses store the holes counter-clockwise, so the
# reader must reverse them); writes to `tips` the global vertex indices of
# the correspondence points: left foot, right foot, head top, apex of the
# gap (and the tail's tip); to `pts` two interior points "x y": the nose
# and the navel.
function rnd() { seed = (seed * 16807) % 2147483647; return seed / 2147483647 }
function emit(x, y) { X[n] = x + shear * (y + 2); Y[n] = y; n++ }
function side(x0, y0, x1, y1, k,   i) { for (i = 0; i < k; i++) emit(x0 + (x1 - x0) * i / k, y0 + (y1 - y0) * i / k) }
function flush(rev,   i) {
	print "ring " n - s0
	if (!rev) for (i = s0; i < n; i++) printf "%.9g %.9g\n", X[i], Y[i]
	else { printf "%.9g %.9g\n", X[s0], Y[s0]; for (i = n - 1; i > s0; i--) printf "%.9g %.9g\n", X[i], Y[i] }
	s0 = n
}
function ellipse(cx, cy, rx, ry, rot, k, ccw,   i, t, u, v) {
	for (i = 0; i < k; i++) {
		t = (ccw ? 1 : -1) * 2 * pi * i / k
		u = rx * cos(t); v = ry * sin(t)
		emit(cx + u * cos(rot) - v * sin(rot), cy + u * sin(rot) + v * cos(rot))
	}
}
BEGIN {
	pi = 3.141592653589793; n = 0; s0 = 0
	if (eyes == "") eyes = 2
	seed = 2000 + 11 * pose
	for (i = 0; i < 3; i++) rnd()
	wb = 0.95 + 0.45 * rnd()           # half width at the feet
	shear = 0.3 * (rnd() - 0.5)
	ah = -0.75 + 0.35 * rnd()          # apex of the gap between the legs
	blink = 0.35 + 0.65 * rnd()
	look = 0.12 * (rnd() - 0.5)
	dens = 8 + int(7 * rnd())          # points per unit length
	cy = 1.1; R = 0.9; t0 = -50 * pi / 180; t1 = pi - t0
	sx = R * cos(t0); sy = cy + R * sin(t0)
	# outer ring, counter-clockwise from the left foot
	lf = n; side(-wb, -2, wb, -2, int(2 * wb * dens) + 2)
	rf = n; side(wb, -2, sx, sy, int(2.5 * dens) + 1)
	k = int((t1 - t0) * R * dens) + 4
	for (i = 0; i < k; i++) {
		t = t0 + (t1 - t0) * i / k
		if (i > 0 && t >= pi / 2 && !top) top = n
		emit(R * cos(t), cy + R * sin(t))
	}
	side(-sx, sy, -wb, -2, int(2.5 * dens) + 1)
	flush(0)
	# the gap between the legs (a hole; the legs are 0.3 wide at the feet)
	gb = wb - 0.3; hs = n
	apex = n + int(1.0 * dens) + 2
	side(-gb, -1.85, 0, ah, int(1.0 * dens) + 2)
	side(0, ah, gb, -1.85, int(1.0 * dens) + 2)
	side(gb, -1.85, -gb, -1.85, int(2 * gb * dens) + 2)
	# the hole as stored: clockwise (even poses) or reversed (odd poses)
	L = n - hs; flush(pose % 2)
	if (pose % 2) apex = hs + L - (apex - hs)    # reversed after its first vertex
	# eyes: clockwise ellipses, first vertex on the outer side
	ke = 10 + int(8 * rnd())
	if (eyes >= 1) { ellipse(-0.35 + look, 1.25, 0.13, 0.13 * blink, 0, ke, 0); flush(0) }
	if (eyes >= 2) { ellipse(0.35 + look, 1.25, 0.13, 0.13 * blink, 0, ke + 2, 0); flush(0) }
	if (tail) {
		tt = n
		ellipse(1.75 + 0.2 * rnd(), -0.6, 0.45, 0.12, 0.6 * (rnd() - 0.5), 16 + int(8 * rnd()), 1)
		flush(0)
	}
	printf "%d %d %d %d%s\n", lf, rf, top, apex, tail ? " " tt : "" > tips
	printf "%.9g %.9g\n", 0 + shear * (0.85 + 2), 0.85 > pts
	printf "%.9g %.9g\n", 0.1 + shear * (-0.1 + 2), -0.1 > pts
}
