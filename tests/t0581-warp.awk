# t0581-warp.awk -- a bent, turned and sheared copy of a rings file whose
# every ring starts at a random vertex, as a tracer or another drawing
# program would store it (pose K of a made-up animation of a drawing).
#   awk -v seed=K [-v amp=A] -f t0581-warp.awk IN.rings >poseK.rings
# amp scales the turn (up to 12 degrees), the bend and the shear (up to a
# tenth of the size); seed 0 keeps every ring's first vertex.
function rnd() { s = (s * 16807) % 2147483647; return s / 2147483647 }
function uni(a, b) { return a + (b - a) * rnd() }
$1 == "ring" { nr++; cnt[nr] = 0; next }
NF == 2 { cnt[nr]++; X[nr, cnt[nr]] = $1; Y[nr, cnt[nr]] = $2
	if (!(mnx != "") || $1 < mnx) mnx = $1; if (!(mxx != "") || $1 > mxx) mxx = $1
	if (!(mny != "") || $2 < mny) mny = $2; if (!(mxy != "") || $2 > mxy) mxy = $2 }
END {
	pi = 3.141592653589793; s = 1000 + 7919 * seed
	for (i = 0; i < 3; i++) rnd()
	if (amp == "") amp = 1
	rot = amp * uni(-12, 12) * pi / 180; bend = amp * uni(-0.08, 0.08); sx = uni(0.9, 1.1); sh = amp * uni(-0.1, 0.1)
	cx = (mnx + mxx) / 2; cy = (mny + mxy) / 2; W = mxx - mnx; H = mxy - mny
	for (r = 1; r <= nr; r++) {
		n = cnt[r]; k = seed ? int(n * rnd()) : 0
		print "ring " n
		for (j = 0; j < n; j++) {
			i = (j + k) % n + 1
			u = (X[r, i] - cx) / W; v = (Y[r, i] - cy) / H
			u2 = sx * u + sh * v + bend * sin(pi * v); v2 = v + bend * 0.5 * sin(pi * u)
			printf "%.6f %.6f\n", cx + W * (cos(rot) * u2 - sin(rot) * v2 * H / W), cy + H * (sin(rot) * u2 * W / H + cos(rot) * v2)
		}
	}
}
