#!/bin/sh
test_description='landmark-auto: extremities matched between poses, left and right by orientation; mesh-render --points; nricp without -l'
. "$(dirname "$0")/test-lib.sh"

test_expect_success 'setup: a six-spiked "character" and a bent, turned copy (same vertices: the truth)' '
	mesh-gen -s 3 icosphere >sph.mesh &&
	awk -v ANG=0 -v BEND=0 -f "$TEST_DIRECTORY/spikes.awk" sph.mesh sph.mesh >a.mesh &&
	awk -v ANG=40 -v BEND=0.3 -f "$TEST_DIRECTORY/spikes.awk" sph.mesh sph.mesh >b.mesh
'
test_expect_success 'the spike tips are extremities' '
	landmark-auto --extremities a.mesh >ext.txt &&
	test "$(grep -vc "^#" ext.txt)" -ge 6
'
test_expect_success 'matched tips are the same vertices; the mirror-symmetric legs are not swapped' '
	landmark-auto -v a.mesh b.mesh >lm.txt 2>err && cat lm.txt err &&
	n=$(awk "/extremity/" lm.txt | wc -l) && test "$n" -ge 5 &&
	awk "/extremity/ && \$1 != \$2 { bad++ } END { exit bad > 0 }" lm.txt
'
test_expect_success 'a mirrored target: the map follows the mirror (left tips go to right tips)' '
	awk "/^frame/ { body = 1; print; next } body && NF == 3 { print -\$1, \$2, \$3; next } /^f / { print \"f\", \$2, \$4, \$3; next } { print }" b.mesh >m.mesh &&
	landmark-auto a.mesh m.mesh >lmm.txt &&
	awk "/extremity/ && \$1 == \$2 { same++ } /extremity/ { n++ } END { exit !(n >= 5 && same <= 2) }" lmm.txt
'
test_expect_success 'the landmark file is what nricp -l reads; nricp without -l uses the same pairs' '
	nricp -l lm.txt a.mesh b.mesh >r1.mesh &&
	nricp --landmarks-out used.txt a.mesh b.mesh >r2.mesh &&
	grep -v "^#" lm.txt | awk "{ print \$1, \$2 }" >want.txt &&
	grep -v "^#" used.txt >got.txt &&
	test_cmp want.txt got.txt &&
	nricp --no-auto a.mesh b.mesh >r0.mesh &&
	h2=$(mesh-metrics --no-header -r b.mesh r2.mesh | awk "{ print \$3 }") &&
	h0=$(mesh-metrics --no-header -r b.mesh r0.mesh | awk "{ print \$3 }") &&
	echo "automatic landmarks $h2, none $h0" && test_le "$h2" "$h0"
'
test_expect_success 'mesh-render --points draws numbered points' '
	mesh-render -s 200x200 a.mesh >plain.png &&
	mesh-render -s 200x200 --points lm.txt a.mesh >pa.png &&
	mesh-render -s 200x200 --points lm.txt --points-column 2 b.mesh >pb.png &&
	! cmp -s plain.png pa.png
'
test_expect_success 'bad input fails cleanly' '
	test_fails_cleanly landmark-auto a.mesh nonexistent.mesh &&
	mesh-gen -f 3 -a wave grid >anim.mesh &&
	test_fails_cleanly landmark-auto a.mesh anim.mesh &&
	test_must_fail_usage landmark-auto a.mesh &&
	test_must_fail_usage landmark-auto --limb 1.5 a.mesh b.mesh &&
	test_fails_cleanly mesh-render --points lm.txt --points-column 3 a.mesh &&
	echo 99999 >far.txt && test_fails_cleanly mesh-render --points far.txt a.mesh &&
	test_must_fail_usage mesh-render --points-column 2 a.mesh
'
test_expect_success 'nricp: an 11-frame target, a non-manifold fan, --no-auto with -l' '
	mesh-gen -f 11 -a wave grid >eleven.mesh &&
	test_fails_cleanly nricp a.mesh eleven.mesh &&
	grep -q "11 frames" "$TRASH/.err" &&
	printf "MESH 1\nvertices 5\nfaces 3\nframes 1\nf 0 1 2\nf 1 0 3\nf 0 1 4\nframe 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n" >fan.mesh &&
	test_fails_cleanly nricp a.mesh fan.mesh &&
	grep -q "non-manifold" "$TRASH/.err" &&
	test_must_fail_usage nricp --no-auto -l lm.txt a.mesh b.mesh &&
	nricp --help | grep -q "\[-l LANDMARKS\]"
'
test_done
