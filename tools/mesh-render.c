/* mesh-render -- render one frame of a MESH stream to a PNG or PPM image.
 *
 * A small z-buffer rasterizer (libcommon/raster.h): orthographic (or
 * perspective) camera from a named view or azimuth/elevation, fitted to the
 * frame, Lambert headlight shading, two-sided lighting, per-face or
 * per-vertex colours from a label or scalar column file, optional wireframe,
 * supersampled edges.  So a person can look at any stream.
 */
#include "cm_error.h"
#include "columns.h"
#include "image.h"
#include "mesh.h"
#include "meshcolor.h"
#include "progress.h"
#include "raster.h"
#include "render_options.h"
#include "tool.h"
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

static const char help[] =
"Usage: mesh-render [options] [file] > out.png\n"
"Render one frame of a MESH stream (file or stdin) as a PNG or PPM image.\n"
"\n"
"Options:\n"
"  -k, --frame K          frame to draw, 0-based; negative counts from the end\n"
"                         (-1 = the last; default 0)\n"
"  -s, --size WxH         image size in pixels (default 800x800)\n"
"      --fit-all          fit the camera to all frames, not just frame K\n"
"      --column N         with --scalars: column N (1-based) of a file with several\n"
"                         columns, e.g. mesh-metrics --per-face (4: distance, 3:\n"
"                         flipped); a file of one block of rows per frame gives\n"
"                         frame K's block\n"
"      --points FILE      draw numbered points (1, 2, ... in row order) at the\n"
"                         vertices named in column 1 of FILE, e.g. a landmark file\n"
"      --points-column N  take the vertex indices from column N instead\n"
"      --only K           draw only the faces labelled K in --labels (one label\n"
"                         per face), in the uniform --color; the camera still\n"
"                         fits every vertex, so the parts of a frame drawn one\n"
"                         at a time line up (e.g. a limb and the body without\n"
"                         it, traced by img2rings for compat-tri --layers)\n"
RENDER_OPTIONS_HELP
"  -f, --format FMT       png or ppm (default from the -o extension, else png)\n"
"  -o, --output FILE      write to FILE (atomically) instead of stdout\n"
"      --compact          smaller PNG (zlib level 6, adaptive filters), ~4x slower\n"
"  -v, --verbose          print timings and the scalar range to stderr\n"
"  -h, --help             show this help\n"
"      --version          show the version\n"
"\n"
"Example: mesh-gen -s 3 icosphere | mesh-render --view iso --wireframe > sphere.png\n";

struct options {
    const char *input;
    int frame, w, h, fit_all, column, points_col;
    const char *points;
    int only, have_only;       /* --only K */
    struct render_options r;   /* camera and look */
};

