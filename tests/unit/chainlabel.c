/* chainlabel: dp_equals_brute_force, moves_never_below_dp,
 * expansion_never_rises_with_truncation */
#include "chainlabel.h"
#include "rng.h"
#include "tap.h"
#include <math.h>
#include <stdlib.h>

/* a random StopShop-like problem: pieces r_a and frames x_f in R^k */
static void make_problem(struct rng *r, int n, int d, double mu, double *U, double *T, double *H,
                         double *c, unsigned char *link)
{
    enum { K = 4 };
    double x[16][K], rr[8][K];
    for (int f = 0; f < n; f++) for (int k = 0; k < K; k++) x[f][k] = rng_normal(r);
    for (int a = 0; a < d; a++) for (int k = 0; k < K; k++) rr[a][k] = rng_normal(r);
    for (int f = 0; f < n; f++)
        for (int a = 0; a < d; a++) {
            double s = 0;
            for (int k = 0; k < K; k++) s += (x[f][k] - rr[a][k]) * (x[f][k] - rr[a][k]);
            U[f * d + a] = s;
        }
    for (int a = 0; a < d; a++)
        for (int b = 0; b < d; b++) {
            double s = 0;
            for (int k = 0; k < K; k++) s += (rr[a][k] - rr[b][k]) * (rr[a][k] - rr[b][k]);
            T[a * d + b] = mu * s;
        }
    for (int f = 0; f < n; f++) {
        link[f] = f + 1 < n && rng_uniform(r) > 0.2;
        c[f] = 0;
        for (int a = 0; a < d; a++) H[f * d + a] = 0;
        if (f + 1 >= n) continue;
        double s = 0;
        for (int k = 0; k < K; k++) s += (x[f + 1][k] - x[f][k]) * (x[f + 1][k] - x[f][k]);
        c[f] = mu * s;
        for (int a = 0; a < d; a++) {
            double p = 0;
            for (int k = 0; k < K; k++) p += (x[f + 1][k] - x[f][k]) * rr[a][k];
            H[f * d + a] = -2 * mu * p;
        }
    }
}

int main(void)
{
    struct rng r;
    rng_seed(&r, 42);
    int dp_ok = 1, dp_label_ok = 1, exp_ok = 1, swap_ok = 1, direct_ok = 1, rise_ok = 1;
    long ntr = 0;
    int exp_worse = 0;
    for (int t = 0; t < 200; t++) {
        int n = 2 + rng_int(&r, 6), d = 1 + rng_int(&r, 4);   /* up to 4^7 = 16384 labelings */
        double mu = t % 4 == 0 ? 0 : rng_uniform(&r) * 3;
        double U[16 * 8], T[64], H[16 * 8], c[16];
        unsigned char link[16];
        make_problem(&r, n, d, mu, U, T, H, c, link);
        struct chain p = {n, d, U, T, H, c, link};
        /* direct check of the expansion of mu |dx - (r_b - r_a)|^2 is in make_problem's algebra;
         * brute force */
        int l[16], best[16];
        double bestE = INFINITY;
        long total = 1;
        for (int f = 0; f < n; f++) total *= d;
        for (long code = 0; code < total; code++) {
            long k = code;
            for (int f = 0; f < n; f++) { l[f] = k % d; k /= d; }
            double e = chain_energy(&p, l, NULL, NULL);
            if (e < bestE - 1e-12) { bestE = e; for (int f = 0; f < n; f++) best[f] = l[f]; }
        }
        int ld[16];
        double Edp = chain_dp(&p, ld);
        double Echeck = chain_energy(&p, ld, NULL, NULL);
        if (fabs(Edp - bestE) > 1e-9 * (1 + fabs(bestE))) dp_ok = 0;
        if (fabs(Echeck - Edp) > 1e-9 * (1 + fabs(Edp))) dp_label_ok = 0;
        (void)best;
        /* moves from a random start */
        int le[16], ls[16];
        for (int f = 0; f < n; f++) le[f] = ls[f] = rng_int(&r, d);
        double E0 = chain_energy(&p, le, NULL, NULL);
        long nt = 0;
        double Eexp = chain_expansion(&p, le, 0, &nt);
        ntr += nt;
        double Esw = chain_swap(&p, ls, 0);
        if (Eexp < Edp - 1e-9 * (1 + fabs(Edp))) exp_ok = 0;
        if (Esw < Edp - 1e-9 * (1 + fabs(Edp))) swap_ok = 0;
        if (Eexp > E0 + 1e-9 * (1 + fabs(E0))) rise_ok = 0;
        if (fabs(chain_energy(&p, le, NULL, NULL) - Eexp) > 1e-9 * (1 + fabs(Eexp))) direct_ok = 0;
        if (Eexp > Edp + 1e-9 * (1 + fabs(Edp))) exp_worse++;
    }
    ok(dp_ok, "chainlabel: dp_equals_brute_force (200 random problems, cuts included)");
    ok(dp_label_ok, "chainlabel: dp_labels_have_reported_energy");
    ok(exp_ok, "chainlabel: expansion_never_below_dp");
    ok(swap_ok, "chainlabel: swap_never_below_dp");
    ok(rise_ok, "chainlabel: expansion_never_rises (truncated %ld non-submodular terms)", ntr);
    ok(direct_ok, "chainlabel: expansion_returns_its_energy");
    diag("expansion above the exact minimum on %d of 200 problems", exp_worse);
    return tap_done();
}
