/* replib: lambda0_is_lloyd, energy_never_increases, gram_equals_direct,
 * energy_matches_evaluate, fixed_pieces_stay, one_piece_per_frame_is_exact */
#include "replib.h"
#include "rng.h"
#include "tap.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* a smooth random animation: a few blend shapes driven by sines + noise */
static double *make_anim(struct rng *r, int n, int nv, double noise)
{
    enum { B = 3 };
    int m3 = 3 * nv;
    double *base = malloc(sizeof(double) * m3 * (B + 1)), *X = malloc(sizeof(double) * (size_t)n * m3);
    for (int k = 0; k < m3 * (B + 1); k++) base[k] = rng_normal(r) + (k < m3 ? 100 : 0);
    double ph[B], fr[B];
    for (int b = 0; b < B; b++) { ph[b] = 6.28 * rng_uniform(r); fr[b] = 0.05 + 0.3 * rng_uniform(r); }
    for (int f = 0; f < n; f++)
        for (int k = 0; k < m3; k++) {
            double v = base[k];
            for (int b = 0; b < B; b++) v += sin(fr[b] * f + ph[b]) * base[(b + 1) * m3 + k];
            X[(size_t)f * m3 + k] = v + noise * rng_normal(r);
        }
    free(base);
    return X;
}

/* reference Lloyd loop (k-means) from given labels; returns the energy */
static double lloyd(const double *X, int n, int m3, int d, int *l, int maxit, int *empty)
{
    double *C = malloc(sizeof(double) * d * m3);
    int *cnt = malloc(sizeof(int) * d);
    double E = 0;
    *empty = 0;
    for (int it = 0; it < maxit; it++) {
        memset(C, 0, sizeof(double) * d * m3);
        memset(cnt, 0, sizeof(int) * d);
        for (int f = 0; f < n; f++) {
            cnt[l[f]]++;
            for (int k = 0; k < m3; k++) C[l[f] * m3 + k] += X[(size_t)f * m3 + k];
        }
        for (int a = 0; a < d; a++) {
            if (!cnt[a]) { *empty = 1; break; }
            for (int k = 0; k < m3; k++) C[a * m3 + k] /= cnt[a];
        }
        int changed = 0;
        E = 0;
        for (int f = 0; f < n; f++) {
            int best = 0;
            double be = INFINITY;
            for (int a = 0; a < d; a++) {
                double s = 0;
                for (int k = 0; k < m3; k++) {
                    double v = X[(size_t)f * m3 + k] - C[a * m3 + k];
                    s += v * v;
                }
                if (s < be) { be = s; best = a; }
            }
            changed += best != l[f];
            l[f] = best;
            E += be;
        }
        if (!changed) break;
    }
    free(C); free(cnt);
    return E;
}

static int mono_ok;
static double last_E;
static int last_restart;
static void mono_log(void *ctx, const struct replib_iter *it)
{
    (void)ctx;
    if (it->restart != last_restart || it->iteration == 0) { last_E = INFINITY; last_restart = it->restart; }
    if (it->energy > last_E * (1 + 1e-10) + 1e-12) mono_ok = 0;
    last_E = it->energy;
}