enum { O_FITALL = 256, O_VERSION, O_COLUMN, O_POINTS, O_POINTSCOL, O_ONLY };

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"frame", 1, 0, 'k'}, {"size", 1, 0, 's'}, {"fit-all", 0, 0, O_FITALL},
        {"column", 1, 0, O_COLUMN}, {"points", 1, 0, O_POINTS}, {"points-column", 1, 0, O_POINTSCOL}, {"only", 1, 0, O_ONLY},
        RENDER_OPTIONS_LONGOPTS, {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'},
        {"version", 0, 0, O_VERSION}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->w = o->h = 800;
    render_options_init(&o->r);
    int c;
    while ((c = getopt_long(argc, argv, "k:s:" RENDER_OPTIONS_SHORTOPTS "vh", lo, NULL)) != -1) {
        if (render_options_parse(&o->r, c, optarg))
            continue;
        switch (c) {
        case 'k': o->frame = arg_int_range(optarg, "--frame", -200000000, 200000000); break;
        case 's':
            if (image_parse_size(optarg, &o->w, &o->h) < 0)
                usage_error("--size: '%s' is not WxH (e.g. 800x600, at most 16384)", optarg);
            break;
        case O_FITALL: o->fit_all = 1; break;
        case O_POINTS: o->points = optarg; break;
        case O_ONLY: o->only = arg_int_range(optarg, "--only", -2000000000, 2000000000); o->have_only = 1; break;
        case O_POINTSCOL:
            o->points_col = (int)arg_long(optarg, "--points-column");
            if (o->points_col < 1) usage_error("--points-column must be >= 1");
            break;
        case O_COLUMN:
            o->column = (int)arg_long(optarg, "--column");
            if (o->column < 1) usage_error("--column must be >= 1");
            break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case O_VERSION: print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind < argc - 1)
        usage_error("expected at most one input file");
    o->input = optind < argc ? argv[optind] : NULL;
    render_options_check(&o->r);
    if (o->column && !o->r.scalars) usage_error("--column needs --scalars");
    if (o->points_col && !o->points) usage_error("--points-column needs --points");
    if (o->have_only && !o->r.labels) usage_error("--only needs --labels");
    if (!o->points_col) o->points_col = 1;
    render_options_format(&o->r, o->r.output);
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
    double t0 = now_seconds();

    /* read up to frame K (fitting the camera on the way with --fit-all) */
    struct mesh_reader r;
    if (mesh_reader_open(&r, o.input) < 0)
        die("%s", cm_errmsg());
    struct camera cam;
    render_options_camera(&o.r, &cam);
    size_t fsz = ((size_t)r.nv + 1) * 3 * sizeof(double);
    int want = o.frame;           /* frame index, or < 0: from the end */
    if (want < 0 && r.nframes >= 0) {
        if (r.nframes + want < 0)
            die("cannot read '%s': no frame %d (the stream has %d frame%s)", r.name, o.frame,
                r.nframes, r.nframes == 1 ? "" : "s");
        want += r.nframes;
    }
    /* from the end of a stream of unknown length: a ring of the last -want
     * frames, allocated as frames arrive (memory O(frames read)) */
    int nring = want < 0 ? -want : 1;
    int nalloc = 0, nbuf = 0;
    double **ring = NULL;
    double *Y = malloc(fsz);
    double *X = want >= 0 ? malloc(fsz) : NULL;
    if ((want >= 0 && !X) || !Y)
        die("out of memory");
    int got = 0, k = 0, rc;
    for (;;) {
        double *dst = k == want ? X : Y;
        if (want < 0) {
            if (k < nring) {
                if (k == nalloc) {
                    nalloc = nalloc ? (nalloc > nring / 2 ? nring : 2 * nalloc) : 1;
                    double **nr = realloc(ring, (size_t)nalloc * sizeof *ring);
                    if (!nr)
                        die("out of memory for the last %d frames", nring);
                    ring = nr;
                }
                if (!(ring[k] = malloc(fsz)))
                    die("out of memory for the last %d frames", nring);
                nbuf++;
            }
            dst = ring[k % nring];
        }
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
    render_options_style(&o.r, &st);
    struct mesh_colors mc;
    memset(&mc, 0, sizeof mc);
    /* --only K: the faces labelled K, the labels select instead of colour */
    int *F = r.F, nf = r.nf;
    if (o.have_only) {
        int *L, n;
        if (labels_read(o.r.labels, r.nf, "faces (--only selects faces)", -2000000000, -2000000001, &L, &n) < 0)
            die("%s", cm_errmsg());
        if (!(F = malloc(3 * ((size_t)r.nf + 1) * sizeof *F))) die("out of memory");
        nf = 0;
        for (int f = 0; f < r.nf; f++)
            if (L[f] == o.only) memcpy(F + 3 * (size_t)nf++, r.F + 3 * (size_t)f, 3 * sizeof *F);
        free(L);
        if (nf == 0) die("cannot read '%s': no face is labelled %d (--only)", o.r.labels, o.only);
        info(1, "--only %d: %d of %d faces", o.only, nf, r.nf);
    }
    if (o.r.labels && !o.have_only && mesh_colors_labels(o.r.labels, r.nv, r.nf, &mc) < 0)
        die("%s", cm_errmsg());
    const double *range = o.r.have_range ? o.r.range : NULL;
    if (o.r.scalars && (o.column ? mesh_colors_scalars_column(o.r.scalars, o.column - 1, want, r.nv, r.nf, range, &mc)
                                 : mesh_colors_scalars(o.r.scalars, r.nv, r.nf, range, &mc)) < 0)
        die("%s", cm_errmsg());
    if ((o.r.labels && !o.have_only) || o.r.scalars) {
        mesh_colors_apply(&mc, &st);
        if (o.r.labels)
            info(1, "%d distinct labels per %s", mc.nlabels, mc.per_face ? "face" : "vertex");
        else
            info(1, "scalars per %s mapped from range %g,%g", mc.per_face ? "face" : "vertex",
                 mc.lo, mc.hi);
    }
    /* numbered points: vertex indices from a column of a file */
    struct columns pts = {0};
    if (o.points) {
        if (columns_read(o.points, 0, -1, NULL, &pts) < 0) die("%s", cm_errmsg());
        if (pts.rows > 0 && o.points_col > pts.cols)
            die("cannot read '%s': no column %d (it has %d)", o.points, o.points_col, pts.cols);
        for (int i = 0; i < pts.rows; i++) {
            double v = pts.x[(size_t)i * pts.cols + o.points_col - 1];
            if (v != (int)v || v < 0 || v >= r.nv)
                die("cannot read '%s': row %d: %g is not a vertex index 0..%d", o.points, i + 1, v, r.nv - 1);
        }
    }
    double t1 = now_seconds();

    struct image im;
    if (raster_render(X, F, r.nv, nf, &cam, &st, o.w, o.h, &im) < 0)
        die("%s", cm_errmsg());
    if (pts.rows > 0) {
        double *P = malloc((size_t)pts.rows * 3 * sizeof *P), *XY = malloc((size_t)pts.rows * 2 * sizeof *XY);
        if (!P || !XY) die("out of memory");
        for (int i = 0; i < pts.rows; i++)
            memcpy(P + 3 * i, X + 3 * (int)pts.x[(size_t)i * pts.cols + o.points_col - 1], 3 * sizeof *P);
        raster_project_points(&cam, o.w, o.h, P, pts.rows, XY);
        int rad = o.w > o.h ? o.h / 160 : o.w / 160, sc = o.w >= 1200 ? 3 : o.w >= 500 ? 2 : 1;
        if (rad < 2) rad = 2;
        static const unsigned char red[3] = {220, 30, 30}, dark[3] = {20, 20, 20}, white[3] = {255, 255, 255};
        for (int i = 0; i < pts.rows; i++) {
            int cx = (int)floor(XY[2 * i]), cy = (int)floor(XY[2 * i + 1]);
            for (int y = -rad - 1; y <= rad + 1; y++)
                for (int x = -rad - 1; x <= rad + 1; x++) {
                    int d2 = x * x + y * y;
                    if (d2 > (rad + 1) * (rad + 1) || cx + x < 0 || cy + y < 0 || cx + x >= im.w || cy + y >= im.h)
                        continue;
                    memcpy(image_px(&im, cx + x, cy + y), d2 > rad * rad ? dark : red, 3);
                }
            char num[16];
            snprintf(num, sizeof num, "%d", i + 1);
            image_text(&im, cx + rad + 2, cy - rad - text_height(sc), num, sc, dark, white);
        }
        free(P);
        free(XY);
    }
    columns_free(&pts);
    double t2 = now_seconds();
    FILE *out = out_open(o.r.output);
    if (image_write(out, &im, o.r.format) < 0)
        die("cannot write output: %s", cm_errmsg());
    out_close(out);
    double t3 = now_seconds();
    info(1, "frame %d: %d vertices, %d faces; read %.1f ms, render %dx%d (x%d) %.1f ms, "
         "write %s %.1f ms", want, r.nv, r.nf, 1e3 * (t1 - t0), o.w, o.h, o.r.ss,
         1e3 * (t2 - t1), o.r.format, 1e3 * (t3 - t2));
    image_free(&im);
    mesh_colors_free(&mc);
    if (F != r.F) free(F);
    mesh_reader_close(&r);
    if (ring) {
        for (int i = 0; i < nbuf; i++) free(ring[i]);
        free(ring);
    } else {
        free(X);
    }
    free(Y);
    return 0;
}
