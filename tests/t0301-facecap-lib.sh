#!/bin/sh
test_description='dict-learn on facecap (lower part, d = 20, lambda = 2) vs lib-uniform, lambda = 0'
. "$(dirname "$0")/test-lib.sh"
need_shared_data anim/facecap-335.tar.xz

# "lower part": faces whose centroid is below 75% of the average face's
# height (y); the static neck is included and costs nothing.
test_expect_success 'setup: facecap OBJ frames -> lower part MESH' '
	mkdir fc && tar -xJf "$SHARED_DATA/anim/facecap-335.tar.xz" -C fc &&
	mesh-import --raw "fc/*/frame_*.obj" >face.mesh && rm -rf fc &&
	anim-avg face.mesh >avg.mesh &&
	awk -v frac=0.75 -f "$TEST_DIRECTORY/lower-part.awk" avg.mesh >part.lab &&
	part-split -l part.lab -p 1 --raw face.mesh >lower.mesh &&
	mesh-info lower.mesh | grep "^frames 335$"
'
test_expect_success 'dict-learn beats uniform sampling with optimal labels (printed factor)' '
	dict-learn -d 20 --lambda 2 --seed 1 --report rep2 --labels-out l2 lower.mesh >lib2.mesh &&
	lib-uniform -d 20 lower.mesh >uni.lib &&
	label-expand -q --lambda 2 --report repu uni.lib lower.mesh >lu &&
	e=$(awk "/^energy /{print \$2}" rep2) && u=$(awk "/^energy /{print \$2}" repu) &&
	awk -v e="$e" -v u="$u" "BEGIN { printf \"facecap lower d=20 lambda=2: dict-learn %g, lib-uniform+DP %g, factor %.2f\n\", e, u, u / e }" >"$TRASH/factor" &&
	test_le "$e" "$u"
'
[ -s "$TRASH/factor" ] && say "# $(cat "$TRASH/factor")"
test_expect_success 'lambda > 0 has lower velocity error than lambda = 0 (Fig. 19)' '
	dict-learn -d 20 --lambda 0 --seed 1 --report rep0 lower.mesh >lib0.mesh &&
	v0=$(awk "/^velocity /{print \$2}" rep0) && v2=$(awk "/^velocity /{print \$2}" rep2) &&
	m0=$(awk "/^mean_velocity_error /{print \$2}" rep0) && m2=$(awk "/^mean_velocity_error /{print \$2}" rep2) &&
	echo "facecap lower d=20 velocity term: lambda 0 $v0 (mean vertex $m0), lambda 2 $v2 (mean vertex $m2)" >"$TRASH/vel" &&
	test_le "$v2" "$v0" && test_le "$m2" "$m0"
'
[ -s "$TRASH/vel" ] && say "# $(cat "$TRASH/vel")"
test_expect_success 'alpha-expansion labels are never below the exact DP' '
	label-expand -q -m dp --report rd lib2.mesh lower.mesh >ld &&
	label-expand -q -m expansion --report re uni.lib lower.mesh >le &&
	a=$(awk "/^energy /{print \$2}" re) && b=$(awk "/^energy /{print \$2}" repu) &&
	echo "uniform library: expansion $a, dp $b" && test_le "$b" "$a"
'
test_expect_success 'the same --seed gives the same bytes' '
	dict-learn -d 20 --lambda 2 --seed 1 --labels-out l2b lower.mesh >lib2b.mesh &&
	test_cmp lib2.mesh lib2b.mesh && test_cmp l2 l2b
'
test_done
