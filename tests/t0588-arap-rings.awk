# t0588-arap-rings.awk -- the outline of frame k of a posed 2D MESH as a
# ring (boundary loop from the faces), every third point dropped starting
# at offset k % 3 (so the poses sample the outline differently), the
# vertices listed in the file tips kept; their ring indices go to lm.
BEGIN { while ((getline l < tips) > 0) keep[l + 0] = ++ntips }
/^f / { a = $2; b = $3; c = $4; E[a " " b] = 1; E[b " " c] = 1; E[c " " a] = 1; next }
/^frame/ { f = $2; v = 0; next }
f == k && NF == 3 { x[v] = $1; y[v] = $2; v++ }
END {
	for (e in E) { split(e, p, " "); if (!((p[2] " " p[1]) in E)) { nx[p[1]] = p[2]; if (start == "" || p[1] + 0 < start + 0) start = p[1] } }
	n = 0; v = start; i = 0
	do { if ((v in keep) || (i + k) % 3) R[n++] = v; i++; v = nx[v] } while (v != start)
	print "ring " n
	for (i = 0; i < n; i++) { print x[R[i]], y[R[i]]; if (R[i] in keep) L[keep[R[i]]] = i }
	for (t = 1; t <= ntips; t++) print L[t] >lm
}
