/* winding.c -- see winding.h */
#include "winding.h"
#include "geometry.h"
#include <math.h>

double winding_number(const double *V, const int *F, int nf, const double p[3])
{
    double w = 0;
    for (int f = 0; f < nf; f++) {
        double a[3], b[3], c[3];
        sub3(V + 3 * F[3 * f], p, a);
        sub3(V + 3 * F[3 * f + 1], p, b);
        sub3(V + 3 * F[3 * f + 2], p, c);
        double la = norm3(a), lb = norm3(b), lc = norm3(c), bc[3];
        cross3(b, c, bc);
        double num = dot3(a, bc);
        double den = la * lb * lc + dot3(a, b) * lc + dot3(b, c) * la + dot3(c, a) * lb;
        w += 2 * atan2(num, den);   /* Van Oosterom-Strackee solid angle */
    }
    return w / (4 * M_PI);
}

void winding_volumes(const double *VA, int nva, const int *FA, int nfa,
                     const double *VB, const int *FB, int nfb, int n, double *va, double *vi)
{
    double lo[3], hi[3];
    bounding_box(VA, nva, lo, hi);
    double h[3], cell = 1;
    for (int d = 0; d < 3; d++) { h[d] = (hi[d] - lo[d]) / n; cell *= h[d]; }
    long ia = 0, ii = 0;
    for (int i = 0; i < n; i++)
        for (int j = 0; j < n; j++)
            for (int k = 0; k < n; k++) {
                double p[3] = {lo[0] + (i + 0.5) * h[0], lo[1] + (j + 0.5) * h[1], lo[2] + (k + 0.5) * h[2]};
                if (winding_number(VA, FA, nfa, p) <= 0.5) continue;
                ia++;
                if (VB && winding_number(VB, FB, nfb, p) > 0.5) ii++;
            }
    *va = ia * cell;
    if (vi) *vi = ii * cell;
}
