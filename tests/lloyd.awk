# lloyd.awk -- reference Lloyd (k-means) loop on the frames of a plain MESH
# stream, for t0300.  Usage: awk -v d=K -f lloyd.awk anim.mesh init-labels
# Prints "energy E" then the final labels, one per line.
FNR == NR {
	if ($1 == "vertices") nv = $2
	else if ($1 == "frame") { f = $2; i = 0; nf = f + 1 }
	else if (f != "" && NF == 3 && $1 != "f") { X[f, i, 0] = $1; X[f, i, 1] = $2; X[f, i, 2] = $3; i++ }
	next
}
{ L[FNR - 1] = $1 }
END {
	for (it = 0; it < 1000; it++) {
		for (a = 0; a < d; a++) { cnt[a] = 0; for (i = 0; i < nv; i++) for (c = 0; c < 3; c++) C[a, i, c] = 0 }
		for (g = 0; g < nf; g++) { a = L[g]; cnt[a]++; for (i = 0; i < nv; i++) for (c = 0; c < 3; c++) C[a, i, c] += X[g, i, c] }
		for (a = 0; a < d; a++) for (i = 0; i < nv; i++) for (c = 0; c < 3; c++) C[a, i, c] /= cnt[a]
		changed = 0; E = 0
		for (g = 0; g < nf; g++) {
			best = -1
			for (a = 0; a < d; a++) {
				s = 0
				for (i = 0; i < nv; i++) for (c = 0; c < 3; c++) { v = X[g, i, c] - C[a, i, c]; s += v * v }
				if (best < 0 || s < bs) { bs = s; best = a }
			}
			if (best != L[g]) changed++
			L[g] = best; E += bs
		}
		if (!changed) break
	}
	printf "energy %.12g\n", E
	for (g = 0; g < nf; g++) print L[g]
}
