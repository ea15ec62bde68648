/* stiffness.c -- see stiffness.h */
#include "stiffness.h"
#include "cm_error.h"
#include "geodesic.h"
#include "geometry.h"
#include <math.h>
#include <stdlib.h>

void stiffness_defaults(struct stiffness_params *p)
{
    *p = (struct stiffness_params){0};   /* every field set, the ones not named below 0 */
    p->kmin = 1; p->kmax = 100; p->gamma = 0.5; p->q = 2; p->radius = 0.1;
    p->weight = STIFF_IDW; p->spread = STIFF_RADIAL; p->geodesic = 0;
}

void landmark_stiffness(const double *V, int nv, const int *L, const double *P, int nl,
                        const struct stiffness_params *p, double *kl)
{
    double diag = bbox_diagonal(V, nv), emax = 0;
    if (!(diag > 0)) diag = 1;
    for (int l = 0; l < nl; l++) {
        double e = dist3(V + 3 * L[l], P + 3 * l) / diag;
        if (e > emax) emax = e;
    }
    for (int l = 0; l < nl; l++) {
        double e = dist3(V + 3 * L[l], P + 3 * l) / diag;
        double k = e > 0 && emax > 0 ? p->kmin * pow(emax / e, p->gamma) : p->kmax;
        kl[l] = k < p->kmin ? p->kmin : k > p->kmax ? p->kmax : k;
    }
}

int stiffness_map(const double *V, const int *F, int nv, int nf, const int *L,
                  const double *kl, int nl, const struct stiffness_params *p, double *k)
{
    double diag = bbox_diagonal(V, nv), r = p->radius * (diag > 0 ? diag : 1);
    double *D = malloc((size_t)nv * nl * sizeof *D + 1);   /* #V by nl distances */
    if (p->geodesic) {
        struct geodesic *g = geodesic_new(V, F, nv, nf);
        if (!g) { free(D); return -1; }
        double *d = malloc((size_t)nv * sizeof *d + 1);
        for (int l = 0; l < nl; l++) {
            if (geodesic_solve(g, L + l, 1, d) < 0) { free(d); free(D); geodesic_free(g); return -1; }
            for (int v = 0; v < nv; v++) D[(size_t)v * nl + l] = d[v] > 0 ? d[v] : 0;
        }
        free(d);
        geodesic_free(g);
    } else {
        for (int v = 0; v < nv; v++)
            for (int l = 0; l < nl; l++) D[(size_t)v * nl + l] = dist3(V + 3 * v, V + 3 * L[l]);
    }
    for (int v = 0; v < nv; v++) {
        const double *d = D + (size_t)v * nl;
        int at = -1;
        for (int l = 0; l < nl; l++) if (L[l] == v) at = l;
        if (at >= 0) { k[v] = kl[at]; continue; }
        double wsum = 0, w[nl > 0 ? nl : 1];
        for (int l = 0; l < nl; l++) {
            double x = d[l] / r;
            w[l] = !isfinite(x) ? 0 : p->weight == STIFF_IDW ? (x > 0 ? 1 / pow(x, p->q) : 1e300)
                                                             : 1 / exp(pow(x, p->q));
            wsum += w[l];
        }
        if (!(wsum > 0)) { k[v] = p->kmax; continue; }
        double kv = 0;
        for (int l = 0; l < nl; l++) {
            double wh = w[l] / wsum;
            if (p->spread == STIFF_GLOBAL) { kv += wh * kl[l]; continue; }
            const double in = 0.4, out = 0.1;
            if (wh >= in) kv += wh * kl[l];
            else if (wh > out) {
                double s = pow((wh - out) / (in - out), 2);
                kv += wh * (s * kl[l] + (1 - s) * p->kmax);
            } else kv += wh * p->kmax;
        }
        k[v] = kv < p->kmin ? p->kmin : kv > p->kmax ? p->kmax : kv;
    }
    free(D);
    return 0;
}
