/* seam.c -- see seam.h */
#include "seam.h"
#include "cm_error.h"
#include "geodesic.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

int seam_vertices(const struct topology *t, const int *P, unsigned char *is_seam)
{
    int n = 0;
    for (int v = 0; v < t->nv; v++) {
        int s = 0;
        for (int k = t->VFs[v] + 1; k < t->VFs[v + 1]; k++)
            if (P[t->VF[k]] != P[t->VF[t->VFs[v]]]) { s = 1; break; }
        is_seam[v] = (unsigned char)s;
        n += s;
    }
    return n;
}

int seam_check_manifold(const struct topology *t, const unsigned char *is_seam)
{
    for (int e = 0; e < t->ne; e++)
        if (t->EFn[e] > 2 && (is_seam[t->E[2 * e]] || is_seam[t->E[2 * e + 1]]))
            return cm_seterr("non-manifold edge %d-%d (%d faces) on the part seam",
                             t->E[2 * e], t->E[2 * e + 1], t->EFn[e]);
    return 0;
}

void seam_grow(const struct topology *t, unsigned char *flags, int rings)
{
    int nv = t->nv;
    unsigned char *next = malloc((size_t)nv + 1);
    for (int r = 0; r < rings; r++) {
        memcpy(next, flags, (size_t)nv);
        for (int v = 0; v < nv; v++)
            if (flags[v])
                for (int k = t->VVs[v]; k < t->VVs[v + 1]; k++) next[t->VV[k]] = 1;
        memcpy(flags, next, (size_t)nv);
    }
    free(next);
}

int seam_roles(const struct topology *t, const int *F, const unsigned char *is_seam,
               int rings, unsigned char *role)
{
    int nv = t->nv, nf = t->nf;
    unsigned char *fix = malloc((size_t)nv + 1);
    memcpy(fix, is_seam, (size_t)nv);
    seam_grow(t, fix, rings);
    /* components (of faces) that contain a seam vertex */
    int *comp = malloc(((size_t)nf + 1) * sizeof *comp);
    int nc = connected_components(t, F, comp);
    unsigned char *has = calloc((size_t)nc + 1, 1);
    for (int f = 0; f < nf; f++)
        for (int c = 0; c < 3; c++)
            if (is_seam[F[3 * f + c]]) has[comp[f]] = 1;
    int nfix = 0;
    for (int v = 0; v < nv; v++) {
        if (fix[v]) { role[v] = SEAM_FIXED; nfix++; }
        else if (t->VFs[v] == t->VFs[v + 1] || !has[comp[t->VF[t->VFs[v]]]]) role[v] = SEAM_KEEP;
        else role[v] = SEAM_FREE;
    }
    free(fix);
    free(comp);
    free(has);
    return nfix;
}

int seam_band(const double *V, const int *F, const struct topology *t,
              const unsigned char *is_seam, double width, unsigned char *role, double *dist)
{
    int nv = t->nv, ns = 0;
    if (!(width > 0)) return cm_seterr("seam band: width must be > 0");
    int *S = malloc(((size_t)nv + 1) * sizeof *S);
    double *D = dist ? dist : malloc(((size_t)nv + 1) * sizeof *D);
    if (!S || !D) {
        free(S);
        if (!dist) free(D);
        return cm_seterr("seam band: out of memory");
    }
    for (int v = 0; v < nv; v++)
        if (is_seam[v]) S[ns++] = v;
    int npin = 0;
    if (ns == 0) {
        for (int v = 0; v < nv; v++) D[v] = INFINITY;
    } else {
        struct geodesic *g = geodesic_new(V, F, nv, t->nf);
        if (!g || geodesic_solve(g, S, ns, D) < 0) {
            geodesic_free(g);
            free(S);
            if (!dist) free(D);
            return -1;
        }
        geodesic_free(g);
    }
    for (int v = 0; v < nv; v++)
        if (role[v] == SEAM_FREE && !(D[v] <= width)) {
            role[v] = SEAM_KEEP;
            npin++;
        }
    free(S);
    if (!dist) free(D);
    return npin;
}
