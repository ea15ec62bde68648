# seam-lib.sh -- awk helpers for the seam tests (t0250-t0299), sourced after
# test-lib.sh.  They read plain MESH streams and label files directly, so
# the checks do not depend on the tools under test.

# labels_by_z MESH THRESHOLD > labels: 1 if the centroid of a face in
# frame 0 has z > THRESHOLD, else 0
labels_by_z() {
    awk -v T="$2" '
        /^f /     { nf++; a[nf] = $2; b[nf] = $3; c[nf] = $4; next }
        /^frame / { if ($2 + 0 > 0) exit; rd = 1; i = 0; next }
        rd        { z[i++] = $3 }
        END       { for (f = 1; f <= nf; f++)
                        print ((z[a[f]] + z[b[f]] + z[c[f]]) / 3 > T ? 1 : 0) }' "$1"
}

# fixed_drift MESH LABELS: the largest motion over the frames of a seam or
# one-ring vertex, relative to the bounding-box diagonal of all frames
fixed_drift() {
    awk -v L="$2" '
        BEGIN { while ((getline l < L) > 0) if (l !~ /^[ \t]*(#|$)/) lab[nl++] = l + 0 }
        /^MESH|^vertices|^faces|^frames/ { next }
        /^f / { A[nf] = $2; B[nf] = $3; C[nf] = $4; nf++; next }
        /^frame / { fr = $2 + 0; i = 0; next }
        { x[fr, i] = $1; y[fr, i] = $2; z[fr, i] = $3; i++; nfr = fr + 1; nv = i
          if (!init) { lo1 = hi1 = $1; lo2 = hi2 = $2; lo3 = hi3 = $3; init = 1 }
          if ($1 < lo1) lo1 = $1; if ($1 > hi1) hi1 = $1
          if ($2 < lo2) lo2 = $2; if ($2 > hi2) hi2 = $2
          if ($3 < lo3) lo3 = $3; if ($3 > hi3) hi3 = $3 }
        function seen(v, f) { if (v in first) { if (first[v] != lab[f]) seam[v] = 1 } else first[v] = lab[f] }
        END {
            for (f = 0; f < nf; f++) { seen(A[f], f); seen(B[f], f); seen(C[f], f) }
            for (f = 0; f < nf; f++)
                if ((A[f] in seam) || (B[f] in seam) || (C[f] in seam)) { fix[A[f]]; fix[B[f]]; fix[C[f]] }
            d = 0; n = 0
            for (v in fix) { n++
                for (k = 1; k < nfr; k++) {
                    e = x[k, v] - x[0, v]; if (e < 0) e = -e; if (e > d) d = e
                    e = y[k, v] - y[0, v]; if (e < 0) e = -e; if (e > d) d = e
                    e = z[k, v] - z[0, v]; if (e < 0) e = -e; if (e > d) d = e } }
            diag = sqrt((hi1 - lo1)^2 + (hi2 - lo2)^2 + (hi3 - lo3)^2)
            if (n == 0) { print "no fixed vertices" > "/dev/stderr"; exit 1 }
            printf "%.3g\n", d / diag }' "$1"
}

# max_motion MESH: the largest coordinate change of any vertex between two
# frames (to see that an animation moves at all)
max_motion() {
    awk '/^MESH|^vertices|^faces|^frames|^f / { next }
         /^frame / { fr = $2 + 0; i = 0; next }
         { if (fr == 0) { x[i] = $1; y[i] = $2; z[i] = $3 }
           else { e = $1 - x[i]; if (e < 0) e = -e; if (e > d) d = e
                  e = $2 - y[i]; if (e < 0) e = -e; if (e > d) d = e
                  e = $3 - z[i]; if (e < 0) e = -e; if (e > d) d = e }
           i++ }
         END { printf "%.6g\n", d + 0 }' "$1"
}

# closed MESH: prints "closed" if every edge has exactly two faces, with
# opposite orientations; otherwise "open N" (N bad edges)
closed() {
    awk '/^f / { e[$2 " " $3]++; e[$3 " " $4]++; e[$4 " " $2]++ }
         END { bad = 0
               for (k in e) { split(k, p, " "); if (e[k] != 1 || e[p[2] " " p[1]] != 1) bad++ }
               if (bad) print "open " bad; else print "closed" }' "$1"
}

# count KEY MESH: the value of a header line ("vertices", "faces", "frames")
count() {
    awk -v k="$1" '$1 == k { print $2; exit }' "$2"
}

# max_diff A B: the largest coordinate difference between two plain MESH
# streams with the same counts, relative to the bounding-box diagonal of A
max_diff() {
    awk 'FNR == 1 { file++; i = 0 }
         /^MESH|^vertices|^faces|^frames|^f |^frame / { next }
         file == 1 { x[i] = $1; y[i] = $2; z[i] = $3; i++
                     if (!init) { lo1 = hi1 = $1; lo2 = hi2 = $2; lo3 = hi3 = $3; init = 1 }
                     if ($1 < lo1) lo1 = $1; if ($1 > hi1) hi1 = $1
                     if ($2 < lo2) lo2 = $2; if ($2 > hi2) hi2 = $2
                     if ($3 < lo3) lo3 = $3; if ($3 > hi3) hi3 = $3; next }
         { e = $1 - x[i]; if (e < 0) e = -e; if (e > d) d = e
           e = $2 - y[i]; if (e < 0) e = -e; if (e > d) d = e
           e = $3 - z[i]; if (e < 0) e = -e; if (e > d) d = e; i++; n2 = i }
         END { if (n2 != length(x)) { print "different sizes" > "/dev/stderr"; exit 1 }
               printf "%.3g\n", d / sqrt((hi1 - lo1)^2 + (hi2 - lo2)^2 + (hi3 - lo3)^2) }' "$1" "$2"
}

# coincident_count MESH: the smallest number, over the frames, of vertices
# sharing their exact position with a lower-numbered vertex
coincident_count() {
    awk '/^MESH|^vertices|^faces|^frames|^f / { next }
         /^frame / { if (started) done(); started = 1; delete seen; n = 0; next }
         { k = $1 " " $2 " " $3; if (k in seen) n++; seen[k] = 1 }
         function done() { if (min == "" || n < min) min = n }
         END { done(); print min + 0 }' "$1"
}
