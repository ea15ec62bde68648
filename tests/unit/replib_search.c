/* replib_search: the greedy k-means++ start and the local search (Hartigan
 * moves, split/merge trials) against the plain method (k-means++, block
 * coordinate descent) on fixed seeds: never a higher energy, lambda = 0 and
 * > 0, Gram and direct back ends, cuts, weights, fixed pieces; the model
 * energy after the search equals the direct evaluation; same seed, same
 * labels whatever the thread count. */
#include "replib.h"
#include "rng.h"
#include "tap.h"
#include "anim_fixture.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

int main(void)
{
    struct rng r;
    rng_seed(&r, 11);
    int never_worse = 1, better = 0, cases = 0, ev_ok = 1, det_ok = 1;
    for (int t = 0; t < 24; t++) {
        int n = 80 + rng_int(&r, 150), nv = 4 + rng_int(&r, 12), d = 3 + rng_int(&r, 25);
        double *X = make_anim(&r, n, nv, 5 + rng_int(&r, 40), 1, 0.3);
        unsigned char *cut = calloc(n, 1);
        for (int f = 1; f < n; f++) cut[f] = t % 3 == 2 && rng_uniform(&r) < 0.03;
        double *w = malloc(sizeof(double) * nv);
        for (int i = 0; i < nv; i++) w[i] = t % 4 == 1 ? 0.2 + rng_uniform(&r) : 1;
        int nfix = t % 6 == 5 ? 2 : 0;
        double *Rf = nfix ? make_anim(&r, nfix, nv, 2, 1, 0.5) : NULL;
        double lambda = t % 2 ? 0 : 2 * rng_uniform(&r) + 0.5;
        struct replib_data D = {0};
        D.n = n; D.nv = nv; D.X = X; D.cut = cut; D.w = w; D.gram = (t / 2) % 2; D.nfix = nfix; D.Rfix = Rf;
        if (replib_prepare(&D) < 0) { ok(0, "prepare"); return tap_done(); }
        struct replib_opts o = {0};
        o.d = d; o.lambda = lambda; o.restarts = 3; o.iterations = 100; o.seed = 100 + t; o.tol = 1e-10;
        o.method = t % 5 == 4 ? REPLIB_EXPANSION : REPLIB_DP;
        struct replib_result old, neu, neu1;
        o.start = REPLIB_START_PLUSPLUS; o.search = 0;
        int rc = replib_learn(&D, &o, &old);
        o.start = REPLIB_START_GREEDY; o.search = 10 + d / 5; o.threads = 2;
        rc |= replib_learn(&D, &o, &neu);
        o.threads = 1;
        rc |= replib_learn(&D, &o, &neu1);
        if (rc) { ok(0, "replib_learn failed"); return tap_done(); }
        cases++;
        if (neu.energy > old.energy * (1 + 1e-12)) {
            never_worse = 0;
            diag("case %d (n %d, d %d, lambda %g): search %.12g > plain %.12g", t, n, d, lambda, neu.energy, old.energy);
        }
        if (neu.energy < old.energy * (1 - 1e-9)) better++;
        struct replib_report rep;
        replib_evaluate(X, n, nv, neu.R, d, neu.labels, w, cut, lambda, &rep, NULL);
        if (fabs(rep.energy - neu.energy) > 1e-8 * rep.energy) {
            ev_ok = 0;
            diag("case %d: model %.12g, evaluated %.12g", t, neu.energy, rep.energy);
        }
        if (memcmp(neu.labels, neu1.labels, sizeof(int) * n) || neu.energy != neu1.energy) det_ok = 0;
        replib_result_free(&old); replib_result_free(&neu); replib_result_free(&neu1);
        replib_data_free(&D);
        free(X); free(cut); free(w); free(Rf);
    }
    ok(never_worse, "replib_search: energy never above the plain method's (%d cases, %d strictly lower)", cases, better);
    ok(better >= cases / 2, "replib_search: strictly lower in at least half the cases (%d of %d)", better, cases);
    ok(ev_ok, "replib_search: model energy after the search equals the direct evaluation");
    ok(det_ok, "replib_search: same labels and energy on 1 and 2 threads");
    return tap_done();
}
