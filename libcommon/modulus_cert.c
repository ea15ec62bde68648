/* modulus_cert.c -- see modulus_cert.h. */
#include "modulus_cert.h"
#include "quad_modulus.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* the vertex budget of one quadrilateral's mesh: far above what the
 * survey's outlines need for 3% (a few thousand), a bound on the cost */
#define QM_MAX_NV 200000
/* a ratio below this needs no tighter bracket: its ceiling is above 50
 * degrees, far above any goal of compat-tri */
#define QM_NO_OBSTRUCTION 2.0
/* the loose width the candidates get first */
#define QM_COARSE 0.3

double affine_distortion_max(double theta)
{
    double t1 = 2 / tan(theta) + 1 / tan(M_PI - 2 * theta);
    double t2 = 1 / tan(theta) + 2 / tan((M_PI - theta) / 2);
    double S = 2 / sqrt(3) * (t1 > t2 ? t1 : t2);
    if (S < 2) S = 2;   /* rounding at 60 degrees */
    return (S + sqrt(S * S - 4)) / 2;
}

double angle_ceiling(double R)
{
    if (!(R > 1)) return M_PI / 3;
    double lo = 1e-9, hi = M_PI / 3;   /* Kmax^2 decreases from infinity to 1 */
    for (int it = 0; it < 100; it++) {
        double m = 0.5 * (lo + hi), K = affine_distortion_max(m);
        if (K * K > R) lo = m; else hi = m;
    }
    return hi;
}

struct quad_state {
    int row[4];
    struct quad_modulus **q;   /* N */
    int fine;                  /* refined to this many levels */
};

/* the largest lower bound of a ratio over pairs of poses (and the pair),
 * and the largest upper bound */
static void ratio_bounds(const struct quad_state *Q, int N, double *L, int *pi, int *pj, double *U)
{
    *L = 0; *U = 0; *pi = 0; *pj = 1;
    for (int i = 0; i < N; i++)
        for (int j = 0; j < N; j++) {
            if (i == j) continue;
            double li, hi, lj, hj;
            quad_modulus_bracket(Q->q[i], &li, &hi, NULL);
            quad_modulus_bracket(Q->q[j], &lj, &hj, NULL);
            if (li / hj > *L) { *L = li / hj; *pi = i; *pj = j; }
            if (hi / lj > *U) *U = hi / lj;
        }
}

static int refine_all(struct quad_state *Q, int N, double tol)
{
    for (int s = 0; s < N; s++)
        if (quad_modulus_refine(Q->q[s], tol, QM_MAX_NV) < 0) return -1;
    return 0;
}

/* The quadruple with the largest lower bound of its ratio (the first on
 * ties), if that bound exceeds *L: *L, its pair of poses (*bi, *bj; may
 * be NULL) and its index are updated; returns the index (-1: none). */
static long best_quad(const struct quad_state *Q, long nq, int N, double *L, int *bi, int *bj)
{
    long best = -1;
    for (long k = 0; k < nq; k++) {
        double l, u;
        int i, j;
        ratio_bounds(&Q[k], N, &l, &i, &j, &u);
        if (l > *L) { *L = l; best = k; if (bi) *bi = i; if (bj) *bj = j; }
    }
    return best;
}

