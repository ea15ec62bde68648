/* correspond.c -- see correspond.h */
#include "correspond.h"
#include "cm_error.h"
#include "geometry.h"
#include <math.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>

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
               int n, double cosmax, double max_dist, double search, int hinted, double *C,
               int *I, double *B, unsigned char *ok)
{
    closest_points_hinted(T, Q, n, hinted ? I : NULL, C, I, B, NULL);
    int rejected = 0;
    for (int i = 0; i < n; i++) {
        double m[3];
        correspond_normal(N, F, I[i], B + 3 * i, m);
        const double *q = M + 3 * i;
        if (search > 0 && dot3(m, q) < cosmax * norm3(m) * norm3(q)) {
            /* the nearest point whose normal agrees, a little farther away
             * (the other side of a thin part: an ear, a leg against the body) */
            int near[256];
            double d0 = dist3(Q + 3 * i, C + 3 * i), best = INFINITY;
            int k = closest_point_faces_within(T, Q + 3 * i, d0 + search, near, 256);
            for (int j = 0; j < k && j < 256; j++) {
                double c[3], b[3], mm[3];
                double d = closest_point_on_face(T, near[j], Q + 3 * i, c, b);
                if (!(d < best)) continue;
                correspond_normal(N, F, near[j], b, mm);
                if (dot3(mm, q) < cosmax * norm3(mm) * norm3(q)) continue;
                best = d;
                I[i] = near[j];
                memcpy(C + 3 * i, c, sizeof c);
                memcpy(B + 3 * i, b, sizeof b);
                memcpy(m, mm, sizeof mm);
            }
        }
        int bad = correspond_on_boundary(t, I[i], B + 3 * i) ||
                  dot3(m, q) < cosmax * norm3(m) * norm3(q) ||
                  (max_dist > 0 && dist3(Q + 3 * i, C + 3 * i) > max_dist);
        rejected += bad;
        if (ok) ok[i] = (unsigned char)!bad;
    }
    return rejected;
}

int correspond_overlay(const int *F, int f, const double *b, const double *d, double dist,
                       double ratio, double tau)
{
    if (!(ratio > 0) || !(dist > tau)) return 0;
    double dc = b[0] * d[F[3 * f]] + b[1] * d[F[3 * f + 1]] + b[2] * d[F[3 * f + 2]];
    return dc < ratio * dist;
}

double correspond_overlay_scale(const double *Q, const double *C, const unsigned char *ok, int n,
                                double factor)
{
    double s = 0;
    int m = 0;
    for (int i = 0; i < n; i++) {
        if (ok && !ok[i]) continue;
        double e = dist3(Q + 3 * i, C + 3 * i);
        s += e * e;
        m++;
    }
    return m ? factor * sqrt(s / m) : 0;
}

int correspond_parts(const struct topology *t, const int *F)
{
    if (t->nboundary > 0) return 1;
    int *c = malloc(((size_t)t->nf + 1) * sizeof *c);
    if (!c) return cm_seterr("out of memory (the components of %d faces)", t->nf);
    int n = connected_components(t, F, c);
    free(c);
    return n > 1;
}
