/* clay_deform.c -- see clay_deform.h */
#include "clay_deform.h"
#include "cm_error.h"
#include "geometry.h"
#include "polar.h"
#include "spd.h"
#include "laplacian.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct clay_deform {
    int nv, nf, nh, ne;
    const int *F;
    double *V, *W;       /* rest positions; per-edge weight k_ij w_ij */
    int *E;              /* #E by 2 */
    int *VVs, *VVe;      /* CSR of incident edges per vertex */
    int *H;
    double lambda, vol0, eps;
    struct spd_solver *S;
};

struct clay_deform *clay_deform_new(const double *V, const int *F, int nv, int nf,
                                    const double *k, const int *H, int nh, double lambda)
{
    for (int h = 0; h < nh; h++)
        if (H[h] < 0 || H[h] >= nv) {
            cm_seterr("landmark %d: vertex %d out of range 0..%d", h + 1, H[h], nv - 1);
            return NULL;
        }
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0) return NULL;
    struct clay_deform *c = calloc(1, sizeof *c);
    c->nv = nv; c->nf = nf; c->nh = nh; c->F = F; c->ne = t.ne; c->lambda = lambda;
    c->V = malloc((size_t)nv * 3 * sizeof *c->V + 1);
    memcpy(c->V, V, (size_t)nv * 3 * sizeof *c->V);
    c->E = malloc((size_t)t.ne * 2 * sizeof *c->E + 1);
    memcpy(c->E, t.E, (size_t)t.ne * 2 * sizeof *c->E);
    c->W = calloc((size_t)t.ne + 1, sizeof *c->W);
    c->H = malloc((size_t)nh * sizeof *c->H + 1);
    memcpy(c->H, H, (size_t)nh * sizeof *c->H);
    cot_edge_weights(V, F, nf, &t, c->W);
    /* clamp (obtuse pairs) and scale by the edge stiffness */
    double mean = 0;
    for (int e = 0; e < t.ne; e++) mean += fabs(c->W[e]) / t.ne;
    for (int e = 0; e < t.ne; e++) {
        double w = c->W[e] > 1e-3 * mean ? c->W[e] : 1e-3 * mean;
        double ke = k ? 0.5 * (k[c->E[2 * e]] + k[c->E[2 * e + 1]]) : 1;
        c->W[e] = w * ke;
    }
    /* incident edges per vertex */
    c->VVs = calloc((size_t)nv + 1, sizeof *c->VVs);
    c->VVe = malloc((size_t)t.ne * 2 * sizeof *c->VVe + 1);
    for (int e = 0; e < t.ne; e++) { c->VVs[c->E[2 * e] + 1]++; c->VVs[c->E[2 * e + 1] + 1]++; }
    for (int v = 0; v < nv; v++) c->VVs[v + 1] += c->VVs[v];
    int *fill = malloc((size_t)nv * sizeof *fill + 1);
    memcpy(fill, c->VVs, (size_t)nv * sizeof *fill);
    for (int e = 0; e < t.ne; e++) { c->VVe[fill[c->E[2 * e]]++] = e; c->VVe[fill[c->E[2 * e + 1]]++] = e; }
    free(fill);
    topology_free(&t);
    /* global matrix: weighted graph Laplacian + lambda at handles (+ a tiny
     * diagonal so pieces without handles stay determined) */
    struct triplets T;
    triplets_init(&T, nv, nv);
    for (int e = 0; e < c->ne; e++) {
        int i = c->E[2 * e], j = c->E[2 * e + 1];
        double w = c->W[e];
        triplets_add(&T, i, i, w); triplets_add(&T, j, j, w);
        triplets_add(&T, i, j, -w); triplets_add(&T, j, i, -w);
    }
    /* a weak pull toward the previous iterate keeps pieces without handles
     * determined (and where they are) */
    double eps = 1e-6 * mean;
    c->eps = eps;
    for (int v = 0; v < nv; v++) triplets_add(&T, v, v, eps);
    for (int h = 0; h < nh; h++) triplets_add(&T, H[h], H[h], lambda);
    cholmod_sparse *A = triplets_to_sparse(&T, 0);
    triplets_free(&T);
    c->S = spd_factor(A);
    sparse_free(&A);
    if (!c->S) { clay_deform_free(c); return NULL; }
    c->vol0 = mesh_volume(V, F, nf);
    return c;
}

