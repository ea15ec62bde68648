# morph2d-lib.sh -- shared helpers of the 2D morphing tests (t05xx).

# bar_pair RES: MESH of 2 frames: a 1 x 0.2 bar and the bar rotated by 90 degrees
bar_pair() {
	mesh-gen -n "$1" -m 2 grid | awk '
	/^frames /{ print "frames 2"; next }
	/^frame /{ print "frame 0"; inframe = 1; next }
	inframe && NF == 3 { X[n] = $1; Y[n] = $2 * 0.2; printf "%.17g %.17g 0\n", X[n], Y[n]; n++; next }
	{ print }
	END { print "frame 1"; for (i = 0; i < n; i++) printf "%.17g %.17g 0\n", -Y[i], X[i] }'
}

# bend_pair TH SQ: a 4 x 0.4 bar, and the bar bent by angle TH with its
# thickness scaled by SQ
bend_pair() {
	mesh-gen -n 40 -m 2 grid | awk -v th="$1" -v sq="$2" '
	/^frames /{ print "frames 2"; next }
	/^frame /{ print "frame 0"; inframe = 1; next }
	inframe && NF == 3 { X[n] = $1 * 4; Y[n] = $2 * 0.4; printf "%.17g %.17g 0\n", X[n], Y[n]; n++; next }
	{ print }
	END { print "frame 1"; r = 4 / th;
	      for (i = 0; i < n; i++) printf "%.17g %.17g 0\n", (r - sq * Y[i]) * sin(X[i] / r), r - (r - sq * Y[i]) * cos(X[i] / r) }'
}

# smallest signed triangle area over all frames of a plain MESH stream
min_area() {
	awk '$1 == "f" { F[nfa++] = $2 " " $3 " " $4 }
	     $1 == "frame" { k = 0; fr++; next }
	     fr > 0 && NF == 3 { X[fr, k] = $1; Y[fr, k] = $2; k++ }
	     END { m = 1e300; for (f = 1; f <= fr; f++) for (t = 0; t < nfa; t++) {
		split(F[t], v, " "); a = v[1]; b = v[2]; c = v[3];
		s = (X[f,b]-X[f,a])*(Y[f,c]-Y[f,a]) - (Y[f,b]-Y[f,a])*(X[f,c]-X[f,a]);
		if (s < m) m = s }; print m }' "$1"
}

# tri_angles MESH: the smallest angle (degrees) of every triangle in every
# frame, one a line ("frame angle", frames from 1)
tri_angles() {
	awk 'function ang(ax, ay, bx, by, cx, cy,  ux, uy, vx, vy, cr) {
		ux = bx - ax; uy = by - ay; vx = cx - ax; vy = cy - ay; cr = ux * vy - uy * vx
		return atan2(cr < 0 ? -cr : cr, ux * vx + uy * vy) * 57.29577951308232 }
	BEGIN { nf = 0 }
	$1 == "f" { A[nf] = $2; B[nf] = $3; C[nf] = $4; nf++; next }
	$1 == "frame" { fr++; k = 0; next }
	fr > 0 && NF == 3 { X[fr, k] = $1; Y[fr, k] = $2; k++ }
	END { for (f = 1; f <= fr; f++) for (t = 0; t < nf; t++) {
		a = A[t]; b = B[t]; c = C[t]
		q = ang(X[f,a], Y[f,a], X[f,b], Y[f,b], X[f,c], Y[f,c])
		r = ang(X[f,b], Y[f,b], X[f,c], Y[f,c], X[f,a], Y[f,a]); if (r < q) q = r
		r = ang(X[f,c], Y[f,c], X[f,a], Y[f,a], X[f,b], Y[f,b]); if (r < q) q = r
		printf "%d %.17g\n", f, q } }' "$1"
}

# worst_angle MESH: the smallest angle (degrees) over every triangle of
# every frame, measured here (not taken from compat-tri -v)
worst_angle() {
	tri_angles "$1" | awk 'BEGIN { m = 180 } $2 < m { m = $2 } END { printf "%.4f\n", m }'
}

# under_share MESH DEG: the largest share (percent) over the frames of the
# triangles whose smallest angle is below DEG degrees
under_share() {
	tri_angles "$1" | awk -v lim="$2" '{ n[$1]++; u[$1] += $2 < lim }
	END { m = 0; for (f in n) if (100 * u[f] / n[f] > m) m = 100 * u[f] / n[f]; printf "%.1f\n", m }'
}

