/* distortion.c -- see distortion.h */
#include "distortion.h"
#include "geometry.h"
#include <math.h>
#include <stdlib.h>

static void centroid(const double *V, int nv, double c[3])
{
    c[0] = c[1] = c[2] = 0;
    for (int v = 0; v < nv; v++)
        for (int d = 0; d < 3; d++) c[d] += V[3 * v + d] / nv;
}

static double tet_volume(const double *V, const int *f, const double c[3])
{
    double a[3], b[3], e[3], n[3];
    sub3(V + 3 * f[0], c, a);
    sub3(V + 3 * f[1], c, b);
    sub3(V + 3 * f[2], c, e);
    cross3(b, e, n);
    return dot3(a, n) / 6;
}

int mesh_distortion(const double *V0, const double *V, const int *F, int nv, int nf,
                    struct distortion *d)
{
    double *A0 = malloc((size_t)nf * sizeof *A0 + 1), *A = malloc((size_t)nf * sizeof *A + 1);
    face_areas(V0, F, nf, A0);
    face_areas(V, F, nf, A);
    double s = 0, ss = 0, sa = 0;
    int na = 0;
    for (int f = 0; f < nf; f++) {
        if (!(A0[f] > 0)) continue;
        double r = A[f] / A0[f] - 1;
        s += r; ss += r * r; sa += fabs(r); na++;
    }
    d->area_abs = na ? sa / na : 0;
    d->area_mean = na ? s / na : 0;
    d->area_sigma = na ? sqrt(fmax(0, ss / na - d->area_mean * d->area_mean)) : 0;
    double c0[3], c[3], mean = 0;
    centroid(V0, nv, c0);
    centroid(V, nv, c);
    for (int f = 0; f < nf; f++) mean += fabs(tet_volume(V0, F + 3 * f, c0)) / nf;
    s = ss = 0;
    int nk = 0;
    for (int f = 0; f < nf; f++) {
        double v0 = tet_volume(V0, F + 3 * f, c0);
        if (!(fabs(v0) >= 1e-3 * mean) || mean == 0) continue;
        double r = tet_volume(V, F + 3 * f, c) / v0 - 1;
        s += r; ss += r * r; nk++;
    }
    d->vol_n = nk;
    d->vol_mean = nk ? s / nk : 0;
    d->vol_sigma = nk ? sqrt(fmax(0, ss / nk - d->vol_mean * d->vol_mean)) : 0;
    d->edge_max = 0;
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) {
            int i = F[3 * f + k], j = F[3 * f + (k + 1) % 3];
            double L = dist3(V0 + 3 * i, V0 + 3 * j), l = dist3(V + 3 * i, V + 3 * j);
            if (L > 0 && fabs(l / L - 1) > d->edge_max) d->edge_max = fabs(l / L - 1);
        }
    double vol0 = mesh_volume(V0, F, nf);
    d->volume_rel = vol0 != 0 ? mesh_volume(V, F, nf) / vol0 - 1 : 0;
    free(A0);
    free(A);
    return 0;
}
