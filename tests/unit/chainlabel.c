/* chainlabel: dp_equals_brute_force, moves_never_below_dp,
 * expansion_never_rises_with_truncation; with a swap cost: dp exact against
 * brute force, swap 0 bit for bit the plain DP, swaps never rise with the cost */
#include "chainlabel.h"
#include "rng.h"
#include "tap.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

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

/* the lowest energy over all d^n labelings */
static double brute_min(const struct chain *p)
{
    int l[16];
    double bestE = INFINITY;
    long total = 1;
    for (int f = 0; f < p->n; f++) total *= p->d;
    for (long code = 0; code < total; code++) {
        long k = code;
        for (int f = 0; f < p->n; f++) { l[f] = k % p->d; k /= p->d; }
        double e = chain_energy(p, l, NULL, NULL);
        if (e < bestE) bestE = e;
    }
    return bestE;
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
        struct chain p = {n, d, U, T, H, c, link, 0};
        /* direct check of the expansion of mu |dx - (r_b - r_a)|^2 is in make_problem's algebra;
         * brute force */
        double bestE = brute_min(&p);
        int ld[16];
        double Edp = chain_dp(&p, ld);
        double Echeck = chain_energy(&p, ld, NULL, NULL);
        if (fabs(Edp - bestE) > 1e-9 * (1 + fabs(bestE))) dp_ok = 0;
        if (fabs(Echeck - Edp) > 1e-9 * (1 + fabs(Edp))) dp_label_ok = 0;
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

    /* swap cost: exact against brute force, 0 = the plain DP bit for bit,
     * swaps non-increasing in the cost (exchange argument on exact minima),
     * no swap across a cut */
    int sw_dp_ok = 1, sw_zero_ok = 1, sw_mono_ok = 1, sw_moves_ok = 1, sw_cut_ok = 1, sw_count_ok = 1;
    int fewer = 0;
    for (int t = 0; t < 200; t++) {
        int n = 2 + rng_int(&r, 6), d = 1 + rng_int(&r, 4);
        double mu = t % 3 == 0 ? 0 : rng_uniform(&r) * 3;
        double U[16 * 8], T[64], H[16 * 8], c[16];
        unsigned char link[16];
        make_problem(&r, n, d, mu, U, T, H, c, link);
        struct chain p = {n, d, U, mu > 0 ? T : NULL, mu > 0 ? H : NULL, mu > 0 ? c : NULL, link, 0};
        int l0[16], lz[16];
        double E0 = chain_dp(&p, l0);
        p.swap = 0.0;
        double Ez = chain_dp(&p, lz);
        for (int f = 0; f < n; f++) if (lz[f] != l0[f]) sw_zero_ok = 0;
        if (memcmp(&E0, &Ez, sizeof E0)) sw_zero_ok = 0;
        int prev_swaps = chain_swaps(&p, l0);
        const double costs[] = {0.05, 0.3, 1, 4, 1e4};
        for (int k = 0; k < 5; k++) {
            p.swap = costs[k];
            int ld[16];
            double bestE = brute_min(&p);
            double Edp = chain_dp(&p, ld);
            if (fabs(Edp - bestE) > 1e-9 * (1 + fabs(bestE))) sw_dp_ok = 0;
            int s = chain_swaps(&p, ld);
            if (s > prev_swaps) sw_mono_ok = 0;
            if (s < prev_swaps) fewer++;
            prev_swaps = s;
            int cnt = 0;
            for (int f = 0; f + 1 < n; f++) {
                cnt += link[f] && ld[f] != ld[f + 1];
            }
            if (cnt != s) sw_count_ok = 0;
            /* a huge cost: no swap left inside a clip; across cuts labels may still change */
            if (costs[k] >= 1e4 && mu == 0 && s != 0) sw_cut_ok = 0;
            int le[16], ls[16];
            for (int f = 0; f < n; f++) le[f] = ls[f] = rng_int(&r, d);
            double Ee = chain_expansion(&p, le, 0, NULL), Es = chain_swap(&p, ls, 0);
            if (Ee < Edp - 1e-9 * (1 + fabs(Edp)) || Es < Edp - 1e-9 * (1 + fabs(Edp))) sw_moves_ok = 0;
        }
    }
    ok(sw_dp_ok, "chainlabel: swap_cost_dp_equals_brute_force (200 problems x 5 costs, cuts included)");
    ok(sw_zero_ok, "chainlabel: swap_cost_0_is_the_plain_dp_bit_for_bit");
    ok(sw_mono_ok && fewer > 0, "chainlabel: swaps_never_rise_with_the_cost (fewer on %d steps)", fewer);
    ok(sw_count_ok, "chainlabel: chain_swaps_counts_linked_changes_only");
    ok(sw_cut_ok, "chainlabel: large_swap_cost_without_velocity_leaves_no_swap_in_a_clip");
    ok(sw_moves_ok, "chainlabel: moves_with_swap_cost_never_below_dp");
    return tap_done();
}