# mesh_vertices MESH: the vertex count of a MESH stream
mesh_vertices() {
	sed -n 's/^vertices //p' "$1" | head -n 1
}

# creature_poses: the six poses of the made-up creature of t0511-creature.awk
# as p0.rings .. p5.rings and its five limb tips as corr.txt (one row per
# tip, one column per pose)
creature_poses() {
	for k in 0 1 2 3 4 5; do
		awk -v pose=$k -v tips=tips$k -f "$TEST_DIRECTORY/t0511-creature.awk" >p$k.rings || return 1
	done &&
	cat tips0 tips1 tips2 tips3 tips4 tips5 | awk '{ for (i = 1; i <= NF; i++) r[i] = r[i] " " $i }
		END { for (i = 1; i <= 5; i++) print substr(r[i], 2) }' >corr.txt
}

# elephant_walk_frames K...: elephant/frame_K.obj of the shared elephant walk
# (anim/elephant-walk-457.tar.xz) into the current directory, for each K
elephant_walk_frames() {
	files= && for k in "$@"; do files="$files elephant/frame_$k.obj"; done &&
	tar -xJf "$SHARED_DATA/anim/elephant-walk-457.tar.xz" -C . $files
}

# face_layers MESH: the layer (connected component, numbered by first
# appearance) of each face, one line each; then "vertex0 L", the layer
# holding vertex 0 (the first vertex of ring 1)
face_layers() {
	awk 'function find(x) { while (P[x] != x) x = P[x]; return x }
	$1 == "f" { F[nf++] = $2 " " $3 " " $4; for (k = 2; k <= 4; k++) if (!($k in P)) P[$k] = $k
		a = find($2); b = find($3); c = find($4); P[b] = a; P[find(c)] = a }
	END { for (f = 0; f < nf; f++) { split(F[f], v, " "); r = find(v[1]); if (!(r in L)) L[r] = nl++; print L[r] }
	      print "vertex0", L[find(0)] }' "$1"
}

# elephant_arm_labels MESH: on stdout one label per face of MESH (a frame
# of the shared elephant walk, imported): 1 for the left arm -- the faces
# whose vertices lie beyond x = 22 and are joined through mesh edges to
# its tip (the largest x among 35 < y < 65) --, 0 for the rest
elephant_arm_labels() {
	awk '/^f / { F[nf++] = $2 " " $3 " " $4; next }
	NF == 3 && $1 !~ /[a-z]/ { x[nv] = $1; y[nv] = $2; nv++ }
	END {
		for (f = 0; f < nf; f++) {
			split(F[f], v, " ")
			for (k = 1; k <= 3; k++) { a = v[k]; A[a, deg[a]++] = v[k % 3 + 1] }
		}
		seed = -1
		for (i = 0; i < nv; i++) if (y[i] > 35 && y[i] < 65 && (seed < 0 || x[i] > x[seed])) seed = i
		q[0] = seed; arm[seed] = 1; h = 0; t = 1
		while (h < t) {
			u = q[h++]
			for (k = 0; k < deg[u]; k++) { w = A[u, k]; if (!(w in arm) && x[w] > 22) { arm[w] = 1; q[t++] = w } }
		}
		for (f = 0; f < nf; f++) { split(F[f], v, " "); print (v[1] in arm) && (v[2] in arm) && (v[3] in arm) }
	}' "$1"
}

# elephant_arm_layers K...: for each frame K of the shared elephant walk
# (elephant_walk_frames first), layK.rings for compat-tri --layers: the
# silhouette seen from the left (mesh-render -V left, 300 by 300) without
# the left arm, then that arm alone (mesh-render --only: the camera of the
# whole frame for both), each traced by img2rings -1.  The arm is
# elephant_arm_labels of the first frame, the same faces in every frame
elephant_arm_layers() {
	eal_first=
	for eal_k in "$@"; do
		mesh-import elephant/frame_$eal_k.obj >e$eal_k.mesh || return 1
		if [ -z "$eal_first" ]; then eal_first=$eal_k; elephant_arm_labels e$eal_k.mesh >arm.labels || return 1; fi
		for eal_p in 0 1; do
			mesh-render -V left -s 300x300 -c 0,0,0 --flat -f ppm -l arm.labels --only $eal_p e$eal_k.mesh \
				>part$eal_p-$eal_k.ppm &&
			img2rings -1 -s 1 -o part$eal_p-$eal_k.rings part$eal_p-$eal_k.ppm || return 1
		done
		cat part0-$eal_k.rings part1-$eal_k.rings >lay$eal_k.rings || return 1
	done
}

