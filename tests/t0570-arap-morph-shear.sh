#!/bin/sh
test_description='arap-morph: shear limiting only outside [0,1]; weight rows normalised, zero sums refused'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

test_expect_success 'setup: three compatible shapes' '
	printf "ring 5\n0 0\n2 0\n2 1\n1 1.5\n0 1\n" >a.rings &&
	printf "ring 5\n0 0\n2 0.5\n2.2 1.5\n1 2.5\n-0.2 1\n" >b.rings &&
	printf "ring 5\n0 0\n1 -1\n2 0\n1.5 1.5\n0 1\n" >c.rings &&
	printf "0 0 0\n1 1 1\n3 3 3\n" >corr.txt &&
	compat-tri -c corr.txt a.rings b.rings c.rings >abc.mesh
'
test_expect_success 'inside the pose simplex -l is plain ARAP, byte for byte' '
	printf "0.2 0.3 0.5\n0.7 0.3 0\n0 0 1\n0.34 0.33 0.33\n" >inside.w &&
	arap-morph abc.mesh inside.w >plain.mesh &&
	arap-morph -l abc.mesh inside.w >limited.mesh &&
	test_cmp plain.mesh limited.mesh
'
test_expect_success 'the paper'"'"'s Hermite remapping changes blends inside the simplex' '
	arap-morph --shear-hermite abc.mesh inside.w >hermite.mesh &&
	! cmp -s plain.mesh hermite.mesh
'
test_expect_success 'outside the simplex -l changes the stretch and keeps every triangle' '
	bend_pair 1.5707963 0.3 >bend.mesh &&
	echo "-1 2" | arap-morph bend.mesh >ux.mesh &&
	echo "-1 2" | arap-morph -l bend.mesh >sx.mesh &&
	! cmp -s ux.mesh sx.mesh && test_le 1e-6 $(min_area sx.mesh)
'
test_expect_success 'a row that does not sum to 1 is divided by its sum (-v counts it)' '
	printf "0.4 0.6 1\n" >twice.w && printf "0.2 0.3 0.5\n" >once.w &&
	arap-morph -v abc.mesh twice.w >twice.mesh 2>log && arap-morph abc.mesh once.w >once.mesh &&
	test_cmp once.mesh twice.mesh && grep -q "1 of 1 weight rows did not sum to 1" log
'
test_expect_success 'a row of zeros (or summing to 0) is a one-line error' '
	printf "0.2 0.3 0.5\n0 0 0\n" >zero.w &&
	test_fails_cleanly arap-morph abc.mesh zero.w && grep -q "row 2: the weights sum to 0" .err &&
	printf "1 -1 0\n" >zs.w && test_fails_cleanly arap-morph -l abc.mesh zs.w
'
test_done
