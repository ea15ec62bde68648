/* mesh-export -- a MESH stream to OBJ, PLY, OFF or STL files.
 *
 * One frame goes to one file (or to stdout); an animation goes to numbered
 * files through a printf pattern ("frame_%04d.obj"), streamed one frame at
 * a time.  Every file is written to a temporary name and renamed when
 * complete, so no file is ever half-written.
 */
#include "cm_error.h"
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
"Write a MESH stream (FILE or stdin) as OBJ, PLY, OFF or STL.\n"
"\n"
"Options:\n"
"  -o, --output PATH    output file (default: stdout, OBJ unless --format);\n"
"                       a pattern with one %d (e.g. 'frame_%04d.obj') writes\n"
"                       one file per frame, numbered from 0\n"
"  -f, --format FMT     obj, ply, off or stl (default: from the extension)\n"
"  -k, --frame K        write only frame K (0-based)\n"
"      --ascii          text PLY / STL (default: binary; binary STL is what\n"
"                       slicers for 3D printing expect)\n"
"  -v, --verbose        print counts and timings to stderr\n"
"  -h, --help           show this help\n"
"      --version        show the version\n"
"\n"
"A stream with several frames needs --frame K or a %d pattern.\n"
"\n"
"Examples:\n"
"  mesh-gen -s 3 icosphere | mesh-export -o sphere.stl\n"
"  mesh-export -o 'frames/frame_%04d.obj' anim.mesh\n";

struct options {
    const char *input, *output, *format;
    long frame;
    int ascii, fmt, pattern;
};

/* A printf pattern with exactly one integer conversion (%d, %04d, %5d)
 * and otherwise only %% escapes?  1 yes, 0 no % at all; usage error if
 * malformed. */
static int check_pattern(const char *s)
{
    int n = 0;
    for (const char *p = s; *p; p++) {
        if (*p != '%') continue;
        if (p[1] == '%') { p++; continue; }
        p++;
        while (*p == '0' || *p == '-') p++;
        while (*p >= '0' && *p <= '9') p++;
        if (*p != 'd')
            usage_error("--output: '%s': only %%d (with width) and %%%% are allowed in a pattern", s);
        n++;
    }
    if (n > 1)
        usage_error("--output: '%s': more than one %%d", s);
    return n;
}

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"output", 1, 0, 'o'}, {"format", 1, 0, 'f'}, {"frame", 1, 0, 'k'}, {"ascii", 0, 0, 'a'},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->frame = -1;
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
        if (!o->fmt) usage_error("unknown format '%s' (obj, ply, off, stl)", o->format);
    } else if (o->output) {
        o->fmt = meshio_format_from_name(o->output);
        if (!o->fmt)
            usage_error("cannot tell the format of '%s' (use .obj, .ply, .off, .stl or --format)", o->output);
    } else {
        o->fmt = MESHIO_OBJ;
    }
    o->pattern = o->output ? check_pattern(o->output) : 0;
    if (o->pattern && o->frame >= 0)
        usage_error("give either --frame K or a %%d pattern, not both");
}

static void write_one(const struct options *o, const char *path, const struct mesh_reader *r, const double *X)
{
    FILE *f = out_open(path);
    if (meshio_write(f, path ? path : "<stdout>", o->fmt, o->ascii ? MESHIO_ASCII : 0,
                     r->nv, r->nf, r->F, X) < 0)
        die("%s", cm_errmsg());
    out_close(f);
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);

    struct mesh_reader r;
    if (mesh_reader_open(&r, o.input) < 0)
        die("%s", cm_errmsg());
    double *X = malloc((size_t)r.nv * 3 * sizeof *X + 1);
    double *Y = malloc((size_t)r.nv * 3 * sizeof *Y + 1);
    if (!X || !Y) die("out of memory");
    double t0 = now_seconds();

    if (o.pattern) {
        /* one file per frame, streamed */
        struct progress p;
        progress_start(&p, "mesh-export", r.nframes);
        int k = 0, got;
        size_t n = strlen(o.output) + 32;
        char *name = malloc(n);
        while ((got = mesh_reader_next(&r, X, NULL)) == 1) {
            snprintf(name, n, o.output, k);
            write_one(&o, name, &r, X);
            progress_step(&p, ++k);
        }
        progress_end(&p);
        if (got < 0) die("%s", cm_errmsg());
        free(name);
        info(1, "wrote %d %s file%s, %d vertices, %d triangles, %.2f s", k, meshio_format_name(o.fmt),
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
        info(1, "wrote frame %ld as %s, %d vertices, %d triangles, %.2f s", want, meshio_format_name(o.fmt),
             r.nv, r.nf, now_seconds() - t0);
    }
    mesh_reader_close(&r);
    free(X);
    free(Y);
    return 0;
}
