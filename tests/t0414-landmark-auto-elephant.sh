#!/bin/sh
test_description='landmark-auto on elephant walk frames (one connectivity: the true correspondence is known)'
. "$(dirname "$0")/test-lib.sh"
need_shared_data anim/elephant-walk-457.tar.xz

test_expect_success 'setup: frames 0, 80 and 120 of the walk' '
	tar -xJf "$SHARED_DATA/anim/elephant-walk-457.tar.xz" -C . elephant/frame_0000.obj elephant/frame_0080.obj elephant/frame_0120.obj &&
	for k in 0000 0080 0120; do mesh-import elephant/frame_$k.obj >e$k.mesh || return 1; done
'
# the largest distance, over the diagonal, between the B-vertex of each
# extremity row and the true partner of its A-vertex (the same index in B)
err() {
	awk -v kind="$2" "FNR == 1 { pass++ } pass == 1 && /^frame/ { body = 1; next }
		pass == 1 && body && NF == 3 { V[n++] = \$0; next }
		pass == 2 && \$0 ~ kind { split(V[\$1], a); split(V[\$2], b);
			d = sqrt((a[1] - b[1])^2 + (a[2] - b[2])^2 + (a[3] - b[3])^2); if (d > m) m = d }
		END { printf \"%.4f\", m / diag }" diag="$(mesh-info "$1" | awk "/^diagonal/ { print \$2 }")" "$1" "$3"
}
for k in 0080 0120; do
	test_expect_success "frame 0 -> $k: every matched tip within 8% of the diagonal of its truth" '
		landmark-auto -v e0000.mesh e'$k'.mesh >lm'$k'.txt 2>err && cat err &&
		test "$(grep -c extremity lm'$k'.txt)" -ge 6 &&
		e=$(err e'$k'.mesh extremity lm'$k'.txt) && echo "largest tip error $e" &&
		test_le "$e" 0.08
	'
done
test_done
