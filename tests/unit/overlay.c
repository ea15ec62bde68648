/* overlay.c -- cdt2_overlay, the fallback of the compatible triangulation
 * for pieces no path splits: on star-shaped polygons of m corners in N
 * shapes (the same angles, radii drawn per shape, so every shape's
 * Delaunay triangulation differs), both ways of choosing the shapes'
 * triangulations give a mesh positive in every shape that covers each
 * shape's polygon exactly (areas), the same bytes twice, and the
 * fewest-crossings choice never more Steiner points than each shape's
 * Delaunay triangulation (Aronov et al.), fewer over the whole set. */
#include "cdt2.h"
#include "predicates2.h"
#include "tap.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static double area2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* shape s's polygon and the overlay's k new points as one array */
static const double *pt(const double *X, const double *S, int s, int m, int k, int v)
{
    return v < m ? X + 2 * v : S + 2 * ((size_t)s * k + (v - m));
}

/* 1 if every face is positive in every shape and the faces' areas sum to
 * the polygon's in every shape */
static int valid(int m, int N, double *const *X, const double *S, int k, const int *F, int nf)
{
    for (int s = 0; s < N; s++) {
        double poly = 0, sum = 0;
        for (int i = 0; i < m; i++) poly += area2(X[s], X[s] + 2 * i, X[s] + 2 * ((i + 1) % m));
        for (int f = 0; f < nf; f++) {
            const double *a = pt(X[s], S, s, m, k, F[3 * f]), *b = pt(X[s], S, s, m, k, F[3 * f + 1]),
                         *c = pt(X[s], S, s, m, k, F[3 * f + 2]);
            if (orient2_sign(a, b, c) <= 0) return 0;
            sum += area2(a, b, c);
        }
        if (fabs(sum - poly) > 1e-9 * fabs(poly)) return 0;
    }
    return 1;
}

int main(void)
{
    unsigned seed = 12345;
    long kd = 0, kf = 0;
    int cases = 0, ok_valid = 1, ok_fewer = 1, ok_same = 1;
    for (int c = 0; c < 24; c++) {
        int m = 8 + 4 * (c % 6), N = 2 + c % 4;
        double *X[6];
        for (int s = 0; s < N; s++) {
            X[s] = malloc(2 * (size_t)m * sizeof **X);
            for (int i = 0; i < m; i++) {
                seed = seed * 1103515245u + 12345u;
                double r = 0.3 + 0.7 * ((seed >> 16) & 1023) / 1023.0, t = 2 * M_PI * i / m;
                X[s][2 * i] = r * cos(t);
                X[s][2 * i + 1] = r * sin(t);
            }
        }
        int kc[2] = {0, 0};
        for (int fewest = 0; fewest <= 1; fewest++) {
            double *S = NULL, *S2 = NULL;
            int k = 0, nf = 0, *F = NULL, k2 = 0, nf2 = 0, *F2 = NULL;
            if (cdt2_overlay(m, N, (const double *const *)X, fewest, &S, &k, &F, &nf) < 0 ||
                cdt2_overlay(m, N, (const double *const *)X, fewest, &S2, &k2, &F2, &nf2) < 0) {
                ok_valid = 0;
                continue;
            }
            if (!valid(m, N, X, S, k, F, nf)) ok_valid = 0;
            if (k != k2 || nf != nf2 || memcmp(F, F2, 3 * (size_t)nf * sizeof *F) ||
                memcmp(S, S2, 2 * (size_t)N * k * sizeof *S))
                ok_same = 0;
            kc[fewest] = k;
            if (fewest) kf += k;
            else kd += k;
            if (fewest && k > kc[0]) ok_fewer = 0;
            free(S); free(S2); free(F); free(F2);
        }
        cases++;
        for (int s = 0; s < N; s++) free(X[s]);
    }
    ok(ok_valid, "%d polygons in 2-5 shapes: both overlays positive in every shape, areas exact", cases);
    ok(ok_same, "the same bytes twice");
    ok(ok_fewer, "fewest crossings: never more Steiner points than the Delaunay triangulations'");
    ok(kf < kd, "fewest crossings: %ld Steiner points over all, the Delaunay triangulations' %ld", kf, kd);
    return tap_done();
}
