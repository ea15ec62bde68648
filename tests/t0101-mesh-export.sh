#!/bin/sh
test_description='mesh-export: formats, frames, numbered files, nothing half-written'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'one frame to stdout is OBJ' '
	mesh-gen -n 2 grid >g.mesh &&
	mesh-export g.mesh >g.obj &&
	test $(grep -c "^v " g.obj) -eq 9 && test $(grep -c "^f " g.obj) -eq 8 &&
	mesh-export <g.mesh >g2.obj && test_cmp g.obj g2.obj
'

test_expect_success 'format from the extension or --format' '
	mesh-export -o g.off g.mesh && head -1 g.off >magic && echo OFF >expect && test_cmp expect magic &&
	mesh-export -o g.ply g.mesh && head -c 3 g.ply >magic && printf ply >expect && test_cmp expect magic &&
	mesh-export -o g.stl g.mesh && test $(wc -c <g.stl) -eq $((84 + 50 * 8)) &&
	mesh-export -f off g.mesh >g2.off && test_cmp g.off g2.off &&
	mesh-export -f stl -o g.bin g.mesh && cmp g.stl g.bin
'

test_expect_success 'OFF round trip is exact' '
	mesh-gen -s 1 icosphere >i.mesh && mesh-export -o i.off i.mesh &&
	mesh-import i.off >i2.mesh && test_cmp i.mesh i2.mesh
'

test_expect_success 'an animation to numbered OBJ files' '
	mesh-gen -f 5 -a wave grid >a.mesh &&
	mkdir out && mesh-export -o "out/f_%04d.obj" a.mesh &&
	ls out >actual &&
	printf "f_0000.obj\nf_0001.obj\nf_0002.obj\nf_0003.obj\nf_0004.obj\n" >expect &&
	test_cmp expect actual &&
	mesh-import "out/f_*.obj" >back.mesh && test_cmp a.mesh back.mesh
'

test_expect_success '--frame K picks one frame' '
	mesh-export -k 3 a.mesh >f3.obj && cmp f3.obj out/f_0003.obj &&
	test_fails_cleanly mesh-export -k 9 a.mesh
'

test_expect_success 'several frames and a single file is an error, nothing written' '
	test_fails_cleanly mesh-export -o one.obj a.mesh &&
	test ! -e one.obj && ! ls one.obj.tmp* 2>/dev/null
'

test_expect_success 'a stream broken midway leaves only complete files' '
	mesh-gen -f 4 grid >b.mesh &&
	head -n $(( $(wc -l <b.mesh) - 3 )) b.mesh >broken.mesh &&
	mkdir bo && test_must_fail mesh-export -o "bo/x_%d.obj" broken.mesh &&
	ls bo >actual && printf "x_0.obj\nx_1.obj\nx_2.obj\n" >expect && test_cmp expect actual
'

test_expect_success 'bad input and usage errors' '
	test_fails_cleanly mesh-export nope.mesh &&
	echo "garbage" >bad.mesh && test_fails_cleanly mesh-export bad.mesh &&
	test_must_fail_usage mesh-export -o x.xyz g.mesh &&
	test_must_fail_usage mesh-export -f xyz g.mesh &&
	test_must_fail_usage mesh-export -o "a_%s.obj" g.mesh &&
	test_must_fail_usage mesh-export -k 1 -o "a_%d.obj" g.mesh &&
	mesh-export --help >help && grep -q "^Usage: mesh-export" help
'
test_done
