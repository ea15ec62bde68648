/* label-expand -- per-frame labels for a fixed replacement library
 * (StopShop Sec. 3.3, label step, Eq. 14-16): exact chain DP, or
 * alpha-expansion / swap on BK max-flow as in the paper.
 */
#include "replib.h"
#include "swapcost.h"
#include "blas_tune.h"
#include "mesh.h"
#include "columns.h"
#include "tool.h"
#include "cm_error.h"
#include <getopt.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static const char help[] =
"Usage: label-expand [options] LIBRARY [FILE]\n"
"Label every frame of an animation (MESH stream FILE, default stdin) with a\n"
"piece of a fixed LIBRARY (MESH stream, frames = pieces), minimizing the\n"
"StopShop energy |x_f - r_l|_W^2 + lambda/2 |dx - dr|_W^2 (Eq. 14-16).\n"
"Labels (0-based piece ids, one per frame) go to stdout; the energy to stderr.\n"
"\n"
"Options:\n"
"  -m, --method M        dp (exact chain DP, default) | expansion | swap\n"
"  -l, --lambda X        velocity weight (default 2)\n"
"  -w, --weights FILE    per-vertex saliency weights\n"
"  -c, --swap-cost C     each change of piece between consecutive frames of a\n"
"                        clip costs C (data-term units) in the energy: fewer\n"
"                        swaps on set; still exact with --method dp (default 0)\n"
"      --swap-sweep LIST relabel for each swap cost of LIST (\"0,1,10\") and\n"
"                        print \"swap_cost swaps energy data velocity mean_err\n"
"                        max_err\" lines (energy without the swap term, Eq. 10)\n"
"                        instead of the labels\n"
"      --report FILE     energy report (key value lines, with the swaps)\n"
"  -q, --quiet           do not print the energy line\n"
"  -o, --output FILE     write the labels to FILE instead of stdout\n"
"  -v, --verbose         timings and swaps on stderr\n"
"  -h, --help            show this help\n"
"      --version         show the version\n"
"\n"
"Example: lib-uniform -d 20 anim.mesh >u.lib && label-expand u.lib anim.mesh >u.lab\n";

