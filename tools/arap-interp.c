/* arap-interp -- as-rigid-as-possible in-betweens of key poses that share
 * one connectivity (E-StopMotion thesis Sec. 3.2.7, corrected: A = R S,
 * R interpolated by angle on a consistent branch, S linearly).
 */
#include "arap_interp.h"
#include "mesh.h"
#include "mesh_concat.h"
#include "progress.h"
#include "tool.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: arap-interp [options] KEYS            (one stream, key poses as frames)\n"
"       arap-interp [options] SOURCE TARGET   (two streams, same connectivity)\n"
"As-rigid-as-possible in-betweens between consecutive key poses.\n"
"\n"
"Options:\n"
"  -n, --steps N      N intervals per pair of keys: writes t = 0, 1/N, ..., 1\n"
"                     (keys shared between segments written once; default 10)\n"
"  -t, --time T       write one pose at time T per pair of keys instead\n"
"                     (T = 0 source, 1 target; any real value extrapolates)\n"
"  -o, --output FILE  write to FILE (atomically) instead of stdout\n"
"      --raw          write the raw (binary) MESH variant (or STOPMO_RAW=1)\n"
"  -v, --verbose      print timings and the largest rotation angle\n"
"  -h, --help         show this help\n"
"      --version      show the version\n"
"\n"
"Example: arap-interp --steps 10 camel-01.mesh camel-02-reg.mesh > inbetween.mesh\n";

struct options {
    const char *in[2];
    int nin, steps, raw, have_t;
    double t;
    const char *output;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"steps", 1, 0, 'n'}, {"time", 1, 0, 't'}, {"output", 1, 0, 'o'},
        {"raw", 0, 0, 'R'}, {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'},
        {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->steps = 10;
    int c;
    while ((c = getopt_long(argc, argv, "n:t:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'n': o->steps = arg_int(optarg, "--steps"); break;
        case 't': o->t = arg_double(optarg, "--time"); o->have_t = 1; break;
        case 'o': o->output = optarg; break;
        case 'R': o->raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (o->steps < 1 || o->steps > 100000) usage_error("--steps must be in 1..100000");
    o->nin = argc - optind;
    if (o->nin > 2) usage_error("expected KEYS or SOURCE TARGET");
    if (o->nin == 0) { o->in[0] = "-"; o->nin = 1; }
    else for (int i = 0; i < o->nin; i++) o->in[i] = argv[optind + i];
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    struct mesh keys;
    if (mesh_read_concat(o.in, o.nin, &keys) < 0) die("%s", cm_errmsg());
    if (keys.nframes < 2) die("cannot interpolate: need at least two key poses, got %d", keys.nframes);
    int nseg = keys.nframes - 1, nv = keys.nv;
    int nout = o.have_t ? nseg : nseg * o.steps + 1;
    /* set up every segment before the first byte of output */
    struct arap_interp **seg = calloc(nseg, sizeof *seg);
    double t0 = now_seconds();
    for (int s = 0; s < nseg; s++) {
        seg[s] = arap_interp_new(mesh_frame(&keys, s), mesh_frame(&keys, s + 1), keys.F, nv, keys.nf);
        if (!seg[s]) die("key poses %d -> %d: %s", s, s + 1, cm_errmsg());
        info(1, "segment %d: largest rotation %.1f degrees", s,
             arap_interp_max_angle(seg[s]) * 180 / M_PI);
    }
    info(1, "setup (factor) %.3f s", now_seconds() - t0);
    double *X = malloc((size_t)nv * 3 * sizeof *X + 1);
    FILE *out = out_open(o.output);
    struct mesh_writer w;
    if (mesh_writer_open(&w, out, nv, keys.nf, keys.F, nout, want_raw(o.raw)) < 0)
        die("cannot write output: %s", cm_errmsg());
    struct progress p;
    progress_start(&p, progname, nout);
    double t1 = now_seconds();
    int done = 0;
    for (int s = 0; s < nseg; s++) {
        int kmax = o.have_t ? 1 : (s == nseg - 1 ? o.steps + 1 : o.steps);
        for (int k = 0; k < kmax; k++) {
            double t = o.have_t ? o.t : (double)k / o.steps;
            if (arap_interp_pose(seg[s], t, X) < 0) die("solve failed: %s", cm_errmsg());
            if (mesh_writer_frame(&w, X, 0) < 0) die("cannot write output: %s", cm_errmsg());
            progress_step(&p, ++done);
        }
    }
    progress_end(&p);
    if (mesh_writer_close(&w) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(out);
    info(1, "%d poses in %.3f s", nout, now_seconds() - t1);
    for (int s = 0; s < nseg; s++) arap_interp_free(seg[s]);
    free(seg);
    free(X);
    mesh_free(&keys);
    return 0;
}
