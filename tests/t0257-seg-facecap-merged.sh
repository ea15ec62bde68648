#!/bin/sh
test_description='seg-graphcut: forehead + chin on the whole facecap head (face, eyes, teeth)'
. "$(dirname "$0")/test-lib.sh"
need_shared_data anim/facecap.glb

test_expect_success 'forehead + chin: one upper and one lower part, the eyes in the upper' '
	mesh-import --merge --raw "$SHARED_DATA/anim/facecap.glb" >head.mesh &&
	seg-graphcut -v --seeds "$STOPMO_ROOT/examples/stopshop/facecap.seeds" head.mesh >labels 2>log &&
	cat log && ! grep -q warning log &&
	grep -q "components, [0-9]* bridges" log &&
	awk "{ n[NR <= 5032 ? \"face\" : NR <= 5032 + 1920 ? \"eyes\" : \"teeth\", \$1]++ }
	     END { printf \"face %d %d eyes %d %d teeth %d %d\\n\", n[\"face\", 0], n[\"face\", 1],
	           n[\"eyes\", 0], n[\"eyes\", 1], n[\"teeth\", 0], n[\"teeth\", 1] }" labels >counts &&
	cat counts &&
	set -- $(cat counts) &&
	test $5 -eq 1920 && test $6 -eq 0 &&
	test $2 -gt 1000 && test $3 -gt 1000
'

test_done