int modulus_certificate(int N, double *const *P, const int *n, const int *corr, int ncorr, double tol,
                        struct modulus_cert *c)
{
    memset(c, 0, sizeof *c);
    c->ceiling = 60;
    c->pose[1] = 1;
    if (N < 2 || ncorr < 4) return 0;
    long nq = (long)ncorr * (ncorr - 1) * (ncorr - 2) * (ncorr - 3) / 24;
    if (nq > 100000) return cm_seterr("%d correspondence points: too many quadruples for the certificate", ncorr);
    struct quad_state *Q = calloc(nq, sizeof *Q);
    if (!Q) return cm_seterr("out of memory");
    int rc = 0, k = 0;
    for (int a = 0; a < ncorr; a++)
        for (int b = a + 1; b < ncorr; b++)
            for (int d = b + 1; d < ncorr; d++)
                for (int e = d + 1; e < ncorr; e++) {
                    struct quad_state *S = &Q[k++];
                    S->row[0] = a; S->row[1] = b; S->row[2] = d; S->row[3] = e;
                }
    /* every pose meshed once; each quadruple starts from that mesh */
    struct quad_modulus **base = calloc(N, sizeof *base);
    if (!base) rc = cm_seterr("out of memory");
    for (int s = 0; s < N && rc == 0; s++) {
        int idx[4];
        for (int t = 0; t < 4; t++) idx[t] = corr[(size_t)Q[0].row[t] * N + s];
        if (!(base[s] = quad_modulus_new(P[s], n[s], idx))) rc = -1;
    }
    for (k = 0; k < nq && rc == 0; k++) {
        struct quad_state *S = &Q[k];
        if (!(S->q = calloc(N, sizeof *S->q))) { rc = cm_seterr("out of memory"); break; }
        for (int s = 0; s < N && rc == 0; s++) {
            int idx[4];
            for (int t = 0; t < 4; t++) idx[t] = corr[(size_t)S->row[t] * N + s];
            if (!(S->q[s] = quad_modulus_recorner(base[s], idx))) rc = -1;
            c->meshes++;
        }
    }
    for (int s = 0; base && s < N; s++) quad_modulus_free(base[s]);
    free(base);
    /* branch and bound, level by level: only the quadruples whose ratio
     * may still exceed the best lower bound are refined (the meshes are
     * nested, so lower bounds only grow and upper bounds only shrink) */
    const double level[3] = {QM_COARSE, 0.1, tol};
    int best = 0, bi = 0, bj = 1;
    double L = 0;
    for (int lev = 0; lev < 3 && rc == 0; lev++) {
        double t = level[lev] > tol ? level[lev] : tol;
        for (int changed = 1; rc == 0 && changed;) {
            changed = 0;
            L = 0;
            best_quad(Q, nq, N, &L, NULL, NULL);
            for (k = 0; k < nq && rc == 0; k++) {
                double l, u;
                int i, j;
                ratio_bounds(&Q[k], N, &l, &i, &j, &u);
                if (Q[k].fine <= lev && u > L && u > QM_NO_OBSTRUCTION) {
                    if (refine_all(&Q[k], N, t) < 0) rc = -1;
                    Q[k].fine = lev + 1;
                    changed = 1;
                    ratio_bounds(&Q[k], N, &l, &i, &j, &u);
                    if (l > L) L = l;
                }
            }
        }
    }
    if (rc == 0) {
        L = -INFINITY;
        best = (int)best_quad(Q, nq, N, &L, &bi, &bj);
        if (best < 0) { best = 0; L = 0; }     /* no bound is a number: no certificate */
        c->quads = (int)nq;
        c->ratio = L;
        c->pose[0] = bi;
        c->pose[1] = bj;
        memcpy(c->row, Q[best].row, sizeof c->row);
        quad_modulus_bracket(Q[best].q[bi], &c->lo[0], &c->hi[0], NULL);
        quad_modulus_bracket(Q[best].q[bj], &c->lo[1], &c->hi[1], NULL);
        c->ratio_hi = c->hi[0] / c->lo[1];
        c->ceiling = angle_ceiling(L) * 180 / M_PI;
        for (k = 0; k < nq; k++)
            for (int s = 0; s < N; s++) {
                int nv;
                if (!Q[k].q || !Q[k].q[s]) continue;
                quad_modulus_bracket(Q[k].q[s], NULL, NULL, &nv);
                if (nv > c->nv) c->nv = nv;
            }
    }
    for (k = 0; k < nq; k++) {
        if (Q[k].q)
            for (int s = 0; s < N; s++) quad_modulus_free(Q[k].q[s]);
        free(Q[k].q);
    }
    free(Q);
    return rc;
}
