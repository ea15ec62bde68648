/* swapcost.c -- see swapcost.h. */
#include "swapcost.h"
#include "cm_error.h"
#include <math.h>
#include <string.h>

int swap_count(const int *l, int n, const unsigned char *cut)
{
    int s = 0;
    for (int f = 0; f + 1 < n; f++)
        s += l[f] != l[f + 1] && !(cut && cut[f + 1]);
    return s;
}

int swap_relabel(struct replib_data *L, double lambda, enum replib_method method, double C,
                 int *l, struct swap_point *pt)
{
    if (!(C >= 0) || !isfinite(C)) return cm_seterr("swap cost %g is not a finite number >= 0", C);
    if (!L->X) return cm_seterr("swap cost: the frames must be in memory");
    L->swap_cost = C;
    double E = replib_label(L, lambda, method, l, NULL, NULL);
    if (isnan(E)) return -1;
    memset(pt, 0, sizeof *pt);
    pt->cost = C;
    pt->swaps = swap_count(l, L->n, L->cut);
    replib_evaluate(L->X, L->n, L->nv, L->Rfix, L->nfix, l, L->w, L->cut, lambda, &pt->rep, NULL);
    pt->energy = pt->rep.energy + C * pt->swaps;
    return 0;
}
