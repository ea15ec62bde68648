/* arap-morph -- N-way as-rigid-as-possible morphing of compatible 2D meshes
 * (Baxter, Barla, Anjyo, N-way morphing Sec. 4.2): one output frame per row
 * of blend weights.
 */
#include "nway_blend.h"
#include "columns.h"
#include "mesh.h"
#include "progress.h"
#include "tool.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <getopt.h>

static const char help[] =
"Usage: arap-morph [options] MESH [WEIGHTS]\n"
"Blend the N frames of a compatible 2D mesh (e.g. from compat-tri) as rigidly\n"
"as possible: one output frame per row of N weights in WEIGHTS (default stdin;\n"
"e.g. from biharm-weights).\n"
"\n"
"  -b, --base K           base pose (default 0)\n"
"  -l, --shear-limit      limit the stretch weights outside [0, 1] (extrapolation);\n"
"                         weights in [0, 1] are unchanged (plain ARAP there)\n"
"      --shear-hermite    the paper's shear limiting: every stretch weight through\n"
"                         a Hermite step (also changes weights inside [0, 1])\n"
"      --linear           baseline: blend vertex positions linearly\n"
"      --sigma S          texture-weight sharpening in [0, 1] (with --texture-weights)\n"
"      --texture-weights FILE  write the sharpened texture weights, one row per frame\n"
"      --raw              raw MESH output (or STOPMO_RAW=1)\n"
"  -o, --output FILE      write to FILE (temporary + rename)\n"
"  -v, --verbose          frames/s and inverted triangles on stderr\n"
"  -h, --help, --version\n"
"\n"
"\n"
"Every row of weights is divided by its sum (so rows need not sum to 1 exactly;\n"
"-v counts rows off by more than 1e-6); a row summing to 0 is an error.\n"
"\n"
"Example: echo '0.5 0.5' | arap-morph two.mesh | mesh2svg >half.svg\n";

struct options {
    const char *mesh, *weights, *output, *texout;
    int base, shear, hermite, linear, raw;
    double sigma;
};

static void parse_args(int argc, char **argv, struct options *o)
{
    static const struct option lo[] = {
        {"base", 1, 0, 'b'}, {"shear-limit", 0, 0, 'l'}, {"shear-hermite", 0, 0, 'H'}, {"linear", 0, 0, 'L'}, {"sigma", 1, 0, 'S'},
        {"texture-weights", 1, 0, 'T'}, {"raw", 0, 0, 'R'}, {"output", 1, 0, 'o'},
        {"verbose", 0, 0, 'v'}, {"help", 0, 0, 'h'}, {"version", 0, 0, 'V'}, {0, 0, 0, 0}};
    memset(o, 0, sizeof *o);
    int c;
    while ((c = getopt_long(argc, argv, "b:lo:vh", lo, NULL)) != -1) {
        switch (c) {
        case 'b': o->base = arg_int(optarg, "--base"); break;
        case 'l': o->shear = 1; break;
        case 'H': o->shear = 1; o->hermite = 1; break;
        case 'L': o->linear = 1; break;
        case 'S': o->sigma = arg_double(optarg, "--sigma"); break;
        case 'T': o->texout = optarg; break;
        case 'R': o->raw = 1; break;
        case 'o': o->output = optarg; break;
        case 'v': verbose++; break;
        case 'h': print_help_and_exit(help);
        case 'V': print_version_and_exit();
        default: usage_error("unknown option");
        }
    }
    if (!(o->sigma >= 0 && o->sigma <= 1)) usage_error("--sigma must be in [0, 1]");
    if (o->base < 0) usage_error("--base must be >= 0");
    if (optind >= argc || optind + 2 < argc) usage_error("expected MESH [WEIGHTS]");
    o->mesh = argv[optind];
    o->weights = optind + 1 < argc ? argv[optind + 1] : NULL;
    if (!strcmp(o->mesh, "-") && (!o->weights || !strcmp(o->weights, "-")))
        usage_error("MESH and WEIGHTS cannot both be stdin");
}

static double now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

