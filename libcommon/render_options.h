/* render_options.h -- the camera and look options shared by the renderers
 * (mesh-render, anim-render); tools only.
 *
 * Like tool.h this is program harness: it parses command-line options and
 * calls usage_error() (exit 2) on a bad value, so it is used only from
 * tools/NAME.c, never from the numerical library.  A tool
 *   1. calls render_options_init(),
 *   2. puts RENDER_OPTIONS_SHORTOPTS into its getopt_long short options and
 *      RENDER_OPTIONS_LONGOPTS into its long option table,
 *   3. passes every option to render_options_parse() first (it returns 1
 *      when it handled the option),
 *   4. after the loop calls render_options_check() and
 *      render_options_format(), and
 *   5. builds the camera and the style with render_options_camera() and
 *      render_options_style().
 * RENDER_OPTIONS_HELP is the help text of these options except -f, -o and
 * --compact (whose wording depends on what the tool writes).
 */
#ifndef CM_RENDER_OPTIONS_H
#define CM_RENDER_OPTIONS_H
#include "raster.h"
#ifdef __cplusplus
extern "C" {
#endif

struct render_options {
    const char *view;                    /* --view name (default "front") */
    int have_az, have_el;                /* --azimuth / --elevation given */
    double azimuth, elevation;           /* degrees; final after render_options_check */
    int up;                              /* 0..5 = x, y, z, -x, -y, -z (default 1) */
    int perspective;                     /* --perspective */
    double fov;                          /* degrees (default 30) */
    const char *labels, *scalars;        /* column files, or NULL */
    int have_range;                      /* --range given */
    double range[2];                     /* --range MIN,MAX */
    int wireframe, flat, ss;             /* --wireframe, --flat, --supersample */
    unsigned char color[3], background[3];
    const char *format;                  /* "png" or "ppm" after render_options_format */
    const char *output;                  /* -o FILE, or NULL */
};

/* Option values above every short option character. */
enum { RO_UP = 0x1000, RO_PERSP, RO_FOV, RO_SCALARS, RO_RANGE, RO_FLAT, RO_SS, RO_COMPACT };

#define RENDER_OPTIONS_SHORTOPTS "V:a:e:l:wc:b:f:o:"
#define RENDER_OPTIONS_LONGOPTS                                                            \
    {"view", 1, 0, 'V'}, {"azimuth", 1, 0, 'a'}, {"elevation", 1, 0, 'e'},                 \
    {"up", 1, 0, RO_UP}, {"perspective", 0, 0, RO_PERSP}, {"fov", 1, 0, RO_FOV},           \
    {"labels", 1, 0, 'l'}, {"scalars", 1, 0, RO_SCALARS}, {"range", 1, 0, RO_RANGE},       \
    {"wireframe", 0, 0, 'w'}, {"flat", 0, 0, RO_FLAT}, {"color", 1, 0, 'c'},               \
    {"colour", 1, 0, 'c'}, {"background", 1, 0, 'b'}, {"supersample", 1, 0, RO_SS},        \
    {"format", 1, 0, 'f'}, {"output", 1, 0, 'o'}, {"compact", 0, 0, RO_COMPACT}

#define RENDER_OPTIONS_HELP                                                                  \
"  -V, --view NAME        front, back, left, right, top, bottom, iso (default front)\n"      \
"  -a, --azimuth DEG      camera azimuth around the up axis (0 = front, 90 = right)\n"       \
"  -e, --elevation DEG    camera elevation above the horizon (90 = top)\n"                   \
"      --up AXIS          world up axis: x, y, z, -x, -y or -z (default y)\n"                \
"      --perspective      perspective projection (default orthographic)\n"                   \
"      --fov DEG          perspective vertical field of view (default 30)\n"                 \
"  -l, --labels FILE      integer label per face (or per vertex): categorical colours\n"     \
"      --scalars FILE     scalar per vertex (or per face): viridis colours\n"                \
"      --range MIN,MAX    scalar range mapped to the colormap (default: data min,max)\n"     \
"  -w, --wireframe        draw the edges of the visible faces\n"                             \
"      --flat             flat shading (face normals) instead of smooth\n"                   \
"  -c, --color COLOR      uniform colour, R,G,B or #rrggbb (default 214,186,150)\n"          \
"  -b, --background COLOR background colour (default white)\n"                               \
"      --supersample N    N x N samples per pixel, 1..8 (default 2)\n"

/* Defaults: front view, up y, orthographic, fov 30, the colours and
 * supersampling of render_style_default(), no labels/scalars/format/output. */
void render_options_init(struct render_options *ro);

/* Handle option c (getopt_long's return) with argument arg.  Returns 1 if
 * it was one of RENDER_OPTIONS_LONGOPTS, 0 otherwise; usage_error() on a
 * bad value.  --compact takes effect at once (image_png_small). */
int render_options_parse(struct render_options *ro, int c, const char *arg);

/* After parsing: resolve the view and the angles and check the ranges and
 * combinations (elevation, fov, supersample, labels vs scalars, range
 * without scalars); usage_error() on a violation. */
void render_options_check(struct render_options *ro);

/* Settle the image format: --format, else from the extension of `path`
 * (.ppm/.pnm = ppm, anything else or NULL = png); usage_error() unless png
 * or ppm. */
void render_options_format(struct render_options *ro, const char *path);

/* An unfitted camera with the chosen angles, up axis and projection. */
void render_options_camera(const struct render_options *ro, struct camera *cam);

/* render_style_default() with the chosen colours, wireframe, shading and
 * supersampling. */
void render_options_style(const struct render_options *ro, struct render_style *st);

#ifdef __cplusplus
}
#endif
#endif
