#!/bin/sh
test_description='mesh-render on real data: the cow (spot.obj) is plainly visible'
. "$(dirname "$0")/test-lib.sh"
need_shared_data meshes/spot.obj

# coverage (fraction of non-white pixels), distinct luminance levels and
# luminance spread of the object in a P6 PPM
ppm_stats() {
	set -- "$1" $(head -c 20 "$1" | tr '\n' ' ' | cut -d' ' -f2,3)
	hdr=$(printf 'P6\n%s %s\n255\n' "$2" "$3" | wc -c)
	tail -c +$((hdr + 1)) "$1" | od -An -v -tu1 | awk '
	{ for (i = 1; i <= NF; i++) { c[k++] = $i; if (k == 3) { px(); k = 0 } } }
	function px(  l) {
		n++
		if (c[0] == 255 && c[1] == 255 && c[2] == 255) return
		l = int(0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2])
		obj++; lev[l] = 1; s += l; s2 += l * l
	}
	END { nl = 0; for (x in lev) nl++; m = s / obj
		printf "%.4f %d %.2f\n", obj / n, nl, sqrt(s2 / obj - m * m) }'
}

test_expect_success 'import spot.obj' '
	mesh-import "$SHARED_DATA/meshes/spot.obj" >spot.mesh
'
test_expect_success 'default render is an 800x800 PNG' '
	mesh-render --view iso -o spot.png spot.mesh &&
	od -An -tu1 -j16 -N8 spot.png | awk "{ print \$1*16777216 + \$2*65536 + \$3*256 + \$4, \$5*16777216 + \$6*65536 + \$7*256 + \$8 }" >size &&
	echo "800 800" >expect && test_cmp expect size
'
test_expect_success 'the cow covers a sensible part of the image and is shaded' '
	mesh-render --view iso -s 200x200 -f ppm spot.mesh >spot.ppm &&
	st=$(ppm_stats spot.ppm) && echo "$st" &&
	set -- $st && test_le 0.15 $1 && test_le $1 0.7 && test_le 40 $2 && test_le 15 $3
'
test_expect_success 'every named view shows the cow' '
	for v in front back left right top bottom; do
		mesh-render --view $v -s 100x100 -f ppm spot.mesh >v.ppm || return 1
		set -- $(ppm_stats v.ppm) && test_le 0.08 $1 || return 1
	done
'
test_done
