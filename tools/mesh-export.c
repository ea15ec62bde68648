/* mesh-export -- a MESH stream to OBJ, PLY, OFF, STL or glTF 2.0 files.
 *
 * One frame goes to one file (or to stdout); an animation goes to numbered
 * files through a printf pattern ("frame_%04d.obj"), streamed one frame at
 * a time, or to one glTF (.glb, .gltf) whose morph targets are the frames
 * and whose STEP-keyed one-hot weights play them, one glTF animation per
 * clip.  --pieces LIB:LABELS writes a replacement animation the same way:
 * per part, one mesh whose morph targets are the printed pieces.  Every
 * file is written to a temporary name and renamed when complete, so no file
 * is ever half-written.
 */
#include "cm_error.h"
#include "columns.h"
#include "gltf_write.h"
#include "mesh.h"
#include "meshio.h"
#include "progress.h"
#include "tool.h"
#include <errno.h>
#include <getopt.h>
#include <stdlib.h>
#include <string.h>

static const char help[] =
"Usage: mesh-export [options] [FILE]\n"
"       mesh-export [options] -o FILM.glb --pieces LIB:LABELS [--pieces ...]\n"
"Write a MESH stream (FILE or stdin) as OBJ, PLY, OFF, STL or glTF 2.0.\n"
"\n"
"Options:\n"
"  -o, --output PATH    output file (default: stdout, OBJ unless --format);\n"
"                       a pattern with one %d (e.g. 'frame_%04d.obj') writes\n"
"                       one file per frame, numbered from 0\n"
"  -f, --format FMT     obj, ply, off, stl, glb or gltf (default: from the\n"
"                       extension)\n"
"  -k, --frame K        write only frame K (0-based)\n"
"      --ascii          text PLY / STL (default: binary; binary STL is what\n"
"                       slicers for 3D printing expect)\n"
"      --fps F          glTF: frames per second of the animation (default 24)\n"
"      --pieces LIB:LABELS  glTF: a replacement animation: one part's pieces\n"
"                       (a MESH stream, one frame per piece) and its per-frame\n"
"                       piece labels; repeat for every part (one mesh each)\n"
"  -v, --verbose        print counts and timings to stderr\n"
"  -h, --help           show this help\n"
"      --version        show the version\n"
"\n"
"A stream with several frames needs --frame K or a %d pattern, except for\n"
"glTF: one .glb/.gltf holds the whole animation (every frame a morph target,\n"
"one-hot STEP weights, one glTF animation per clip).  A .gltf file gets its\n"
"buffer in FILE.bin beside it (on stdout: embedded as base64).\n"
"\n"
"Examples:\n"
"  mesh-gen -s 3 icosphere | mesh-export -o sphere.stl\n"
"  mesh-export -o 'frames/frame_%04d.obj' anim.mesh\n"
"  mesh-export --fps 12 -o film.glb stopmo.mesh\n"
"  mesh-export -o film.glb --pieces lib_0.mesh:labels_0.txt \\\n"
"              --pieces lib_1.mesh:labels_1.txt\n";