# camel_traced_poses: camel1.rings .. camel5.rings, the five gallop frames
# of the shared scans rendered from the side (300 by 300) and traced
camel_traced_poses() {
	for i in 1 2 3 4 5; do
		mesh-import "$SHARED_DATA/scans/camel-gallop-0$i.off" |
		mesh-render -V right -s 300x300 -c 0,0,0 --flat -f ppm >camel$i.ppm &&
		img2rings -1 -s 1 -o camel$i.rings camel$i.ppm || return 1
	done
}

# camel_landmarks POSE: on the traced camel gallop (camel_traced_poses), seven
# landmarks per pose picked by eye on the 300x300 renders (pixel units, y
# up): ear tip, snout, neck-hump notch, first and second hoof along the
# outline, last (rear) hoof, tail tip.  Each is snapped to the nearest
# outline vertex (all within 6 pixels).
camel_landmarks() {
	case $1 in
	1) echo "40 221 26 177 80 191 12 95 115 80 287 109 239 196" ;;
	2) echo "30 226 16 177 82 192 31 65 151 64 285 72 256 198" ;;
	3) echo "28 226 14 178 83 193 72 62 153 94 288 91 243 189" ;;
	4) echo "30 230 16 172 82 191 137 71 182 70 287 65 261 177" ;;
	5) echo "30 248 16 181 98 204 128 55 198 40 287 36 285 184" ;;
	esac
}
# camel_vertices RINGS POSE: the landmarks' vertex indices, one a line
camel_vertices() {
	camel_landmarks $2 | tr ' ' '\n' | paste -d' ' - - | awk 'NR == FNR { if (FNR > 1) { x[n] = $1; y[n] = $2; n++ } next }
	{ b = -1; for (i = 0; i < n; i++) { d = ($1 - x[i]) ^ 2 + ($2 - y[i]) ^ 2; if (b < 0 || d < bd) { bd = d; b = i } }
	  if (bd > 36) { print "landmark far from the outline" >"/dev/stderr"; exit 1 } print b }' "$1" -
}

# arc_error_max RINGS PAIRS: the largest arc distance (% of the perimeter of
# the single ring of RINGS) between the two vertex indices of a row of PAIRS
arc_error_max() {
	awk 'NR == FNR { if (FNR > 1) { x[n] = $1; y[n] = $2; n++ } next }
	FNR == 1 { c[0] = 0; for (i = 0; i < n; i++) { j = (i + 1) % n; c[i + 1] = c[i] + sqrt((x[j] - x[i]) ^ 2 + (y[j] - y[i]) ^ 2) } L = c[n] }
	{ d = c[$1] - c[$2]; if (d < 0) d = -d; if (L - d < d) d = L - d; if (d > m) m = d }
	END { printf "%.2f\n", 100 * m / L }' "$1" "$2"
}

# every_subset LM RINGS ROWS [compat-tri options]: compat-tri on every subset
# of 2..6 of six poses; LM and RINGS are printf patterns of the pose number
# 0-5 (e.g. horselm%d, horse%d.rings), ROWS a sed script picking the rows of
# the pasted landmark files ("p": all).  Prints "ok total worst": the worst
# angle over every triangle of every mesh made; failures on stderr.
every_subset() {
	lmf=$1 rf=$2 rows=$3 && shift 3 && ok=0 tot=0 worst=90 mask=3 &&
	while [ $mask -lt 64 ]; do
		cols= files=
		for k in 0 1 2 3 4 5; do
			if [ $(((mask >> k) & 1)) = 1 ]; then
				cols="$cols $(printf "$lmf" $k)" files="$files $(printf "$rf" $k)"
			fi
		done
		case $cols in *" "*" "*)
			tot=$((tot + 1))
			paste -d" " $cols | sed -n "$rows" >sub.corr
			if compat-tri "$@" -c sub.corr $files >sub.mesh 2>sub.err && test_le 1e-12 $(min_area sub.mesh)
			then
				ok=$((ok + 1))
				worst=$(awk -v a=$(worst_angle sub.mesh) -v b=$worst "BEGIN { print (a < b ? a : b) }")
			else echo "poses$files: $(tail -1 sub.err)" >&2; fi ;;
		esac
		mask=$((mask + 1))
	done &&
	echo "$ok $tot $worst"
}

