/* dict-bench -- time the StopShop library optimisation (libcommon/replib)
 * on a generated animation of a given size (Table 1 sizes).
 *
 *   dict-bench V FRAMES D [RESTARTS [ITERATIONS [SEED]]]
 *
 * The animation: a rest shape plus B = 24 random smooth "blend shapes"
 * driven by smooth random weights (a few sines each, with occasional fast
 * onsets), like a facial performance; clips of 500 frames.  Generated with
 * one GEMM.  Prints key=value lines for bench/b-dict.sh.
 */
#include "replib.h"
#include "chainlabel.h"
#include "rng.h"
#include "blas_tune.h"
#include <sys/resource.h>
#include <sys/mman.h>
#include <cblas.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

static double wall(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static void log_iter(void *ctx, const struct replib_iter *it)
{
    (void)ctx;
    fprintf(stderr, "restart %d iteration %d: E %.10g changed %d reseeded %d %.4f s\n", it->restart,
            it->iteration, it->energy, it->changed, it->reseeded, it->seconds);
}

static double cpu(void)
{
    struct rusage u;
    getrusage(RUSAGE_SELF, &u);
    return u.ru_utime.tv_sec + u.ru_stime.tv_sec + 1e-6 * (u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

int main(int argc, char **argv)
{
    blas_tune(argv);
    if (argc < 4) {
        fprintf(stderr, "usage: dict-bench V FRAMES D [RESTARTS [ITERATIONS [SEED]]]\n");
        return 2;
    }
    int nv = atoi(argv[1]), n = atoi(argv[2]), d = atoi(argv[3]);
    int restarts = argc > 4 ? atoi(argv[4]) : 5, iters = argc > 5 ? atoi(argv[5]) : 50;
    long seed = argc > 6 ? atol(argv[6]) : 1;
    enum { B = 24 };
    int m3 = 3 * nv;
    struct rng r;
    rng_seed(&r, (uint64_t)seed);
    double t0 = wall();
    double *S = malloc(sizeof(double) * (size_t)B * m3), *W = malloc(sizeof(double) * (size_t)n * B);
    double *X = NULL;
    size_t xb = ((sizeof(double) * (size_t)n * m3) + ((size_t)2 << 20) - 1) & ~(((size_t)2 << 20) - 1);
    if (posix_memalign((void **)&X, (size_t)2 << 20, xb) == 0) madvise(X, xb, MADV_HUGEPAGE);
    unsigned char *cut = calloc(n, 1);
    if (!S || !W || !X || !cut) { fprintf(stderr, "dict-bench: out of memory\n"); return 1; }
    /* smooth blend shapes: low-frequency functions of a rest position */
    for (int i = 0; i < nv; i++) {
        double u = rng_uniform(&r), v = rng_uniform(&r);
        for (int b = 0; b < B; b++) {
            double a = sin(3.1 * (b + 1) * u + b) * cos(2.3 * (b % 5 + 1) * v);
            S[(size_t)b * m3 + 3 * i] = 0.01 * a;
            S[(size_t)b * m3 + 3 * i + 1] = 0.01 * a * (b % 3 - 1);
            S[(size_t)b * m3 + 3 * i + 2] = 0.01 * cos(a + b);
        }
    }
    for (int b = 0; b < B; b++) {
        double f1 = 0.01 + 0.08 * rng_uniform(&r), f2 = 0.1 * rng_uniform(&r), p = 6.28 * rng_uniform(&r);
        for (int f = 0; f < n; f++) {
            double s = sin(f1 * f + p) + 0.3 * sin(f2 * f);
            W[(size_t)f * B + b] = s > 0.4 ? s : 0.4 * s;   /* blendshape-like onsets */
        }
    }
    cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasNoTrans, n, m3, B, 1.0, W, B, S, m3, 0.0, X, m3);
    for (int f = 500; f < n; f += 500) cut[f] = 1;
    free(S); free(W);
    double tgen = wall() - t0;

    double c0 = cpu();
    struct replib_data D = {0};
    D.n = n; D.nv = nv; D.X = X; D.cut = cut; D.gram = getenv("DICT_BENCH_GRAM") ? atoi(getenv("DICT_BENCH_GRAM")) : -1;
    D.no_lowrank = getenv("DICT_BENCH_FULLRANK") != NULL;
    if (replib_prepare(&D) < 0) { fprintf(stderr, "dict-bench: prepare failed\n"); return 1; }
    struct replib_opts o = {0};
    o.d = d; o.lambda = 2; o.restarts = restarts; o.iterations = iters; o.seed = (uint64_t)seed; o.tol = 1e-10;
    if (getenv("DICT_BENCH_LOG")) o.log = log_iter;
    struct replib_result res;
    if (replib_learn(&D, &o, &res) < 0) { fprintf(stderr, "dict-bench: learn failed\n"); return 1; }
    double cpu_s = cpu() - c0;
    printf("blas=%s lowrank=%d cpu_s=%.3f ", blas_corename(), D.lowrank, cpu_s);
    printf("vertices=%d frames=%d pieces=%d backend=%s generate_s=%.3f prepare_s=%.3f learn_s=%.3f total_s=%.3f "
           "restarts=%d iterations=%d per_iteration_s=%.4f label_per_iteration_s=%.4f energy=%.10g\n",
           nv, n, d, D.K ? "gram" : "direct", tgen, D.prep_seconds, res.seconds,
           D.prep_seconds + res.seconds, res.restarts, res.iterations,
           res.seconds / res.iterations, res.label_seconds / res.iterations, res.energy);

    /* DP vs alpha-expansion vs swap on the final library (one label step) */
    struct replib_data L = {0};
    L.n = n; L.nv = nv; L.X = X; L.cut = cut; L.nfix = d; L.Rfix = res.R; L.gram = 0;
    if (replib_prepare(&L) < 0) return 1;
    int *l = malloc(sizeof(int) * n);
    double tdp, texp;
    double Edp = replib_label_timed(&L, 2, REPLIB_DP, l, NULL, NULL, &tdp);
    double Eexp = replib_label_timed(&L, 2, REPLIB_EXPANSION, l, NULL, NULL, &texp);
    printf("dp_energy=%.10g dp_s=%.6f expansion_energy=%.10g expansion_s=%.6f\n", Edp, tdp, Eexp, texp);
    free(l);
    replib_data_free(&L);
    replib_result_free(&res);
    replib_data_free(&D);
    free(X); free(cut);
    return 0;
}
