/* nricp.c -- see nricp.h */
#include "nricp.h"
#include "arap_fit.h"
#include "closest_point.h"
#include "correspond.h"
#include "cm_error.h"
#include "geometry.h"
#include "mesh_distance.h"
#include "mesh_clean.h"
#include "nricp_untangle.h"
#include "patch_unflip.h"
#include "procrustes.h"
#include "spd.h"
#include "topology.h"
#include <stdio.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void nricp_defaults(struct nricp_params *p)
{
    *p = (struct nricp_params){0};   /* every field set, the ones not named below 0 */
    p->steps = 6;
    p->alpha_max = 50;
    p->alpha_min = 0.5;
    p->beta = 10;
    p->gamma = 1;
    p->max_angle = 60;
    p->max_dist = 0.1;
    p->backward = 1;
    p->eps = 1e-4;
    p->max_inner = 1;
    p->fit = 30;
    p->fit_smooth = 1;
    p->search = 0.01;
    p->fit_weight = 30;
    p->nearest_vertex = 0;
    p->rigid = 0;
    p->rigid_iters = 4;
    p->untangle = 1;
    p->unflip = 2;
    p->fit_release = 0;
    p->coarse = 0;
    p->fine_steps = 2;
    p->rigid_const = 0;
    p->parts = -1;
    p->overlay = 0.5;
    p->small_parts = 0.1;
}

int nricp_small_parts(const double *R, const int *F, int nv, int nf, double frac, double *P)
{
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0) return -1;
    int *cf = malloc(((size_t)nf + 1) * sizeof *cf), *cv = malloc(((size_t)nv + 1) * sizeof *cv);
    int nc = cf && cv ? connected_components(&t, F, cf) : -1;
    topology_free(&t);
    if (nc < 0) { free(cf); free(cv); return cm_seterr("out of memory"); }
    for (int v = 0; v < nv; v++) cv[v] = -1;
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) cv[F[3 * f + k]] = cf[f];
    int *cnt = calloc((size_t)nc + 1, sizeof *cnt), *grp = malloc(((size_t)nc + 1) * sizeof *grp);
    unsigned char *small = malloc((size_t)nc + 1);
    double *box = malloc(((size_t)nc * 6 + 1) * sizeof *box);
    int *idx = malloc(((size_t)nv + 1) * sizeof *idx);
    double *A = malloc(((size_t)nv * 3 + 1) * sizeof *A), *B = malloc(((size_t)nv * 3 + 1) * sizeof *B);
    int ng = -1;
    if (!cnt || !grp || !small || !box || !idx || !A || !B) { cm_seterr("out of memory"); goto done; }
    for (int c = 0; c < nc; c++) {
        for (int d = 0; d < 3; d++) { box[6 * c + d] = INFINITY; box[6 * c + 3 + d] = -INFINITY; }
        grp[c] = c;
    }
    for (int v = 0; v < nv; v++) {
        int c = cv[v];
        if (c < 0) continue;
        cnt[c]++;
        for (int d = 0; d < 3; d++) {
            if (R[3 * v + d] < box[6 * c + d]) box[6 * c + d] = R[3 * v + d];
            if (R[3 * v + d] > box[6 * c + 3 + d]) box[6 * c + 3 + d] = R[3 * v + d];
        }
    }
    /* small: a box diagonal of at most frac of the source's, or at most
     * frac of its vertices (too few to carry a deformation of their own); small
     * components whose boxes come within the gap: one group (union-find) */
    double diag = bbox_diagonal(R, nv), gap = SMALL_PARTS_GAP * diag;
    for (int c = 0; c < nc; c++) {
        double e2 = 0;
        for (int d = 0; d < 3; d++) e2 += (box[6 * c + 3 + d] - box[6 * c + d]) * (box[6 * c + 3 + d] - box[6 * c + d]);
        small[c] = cnt[c] > 0 && (sqrt(e2) <= frac * diag || cnt[c] <= frac * nv);
    }
    for (int a = 0; a < nc; a++) {
        if (!small[a]) continue;
        for (int b = a + 1; b < nc; b++) {
            if (!small[b]) continue;
            int near = 1;
            for (int d = 0; d < 3 && near; d++)
                near = box[6 * a + d] - gap <= box[6 * b + 3 + d] && box[6 * b + d] - gap <= box[6 * a + 3 + d];
            if (!near) continue;
            int ra = a, rb = b;
            while (grp[ra] != ra) ra = grp[ra];
            while (grp[rb] != rb) rb = grp[rb];
            if (ra != rb) grp[ra > rb ? ra : rb] = ra < rb ? ra : rb;
        }
    }
    ng = 0;
    for (int g = 0; g < nc; g++) {
        if (grp[g] != g || !small[g]) continue;
        int n = 0;
        for (int v = 0; v < nv; v++) {
            int c = cv[v];
            if (c < 0) continue;
            while (grp[c] != c) c = grp[c];
            if (c != g) continue;
            idx[n] = v;
            memcpy(A + 3 * n, R + 3 * v, 3 * sizeof *A);
            memcpy(B + 3 * n, P + 3 * v, 3 * sizeof *B);
            n++;
        }
        if (n < 3) continue;
        double Rm[9], tv[3];
        if (procrustes(A, B, NULL, n, 0, Rm, tv, NULL) < 0) { ng = -1; goto done; }
        similarity_apply(Rm, tv, 1, A, n, A);
        for (int k = 0; k < n; k++) memcpy(P + 3 * idx[k], A + 3 * k, 3 * sizeof *P);
        ng++;
    }
