# view-lib.sh -- headless Chromium for the anim-view tests (t016x).
#
#   view_skip                  empty when pages can be written and shown, else
#                              the reason (no three.js in this build, no chromium)
#   test_expect_view 'title' 'commands'   like test_expect_success, but skipped
#                              with the reason when view_skip is set
#   shoot PAGE.html[#frame=N] OUT.png   load the page from its file path in
#                              headless chromium (software WebGL), screenshot
#                              the 1000x500 window into OUT.png, its DOM after
#                              the script ran into OUT.png.dom (one launch),
#                              console log into OUT.png.log; fails unless the
#                              page reached data-status="ready"
#   console_clean OUT.png.log  the page said 'stopmo-status ready' and logged
#                              nothing else (SwiftShader's own "GPU stall due
#                              to ReadPixels" performance notes excepted)
#   stage_fraction OUT.png     fraction of the views' area (below the 40-pixel
#                              bar) whose pixels differ from the background
#   picture_change A.png B.png fraction of that area that differs between A and B
CHROMIUM=$(command -v chromium || command -v chromium-browser || true)
view_skip=
if ! mesh-gen grid | anim-view -o "$TRASH/.probe.html" - 2>"$TRASH/.probe.err"; then
    view_skip="anim-view cannot write pages here: $(cat "$TRASH/.probe.err")"
elif [ -z "$CHROMIUM" ]; then
    view_skip="chromium is not installed (make check installs it as root: make test-deps)"
elif ! command -v node >/dev/null; then
    view_skip="node is not installed (needed to count screenshot pixels)"
fi

test_expect_view() {
    if [ -n "$view_skip" ] && [ -z "$test_skip_all" ]; then
        test_count=$((test_count + 1))
        say "ok $test_count # skip $1 ($view_skip)"
        return 0
    fi
    test_expect_success "$@"
}

shoot() {
    page=${1%%#*}
    frag=
    case $1 in *'#'*) frag="#${1#*#}" ;; esac
    case $page in /*) ;; *) page=$PWD/$page ;; esac
    timeout 180 "$CHROMIUM" --headless --no-sandbox --disable-gpu --use-angle=swiftshader \
        --enable-unsafe-swiftshader --hide-scrollbars --no-first-run --disable-extensions \
        --user-data-dir="$TRASH/.chromium" --window-size=1000,500 --virtual-time-budget=20000 \
        --enable-logging=stderr --v=0 --screenshot="$2" --dump-dom "file://$page$frag" 2>"$2.log" >"$2.dom"
    test -s "$2" || { echo "no screenshot; chromium said:" >&2; tail -5 "$2.log" >&2; return 1; }
    grep -q 'data-status="ready"' "$2.dom" || { echo "page not ready:" >&2; grep -o '<pre id="errors".*' "$2.dom" >&2; return 1; }
}

console_clean() {
    grep -q '"stopmo-status ready' "$1" || { echo "page did not get ready:" >&2; grep CONSOLE "$1" >&2; return 1; }
    if grep ':CONSOLE' "$1" | grep -v '"stopmo-status ready' | grep -v 'GL Driver Message (OpenGL, Performance, GL_CLOSE_PATH_NV, High): GPU stall due to ReadPixels' >"$1.bad"; then
        echo "console messages:" >&2; cat "$1.bad" >&2; return 1
    fi
}

# the page's background colour (web/anim-view.html: --bg #2b2f36)
stage_fraction() { node "$TEST_DIRECTORY/png-pixels.js" bg "$1" 0,40,1000,500 43,47,54; }
# the same in a box X0,Y0,X1,Y1 against colour R,G,B
box_fraction() { node "$TEST_DIRECTORY/png-pixels.js" bg "$1" "$2" "$3"; }
picture_change() { node "$TEST_DIRECTORY/png-pixels.js" diff "$1" "$2" 0,40,1000,500; }
