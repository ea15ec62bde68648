/* anim-slice -- select frames of a MESH animation: ranges, lists, clips.
 *
 * Streams: memory O(one frame).  Frames come out in stream order; cut marks
 * are kept (a selected frame starts a clip if a cut lay between it and the
 * previous selected frame).  Without options every frame passes through
 * unchanged, which makes anim-slice the plain <-> raw converter:
 *   STOPMO_RAW=1 anim-slice a.mesh >a.raw
 */
#include "mesh.h"
#include "tool.h"
#include "cm_error.h"
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: anim-slice [options] [FILE]\n"
"Select frames of a MESH animation.  Without options every frame passes\n"
"through (a plain <-> raw converter with --raw or STOPMO_RAW=1).\n"
"\n"
"Options:\n"
"  -f, --frames SPEC  comma separated items, each N, START:STOP or\n"
"                     START:STOP:STEP (STOP excluded, as in Python; START\n"
"                     defaults to 0, STOP to the end; negative numbers count\n"
"                     from the end when the stream announces its frame count)\n"
"  -c, --clip K       only clip K (0-based; clips are separated by cut marks);\n"
"                     with --frames, the frame numbers count within the clip\n"
"  -o, --output FILE  write to FILE (temporary + rename) instead of stdout\n"
"      --raw          write the raw (binary) variant (or STOPMO_RAW=1)\n"
"  -v, --verbose      print the number of selected frames on stderr\n"
"  -h, --help         show this help\n"
"      --version      show the version\n"
"\n"
"Frames come out in stream order, each at most once.  A listed single frame\n"
"that does not exist is an error; ranges are clipped to the stream.\n"
"\n"
"Examples:\n"
"  anim-slice -f 0:100:2 walk.mesh >half.mesh    every second of frames 0..99\n"
"  anim-slice -f 0,10,-1 walk.mesh               first, eleventh and last\n"
"  anim-slice --clip 1 takes.mesh                the second clip\n";

struct range { long start, stop, step; int single; int s_rel, e_rel; };

