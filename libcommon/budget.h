/* budget.h -- one printing budget for all parts of a replacement animation:
 * choose the library size of every part from its error-vs-size curve (the
 * dict-learn --sweep of that part) so the summed error is least and the
 * summed cost (pieces, or grams of resin) stays within the budget.
 *
 * Curves are sampled: part p may take one of its n_p sizes d_p[i] (pieces)
 * with error e_p[i] (additive over parts, e.g. the StopShop energy) at cost
 * c_p d_p[i] (c_p = 1 for a piece budget, grams per piece for a resin one).
 *
 * Two methods:
 *   BUDGET_EXACT   dynamic programming over parts on Pareto fronts of
 *                  (cost, error): exact for any curves, convex or not;
 *   BUDGET_GREEDY  start every part at its smallest size and repeatedly take
 *                  the step with the largest error drop per unit of cost
 *                  that still fits (marginal gain): optimal when every
 *                  curve is convex and the steps are unit, not otherwise.
 */
#ifndef CM_BUDGET_H
#define CM_BUDGET_H
#ifdef __cplusplus
extern "C" {
#endif

enum budget_method { BUDGET_EXACT, BUDGET_GREEDY };

/* np parts; n: np sample counts; d: np arrays of n[p] sizes (increasing,
 * >= 1); e: np arrays of n[p] errors; c: np costs per piece (> 0);
 * budget: the most total cost allowed.
 * pick (out): np indices into d[p] / e[p].  *cost, *err (out): totals.
 * Returns -1 (cm_errmsg says why: the smallest sizes already cost more than
 * the budget, or bad input). */
int budget_allocate(int np, const int *n, const int *const *d, const double *const *e, const double *c,
                    double budget, enum budget_method method, int *pick, double *cost, double *err);

/* Is the sampled curve convex (error drop per piece never grows with d)?
 * Returns 1 or 0; *at (out, may be NULL): the size where it first is not. */
int budget_curve_convex(int n, const int *d, const double *e, int *at);

#ifdef __cplusplus
}
#endif
#endif
