#!/bin/sh
test_description='compat-tri with no correspondence point on silhouettes traced from renders (camel gallop, five frames)'
. "$(dirname "$0")/test-lib.sh"
need_shared_data scans/camel-gallop-05.off

# The generator: each gallop frame (remeshed separately) rendered from the
# side as a black silhouette, traced by img2rings (148-198 outline points).
test_expect_success 'generate five camel poses: mesh-import | mesh-render | img2rings' '
	for i in 1 2 3 4 5; do
		mesh-import "$SHARED_DATA/scans/camel-gallop-0$i.off" |
		mesh-render -V right -s 300x300 -c 0,0,0 --flat -f ppm >camel$i.ppm &&
		img2rings -1 -s 1 -o camel$i.rings camel$i.ppm || return 1
	done &&
	for i in 1 2 3 4 5; do n=$(sed -n "s/^ring //p" camel$i.rings); test $n -ge 100 || return 1; done
'
test_expect_success 'every pair and every triple of poses: compatible meshes without a single click' '
	fail=0 &&
	for s in "1 2" "1 3" "1 4" "1 5" "2 3" "2 4" "2 5" "3 4" "3 5" "4 5" \
		 "1 2 3" "1 2 4" "1 2 5" "1 3 4" "1 3 5" "1 4 5" "2 3 4" "2 3 5" "2 4 5" "3 4 5"; do
		f= && for i in $s; do f="$f camel$i.rings"; done &&
		if compat-tri --points-out p.txt $f >m.mesh 2>err; then
			k=$(echo $s | wc -w) &&
			grep -q "^frames $k" m.mesh && test $(grep -vc "^#" p.txt) -ge 10 || fail=$((fail + 1))
		else echo "poses $s: $(cat err)"; fail=$((fail + 1)); fi
	done &&
	echo "failed: $fail of 20" && test $fail -eq 0
'
test_expect_success 'five points at most (--match-points 5): pairs still compatible' '
	for s in "1 2" "2 4" "3 5"; do
		set -- $s && compat-tri --match-points 5 --points-out p5.txt camel$1.rings camel$2.rings >m5.mesh &&
		test $(grep -vc "^#" p5.txt) -le 5 || return 1
	done
'
test_done