done:
    free(cf); free(cv); free(cnt); free(grp); free(small); free(box); free(idx); free(A); free(B);
    return ng;
}

/* right-hand side of the ARAP edge rows: w ([v_i 1] X_i - [v_j 1] X_j)
 * = w (Q_i + Q_j)/2 (r_i - r_j), added to B (4n by 3) */
static void rigid_rhs(const struct topology *t, const double *V, const double *R, const double *Q,
                      double w, double *B)
{
    for (int e = 0; e < t->ne; e++) {
        int i = t->E[2 * e], j = t->E[2 * e + 1];
        double r[3], g[3];
        sub3(R + 3 * i, R + 3 * j, r);
        for (int d = 0; d < 3; d++) {
            g[d] = 0;
            for (int c = 0; c < 3; c++) g[d] += 0.5 * (Q[9 * i + 3 * d + c] + Q[9 * j + 3 * d + c]) * r[c];
        }
        const double *vi = V + 3 * i, *vj = V + 3 * j;
        for (int d = 0; d < 3; d++) {
            for (int c = 0; c < 3; c++) {
                B[(size_t)(4 * i + c) * 3 + d] += w * vi[c] * g[d];
                B[(size_t)(4 * j + c) * 3 + d] -= w * vj[c] * g[d];
            }
            B[(size_t)(4 * i + 3) * 3 + d] += w * g[d];
            B[(size_t)(4 * j + 3) * 3 + d] -= w * g[d];
        }
    }
}

/* The normal matrix lives in a fixed pattern: a full 4x4 block for every
 * vertex and every edge (upper triangle only, stype 1), so every iteration
 * only rewrites values and refactors numerically. */
struct system {
    int n;                 /* #V */
    cholmod_sparse *A;     /* 4n by 4n, upper */
    int *colblk;           /* for column 4j+s: start of its entries */
    int *nbs, *nb;         /* CSR: for vertex j the sorted vertices i <= j of its blocks */
};

static int system_new(struct system *S, const struct topology *t, int n)
{
    S->n = n;
    S->nbs = malloc((n + 1) * sizeof *S->nbs);
    int cnt = 0;
    for (int j = 0; j < n; j++) {
        S->nbs[j] = cnt;
        for (int q = t->VVs[j]; q < t->VVs[j + 1]; q++) cnt += t->VV[q] < j;
        cnt++;
    }
    S->nbs[n] = cnt;
    S->nb = malloc((cnt + 1) * sizeof *S->nb);
    for (int j = 0; j < n; j++) {
        int k = S->nbs[j];
        for (int q = t->VVs[j]; q < t->VVs[j + 1]; q++)
            if (t->VV[q] < j) S->nb[k++] = t->VV[q];   /* VV is sorted */
        S->nb[k++] = j;
    }
    size_t nnz = 0;
    for (int j = 0; j < n; j++) {
        int m = S->nbs[j + 1] - S->nbs[j] - 1;   /* blocks above the diagonal */
        nnz += 4 * (size_t)(4 * m) + 10;
    }
    cholmod_common *c = cm_cholmod();
    S->A = cholmod_allocate_sparse(4 * n, 4 * n, nnz, 1, 1, 1, CHOLMOD_REAL, c);
    if (!S->A) return cm_seterr("out of memory for the NRICP system");
    int *Ap = S->A->p, *Ai = S->A->i;
    size_t pos = 0;
    for (int j = 0; j < n; j++)
        for (int s = 0; s < 4; s++) {
            Ap[4 * j + s] = (int)pos;
            for (int k = S->nbs[j]; k < S->nbs[j + 1]; k++) {
                int i = S->nb[k];
                int rmax = i < j ? 4 : s + 1;
                for (int r = 0; r < rmax; r++) Ai[pos++] = 4 * i + r;
            }
        }
    Ap[4 * n] = (int)pos;
    return 0;
}

static void system_free(struct system *S)
{
    if (S->A) cholmod_free_sparse(&S->A, cm_cholmod());
    free(S->nbs);
    free(S->nb);
}

