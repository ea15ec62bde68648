#!/bin/sh
test_description='examples/clay writes out/review.html: registered key poses over their scans (camel gallop)'
. "$(dirname "$0")/test-lib.sh"
. "$TEST_DIRECTORY/view-lib.sh"
need_shared_data scans/camel-gallop-02.off

# only the first registration (KEYS=02): scan_01 and reg_02 over scans 01, 02
run_recipe() {
	make -s -C "$STOPMO_ROOT/examples/clay" BIN="$STOPMO_ROOT/bin" OUT="$TRASH/out" \
		DATA="$SHARED_DATA/scans" KEYS=02 "$@"
}

test_expect_view 'the recipe writes out/review.html with one scan per key' '
	run_recipe "$TRASH/out/review.html" >log 2>&1 &&
	test $(grep -o "<script type=\"application/octet-stream\"" out/review.html | wc -l) -eq 6
'
test_expect_view 'key 2 is drawn over scan 2: transparent, wireframe and hidden all differ' '
	shoot "out/review.html#frame=1" t.png && console_clean t.png.log &&
	grep -q "data-scan=\"1\"" t.png.dom && grep -q "scan: transparent" t.png.dom &&
	shoot "out/review.html#frame=1&scan=wireframe" w.png && console_clean w.png.log &&
	shoot "out/review.html#frame=1&scan=off" o.png && console_clean o.png.log &&
	f=$(stage_fraction o.png) && echo "camel pixels: $f" && test_le 0.05 "$f" &&
	d=$(picture_change t.png o.png) && echo "transparent scan changes $d" && test_le 0.02 "$d" &&
	d=$(picture_change w.png o.png) && echo "wireframe scan changes $d" && test_le 0.02 "$d"
'
test_done
