/* swapcost.h -- fewer swaps on set: relabel an animation with a fixed
 * replacement library when every change of piece between consecutive
 * frames of one clip costs C (chainlabel.h's swap term, exact by chain DP),
 * and count the swaps.  Shared by dict-learn and label-expand.
 *
 * The energy minimized is the StopShop energy of replib.h plus C per swap:
 *   E_C(l) = sum_f |x_f - r_{l_f}|_W^2
 *          + lambda/2 sum_{f, f+1 in one clip} |dx_f - dr|_W^2
 *          + C #{f, f+1 in one clip : l_f != l_{f+1}}
 * C is in the units of the data term (squared model units times weight).
 * A change of piece across a clip boundary (a frame header "cut") is free
 * and is not counted.
 */
#ifndef CM_SWAPCOST_H
#define CM_SWAPCOST_H
#include "replib.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Swaps of labels l (n) inside clips: f in [0, n-1) with l_f != l_{f+1}
 * and cut[f+1] == 0 (cut: n flags, 1 = frame starts a clip, or NULL). */
int swap_count(const int *l, int n, const unsigned char *cut);

/* One point of a swap sweep. */
struct swap_point {
    double cost;                /* C */
    int swaps;                  /* swaps inside clips */
    struct replib_report rep;   /* data, velocity and errors of the labels (no swap term) */
    double energy;              /* rep.energy + C * swaps */
};

/* Labels for the fixed library of L (prepared by replib_prepare with
 * nfix = d pieces, Rfix = the library, X = the frames in memory) with swap
 * cost C >= 0 (finite).  l (out): n labels.  pt (out): the point.  L's
 * swap_cost is set to C (and left so).  C = 0 gives exactly replib_label's
 * labels.  Returns 0, or -1 with cm_errmsg. */
int swap_relabel(struct replib_data *L, double lambda, enum replib_method method, double C,
                 int *l, struct swap_point *pt);

#ifdef __cplusplus
}
#endif
#endif
