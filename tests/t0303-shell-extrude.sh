#!/bin/sh
test_description='shell-extrude (closed solids with a shared seam) and assembly-sheet'
. "$(dirname "$0")/test-lib.sh"

# a 6 x 6 grid animation whose boundary is constant (as after seam-homog):
# vertex v = 7 j + i is on the boundary when i or j is 0 or 6
seam_const() {
	awk '$1 == "frame" { k = $2; v = 0; print; next }
	     k != "" && NF == 3 { i = v % 7; j = int(v / 7);
	         if (i == 0 || i == 6 || j == 0 || j == 6) {
	             if (k == 0) first[v] = $0; else $0 = first[v] }
	         v++ }
	     { print }' "$1"
}

test_expect_success 'setup: seam-constant pieces' '
	mesh-gen -f 4 -a wave --amount 0.2 -n 6 grid >raw.mesh &&
	seam_const raw.mesh >lib.mesh &&
	mesh-info lib.mesh | grep "^frames 4$"
'
test_expect_success 'every piece becomes a closed, oriented, manifold solid' '
	shell-extrude -t 0.05 lib.mesh >solid.mesh &&
	mesh-info solid.mesh >info &&
	grep "^closed yes$" info && grep "^oriented yes$" info && grep "^manifold yes$" info &&
	grep "^vertices 98$" info && grep "^faces 192$" info
'
test_expect_success 'a flat piece gives a closed slab' '
	mesh-gen -n 4 grid >flat.mesh &&
	shell-extrude -t 0.1 flat.mesh >flat.solid &&
	mesh-info flat.solid >fi && grep "^closed yes" fi && grep "^components 1$" fi
'
test_expect_success 'the seam side is identical in every piece (pieces mate)' '
	awk "\$1 == \"frame\" { k = \$2; v = 0; next }
	     k != \"\" && NF == 3 { u = v % 49; i = u % 7; j = int(u / 7);
	         if (i == 0 || i == 6 || j == 0 || j == 6) {
	             if (k == 0) s[v] = \$0; else if (s[v] != \$0) { print \"differs\", k, v; bad = 1 } }
	         v++ }
	     END { exit bad }" solid.mesh
'
test_expect_success '--thickness-rel scales with the piece' '
	shell-extrude -r 0.05 lib.mesh >r.mesh && mesh-info r.mesh | grep "^closed yes"
'
test_expect_success 'assembly-sheet: frame rows, catalogue counts and grams' '
	printf "0\n1\n1\n3\n" >la && printf "2\n2\n0\n0\n" >lb &&
	assembly-sheet -n up,low -s solid.mesh,solid.mesh -c cat.csv --unit-mm 10 --density 1 la lb >sheet.csv &&
	printf "frame,up,low\n0,0,2\n1,1,2\n2,1,0\n3,3,0\n" >expect && test_cmp expect sheet.csv &&
	grep "^up,1,2,1-2," cat.csv && grep "^up,2,0,," cat.csv && grep "^low,0,2,2-3," cat.csv &&
	test $(wc -l <cat.csv) -eq 9 &&
	awk -F, "NR > 1 && \$3 > 0 && !(\$6 > 0) { exit 1 }" cat.csv
'
test_expect_success 'grams = volume x unit^3 x density' '
	shell-extrude -t 0.1 flat.mesh >flat.solid && echo 0 >l1 &&
	assembly-sheet -s flat.solid -c c1.csv --unit-mm 10 --density 2 l1 >/dev/null &&
	g=$(awk -F, "NR == 2 { print \$6 }" c1.csv) && v=$(awk -F, "NR == 2 { print \$5 }" c1.csv) &&
	test_near "$v" 0.1 1e-9 && test_near "$g" 0.2 1e-6
'
test_expect_success 'bad input fails cleanly' '
	printf "0\n1\n" >short &&
	test_fails_cleanly assembly-sheet la short &&
	printf "0\n9\n1\n1\n" >big &&
	test_fails_cleanly assembly-sheet -s solid.mesh big &&
	: >nolabels &&
	test_fails_cleanly assembly-sheet nolabels &&
	head -12 lib.mesh >trunc.mesh &&
	test_fails_cleanly shell-extrude trunc.mesh &&
	test_must_fail_usage shell-extrude -t -1 lib.mesh &&
	test_must_fail_usage assembly-sheet -n a la lb
'
test_done
