# spikes.awk -- a 'character' from a sphere: six vertices pulled out into
# spikes of different lengths (head, tail, four legs symmetric in x), then
# an optional rotation about z by ANG degrees and a bend (x += BEND * y^2)
BEGIN { nd = 6
  dx[1] = 0;    dy[1] = 1;  dz[1] = 0.3;  L[1] = 2.2   # head
  dx[2] = 0;    dy[2] = -1; dz[2] = 0.2;  L[2] = 1.8   # tail
  dx[3] = 0.6;  dy[3] = 0.5;  dz[3] = -1; L[3] = 2.6   # front right
  dx[4] = -0.6; dy[4] = 0.5;  dz[4] = -1; L[4] = 2.6   # front left
  dx[5] = 0.6;  dy[5] = -0.5; dz[5] = -1; L[5] = 2.0   # back right
  dx[6] = -0.6; dy[6] = -0.5; dz[6] = -1; L[6] = 2.0   # back left
  c = cos(ANG * 3.14159265358979 / 180); s = sin(ANG * 3.14159265358979 / 180) }
FNR == 1 { pass++ }
/^frame/ { body = 1; if (pass == 2) print; next }
pass == 1 && body && NF == 3 { n++
  for (k = 1; k <= nd; k++) { d = $1 * dx[k] + $2 * dy[k] + $3 * dz[k]; if (!(k in best) || d > best[k]) { best[k] = d; tip[k] = n } } next }
pass == 1 { next }
body && NF == 3 { m++; x = $1; y = $2; z = $3
  for (k = 1; k <= nd; k++) if (tip[k] == m) { x *= L[k]; y *= L[k]; z *= L[k] }
  x += BEND * y * y
  printf "%.17g %.17g %.17g\n", c * x - s * y, s * x + c * y, z; next }
{ print }