# stick_pose CHAR K: CHARK.rings (t0587's generated character CHAR, horse
# or flamingo, pose K traced by img2rings) and CHARlmK (its seven
# landmarks as vertex indices in outline order, each within 4 pixels)
stick_pose() {
	awk -v char=$1 -v pose=$2 -v lm=pts$2 -f "$TEST_DIRECTORY/t0587-stick-character.awk" >$1$2.ppm &&
	img2rings -1 -s 1 -o $1$2.rings $1$2.ppm &&
	awk 'NR == FNR { if (FNR > 1) { x[n] = $1; y[n] = $2; n++ } next }
	{ b = -1; for (i = 0; i < n; i++) { d = ($2 - x[i]) ^ 2 + ($3 - y[i]) ^ 2; if (b < 0 || d < bd) { bd = d; b = i } }
	  if (bd > 16) { print $1 " far from the outline" >"/dev/stderr"; exit 1 } print b }' $1$2.rings pts$2 >$1lm$2
}

# stick_layer_pose CHAR K LANDMARK: the stick CHAR of pose K without its
# leg 0 (bodyK.rings) and that leg alone (legK.rings), both traced;
# layersK.rings: body then leg (for compat-tri --layers); rowsK: the
# landmarks other than LANDMARK (the leg's: hoof0, toe0) as indices into
# bodyK.rings, in CHARlm order; rows5K: the same of stick_rows's five
stick_layer_pose() {
	awk -v char=$1 -v pose=$2 -v lm=pts$2 -v omit=0 -f "$TEST_DIRECTORY/t0587-stick-character.awk" >body$2.ppm &&
	awk -v char=$1 -v pose=$2 -v lm=/dev/null -v only=0 -f "$TEST_DIRECTORY/t0587-stick-character.awk" >leg$2.ppm &&
	img2rings -1 -s 1 -o body$2.rings body$2.ppm &&
	img2rings -1 -s 1 -o leg$2.rings leg$2.ppm &&
	cat body$2.rings leg$2.rings >layers$2.rings &&
	awk -v leg=$3 'NR == FNR { if (FNR > 1) { x[n] = $1; y[n] = $2; n++ } next }
	$1 != leg { b = -1; for (i = 0; i < n; i++) { d = ($2 - x[i]) ^ 2 + ($3 - y[i]) ^ 2; if (b < 0 || d < bd) { bd = d; b = i } }
	  if (bd > 16) { print $1 " far from the outline" >"/dev/stderr"; exit 1 }
	  print b >"rows" pose; if (FNR == 1 || FNR == 3 || FNR >= 5) print b >"rows5" pose }' pose=$2 body$2.rings pts$2
}

# stick_poses CHAR K...: stick_pose CHAR K for each K
stick_poses() {
	sp_char=$1; shift
	for sp_k in "$@"; do stick_pose $sp_char $sp_k || return 1; done
}

# outline_within MESH RING...: every frame's outline (frame k against the
# k-th RING) within compat-tri's default tolerance, 0.005 of the diagonal
outline_within() {
	ow_mesh=$1; shift
	ow_k=0
	for ow_ring in "$@"; do
		test_le $(outline_error $ow_mesh $ow_ring $ow_k) 0.005000001 || return 1
		ow_k=$((ow_k + 1))
	done
}

# stick_rows CHAR K...: on stdout, the five given rows the stick-character
# tests use (landmarks 1 3 5 6 7 of CHARlmK, one column per pose K, after
# stick_pose): the two feet, the head, the neck and the tail
stick_rows() {
	sr_char=$1; shift
	sr_files=
	for sr_k in "$@"; do sr_files="$sr_files ${sr_char}lm$sr_k"; done
	paste -d" " $sr_files | sed -n "1p;3p;5p;6p;7p"
}

