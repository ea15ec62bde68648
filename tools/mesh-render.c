/* mesh-render -- render one frame of a MESH stream to a PNG or PPM image.
 *
 * A small z-buffer rasterizer (libcommon/raster.h): orthographic (or
 * perspective) camera from a named view or azimuth/elevation, fitted to the
 * frame, Lambert headlight shading, two-sided lighting, per-face or
 * per-vertex colours from a label or scalar column file, optional wireframe,
 * supersampled edges.  So a person can look at any stream.
 */
#include "cm_error.h"
#include "colormap.h"
#include "image.h"
#include "mesh.h"
#include "meshcolor.h"
#include "raster.h"
#include "tool.h"
#include <getopt.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

static const char help[] =
"Usage: mesh-render [options] [file] > out.png\n"
"Render one frame of a MESH stream (file or stdin) as a PNG or PPM image.\n"
"\n"
"Options:\n"
"  -k, --frame K          frame to draw, 0-based; negative counts from the end\n"
"                         (-1 = the last; default 0)\n"
"  -s, --size WxH         image size in pixels (default 800x800)\n"
"  -V, --view NAME        front, back, left, right, top, bottom, iso (default front)\n"
"  -a, --azimuth DEG      camera azimuth around the up axis (0 = front, 90 = right)\n"
"  -e, --elevation DEG    camera elevation above the horizon (90 = top)\n"
"      --up AXIS          world up axis: x, y, z, -x, -y or -z (default y)\n"
"      --perspective      perspective projection (default orthographic)\n"
"      --fov DEG          perspective vertical field of view (default 30)\n"
"      --fit-all          fit the camera to all frames, not just frame K\n"
"  -l, --labels FILE      integer label per face (or per vertex): categorical colours\n"
"      --scalars FILE     scalar per vertex (or per face): viridis colours\n"
"      --range MIN,MAX    scalar range mapped to the colormap (default: data min,max)\n"
"  -w, --wireframe        draw the edges of the visible faces\n"
"      --flat             flat shading (face normals) instead of smooth\n"
"  -c, --color COLOR      uniform colour, R,G,B or #rrggbb (default 214,186,150)\n"
"  -b, --background COLOR background colour (default white)\n"
"      --supersample N    N x N samples per pixel, 1..8 (default 2)\n"
"  -f, --format FMT       png or ppm (default from the -o extension, else png)\n"
"  -o, --output FILE      write to FILE (atomically) instead of stdout\n"
"      --compact          smaller PNG (zlib level 6, adaptive filters), ~4x slower\n"
"  -v, --verbose          print timings and the scalar range to stderr\n"
"  -h, --help             show this help\n"
"      --version          show the version\n"
"\n"
"Example: mesh-gen -s 3 icosphere | mesh-render --view iso --wireframe > sphere.png\n";

struct options {
    const char *input, *output, *labels, *scalars, *format;
    int frame, w, h, up, perspective, fit_all, wireframe, flat, ss, have_range;
    double azimuth, elevation, fov, range[2];
    unsigned char color[3], background[3];
};

enum { O_UP = 256, O_PERSP, O_FOV, O_FITALL, O_SCALARS, O_RANGE, O_FLAT, O_SS, O_VERSION, O_COMPACT };

static int parse_axis(const char *s)
{
    static const char *names[] = {"x", "y", "z", "-x", "-y", "-z"};
    for (int i = 0; i < 6; i++)
        if (!strcmp(s, names[i]) || (i < 3 && s[0] == '+' && !strcmp(s + 1, names[i])))
            return i;
    usage_error("--up: '%s' is not x, y, z, -x, -y or -z", s);
}

