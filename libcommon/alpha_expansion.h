/* alpha_expansion.h -- multi-label Potts energy minimization by alpha-expansion
 * (Boykov, Veksler, Zabih 2001) on BK max-flow (graphcut.h), on a general
 * graph:
 *
 *   E(L) = sum_i U(i, L_i) + sum_e W_e [L_a(e) != L_b(e)]
 *
 * Each expansion move (may every node switch to label alpha?) is solved
 * exactly by one s-t min cut, with the pairwise terms built as in
 * Kolmogorov and Zabih 2004.  Labels alpha = 0, 1, ..., s-1 are tried in
 * this fixed order, cycle after cycle, until a whole cycle lowers the
 * energy by no more than a relative 1e-12 (or max_cycles).  Deterministic:
 * the same input gives the same labels.  The result is a local minimum
 * with respect to every expansion move, within a factor 2 of the global
 * minimum for Potts energies.
 */
#ifndef CM_ALPHA_EXPANSION_H
#define CM_ALPHA_EXPANSION_H
#ifdef __cplusplus
extern "C" {
#endif

struct alpha_expansion_stats {
    double unary;      /* sum_i U(i, L_i) of the result */
    double binary;     /* sum_e W_e [labels differ] of the result */
    int cycles;        /* cycles run (a cycle tries every label once) */
    int moves;         /* expansion moves that lowered the energy */
};

/* Minimize E(L).
 *   n       number of nodes
 *   s       number of labels (>= 1)
 *   U       n by s unary costs, row-major (U[i*s + l]); INFINITY forbids
 *           label l at node i; every node needs a finite label
 *   ne      number of edges
 *   E       ne by 2 node indices (self loops are ignored)
 *   W       ne edge weights, finite and >= 0 (W NULL: all 1)
 *   L       n labels: input initial labeling if init != 0 (must have finite
 *           cost), else ignored and started at the per-node argmin of U
 *           (first on ties); output the result in 0..s-1
 *   max_cycles  <= 0: no limit
 *   st      may be NULL: energies and counts of the result
 * Returns 0, or -1 (cm_errmsg set) on bad input or allocation failure. */
int alpha_expansion(int n, int s, const double *U, int ne, const int *E, const double *W,
                    int *L, int init, int max_cycles, struct alpha_expansion_stats *st);

/* Energy of a labeling (unary and binary parts, either pointer may be NULL). */
void potts_energy(int n, int s, const double *U, int ne, const int *E, const double *W,
                  const int *L, double *unary, double *binary);

#ifdef __cplusplus
}
#endif
#endif
