# lower-part.awk -- per-face labels for t0301: 1 if the face centroid's y is
# below ymin + frac * (ymax - ymin) of a plain one-frame mesh, else 0.
# Stands in for seg-graphcut's "lower part" until segmentations exist.
$1 == "vertices" { nv = $2; next }
$1 == "f" { nf++; a[nf] = $2; b[nf] = $3; c[nf] = $4; next }
$1 == "frame" { inframe = 1; i = 0; next }
inframe && NF == 3 { y[i] = $2; if (i == 0 || $2 < lo) lo = $2; if (i == 0 || $2 > hi) hi = $2; i++ }
END {
	t = lo + frac * (hi - lo)
	for (k = 1; k <= nf; k++) print ((y[a[k]] + y[b[k]] + y[c[k]]) / 3 < t) ? 1 : 0
}
