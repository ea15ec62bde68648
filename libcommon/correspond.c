/* correspond.c -- see correspond.h */
#include "correspond.h"
#include "geometry.h"
#include <stddef.h>

void correspond_normal(const double *N, const int *F, int f, const double *b, double n[3])
{
    for (int d = 0; d < 3; d++)
        n[d] = b[0] * N[3 * F[3 * f] + d] + b[1] * N[3 * F[3 * f + 1] + d] +
               b[2] * N[3 * F[3 * f + 2] + d];
}

int correspond_on_boundary(const struct topology *t, int f, const double *b)
{
    const double tol = 1e-9;
    for (int c = 0; c < 3; c++) {
        /* the edge from corner c to c+1 is opposite corner c+2 */
        int e = t->FE[3 * f + c];
        if (t->EFn[e] == 1 && b[(c + 2) % 3] < tol) return 1;
    }
    return 0;
}

int correspond(const struct closest_point_tree *T, const int *F, const double *N,
               const struct topology *t, const double *Q, const double *M,
               int n, double cosmax, double max_dist, int hinted, double *C, int *I, double *B,
               unsigned char *ok)
{
    closest_points_hinted(T, Q, n, hinted ? I : NULL, C, I, B, NULL);
    int rejected = 0;
    for (int i = 0; i < n; i++) {
        double m[3];
        correspond_normal(N, F, I[i], B + 3 * i, m);
        const double *q = M + 3 * i;
        int bad = correspond_on_boundary(t, I[i], B + 3 * i) ||
                  dot3(m, q) < cosmax * norm3(m) * norm3(q) ||
                  (max_dist > 0 && dist3(Q + 3 * i, C + 3 * i) > max_dist);
        rejected += bad;
        if (ok) ok[i] = (unsigned char)!bad;
    }
    return rejected;
}
