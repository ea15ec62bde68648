/* arap_fit.c -- see arap_fit.h */
#include "arap_fit.h"
#include "cm_error.h"
#include "correspond.h"
#include "geometry.h"
#include "laplacian.h"
#include "polar.h"
#include "spd.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void arap_ring_rotations(const struct topology *t, const double *R, const double *P, int nv,
                         double *Q)
{
    for (int i = 0; i < nv; i++) {
        double M[9] = {0}, Sm[9];
        for (int q = t->VVs[i]; q < t->VVs[i + 1]; q++) {
            int j = t->VV[q];
            double e[3], e2[3];
            sub3(R + 3 * i, R + 3 * j, e);
            sub3(P + 3 * i, P + 3 * j, e2);
            for (int r = 0; r < 3; r++)
                for (int c = 0; c < 3; c++) M[3 * r + c] += e2[r] * e[c];
        }
        if (t->VVs[i + 1] == t->VVs[i]) {
            memset(Q + 9 * i, 0, 9 * sizeof *Q);
            Q[9 * i] = Q[9 * i + 4] = Q[9 * i + 8] = 1;
        } else
            polar3(M, Q + 9 * i, Sm);
    }
}

void arap_fit_defaults(struct arap_fit_params *p)
{
    *p = (struct arap_fit_params){0};   /* every field set, the ones not named below 0 */
    p->iters = 30;
    p->inner = 1;
    p->mu_min = 0.1;
    p->mu_max = 30;
    p->backward = 1;
    p->max_angle = 60;
    p->max_dist = 0;
    p->search = 0;
    p->release_rings = 1;
    p->rest_smooth = 1;
    p->plane = 0.9;
    p->levels = 6;
    p->release_mean = 0;
}

/* the matrix L + mu I (upper triangle), L the edge graph Laplacian */
static cholmod_sparse *system_matrix(const struct topology *t, const int *isolated, double mu)
{
    struct triplets Q;
    triplets_init(&Q, t->nv, t->nv);
    for (int e = 0; e < t->ne; e++) {
        int i = t->E[2 * e], j = t->E[2 * e + 1];
        triplets_add(&Q, i, i, 1);
        triplets_add(&Q, j, j, 1);
        triplets_add(&Q, i, j, -1);
    }
    for (int i = 0; i < t->nv; i++) triplets_add(&Q, i, i, isolated[i] ? 1 : mu);
    cholmod_sparse *A = triplets_to_sparse(&Q, 1);
    triplets_free(&Q);
    return A;
}

