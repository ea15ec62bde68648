/* laplacian.c -- see laplacian.h */
#include "laplacian.h"
#include "cm_error.h"
#include "geometry.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* cotangent of the angle at corner c of face f */
static void face_cots(const double *V, const int *F, int f, double cot[3], double *area2)
{
    const double *p[3] = {V + 3 * F[3 * f], V + 3 * F[3 * f + 1], V + 3 * F[3 * f + 2]};
    double n[3], u[3], v[3];
    sub3(p[1], p[0], u);
    sub3(p[2], p[0], v);
    cross3(u, v, n);
    double a2 = norm3(n);          /* twice the area */
    *area2 = a2;
    for (int c = 0; c < 3; c++) {
        double e1[3], e2[3];
        sub3(p[(c + 1) % 3], p[c], e1);
        sub3(p[(c + 2) % 3], p[c], e2);
        cot[c] = a2 > 0 ? dot3(e1, e2) / a2 : 0;
    }
}

void cot_laplacian_triplets(const double *V, const int *F, int nf, double scale,
                            struct triplets *T)
{
    for (int f = 0; f < nf; f++) {
        double cot[3], a2;
        face_cots(V, F, f, cot, &a2);
        for (int c = 0; c < 3; c++) {
            /* the edge opposite corner c joins corners c+1 and c+2 */
            int i = F[3 * f + (c + 1) % 3], j = F[3 * f + (c + 2) % 3];
            double w = 0.5 * cot[c] * scale;
            triplets_add(T, i, j, w);
            triplets_add(T, j, i, w);
            triplets_add(T, i, i, -w);
            triplets_add(T, j, j, -w);
        }
    }
}

void cot_edge_weights(const double *V, const int *F, int nf, const struct topology *t, double *W)
{
    memset(W, 0, (size_t)t->ne * sizeof *W);
    for (int f = 0; f < nf; f++) {
        double cot[3], a2;
        face_cots(V, F, f, cot, &a2);
        /* FE[3f+c] is the edge from corner c to c+1, opposite corner c+2 */
        for (int c = 0; c < 3; c++)
            W[t->FE[3 * f + c]] += 0.5 * cot[(c + 2) % 3];
    }
}

cholmod_sparse *cot_laplacian(const double *V, const int *F, int nv, int nf)
{
    struct triplets T;
    triplets_init(&T, nv, nv);
    cot_laplacian_triplets(V, F, nf, 1.0, &T);
    cholmod_sparse *L = triplets_to_sparse(&T, 0);
    triplets_free(&T);
    return L;
}

void mass_diag(const double *V, const int *F, int nv, int nf, enum mass_type type, double *M)
{
    memset(M, 0, (size_t)nv * sizeof *M);
    for (int f = 0; f < nf; f++) {
        double cot[3], a2;
        face_cots(V, F, f, cot, &a2);
        double area = 0.5 * a2;
        if (type == MASS_BARYCENTRIC) {
            for (int c = 0; c < 3; c++) M[F[3 * f + c]] += area / 3;
            continue;
        }
        int obtuse = -1;
        for (int c = 0; c < 3; c++)
            if (cot[c] < 0) obtuse = c;
        if (obtuse >= 0) {
            for (int c = 0; c < 3; c++)
                M[F[3 * f + c]] += c == obtuse ? area / 2 : area / 4;
            continue;
        }
        for (int c = 0; c < 3; c++) {
            /* Voronoi share of corner c: 1/8 (|e_b|^2 cot + |e_c|^2 cot) */
            const double *p = V + 3 * F[3 * f + c];
            const double *q = V + 3 * F[3 * f + (c + 1) % 3];
            const double *r = V + 3 * F[3 * f + (c + 2) % 3];
            double dq = dist3(p, q), dr = dist3(p, r);
            M[F[3 * f + c]] += (dq * dq * cot[(c + 2) % 3] + dr * dr * cot[(c + 1) % 3]) / 8;
        }
    }
}

int umbrella_smooth(const struct topology *t, const unsigned char *mask, double lambda, int sweeps,
                    double *V)
{
    if (sweeps < 1) return 0;
    double *W = malloc(((size_t)t->nv * 3 + 1) * sizeof *W);
    if (!W) return cm_seterr("out of memory");
    for (int s = 0; s < sweeps; s++) {
        memcpy(W, V, (size_t)t->nv * 3 * sizeof *W);
        for (int i = 0; i < t->nv; i++) {
            int deg = t->VVs[i + 1] - t->VVs[i];
            if (deg == 0 || (mask && !mask[i])) continue;
            for (int d = 0; d < 3; d++) {
                double m = 0;
                for (int q = t->VVs[i]; q < t->VVs[i + 1]; q++) m += W[3 * t->VV[q] + d];
                V[3 * i + d] = (1 - lambda) * W[3 * i + d] + lambda * m / deg;
            }
        }
    }
    free(W);
    return 0;
}
