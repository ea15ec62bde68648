/* alpha_expansion: no_expansion_move_improves, within_factor_2_of_optimum,
 * chain_exact, forbidden_labels_respected, deterministic */
#include "alpha_expansion.h"
#include "cm_error.h"
#include "rng.h"
#include "tap.h"
#include <math.h>
#include <string.h>

static double energy(int n, int s, const double *U, int ne, const int *E, const double *W, const int *L)
{
    double u, b;
    potts_energy(n, s, U, ne, E, W, L, &u, &b);
    return u + b;
}

int main(void)
{
    struct rng r;
    rng_seed(&r, 11);
    int local_ok = 1, factor_ok = 1, stats_ok = 1, det_ok = 1, exact = 0;
    for (int t = 0; t < 60; t++) {
        enum { N = 7, S = 3 };
        double U[N * S], W[N * N];
        int E[2 * N * N], ne = 0, L[N], L2[N];
        for (int i = 0; i < N * S; i++) U[i] = rng_uniform(&r) * 2;
        for (int i = 0; i < N; i++)
            for (int j = i + 1; j < N; j++)
                if (rng_uniform(&r) < 0.5) { E[2 * ne] = i; E[2 * ne + 1] = j; W[ne++] = rng_uniform(&r); }
        struct alpha_expansion_stats st;
        if (alpha_expansion(N, S, U, ne, E, W, L, 0, 0, &st) < 0) { local_ok = 0; continue; }
        double e = energy(N, S, U, ne, E, W, L);
        if (fabs(st.unary + st.binary - e) > 1e-12) stats_ok = 0;
        /* brute force: global optimum and every expansion move */
        double best = 1e300;
        int tot = 1;
        for (int k = 0; k < N; k++) tot *= S;
        for (int m = 0; m < tot; m++) {
            int M[N], x = m;
            for (int k = 0; k < N; k++) { M[k] = x % S; x /= S; }
            double em = energy(N, S, U, ne, E, W, M);
            if (em < best) best = em;
        }
        for (int a = 0; a < S; a++)
            for (int m = 0; m < 1 << N; m++) {
                int M[N];
                for (int k = 0; k < N; k++) M[k] = (m >> k & 1) ? a : L[k];
                if (energy(N, S, U, ne, E, W, M) < e - 1e-9) local_ok = 0;
            }
        if (e > 2 * best + 1e-9) factor_ok = 0;
        if (fabs(e - best) < 1e-9) exact++;
        alpha_expansion(N, S, U, ne, E, W, L2, 0, 0, NULL);
        if (memcmp(L, L2, sizeof L)) det_ok = 0;
    }
    ok(local_ok, "alpha_expansion: no expansion move improves the result (60 random graphs)");
    ok(factor_ok, "alpha_expansion: energy within factor 2 of the brute-force optimum");
    diag("global optimum reached in %d of 60", exact);
    ok(exact >= 50, "alpha_expansion: usually the global optimum (%d of 60)", exact);
    ok(stats_ok, "alpha_expansion: reported energy equals the recomputed energy");
    ok(det_ok, "alpha_expansion: deterministic");

    /* chain 0..9, label 0 cheap at the left, 1 at the right: one cut, at the
     * cheapest edge */
    {
        double U[20], W[9] = {5, 5, 5, 5, 0.5, 5, 5, 5, 5};
        int E[18], L[10];
        for (int i = 0; i < 10; i++) { U[2 * i] = i < 5 ? 0 : 1; U[2 * i + 1] = i < 5 ? 1 : 0; }
        U[2 * 0 + 1] = INFINITY; U[2 * 9] = INFINITY;   /* ends fixed */
        for (int e = 0; e < 9; e++) { E[2 * e] = e; E[2 * e + 1] = e + 1; }
        struct alpha_expansion_stats st;
        int rc = alpha_expansion(10, 2, U, 9, E, W, L, 0, 0, &st);
        int good = rc == 0;
        for (int i = 0; i < 10; i++) good &= L[i] == (i < 5 ? 0 : 1);
        ok(good && fabs(st.binary - 0.5) < 1e-12 && st.unary == 0, "alpha_expansion: chain cut at the cheapest edge");
        /* make the middle expensive: cut moves, forbidden labels respected */
        for (int i = 1; i < 9; i++) { U[2 * i] = 0; U[2 * i + 1] = 0; }
        W[4] = 5; W[1] = 0.25;
        rc = alpha_expansion(10, 2, U, 9, E, W, L, 0, 0, &st);
        good = rc == 0 && L[0] == 0 && L[9] == 1 && L[1] == 0 && L[2] == 1;
        ok(good, "alpha_expansion: forbidden labels respected, cut follows weights");
        U[0] = INFINITY;
        ok(alpha_expansion(10, 2, U, 9, E, W, L, 0, 0, &st) < 0, "alpha_expansion: node without allowed label refused (%s)", cm_errmsg());
    }
    return tap_done();
}
