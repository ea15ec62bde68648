/* web_assets.c -- the page template and three.js, built in with .incbin.
 *
 * Paths are relative to the top of the source tree, where make runs the
 * compiler; the Makefile lists them as prerequisites of this object.
 */
#include "web_assets.h"
#include <string.h>

#define INCBIN(sym, path)                                            \
    __asm__(".section .rodata\n"                                     \
            ".balign 16\n"                                           \
            ".global " #sym "_start\n" #sym "_start:\n"              \
            ".incbin \"" path "\"\n"                                 \
            ".global " #sym "_end\n" #sym "_end:\n"                  \
            ".byte 0\n"                                              \
            ".previous\n");                                          \
    extern const unsigned char sym##_start[], sym##_end[]

INCBIN(cm_asset_html, "web/anim-view.html");
INCBIN(cm_asset_js, "web/anim-view.js");
INCBIN(cm_asset_three, "build/web/three.module.js");
INCBIN(cm_asset_core, "build/web/three.core.js");
INCBIN(cm_asset_orbit, "build/web/OrbitControls.js");
INCBIN(cm_asset_version, "build/web/three.version");

static struct web_asset assets[6];

static void init(void)
{
    if (assets[0].name) return;
    const struct { const char *name; const unsigned char *a, *b; } t[6] = {
        {"anim-view.html", cm_asset_html_start, cm_asset_html_end},
        {"anim-view.js", cm_asset_js_start, cm_asset_js_end},
        {"three.module.js", cm_asset_three_start, cm_asset_three_end},
        {"three.core.js", cm_asset_core_start, cm_asset_core_end},
        {"OrbitControls.js", cm_asset_orbit_start, cm_asset_orbit_end},
        {"three.version", cm_asset_version_start, cm_asset_version_end},
    };
    for (int i = 0; i < 6; i++)
        assets[i] = (struct web_asset){t[i].name, t[i].a, (size_t)(t[i].b - t[i].a)};
}

const struct web_asset *web_asset(const char *name)
{
    init();
    for (int i = 0; i < 6; i++)
        if (!strcmp(assets[i].name, name)) return &assets[i];
    return NULL;
}

const char *web_asset_missing(void)
{
    init();
    for (int i = 0; i < 6; i++)
        if (assets[i].size == 0)
            return i < 2 ? "the page template was empty at build time (web/ in the source tree)"
                         : "built without three.js: the npm package 'three' was not in node_modules "
                           "when this program was built; run 'make deps' (needs npm) and 'make' again";
    return NULL;
}
