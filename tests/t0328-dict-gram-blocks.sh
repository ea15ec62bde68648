#!/bin/sh
test_description='dict-learn Gram back end: the Gram matrix made by blocks of 256 columns (weights, fixed pieces) agrees with the direct back end; at lambda 0 the kept sums of unchanged pieces give the same bytes as making every sum again; an overflowing input is refused'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/dict-lib.sh"

# replib.c gram_by_columns adds Z[:, c] Z[:, c]^T block by block (never
# holding Z); gram_rows_kept keeps a piece's sum of Gram rows while its
# frames stay the same.  The head has 162 vertices: 486 columns, a block of
# 256 and one of 230.

test_expect_success 'setup: a 150-frame 162-vertex head with noise, weights, 3 fixed pieces' '
	noisy_head 150 3 5 xy "-s 2" &&
	mesh-info noisy.mesh | grep "^vertices 162\$" &&
	awk "BEGIN { srand(4); for (i = 0; i < 162; i++) printf \"%.4f\n\", 0.25 + rand() }" >w.txt &&
	dict-learn -d 3 -l 0 --seed 2 noisy.mesh >fixed.lib &&
	awk "BEGIN { for (f = 0; f < 150; f++) print f % 7 }" >init.lab
'
for lam in 0 2; do
	for extra in "" "-w w.txt" "--fixed fixed.lib"; do
		test_expect_success "lambda $lam ${extra:-(plain)}: Gram by blocks and direct back end agree from the same start" "
			dict-learn -d 9 -l $lam -r 1 --search 0 --init-labels init.lab $extra --gram on --report g.rep noisy.mesh >g.lib &&
			dict-learn -d 9 -l $lam -r 1 --search 0 --init-labels init.lab $extra --gram off --report o.rep noisy.mesh >o.lib &&
			a=\$(awk '/^energy /{print \$2}' g.rep) && b=\$(awk '/^energy /{print \$2}' o.rep) &&
			test_near \"\$a\" \"\$b\" \"\$(awk -v r=\"\$a\" 'BEGIN{print 1e-9 * r}')\"
		"
	done
done
test_expect_success 'single-precision Gram by blocks: (nearly) the same energy' '
	dict-learn -d 9 -l 0 -r 1 --search 0 --init-labels init.lab --gram single --report s.rep noisy.mesh >/dev/null &&
	dict-learn -d 9 -l 0 -r 1 --search 0 --init-labels init.lab --gram on --report g.rep noisy.mesh >/dev/null &&
	a=$(awk "/^energy /{print \$2}" g.rep) && b=$(awk "/^energy /{print \$2}" s.rep) &&
	test_near "$a" "$b" "$(awk -v r="$a" "BEGIN{print 1e-4 * r}")"
'
for d in 6 25; do
	test_expect_success "lambda 0, d = $d, with the search: kept sums = every sum made again, byte for byte" "
		dict-learn -vv -d $d -l 0 --seed 3 --gram on --report k.rep --labels-out k.lab noisy.mesh >k.lib 2>k.log &&
		STOPMO_DICT_NO_KEPT_SUMS=1 dict-learn -d $d -l 0 --seed 3 --gram on --report m.rep --labels-out m.lab noisy.mesh >m.lib &&
		test \$(grep -c 'iteration' k.log) -gt 20 &&
		test_cmp k.lib m.lib && test_cmp k.lab m.lab && test_cmp k.rep m.rep
	"
done
test_expect_success 'lambda 0 with fixed pieces: kept sums = every sum made again' '
	dict-learn -d 10 -l 0 --seed 3 --fixed fixed.lib --gram on --labels-out k.lab noisy.mesh >k.lib &&
	STOPMO_DICT_NO_KEPT_SUMS=1 dict-learn -d 10 -l 0 --seed 3 --fixed fixed.lib --gram on --labels-out m.lab noisy.mesh >m.lib &&
	test_cmp k.lib m.lib && test_cmp k.lab m.lab
'
test_expect_success 'coordinates whose sum over the frames overflows: one line naming the vertex, exit 1, no output' '
	awk "/^frame /{ fr = 1 } fr && NF == 3 && \$1 != \"frame\" { printf \"%s 1e307 %s\n\", \$1, \$3; next } { print }" head.mesh >huge.mesh &&
	test_must_fail dict-learn -d 5 -o out.lib huge.mesh 2>err &&
	test $(wc -l <err) -eq 1 &&
	grep "huge.mesh.*vertex 0: coordinates too large" err &&
	test ! -e out.lib
'
test_done
