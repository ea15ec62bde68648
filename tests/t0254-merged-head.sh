#!/bin/sh
test_description='a merged multi-component head: OBJ frames of head-gen plus eyeballs, mesh-import'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/merged-head-lib.sh"

# static_from MESH K: the largest motion over the frames of the vertices
# with index >= K (plain MESH stream), and how many such vertices there are
static_from() {
	awk -v K="$2" '
		/^frame / { fr = $2 + 0; i = 0; rd = 1; next }
		!rd { next }
		{ if (i >= K) { n = i - K + 1
			if (fr == 0) { x[i] = $1; y[i] = $2; z[i] = $3 }
			else { d = ($1 - x[i]) ^ 2 + ($2 - y[i]) ^ 2 + ($3 - z[i]) ^ 2; if (d > m) m = d } }
		  i++ }
		END { printf "%d %.3g\n", n, sqrt(m) }' "$1"
}

test_expect_success 'merged_head: one animation, head then two static eyeballs' '
	merged_head 12 merged.mesh &&
	mesh-info merged.mesh >info &&
	grep "^vertices 966$" info && grep "^faces 1920$" info && grep "^frames 12$" info &&
	grep "^components 3$" info && grep "^manifold yes$" info &&
	static_from merged.mesh 642 >eyes && cat eyes &&
	test "$(cat eyes)" = "324 0"
'

test_expect_success 'the head keeps head-gen motion and numbering (first 642 vertices)' '
	head-gen -f 12 -s 3 --clips 1 >head.mesh &&
	awk "/^frame /{ print; i = 0; r = 1; next } r && i++ < 642" merged.mesh >a &&
	awk "/^frame /{r=1} r{print}" head.mesh >b &&
	paste -d" " a b | awk "NF == 6 { for (k = 1; k <= 3; k++) { d = \$k - \$(k + 3); if (d < 0) d = -d; if (d > m) m = d } }
		\$1 == \"frame\" && \$1 != \$3 { bad = 1 } END { print m; exit bad }" >dev &&
	test_le "$(cat dev)" 1e-8
'

test_expect_success 'mesh-import --merge is for scene files: a sequence of OBJ files is refused' '
	test_must_fail_usage mesh-import --merge "mh-frames/head_*.obj" >out &&
	test ! -s out
'

test_done