# outline_error MESH RING POSE: two-sided Hausdorff distance between frame
# POSE's boundary polygon (edges in one triangle only) and RING, over the
# ring's bounding-box diagonal (the ring's vertices to the polygon; the
# polygon's vertices and 16 points on each of its edges to the ring)
outline_error() {
	awk -v pose=$3 'BEGIN { n = 0 } function sd(px, py, ax, ay, bx, by,  dx, dy, l, t) {
		dx = bx - ax; dy = by - ay; l = dx * dx + dy * dy; t = l > 0 ? ((px - ax) * dx + (py - ay) * dy) / l : 0
		if (t < 0) t = 0; if (t > 1) t = 1; return sqrt((ax + t * dx - px) ^ 2 + (ay + t * dy - py) ^ 2) }
	FILENAME == ARGV[1] {
		if ($1 == "f") { for (k = 0; k < 3; k++) E[$(2 + k) " " $(2 + (k + 1) % 3)] = 1; next }
		if ($1 == "frame") { fr = $2; k = 0; next }
		if (fr == pose && NF == 3) { X[k] = $1; Y[k] = $2; k++ }
		next }
	FNR == 1 { next }
	{ PX[n] = $1; PY[n] = $2; n++ }
	END { for (e in E) { split(e, v, " "); if (!((v[2] " " v[1]) in E)) S[v[1]] = v[2] }
		lx = hx = PX[0]; ly = hy = PY[0]
		for (i = 0; i < n; i++) { if (PX[i] < lx) lx = PX[i]; if (PX[i] > hx) hx = PX[i]; if (PY[i] < ly) ly = PY[i]; if (PY[i] > hy) hy = PY[i] }
		h = 0
		for (i = 0; i < n; i++) { d = 1e300; for (a in S) { b = S[a]; x = sd(PX[i], PY[i], X[a], Y[a], X[b], Y[b]); if (x < d) d = x } if (d > h) h = d }
		for (a in S) { b = S[a]; for (t = 0; t < 16; t++) { qx = X[a] + t / 16 * (X[b] - X[a]); qy = Y[a] + t / 16 * (Y[b] - Y[a]); d = 1e300
			for (i = 0; i < n; i++) { j = (i + 1) % n; x = sd(qx, qy, PX[i], PY[i], PX[j], PY[j]); if (x < d) d = x } if (d > h) h = d } }
		printf "%.9f\n", h / sqrt((hx - lx) ^ 2 + (hy - ly) ^ 2) }' "$1" "$2"
}
# given_on_vertices MESH CORR RING...: every given row a vertex at its input point in every frame
given_on_vertices() {
	gm=$1 gc=$2; shift 2
	awk -v nr=$# 'FILENAME == ARGV[1] { if ($1 == "frame") { fr = $2; k = 0; next }
		if (fr != "" && NF == 3) { X[fr, k] = $1; Y[fr, k] = $2; k++ } next }
	FILENAME == ARGV[2] { for (s = 0; s < NF; s++) C[FNR - 1, s] = $(s + 1); nc = FNR; next }
	FNR == 1 { ri++; next }
	{ PX[ri - 1, FNR - 2] = $1; PY[ri - 1, FNR - 2] = $2 }
	END { for (s = 0; s < nr; s++) for (c = 0; c < nc; c++) { i = C[c, s]; f = 0
		for (w = 0; (s, w) in X; w++) if (X[s, w] == PX[s, i] && Y[s, w] == PY[s, i]) f = 1
		if (!f) { print "pose " s ": given row " c + 1 " is not a vertex at its point"; bad = 1 } }
		exit bad }' "$gm" "$gc" "$@"
}

# same_bytes_threads ARGS...: compat-tri ARGS gives the same bytes with
# --threads 1, 2 and 3
same_bytes_threads() {
	compat-tri --threads 1 "$@" >sbt1.mesh &&
	compat-tri --threads 2 "$@" >sbt2.mesh &&
	compat-tri --threads 3 "$@" >sbt3.mesh &&
	test_cmp sbt1.mesh sbt2.mesh && test_cmp sbt1.mesh sbt3.mesh
}

