/* lin-interp -- linear in-betweens of key poses that share one
 * connectivity: X(t) = (1 - t) V0 + t V1 per vertex.  The baseline that
 * arap-interp is measured against (thesis Tables 3.1-3.2).
 */
#include "mesh.h"
#include "mesh_concat.h"
#include "tool.h"
#include "cm_error.h"
#include <stdlib.h>
#include <string.h>
#include <getopt.h>

static const char help[] =
"Usage: lin-interp [options] KEYS            (one stream, key poses as frames)\n"
"       lin-interp [options] SOURCE TARGET   (two streams, same connectivity)\n"
"Linear (per-vertex) in-betweens between consecutive key poses.\n"
"\n"
"Options:\n"
"  -n, --steps N      N intervals per pair of keys: t = 0, 1/N, ..., 1 (default 10)\n"
"  -t, --time T       write one pose at time T per pair of keys instead\n"
"  -o, --output FILE  write to FILE (atomically) instead of stdout\n"
"      --raw          write the raw (binary) MESH variant (or STOPMO_RAW=1)\n"
"  -h, --help         show this help\n"
"      --version      show the version\n"
"\n"
"Example: lin-interp --steps 10 a.mesh b.mesh | mesh-metrics -r a.mesh\n";

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    static const struct option lo[] = {
        {"steps", 1, 0, 'n'}, {"time", 1, 0, 't'}, {"output", 1, 0, 'o'},
        {"raw", 0, 0, 'R'}, {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'},
        {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    int steps = 10, raw = 0, have_t = 0, c;
    double tt = 0;
    const char *output = NULL;
    while ((c = getopt_long(argc, argv, "n:t:o:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'n': steps = arg_int(optarg, "--steps"); break;
        case 't': tt = arg_double(optarg, "--time"); have_t = 1; break;
        case 'o': output = optarg; break;
        case 'R': raw = 1; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (steps < 1 || steps > 100000) usage_error("--steps must be in 1..100000");
    int nin = argc - optind;
    if (nin > 2) usage_error("expected KEYS or SOURCE TARGET");
    const char *in[2] = {"-", NULL};
    if (nin == 0) nin = 1;
    else for (int i = 0; i < nin; i++) in[i] = argv[optind + i];
    struct mesh keys;
    if (mesh_read_concat(in, nin, &keys) < 0) die("%s", cm_errmsg());
    if (keys.nframes < 2) die("cannot interpolate: need at least two key poses, got %d", keys.nframes);
    int nseg = keys.nframes - 1, nv = keys.nv;
    int nout = have_t ? nseg : nseg * steps + 1;
    double *X = malloc((size_t)nv * 3 * sizeof *X + 1);
    FILE *out = out_open(output);
    struct mesh_writer w;
    if (mesh_writer_open(&w, out, nv, keys.nf, keys.F, nout, want_raw(raw)) < 0)
        die("cannot write output: %s", cm_errmsg());
    for (int s = 0; s < nseg; s++) {
        const double *A = mesh_frame(&keys, s), *B = mesh_frame(&keys, s + 1);
        int kmax = have_t ? 1 : (s == nseg - 1 ? steps + 1 : steps);
        for (int k = 0; k < kmax; k++) {
            double t = have_t ? tt : (double)k / steps;
            for (int i = 0; i < 3 * nv; i++) X[i] = (1 - t) * A[i] + t * B[i];
            if (mesh_writer_frame(&w, X, 0) < 0) die("cannot write output: %s", cm_errmsg());
        }
    }
    if (mesh_writer_close(&w) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(out);
    free(X);
    mesh_free(&keys);
    return 0;
}
