# t0581-face.awk -- a made-up face for the compat-tri tests of rings that
# are matched without correspondence rows: a head with a nose on the right
# and two eyes (holes), or a separate arrow beside the head (a piece).  The
# whole drawing turns by 8 degrees a pose.  Each eye starts at an arbitrary
# angle, as a tracer would start it, and is stored clockwise.
#   awk -v pose=K [-v ry=R] [-v jit=J] [-v arrow=1] -f t0581-face.awk >poseK.rings
# ry: the eyes' height over their width (1: round); jit: each eye vertex's
# radius is scaled by 1 + jit (u - 1/2), u uniform (a traced circle's
# pixel noise); arrow=1: no eyes, an arrow that turns 35 degrees a pose
# more than the head (its start moves 3 vertices a pose).
function rnd() { seed = (seed * 16807) % 2147483647; return seed / 2147483647 }
function emit(x, y) { X[n] = x * cos(rot) - y * sin(rot) + 0.1 * pose; Y[n] = x * sin(rot) + y * cos(rot); n++ }
function flush(  i) { print "ring " n - s0; for (i = s0; i < n; i++) printf "%.9g %.9g\n", X[i], Y[i]; s0 = n }
BEGIN {
	pi = 3.141592653589793; rot = (pose - 2) * 8 * pi / 180; seed = 77 + 13 * pose
	if (ry == "") ry = 1
	k = 64 + 3 * pose
	for (i = 0; i < k; i++) {
		t = 2 * pi * i / k
		r = 1 + 0.25 * exp(-((t - 0.2) / 0.18) ^ 2) + 0.05 * cos(3 * t)
		emit(r * cos(t) * 0.9, r * sin(t) * 1.1)
	}
	flush()
	if (arrow) {
		split("-0.5 -0.1 0.1 -0.1 0.1 -0.25 0.5 0 0.1 0.25 0.1 0.1 -0.5 0.1", A, " ")
		a = 35 * pose * pi / 180; m = 0
		for (j = 0; j < 7; j++) {
			x0 = A[2 * j + 1]; y0 = A[2 * j + 2]; x1 = A[(2 * j + 2) % 14 + 1]; y1 = A[(2 * j + 3) % 14 + 1]
			for (q = 0; q < 4; q++) {
				x = x0 + (x1 - x0) * q / 4; y = y0 + (y1 - y0) * q / 4
				PX[m] = 2.3 + 0.6 * (x * cos(a) - y * sin(a)); PY[m] = 0.6 * (x * sin(a) + y * cos(a)); m++
			}
		}
		for (j = 0; j < m; j++) { i = (j + 3 * pose) % m; emit(PX[i], PY[i]) }
		flush()
		exit
	}
	for (e = 0; e < 2; e++) {
		m = 14 + pose + 2 * e; ph = 2 * pi * ((0.37 * (pose + 1) * (e + 2)) % 1)
		for (i = 0; i < m; i++) {
			t = ph - 2 * pi * i / m
			jr = 1 + jit * (rnd() - 0.5)
			emit((e ? 0.45 : -0.25) + 0.14 * jr * cos(t), 0.35 + 0.14 * jr * ry * sin(t))
		}
		flush()
	}
}
