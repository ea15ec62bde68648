/* budget.c -- see budget.h */
#include "budget.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

int budget_curve_convex(int n, const int *d, const double *e, int *at)
{
    /* slopes s_i = (e_{i+1} - e_i) / (d_{i+1} - d_i) must not decrease */
    for (int i = 1; i + 1 < n; i++) {
        double s0 = (e[i] - e[i - 1]) / (d[i] - d[i - 1]), s1 = (e[i + 1] - e[i]) / (d[i + 1] - d[i]);
        if (s1 < s0 - 1e-12 * (fabs(s0) + fabs(s1))) {
            if (at) *at = d[i];
            return 0;
        }
    }
    return 1;
}

/* a state of the DP: cost and error so far, and the choice that made it */
struct state { double cost, err; int from, pick; };

static int by_cost(const void *a, const void *b)
{
    const struct state *x = a, *y = b;
    if (x->cost != y->cost) return x->cost < y->cost ? -1 : 1;
    if (x->err != y->err) return x->err < y->err ? -1 : 1;
    return 0;
}

static int exact(int np, const int *n, const int *const *d, const double *const *e, const double *c,
                 double budget, int *pick, double *cost, double *err)
{
    /* front[p]: the Pareto front (cost up, error down) over parts 0..p */
    struct state **front = calloc(np, sizeof *front);
    int *nfront = calloc(np, sizeof(int));
    int ok = 0;
    for (int p = 0; p < np; p++) {
        int nprev = p ? nfront[p - 1] : 1, m = 0;
        struct state *cand = malloc(sizeof(struct state) * (size_t)nprev * n[p]);
        for (int s = 0; s < nprev; s++)
            for (int i = 0; i < n[p]; i++) {
                double c0 = p ? front[p - 1][s].cost : 0, e0 = p ? front[p - 1][s].err : 0;
                double ci = c0 + c[p] * d[p][i];
                if (ci > budget * (1 + 1e-12)) continue;
                cand[m++] = (struct state){ci, e0 + e[p][i], s, i};
            }
        qsort(cand, m, sizeof *cand, by_cost);
        int k = 0;
        for (int j = 0; j < m; j++)   /* keep the states no cheaper one beats */
            if (k == 0 || cand[j].err < cand[k - 1].err) cand[k++] = cand[j];
        front[p] = cand; nfront[p] = k;
        if (k == 0) goto done;
    }
    /* the least error within budget: the last state of the front */
    int s = nfront[np - 1] - 1;
    *cost = front[np - 1][s].cost; *err = front[np - 1][s].err;
    for (int p = np - 1; p >= 0; p--) {
        pick[p] = front[p][s].pick;
        s = front[p][s].from;
    }
    ok = 1;
done:
    for (int p = 0; p < np; p++) free(front[p]);
    free(front); free(nfront);
    return ok ? 0 : -1;
}

static int greedy(int np, const int *n, const int *const *d, const double *const *e, const double *c,
                  double budget, int *pick, double *cost, double *err)
{
    double total = 0;
    for (int p = 0; p < np; p++) { pick[p] = 0; total += c[p] * d[p][0]; }
    if (total > budget * (1 + 1e-12)) return -1;
    for (;;) {
        int best = -1;
        double gain = 0;
        for (int p = 0; p < np; p++) {
            int i = pick[p];
            if (i + 1 >= n[p]) continue;
            double dc = c[p] * (d[p][i + 1] - d[p][i]);
            if (total + dc > budget * (1 + 1e-12)) continue;
            double g = (e[p][i] - e[p][i + 1]) / dc;
            if (g > gain) { gain = g; best = p; }
        }
        if (best < 0) break;
        total += c[best] * (d[best][pick[best] + 1] - d[best][pick[best]]);
        pick[best]++;
    }
    *cost = total; *err = 0;
    for (int p = 0; p < np; p++) *err += e[p][pick[p]];
    return 0;
}

int budget_allocate(int np, const int *n, const int *const *d, const double *const *e, const double *c,
                    double budget, enum budget_method method, int *pick, double *cost, double *err)
{
    if (np < 1) return cm_seterr("no parts");
    double least = 0;
    for (int p = 0; p < np; p++) {
        if (n[p] < 1) return cm_seterr("part %d: an empty error curve", p);
        if (!(c[p] > 0)) return cm_seterr("part %d: cost per piece %g is not positive", p, c[p]);
        for (int i = 0; i < n[p]; i++) {
            if (d[p][i] < 1 || (i && d[p][i] <= d[p][i - 1]))
                return cm_seterr("part %d: sizes must increase from 1 (row %d: %d)", p, i + 1, d[p][i]);
            if (!isfinite(e[p][i])) return cm_seterr("part %d: error %g at size %d", p, e[p][i], d[p][i]);
        }
        least += c[p] * d[p][0];
    }
    if (least > budget * (1 + 1e-12))
        return cm_seterr("the smallest library of every part already costs %g, over the budget %g", least, budget);
    return method == BUDGET_GREEDY ? greedy(np, n, d, e, c, budget, pick, cost, err)
                                   : exact(np, n, d, e, c, budget, pick, cost, err);
}