/* pointer to entry (4i + r, 4j + s) with i <= j (r <= s if i == j) */
static double *entry(struct system *S, int i, int j, int r, int s)
{
    int lo = S->nbs[j], hi = S->nbs[j + 1] - 1;
    while (lo < hi) {
        int mid = (lo + hi) / 2;
        if (S->nb[mid] < i) lo = mid + 1; else hi = mid;
    }
    int rank = lo - S->nbs[j];
    int *Ap = S->A->p;
    return (double *)S->A->x + Ap[4 * j + s] + 4 * rank + r;
}

/* add w * a a^T for a row a with up to 3 vertices vi (coefficients b_k times [v 1]) */
static void add_row(struct system *S, double *B, const int *vi, const double *bk, int m,
                    const double *V, double w, const double *target)
{
    double a[3][4];
    for (int k = 0; k < m; k++) {
        const double *v = V + 3 * vi[k];
        a[k][0] = bk[k] * v[0]; a[k][1] = bk[k] * v[1]; a[k][2] = bk[k] * v[2]; a[k][3] = bk[k];
    }
    for (int p = 0; p < m; p++)
        for (int q = 0; q < m; q++) {
            int i = vi[p], j = vi[q];
            if (i > j) continue;
            for (int r = 0; r < 4; r++)
                for (int s = 0; s < 4; s++) {
                    if (i == j && r > s) continue;
                    *entry(S, i, j, r, s) += w * a[p][r] * a[q][s];
                }
        }
    for (int p = 0; p < m; p++)
        for (int r = 0; r < 4; r++)
            for (int d = 0; d < 3; d++) B[(size_t)(4 * vi[p] + r) * 3 + d] += w * a[p][r] * target[d];
}

/* reports the ARAP fit's iterations as steps K, K+1, ... */
struct fit_ctx {
    nricp_step_fn cb;
    void *ctx;
    int K;
    double sc;
    const double *c;
    int nv;
    double *X;
};

static int fit_step(void *ctx, int iter, double mu, int rejected, int folded, const double *P)
{
    struct fit_ctx *f = ctx;
    for (int i = 0; i < f->nv; i++)
        for (int d = 0; d < 3; d++) f->X[3 * i + d] = P[3 * i + d] * f->sc + f->c[d];
    f->cb(f->ctx, f->K + iter, mu, 0, 0, rejected, folded, f->X);
    return 0;
}

/* The coarse level of the coarse-to-fine schedule: every vertex of the
 * fine source in a face of the coarse one (its closest point there), so
 * the coarse affine maps, blended by the barycentrics, carry the fine
 * vertices. */
struct coarse_map {
    int nv;                /* fine vertices */
    const double *V;       /* #V by 3 fine start (normalized) */
    const int *FC;         /* coarse faces */
    int *face;             /* #V coarse face of each fine vertex */
    double *bary;          /* #V by 3 */
};

/* P (#V by 3, out): the fine vertices moved by the coarse maps XC (4 #VC by 3) */
static void coarse_apply(const struct coarse_map *m, const double *XC, double *P)
{
    for (int i = 0; i < m->nv; i++) {
        const int *f = m->FC + 3 * m->face[i];
        const double *b = m->bary + 3 * i, *v = m->V + 3 * i;
        double M[12] = {0};
        for (int k = 0; k < 3; k++)
            for (int q = 0; q < 12; q++) M[q] += b[k] * XC[12 * (size_t)f[k] + q];
        for (int d = 0; d < 3; d++)
            P[3 * i + d] = v[0] * M[d] + v[1] * M[3 + d] + v[2] * M[6 + d] + M[9 + d];
    }
}

/* what the stiffness steps share at every level: the target (normalized),
 * its topology, tree and normals, the landmarks, the parameters, the report */
struct target_side {
    const double *VT, *NT;
    const int *FT;
    int nvt, nft;
    const struct topology *tt;
    const struct closest_point_tree *TT;
    const double *LD;      /* nl by 3 landmark positions */
    int nl;
    const struct nricp_params *p;
    nricp_step_fn cb;
    void *ctx;
    double sc;
    const double *c;
    double *Xout;          /* #V (fine) by 3, the report's buffer */
    int nout;              /* fine vertices */
    double overlay;        /* the overlay ratio of the backward pairs (0: the source has no parts) */
};

/* The stiffness steps k0 .. k1 - 1 of the schedule on one level: source VS
 * (#VS by 3, normalized) with faces FS, rest Rr of the rigid term; landmark
 * l is the row sum_k lm_b[l][k] p(lm_v[l][k]) (one vertex with weight 1 at
 * the fine level, a point of a face at the coarse one).  P (#VS by 3): in
 * the start, out the deformed source; X (4 #VS by 3, out): the last maps.
 * cm (coarse level) carries every step's maps to the fine vertices for the
 * report.  Returns 0, 1 when the report asked to stop, -1 on error. */
