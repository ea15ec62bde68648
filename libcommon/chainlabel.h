/* chainlabel.h -- multi-label problems on a chain (frames of an animation,
 * each coupled only to the next one inside its clip), as in the StopShop
 * labeling step (Eq. 14-16):
 *
 *   E(l) = sum_f U[f][l_f] + sum_{f: link[f]} ( c[f] + T[l_f][l_{f+1}]
 *                                               + H[f][l_{f+1}] - H[f][l_f]
 *                                               + swap [l_f != l_{f+1}] )
 *
 * For StopShop, with mu = lambda/2, P = Z R^T and Q = R R^T:
 *   U[f][a] = |z_f|^2 + Q_aa - 2 P_fa                   (Eq. 15)
 *   T[a][b] = mu |r_a - r_b|^2 = mu (Q_aa + Q_bb - 2 Q_ab)
 *   H[f][a] = -2 mu (P_{f+1,a} - P_{f,a})   (dz_f . r_a from one GEMM)
 *   c[f]    = mu |z_{f+1} - z_f|^2                      (Eq. 16)
 * which is mu |dz_f - (r_b - r_a)|^2 expanded.  The swap term (a Potts
 * term, >= 0) charges every change of piece between two frames of one clip:
 * the animator's swaps on set.  A change across a clip boundary is free.
 *
 * Three minimizers:
 *   chain_dp         exact (Viterbi, O(n d^2)): the graph is a chain.  The
 *                    swap term adds O(d) per frame:
 *                    min_a (h_a + T_ab + swap [a != b])
 *                      = min(h_b, min_a (h_a + T_ab) + swap)   (T_bb = 0).
 *   chain_expansion  alpha-expansion moves solved with BK max-flow.  An
 *                    expansion move on a pair labelled (a, b) is submodular
 *                    only if T_ab <= T_a,alpha + T_alpha,b, which squared
 *                    distances often break (the paper's Eq. 17-18 argument
 *                    does not cover expansion).  Such pair terms are
 *                    "truncated": E01 and E10 are raised until the move is
 *                    submodular; the move's energy is then an upper bound that
 *                    is exact at the current labeling, so the true energy
 *                    never rises.  Never better than chain_dp.
 *   chain_swap       alpha-beta swap moves (always submodular here, since
 *                    the H terms are unary per move and T is symmetric with
 *                    zero diagonal).
 * All run in place on labels l (n, values in [0, d)); the moves start from
 * the labeling given in l.
 */
#ifndef CM_CHAINLABEL_H
#define CM_CHAINLABEL_H
#ifdef __cplusplus
extern "C" {
#endif

struct chain {
    int n;                      /* frames */
    int d;                      /* labels */
    const double *U;            /* n by d unary costs, row-major */
    const double *T;            /* d by d pair costs (symmetric, zero diagonal) or NULL for no pair term */
    const double *H;            /* n by d per-pair linear terms (row f used for pair f,f+1) or NULL */
    const double *c;            /* n per-pair constants (entry f for pair f,f+1) or NULL */
    const unsigned char *link;  /* n flags: link[f] = 1 couples f and f+1 (0 at a cut and for f = n-1); NULL = all linked */
    double swap;                /* cost of a change of label between linked frames, >= 0 and finite
                                   (energy units); 0 = none, and then every result is bit for bit
                                   what it was without the term */
};

/* Number of changes of label between linked frames of l (n): the swaps. */
int chain_swaps(const struct chain *p, const int *l);

/* Energy of labels l (n), and optionally its parts: *unary = sum of U terms,
 * *pair = sum of pair terms (either pointer may be NULL). */
double chain_energy(const struct chain *p, const int *l, double *unary, double *pair);

/* Exact minimum by dynamic programming, one pass per clip.  l (out): n.
 * Ties go to the lowest label.  Returns the energy, or NAN and cm_seterr on
 * allocation failure. */
double chain_dp(const struct chain *p, int *l);

/* Alpha-expansion from the labeling in l (in/out), sweeping alpha = 0..d-1
 * until no move lowers the energy or max_sweeps sweeps (<= 0: 20).
 * *ntrunc (may be NULL) gets the number of truncated pair terms.  Returns
 * the final energy (NAN on failure). */
double chain_expansion(const struct chain *p, int *l, int max_sweeps, long *ntrunc);

/* Alpha-beta swap from the labeling in l (in/out), same conventions. */
double chain_swap(const struct chain *p, int *l, int max_sweeps);

#ifdef __cplusplus
}
#endif
#endif
