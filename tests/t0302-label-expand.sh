#!/bin/sh
test_description='label-expand and lib-uniform: fixed-library labels, uniform baseline'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'setup' '
	mesh-gen -f 60 -a wave -n 6 --cut-every 30 grid >anim.mesh
'
test_expect_success 'lib-uniform -d takes evenly spaced frames; -k every k-th' '
	lib-uniform -d 6 --labels-out hold anim.mesh >u.lib &&
	grep "^frames 6$" u.lib &&
	lib-uniform -k 7 anim.mesh >k.lib && grep "^frames 9$" k.lib &&
	test $(wc -l <hold) -eq 60 && test "$(sed -n 11p hold)" = 1
'
test_expect_success 'label-expand gives one label per frame, energy on stderr' '
	label-expand u.lib anim.mesh >lab 2>err &&
	test $(wc -l <lab) -eq 60 && grep "energy" err
'
test_expect_success 'DP labels are optimal: never above hold labels or expansion/swap' '
	label-expand -q --report rd u.lib anim.mesh >ld &&
	label-expand -q -m expansion --report re u.lib anim.mesh >le &&
	label-expand -q -m swap --report rs u.lib anim.mesh >ls &&
	d=$(awk "/^energy /{print \$2}" rd) &&
	test_le "$d" "$(awk "/^energy /{print \$2}" re)" &&
	test_le "$d" "$(awk "/^energy /{print \$2}" rs)"
'
test_expect_success 'a library equal to the animation is labelled exactly' '
	label-expand -q --report rx anim.mesh anim.mesh >lx &&
	test_le "$(awk "/^max_error /{print \$2}" rx)" 1e-12 &&
	awk "\$1 != NR - 1 { exit 1 }" lx
'
test_expect_success 'label-expand of the dict-learn library reproduces its energy' '
	dict-learn -d 6 --report rl --labels-out ll anim.mesh >dl.lib &&
	label-expand -q --report rle dl.lib anim.mesh >lle &&
	a=$(awk "/^energy /{print \$2}" rl) && b=$(awk "/^energy /{print \$2}" rle) &&
	test_near "$a" "$b" "$(awk -v r="$a" "BEGIN{print 1e-8 * r}")"
'
test_expect_success 'bad input fails cleanly' '
	mesh-gen -f 3 -n 5 grid >other.mesh &&
	test_fails_cleanly label-expand other.mesh anim.mesh &&
	test_fails_cleanly lib-uniform -d 61 anim.mesh &&
	test_fails_cleanly lib-uniform -d 0 anim.mesh &&
	echo 1 >w1 && test_fails_cleanly label-expand -w w1 u.lib anim.mesh &&
	test_must_fail_usage label-expand &&
	test_must_fail_usage label-expand -m nope u.lib anim.mesh
'
test_done
