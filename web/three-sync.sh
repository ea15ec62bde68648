#!/bin/sh
# three-sync.sh OUTDIR -- copy three.js from node_modules/three (npm, installed
# by `make deps`) to OUTDIR for anim-view to build in (libcommon/web_assets.c).
# Files are rewritten only when their content changes, so make rebuilds
# exactly when `three` appears, disappears or changes version (npm unpacks
# with old timestamps, which mtimes alone would miss).  Without the package
# the files are empty and anim-view refuses to write pages, saying why.
set -u
out=$1
src=node_modules/three
mkdir -p "$out" || exit 1
put() {   # put NAME: move $out/NAME.new into place if it differs
    if cmp -s "$out/$1.new" "$out/$1"; then rm -f "$out/$1.new"; else mv -f "$out/$1.new" "$out/$1"; fi
}
if [ -f "$src/build/three.core.js" ] && [ -f "$src/build/three.module.js" ] &&
   [ -f "$src/examples/jsm/controls/OrbitControls.js" ]; then
    # one import map holds both modules: the relative import becomes a bare name
    sed "s#from '\./three\.core\.js'#from 'three-core'#" "$src/build/three.module.js" >"$out/three.module.js.new"
    cp "$src/build/three.core.js" "$out/three.core.js.new"
    cp "$src/examples/jsm/controls/OrbitControls.js" "$out/OrbitControls.js.new"
    sed -n 's/^ *"version": *"\([^"]*\)".*/\1/p' "$src/package.json" | head -n 1 >"$out/three.version.new"
else
    echo "anim-view: npm package 'three' not found in node_modules (run 'make deps'); anim-view is built without it and will refuse to write pages" >&2
    for f in three.module.js three.core.js OrbitControls.js three.version; do : >"$out/$f.new"; done
fi
for f in three.module.js three.core.js OrbitControls.js three.version; do put $f; done
