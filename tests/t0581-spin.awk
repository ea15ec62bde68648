# t0581-spin.awk -- how far compat-tri's matching turns each hole or piece
# after the first ring (rings 2, 3, ...) against the face's own turn of
# 8 degrees a pose (t0581-face.awk): for every row of a --points-out file
# on that ring, the angle of its vertex about the ring's mean vertex in
# pose s minus the angle in pose 0; prints "ring R pose S: spin D" (the
# mean direction, degrees, in (-180, 180]).
#   awk -f t0581-spin.awk POINTS pose0.rings pose1.rings ...
FILENAME == ARGV[1] { if ($1 !~ /^#/) { nr++; for (s = 1; s <= NF; s++) C[nr, s - 1] = $s; ns = NF }; next }
FNR == 1 { sh++; g = 0; r = -1 }
$1 == "ring" { r++; RB[sh - 1, r] = g; RT[sh - 1, r] = g + $2; if (r + 1 > nring) nring = r + 1; next }
{ X[sh - 1, g] = $1; Y[sh - 1, g] = $2; RI[sh - 1, g] = r; g++ }
END {
	pi = 3.141592653589793
	for (s = 0; s < ns; s++) for (q = 1; q < nring; q++) {
		cx[s, q] = 0; cy[s, q] = 0
		for (i = RB[s, q]; i < RT[s, q]; i++) { cx[s, q] += X[s, i]; cy[s, q] += Y[s, i] }
		cx[s, q] /= RT[s, q] - RB[s, q]; cy[s, q] /= RT[s, q] - RB[s, q]
	}
	for (q = 1; q < nring; q++) for (s = 1; s < ns; s++) {
		sx = 0; sy = 0
		for (k = 1; k <= nr; k++) {
			a = C[k, 0]; b = C[k, s]
			if (RI[0, a] != q) continue
			t0 = atan2(Y[0, a] - cy[0, q], X[0, a] - cx[0, q]); t1 = atan2(Y[s, b] - cy[s, q], X[s, b] - cx[s, q])
			d = t1 - t0 - s * 8 * pi / 180; sx += cos(d); sy += sin(d)
		}
		printf "ring %d pose %d: spin %.1f\n", q + 1, s, atan2(sy, sx) * 180 / pi
	}
}