int clay_deform_solve(struct clay_deform *c, const double *T, int iters, int keep_volume,
                      double *X)
{
    int nv = c->nv;
    double *R = malloc((size_t)nv * 9 * sizeof *R + 1), *B = malloc((size_t)nv * 3 * sizeof *B + 1);
    double *N = malloc((size_t)nv * 3 * sizeof *N + 1);
    int rc = 0;
    for (int it = 0; it < iters; it++) {
        /* local: best rotation per vertex, R_i = polar(S_i^T),
         * S_i = sum_j w_ij (v_i - v_j)(x_i - x_j)^T */
        for (int i = 0; i < nv; i++) {
            double S[9] = {0}, St[9], Q[9];
            for (int q = c->VVs[i]; q < c->VVs[i + 1]; q++) {
                int e = c->VVe[q], j = c->E[2 * e] == i ? c->E[2 * e + 1] : c->E[2 * e];
                double a[3], b[3];
                sub3(c->V + 3 * i, c->V + 3 * j, a);
                sub3(X + 3 * i, X + 3 * j, b);
                for (int r = 0; r < 3; r++)
                    for (int s = 0; s < 3; s++) S[3 * r + s] += c->W[e] * a[r] * b[s];
            }
            mat3_transpose(S, St);
            polar3(St, R + 9 * i, Q);
        }
        /* global: L x = sum_j w_ij/2 (R_i + R_j)(v_i - v_j) + lambda t */
        memset(B, 0, (size_t)nv * 3 * sizeof *B);
        for (int e = 0; e < c->ne; e++) {
            int i = c->E[2 * e], j = c->E[2 * e + 1];
            double d[3], Ri[9];
            sub3(c->V + 3 * i, c->V + 3 * j, d);
            for (int k = 0; k < 9; k++) Ri[k] = 0.5 * c->W[e] * (R[9 * i + k] + R[9 * j + k]);
            for (int r = 0; r < 3; r++) {
                double g = Ri[3 * r] * d[0] + Ri[3 * r + 1] * d[1] + Ri[3 * r + 2] * d[2];
                B[3 * i + r] += g;
                B[3 * j + r] -= g;
            }
        }
        for (int h = 0; h < c->nh; h++)
            for (int r = 0; r < 3; r++) B[3 * c->H[h] + r] += c->lambda * T[3 * h + r];
        for (int v = 0; v < 3 * nv; v++) B[v] += c->eps * X[v];
        if (spd_solve(c->S, B, X, 3) < 0) { rc = -1; break; }
        if (keep_volume && c->vol0 != 0) {
            /* restore the enclosed volume: move along the normals */
            for (int pass = 0; pass < 2; pass++) {
                double vol = mesh_volume(X, c->F, c->nf), area = mesh_area(X, c->F, c->nf);
                if (!(area > 0)) break;
                double delta = (c->vol0 - vol) / area;
                vertex_normals(X, c->F, nv, c->nf, N);
                for (int v = 0; v < nv; v++)
                    for (int r = 0; r < 3; r++) X[3 * v + r] += delta * N[3 * v + r];
            }
        }
    }
    free(R); free(B); free(N);
    return rc;
}

void clay_deform_free(struct clay_deform *c)
{
    if (!c) return;
    spd_free(c->S);
    free(c->V); free(c->W); free(c->E); free(c->VVs); free(c->VVe); free(c->H);
    free(c);
}
