# drift-lib.sh -- how far seam-homog moved an animation (t0258, t0259),
# sourced after test-lib.sh; reads plain MESH streams only.

# drift IN OUT: measured from the plain streams alone, relative to the bbox
# diagonal of the input's average: "still max mean" = the number of still
# vertices (moving < 0.1% from their average in IN), their largest change
# OUT - IN over all frames, the mean and the max change of all vertices
drift() {
	awk '
		FNR == 1 { file++ }
		/^frame / { fr = $2 + 0; i = 0; rd = 1; next }
		!rd || /^f / || NF != 3 { next }
		file == 1 { x[fr, i] = $1; y[fr, i] = $2; z[fr, i] = $3
			    ax[i] += $1; ay[i] += $2; az[i] += $3; i++; nv = i; nfr = fr + 1; next }
		file == 2 { if (fr == 0 && i == 0) {
				for (v = 0; v < nv; v++) { ax[v] /= nfr; ay[v] /= nfr; az[v] /= nfr
					if (!v || ax[v] < l1) l1 = ax[v]; if (!v || ax[v] > h1) h1 = ax[v]
					if (!v || ay[v] < l2) l2 = ay[v]; if (!v || ay[v] > h2) h2 = ay[v]
					if (!v || az[v] < l3) l3 = az[v]; if (!v || az[v] > h3) h3 = az[v] }
				for (f = 0; f < nfr; f++) for (v = 0; v < nv; v++) {
					d = sqrt((x[f, v] - ax[v]) ^ 2 + (y[f, v] - ay[v]) ^ 2 + (z[f, v] - az[v]) ^ 2)
					if (d > mot[v]) mot[v] = d } }
			    c = sqrt(($1 - x[fr, i]) ^ 2 + ($2 - y[fr, i]) ^ 2 + ($3 - z[fr, i]) ^ 2)
			    if (c > ch[i]) ch[i] = c; sum += c; n++; if (c > cmax) cmax = c; i++ }
		END { dg = sqrt((h1 - l1) ^ 2 + (h2 - l2) ^ 2 + (h3 - l3) ^ 2)
		      for (v = 0; v < nv; v++) if (mot[v] < 0.001 * dg) { ns++; if (ch[v] > sm) sm = ch[v] }
		      printf "%d %.3g %.3g %.3g\n", ns, sm / dg, sum / n / dg, cmax / dg }' "$1" "$2"
}

