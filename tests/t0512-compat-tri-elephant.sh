#!/bin/sh
test_description='compat-tri: every subset of the six shared elephant poses (skips without ../shared/data)'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/morph2d-lib.sh"
need_shared_data shapes2d/poses/elephant-pose6.rings.txt
P="$SHARED_DATA/shapes2d/poses"

test_expect_success 'every subset of 2..6 poses (corr6.txt), positive in every pose' '
	ok=0 tot=0 mask=3 &&
	while [ $mask -lt 64 ]; do
		cols= files= i=0
		for k in 1 2 3 4 5 6; do
			if [ $(((mask >> i) & 1)) = 1 ]; then cols="$cols,$k"; files="$files $P/elephant-pose$k.rings.txt"; fi
			i=$((i + 1))
		done
		case $cols in ,*,*)
			tot=$((tot + 1))
			grep -v "^#" "$STOPMO_ROOT/examples/morph2d/corr6.txt" | cut -d" " -f"${cols#,}" >sub.corr
			if compat-tri --refine none -l 0 -s 0 -c sub.corr $files >sub.mesh 2>sub.err &&
			   test_le 1e-12 $(min_area sub.mesh); then ok=$((ok + 1))
			else echo "poses $cols: $(cat sub.err)" >&2; fi ;;
		esac
		mask=$((mask + 1))
	done &&
	echo "$ok of $tot" >result && echo "57 of 57" >expect && test_cmp expect result
'
test_done
