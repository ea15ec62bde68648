# merged-head-lib.sh -- a multi-component test head that a fresh clone can
# build (t0254-t0269), sourced after test-lib.sh.
#
# merged_head FRAMES OUT.mesh: head-gen's talking head (subdivision 3) as an
# OBJ frame sequence, each frame with two separate eyeball spheres appended
# (mesh-gen icospheres of radius 0.075 sitting in the eye sockets, static),
# imported back with mesh-import: one MESH animation with three connected
# components, the head's vertices and faces first.  Like a production rig
# exported frame by frame (skin, eyes), and the eyes carry no seed.
merged_head() {
	head-gen -f "$1" -s 3 --clips 1 >mh-head.mesh &&
	mkdir -p mh-frames && rm -f mh-frames/*.obj &&
	mesh-export -o 'mh-frames/head_%03d.obj' mh-head.mesh &&
	mesh-gen -s 2 icosphere >mh-eye.mesh &&
	mesh-export -o mh-eye.obj mh-eye.mesh &&
	for f in mh-frames/head_*.obj; do
		awk -v r=0.075 '
			NR == FNR { if ($1 == "v") { ne++; ex[ne] = $2; ey[ne] = $3; ez[ne] = $4 }
				    if ($1 == "f") { nfc++; fa[nfc] = $2; fb[nfc] = $3; fc[nfc] = $4 }
				    next }
			{ print; if ($1 == "v") nv++ }
			END { if (!ne || !nv) exit 1
			      for (e = -1; e <= 1; e += 2) {
				for (i = 1; i <= ne; i++)
					printf "v %.9g %.9g %.9g\n", ex[i] * r + 0.194 * e, ey[i] * r + 0.22, ez[i] * r + 0.72
				for (i = 1; i <= nfc; i++)
					printf "f %d %d %d\n", fa[i] + nv, fb[i] + nv, fc[i] + nv
				nv += ne } }' mh-eye.obj "$f" >"$f.tmp" || return 1
		mv "$f.tmp" "$f" || return 1
	done &&
	mesh-import 'mh-frames/head_*.obj' >"$2"
}
