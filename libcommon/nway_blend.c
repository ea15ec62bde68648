/* nway_blend.c -- see nway_blend.h */
#include "nway_blend.h"
#include "cm_error.h"
#include "polar.h"
#include "sparse.h"
#include "spd.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct nway_blend {
    int N, nv, nf;
    int *F;
    double *G;        /* #F by 2 by 3 gradient operators of the base triangles */
    double *area;     /* #F base areas */
    double *alpha;    /* #F by N unwrapped angles */
    double *S;        /* #F by N by 4 stretch matrices */
    struct quad_solver *solver;
    double *b, *y, *x;  /* #V by 2 work arrays */
    int npin;           /* fixed vertices: the first of each connected component, and every vertex in no triangle */
    int *pin;           /* npin vertex indices */
    double *P;          /* npin by N by 2: their positions in the shapes */
};

double hermite_step(double t, double a, double b)
{
    if (t <= a) return 0;
    if (t >= b) return 1;
    double u = (t - a) / (b - a);
    return u * u * (3 - 2 * u);
}

double soft_clamp(double t, double d)
{
    if (t < 0) return d * tanh(t / d);
    if (t > 1) return 1 + d * tanh((t - 1) / d);
    return t;
}

void shear_limit_weights(const double *w, int N, int mode, double *wl)
{
    double s = 0;
    for (int i = 0; i < N; i++)
        s += wl[i] = mode == SHEAR_HERMITE ? hermite_step(w[i], 0, 1) : soft_clamp(w[i], SHEAR_MARGIN);
    for (int i = 0; i < N; i++) wl[i] = s > 0 ? wl[i] / s : 1.0 / N;
}

void texture_weights(const double *w, int N, int mode, double sigma, double *wt)
{
    /* colours must not extrapolate: the Hermite step, or a hard clamp to
     * [0, 1] (the identity inside, like the soft clamp) */
    if (mode == SHEAR_HERMITE) shear_limit_weights(w, N, mode, wt);
    else {
        double s = 0;
        for (int i = 0; i < N; i++) s += wt[i] = fmin(fmax(w[i], 0), 1);
        for (int i = 0; i < N; i++) wt[i] = s > 0 ? wt[i] / s : 1.0 / N;
    }
    double s = 0;
    for (int i = 0; i < N; i++) {
        double x = sigma > 0 ? sigma * hermite_step(wt[i], sigma / 2, 1 - sigma / 2) : 0;
        s += wt[i] = x + (1 - sigma) * wt[i];
    }
    for (int i = 0; i < N; i++) wt[i] = s > 0 ? wt[i] / s : 1.0 / N;
}

void nway_blend_free(struct nway_blend *B)
{
    if (!B) return;
    quad_solver_free(B->solver);
    free(B->F); free(B->G); free(B->area); free(B->alpha); free(B->S);
    free(B->b); free(B->y); free(B->x);
    free(B->pin); free(B->P);
    free(B);
}

