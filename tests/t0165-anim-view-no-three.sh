#!/bin/sh
test_description='anim-view built without three.js (npm package missing): the build says so, the tool refuses with one line'
. "$(dirname "$0")/test-lib.sh"

# rebuild only libcommon/web_assets.c in a scratch tree whose node_modules has
# no three, and link it into anim-view in place of the real one
test_expect_success 'setup: web assets synced without node_modules/three' '
	mkdir -p scratch/web && cp "$STOPMO_ROOT"/web/* scratch/web/ &&
	(cd scratch && sh web/three-sync.sh build/web) 2>sync.err &&
	cat sync.err && grep -q "npm package .three. not found.*make deps" sync.err &&
	test ! -s scratch/build/web/three.core.js && test ! -s scratch/build/web/three.module.js
'
test_expect_success 'anim-view links with the empty assets' '
	ldlibs=$(make -s -C "$STOPMO_ROOT" --eval "print-ldlibs: ; @echo \$(LDLIBS)" print-ldlibs) &&
	(cd scratch && ${CC:-cc} -std=c11 $STOPMO_LINKFLAGS -c -I"$STOPMO_ROOT/libcommon" -o web_assets.o "$STOPMO_ROOT/libcommon/web_assets.c") &&
	${CC:-cc} -pthread $STOPMO_LINKFLAGS -o anim-view-no-three "$STOPMO_BUILD/tools/anim-view.o" scratch/web_assets.o \
	  "$STOPMO_BUILD/libcommon.a" $ldlibs
'
test_expect_success 'it refuses to write a page: exit 1, one line naming make deps, nothing written' '
	mesh-gen grid >g.mesh &&
	test_fails_cleanly ./anim-view-no-three g.mesh 2>err &&
	grep -q "^anim-view-no-three: built without three.js.*make deps" err &&
	test_must_fail ./anim-view-no-three -o page.html g.mesh 2>/dev/null && test ! -e page.html &&
	./anim-view-no-three --help >help && grep -q "^Usage: anim-view" help
'
test_done