static int run_stages(const double *VS, const double *Rr, const int *FS, int nvs, int nfs,
                      const int *lm_v, const double *lm_b, int lm_m, const struct target_side *T,
                      int k0, int k1, const struct coarse_map *cm, double *P, double *X)
{
    const struct nricp_params *p = T->p;
    const double *VT = T->VT, *NT = T->NT;
    const int *FT = T->FT;
    int nvt = T->nvt, nl = T->nl;
    int rc = -1;
    struct topology ts = {0};
    struct system S = {0};
    struct spd_solver *L = NULL;
    double *B = malloc(((size_t)nvs * 12 + 1) * sizeof *B);
    double *Pold = malloc(((size_t)nvs * 3 + 1) * sizeof *Pold);
    double *NS = malloc(((size_t)nvs * 3 + 1) * sizeof *NS);
    double *U = malloc(((size_t)nvs * 3 + 1) * sizeof *U), *UB = malloc(((size_t)nvs * 3 + 1) * sizeof *UB);
    int *UF = malloc(((size_t)nvs + 1) * sizeof *UF);
    double *TB = malloc(((size_t)nvt * 3 + 1) * sizeof *TB), *TC = malloc(((size_t)nvt * 3 + 1) * sizeof *TC);
    int *TF = malloc(((size_t)nvt + 1) * sizeof *TF);
    unsigned char *uok = malloc((size_t)nvs + 1), *tok = malloc((size_t)nvt + 1);
    double *Q = p->rigid > 0 ? malloc(((size_t)nvs * 9 + 1) * sizeof *Q) : NULL;
    double *B0 = p->rigid > 0 ? malloc(((size_t)nvs * 12 + 1) * sizeof *B0) : NULL;
    double *PF = cm ? malloc(((size_t)cm->nv * 3 + 1) * sizeof *PF) : NULL;
    double *DS = malloc(((size_t)nvs + 1) * sizeof *DS);   /* each vertex's distance to the target */
    if (!B || !Pold || !NS || !U || !UB || !UF || !TB || !TC || !TF || !uok || !tok || !DS ||
        (p->rigid > 0 && (!Q || !B0)) || (cm && !PF)) {
        cm_seterr("out of memory");
        goto done;
    }
    if (topology_build(FS, nfs, nvs, &ts) < 0) goto done;
    if (system_new(&S, &ts, nvs) < 0) goto done;
    for (int i = 0; i < nvs; i++) {
        memset(X + 12 * (size_t)i, 0, 12 * sizeof *X);
        X[12 * i + 0] = 1; X[12 * i + 4] = 1; X[12 * i + 8] = 1;
    }
    double cosmax = cos(p->max_angle * M_PI / 180);
    double g2[4] = {1, 1, 1, p->gamma * p->gamma};
    int K = p->steps < 1 ? 1 : p->steps;
    int first = 1;
    for (int k = k0; k < k1; k++) {
        double alpha = K == 1 ? p->alpha_max
                              : p->alpha_max * pow(p->alpha_min / p->alpha_max, (double)k / (K - 1));
        double beta = K == 1 ? 0 : p->beta * (1 - (double)k / (K - 1));
        int inner, rejected = 0;
        for (inner = 0; inner < p->max_inner; inner++) {
            /* correspondences, source -> target */
            vertex_normals(P, FS, nvs, nfs, NS);
            rejected = correspond(T->TT, FT, NT, T->tt, P, NS, nvs, cosmax, p->max_dist, p->search, !first,
                                  U, UF, UB, uok);
            if (p->nearest_vertex)
                for (int i = 0; i < nvs; i++) {
                    int best = 0;
                    for (int q = 1; q < 3; q++) if (UB[3 * i + q] > UB[3 * i + best]) best = q;
                    memcpy(U + 3 * i, VT + 3 * FT[3 * UF[i] + best], 3 * sizeof *U);
                }
            memset(S.A->x, 0, S.A->nzmax * sizeof(double));
            memset(B, 0, (size_t)nvs * 12 * sizeof *B);
            for (int i = 0; i < nvs; i++) {
                if (!uok[i] || ts.VFs[i + 1] == ts.VFs[i]) { rejected += uok[i]; continue; }
                double one = 1;
                add_row(&S, B, &i, &one, 1, VS, 1, U + 3 * i);
            }
            /* target -> source: each target vertex pulls the closest point of the source */
            if (p->backward > 0) {
                struct closest_point_tree *TS = closest_point_tree_new(P, nvs, FS, nfs);
                if (!TS) goto done;
                correspond(TS, FS, NS, &ts, VT, NT, nvt, cosmax, p->max_dist, p->search, !first, TC, TF, TB, tok);
                closest_point_tree_free(TS);
                double wb = p->backward * (double)nvs / nvt;
                /* with parts: no pull from target surface lying over source that
                 * already fits (correspond_overlay) */
                double tau = 0;
                if (T->overlay > 0) {
                    for (int i = 0; i < nvs; i++) DS[i] = dist3(P + 3 * i, U + 3 * i);
                    tau = correspond_overlay_scale(P, U, uok, nvs, OVERLAY_TAU);
                }
                for (int j = 0; j < nvt; j++)
                    if (tok[j] && T->tt->VFs[j + 1] > T->tt->VFs[j] &&
                        !correspond_overlay(FS, TF[j], TB + 3 * j, DS, dist3(VT + 3 * j, TC + 3 * j),
                                            T->overlay, tau))
                        add_row(&S, B, FS + 3 * TF[j], TB + 3 * j, 3, VS, wb, VT + 3 * j);
            }
            /* landmarks */
            for (int l = 0; l < nl && beta > 0; l++)
                add_row(&S, B, lm_v + lm_m * l, lm_b + lm_m * l, lm_m, VS, beta * beta, T->LD + 3 * l);
            /* stiffness */
            double a2 = alpha * alpha;
            for (int e = 0; e < ts.ne; e++) {
                int i = ts.E[2 * e], j = ts.E[2 * e + 1];      /* i < j */
                double w = a2;
                for (int r = 0; r < 4; r++) {
                    *entry(&S, i, i, r, r) += w * g2[r];
                    *entry(&S, j, j, r, r) += w * g2[r];
                    *entry(&S, i, j, r, r) -= w * g2[r];
                }
            }
            /* a tiny pull toward the identity map keeps pieces without any
             * correspondence (and isolated vertices) determined */
            for (int i = 0; i < nvs; i++) {
                double wreg = ts.VFs[i + 1] == ts.VFs[i] ? 1 : 1e-8;
                for (int r = 0; r < 4; r++) {
                    *entry(&S, i, i, r, r) += wreg;
                    if (r < 3) B[(size_t)(4 * i + r) * 3 + r] += wreg;
                }
            }
            /* as rigid as possible: edge rows ([v_i 1] X_i - [v_j 1] X_j)
             * toward the rest edge turned by the rings' rotations */
            double wr = p->rigid_const ? p->rigid : p->rigid * alpha / p->alpha_max;
            if (Q && wr > 0) {
                double bk[2] = {1, -1}, zero[3] = {0, 0, 0};
                for (int e = 0; e < ts.ne; e++)
                    add_row(&S, B, ts.E + 2 * e, bk, 2, VS, wr, zero);
                memcpy(B0, B, (size_t)nvs * 12 * sizeof *B);
                arap_ring_rotations(&ts, Rr, P, nvs, Q);
                rigid_rhs(&ts, VS, Rr, Q, wr, B);
            }
            first = 0;
            /* same pattern every time: analysis once, numeric refactor after */
            if (!L) L = spd_factor(S.A);
            else if (spd_refactor(L, S.A) < 0) { spd_free(L); L = NULL; }
            if (!L) {
                char m[512];
                snprintf(m, sizeof m, "%s", cm_errmsg());
                cm_seterr("stiffness step %d (alpha %g): %s", k + 1, alpha, m);
                goto done;
            }
            memcpy(Pold, P, (size_t)nvs * 3 * sizeof *P);
            int nr = Q && wr > 0 ? (p->rigid_iters > 0 ? p->rigid_iters : 1) : 1;
            for (int it = 0; it < nr; it++) {
                if (it > 0) {
                    /* ARAP local step on the new pose, the same factorization */
                    arap_ring_rotations(&ts, Rr, P, nvs, Q);
                    memcpy(B, B0, (size_t)nvs * 12 * sizeof *B);
                    rigid_rhs(&ts, VS, Rr, Q, wr, B);
                }
                if (spd_solve(L, B, X, 3) < 0) goto done;
                for (int i = 0; i < nvs; i++) {
                    const double *v = VS + 3 * i, *x = X + 12 * i;
                    for (int d = 0; d < 3; d++)
                        P[3 * i + d] = v[0] * x[d] + v[1] * x[3 + d] + v[2] * x[6 + d] + x[9 + d];
                }
            }
            double ch = 0;
            for (int i = 0; i < 3 * nvs; i++) ch += (P[i] - Pold[i]) * (P[i] - Pold[i]);
            if (sqrt(ch / nvs) < p->eps) { inner++; break; }
        }
        if (T->cb) {
            const double *PP = P;
            if (cm) { coarse_apply(cm, X, PF); PP = PF; }
            for (int i = 0; i < T->nout; i++)
                for (int d = 0; d < 3; d++) T->Xout[3 * i + d] = PP[3 * i + d] * T->sc + T->c[d];
            if (T->cb(T->ctx, k, alpha, beta, inner, rejected, -1, T->Xout)) { rc = 1; goto done; }
        }
    }
    rc = 0;
done:
    spd_free(L);
    system_free(&S);
    topology_free(&ts);
    free(B); free(Pold); free(NS); free(U); free(UB); free(UF); free(TB); free(TC); free(TF);
    free(uok); free(tok); free(Q); free(B0); free(PF); free(DS);
    return rc;
}

