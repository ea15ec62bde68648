# t0587-stick-character.awk -- a side view of a stick-and-capsule character
# in one of six poses, as a 300 by 300 PPM (black on white, for img2rings)
# on stdout, and its seven landmarks (outline points: name, x, y in pixels,
# y up, as img2rings writes them) to the file named by -v lm.
#   awk -v char=horse|flamingo -v pose=0..5 -v lm=FILE -f t0587-stick-character.awk
# horse: standing, grazing, a foreleg lifted, a rear hoof cocked, walking,
# head up (four legs, neck, head, ear, tail); flamingo: standing, feeding,
# one leg folded, walking, preening, head down (legs 5 pixels wide, an S
# neck, a beak).  Landmarks in outline order: horse rear hoofs, front
# hoofs, snout, ear, tail; flamingo toe, beak, head, two neck bends, tail,
# toe.  The legs never cross, so the order is the same in every pose.
# Layers (compat-tri --layers): -v omit=K draws the character without
# leg K (horse 0 front left .. 3 rear right; flamingo 0, 1), -v only=K
# draws leg K alone (the landmarks are still those of the whole one).
function rad(d) { return d * 3.141592653589793 / 180 }
function cap(ax, ay, bx, by, ra, rb) { CA[nc] = ax; CB[nc] = ay; CC[nc] = bx; CD[nc] = by; CR[nc] = ra; CS[nc] = rb; nc++ }
function ell(cx, cy, a, b, th) { EX[ne] = cx; EY[ne] = cy; EA[ne] = a; EB[ne] = b; ET[ne] = rad(th); ne++ }
# step from (x, y) by length l at angle a (degrees): sets PX, PY
function step(x, y, a, l) { PX = x + l * cos(rad(a)); PY = y + l * sin(rad(a)) }
function mark(name, x, y) { LN[nl] = name; LX[nl] = x; LY[nl] = y; nl++ }
function tip(ax, ay, bx, by, r, name,   l) { l = sqrt((bx - ax) ^ 2 + (by - ay) ^ 2); mark(name, bx + r * (bx - ax) / l, by + r * (by - ay) / l) }
function side(ax, ay, bx, by, r, name,   l) { l = sqrt((bx - ax) ^ 2 + (by - ay) ^ 2); mark(name, bx - r * (by - ay) / l, by + r * (bx - ax) / l) }
function inside(x, y,   i, u, v, p, q, dx, dy, t, r) {
	for (i = 0; i < ne && only == ""; i++) {
		u = x - EX[i]; v = y - EY[i]; p = u * cos(ET[i]) + v * sin(ET[i]); q = -u * sin(ET[i]) + v * cos(ET[i])
		if ((p / EA[i]) ^ 2 + (q / EB[i]) ^ 2 <= 1) return 1
	}
	for (i = 0; i < nc; i++) {
		if (only != "" && (i < LEG0[only] || i >= LEG1[only])) continue
		if (omit != "" && i >= LEG0[omit] && i < LEG1[omit]) continue
		dx = CC[i] - CA[i]; dy = CD[i] - CB[i]
		t = ((x - CA[i]) * dx + (y - CB[i]) * dy) / (dx * dx + dy * dy); t = t < 0 ? 0 : t > 1 ? 1 : t
		r = CR[i] + t * (CS[i] - CR[i])
		if ((x - CA[i] - t * dx) ^ 2 + (y - CB[i] - t * dy) ^ 2 <= r * r) return 1
	}
	return 0
}
function horse(   P, L, k, hip, sx, sy, hx, hy, ex, ey, tx, ty, kx, ky, fx, fy) {
	# neck head tail, then upper and lower angle of the legs FL FR RL RR
	split("60 -70 -110 -90 -90 -95 -88 -90 -92 -85 -90|10 -100 -100 -105 -95 -80 -85 -95 -88 -80 -95|" \
	      "70 -40 -130 -40 -110 -95 -90 -90 -90 -100 -85|50 -80 -140 -100 -100 -75 -80 -100 -70 -80 -90|" \
	      "35 -60 -150 -110 -105 -70 -75 -115 -95 -70 -100|80 -20 -95 -90 -90 -90 -90 -95 -95 -85 -85", L, "|")
	split(L[pose + 1], P, " ")
	S = 1.281320825887562; OX = -39.36782665353516; OY = -41.6972402450067
	ell(140, 165, 62, 24, 3)
	sx = 188; sy = 175; step(sx, sy, P[1], 55); hx = PX; hy = PY
	cap(sx, sy, hx, hy, 15, 8); step(hx, hy, P[2], 38); cap(hx, hy, PX, PY, 9, 5); tip(hx, hy, PX, PY, 5, "snout")
	step(hx, hy, P[2] + 150, 16); cap(hx, hy, PX, PY, 3.5, 1.5); tip(hx, hy, PX, PY, 1.5, "ear")
	step(80, 172, P[3], 45); cap(80, 172, PX, PY, 6, 2.5); tip(80, 172, PX, PY, 2.5, "tail")
	split("176 200 90 112", hip, " ")
	for (k = 0; k < 4; k++) {
		step(hip[k + 1], 150, P[4 + 2 * k], 42); kx = PX; ky = PY
		step(kx, ky, P[5 + 2 * k], 48); fx = PX; fy = PY
		LEG0[k] = nc; cap(hip[k + 1], 150, kx, ky, 9, 5); cap(kx, ky, fx, fy, 4.5, 4); LEG1[k] = nc
		tip(kx, ky, fx, fy, 4, "hoof" k)
	}
	split("hoof2 hoof3 hoof0 hoof1 snout ear tail", ORD, " ")
}
function flamingo(   P, L, k, b, bx, by, tx, ty, nx, ny, X, Y, hx, hy, kx, ky, ax, ay, hip) {
	# body, neck angles (4), beak, thigh and shin angles of both legs, feet
	split("10 80 100 70 20 -60 -100 -90 -80 -95 0 180|-10 40 -10 -60 -90 -150 -95 -85 -85 -100 0 180|" \
	      "15 90 110 80 40 -50 -95 -90 -40 -160 0 200|5 70 95 60 0 -80 -70 -100 -110 -80 10 170|" \
	      "20 100 130 100 60 -30 -90 -95 -60 -140 0 230|0 60 40 10 -40 -110 -85 -95 -100 -80 -10 190", L, "|")
	split(L[pose + 1], P, " ")
	S = 1.2767926869983877; OX = -71.37986858239142; OY = -61.63082678054195
	b = P[1]; bx = 150; by = 170
	ell(bx, by, 42, 20, b)
	tx = bx - 35 * cos(rad(b)); ty = by - 35 * sin(rad(b)); step(tx, ty, 180 + b - 15, 22)
	cap(tx, ty, PX, PY, 9, 2); tip(tx, ty, PX, PY, 2, "tail")
	X[0] = bx + 34 * cos(rad(b)); Y[0] = by + 10 + 34 * sin(rad(b))
	for (k = 1; k <= 4; k++) { step(X[k - 1], Y[k - 1], P[1 + k], k < 4 ? 22 : 18); X[k] = PX; Y[k] = PY; cap(X[k - 1], Y[k - 1], X[k], Y[k], 5, 4) }
	side(X[1], Y[1], X[2], Y[2], 4.5, "neckA"); side(X[2], Y[2], X[3], Y[3], 4.2, "neckB")
	hx = X[4]; hy = Y[4]; ell(hx, hy, 8, 7, 0)
	step(hx, hy, P[6], 24); cap(hx, hy, PX, PY, 4.5, 1.5); tip(hx, hy, PX, PY, 1.5, "beak"); tip(PX, PY, hx, hy, 7, "crown")
	split("158 145", hip, " ")
	for (k = 0; k < 2; k++) {
		step(hip[k + 1], 160, P[7 + 2 * k], 45); kx = PX; ky = PY
		step(kx, ky, P[8 + 2 * k], 55); ax = PX; ay = PY
		LEG0[k] = nc; cap(hip[k + 1], 160, kx, ky, 3.2, 2.6); cap(kx, ky, ax, ay, 2.6, 2.2)
		step(ax, ay, P[11 + k], 16); cap(ax, ay, PX, PY, 2.4, 1.5); LEG1[k] = nc; tip(ax, ay, PX, PY, 1.5, "toe" k)
	}
	split("toe0 beak crown neckB neckA tail toe1", ORD, " ")
}
BEGIN {
	nc = ne = nl = 0
	if (char == "horse") horse(); else if (char == "flamingo") flamingo(); else { print "char?" >"/dev/stderr"; exit 1 }
	printf "P3\n300 300\n1\n"
	for (r = 0; r < 300; r++) {
		line = ""
		for (c = 0; c < 300; c++) line = line (inside((c + 0.5 - OX) / S, (300 - r - 0.5 - OY) / S) ? " 0 0 0" : " 1 1 1")
		print substr(line, 2)
	}
	for (j = 1; j <= 7; j++) for (i = 0; i < nl; i++) if (LN[i] == ORD[j]) printf "%s %.3f %.3f\n", LN[i], LX[i] * S + OX, LY[i] * S + OY >lm
}