struct nway_blend *nway_blend_new(double *const *X, int N, int nv, const int *F, int nf, int base)
{
    struct nway_blend *B = calloc(1, sizeof *B);
    B->N = N; B->nv = nv; B->nf = nf;
    B->F = malloc(3 * (size_t)nf * sizeof *B->F);
    memcpy(B->F, F, 3 * (size_t)nf * sizeof *F);
    B->G = malloc(6 * (size_t)nf * sizeof *B->G);
    B->area = malloc((size_t)nf * sizeof *B->area);
    B->alpha = malloc((size_t)nf * N * sizeof *B->alpha);
    B->S = malloc(4 * (size_t)nf * N * sizeof *B->S);
    B->b = malloc(2 * (size_t)nv * sizeof *B->b);
    B->y = calloc(2 * (size_t)nv, sizeof *B->y);
    B->x = malloc(2 * (size_t)nv * sizeof *B->x);
    const double *P = X[base];
    struct triplets T;
    triplets_init(&T, nv, nv);
    for (int f = 0; f < nf; f++) {
        const int *t = F + 3 * f;
        const double *p0 = P + 3 * t[0], *p1 = P + 3 * t[1], *p2 = P + 3 * t[2];
        /* E = [p1-p0, p2-p0] as columns; gradient of hat functions: rows of E^-T */
        double e1x = p1[0] - p0[0], e1y = p1[1] - p0[1], e2x = p2[0] - p0[0], e2y = p2[1] - p0[1];
        double det = e1x * e2y - e2x * e1y;
        if (!(fabs(det) > 0)) {
            nway_blend_free(B);
            cm_seterr("triangle %d is degenerate in the base pose", f);
            return NULL;
        }
        /* E^-1 = 1/det [e2y -e2x; -e1y e1x]; grad phi1 = row 0 of E^-1, phi2 = row 1 */
        double *G = B->G + 6 * f;
        double g1x = e2y / det, g1y = -e2x / det, g2x = -e1y / det, g2y = e1x / det;
        G[0] = -g1x - g2x; G[1] = g1x; G[2] = g2x;     /* d/dx of phi0, phi1, phi2 */
        G[3] = -g1y - g2y; G[4] = g1y; G[5] = g2y;     /* d/dy */
        double a = 0.5 * fabs(det);
        B->area[f] = a;
        for (int r = 0; r < 2; r++)
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) triplets_add(&T, t[i], t[j], a * G[3 * r + i] * G[3 * r + j]);
        /* A_fi = [q1-q0, q2-q0] E^-1 for every shape */
        for (int s = 0; s < N; s++) {
            const double *Q = X[s];
            double A[4];
            for (int c = 0; c < 2; c++) {   /* row c of A: gradient of coordinate c */
                double v0 = Q[3 * t[0] + c], v1 = Q[3 * t[1] + c], v2 = Q[3 * t[2] + c];
                A[2 * c] = G[0] * v0 + G[1] * v1 + G[2] * v2;
                A[2 * c + 1] = G[3] * v0 + G[4] * v1 + G[5] * v2;
            }
            double R[4], S[4];
            if (s == base) {
                R[0] = R[3] = S[0] = S[3] = 1; R[1] = R[2] = S[1] = S[2] = 0;
            } else polar2(A, R, S);
            B->alpha[(size_t)f * N + s] = s == base ? 0 : rot2_angle(R);
            memcpy(B->S + 4 * ((size_t)f * N + s), S, sizeof S);
        }
    }
    /* unwrap angles: BFS over triangle adjacency, per shape */
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0) { triplets_free(&T); nway_blend_free(B); return NULL; }
    /* the translation of every connected component (separate pieces of a
     * drawing: compat-tri's several rings) is free: its first vertex is
     * fixed, as is every vertex in no triangle (vertex 0 alone for one
     * component) */
    int *comp = malloc(((size_t)nf + 1) * sizeof *comp), *first = NULL;
    int ncomp = comp ? connected_components(&t, F, comp) : -1;
    B->pin = malloc(((size_t)nv + 1) * sizeof *B->pin);
    if (ncomp >= 0) first = malloc(((size_t)ncomp + 1) * sizeof *first);
    if (!comp || ncomp < 0 || !first || !B->pin) {
        free(comp); free(first); topology_free(&t); triplets_free(&T); nway_blend_free(B);
        cm_seterr("out of memory");
        return NULL;
    }
    for (int k = 0; k < ncomp; k++) first[k] = nv;
    for (int f = 0; f < nf; f++)
        for (int j = 0; j < 3; j++)
            if (F[3 * f + j] < first[comp[f]]) first[comp[f]] = F[3 * f + j];
    unsigned char *fixed = calloc(nv + 1, 1);
    if (!fixed) {
        free(comp); free(first); topology_free(&t); triplets_free(&T); nway_blend_free(B);
        cm_seterr("out of memory");
        return NULL;
    }
    for (int k = 0; k < ncomp; k++) fixed[first[k]] = 1;
    for (int v = 0; v < nv; v++)
        if (t.VFs[v + 1] == t.VFs[v]) fixed[v] = 1;
    free(comp); free(first);
    for (int v = 0; v < nv; v++)
        if (fixed[v]) B->pin[B->npin++] = v;
    B->P = malloc(((size_t)B->npin * N * 2 + 1) * sizeof *B->P);
    if (!B->P) { free(fixed); topology_free(&t); triplets_free(&T); nway_blend_free(B); cm_seterr("out of memory"); return NULL; }
    for (int k = 0; k < B->npin; k++)
        for (int s = 0; s < N; s++) {
            B->P[2 * ((size_t)k * N + s)] = X[s][3 * B->pin[k]];
            B->P[2 * ((size_t)k * N + s) + 1] = X[s][3 * B->pin[k] + 1];
        }
    int *queue = malloc((size_t)nf * sizeof *queue);
    unsigned char *seen = calloc(nf, 1);
    for (int f0 = 0; f0 < nf; f0++) {
        if (seen[f0]) continue;
        int qh = 0, qt = 0;
        queue[qt++] = f0; seen[f0] = 1;
        while (qh < qt) {
            int f = queue[qh++];
            for (int c = 0; c < 3; c++) {
                int e = t.FE[3 * f + c];
                for (int k = 0; k < 2; k++) {
                    int g = t.EF[2 * e + k];
                    if (g < 0 || seen[g]) continue;
                    for (int s = 0; s < N; s++) {
                        double ref = B->alpha[(size_t)f * N + s], *a = &B->alpha[(size_t)g * N + s];
                        *a += 2 * M_PI * round((ref - *a) / (2 * M_PI));
                    }
                    seen[g] = 1;
                    queue[qt++] = g;
                }
            }
        }
    }
    free(queue); free(seen);
    topology_free(&t);
    cholmod_sparse *L = triplets_to_sparse(&T, 1);
    triplets_free(&T);
    B->solver = quad_solver_new(L, fixed);
    free(fixed);
    sparse_free(&L);
    if (!B->solver) { nway_blend_free(B); return NULL; }
    return B;
}

