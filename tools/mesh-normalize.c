/* mesh-normalize -- scale and translate a MESH animation into the unit
 * bounding box (longest side 1, centred at the origin), with one transform
 * for every frame, and print that transform so it can be undone.
 *
 * The bounding box is over all frames, so the input is read twice: a named
 * file is simply reopened; standard input is spooled to an (unlinked)
 * temporary raw stream during the first pass (mesh_spool.h, bit-exact).
 * Memory stays O(one frame).
 */
#include "mesh.h"
#include "mesh_spool.h"
#include "geometry.h"
#include "numparse.h"
#include "tool.h"
#include "cm_error.h"
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <getopt.h>

static const char help[] =
"Usage: mesh-normalize [options] [FILE]\n"
"Scale and translate a MESH animation so that the bounding box of all its\n"
"frames has its longest side 1 and its centre at the origin:\n"
"  x' = s x + t,   s = 1 / longest side,   t = -s * centre.\n"
"The same transform applies to every frame.  It is printed as one line\n"
"  scale S translate TX TY TZ\n"
"on stderr (or to --transform FILE), with round-trip exact numbers.\n"
"\n"
"Options:\n"
"  -t, --transform FILE  write the transform line to FILE instead of stderr\n"
"      --apply FILE      apply the transform in FILE instead of computing one\n"
"      --undo FILE       apply the inverse of the transform in FILE:\n"
"                        x = (x' - t) / s\n"
"  -o, --output FILE     write to FILE (temporary + rename) instead of stdout\n"
"      --raw             write the raw (binary) variant (or STOPMO_RAW=1)\n"
"  -q, --quiet           do not print the transform on stderr\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example:\n"
"  mesh-normalize -t xf.txt big.mesh >unit.mesh\n"
"  mesh-normalize --undo xf.txt unit.mesh >back.mesh\n";

struct options {
    const char *input, *output, *transform, *apply, *undo;
    int raw, quiet;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"transform", 1, 0, 't'}, {"apply", 1, 0, 'A'}, {"undo", 1, 0, 'U'},
        {"output", 1, 0, 'o'}, {"raw", 0, 0, 'R'}, {"quiet", 0, 0, 'q'},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    int c;
    while ((c = getopt_long(argc, argv, "t:o:qvh", lo, NULL)) != -1) {
        switch (c) {
        case 't': o->transform = optarg; break;
        case 'A': o->apply = optarg; break;
        case 'U': o->undo = optarg; break;
        case 'o': o->output = optarg; break;
        case 'R': o->raw = 1; break;
        case 'q': o->quiet = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind < argc - 1)
        usage_error("expected at most one input file");
    if (o->apply && o->undo)
        usage_error("--apply and --undo exclude each other");
    if ((o->apply || o->undo) && o->transform)
        usage_error("--transform writes a computed transform; not with --apply/--undo");
    o->input = optind < argc ? argv[optind] : NULL;
}