# check a plain MESH stream of N frames against the input ring files:
# every triangle positive in every frame (> 0 as printed), every
# correspondence row (global vertex indices) and every interior point a
# vertex at exactly its input position, the triangles' area equal to the
# rings' (PIECES, 1-based ring numbers, minus the other rings) within REL
# (0: to 1e-9, and every input vertex must be a mesh vertex), COMP
# connected components
check_holes() {   # check_holes MESH CORR PTS REL COMP PIECES RING...
	ch_mesh=$1 ch_corr=$2 ch_pts=$3 ch_rel=$4 ch_comp=$5 ch_pieces=$6; shift 6
	awk -v nr=$# -v rel="$ch_rel" -v comp="$ch_comp" -v pieces="$ch_pieces" '
	function flush() { if (rs) { a = 0; for (i = 0; i < rs; i++) { j = (i + 1) % rs; a += RX[i] * RY[j] - RX[j] * RY[i] }
		a = (a > 0 ? a : -a) / 2; A[ri] += (rk in PC) ? a : -a }; rs = 0 }
	function find(x) { while (P[x] != x) x = P[x] = P[P[x]]; return x }
	BEGIN { ri = -1; nf = 0; rs = 0; np = split(pieces, pp, " "); for (i = 1; i <= np; i++) PC[pp[i]] = 1 }
	FILENAME == ARGV[1] {
		if ($1 == "f") { F0[nf] = $2; F1[nf] = $3; F2[nf] = $4; nf++; next }
		if ($1 == "frame") { fr = $2; k = 0; next }
		if (fr != "" && NF == 3) { X[fr, k] = $1; Y[fr, k] = $2; V[fr, $1 " " $2] = 1; k++; nv = k }
		next }
	FILENAME == ARGV[2] { for (s = 0; s < NF; s++) C[FNR - 1, s] = $(s + 1); nc = FNR; next }
	FILENAME == ARGV[3] { for (s = 0; s < NF / 2; s++) { QX[FNR - 1, s] = $(2 * s + 1); QY[FNR - 1, s] = $(2 * s + 2) }; nq = FNR; next }
	FNR == 1 { flush(); ri++; pi = 0; rk = 0 }
	$1 == "ring" { flush(); rk++; next }
	{ PX[ri, pi] = $1; PY[ri, pi] = $2; RX[rs] = $1; RY[rs] = $2; rs++; pi++; NP[ri] = pi }
	END { flush(); bad = 0; tol = rel ? rel : 1e-9
		for (s = 0; s < nr; s++) { tot = 0
			for (t = 0; t < nf; t++) {
				a = (X[s,F1[t]]-X[s,F0[t]])*(Y[s,F2[t]]-Y[s,F0[t]]) - (Y[s,F1[t]]-Y[s,F0[t]])*(X[s,F2[t]]-X[s,F0[t]])
				if (!(a > 0)) { print "frame " s ": triangle " t " has area " a; bad = 1 }
				tot += a / 2 }
			d = tot - A[s]
			if (!(d < tol * A[s] && -d < tol * A[s])) { print "frame " s ": mesh area " tot ", rings " A[s]; bad = 1 }
			for (c = 0; c < nc; c++) { i = C[c, s]
				if (!((s, PX[s, i] " " PY[s, i]) in V)) { print "shape " s ": correspondence " c " (vertex " i ") is not a mesh vertex"; bad = 1 } }
			for (c = 0; c < nq; c++)
				if (!((s, QX[c, s] " " QY[c, s]) in V)) { print "shape " s ": interior point " c " is not a mesh vertex"; bad = 1 }
			if (!rel) for (i = 0; i < NP[s]; i++)
				if (!((s, PX[s, i] " " PY[s, i]) in V)) { print "shape " s ": input vertex " i " is not a mesh vertex"; bad = 1 } }
		for (v = 0; v < nv; v++) P[v] = v
		for (t = 0; t < nf; t++) { P[find(F0[t])] = find(F1[t]); P[find(F1[t])] = find(F2[t]) }
		for (t = 0; t < nf; t++) if (!(find(F0[t]) in R)) { R[find(F0[t])] = 1; nco++ }
		if (nco != comp) { print nco " components, expected " comp; bad = 1 }
		exit bad }' "$ch_mesh" "$ch_corr" "$ch_pts" "$@"
}