struct options {
    const char *library, *input, *weights, *report, *output;
    double lambda, swap_cost;
    double *sweep;
    int nsweep;
    int quiet;
    enum replib_method method;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"method", 1, 0, 'm'}, {"lambda", 1, 0, 'l'}, {"weights", 1, 0, 'w'},
        {"swap-cost", 1, 0, 'c'}, {"swap-sweep", 1, 0, 'S'},
        {"report", 1, 0, 'P'}, {"quiet", 0, 0, 'q'}, {"output", 1, 0, 'o'},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    o->lambda = 2;
    int c;
    while ((c = getopt_long(argc, argv, "m:l:w:c:qo:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'm':
            if (!strcmp(optarg, "dp")) o->method = REPLIB_DP;
            else if (!strcmp(optarg, "expansion")) o->method = REPLIB_EXPANSION;
            else if (!strcmp(optarg, "swap")) o->method = REPLIB_SWAP;
            else usage_error("--method: '%s' is not dp, expansion or swap", optarg);
            break;
        case 'l': o->lambda = arg_double(optarg, "--lambda"); break;
        case 'w': o->weights = optarg; break;
        case 'c': o->swap_cost = arg_nonneg(optarg, "--swap-cost"); break;
        case 'S':
            o->nsweep = arg_nonneg_list(optarg, "--swap-sweep", &o->sweep);
            break;
        case 'P': o->report = optarg; break;
        case 'q': o->quiet = 1; break;
        case 'o': o->output = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (optind >= argc) usage_error("expected a LIBRARY");
    if (optind < argc - 2) usage_error("expected LIBRARY and at most one input FILE");
    o->library = argv[optind];
    o->input = optind + 1 < argc ? argv[optind + 1] : NULL;
    if (!(o->lambda >= 0) || !isfinite(o->lambda)) usage_error("--lambda must be >= 0");
    if (o->nsweep && o->swap_cost > 0) usage_error("--swap-sweep and --swap-cost exclude each other");
}

int main(int argc, char **argv)
{
    blas_tune(argv);
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    struct mesh lib, m;
    if (mesh_read(o.library, &lib) < 0) die("%s", cm_errmsg());
    if (mesh_read(o.input, &m) < 0) die("%s", cm_errmsg());
    const char *iname = o.input ? o.input : "<stdin>";
    if (lib.nv != m.nv)
        die("cannot read '%s': %d vertices per frame, the library '%s' has %d", iname, m.nv, o.library, lib.nv);
    struct columns wc = {0};
    if (o.weights && columns_read(o.weights, 1, m.nv, "vertices", &wc) < 0) die("%s", cm_errmsg());

    struct timespec t0, t1;
    clock_gettime(CLOCK_MONOTONIC, &t0);
    struct replib_data D = {0};
    D.n = m.nframes; D.nv = m.nv; D.X = m.V; D.nfix = lib.nframes; D.Rfix = lib.V;
    D.w = o.weights ? wc.x : NULL; D.cut = m.cut; D.gram = 0;
    D.swap_cost = o.swap_cost;
    if (replib_prepare(&D) < 0) die("cannot read '%s': %s", iname, cm_errmsg());
    int *l = malloc(sizeof(int) * m.nframes);
    if (!l) die("out of memory");
    if (o.nsweep) {
        /* swaps against error, one line per cost; everything computed first */
        struct swap_point *pt = malloc(sizeof *pt * o.nsweep);
        if (!pt) die("out of memory");
        for (int k = 0; k < o.nsweep; k++) {
            if (swap_relabel(&D, o.lambda, o.method, o.sweep[k], l, &pt[k]) < 0) die("%s", cm_errmsg());
            info(1, "swap cost %g: %d swaps, energy %.10g", o.sweep[k], pt[k].swaps, pt[k].energy);
        }
        FILE *out = out_open(o.output);
        fprintf(out, "# swap_cost swaps energy data velocity mean_err max_err (%d frames, %d clips, %d pieces, lambda %g)\n",
                m.nframes, mesh_nclips(&m), lib.nframes, o.lambda);
        for (int k = 0; k < o.nsweep; k++)
            fprintf(out, "%.10g %d %.10g %.10g %.10g %.10g %.10g\n", pt[k].cost, pt[k].swaps, pt[k].rep.energy,
                    pt[k].rep.data, pt[k].rep.velocity, pt[k].rep.mean_err, pt[k].rep.max_err);
        out_close(out);
        free(pt); free(l); free(o.sweep);
        replib_data_free(&D); columns_free(&wc); mesh_free(&lib); mesh_free(&m);
        return 0;
    }
    double data, vel, lsecs = 0;
    double E = replib_label_timed(&D, o.lambda, o.method, l, &data, &vel, &lsecs);
    if (isnan(E)) die("%s", cm_errmsg());
    int swaps = swap_count(l, m.nframes, m.cut);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double secs = (t1.tv_sec - t0.tv_sec) + 1e-9 * (t1.tv_nsec - t0.tv_nsec);
    struct replib_report rep;
    replib_evaluate(m.V, m.nframes, m.nv, lib.V, lib.nframes, l, D.w, m.cut, o.lambda, &rep, NULL);

    FILE *out = out_open(o.output);
    if (labels_write(out, l, m.nframes) < 0) die("cannot write output");
    if (o.report) {
        FILE *f = out_open(o.report);
        fprintf(f, "# label-expand report (energy = data + lambda/2 * velocity, Eq. 10)\n");
        fprintf(f, "frames %d\nvertices %d\npieces %d\nlambda %.10g\nmethod %s\n", m.nframes, m.nv,
                lib.nframes, o.lambda,
                o.method == REPLIB_DP ? "dp" : o.method == REPLIB_EXPANSION ? "expansion" : "swap");
        fprintf(f, "energy %.10g\ndata %.10g\nvelocity %.10g\n", rep.energy, rep.data, rep.velocity);
        fprintf(f, "clips %d\nswaps %d\nswap_cost %.10g\nenergy_with_swaps %.10g\n", mesh_nclips(&m), swaps,
                o.swap_cost, rep.energy + o.swap_cost * swaps);
        fprintf(f, "mean_error %.10g\nmax_error %.10g\nworst_frame %d\n", rep.mean_err, rep.max_err, rep.worst_frame);
        fprintf(f, "mean_velocity_error %.10g\nmax_velocity_error %.10g\nseconds %.6f\nlabel_seconds %.6f\n",
                rep.mean_verr, rep.max_verr, secs, lsecs);
        out_close(f);
    }
    out_close(out);
    if (!o.quiet)
        fprintf(stderr, "%s: energy %.10g (data %.10g, velocity %.10g), mean error %.6g, max error %.6g\n",
                progname, rep.energy, rep.data, rep.velocity, rep.mean_err, rep.max_err);
    info(1, "%d swaps on set inside %d clips (swap cost %g: energy with swaps %.10g)", swaps, mesh_nclips(&m),
         o.swap_cost, rep.energy + o.swap_cost * swaps);
    info(1, "%d frames, %d pieces: %.4f s in all, label step %.4f s (model energy %.10g)", m.nframes,
         lib.nframes, secs, lsecs, E);
    (void)data; (void)vel;
    free(l);
    replib_data_free(&D);
    columns_free(&wc);
    mesh_free(&lib);
    mesh_free(&m);
    return 0;
}