int nway_blend_eval(struct nway_blend *B, const double *w, const double *ws, double *out)
{
    int N = B->N;
    if (!ws) ws = w;
    memset(B->b, 0, 2 * (size_t)B->nv * sizeof *B->b);
    for (int f = 0; f < B->nf; f++) {
        double al = 0, S[4] = {0, 0, 0, 0};
        const double *as = B->alpha + (size_t)f * N, *Ss = B->S + 4 * (size_t)f * N;
        for (int i = 0; i < N; i++) {
            al += w[i] * as[i];
            for (int k = 0; k < 4; k++) S[k] += ws[i] * Ss[4 * i + k];
        }
        double c = cos(al), s = sin(al);
        double A[4] = {c * S[0] - s * S[2], c * S[1] - s * S[3], s * S[0] + c * S[2], s * S[1] + c * S[3]};
        const double *G = B->G + 6 * f;
        const int *t = B->F + 3 * f;
        double a = B->area[f];
        for (int i = 0; i < 3; i++)
            for (int r = 0; r < 2; r++) {
                /* b_i += area * G[:, i] . A[r, :] */
                B->b[2 * t[i] + r] += a * (G[i] * A[2 * r] + G[3 + i] * A[2 * r + 1]);
            }
    }
    for (int k = 0; k < B->npin; k++) {   /* the fixed vertices at the blend of their positions */
        double a[2] = {0, 0};
        for (int i = 0; i < N; i++)
            for (int c = 0; c < 2; c++) a[c] += w[i] * B->P[2 * ((size_t)k * N + i) + c];
        B->y[2 * B->pin[k]] = a[0]; B->y[2 * B->pin[k] + 1] = a[1];
    }
    if (quad_solver_solve(B->solver, B->b, B->y, B->x, 2) < 0) return -1;
    for (int v = 0; v < B->nv; v++) { out[3 * v] = B->x[2 * v]; out[3 * v + 1] = B->x[2 * v + 1]; out[3 * v + 2] = 0; }
    return 0;
}