int main(int argc, char **argv)
{
    tool_init(argc, argv);
    struct options o;
    parse_args(argc, argv, &o);
    struct mesh m;
    if (mesh_read(o.mesh, &m) < 0) die("%s", cm_errmsg());
    int N = m.nframes;
    if (o.base >= N) die("cannot read '%s': base pose %d asked, the stream has %d frames", o.mesh, o.base, N);
    if (m.nv < 1 || m.nf < 1) die("cannot read '%s': empty mesh", o.mesh);
    struct columns W;
    if (columns_read(o.weights, 0, -1, NULL, &W) < 0) die("%s", cm_errmsg());
    if (W.rows > 0 && W.cols != N)
        die("cannot read '%s': line 1: %d weights per row, but the mesh has %d frames (poses)",
            o.weights ? o.weights : "<stdin>", W.cols, N);
    double **X = malloc(N * sizeof *X);
    for (int s = 0; s < N; s++) X[s] = mesh_frame(&m, s);
    /* every row is divided by its sum: refuse zero sums before any output */
    for (int r = 0; r < W.rows; r++) {
        double sum = 0, mx = 0;
        for (int s = 0; s < N; s++) { sum += W.x[(size_t)r * N + s]; mx = fmax(mx, fabs(W.x[(size_t)r * N + s])); }
        if (!(fabs(sum) > 1e-9 * mx) || !isfinite(sum))
            die("cannot read '%s': row %d: the weights sum to %g; blend weights must sum to 1 "
                "(rows are divided by their sum, which needs a nonzero sum)",
                o.weights ? o.weights : "<stdin>", r + 1, sum);
    }
    double t0 = now();
    struct nway_blend *B = NULL;
    if (!o.linear) {
        B = nway_blend_new(X, N, m.nv, m.F, m.nf, o.base);
        if (!B) die("cannot read '%s': %s", o.mesh, cm_errmsg());
    }
    double t1 = now();
    FILE *tex = o.texout ? out_open(o.texout) : NULL;
    FILE *out = out_open(o.output);
    struct mesh_writer mw;
    if (mesh_writer_open(&mw, out, m.nv, m.nf, m.F, W.rows, want_raw(o.raw)) < 0)
        die("cannot write output: %s", cm_errmsg());
    double *Y = malloc(3 * (size_t)m.nv * sizeof *Y), *wl = malloc(N * sizeof *wl);
    long inverted = 0;
    double tcomp = 0;
    int frames_inv = 0;
    struct progress pg;
    progress_start(&pg, "arap-morph", W.rows);
    int renorm = 0;
    double *wn = malloc(N * sizeof *wn);
    for (int r = 0; r < W.rows; r++) {
        double sum = 0;
        for (int s = 0; s < N; s++) sum += W.x[(size_t)r * N + s];
        if (fabs(sum - 1) > 1e-6) renorm++;
        for (int s = 0; s < N; s++) wn[s] = W.x[(size_t)r * N + s] / sum;
        const double *w = wn;
        double tb = now();
        if (o.linear) {
            memset(Y, 0, 3 * (size_t)m.nv * sizeof *Y);
            for (int s = 0; s < N; s++)
                for (size_t k = 0; k < 3 * (size_t)m.nv; k++) Y[k] += w[s] * X[s][k];
        } else {
            if (o.shear) shear_limit_weights(w, N, o.hermite ? SHEAR_HERMITE : SHEAR_SOFT, wl);
            if (nway_blend_eval(B, w, o.shear ? wl : NULL, Y) < 0) die("%s", cm_errmsg());
        }
        tcomp += now() - tb;
        if (verbose) {
            int inv = 0;
            for (int f = 0; f < m.nf; f++) {
                const double *a = Y + 3 * m.F[3 * f], *b = Y + 3 * m.F[3 * f + 1], *c = Y + 3 * m.F[3 * f + 2];
                if ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]) <= 0) inv++;
            }
            inverted += inv;
            frames_inv += inv > 0;
        }
        if (mesh_writer_frame(&mw, Y, 0) < 0) die("cannot write output: %s", cm_errmsg());
        if (tex) {
            texture_weights(w, N, o.hermite ? SHEAR_HERMITE : SHEAR_SOFT, o.sigma, wl);
            columns_write(tex, wl, 1, N);
        }
        progress_step(&pg, r + 1);
    }
    progress_end(&pg);
    double t2 = now();
    if (mesh_writer_close(&mw) < 0) die("cannot write output: %s", cm_errmsg());
    out_close(out);
    if (tex) out_close(tex);
    info(1, "%s: %d vertices, %d triangles, %d poses; setup %.4f s; %d frames: blending %.4f s = %.1f frames/s "
            "(with output %.4f s)", o.linear ? "linear" : o.shear ? o.hermite ? "arap, shear-limited (Hermite)" : "arap, shear-limited" : "arap", m.nv, m.nf, N,
         t1 - t0, W.rows, tcomp, W.rows / fmax(tcomp, 1e-9), t2 - t1);
    info(1, "inverted triangles: %ld in %d of %d frames", inverted, frames_inv, W.rows);
    if (renorm) info(1, "%d of %d weight rows did not sum to 1 and were divided by their sum", renorm, W.rows);
    free(wn);
    nway_blend_free(B);
    free(Y); free(wl); free(X);
    columns_free(&W);
    mesh_free(&m);
    return 0;
}