static const char *format_from_name(const char *path)
{
    const char *dot = path ? strrchr(path, '.') : NULL;
    if (dot && (!strcmp(dot, ".ppm") || !strcmp(dot, ".pnm")))
        return "ppm";
    return "png";
}

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"frame", 1, 0, 'k'}, {"size", 1, 0, 's'}, {"view", 1, 0, 'V'},
        {"azimuth", 1, 0, 'a'}, {"elevation", 1, 0, 'e'}, {"up", 1, 0, O_UP},
        {"perspective", 0, 0, O_PERSP}, {"fov", 1, 0, O_FOV}, {"fit-all", 0, 0, O_FITALL},
        {"labels", 1, 0, 'l'}, {"scalars", 1, 0, O_SCALARS}, {"range", 1, 0, O_RANGE},
        {"wireframe", 0, 0, 'w'}, {"flat", 0, 0, O_FLAT}, {"color", 1, 0, 'c'},
        {"colour", 1, 0, 'c'}, {"background", 1, 0, 'b'}, {"supersample", 1, 0, O_SS},
        {"format", 1, 0, 'f'}, {"output", 1, 0, 'o'}, {"verbose", 0, 0, 'v'},
        {"compact", 0, 0, O_COMPACT}, {"help", 0, 0, 'h'}, {"version", 0, 0, O_VERSION}, {0, 0, 0, 0}};
    struct render_style def;
    render_style_default(&def);
    memset(o, 0, sizeof *o);
    o->w = o->h = 800;
    o->up = 1;
    o->fov = 30;
    o->ss = def.ss;
    memcpy(o->color, def.color, 3);
    memcpy(o->background, def.background, 3);
    const char *view = "front";
    int have_az = 0, have_el = 0;
    double az = 0, el = 0;
    int c;
    while ((c = getopt_long(argc, argv, "k:s:V:a:e:l:wc:b:f:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'k': o->frame = (int)arg_long(optarg, "--frame"); break;
        case 's':
            if (image_parse_size(optarg, &o->w, &o->h) < 0)
                usage_error("--size: '%s' is not WxH (e.g. 800x600, at most 16384)", optarg);
            break;
        case 'V': view = optarg; break;
        case 'a': az = arg_double(optarg, "--azimuth"); have_az = 1; break;
        case 'e': el = arg_double(optarg, "--elevation"); have_el = 1; break;
        case O_UP: o->up = parse_axis(optarg); break;
        case O_PERSP: o->perspective = 1; break;
        case O_FOV: o->fov = arg_double(optarg, "--fov"); break;
        case O_FITALL: o->fit_all = 1; break;
        case 'l': o->labels = optarg; break;
        case O_SCALARS: o->scalars = optarg; break;
        case O_RANGE: {
            char *end;
            o->range[0] = strtod(optarg, &end);
            if (end == optarg || *end != ',')
                usage_error("--range: '%s' is not MIN,MAX", optarg);
            o->range[1] = arg_double(end + 1, "--range");
            if (!(o->range[1] > o->range[0]))
                usage_error("--range: MAX must be greater than MIN");
            o->have_range = 1;
            break;
        }
        case 'w': o->wireframe = 1; break;
        case O_FLAT: o->flat = 1; break;
        case 'c':
            if (color_parse(optarg, o->color) < 0)
                usage_error("--color: '%s' is not R,G,B (0..255) or #rrggbb", optarg);
            break;
        case 'b':
            if (color_parse(optarg, o->background) < 0)
                usage_error("--background: '%s' is not R,G,B (0..255) or #rrggbb", optarg);
            break;
        case O_SS: o->ss = (int)arg_long(optarg, "--supersample"); break;
        case 'f': o->format = optarg; break;
        case 'o': o->output = optarg; break;
        case O_COMPACT: image_png_small(1); break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case O_VERSION: print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind < argc - 1)
        usage_error("expected at most one input file");
    o->input = optind < argc ? argv[optind] : NULL;
    if (camera_named_view(view, &o->azimuth, &o->elevation) < 0)
        usage_error("unknown view '%s' (front, back, left, right, top, bottom, iso)", view);
    if (have_az) o->azimuth = az;
    if (have_el) o->elevation = el;
    if (o->elevation < -90 || o->elevation > 90)
        usage_error("--elevation must be in -90..90");
    if (!(o->fov > 1 && o->fov < 170))
        usage_error("--fov must be in 1..170 degrees");
    if (o->ss < 1 || o->ss > 8)
        usage_error("--supersample must be in 1..8");
    if (o->labels && o->scalars)
        usage_error("--labels and --scalars exclude each other");
    if (o->have_range && !o->scalars)
        usage_error("--range needs --scalars");
    if (!o->format)
        o->format = format_from_name(o->output);
    if (strcmp(o->format, "png") && strcmp(o->format, "ppm"))
        usage_error("--format: '%s' is not png or ppm", o->format);
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* Is the input a pipe (or terminal) whose writer would get SIGPIPE if we
 * stopped reading early? */
static int is_stream(const char *path)
{
    struct stat st;
    int r = (!path || !strcmp(path, "-")) ? fstat(0, &st) : stat(path, &st);
    return r != 0 || !S_ISREG(st.st_mode);
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    double t0 = now();

    /* read up to frame K (fitting the camera on the way with --fit-all) */
    struct mesh_reader r;
    if (mesh_reader_open(&r, o.input) < 0)
        die("%s", cm_errmsg());
    struct camera cam;
    camera_init(&cam, o.azimuth, o.elevation, o.up);
    cam.perspective = o.perspective;
    cam.fov = o.fov;
    size_t fsz = ((size_t)r.nv + 1) * 3 * sizeof(double);
    int want = o.frame;           /* frame index, or < 0: from the end */
    if (want < 0 && r.nframes >= 0) {
        if (r.nframes + want < 0)
            die("cannot read '%s': no frame %d (the stream has %d frame%s)", r.name, o.frame,
                r.nframes, r.nframes == 1 ? "" : "s");
        want += r.nframes;
    }
    /* from the end of a stream of unknown length: a ring of the last -want frames */
    int nring = want < 0 ? -want : 1;
    double **ring = malloc((size_t)nring * sizeof *ring);
    double *Y = malloc(fsz);
    if (!ring || !Y)
        die("out of memory");
    for (int i = 0; i < nring; i++)
        if (!(ring[i] = malloc(fsz)))
            die("out of memory for the last %d frames", nring);
    double *X = ring[0];
    int got = 0, k = 0, rc;
    for (;;) {
        double *dst = want < 0 ? ring[k % nring] : k == want ? X : Y;
        if ((rc = mesh_reader_next(&r, dst, NULL)) <= 0)
            break;
        if (k == want) got = 1;
        if (o.fit_all || k == want)
            camera_fit(&cam, dst, r.nv);
        k++;
        if (got && !o.fit_all && !is_stream(o.input))
            break;
    }
    if (rc < 0)
        die("%s", cm_errmsg());
    if (want < 0 && k >= nring) {
        want = k - nring;
        X = ring[want % nring];
        if (!o.fit_all)
            camera_fit(&cam, X, r.nv);
        got = 1;
    }
    if (!got)
        die("cannot read '%s': no frame %d (the stream has %d frame%s)", r.name, o.frame, k,
            k == 1 ? "" : "s");

    struct render_style st;
    render_style_default(&st);
    memcpy(st.color, o.color, 3);
    memcpy(st.background, o.background, 3);
    st.wireframe = o.wireframe;
    st.flat = o.flat;
    st.ss = o.ss;
    struct mesh_colors mc;
    memset(&mc, 0, sizeof mc);
    if (o.labels && mesh_colors_labels(o.labels, r.nv, r.nf, &mc) < 0)
        die("%s", cm_errmsg());
    if (o.scalars && mesh_colors_scalars(o.scalars, r.nv, r.nf, o.have_range ? o.range : NULL, &mc) < 0)
        die("%s", cm_errmsg());
    if (o.labels || o.scalars) {
        mesh_colors_apply(&mc, &st);
        if (o.labels)
            info(1, "%d distinct labels per %s", mc.nlabels, mc.per_face ? "face" : "vertex");
        else
            info(1, "scalars per %s mapped from range %g,%g", mc.per_face ? "face" : "vertex",
                 mc.lo, mc.hi);
    }
    double t1 = now();

    struct image im;
    if (raster_render(X, r.F, r.nv, r.nf, &cam, &st, o.w, o.h, &im) < 0)
        die("%s", cm_errmsg());
    double t2 = now();
    FILE *out = out_open(o.output);
    if (image_write(out, &im, o.format) < 0)
        die("cannot write output: %s", cm_errmsg());
    out_close(out);
    double t3 = now();
    info(1, "frame %d: %d vertices, %d faces; read %.1f ms, render %dx%d (x%d) %.1f ms, "
         "write %s %.1f ms", want, r.nv, r.nf, 1e3 * (t1 - t0), o.w, o.h, o.ss,
         1e3 * (t2 - t1), o.format, 1e3 * (t3 - t2));
    image_free(&im);
    mesh_colors_free(&mc);
    mesh_reader_close(&r);
    for (int i = 0; i < nring; i++) free(ring[i]);
    free(ring);
    free(Y);
    return 0;
}
