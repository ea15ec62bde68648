#!/bin/sh
test_description='--swap-cost on facecap (lower part, d = 20, lambda = 2): swaps against error on real capture'
. "$(dirname "$0")/test-lib.sh"
need_shared_data anim/facecap-335.tar.xz

key() { awk -v k="$1" '$1 == k { print $2 }' "$2"; }

test_expect_success 'setup: facecap OBJ frames -> lower part MESH' '
	mkdir fc && tar -xJf "$SHARED_DATA/anim/facecap-335.tar.xz" -C fc &&
	mesh-import --raw "fc/*/frame_*.obj" >face.mesh && rm -rf fc &&
	anim-avg face.mesh >avg.mesh &&
	awk -v frac=0.75 -f "$TEST_DIRECTORY/lower-part.awk" avg.mesh >part.lab &&
	part-split -l part.lab -p 1 --raw face.mesh >lower.mesh
'
# the energy per frame is about 2e5 here: swap costs from 1/10 to 100 times it
test_expect_success 'dict-learn --swap-sweep: swaps fall, error rises, monotone' '
	dict-learn -d 20 --seed 1 --report rep --swap-sweep 0,3e5,3e6,1e7,3e7 lower.mesh >sweep &&
	awk "!/^#/ { if (n++ && (\$2 > s || \$3 < e)) exit 1; s = \$2; e = \$3 }" sweep &&
	s0=$(awk "\$1 == 0 { print \$2 }" sweep) && s3=$(awk "\$1 == 3e+07 { print \$2 }" sweep) &&
	test "$s3" -lt "$s0" &&
	awk "!/^#/ { printf \"%s%s: %d swaps, mean error %.3g\", n++ ? \"; \" : \"\", \$1, \$2, \$6 }" sweep >"$TRASH/fig"
'
[ -s "$TRASH/fig" ] && say "# facecap lower d=20, swap cost: $(cat "$TRASH/fig")"
test_expect_success 'label-expand with the learned library agrees with dict-learn --swap-cost' '
	dict-learn -d 20 --seed 1 --swap-cost 1e7 --report r7 --labels-out l7 lower.mesh >lib.mesh &&
	label-expand -q --swap-cost 1e7 --report x7 lib.mesh lower.mesh >x7l &&
	cmp l7 x7l && test "$(key swaps r7)" = "$(awk "\$1 == 1e+07 { print \$2 }" sweep)"
'
test_done
