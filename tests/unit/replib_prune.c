/* replib_prune: the bounds that skip frames in the distance columns of the
 * greedy start and the split/merge proposals (replib.c's dcols_pruned)
 * change nothing: the same labels, the same library bit for bit and the
 * same energy as measuring every frame (replib_opts.no_prune), on the
 * direct back end (where the bounds apply: reduced coordinates of at most
 * 256 columns, a CPU with FMA and AVX2 or AVX-512), lambda 0 and > 0, cuts,
 * weights, fixed pieces (centres that are not frames), 1 and 2 threads,
 * frame counts past the threads' help threshold (512); and far-apart
 * clusters, where most frames are skipped, next to overlapping ones. */
#include "replib.h"
#include "blas_tune.h"
#include "rng.h"
#include "tap.h"
#include "anim_fixture.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

int main(int argc, char **argv)
{
    (void)argc;
    blas_tune(argv);        /* the kernels the bounds run with (re-executes once) */
    diag("OpenBLAS kernel %s (the bounds apply on any kernel of a CPU with FMA and AVX2 or AVX-512; "
         "elsewhere both runs measure every frame)", blas_corename());
    struct rng r;
    rng_seed(&r, 23);
    int same_labels = 1, same_lib = 1, same_energy = 1, cases = 0;
    for (int t = 0; t < 16; t++) {
        int big = t % 4 == 3;
        int n = big ? 600 + rng_int(&r, 300) : 80 + rng_int(&r, 200), nv = 4 + rng_int(&r, 30);
        int d = 3 + rng_int(&r, big ? 60 : 30);
        double spread = t % 2 ? 20 : 1;
        double *X = make_anim(&r, n, nv, 5 + rng_int(&r, 40), spread, 0.3);
        unsigned char *cut = calloc(n, 1);
        for (int f = 1; f < n; f++) cut[f] = t % 3 == 2 && rng_uniform(&r) < 0.03;
        double *w = malloc(sizeof(double) * nv);
        for (int i = 0; i < nv; i++) w[i] = t % 5 == 1 ? 0.2 + rng_uniform(&r) : 1;
        int nfix = t % 6 == 5 ? 2 : 0;
        double *Rf = nfix ? make_anim(&r, nfix, nv, 2, spread, 0.5) : NULL;
        double lambda = t % 4 == 1 ? 0 : 2 * rng_uniform(&r) + 0.5;
        struct replib_data D = {0};
        D.n = n; D.nv = nv; D.X = X; D.cut = cut; D.w = w; D.gram = 0; D.nfix = nfix; D.Rfix = Rf;
        if (replib_prepare(&D) < 0) { ok(0, "prepare: %s", "failed"); return tap_done(); }
        struct replib_opts o = {0};
        o.d = d; o.lambda = lambda; o.restarts = 3; o.iterations = 100; o.seed = 500 + t; o.tol = 1e-10;
        o.start = REPLIB_START_GREEDY; o.search = 10 + d / 5; o.threads = 1 + t % 2;
        struct replib_result all, pruned;
        o.no_prune = 1;
        int rc = replib_learn(&D, &o, &all);
        o.no_prune = 0;
        rc |= replib_learn(&D, &o, &pruned);
        if (rc) { ok(0, "replib_learn failed"); return tap_done(); }
        cases++;
        if (memcmp(all.labels, pruned.labels, sizeof(int) * n)) {
            same_labels = 0;
            diag("case %d (n %d, d %d, lambda %g): labels differ", t, n, d, lambda);
        }
        if (memcmp(all.R, pruned.R, sizeof(double) * (size_t)d * 3 * nv)) {
            same_lib = 0;
            diag("case %d: library differs", t);
        }
        if (all.energy != pruned.energy) {
            same_energy = 0;
            diag("case %d: energy %.17g measured, %.17g pruned", t, all.energy, pruned.energy);
        }
        replib_result_free(&all); replib_result_free(&pruned);
        replib_data_free(&D);
        free(X); free(cut); free(w); free(Rf);
    }
    ok(same_labels, "replib_prune: the same labels as measuring every frame (%d cases)", cases);
    ok(same_lib, "replib_prune: the same library, bit for bit");
    ok(same_energy, "replib_prune: the same energy");
    return tap_done();
}
