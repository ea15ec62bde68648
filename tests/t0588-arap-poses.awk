# t0588-arap-poses.awk -- handles that pose a drawing: read a one-frame 2D
# MESH (a drawing meshed by compat-tri -e 0), print an arap-deform2d
# handle file for len(angles) poses: the two vertices nearest the centroid
# stay, and five boundary vertices evenly spaced along the outline (the
# "tips", written to the file tips) turn about the vertex 45% of the way to
# the centroid by angles[k] degrees (pose k, tip t: angles "a00,a01,...;a10,...").
/^f / { a = $2; b = $3; c = $4; E[a " " b] = 1; E[b " " c] = 1; E[c " " a] = 1; next }
/^frame/ { fr = 1; nv = 0; next }
fr && NF == 3 { x[nv] = $1; y[nv] = $2; cx += $1; cy += $2; nv++ }
function nearest(px, py, skip,   v, b, d, bd) {
	b = -1
	for (v = 0; v < nv; v++) {
		if (v == skip) continue
		d = (x[v] - px) ^ 2 + (y[v] - py) ^ 2
		if (b < 0 || d < bd) { b = v; bd = d }
	}
	return b
}
END {
	cx /= nv; cy /= nv
	for (e in E) { split(e, p, " "); if (!((p[2] " " p[1]) in E)) { nx[p[1]] = p[2]; if (start == "" || p[1] + 0 < start + 0) start = p[1] } }
	n = 0; v = start
	do { loop[n++] = v; v = nx[v] } while (v != start && n <= nv)
	f0 = nearest(cx, cy, -1); f1 = nearest(x[f0], y[f0], f0)
	np = split(angles, P, ";")
	printf "%d", f0; for (k = 1; k <= np; k++) printf " %.9g %.9g", x[f0], y[f0]; print ""
	printf "%d", f1; for (k = 1; k <= np; k++) printf " %.9g %.9g", x[f1], y[f1]; print ""
	for (t = 0; t < 5; t++) {
		tip = loop[int((t + 0.5) * n / 5)]; print tip >tips
		piv = nearest(x[tip] + 0.45 * (cx - x[tip]), y[tip] + 0.45 * (cy - y[tip]), tip)
		printf "%d", tip
		for (k = 1; k <= np; k++) {
			split(P[k], A, ","); r = A[t + 1] * 3.141592653589793 / 180
			dx = x[tip] - x[piv]; dy = y[tip] - y[piv]
			printf " %.9g %.9g", x[piv] + cos(r) * dx - sin(r) * dy, y[piv] + sin(r) * dx + cos(r) * dy
		}
		print ""
	}
}
