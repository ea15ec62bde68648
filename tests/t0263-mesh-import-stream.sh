#!/bin/sh
test_description='mesh-import of an OBJ sequence streams: memory O(one frame), nothing half-written'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'setup: 60 OBJ frames of an 11,712-vertex animation' '
	mesh-gen -f 60 -n 96 -m 121 cylinder >cyl.mesh &&
	mkdir -p fr && mesh-export -o "fr/f_%03d.obj" cyl.mesh &&
	test "$(ls fr | wc -l)" = 60
'

test_expect_success 'the sequence imports to the same positions and faces, one frame per file' '
	mesh-import "fr/f_*.obj" >seq.mesh &&
	mesh-info seq.mesh >info && grep "^frames 60$" info &&
	anim-diff -s cyl.mesh seq.mesh >d && awk "\$1 == \"max\" { exit \$2 > 1e-12 }" d &&
	mesh-import --raw "fr/f_*.obj" >seq.raw && anim-slice seq.raw >seq2.mesh && test_cmp seq.mesh seq2.mesh &&
	mesh-import --weld "fr/f_*.obj" >w.mesh && mesh-info w.mesh | grep "^frames 60$"
'

test_expect_success 'a bad last frame: exit 1, one line naming it, nothing on stdout' '
	head -n 40 fr/f_059.obj >fr/f_060.obj &&
	test_fails_cleanly mesh-import "fr/f_*.obj" 2>err &&
	grep -q "f_060.obj" err && rm fr/f_060.obj
'

test_expect_success 'memory does not grow with the frames (peak resident set, 10 vs 60 frames)' '
	if [ -n "${STOPMO_SANITIZE:-}" ]; then echo "ASan holds freed memory in quarantine: measured in the normal build"; exit 0; fi &&
	/usr/bin/time -f %M -o m10 mesh-import --raw "fr/f_00*.obj" >/dev/null &&
	/usr/bin/time -f %M -o m60 mesh-import --raw "fr/f_*.obj" >/dev/null &&
	echo "peak KB: 10 frames $(cat m10), 60 frames $(cat m60)" &&
	test "$(cat m60)" -lt "$(($(cat m10) * 3 / 2))"
'

test_done
