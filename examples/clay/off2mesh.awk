# throwaway OFF -> MESH converter (until mesh-import lands): drops every face
# whose vertex set occurs more than once (fins of scanned meshes)
NR == 1 { next }
NR == 2 { nv = $1; nf = $2; next }
NR <= 2 + nv { v[NR - 3] = $1 " " $2 " " $3; next }
NR <= 2 + nv + nf { a = $2; b = $3; c = $4; x = a; y = b; z = c
  if (x > y) { t = x; x = y; y = t } if (y > z) { t = y; y = z; z = t } if (x > y) { t = x; x = y; y = t }
  k = x " " y " " z; cnt[k]++; n++; key[n] = k; f[n] = a " " b " " c }
END { m = 0; for (i = 1; i <= n; i++) if (cnt[key[i]] == 1) m++
  print "MESH 1"; print "vertices", nv; print "faces", m; print "frames 1"
  for (i = 1; i <= n; i++) if (cnt[key[i]] == 1) print "f", f[i]
  print "frame 0"; for (i = 0; i < nv; i++) print v[i] }