struct options {
    const char *input, *output, *format;
    long frame;
    int ascii, fmt, pattern;
    int gltf;                  /* GLTF_JSON, GLTF_BINARY or 0 (fmt is meshio's) */
    double fps;
    char **pieces;             /* np "LIB:LABELS" specs */
    int np;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"output", 1, 0, 'o'}, {"format", 1, 0, 'f'}, {"frame", 1, 0, 'k'}, {"ascii", 0, 0, 'a'},
        {"fps", 1, 0, 'P'}, {"pieces", 1, 0, 'L'},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->frame = -1;
    o->fps = 24;
    int c;
    while ((c = getopt_long(argc, argv, "o:f:k:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'o': o->output = optarg; break;
        case 'f': o->format = optarg; break;
        case 'k':
            o->frame = arg_long(optarg, "--frame");
            if (o->frame < 0) usage_error("--frame must not be negative");
            break;
        case 'a': o->ascii = 1; break;
        case 'P':
            o->fps = arg_double(optarg, "--fps");
            if (!(o->fps > 0 && o->fps <= 10000)) usage_error("--fps must be in (0, 10000]");
            break;
        case 'L': {
            const char *colon = strchr(optarg, ':');
            if (!colon || colon == optarg || !colon[1] || strchr(colon + 1, ':'))
                usage_error("--pieces: expected LIB:LABELS, got '%s'", optarg);
            o->pieces = realloc(o->pieces, (o->np + 1) * sizeof *o->pieces);
            if (!o->pieces) die("out of memory");
            o->pieces[o->np++] = optarg;
            break;
        }
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind < argc - 1)
        usage_error("expected at most one input FILE");
    o->input = optind < argc ? argv[optind] : NULL;
    if (o->output && !strcmp(o->output, "-")) o->output = NULL;
    if (o->format) {
        o->fmt = meshio_format_parse(o->format);
        o->gltf = gltf_container_parse(o->format);
        if (!o->fmt && !o->gltf) usage_error("unknown format '%s' (obj, ply, off, stl, glb, gltf)", o->format);
    } else if (o->output) {
        o->fmt = meshio_format_from_name(o->output);
        o->gltf = gltf_container_from_name(o->output);
        if (!o->fmt && !o->gltf)
            usage_error("cannot tell the format of '%s' (use .obj, .ply, .off, .stl, .glb, .gltf or --format)",
                        o->output);
    } else {
        o->fmt = MESHIO_OBJ;
    }
    o->pattern = o->output ? pattern_check(o->output, "--output", 0) : 0;
    if (o->pattern && o->frame >= 0)
        usage_error("give either --frame K or a %%d pattern, not both");
    if (o->np) {
        if (!o->gltf) usage_error("--pieces writes glTF: use -o FILE.glb or .gltf (or --format glb)");
        if (o->input) usage_error("--pieces takes no input FILE");
        if (o->pattern || o->frame >= 0) usage_error("--pieces writes one file: no --frame, no %%d pattern");
        int nstdin = 0;
        for (int i = 0; i < o->np; i++)
            nstdin += !strncmp(o->pieces[i], "-:", 2) + !strcmp(strchr(o->pieces[i], ':') + 1, "-");
        if (nstdin > 1) usage_error("only one input can be standard input ('-')");
    }
}

/* a file's name without directories and extension, for mesh names */
static char *stem(const char *path, const char *def)
{
    if (!path || !strcmp(path, "-")) return strdup(def);
    const char *b = strrchr(path, '/');
    b = b ? b + 1 : path;
    char *s = strdup(b);
    char *dot = strrchr(s, '.');
    if (dot && dot != s) *dot = '\0';
    return s;
}

/* Write a finished glTF scene to path (NULL: stdout).  A .gltf file gets
 * its buffer in a .bin file beside it; on stdout it is embedded. */
static void gltf_save(const struct options *o, const char *path, struct gltf_writer *g)
{
    const char *name = path ? path : "<stdout>";
    if (o->gltf == GLTF_JSON && path) {
        size_t n = strlen(path);
        char *bin = malloc(n + 5);
        if (!bin) die("out of memory");
        memcpy(bin, path, n + 1);
        if (gltf_container_from_name(bin) == GLTF_JSON) bin[n - 5] = '\0';
        strcat(bin, ".bin");
        const char *uri = strrchr(bin, '/');
        uri = uri ? uri + 1 : bin;
        FILE *bf = out_open(bin);
        FILE *f = out_open(path);
        if (gltf_write(g, GLTF_JSON, f, name, bf, uri) < 0)
            die("%s", cm_errmsg());
        out_close(bf);
        out_close(f);
        free(bin);
    } else {
        FILE *f = out_open(path);
        if (gltf_write(g, o->gltf, f, name, NULL, NULL) < 0)
            die("%s", cm_errmsg());
        out_close(f);
    }
}

static struct gltf_writer *gltf_new(void)
{
    struct gltf_writer *g = gltf_writer_new("stopmo mesh-export " STOPMO_VERSION);
    if (!g) die("%s", cm_errmsg());
    return g;
}

static void write_one(const struct options *o, const char *path, const struct mesh_reader *r, const double *X)
{
    if (o->gltf) {
        struct gltf_writer *g = gltf_new();
        char *nm = stem(o->input, "mesh");
        if (gltf_add_mesh(g, nm, r->nv, r->nf, r->F, X) < 0)
            die("%s", cm_errmsg());
        gltf_save(o, path, g);
        gltf_writer_free(g);
        free(nm);
        return;
    }
    FILE *f = out_open(path);
    if (meshio_write(f, path ? path : "<stdout>", o->fmt, o->ascii ? MESHIO_ASCII : 0,
                     r->nv, r->nf, r->F, X) < 0)
        die("%s", cm_errmsg());
    out_close(f);
}

/* The whole stream as one glTF: every frame a morph target (frame 0 is
 * also the base), one animation per clip with one-hot STEP weights. */
static void write_gltf_animation(const struct options *o, struct mesh_reader *r, double *X, double *Y)
{
    struct gltf_writer *g = gltf_new();
    char *nm = stem(o->input, "mesh");
    int got = mesh_reader_next(r, X, NULL);
    if (got < 0) die("%s", cm_errmsg());
    if (got == 0) die("cannot read '%s': the stream has no frames", r->name);
    if (gltf_add_mesh(g, nm, r->nv, r->nf, r->F, X) < 0)
        die("%s", cm_errmsg());
    int n = 1, cap = 64, nclip = 1, cut;
    int *start = malloc(cap * sizeof *start);   /* first frame of each clip, then n */
    if (!start) die("out of memory");
    start[0] = 0;
    char tname[32];
    struct progress p;
    progress_start(&p, "mesh-export", r->nframes);
    while ((got = mesh_reader_next(r, Y, &cut)) == 1) {
        if (n == 1) {
            snprintf(tname, sizeof tname, "frame_%04d", 0);
            if (gltf_add_target(g, 0, tname, X) < 0) die("%s", cm_errmsg());
        }
        snprintf(tname, sizeof tname, "frame_%04d", n);
        if (gltf_add_target(g, 0, tname, Y) < 0) die("%s", cm_errmsg());
        if (cut) {
            if (nclip + 1 >= cap && !(start = realloc(start, (cap *= 2) * sizeof *start))) die("out of memory");
            start[nclip++] = n;
        }
        progress_step(&p, ++n);
    }
    progress_end(&p);
    if (got < 0) die("%s", cm_errmsg());
    start[nclip] = n;
    if (n > 1) {
        int *hot = malloc((size_t)n * sizeof *hot);
        double *t = malloc((size_t)n * sizeof *t);
        if (!hot || !t) die("out of memory");
        for (int c = 0; c < nclip; c++) {
            char aname[300];
            if (nclip == 1) snprintf(aname, sizeof aname, "%s", nm);
            else snprintf(aname, sizeof aname, "%s_clip_%d", nm, c);
            int len = start[c + 1] - start[c];
            for (int k = 0; k < len; k++) {
                t[k] = k / o->fps;
                hot[k] = start[c] + k;
            }
            int a = gltf_add_animation(g, aname);
            if (a < 0 || gltf_add_onehot_channel(g, a, 0, len, t, hot) < 0)
                die("%s", cm_errmsg());
        }
        free(hot);
        free(t);
    }
    gltf_save(o, o->output, g);
    info(1, "wrote %s: %d frame%s (%d clip%s, %g fps), %d vertices, %d triangles",
         o->output ? o->output : "<stdout>", n, n == 1 ? "" : "s", nclip, nclip == 1 ? "" : "s", o->fps,
         r->nv, r->nf);
    gltf_writer_free(g);
    free(start);
    free(nm);
}

/* --pieces: a replacement animation, one mesh per part whose morph targets
 * are the part's pieces, one animation whose channels mount piece
 * labels[k] of every part in frame k. */
static void write_gltf_pieces(const struct options *o)
{
    size_t np = (size_t)(o->np > 0 ? o->np : 1);
    struct mesh *lib = calloc(np, sizeof *lib);
    int **lab = calloc(np, sizeof *lab), n = 0;
    if (!lib || !lab) die("out of memory");
    for (int p = 0; p < o->np; p++) {
        char *spec = strdup(o->pieces[p]);
        char *labels = strchr(spec, ':');
        *labels++ = '\0';
        if (mesh_read(spec, &lib[p]) < 0)
            die("%s", cm_errmsg());
        int nl;
        if (labels_read(labels, -1, "frames", 0, lib[p].nframes - 1, &lab[p], &nl) < 0)
            die("%s", cm_errmsg());
        const char *lname = strcmp(labels, "-") ? labels : "<stdin>";
        if (nl < 1)
            die("cannot read '%s': no labels (one piece number per frame expected)", lname);
        if (p > 0 && nl != n)
            die("cannot read '%s': %d labels, but part 0 has %d frames", lname, nl, n);
        n = nl;
        free(spec);
    }
    struct gltf_writer *g = gltf_new();
    char name[32];
    for (int p = 0; p < o->np; p++) {
        snprintf(name, sizeof name, "part_%d", p);
        if (gltf_add_mesh(g, name, lib[p].nv, lib[p].nf, lib[p].F, mesh_frame(&lib[p], 0)) < 0)
            die("%s", cm_errmsg());
        for (int i = 0; i < lib[p].nframes; i++) {
            snprintf(name, sizeof name, "piece_%d", i);
            if (gltf_add_target(g, p, name, mesh_frame(&lib[p], i)) < 0)
                die("%s", cm_errmsg());
        }
    }
    double *t = malloc((size_t)n * sizeof *t);
    if (!t) die("out of memory");
    for (int k = 0; k < n; k++) t[k] = k / o->fps;
    int a = gltf_add_animation(g, "replacement");
    for (int p = 0; p < o->np; p++)
        if (a < 0 || gltf_add_onehot_channel(g, a, p, n, t, lab[p]) < 0)
            die("%s", cm_errmsg());
    gltf_save(o, o->output, g);
    info(1, "wrote %s: %d part%s, %d frames at %g fps", o->output ? o->output : "<stdout>", o->np,
         o->np == 1 ? "" : "s", n, o->fps);
    gltf_writer_free(g);
    for (int p = 0; p < o->np; p++) { mesh_free(&lib[p]); free(lab[p]); }
    free(lib);
    free(lab);
    free(t);
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    if (o.np) {
        write_gltf_pieces(&o);
        free(o.pieces);
        return 0;
    }

    struct mesh_reader r;
    if (mesh_reader_open(&r, o.input) < 0)
        die("%s", cm_errmsg());
    double *X = malloc((size_t)r.nv * 3 * sizeof *X + 1);
    double *Y = malloc((size_t)r.nv * 3 * sizeof *Y + 1);
    if (!X || !Y) die("out of memory");
    double t0 = now_seconds();

    if (o.gltf && !o.pattern && o.frame < 0) {
        write_gltf_animation(&o, &r, X, Y);
        info(1, "%.2f s", now_seconds() - t0);
    } else if (o.pattern) {
        /* one file per frame, streamed */
        struct progress p;
        progress_start(&p, "mesh-export", r.nframes);
        int k = 0, got;
        while ((got = mesh_reader_next(&r, X, NULL)) == 1) {
            char *name = pattern_format(o.output, k);
            write_one(&o, name, &r, X);
            free(name);
            progress_step(&p, ++k);
        }
        progress_end(&p);
        if (got < 0) die("%s", cm_errmsg());
        info(1, "wrote %d %s file%s, %d vertices, %d triangles, %.2f s", k,
             o.gltf ? (o.gltf == GLTF_BINARY ? "glb" : "gltf") : meshio_format_name(o.fmt),
             k == 1 ? "" : "s", r.nv, r.nf, now_seconds() - t0);
    } else {
        /* one frame: --frame K, or the only frame of the stream */
        long want = o.frame >= 0 ? o.frame : 0;
        long k = 0;
        int got;
        while ((got = mesh_reader_next(&r, X, NULL)) == 1 && k < want) k++;
        if (got < 0) die("%s", cm_errmsg());
        if (got == 0)
            die("cannot read '%s': no frame %ld (the stream has %ld)", r.name, want, k);
        if (o.frame < 0) {
            got = mesh_reader_next(&r, Y, NULL);
            if (got < 0) die("%s", cm_errmsg());
            if (got == 1)
                die("cannot write: '%s' has several frames; choose one with --frame K or "
                    "write all with a %%d pattern in -o", r.name);
        }
        write_one(&o, o.output, &r, X);
        if (!o.output && fclose(stdout) != 0)
            die("cannot write output: %s", strerror(errno));
        info(1, "wrote frame %ld as %s, %d vertices, %d triangles, %.2f s", want,
             o.gltf ? (o.gltf == GLTF_BINARY ? "glb" : "gltf") : meshio_format_name(o.fmt),
             r.nv, r.nf, now_seconds() - t0);
    }
    mesh_reader_close(&r);
    free(X);
    free(Y);
    free(o.pieces);
    return 0;
}