/* The coarse level: SOURCE remeshed isotropically to p->coarse diagonals
 * (mesh_clean.h, CGAL), every fine vertex mapped to its closest point on it.
 * Returns 0, 1 when the remeshing fails or does not coarsen (the schedule
 * then runs on SOURCE alone), or -1 out of memory (cm_errmsg). */
static int coarse_build(const double *VS, const int *FS, int nvs, int nfs, double edge,
                        double **VC, int *nvc, int **FC, int *nfc, struct coarse_map *m)
{
    struct mesh_clean_opts o = {0};
    o.fill_holes = 0;
    o.edge_length = edge;
    o.iterations = 3;
    struct mesh_clean_report rep;
    *VC = NULL; *FC = NULL;
    if (mesh_clean(VS, nvs, FS, nfs, &o, VC, nvc, FC, nfc, &rep) < 0 || *nfc < 4 || *nvc >= nvs) {
        free(*VC); free(*FC);
        *VC = NULL; *FC = NULL;
        return 1;
    }
    struct closest_point_tree *CT = closest_point_tree_new(*VC, *nvc, *FC, *nfc);
    if (!CT) { free(*VC); free(*FC); *VC = NULL; *FC = NULL; return 1; }
    m->nv = nvs;
    m->V = VS;
    m->FC = *FC;
    m->face = malloc(((size_t)nvs + 1) * sizeof *m->face);
    m->bary = malloc(((size_t)nvs * 3 + 1) * sizeof *m->bary);
    if (!m->face || !m->bary) {
        closest_point_tree_free(CT);
        free(m->face); free(m->bary); m->face = NULL; m->bary = NULL;
        free(*VC); free(*FC); *VC = NULL; *FC = NULL;
        return cm_seterr("out of memory (the coarse level's map of %d vertices)", nvs);
    }
    closest_points(CT, VS, nvs, NULL, m->face, m->bary, NULL);
    closest_point_tree_free(CT);
    return 0;
}

