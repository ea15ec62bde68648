# match-frames.awk -- the largest distance between two MESH animations
# (plain text) of one surface whose vertices are numbered differently (an
# export that split them, then mesh-import --weld).
#
#   awk -f match-frames.awk [-v yup=1] REF.mesh OTHER.mesh
#
# Every vertex of OTHER is matched to the nearest vertex of REF in frame 0
# (those whose frame-0 coordinates round to the same 1e-4 are candidates;
# a vertex without one is compared with all), then the matched pairs
# are measured in every frame.  yup=1: OTHER is in glTF axes (+Y up), REF in
# Blender's (+Z up): OTHER's (x, y, z) is taken as (x, -z, y).  Prints
#   frames 48 vertices 2012 match 0 max 8.9e-08
# (match: the largest frame-0 distance of a matched pair); "frames differ"
# if the frame counts differ.
FNR == 1 { file++; frame = -1 }
$1 == "frame" { frame++; v = 0; nf[file] = frame + 1; next }
frame < 0 || NF != 3 { next }
{
	x = $1; y = $2; z = $3
	if (file == 2 && yup) { y = -$3; z = $2 }
	X[file, frame, v] = x; Y[file, frame, v] = y; Z[file, frame, v] = z
	v++
	nv[file] = v
}
END {
	if (nf[1] != nf[2]) { print "frames differ: " nf[1] " and " nf[2]; exit 1 }
	match0 = 0
	for (i = 0; i < nv[1]; i++) {
		key = sprintf("%.4f %.4f %.4f", X[1, 0, i], Y[1, 0, i], Z[1, 0, i])
		cell[key] = (key in cell) ? cell[key] " " i : i
	}
	for (j = 0; j < nv[2]; j++) {
		best = -1
		key = sprintf("%.4f %.4f %.4f", X[2, 0, j], Y[2, 0, j], Z[2, 0, j])
		nc = (key in cell) ? split(cell[key], cand, " ") : 0
		for (c = 1; c <= nc; c++) {
			i = cand[c]
			d = (X[1, 0, i] - X[2, 0, j]) ^ 2 + (Y[1, 0, i] - Y[2, 0, j]) ^ 2 + (Z[1, 0, i] - Z[2, 0, j]) ^ 2
			if (best < 0 || d < best) { best = d; m[j] = i }
		}
		for (i = 0; nc == 0 && i < nv[1]; i++) {
			d = (X[1, 0, i] - X[2, 0, j]) ^ 2 + (Y[1, 0, i] - Y[2, 0, j]) ^ 2 + (Z[1, 0, i] - Z[2, 0, j]) ^ 2
			if (best < 0 || d < best) { best = d; m[j] = i }
		}
		if (best > match0) match0 = best
	}
	max = 0
	for (k = 0; k < nf[1]; k++)
		for (j = 0; j < nv[2]; j++) {
			i = m[j]
			d = (X[1, k, i] - X[2, k, j]) ^ 2 + (Y[1, k, i] - Y[2, k, j]) ^ 2 + (Z[1, k, i] - Z[2, k, j]) ^ 2
			if (d > max) max = d
		}
	printf "frames %d vertices %d match %.3g max %.3g\n", nf[2], nv[2], sqrt(match0), sqrt(max)
}