int main(void)
{
    struct rng r;
    rng_seed(&r, 3);

    /* lambda = 0: the same energy and labels as Lloyd from the same start */
    int lloyd_ok = 1, tested = 0;
    for (int t = 0; t < 10; t++) {
        int n = 40 + rng_int(&r, 40), nv = 5 + rng_int(&r, 10), d = 2 + rng_int(&r, 6);
        double *X = make_anim(&r, n, nv, 0.3);
        int *l0 = malloc(sizeof(int) * n), *lr = malloc(sizeof(int) * n);
        for (int f = 0; f < n; f++) l0[f] = lr[f] = (int)((long)f * d / n);
        int empty;
        double Eref = lloyd(X, n, 3 * nv, d, lr, 1000, &empty);
        if (empty) { free(X); free(l0); free(lr); continue; }
        struct replib_data D = {0};
        D.n = n; D.nv = nv; D.X = X; D.gram = t % 2;
        replib_prepare(&D);
        struct replib_opts o = {0};
        o.d = d; o.lambda = 0; o.restarts = 1; o.iterations = 1000; o.init_labels = l0;
        struct replib_result res;
        if (replib_learn(&D, &o, &res) < 0) { lloyd_ok = 0; break; }
        struct replib_report rep;
        replib_evaluate(X, n, nv, res.R, d, res.labels, NULL, NULL, 0, &rep, NULL);
        if (fabs(rep.energy - Eref) > 1e-8 * Eref || memcmp(res.labels, lr, sizeof(int) * n)) {
            lloyd_ok = 0;
            diag("Lloyd %.12g, dict-learn %.12g", Eref, rep.energy);
        }
        tested++;
        replib_result_free(&res);
        replib_data_free(&D);
        free(X); free(l0); free(lr);
    }
    ok(lloyd_ok && tested >= 5, "replib: lambda0_is_lloyd (%d problems, same energy and labels)", tested);

    /* monotone energy, Gram == direct, model energy == direct evaluation,
     * with cuts, weights and fixed pieces */
    int gd_ok = 1, ev_ok = 1, fix_ok = 1;
    mono_ok = 1;
    for (int t = 0; t < 12; t++) {
        int n = 60 + rng_int(&r, 60), nv = 6 + rng_int(&r, 8), d = 3 + rng_int(&r, 8), m3 = 3 * nv;
        double *X = make_anim(&r, n, nv, 0.2);
        unsigned char *cut = calloc(n, 1);
        for (int f = 1; f < n; f++) cut[f] = rng_uniform(&r) < 0.05;
        double *w = malloc(sizeof(double) * nv);
        for (int i = 0; i < nv; i++) w[i] = t % 3 ? 0.1 + rng_uniform(&r) : 1;
        int nfix = t % 4 == 3 ? 2 : 0;
        double *Rf = nfix ? make_anim(&r, nfix, nv, 0.5) : NULL;
        double lambda = 0.5 + 3 * rng_uniform(&r);
        int *l0 = malloc(sizeof(int) * n);
        for (int f = 0; f < n; f++) l0[f] = rng_int(&r, d);
        double *R2[2] = {0};
        for (int g = 0; g < 2; g++) {
            struct replib_data D = {0};
            D.n = n; D.nv = nv; D.X = X; D.cut = cut; D.w = w; D.gram = g; D.nfix = nfix; D.Rfix = Rf;
            replib_prepare(&D);
            struct replib_opts o = {0};
            o.d = d; o.lambda = lambda; o.restarts = 3; o.iterations = 100; o.seed = t;
            o.init_labels = l0; o.log = mono_log; o.method = t % 5 == 4 ? REPLIB_EXPANSION : REPLIB_DP;
            struct replib_result res;
            last_restart = -1;
            if (replib_learn(&D, &o, &res) < 0) { gd_ok = 0; break; }
            struct replib_report rep;
            replib_evaluate(X, n, nv, res.R, d, res.labels, w, cut, lambda, &rep, NULL);
            if (fabs(rep.energy - res.energy) > 1e-7 * rep.energy) {
                ev_ok = 0;
                diag("model %.12g, evaluated %.12g", res.energy, rep.energy);
            }
            for (int a = 0; a < nfix; a++)
                for (int k = 0; k < m3; k++)
                    if (res.R[a * m3 + k] != Rf[a * m3 + k]) fix_ok = 0;
            R2[g] = res.R;
            res.R = NULL;
            replib_result_free(&res);
            replib_data_free(&D);
        }
        free(R2[0]); free(R2[1]);
        /* restart 0 only: must agree */
        double E1[2];
        for (int g = 0; g < 2; g++) {
            struct replib_data D = {0};
            D.n = n; D.nv = nv; D.X = X; D.cut = cut; D.w = w; D.gram = g; D.nfix = nfix; D.Rfix = Rf;
            replib_prepare(&D);
            struct replib_opts o = {0};
            o.d = d; o.lambda = lambda; o.restarts = 1; o.iterations = 100; o.init_labels = l0;
            struct replib_result res;
            replib_learn(&D, &o, &res);
            E1[g] = res.energy;
            replib_result_free(&res);
            replib_data_free(&D);
        }
        if (fabs(E1[0] - E1[1]) > 1e-8 * E1[0]) { gd_ok = 0; diag("direct %.12g gram %.12g", E1[0], E1[1]); }
        free(X); free(cut); free(w); free(Rf); free(l0);
    }
    ok(mono_ok, "replib: energy_never_increases (every iteration of every restart)");
    ok(gd_ok, "replib: gram_equals_direct (same start)");
    ok(ev_ok, "replib: model_energy_equals_direct_evaluation (cuts, weights, fixed pieces)");
    ok(fix_ok, "replib: fixed_pieces_stay");

    /* d = n: every frame its own piece, zero error */
    {
        int n = 30, nv = 7;
        double *X = make_anim(&r, n, nv, 0.1);
        struct replib_data D = {0};
        D.n = n; D.nv = nv; D.X = X; D.gram = -1;
        replib_prepare(&D);
        struct replib_opts o = {0};
        o.d = n; o.lambda = 2; o.restarts = 1; o.iterations = 10;
        struct replib_result res;
        replib_learn(&D, &o, &res);
        struct replib_report rep;
        replib_evaluate(X, n, nv, res.R, n, res.labels, NULL, NULL, 2, &rep, NULL);
        ok(rep.max_err < 1e-9, "replib: one_piece_per_frame_is_exact (max error %g)", rep.max_err);
        replib_result_free(&res);
        replib_data_free(&D);
        free(X);
    }
    /* the exact low-rank Gram matrix gives the same result as DSYRK, and
     * full-rank data falls back to DSYRK */
    for (int lowrank_case = 0; lowrank_case < 2; lowrank_case++) {
        int n = 1600, nv = 100;
        double *X = lowrank_case == 0 ? make_anim(&r, n, nv, 0) : make_anim(&r, n, nv, 0.5);
        double E[2];
        int rank = -1;
        for (int nl = 0; nl < 2; nl++) {
            struct replib_data D = {0};
            D.n = n; D.nv = nv; D.X = X; D.gram = 1; D.no_lowrank = nl;
            replib_prepare(&D);
            if (nl == 0) rank = D.lowrank;
            struct replib_opts o = {0};
            o.d = 12; o.lambda = 2; o.restarts = 2; o.iterations = 30; o.seed = 5;
            struct replib_result res;
            replib_learn(&D, &o, &res);
            E[nl] = res.energy;
            replib_result_free(&res);
            replib_data_free(&D);
        }
        if (lowrank_case == 0)
            ok(rank == 64 && fabs(E[0] - E[1]) <= 1e-9 * E[1],
               "replib: lowrank_gram_equals_dsyrk (rank %d, %.12g vs %.12g)", rank, E[0], E[1]);
        else
            ok(rank == 0 && E[0] == E[1], "replib: full_rank_falls_back_to_dsyrk (rank %d)", rank);
        free(X);
    }
    /* a long static animation: zero variance, the low-rank test backs off */
    {
        int n = 1600, nv = 10;
        double *X = malloc(sizeof(double) * n * 3 * nv);
        for (int f = 0; f < n; f++)
            for (int k = 0; k < 3 * nv; k++) X[f * 3 * nv + k] = k;
        struct replib_data D = {0};
        D.n = n; D.nv = nv; D.X = X; D.gram = -1;
        int rc = replib_prepare(&D);
        struct replib_opts o = {0};
        o.d = 3; o.lambda = 2; o.restarts = 2; o.iterations = 5;
        struct replib_result res;
        rc |= replib_learn(&D, &o, &res);
        ok(rc == 0 && D.lowrank == 0 && fabs(res.energy) < 1e-9, "replib: static_animation_zero_energy (%g)",
           rc ? -1.0 : res.energy);
        if (!rc) replib_result_free(&res);
        replib_data_free(&D);
        free(X);
    }
    return tap_done();
}