int nricp_register(const double *VS0, const double *RS0, const int *FS, int nvs, int nfs,
                   const double *VT0, const int *FT, int nvt, int nft,
                   const int *lm_src, const double *lm_dst0, int nl,
                   const struct nricp_params *p, double *Xout, nricp_step_fn cb, void *ctx)
{
    int rc = -1;
    for (int l = 0; l < nl; l++)
        if (lm_src[l] < 0 || lm_src[l] >= nvs)
            return cm_seterr("landmark %d: source vertex %d out of range 0..%d", l + 1, lm_src[l], nvs - 1);
    /* normalize: centre and diagonal of the target */
    double lo[3], hi[3], c[3];
    bounding_box(VT0, nvt, lo, hi);
    double sc = bbox_diagonal(VT0, nvt);
    if (!(sc > 0)) return cm_seterr("the target is a single point");
    for (int d = 0; d < 3; d++) c[d] = 0.5 * (lo[d] + hi[d]);
    double *VS = malloc((size_t)nvs * 3 * sizeof *VS + 1), *VT = malloc((size_t)nvt * 3 * sizeof *VT + 1);
    double *LD = malloc((size_t)nl * 3 * sizeof *LD + 1);
    double *RS = RS0 ? malloc((size_t)nvs * 3 * sizeof *RS + 1) : NULL;
    if (!VS || !VT || !LD || (RS0 && !RS)) {
        free(VS); free(VT); free(LD); free(RS);
        return cm_seterr("out of memory (registering %d onto %d vertices)", nvs, nvt);
    }
    for (int i = 0; i < nvs; i++) for (int d = 0; d < 3; d++) VS[3 * i + d] = (VS0[3 * i + d] - c[d]) / sc;
    for (int i = 0; i < nvt; i++) for (int d = 0; d < 3; d++) VT[3 * i + d] = (VT0[3 * i + d] - c[d]) / sc;
    for (int i = 0; i < nl; i++) for (int d = 0; d < 3; d++) LD[3 * i + d] = (lm_dst0[3 * i + d] - c[d]) / sc;
    if (RS0) {
        for (int i = 0; i < nvs; i++) for (int d = 0; d < 3; d++) RS[3 * i + d] = (RS0[3 * i + d] - c[d]) / sc;
    }

    struct topology tt = {0};
    struct closest_point_tree *TT = NULL;
    double *X = malloc(((size_t)nvs * 12 + 1) * sizeof *X);          /* 4n by 3 */
    double *P = malloc(((size_t)nvs * 3 + 1) * sizeof *P);
    double *NT = malloc(((size_t)nvt * 3 + 1) * sizeof *NT);
    double *lm_b = malloc(((size_t)nl * 3 + 1) * sizeof *lm_b);
    int *lm_v = malloc(((size_t)nl * 3 + 1) * sizeof *lm_v);
    double *VC = NULL, *RC = NULL, *XC = NULL, *PC = NULL;
    int *FC = NULL, nvc = 0, nfc = 0;
    struct coarse_map cm = {0};
    const double *Rr = RS ? RS : VS;   /* rest shape of the ARAP term */
    if (!X || !P || !NT || !lm_b || !lm_v) {
        cm_seterr("out of memory (registering %d onto %d vertices)", nvs, nvt);
        goto done;
    }
    if (topology_build(FT, nft, nvt, &tt) < 0) goto done;
    TT = closest_point_tree_new(VT, nvt, FT, nft);
    if (!TT) goto done;
    vertex_normals(VT, FT, nvt, nft, NT);
    memcpy(P, VS, (size_t)nvs * 3 * sizeof *P);
    int K = p->steps < 1 ? 1 : p->steps;
    /* a source with parts (holes, several components): the precautions */
    int parts = p->parts;
    if (parts < 0) {
        struct topology tsrc;
        if (topology_build(FS, nfs, nvs, &tsrc) < 0) goto done;
        parts = correspond_parts(&tsrc, FS);
        topology_free(&tsrc);
        if (parts < 0) goto done;
    }
    struct target_side ts = {VT, NT, FT, nvt, nft, &tt, TT, LD, nl, p, cb, ctx, sc, c, Xout, nvs,
                             parts ? p->overlay : 0};
    /* coarse to fine: the stiff steps on SOURCE remeshed coarser, the last
     * fine_steps on SOURCE itself, from the coarse maps blended */
    int kf = 0;
    int coarse = p->coarse > 0 && K > 1 ? coarse_build(VS, FS, nvs, nfs, p->coarse, &VC, &nvc, &FC, &nfc, &cm)
                                        : 1;
    if (coarse < 0) goto done;
    if (coarse == 0) {
        kf = K - (p->fine_steps < 0 ? 0 : p->fine_steps >= K ? K - 1 : p->fine_steps);
        /* landmarks: the coarse face point under each landmark vertex */
        for (int l = 0; l < nl; l++) {
            int i = lm_src[l];
            for (int k = 0; k < 3; k++) {
                lm_v[3 * l + k] = FC[3 * cm.face[i] + k];
                lm_b[3 * l + k] = cm.bary[3 * i + k];
            }
        }
        /* the rigid term's rest: the fine rest at each coarse vertex's
         * closest point of the fine start */
        const double *Rc = VC;
        if (RS && p->rigid > 0) {
            struct closest_point_tree *FTr = closest_point_tree_new(VS, nvs, FS, nfs);
            if (!FTr) goto done;
            int *fi = malloc(((size_t)nvc + 1) * sizeof *fi);
            double *bi = malloc(((size_t)nvc * 3 + 1) * sizeof *bi);
            RC = malloc(((size_t)nvc * 3 + 1) * sizeof *RC);
            if (!fi || !bi || !RC) {
                closest_point_tree_free(FTr);
                free(fi); free(bi);
                cm_seterr("out of memory (the coarse level's rest of %d vertices)", nvc);
                goto done;
            }
            closest_points(FTr, VC, nvc, NULL, fi, bi, NULL);
            closest_point_tree_free(FTr);
            for (int v = 0; v < nvc; v++)
                for (int d = 0; d < 3; d++) {
                    RC[3 * v + d] = 0;
                    for (int k = 0; k < 3; k++)
                        RC[3 * v + d] += bi[3 * v + k] * RS[3 * FS[3 * fi[v] + k] + d];
                }
            free(fi); free(bi);
            Rc = RC;
        }
        if (cb) cb(ctx, 0, 0, 0, nvc, nfc, -3, NULL);
        XC = malloc(((size_t)nvc * 12 + 1) * sizeof *XC);
        PC = malloc(((size_t)nvc * 3 + 1) * sizeof *PC);
        if (!XC || !PC) {
            cm_seterr("out of memory (the coarse level's %d vertices)", nvc);
            goto done;
        }
        memcpy(PC, VC, (size_t)nvc * 3 * sizeof *PC);
        int r = run_stages(VC, Rc, FC, nvc, nfc, lm_v, lm_b, 3, &ts, 0, kf, &cm, PC, XC);
        if (r < 0) goto done;
        coarse_apply(&cm, XC, P);
        if (r > 0) kf = K;     /* the report stopped the schedule */
    }
    if (kf < K) {
        for (int l = 0; l < nl; l++) { lm_v[l] = lm_src[l]; lm_b[l] = 1; }
        int r = run_stages(VS, Rr, FS, nvs, nfs, lm_v, lm_b, 1, &ts, kf, K, NULL, P, X);
        if (r < 0) goto done;
    }
    /* the ARAP fit: unfolds what the affine maps folded (arap_fit.h) */
    if (p->fit > 0) {
        struct fit_ctx fc = {cb, ctx, K, sc, c, nvs, Xout};
        struct arap_fit_params ap;
        arap_fit_defaults(&ap);
        ap.iters = p->fit;
        ap.mu_max = p->fit_weight;
        if (ap.mu_min > ap.mu_max) ap.mu_min = ap.mu_max;
        ap.backward = p->backward;
        ap.max_angle = p->max_angle;
        ap.max_dist = p->max_dist;
        ap.search = p->search;
        ap.rest_smooth = p->fit_smooth;
        ap.release_mean = p->fit_release;
        ap.overlay = parts ? p->overlay : 0;
        ap.rest_keep = parts != 0;
        int frc = arap_fit(RS ? RS : VS, FS, nvs, nfs, VT, FT, nvt, nft, TT, &ap, P, cb ? fit_step : NULL, &fc);
        if (frc < 0) goto done;
    }
    /* pleats where the target folds: smoothed out on the target */
    if (p->untangle > 0) {
        struct nricp_untangle_params up;
        nricp_untangle_defaults(&up);
        up.rings = p->untangle;
        up.tol = FLIP_THIN_TOL;     /* coordinates are in diagonals here */
        int fl[2];
        if (nricp_untangle(P, FS, nvs, nfs, VT, FT, nvt, nft, TT, &up, fl) < 0) goto done;
        if (cb) {
            for (int i = 0; i < nvs; i++)
                for (int d = 0; d < 3; d++) Xout[3 * i + d] = P[3 * i + d] * sc + c[d];
            cb(ctx, K + (p->fit > 0 ? p->fit : 0), 0, 0, fl[0], fl[1], -2, Xout);
        }
    }
    /* what is left flipped: each patch laid flat by a foldover-free solve */
    if (p->unflip > 0) {
        struct patch_unflip_params up;
        patch_unflip_defaults(&up);
        up.rings = p->unflip;
        up.tol = FLIP_THIN_TOL;     /* coordinates are in diagonals here */
        int st[4];
        if (patch_unflip(P, RS ? RS : VS, FS, nvs, nfs, VT, FT, nvt, nft, TT, &up, st) < 0) goto done;
        if (cb) {
            for (int i = 0; i < nvs; i++)
                for (int d = 0; d < 3; d++) Xout[3 * i + d] = P[3 * i + d] * sc + c[d];
            cb(ctx, K + (p->fit > 0 ? p->fit : 0), 0, 0, st[0], st[1], -4, Xout);
        }
    }
    /* small parts: each group the rigid motion of its rest that fits it */
    if (parts && p->small_parts > 0) {
        int ng = nricp_small_parts(Rr, FS, nvs, nfs, p->small_parts, P);
        if (ng < 0) goto done;
        if (cb && ng > 0) {
            for (int i = 0; i < nvs; i++)
                for (int d = 0; d < 3; d++) Xout[3 * i + d] = P[3 * i + d] * sc + c[d];
            cb(ctx, K + (p->fit > 0 ? p->fit : 0), 0, 0, ng, 0, -5, Xout);
        }
    }
    for (int i = 0; i < nvs; i++)
        for (int d = 0; d < 3; d++) Xout[3 * i + d] = P[3 * i + d] * sc + c[d];
    rc = 0;
done:
    closest_point_tree_free(TT);
    topology_free(&tt);
    free(VS); free(RS); free(VT); free(LD); free(X); free(P); free(NT); free(lm_b); free(lm_v);
    free(VC); free(FC); free(RC); free(XC); free(PC); free(cm.face); free(cm.bary);
    return rc;
}

double nricp_stretch(const double *R, const double *X, const int *F, int nf)
{
    double sum = 0;
    long n = 0;
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) {
            int a = F[3 * f + k], b = F[3 * f + (k + 1) % 3];
            double l0 = 0, l = 0;
            for (int d = 0; d < 3; d++) {
                double u = R[3 * a + d] - R[3 * b + d], v = X[3 * a + d] - X[3 * b + d];
                l0 += u * u;
                l += v * v;
            }
            if (!(l0 > 0)) continue;
            sum += fabs(sqrt(l / l0) - 1);
            n++;
        }
    return n ? sum / n : 0;
}
