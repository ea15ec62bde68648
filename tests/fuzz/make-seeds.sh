#!/bin/sh
# make-seeds.sh BIN -- (re)make the seed corpora of the fuzz harnesses in
# tests/fuzz/corpus/NAME/ with the project's own tools (mesh-gen,
# mesh-export, gltf-morph.pl).  Small inputs: the fuzzers mutate them.
set -eu
BIN=${1:-$(dirname "$0")/../../bin}
D=$(cd "$(dirname "$0")" && pwd)/corpus
T=$(mktemp -d)
trap 'rm -rf "$T"' EXIT
mkdir -p "$D/mesh" "$D/meshio" "$D/gltf" "$D/columns" "$D/rings" "$D/compat"
# MESH: plain and raw, one and several frames, cut marks, "frames ?"
"$BIN/mesh-gen" -n 1 grid >"$D/mesh/grid1.mesh"
"$BIN/mesh-gen" --raw -n 1 grid >"$D/mesh/grid1-raw.mesh"
"$BIN/mesh-gen" -f 3 -n 2 -m 1 --cut-every 2 cylinder >"$D/mesh/cyl-cut.mesh"
"$BIN/mesh-gen" --raw -f 2 -n 2 -m 1 cylinder >"$D/mesh/cyl-raw.mesh"
sed 's/^frames 3$/frames ?/' "$D/mesh/cyl-cut.mesh" >"$D/mesh/cyl-q.mesh"
printf 'MESH 1\n# comment\nvertices 3\nfaces 1\nframes 1\nf 0 1 2\nframe 0\n0.1 -2e-3 1e+5\n1 0 0\n0 1 0\n' >"$D/mesh/tri.mesh"
# OBJ, OFF, PLY, STL (first byte: 0 obj, 1 off, 2 ply, 3 stl)
"$BIN/mesh-gen" -s 0 icosphere >"$T/ico.mesh"
"$BIN/mesh-gen" -n 1 grid >"$T/g.mesh"
for f in obj off; do "$BIN/mesh-export" -o "$T/ico.$f" "$T/ico.mesh"; done
"$BIN/mesh-export" -o "$T/ico.ply" "$T/ico.mesh"
"$BIN/mesh-export" --ascii -o "$T/icoa.ply" "$T/g.mesh"
"$BIN/mesh-export" -o "$T/ico.stl" "$T/g.mesh"
"$BIN/mesh-export" --ascii -o "$T/icoa.stl" "$T/g.mesh"
{ printf '\000'; cat "$T/ico.obj"; } >"$D/meshio/ico.obj"
{ printf '\000'; printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nf 1/1 2/1 3/1 4/1\nf -4 -2 -1\n'; } >"$D/meshio/quad.obj"
{ printf '\001'; cat "$T/ico.off"; } >"$D/meshio/ico.off"
{ printf '\002'; cat "$T/ico.ply"; } >"$D/meshio/ico.ply"
{ printf '\002'; cat "$T/icoa.ply"; } >"$D/meshio/grid-ascii.ply"
{ printf '\003'; cat "$T/ico.stl"; } >"$D/meshio/grid.stl"
{ printf '\003'; cat "$T/icoa.stl"; } >"$D/meshio/grid-ascii.stl"
# glTF: the small morph animation with normalized uint8 weights
perl "$D/../../gltf-morph.pl" >"$D/gltf/morph.gltf"
perl "$D/../../gltf-morph.pl" 4 16 >"$D/gltf/morph-stride.gltf"
# columns, labels, landmarks
printf '0\n1\n1\n# comment\n2\n' >"$D/columns/labels.txt"
printf '0.5, 1e-3\n2 3\n' >"$D/columns/csv.txt"
printf '1 2\n3 4\n5 6\n' >"$D/columns/landmarks2.txt"
printf '1 0.5 0.25 -1\n3 0 0 1e3\n' >"$D/columns/landmarks4.txt"
# rings: an outline with a hole; compat: two outlines separated by "--"
printf 'ring 4\n0 0\n4 0\n4 4\n0 4\nring 3\n1 1\n1 2\n2 1\n' >"$D/rings/hole.rings"
printf '# a triangle\nring 3\n0 0\n1 0\n0 1\n' >"$D/rings/tri.rings"
printf 'ring 6\n0 0\n2 0\n3 1\n2 2\n0 2\n-1 1\n--\nring 6\n0 0\n2 -1\n4 1\n2 3\n0 2\n-2 1\n' >"$D/compat/hex.txt"
printf 'ring 8\n0 0\n3 0\n3 1\n1 1\n1 2\n3 2\n3 3\n0 3\n--\nring 8\n0 0\n3 0\n3 1.5\n2 1.5\n2 1.7\n3 1.7\n3 3\n0 3\n' >"$D/compat/notch.txt"
