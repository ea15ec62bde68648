/* anim-render -- a film strip / contact sheet of chosen frames of one or
 * more MESH streams, or one image per frame.
 *
 * One fixed camera is fitted to every chosen frame of every input, so the
 * tiles are directly comparable; each tile is stamped with its frame
 * number.  Several inputs are drawn as rows (e.g. the input animation above
 * its stop-motion result), optionally titled.
 */
#include "cm_error.h"
#include "image.h"
#include "mesh.h"
#include "meshcolor.h"
#include "mesh_spool.h"
#include "progress.h"
#include "raster.h"
#include "render_options.h"
#include "tool.h"
#include <getopt.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: anim-render [options] [file...] > sheet.png\n"
"Render chosen frames of MESH streams as a contact sheet: one row (or block of\n"
"rows) per input, tiles stamped with their frame numbers, one fixed camera.\n"
"\n"
"Frames (per input; default --count 8):\n"
"      --frames LIST      comma separated frame indices (negative: from the end)\n"
"      --every K          frames 0, K, 2K, ...\n"
"  -n, --count N          N frames evenly spaced from first to last\n"
"      --all              every frame\n"
"Layout:\n"
"  -C, --columns C        tiles per row (default: the number of chosen frames, at most 8;\n"
"                         inputs of one frame each flow through the columns)\n"
"  -s, --size WxH         size of one tile in pixels (default 320x320)\n"
"      --gap N            pixels between tiles (default 4)\n"
"  -t, --titles LIST      comma separated titles, one per input, drawn left of its rows\n"
"      --no-stamp         do not stamp frame numbers\n"
"      --each PATTERN     write one image per frame to PATTERN (e.g. 'out_%04d.png',\n"
"                         one integer conversion); inputs side by side\n"
"Camera and look (as mesh-render):\n"
RENDER_OPTIONS_HELP
"Output:\n"
"  -f, --format FMT       png or ppm (default from the -o extension, else png)\n"
"  -o, --output FILE      write the sheet to FILE (atomically) instead of stdout\n"
"      --compact          smaller PNG (zlib level 6, adaptive filters), ~4x slower\n"
"  -v, --verbose          print counts and timings to stderr\n"
"  -h, --help             show this help\n"
"      --version          show the version\n"
"\n"
"Example: anim-render --count 6 -t input,result in.mesh out.mesh > compare.png\n";

enum { SEL_COUNT, SEL_EVERY, SEL_LIST, SEL_ALL };

struct options {
    const char **inputs;
    int ninputs;
    const char *each, *titles_arg;
    int sel, count, every, nlist, *list;
    int columns, w, h, gap, stamp;
    struct render_options r;   /* camera and look */
    char **titles;
    int ntitles;
};

enum { O_VERSION = 256, O_FRAMES, O_EVERY, O_ALL, O_GAP, O_NOSTAMP, O_EACH };

/* PATTERN must hold exactly one integer conversion %[0][width]d (and %%). */
static int check_pattern(const char *p)
{
    int n = 0;
    for (; *p; p++) {
        if (*p != '%')
            continue;
        p++;
        if (*p == '%')
            continue;
        if (*p == '0') p++;
        while (*p >= '0' && *p <= '9') p++;
        if (*p != 'd')
            return -1;
        n++;
    }
    return n == 1 ? 0 : -1;
}