int arap_fit(const double *R0, const int *F, int nv, int nf,
             const double *VT, const int *FT, int nvt, int nft,
             const struct closest_point_tree *TT, const struct arap_fit_params *p,
             double *P, arap_fit_step_fn cb, void *ctx)
{
    int rc = -1;
    struct topology ts = {0}, tt = {0};
    struct spd_solver *S = NULL;
    double *Rot = malloc(((size_t)nv * 9 + 1) * sizeof *Rot), *R = malloc(((size_t)nv * 3 + 1) * sizeof *R);
    double *NS = malloc(((size_t)nv * 3 + 1) * sizeof *NS), *NT = malloc(((size_t)nvt * 3 + 1) * sizeof *NT);
    double *U = malloc(((size_t)nv * 3 + 1) * sizeof *U), *UB = malloc(((size_t)nv * 3 + 1) * sizeof *UB);
    double *TC = malloc(((size_t)nvt * 3 + 1) * sizeof *TC), *TB = malloc(((size_t)nvt * 3 + 1) * sizeof *TB);
    double *G = malloc(((size_t)nv * 3 + 1) * sizeof *G), *Gw = malloc(((size_t)nv + 1) * sizeof *Gw);
    double *rhs = malloc(((size_t)nv * 3 + 1) * sizeof *rhs);
    int *UF = malloc(((size_t)nv + 1) * sizeof *UF), *TF = malloc(((size_t)nvt + 1) * sizeof *TF);
    int *iso = malloc(((size_t)nv + 1) * sizeof *iso);
    unsigned char *uok = malloc((size_t)nv + 1), *tok = malloc((size_t)nvt + 1);
    unsigned char *loose = calloc((size_t)nv + 1, 1), *loose2 = malloc((size_t)nv + 1);
    double *NR = malloc(((size_t)nf * 3 + 1) * sizeof *NR), *NP = malloc(((size_t)nf * 3 + 1) * sizeof *NP);
    double *DS = malloc(((size_t)nv + 1) * sizeof *DS);
    if (topology_build(F, nf, nv, &ts) < 0 || topology_build(FT, nft, nvt, &tt) < 0) goto done;
    for (int i = 0; i < nv; i++) iso[i] = ts.VFs[i + 1] == ts.VFs[i];
    /* the rest shape, smoothed: p_i <- (p_i + mean of its neighbours) / 2 */
    memcpy(R, R0, (size_t)nv * 3 * sizeof *R);
    if (!p->rest_keep) {
        if (umbrella_smooth(&ts, NULL, 0.5, p->rest_smooth, R) < 0) goto done;
    } else if (p->rest_smooth > 0) {
        /* rims kept, and every sweep inflated back (Taubin): the parts keep their size */
        unsigned char *inner = malloc((size_t)nv + 1);
        if (!inner) { cm_seterr("out of memory"); goto done; }
        memset(inner, 1, (size_t)nv);
        for (int e = 0; e < ts.ne; e++)
            if (ts.EFn[e] == 1) inner[ts.E[2 * e]] = inner[ts.E[2 * e + 1]] = 0;
        int bad = 0;
        for (int s = 0; s < p->rest_smooth && !bad; s++)
            bad = umbrella_smooth(&ts, inner, 0.5, 1, R) < 0 || umbrella_smooth(&ts, inner, -0.53, 1, R) < 0;
        free(inner);
        if (bad) goto done;
    }
    vertex_normals(VT, FT, nvt, nft, NT);
    face_normals(R, F, nf, NR);
    double cosmax = cos(p->max_angle * M_PI / 180);
    int K = p->iters < 1 ? 1 : p->iters;
    int levels = p->levels < 1 ? 1 : p->levels > K ? K : p->levels;
    double mu = 0;
    for (int k = 0; k < K; k++) {
        /* the data weight of this iteration's level; a new level refactors */
        int lev = (int)((long)k * levels / K);
        double mu_k = levels == 1 ? p->mu_max
                                  : p->mu_min * pow(p->mu_max / p->mu_min, (double)lev / (levels - 1));
        if (mu_k != mu) {
            mu = mu_k;
            cholmod_sparse *A = system_matrix(&ts, iso, mu);
            if (!A) goto done;
            if (!S) S = spd_factor(A);
            else if (spd_refactor(S, A) < 0) { spd_free(S); S = NULL; }
            sparse_free(&A);
            if (!S) {
                char m[512];
                snprintf(m, sizeof m, "%s", cm_errmsg());
                cm_seterr("ARAP fit, data weight %g: %s", mu, m);
                goto done;
            }
        }
        /* correspondences, mesh -> target: the goal of p_i is its closest
         * point u_i, moved back along the target's tangent plane by the
         * fraction 'plane' of the tangential offset (point-to-plane) */
        vertex_normals(P, F, nv, nf, NS);
        int rejected = correspond(TT, FT, NT, &tt, P, NS, nv, cosmax, p->max_dist, p->search, k > 0,
                                  U, UF, UB, uok);
        for (int i = 0; i < nv; i++) {
            double n[3], dv[3];
            Gw[i] = 0;
            memset(G + 3 * i, 0, 3 * sizeof *G);
            if (!uok[i] || loose[i] || iso[i]) continue;
            correspond_normal(NT, FT, UF[i], UB + 3 * i, n);
            double l = norm3(n);
            if (l > 0) for (int d = 0; d < 3; d++) n[d] /= l;
            sub3(P + 3 * i, U + 3 * i, dv);
            double dn = dot3(dv, n);
            for (int d = 0; d < 3; d++) G[3 * i + d] = U[3 * i + d] + p->plane * (dv[d] - dn * n[d]);
            Gw[i] = 1;
        }
        /* target -> mesh: target vertex t pulls the closest point c of the
         * mesh; each corner k of its face gets the goal p_k + (t - c) with
         * weight backward * b_k */
        if (p->backward > 0) {
            struct closest_point_tree *TS = closest_point_tree_new(P, nv, F, nf);
            if (!TS) goto done;
            correspond(TS, F, NS, &ts, VT, NT, nvt, cosmax, p->max_dist, p->search, k > 0, TC, TF, TB, tok);
            closest_point_tree_free(TS);
            double wb = p->backward * (double)nv / nvt;
            double tau = 0;
            if (p->overlay > 0) {
                for (int i = 0; i < nv; i++) DS[i] = dist3(P + 3 * i, U + 3 * i);
                tau = correspond_overlay_scale(P, U, uok, nv, ARAP_FIT_OVERLAY_TAU);
            }
            for (int j = 0; j < nvt; j++) {
                if (!tok[j] || tt.VFs[j + 1] == tt.VFs[j]) continue;
                if (correspond_overlay(F, TF[j], TB + 3 * j, DS, dist3(VT + 3 * j, TC + 3 * j),
                                       p->overlay, tau))
                    continue;
                for (int a = 0; a < 3; a++) {
                    int v = F[3 * TF[j] + a];
                    double w = wb * TB[3 * j + a];
                    if (loose[v] || iso[v] || !(w > 0)) continue;
                    for (int d = 0; d < 3; d++)
                        G[3 * v + d] += w * (P[3 * v + d] + VT[3 * j + d] - TC[3 * j + d]);
                    Gw[v] += w;
                }
            }
        }
        /* every vertex ends with one goal of weight mu (the matrix stays
         * L + mu I): the weighted mean of its goals, or its own position
         * when it has none (rejected, released); with release_mean a
         * released vertex the mean of its neighbours instead */
        for (int i = 0; i < nv; i++) {
            if (p->release_mean && loose[i] && !iso[i] && !(Gw[i] > 0)) {
                double a[3] = {0, 0, 0}, w = 1.0 / (ts.VVs[i + 1] - ts.VVs[i]);
                for (int q = ts.VVs[i]; q < ts.VVs[i + 1]; q++)
                    for (int d = 0; d < 3; d++) a[d] += P[3 * ts.VV[q] + d];
                for (int d = 0; d < 3; d++) G[3 * i + d] = a[d] * w;
                continue;
            }
            for (int d = 0; d < 3; d++)
                G[3 * i + d] = Gw[i] > 0 ? G[3 * i + d] / Gw[i] : P[3 * i + d];
        }
        for (int it = 0; it < p->inner; it++) {
            /* local step: the rotation of every one-ring, rest -> pose */
            arap_ring_rotations(&ts, R, P, nv, Rot);
            /* global step: (L + mu I) P = ARAP term + mu G */
            for (int i = 0; i < nv; i++)
                for (int d = 0; d < 3; d++) rhs[3 * i + d] = (iso[i] ? 1 : mu) * G[3 * i + d];
            for (int e = 0; e < ts.ne; e++) {
                int i = ts.E[2 * e], j = ts.E[2 * e + 1];
                double r[3];
                sub3(R + 3 * i, R + 3 * j, r);
                for (int d = 0; d < 3; d++) {
                    double g = 0;
                    for (int c = 0; c < 3; c++)
                        g += 0.5 * (Rot[9 * i + 3 * d + c] + Rot[9 * j + 3 * d + c]) * r[c];
                    rhs[3 * i + d] += g;
                    rhs[3 * j + d] -= g;
                }
            }
            if (spd_solve(S, rhs, P, 3) < 0) goto done;
        }
        /* folds: faces whose normal points against their rest normal turned
         * by the mean rotation of their corners; their vertices and rings
         * around them go without data terms next time, so the rotations
         * unfold them */
        face_normals(P, F, nf, NP);
        memset(loose, 0, nv);
        int nfold = 0;
        for (int f = 0; f < nf; f++) {
            double m[3] = {0, 0, 0};
            for (int c = 0; c < 3; c++) {
                const double *Q = Rot + 9 * F[3 * f + c], *r = NR + 3 * f;
                for (int d = 0; d < 3; d++) m[d] += Q[3 * d] * r[0] + Q[3 * d + 1] * r[1] + Q[3 * d + 2] * r[2];
            }
            if (dot3(m, NP + 3 * f) < 0) {
                nfold++;
                for (int c = 0; c < 3; c++) loose[F[3 * f + c]] = 1;
            }
        }
        for (int g = 0; g < p->release_rings; g++) {
            memcpy(loose2, loose, nv);
            for (int i = 0; i < nv; i++)
                if (loose2[i]) for (int q = ts.VVs[i]; q < ts.VVs[i + 1]; q++) loose[ts.VV[q]] = 1;
        }
        if (cb && cb(ctx, k, mu, rejected, nfold, P)) break;
    }
    rc = 0;
done:
    spd_free(S);
    topology_free(&ts);
    topology_free(&tt);
    free(Rot); free(R); free(NS); free(NT); free(U); free(UB); free(TC); free(TB); free(G); free(Gw);
    free(rhs); free(UF); free(TF); free(iso); free(uok); free(tok); free(loose); free(loose2);
    free(NR); free(NP); free(DS);
    return rc;
}
