/* web_assets.h -- files built into the binaries for the HTML pages that
 * tools write (anim-view): the page template and script from web/, and
 * three.js from the npm package `three` (copied to build/web/ by the
 * Makefile from node_modules/, which `make deps` fills).
 *
 * The bytes are included at build time with the assembler's .incbin, so a
 * page never fetches anything.  When `three` was not installed at build
 * time, its assets are empty (size 0) and web_asset_missing() says so.
 */
#ifndef CM_WEB_ASSETS_H
#define CM_WEB_ASSETS_H
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif

struct web_asset {
    const char *name;            /* e.g. "three.core.js" */
    const unsigned char *data;   /* size bytes (not NUL-terminated) */
    size_t size;
};

/* The asset called name: "anim-view.html", "anim-view.js",
 * "three.module.js" (its import of './three.core.js' rewritten to the bare
 * name 'three-core', so both can live in one import map), "three.core.js",
 * "OrbitControls.js", "three.version".  NULL for an unknown name. */
const struct web_asset *web_asset(const char *name);

/* NULL when every asset is present; otherwise a one-line message naming
 * the first empty one and how to get it (make deps, then make). */
const char *web_asset_missing(void);

#ifdef __cplusplus
}
#endif
#endif