static char **split_titles(const char *s, int *n)
{
    int cap = 4, k = 0;
    char **v = malloc(cap * sizeof *v);
    const char *p = s;
    for (;;) {
        const char *q = strchr(p, ',');
        size_t len = q ? (size_t)(q - p) : strlen(p);
        if (k == cap) v = realloc(v, (cap *= 2) * sizeof *v);
        v[k] = malloc(len + 1);
        memcpy(v[k], p, len);
        v[k][len] = 0;
        k++;
        if (!q) break;
        p = q + 1;
    }
    *n = k;
    return v;
}

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"frames", 1, 0, O_FRAMES}, {"every", 1, 0, O_EVERY}, {"count", 1, 0, 'n'},
        {"all", 0, 0, O_ALL}, {"columns", 1, 0, 'C'}, {"size", 1, 0, 's'},
        {"gap", 1, 0, O_GAP}, {"titles", 1, 0, 't'}, {"no-stamp", 0, 0, O_NOSTAMP},
        {"each", 1, 0, O_EACH}, RENDER_OPTIONS_LONGOPTS, {"verbose", 0, 0, 'v'},
        {"help", 0, 0, 'h'}, {"version", 0, 0, O_VERSION}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->sel = SEL_COUNT;
    o->count = 8;
    o->w = o->h = 320;
    o->gap = 4;
    o->stamp = 1;
    render_options_init(&o->r);
    int nsel = 0;
    int c;
    while ((c = getopt_long(argc, argv, "n:C:s:t:" RENDER_OPTIONS_SHORTOPTS "vh", lo, NULL)) != -1) {
        if (render_options_parse(&o->r, c, optarg))
            continue;
        switch (c) {
        case O_FRAMES: o->sel = SEL_LIST; nsel++; o->nlist = arg_intlist(optarg, "--frames", &o->list); break;
        case O_EVERY: o->sel = SEL_EVERY; nsel++; o->every = arg_int(optarg, "--every"); break;
        case 'n': o->sel = SEL_COUNT; nsel++; o->count = arg_int(optarg, "--count"); break;
        case O_ALL: o->sel = SEL_ALL; nsel++; break;
        case 'C':
            o->columns = arg_int(optarg, "--columns");
            if (o->columns < 1)
                usage_error("--columns must be at least 1");
            break;
        case 's':
            if (image_parse_size(optarg, &o->w, &o->h) < 0)
                usage_error("--size: '%s' is not WxH (e.g. 320x240, at most 16384)", optarg);
            break;
        case O_GAP: o->gap = arg_int(optarg, "--gap"); break;
        case 't': o->titles_arg = optarg; break;
        case O_NOSTAMP: o->stamp = 0; break;
        case O_EACH: o->each = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case O_VERSION: print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    static const char *stdin_only[] = {"-"};
    if (optind < argc) {
        o->inputs = (const char **)argv + optind;
        o->ninputs = argc - optind;
    } else {
        o->inputs = stdin_only;
        o->ninputs = 1;
    }
    int nstdin = 0;
    for (int i = 0; i < o->ninputs; i++) nstdin += !strcmp(o->inputs[i], "-");
    if (nstdin > 1)
        usage_error("stdin ('-') can be read only once");
    if (nsel > 1)
        usage_error("choose frames with one of --frames, --every, --count, --all");
    if (o->sel == SEL_COUNT && o->count < 1)
        usage_error("--count must be at least 1");
    if (o->sel == SEL_EVERY && o->every < 1)
        usage_error("--every must be at least 1");
    if (o->gap < 0 || o->gap > 1000)
        usage_error("--gap must be in 0..1000");
    render_options_check(&o->r);
    if (o->titles_arg) {
        o->titles = split_titles(o->titles_arg, &o->ntitles);
        if (o->ntitles != o->ninputs)
            usage_error("--titles: %d title%s for %d input%s", o->ntitles,
                        o->ntitles == 1 ? "" : "s", o->ninputs, o->ninputs == 1 ? "" : "s");
    }
    if (o->each) {
        if (check_pattern(o->each) < 0)
            usage_error("--each: '%s' needs exactly one integer conversion like %%04d", o->each);
        if (o->r.output)
            usage_error("--each and --output exclude each other");
    }
    render_options_format(&o->r, o->each ? o->each : o->r.output);
}

/* One input.  Memory mode keeps the chosen frames; streaming mode (one
 * image per frame, a stream without a frame count, or more than
 * KEEP_LIMIT bytes of chosen frames) keeps only each frame's view-space
 * bounds in the first pass and reads the frames again to draw them
 * (mesh_spool: a regular file is reopened, a pipe is spooled to a
 * temporary raw file), so memory stays O(one frame). */
#define KEEP_LIMIT ((size_t)256 << 20)

struct input {
    const char *name;
    int nv, nf, nframes;
    int *F;                /* #F by 3 */
    int nsel;
    int *sel;              /* chosen frame indices, -1 = this input lacks it */
    /* memory mode */
    double **X;            /* nsel frames, #V by 3 each (NULL where sel is -1) */
    /* streaming mode */
    int streaming;
    double *bounds;        /* nframes by 6: view-space lo[3], hi[3] */
    struct mesh_spool sp;
    struct mesh_reader r2;
    int open2, pos;        /* second-pass reader open; frames read from it */
    double *cur;           /* #V by 3: the frame last read */
};

/* Choose frame indices of a stream of n frames; -1 entries are skipped
 * tiles (an index this input does not have). */
static int choose(const struct options *o, int n, int **out)
{
    int *s;
    int k = 0;
    switch (o->sel) {
    case SEL_LIST:
        s = malloc((size_t)o->nlist * sizeof *s);
        for (int i = 0; i < o->nlist; i++) {
            int f = o->list[i] < 0 ? n + o->list[i] : o->list[i];
            s[k++] = f >= 0 && f < n ? f : -1;
        }
        break;
    case SEL_EVERY:
        s = malloc(((size_t)n / o->every + 1) * sizeof *s);
        for (int f = 0; f < n; f += o->every) s[k++] = f;
        break;
    case SEL_ALL:
        s = malloc(((size_t)n + 1) * sizeof *s);
        for (int f = 0; f < n; f++) s[k++] = f;
        break;
    default: {
        int c = o->count < n ? o->count : n;
        s = malloc(((size_t)c + 1) * sizeof *s);
        for (int i = 0; i < c; i++)
            s[k++] = c == 1 ? 0 : (int)((double)i * (n - 1) / (c - 1) + 0.5);
        break;
    }
    }
    *out = s;
    return k;
}

/* First pass over one input: validate the whole stream, count its frames,
 * choose, and keep either the chosen frames or every frame's bounds. */
static void read_input(const struct options *o, const char *path, struct mesh_reader *r,
                       int streaming, const struct camera *cam, struct input *in)
{
    memset(in, 0, sizeof *in);
    in->name = strdup(r->name);
    in->nv = r->nv;
    in->nf = r->nf;
    in->streaming = streaming;
    in->F = malloc(((size_t)r->nf + 1) * 3 * sizeof *in->F);
    memcpy(in->F, r->F, (size_t)r->nf * 3 * sizeof *in->F);
    size_t fsz = ((size_t)r->nv + 1) * 3 * sizeof(double);
    int *want = NULL, nwant = 0;
    char *keep = NULL;
    if (!streaming) {   /* memory mode needs the frame count up front */
        nwant = choose(o, r->nframes, &want);
        keep = calloc((size_t)r->nframes + 1, 1);
        for (int i = 0; i < nwant; i++)
            if (want[i] >= 0) keep[want[i]] = 1;
    } else if (mesh_spool_begin(&in->sp, path, r) < 0)
        die("%s", cm_errmsg());
    double **frames = NULL;   /* memory mode: indexed by frame number */
    int cap = 0, k = 0, rc, bcap = 0;
    double *scratch = malloc(fsz);
    if (!scratch)
        die("out of memory");
    for (;;) {
        double *dst = scratch;
        if (!streaming && keep[k < r->nframes ? k : r->nframes]) {
            dst = malloc(fsz);
            if (!dst)
                die("out of memory keeping the frames of '%s'", r->name);
        }
        int cut = 0;
        rc = mesh_reader_next(r, dst, &cut);
        if (rc <= 0) {
            if (dst != scratch) free(dst);
            break;
        }
        if (streaming) {
            if (mesh_spool_frame(&in->sp, dst, cut) < 0)
                die("%s", cm_errmsg());
            struct camera c = *cam;
            camera_reset(&c);
            camera_fit(&c, dst, r->nv);
            if (k == bcap) {
                bcap = bcap ? 2 * bcap : 256;
                in->bounds = realloc(in->bounds, (size_t)bcap * 6 * sizeof *in->bounds);
            }
            memcpy(in->bounds + 6 * k, c.lo, 3 * sizeof(double));
            memcpy(in->bounds + 6 * k + 3, c.hi, 3 * sizeof(double));
        } else {
            if (k == cap) {
                cap = cap ? 2 * cap : 64;
                frames = realloc(frames, (size_t)cap * sizeof *frames);
            }
            frames[k] = dst != scratch ? dst : NULL;
        }
        k++;
    }
    if (rc < 0)
        die("%s", cm_errmsg());
    if (k == 0)
        die("cannot read '%s': no frames", r->name);
    in->nframes = k;
    if (streaming) {
        nwant = choose(o, k, &want);
        in->cur = scratch;
        scratch = NULL;
    }
    in->nsel = nwant;
    in->sel = want;
    if (!streaming) {
        in->X = calloc((size_t)nwant + 1, sizeof *in->X);
        for (int i = 0; i < nwant; i++)
            if (want[i] >= 0) in->X[i] = frames[want[i]];
    }
    free(frames);
    free(keep);
    free(scratch);
}

/* Extend the camera's fit by the chosen frames of an input. */
static void fit_input(struct camera *cam, const struct input *in)
{
    for (int i = 0; i < in->nsel; i++) {
        if (in->sel[i] < 0)
            continue;
        if (!in->streaming)
            camera_fit(cam, in->X[i], in->nv);
        else
            camera_fit_box(cam, in->bounds + 6 * in->sel[i], in->bounds + 6 * in->sel[i] + 3);
    }
}

/* The positions of chosen frame i (sel[i] >= 0). */
static const double *get_frame(struct input *in, int i)
{
    if (!in->streaming)
        return in->X[i];
    int want = in->sel[i];
    if (in->open2 && in->pos > want + 1) {   /* behind us: start over */
        mesh_reader_close(&in->r2);
        in->open2 = 0;
    }
    if (!in->open2) {
        if (mesh_spool_rewind(&in->sp, &in->r2) < 0)
            die("%s", cm_errmsg());
        in->open2 = 1;
        in->pos = 0;
    }
    while (in->pos <= want) {
        int rc = mesh_reader_next(&in->r2, in->cur, NULL);
        if (rc <= 0)
            die("%s", rc < 0 ? cm_errmsg() : "second pass: stream ended early");
        in->pos++;
    }
    return in->cur;
}

/* the colour between tiles: the background, a little darker (lighter if dark) */
static void gap_colour(const unsigned char bg[3], unsigned char out[3])
{
    int lum = (299 * bg[0] + 587 * bg[1] + 114 * bg[2]) / 1000;
    for (int k = 0; k < 3; k++)
        out[k] = (unsigned char)(lum > 128 ? bg[k] * 0.85 : bg[k] + (255 - bg[k]) * 0.2);
}

/* dark text on a light background, light text on a dark one */
static void text_colour(const unsigned char bg[3], unsigned char fg[3])
{
    int lum = (299 * bg[0] + 587 * bg[1] + 114 * bg[2]) / 1000;
    fg[0] = fg[1] = fg[2] = lum > 128 ? 40 : 225;
}

static void render_tile(const struct options *o, struct input *in, int i,
                        const struct camera *cam, struct render_style *st,
                        const struct mesh_colors *mc, const char *label, struct image *tile)
{
    if (o->r.labels || o->r.scalars)
        mesh_colors_apply(mc, st);
    if (raster_render(get_frame(in, i), in->F, in->nv, in->nf, cam, st, o->w, o->h, tile) < 0)
        die("%s", cm_errmsg());
    if (label) {
        int sc = o->h >= 480 ? 3 : o->h >= 200 ? 2 : 1;
        unsigned char fg[3];
        text_colour(o->r.background, fg);
        image_text(tile, 2 * sc, 2 * sc, label, sc, fg, o->r.background);
    }
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    double t0 = now_seconds();

    /* open every input (headers), then decide between memory and streaming */
    struct mesh_reader *rd = calloc((size_t)o.ninputs, sizeof *rd);
    size_t keep_bytes = 0;
    int streaming = o.each != NULL;
    for (int j = 0; j < o.ninputs; j++) {
        if (mesh_reader_open(&rd[j], o.inputs[j]) < 0)
            die("%s", cm_errmsg());
        if (rd[j].nframes < 0) {
            streaming = 1;
            continue;
        }
        int *w, n = choose(&o, rd[j].nframes, &w);
        keep_bytes += (size_t)n * rd[j].nv * 3 * sizeof(double);
        free(w);
    }
    if (keep_bytes > KEEP_LIMIT)
        streaming = 1;
    struct camera cam;
    render_options_camera(&o.r, &cam);
    struct input *in = calloc((size_t)o.ninputs, sizeof *in);
    for (int j = 0; j < o.ninputs; j++) {
        read_input(&o, o.inputs[j], &rd[j], streaming, &cam, &in[j]);
        mesh_reader_close(&rd[j]);
    }
    free(rd);

    /* validate the choice and fit one camera to every chosen frame */
    int maxsel = 0, tiles = 0;
    for (int j = 0; j < o.ninputs; j++) {
        if (in[j].nsel > maxsel) maxsel = in[j].nsel;
        fit_input(&cam, &in[j]);
        for (int i = 0; i < in[j].nsel; i++) tiles += in[j].sel[i] >= 0;
    }
    if (o.sel == SEL_LIST)
        for (int i = 0; i < o.nlist; i++) {
            int any = 0;
            for (int j = 0; j < o.ninputs; j++) any |= in[j].sel[i] >= 0;
            if (!any) {
                if (o.ninputs == 1)
                    die("cannot read '%s': no frame %d (the stream has %d frame%s)", in[0].name,
                        o.list[i], in[0].nframes, in[0].nframes == 1 ? "" : "s");
                die("no input has frame %d", o.list[i]);
            }
        }
    if (tiles == 0)
        die("no frames to draw");

    struct render_style st;
    render_options_style(&o.r, &st);
    struct mesh_colors mc;
    memset(&mc, 0, sizeof mc);
    if (o.r.labels && mesh_colors_labels(o.r.labels, in[0].nv, in[0].nf, &mc) < 0)
        die("%s", cm_errmsg());
    if (o.r.scalars &&
        mesh_colors_scalars(o.r.scalars, in[0].nv, in[0].nf, o.r.have_range ? o.r.range : NULL, &mc) < 0)
        die("%s", cm_errmsg());
    if (o.r.labels || o.r.scalars)
        for (int j = 1; j < o.ninputs; j++) {
            char what[512];
            snprintf(what, sizeof what, "cannot colour '%s'", in[j].name);
            if (mesh_colors_check(&mc, in[j].nv, in[j].nf, what) < 0)
                die("%s", cm_errmsg());
        }
    double t1 = now_seconds();
    info(1, "%d input%s, %d tiles of %dx%d; first pass (%s) %.1f ms", o.ninputs,
         o.ninputs == 1 ? "" : "s", tiles, o.w, o.h,
         streaming ? "streaming: bounds per frame" : "keeping the chosen frames", 1e3 * (t1 - t0));

    char label[64];
    unsigned char gapc[3];
    gap_colour(o.r.background, gapc);
    if (o.each) {
        /* one image per chosen frame slot: inputs side by side */
        struct progress pr;
        progress_start(&pr, progname, maxsel);
        struct image *row = calloc((size_t)o.ninputs, sizeof *row);
        for (int i = 0; i < maxsel; i++) {
            int fnum = -1;   /* file number: the frame of the first input drawn */
            for (int j = 0; j < o.ninputs && fnum < 0; j++)
                if (i < in[j].nsel && in[j].sel[i] >= 0) fnum = in[j].sel[i];
            for (int j = 0; j < o.ninputs; j++) {
                image_free(&row[j]);
                if (i >= in[j].nsel || in[j].sel[i] < 0) {
                    if (image_alloc(&row[j], o.w, o.h, o.r.background) < 0)
                        die("%s", cm_errmsg());
                    continue;
                }
                const char *lab = NULL;
                if (o.stamp || o.titles) {
                    if (o.titles && o.stamp)
                        snprintf(label, sizeof label, "%.40s %d", o.titles[j], in[j].sel[i]);
                    else if (o.titles)
                        snprintf(label, sizeof label, "%.60s", o.titles[j]);
                    else
                        snprintf(label, sizeof label, "%d", in[j].sel[i]);
                    lab = label;
                }
                render_tile(&o, &in[j], i, &cam, &st, &mc, lab, &row[j]);
            }
            struct image im;
            if (o.ninputs == 1) {
                im = row[0];
                row[0].rgb = NULL;
            } else if (image_grid(row, o.ninputs, o.ninputs, o.gap, gapc, &im) < 0)
                die("%s", cm_errmsg());
            size_t n = strlen(o.each) + 32;
            char *path = malloc(n);
            snprintf(path, n, o.each, fnum);
            FILE *f = out_open(path);
            if (image_write(f, &im, o.r.format) < 0)
                die("cannot write '%s': %s", path, cm_errmsg());
            out_close(f);
            info(2, "wrote %s", path);
            free(path);
            image_free(&im);
            progress_step(&pr, i + 1);
        }
        progress_end(&pr);
        for (int j = 0; j < o.ninputs; j++) image_free(&row[j]);
        free(row);
    } else {
        /* contact sheet: each input starts a new row; titles in a left
         * margin.  When every input shows one frame, the inputs flow
         * through the C columns instead (one tile each, its title as the
         * stamp) */
        int flow = o.ninputs > 1 && maxsel == 1;
        int C = o.columns > 0 ? o.columns : flow ? (o.ninputs < 8 ? o.ninputs : 8)
                                          : maxsel < 8 ? maxsel : 8;
        int nrows = 0;
        if (flow) nrows = (o.ninputs + C - 1) / C;
        else for (int j = 0; j < o.ninputs; j++) nrows += (in[j].nsel + C - 1) / C;
        int tsc = o.h >= 480 ? 3 : o.h >= 200 ? 2 : 1;
        int margin = 0;
        if (o.titles && !flow)
            for (int j = 0; j < o.ninputs; j++) {
                int tw = text_width(o.titles[j], tsc) + 2 * tsc + o.gap;
                if (tw > margin) margin = tw;
            }
        struct image sheet;
        if (image_alloc(&sheet, margin + C * o.w + (C + 1) * o.gap,
                        nrows * o.h + (nrows + 1) * o.gap, gapc) < 0)
            die("%s", cm_errmsg());
        unsigned char fg[3];
        text_colour(gapc, fg);
        struct progress pr;
        progress_start(&pr, progname, tiles);
        int r0 = 0, done = 0;
        for (int j = 0; j < o.ninputs; j++) {
            if (o.titles && !flow)
                image_text(&sheet, o.gap + tsc, o.gap + r0 * (o.h + o.gap) + (o.h - text_height(tsc)) / 2,
                           o.titles[j], tsc, fg, NULL);
            for (int i = 0; i < in[j].nsel; i++) {
                if (in[j].sel[i] < 0)
                    continue;
                struct image tile;
                snprintf(label, sizeof label, "%d", in[j].sel[i]);
                if (flow && o.titles) snprintf(label, sizeof label, "%s", o.titles[j]);
                render_tile(&o, &in[j], i, &cam, &st, &mc, o.stamp || (flow && o.titles) ? label : NULL, &tile);
                int r = flow ? j / C : r0 + i / C, c = flow ? j % C : i % C;
                image_blit(&sheet, &tile, margin + o.gap + c * (o.w + o.gap), o.gap + r * (o.h + o.gap));
                image_free(&tile);
                progress_step(&pr, ++done);
            }
            r0 += (in[j].nsel + C - 1) / C;
        }
        progress_end(&pr);
        double t2 = now_seconds();
        FILE *out = out_open(o.r.output);
        if (image_write(out, &sheet, o.r.format) < 0)
            die("cannot write output: %s", cm_errmsg());
        out_close(out);
        info(1, "sheet %dx%d (%d columns, %d rows): render %.1f ms, write %s %.1f ms", sheet.w,
             sheet.h, C, nrows, 1e3 * (t2 - t1), o.r.format, 1e3 * (now_seconds() - t2));
        image_free(&sheet);
    }
    for (int j = 0; j < o.ninputs; j++) {
        if (in[j].streaming) {
            if (in[j].open2) mesh_reader_close(&in[j].r2);
            mesh_spool_free(&in[j].sp);
        } else
            for (int i = 0; i < in[j].nsel; i++) {  /* a frame chosen twice is kept once */
                int seen = 0;
                for (int k = 0; k < i && !seen; k++) seen = in[j].X[k] == in[j].X[i];
                if (!seen) free(in[j].X[i]);
            }
        free((char *)in[j].name);
        free(in[j].F);
        free(in[j].sel);
        free(in[j].X);
        free(in[j].bounds);
        free(in[j].cur);
    }
    free(in);
    free(o.list);
    for (int i = 0; i < o.ntitles; i++) free(o.titles[i]);
    free(o.titles);
    mesh_colors_free(&mc);
    return 0;
}