struct options {
    const char *input, *output, *spec;
    int clip, raw;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"frames", 1, 0, 'f'}, {"clip", 1, 0, 'c'}, {"output", 1, 0, 'o'},
        {"raw", 0, 0, 'R'}, {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'},
        {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->clip = -1;
    int c;
    while ((c = getopt_long(argc, argv, "f:c:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'f': o->spec = optarg; break;
        case 'c':
            o->clip = arg_int(optarg, "--clip");
            if (o->clip < 0) usage_error("--clip must be >= 0");
            break;
        case 'o': o->output = optarg; break;
        case 'R': o->raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind < argc - 1)
        usage_error("expected at most one input file");
    o->input = optind < argc ? argv[optind] : NULL;
}

/* one number of a range item; empty -> *present = 0 */
static const char *spec_number(const char *p, long *v, int *present)
{
    *present = 0;
    if (*p == ':' || *p == ',' || *p == 0)
        return p;
    char *end;
    errno = 0;
    long x = strtol(p, &end, 10);
    if (end == p || errno || x > INT_MAX || x < -(long)INT_MAX)
        return NULL;
    *v = x;
    *present = 1;
    return end;
}

static int parse_spec(const char *s, struct range **out)
{
    int n = 0, cap = 4;
    struct range *R = malloc(cap * sizeof *R);
    const char *p = s;
    for (;;) {
        struct range r = {0, LONG_MAX, 1, 0, 0, 0};
        long a = 0, b = 0, st = 1;
        int ha, hb = 0, hs = 0;
        p = spec_number(p, &a, &ha);
        if (!p) goto bad;
        if (*p == ':') {
            p = spec_number(p + 1, &b, &hb);
            if (!p) goto bad;
            if (*p == ':') {
                p = spec_number(p + 1, &st, &hs);
                if (!p || !hs) goto bad;
                if (st <= 0) usage_error("--frames: STEP must be positive in '%s'", s);
            }
            if (ha) { r.start = a; r.s_rel = a < 0; }
            if (hb) { r.stop = b; r.e_rel = b < 0; }
            r.step = st;
        } else {
            if (!ha) goto bad;
            r.start = a;
            r.stop = a + 1;
            r.single = 1;
            r.s_rel = r.e_rel = a < 0;
        }
        if (n == cap) R = realloc(R, (cap *= 2) * sizeof *R);
        R[n++] = r;
        if (*p == 0) break;
        if (*p != ',') goto bad;
        p++;
    }
    *out = R;
    return n;
bad:
    usage_error("--frames: cannot parse '%s' (items N, START:STOP or START:STOP:STEP)", s);
}

/* Resolve negative (from-the-end) numbers against a known frame count. */
static void resolve(struct range *R, int n, long count)
{
    for (int i = 0; i < n; i++) {
        if (R[i].single) {
            if (R[i].start < 0) R[i].start += count;
            R[i].stop = R[i].start + 1;
            continue;
        }
        if (R[i].s_rel) { R[i].start += count; if (R[i].start < 0) R[i].start = 0; }
        if (R[i].e_rel) { R[i].stop += count; if (R[i].stop < 0) R[i].stop = 0; }
    }
}

static int selected(const struct range *R, int n, long k)
{
    if (n == 0)
        return 1;
    for (int i = 0; i < n; i++)
        if (k >= R[i].start && k < R[i].stop && (k - R[i].start) % R[i].step == 0)
            return 1;
    return 0;
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    struct range *R = NULL;
    int nr = o.spec ? parse_spec(o.spec, &R) : 0;

    struct mesh_reader r;
    if (mesh_reader_open(&r, o.input) < 0)
        die("%s", cm_errmsg());
    int relative = 0;
    for (int i = 0; i < nr; i++)
        relative |= R[i].s_rel || R[i].e_rel;
    if (relative) {
        if (o.clip >= 0)
            die("'%s': negative frame numbers cannot be used with --clip", r.name);
        if (r.nframes < 0)
            die("'%s': negative frame numbers need a stream that announces its frame count "
                "(it says 'frames ?')", r.name);
        resolve(R, nr, r.nframes);
    }
    /* output frame count, known in advance unless we select a clip or the
     * input does not say; single frames must exist */
    long count = -1;
    if (o.clip < 0 && r.nframes >= 0) {
        for (int i = 0; i < nr; i++)
            if (R[i].single && (R[i].start < 0 || R[i].start >= r.nframes))
                die("'%s': frame %ld does not exist (%d frames)", r.name,
                    R[i].start - (R[i].s_rel ? r.nframes : 0), r.nframes);
        count = 0;
        for (long k = 0; k < r.nframes; k++)
            count += selected(R, nr, k);
        if (count == 0)
            die("'%s': no frames selected", r.name);
    }

    size_t n3 = (size_t)r.nv * 3;
    double *X = malloc((n3 + 1) * sizeof *X);
    if (!X)
        die("out of memory");
    FILE *out = NULL;
    struct mesh_writer w;
    int raw = want_raw(o.raw);
    long k = 0, clip = 0, kc = 0, written = 0;
    int cut, pending = 0, rc;
    while ((rc = mesh_reader_next(&r, X, &cut)) > 0) {
        if (k > 0 && cut) {
            clip++;
            kc = 0;
            pending = 1;
        }
        int sel = o.clip < 0 ? selected(R, nr, k) : clip == o.clip && selected(R, nr, kc);
        if (sel) {
            if (!out) {
                /* the header goes out with the first selected frame, so an
                 * empty selection writes nothing */
                out = out_open(o.output);
                if (mesh_writer_open(&w, out, r.nv, r.nf, r.F, (int)count, raw) < 0)
                    die("cannot write output: %s", cm_errmsg());
            }
            if (mesh_writer_frame(&w, X, pending) < 0)
                die("cannot write output: %s", cm_errmsg());
            pending = 0;
            written++;
        }
        k++;
        kc++;
    }
    if (rc < 0)
        die("%s", cm_errmsg());
    if (!out) {
        if (o.clip >= 0 && o.clip > clip)
            die("'%s': no clip %d (the stream has %ld clips)", r.name, o.clip, clip + 1);
        die("'%s': no frames selected", r.name);
    }
    if (o.clip >= 0 || r.nframes < 0) {
        /* single frames must have existed */
        long n = o.clip >= 0 ? -1 : k;
        for (int i = 0; i < nr && n >= 0; i++)
            if (R[i].single && R[i].start >= n)
                die("'%s': frame %ld does not exist (%ld frames)", r.name, R[i].start, n);
    }
    if (mesh_writer_close(&w) < 0)
        die("cannot write output: %s", cm_errmsg());
    out_close(out);
    info(1, "selected %ld of %ld frames", written, k);
    mesh_reader_close(&r);
    free(X);
    free(R);
    return 0;
}
