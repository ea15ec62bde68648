#!/bin/sh
test_description='compat-tri: the certificate of the given points (conformal moduli of quadrilaterals of four given points; man compat-tri, CERTIFICATE): a hidden leg is certified below 20 degrees and the mesh stays below the ceiling, an easy pair is not; --bound alone; bad input'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"

# ceiling FILE: the angle of a certificate line
ceiling() {
	sed -n 's/.*keeps more than \([0-9.]*\) deg in both.*/\1/p' "$1"
}

test_expect_success 'setup: a body with a thin leg, the leg hidden (its outline squeezed into the body), the leg bent' '
	printf "ring 9\n0 0\n4 0\n4 -8\n4.25 -8\n4.5 -8\n4.5 0\n10 0\n10 4\n0 4\n" >leg.rings &&
	printf "ring 9\n0 0\n4 0\n4.05 0\n4.25 0\n4.45 0\n4.5 0\n10 0\n10 4\n0 4\n" >hidden.rings &&
	printf "ring 9\n0 0\n4 0\n6 -7\n6.3 -7.2\n6.5 -6.8\n4.5 0\n10 0\n10 4\n0 4\n" >bent.rings &&
	printf "0 0\n1 1\n2 2\n4 4\n5 5\n7 7\n" >corr.txt
'

test_expect_success 'hidden leg: --bound certifies a ceiling below 20 degrees, naming the poses and four rows' '
	compat-tri --bound -c corr.txt leg.rings hidden.rings >b.txt &&
	cat b.txt &&
	test $(wc -l <b.txt) -eq 1 &&
	grep "^the given points force a map stretch of at least [0-9.]*x between poses 1 and 0 (rows [0-9] [0-9] [0-9] [0-9] of corr.txt: modulus" b.txt &&
	test_le $(ceiling b.txt) 19.99
'

test_expect_success 'hidden leg: -v prints the same line, the mesh is the one without -v and its worst angle is below the ceiling (-e 0: the input outline)' '
	compat-tri -e 0 -c corr.txt leg.rings hidden.rings >m0.mesh &&
	compat-tri -e 0 -v -c corr.txt leg.rings hidden.rings >m1.mesh 2>log &&
	test_cmp m0.mesh m1.mesh &&
	grep "compat-tri: certificate: the given points force" log >line &&
	test "$(sed "s/^compat-tri: certificate: //" line)" = "$(cat b.txt)" &&
	grep "certificate: 15 quadruples of the given points in 2 shapes" log &&
	grep "certificate: the goal of 20 deg is out of reach with the given points (no triangulation keeps more than $(ceiling b.txt) deg); the mesh reaches" log &&
	test_le 1e-12 $(min_area m1.mesh) &&
	test_le $(worst_angle m1.mesh) $(ceiling b.txt)
'

test_expect_success 'bent leg (no obstruction): ceiling above 50 degrees' '
	compat-tri --bound -c corr.txt leg.rings bent.rings >e.txt &&
	cat e.txt &&
	test_le 50 $(ceiling e.txt)
'

test_expect_success '--bound: the same bytes again, and with the files run clockwise (indices counted in file order)' '
	compat-tri --bound -c corr.txt leg.rings hidden.rings >b2.txt &&
	test_cmp b.txt b2.txt &&
	for f in leg hidden; do
		{ echo "ring 9"; sed 1d $f.rings | awk "{ l[NR] = \$0 } END { for (i = NR; i >= 1; i--) print l[i] }"; } >$f-cw.rings || return 1
	done &&
	awk "{ print 8 - \$1, 8 - \$2 }" corr.txt >corr-cw.txt &&
	compat-tri --bound -c corr-cw.txt leg-cw.rings hidden-cw.rings >cw.txt &&
	cat cw.txt &&
	test "$(ceiling cw.txt)" = "$(ceiling b.txt)"
'

test_expect_success 'fewer than 4 given rows: no bound; --bound refuses with the reason (exit 1, nothing on stdout), -v says so' '
	head -n 3 corr.txt >c3.txt &&
	test_fails_cleanly compat-tri --bound -c c3.txt leg.rings hidden.rings 2>n.err &&
	grep "3 points given in every shape; 4 are needed" n.err &&
	compat-tri -v -c c3.txt leg.rings hidden.rings 2>n.log >n.mesh &&
	grep "certificate: 3 points given in every shape; 4 are needed" n.log
'

test_expect_success 'several rings: -v says the certificate is not computed' '
	printf "ring 4\n0 0\n10 0\n10 10\n0 10\nring 4\n4 4\n4 6\n6 6\n6 4\n" >h0.rings &&
	printf "ring 4\n0 0\n12 0\n12 10\n0 10\nring 4\n5 4\n5 6\n7 6\n7 4\n" >h1.rings &&
	printf "0 0\n1 1\n2 2\n4 4\n" >hc.txt &&
	compat-tri -v -c hc.txt h0.rings h1.rings >h.mesh 2>hlog &&
	grep "certificate: not computed for several rings" hlog &&
	test_fails_cleanly compat-tri --bound -c hc.txt h0.rings h1.rings 2>herr &&
	grep "bound: not computed for several rings" herr
'

test_expect_success 'too many given rows for the certificate (90 rows: 2.6 million quadruples): -v says it is not computed and meshes as without -v; --bound refuses' '
	awk "BEGIN { print \"ring 120\"; for (i = 0; i < 120; i++) { a = 6.283185307179586 * i / 120; printf \"%.6f %.6f\\n\", 50 * cos(a), 30 * sin(a) } }" >e0.rings &&
	awk "BEGIN { print \"ring 120\"; for (i = 0; i < 120; i++) { a = 6.283185307179586 * i / 120; printf \"%.6f %.6f\\n\", 40 * cos(a), 40 * sin(a) + 5 * cos(3 * a) } }" >e1.rings &&
	awk "BEGIN { for (i = 0; i < 90; i++) print i, i }" >many.txt &&
	compat-tri -c many.txt e0.rings e1.rings >quiet.mesh &&
	compat-tri -v -c many.txt e0.rings e1.rings >loud.mesh 2>many.log &&
	grep "certificate: not computed: 90 correspondence points: too many quadruples" many.log &&
	grep "result:" many.log &&
	cmp quiet.mesh loud.mesh &&
	test_fails_cleanly compat-tri --bound -c many.txt e0.rings e1.rings 2>many.err &&
	grep "bound: not computed: 90 correspondence points" many.err
'

test_expect_success 'bad input: --bound without -c is a usage error; a bad index, rows out of order: one line, exit 1, nothing on stdout' '
	test_must_fail_usage compat-tri --bound leg.rings hidden.rings 2>err &&
	grep "needs -c" err &&
	printf "0 0\n1 1\n2 2\n4 40\n" >bad.txt &&
	test_fails_cleanly compat-tri --bound -c bad.txt leg.rings hidden.rings 2>err &&
	grep "not a vertex index" err &&
	printf "0 0\n2 1\n1 2\n4 4\n" >order.txt &&
	test_fails_cleanly compat-tri --bound -c order.txt leg.rings hidden.rings 2>err &&
	grep "cyclic order" err
'

test_done