/* Read "scale S translate TX TY TZ" (one line; '#' comments allowed). */
static void read_transform(const char *path, double *s, double t[3])
{
    FILE *f = fopen(path, "r");
    if (!f)
        die("cannot read '%s': %s", path, strerror(errno));
    char line[512];
    long lineno = 0;
    int got = 0;
    while (fgets(line, sizeof line, f)) {
        lineno++;
        char *p = line;
        while (*p == ' ' || *p == '\t') p++;
        if (*p == '#' || *p == '\n' || *p == 0)
            continue;
        const char *q = NULL;
        if (!strncmp(p, "scale", 5)) q = parse_double(p + 5, s);
        while (q && (*q == ' ' || *q == '\t')) q++;
        if (q && !strncmp(q, "translate", 9)) {
            q += 9;
            for (int d = 0; d < 3 && q; d++) q = parse_double(q, &t[d]);
        } else q = NULL;
        while (q && (*q == ' ' || *q == '\t' || *q == '\r' || *q == '\n')) q++;
        if (!q || *q || !isfinite(*s) || *s == 0 || !isfinite(t[0]) || !isfinite(t[1]) ||
            !isfinite(t[2]))
            die("cannot read '%s': line %ld: expected 'scale S translate TX TY TZ' "
                "(S nonzero)", path, lineno);
        got = 1;
        break;
    }
    fclose(f);
    if (!got)
        die("cannot read '%s': no 'scale S translate TX TY TZ' line", path);
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);

    double s = 1, t[3] = {0, 0, 0};
    int compute = !o.apply && !o.undo;
    if (o.apply) read_transform(o.apply, &s, t);
    if (o.undo) read_transform(o.undo, &s, t);

    const char *path = o.input;
    struct mesh_reader r;
    struct mesh_spool sp;
    double *X = NULL;
    int rc, cut;
    if (mesh_reader_open(&r, path) < 0)
        die("%s", cm_errmsg());
    if (!(X = malloc(((size_t)r.nv * 3 + 1) * sizeof *X)))
        die("out of memory");
    if (compute) {
        /* pass 1: bounding box of all frames */
        if (mesh_spool_begin(&sp, path, &r) < 0)
            die("%s", cm_errmsg());
        double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
        long k = 0;
        while ((rc = mesh_reader_next(&r, X, &cut)) > 0) {
            if (mesh_spool_frame(&sp, X, cut) < 0)
                die("%s", cm_errmsg());
            double l[3], h[3];
            if (r.nv == 0) continue;
            bounding_box(X, r.nv, l, h);
            for (int d = 0; d < 3; d++) {
                if (k == 0 || l[d] < lo[d]) lo[d] = l[d];
                if (k == 0 || h[d] > hi[d]) hi[d] = h[d];
            }
            k++;
        }
        if (rc < 0)
            die("%s", cm_errmsg());
        double side = 0;
        for (int d = 0; d < 3; d++)
            if (hi[d] - lo[d] > side) side = hi[d] - lo[d];
        s = side > 0 ? 1 / side : 1;
        /* an extent that overflows (1e308 wide) or whose inverse does
         * (below 1e-308) has no scale that double precision can undo */
        if (!isfinite(side) || (side > 0 && !(s >= DBL_MIN && s <= DBL_MAX))) {
            long double ext = 0;
            for (int d = 0; d < 3; d++)
                if ((long double)hi[d] - lo[d] > ext) ext = (long double)hi[d] - lo[d];
            die("cannot read '%s': its extent %Lg cannot be scaled to 1 in double precision",
                r.name, ext);
        }
        for (int d = 0; d < 3; d++)
            t[d] = -s * 0.5 * (lo[d] + hi[d]) + 0.0;   /* no -0 */
        mesh_reader_close(&r);
        if (mesh_spool_rewind(&sp, &r) < 0)
            die("%s", cm_errmsg());
    }

    /* the transform to apply: x' = a x + b */
    double a = s, b[3] = {t[0], t[1], t[2]};
    if (o.undo) {
        a = 1 / s;
        for (int d = 0; d < 3; d++) b[d] = -t[d] / s;
    }
    FILE *out = out_open(o.output);
    struct mesh_writer w;
    if (mesh_writer_open(&w, out, r.nv, r.nf, r.F, r.nframes, want_raw(o.raw)) < 0)
        die("cannot write output: %s", cm_errmsg());
    size_t nv = (size_t)r.nv;
    while ((rc = mesh_reader_next(&r, X, &cut)) > 0) {
        if (o.undo)
            for (size_t i = 0; i < nv; i++)
                for (int d = 0; d < 3; d++) X[3 * i + d] = (X[3 * i + d] - t[d]) / s;
        else
            for (size_t i = 0; i < nv; i++)
                for (int d = 0; d < 3; d++) X[3 * i + d] = a * X[3 * i + d] + b[d];
        for (size_t i = 0; i < 3 * nv; i++)
            if (!isfinite(X[i]))
                die("cannot read '%s': frame %d: vertex %zu: the transform overflows", r.name,
                    r.frame - 1, i / 3);
        if (mesh_writer_frame(&w, X, cut) < 0)
            die("cannot write output: %s", cm_errmsg());
    }
    if (rc < 0)
        die("%s", cm_errmsg());
    if (mesh_writer_close(&w) < 0)
        die("cannot write output: %s", cm_errmsg());
    if (compute) {
        char xs[4][40];
        format_double(xs[0], s);
        for (int d = 0; d < 3; d++) format_double(xs[d + 1], t[d]);
        if (o.transform) {
            FILE *tf = out_open(o.transform);
            fprintf(tf, "scale %s translate %s %s %s\n", xs[0], xs[1], xs[2], xs[3]);
            out_close(tf);
        } else if (!o.quiet) {
            fprintf(stderr, "scale %s translate %s %s %s\n", xs[0], xs[1], xs[2], xs[3]);
        }
    }
    out_close(out);
    mesh_reader_close(&r);
    if (compute)
        mesh_spool_free(&sp);
    free(X);
    return 0;
}
