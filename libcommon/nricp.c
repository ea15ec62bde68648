/* nricp.c -- see nricp.h */
#include "nricp.h"
#include "closest_point.h"
#include "cm_error.h"
#include "geometry.h"
#include "polar.h"
#include "mesh_distance.h"
#include "spd.h"
#include "topology.h"
#include <stdio.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void nricp_defaults(struct nricp_params *p)
{
    p->steps = 8;
    p->alpha_max = 50;
    p->alpha_min = 0.5;
    p->beta = 10;
    p->gamma = 1;
    p->max_angle = 60;
    p->max_dist = 0.1;
    p->backward = 1;
    p->eps = 1e-4;
    p->max_inner = 3;
    p->relax = 5;
    p->untangle = 10;
    p->untangle_weight = 100;
    p->nearest_vertex = 0;
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

/* is the closest point (face f, barycentrics b) on the boundary? */
static int on_boundary(const struct topology *t, const int *F, int f, const double *b)
{
    const double tol = 1e-9;
    for (int c = 0; c < 3; c++) {
        /* edge from corner c to c+1 is opposite corner c+2 */
        int e = t->FE[3 * f + c];
        if (t->EFn[e] == 1 && b[(c + 2) % 3] < tol) return 1;
    }
    (void)F;
    return 0;
}

static void interp_normal(const double *N, const int *F, int f, const double *b, double *n)
{
    for (int d = 0; d < 3; d++)
        n[d] = b[0] * N[3 * F[3 * f] + d] + b[1] * N[3 * F[3 * f + 1] + d] + b[2] * N[3 * F[3 * f + 2] + d];
}

int nricp_register(const double *VS0, const int *FS, int nvs, int nfs,
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
    for (int i = 0; i < nvs; i++) for (int d = 0; d < 3; d++) VS[3 * i + d] = (VS0[3 * i + d] - c[d]) / sc;
    for (int i = 0; i < nvt; i++) for (int d = 0; d < 3; d++) VT[3 * i + d] = (VT0[3 * i + d] - c[d]) / sc;
    for (int i = 0; i < nl; i++) for (int d = 0; d < 3; d++) LD[3 * i + d] = (lm_dst0[3 * i + d] - c[d]) / sc;

    struct topology ts = {0}, tt = {0};
    struct system S = {0};
    struct closest_point_tree *TT = NULL, *TT0 = NULL;
    struct spd_solver *L = NULL;
    double *X = calloc((size_t)nvs * 12 + 1, sizeof *X);          /* 4n by 3 */
    double *B = malloc(((size_t)nvs * 12 + 1) * sizeof *B);
    double *P = malloc(((size_t)nvs * 3 + 1) * sizeof *P), *Pold = malloc(((size_t)nvs * 3 + 1) * sizeof *Pold);
    double *NS = malloc(((size_t)nvs * 3 + 1) * sizeof *NS), *NT = malloc(((size_t)nvt * 3 + 1) * sizeof *NT);
    double *U = malloc(((size_t)nvs * 3 + 1) * sizeof *U), *UB = malloc(((size_t)nvs * 3 + 1) * sizeof *UB);
    int *UF = malloc(((size_t)nvs + 1) * sizeof *UF);
    double *TB = malloc(((size_t)nvt * 3 + 1) * sizeof *TB), *TC = malloc(((size_t)nvt * 3 + 1) * sizeof *TC);
    int *TF = malloc(((size_t)nvt + 1) * sizeof *TF);
    unsigned char *FL = malloc((size_t)nfs + 1), *VM = malloc((size_t)nvs + 1), *VM2 = malloc((size_t)nvs + 1);
    if (topology_build(FS, nfs, nvs, &ts) < 0 || topology_build(FT, nft, nvt, &tt) < 0) goto done;
    if (system_new(&S, &ts, nvs) < 0) goto done;
    TT = closest_point_tree_new(VT, nvt, FT, nft);
    if (!TT) goto done;
    vertex_normals(VT, FT, nvt, nft, NT);
    for (int i = 0; i < nvs; i++) { X[12 * i + 0] = 1; X[12 * i + 4] = 1; X[12 * i + 8] = 1; }
    memcpy(P, VS, (size_t)nvs * 3 * sizeof *P);
    double cosmax = cos(p->max_angle * M_PI / 180);
    double g2[4] = {1, 1, 1, p->gamma * p->gamma};
    int K = p->steps < 1 ? 1 : p->steps;
    int first = 1;
    int nflip = -1;
    for (int k = 0; k < K; k++) {
        double alpha = K == 1 ? p->alpha_max
                              : p->alpha_max * pow(p->alpha_min / p->alpha_max, (double)k / (K - 1));
        double beta = K == 1 ? 0 : p->beta * (1 - (double)k / (K - 1));
        int inner, rejected = 0;
        for (inner = 0; inner < p->max_inner; inner++) {
            /* correspondences, source -> target */
            vertex_normals(P, FS, nvs, nfs, NS);
            closest_points_hinted(TT, P, nvs, first ? NULL : UF, U, UF, UB, NULL);
            if (p->nearest_vertex)
                for (int i = 0; i < nvs; i++) {
                    int best = 0;
                    for (int q = 1; q < 3; q++) if (UB[3 * i + q] > UB[3 * i + best]) best = q;
                    memcpy(U + 3 * i, VT + 3 * FT[3 * UF[i] + best], 3 * sizeof *U);
                    for (int q = 0; q < 3; q++) UB[3 * i + q] = q == best;
                }
            memset(S.A->x, 0, S.A->nzmax * sizeof(double));
            memset(B, 0, (size_t)nvs * 12 * sizeof *B);
            rejected = 0;
            for (int i = 0; i < nvs; i++) {
                double n[3];
                interp_normal(NT, FT, UF[i], UB + 3 * i, n);
                double dd = dist3(P + 3 * i, U + 3 * i);
                int bad = on_boundary(&tt, FT, UF[i], UB + 3 * i) ||
                          dot3(n, NS + 3 * i) < cosmax * norm3(n) * norm3(NS + 3 * i) ||
                          (p->max_dist > 0 && dd > p->max_dist) || ts.VFs[i + 1] == ts.VFs[i];
                if (bad) { rejected++; continue; }
                double one = 1;
                add_row(&S, B, &i, &one, 1, VS, 1, U + 3 * i);
            }
            /* target -> source: each target vertex pulls the closest point of the source */
            if (p->backward > 0) {
                struct closest_point_tree *TS = closest_point_tree_new(P, nvs, FS, nfs);
                if (!TS) goto done;
                closest_points_hinted(TS, VT, nvt, first ? NULL : TF, TC, TF, TB, NULL);
                closest_point_tree_free(TS);
                double wb = p->backward * (double)nvs / nvt;
                for (int j = 0; j < nvt; j++) {
                    int f = TF[j];
                    double n[3];
                    interp_normal(NS, FS, f, TB + 3 * j, n);
                    double dd = dist3(VT + 3 * j, TC + 3 * j);
                    if (tt.VFs[j + 1] == tt.VFs[j] || on_boundary(&ts, FS, f, TB + 3 * j) ||
                        dot3(n, NT + 3 * j) < cosmax * norm3(n) * norm3(NT + 3 * j) ||
                        (p->max_dist > 0 && dd > p->max_dist))
                        continue;
                    add_row(&S, B, FS + 3 * f, TB + 3 * j, 3, VS, wb, VT + 3 * j);
                }
            }
            /* landmarks */
            for (int l = 0; l < nl && beta > 0; l++) {
                double one = 1;
                add_row(&S, B, lm_src + l, &one, 1, VS, beta * beta, LD + 3 * l);
            }
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
            if (spd_solve(L, B, X, 3) < 0) goto done;
            memcpy(Pold, P, (size_t)nvs * 3 * sizeof *P);
            double ch = 0;
            for (int i = 0; i < nvs; i++) {
                const double *v = VS + 3 * i, *x = X + 12 * i;
                for (int d = 0; d < 3; d++) {
                    P[3 * i + d] = v[0] * x[d] + v[1] * x[3 + d] + v[2] * x[6 + d] + x[9 + d];
                    ch += (P[3 * i + d] - Pold[3 * i + d]) * (P[3 * i + d] - Pold[3 * i + d]);
                }
            }
            if (sqrt(ch / nvs) < p->eps) { inner++; break; }
        }
        if (cb) {
            for (int i = 0; i < nvs; i++)
                for (int d = 0; d < 3; d++) Xout[3 * i + d] = P[3 * i + d] * sc + c[d];
            if (cb(ctx, k, alpha, beta, inner, rejected, -1, Xout)) break;
        }
    }
    /* untangling (outer > 0): ARAP toward the (unfolded) source restricted
     * to the flipped faces and their one-rings, the closest target points
     * as soft constraints; then the fold-removal sweeps; the pose with the
     * fewest flipped faces (flipped_face_flags, in the input coordinates as
     * the tool measures them) is kept */
    double *UR = NULL, *Pbest = malloc(((size_t)nvs * 3 + 1) * sizeof *Pbest);
    int nbest = -1;
    int nouter = p->untangle > 0 ? p->untangle + 1 : 1;
    for (int outer = 0; outer < nouter; outer++) {
    if (outer > 0) {
        UR = malloc(((size_t)nvs * 9 + 1) * sizeof *UR);
        unsigned char *VM3 = malloc((size_t)nvs + 1);
        double *W = malloc(((size_t)nvs + 1) * sizeof *W);
        for (int round = outer - 1; round < outer; round++) {
            nflip = flipped_face_flags(P, FS, nfs, VT, FT, TT, FL);
            if (cb) {
                for (int i = 0; i < nvs; i++)
                    for (int d = 0; d < 3; d++) Xout[3 * i + d] = P[3 * i + d] * sc + c[d];
                cb(ctx, K + round, 0, 0, 0, 0, nflip, Xout);
            }
            if (!nflip) break;
            memset(VM, 0, nvs);
            for (int f = 0; f < nfs; f++)
                if (FL[f]) for (int q = 0; q < 3; q++) VM[FS[3 * f + q]] = 1;
            for (int g = 0; g < 1; g++) {     /* and their one-rings */
                memcpy(VM2, VM, nvs);
                for (int i = 0; i < nvs; i++)
                    if (VM2[i]) for (int q = ts.VVs[i]; q < ts.VVs[i + 1]; q++) VM[ts.VV[q]] = 1;
            }
            memcpy(VM3, VM, nvs);                     /* region and its ring: rotations */
            for (int i = 0; i < nvs; i++)
                if (VM[i]) for (int q = ts.VVs[i]; q < ts.VVs[i + 1]; q++) VM3[ts.VV[q]] = 1;
            vertex_normals(P, FS, nvs, nfs, NS);
            closest_points_hinted(TT, P, nvs, UF, U, UF, UB, NULL);
            for (int i = 0; i < nvs; i++) {
                W[i] = 0;
                if (!VM[i]) continue;
                double n[3];
                interp_normal(NT, FT, UF[i], UB + 3 * i, n);
                double dd = dist3(P + 3 * i, U + 3 * i);
                int bad = on_boundary(&tt, FT, UF[i], UB + 3 * i) ||
                          (p->max_dist > 0 && dd > p->max_dist);
                W[i] = bad ? 0 : p->untangle_weight;
            }
            for (int it = 0; it < 100; it++) {
                /* local step: best rotation of each one-ring, source -> current */
                for (int i = 0; i < nvs; i++) {
                    if (!VM3[i]) continue;
                    double A[9] = {0}, Sm[9];
                    for (int q = ts.VVs[i]; q < ts.VVs[i + 1]; q++) {
                        int j = ts.VV[q];
                        double e[3], e2[3];
                        sub3(VS + 3 * i, VS + 3 * j, e);
                        sub3(P + 3 * i, P + 3 * j, e2);
                        for (int r = 0; r < 3; r++)
                            for (int cc = 0; cc < 3; cc++) A[3 * r + cc] += e2[r] * e[cc];
                    }
                    polar3(A, UR + 9 * i, Sm);
                }
                /* global step: one Gauss-Seidel sweep over the region */
                for (int i = 0; i < nvs; i++) {
                    int deg = ts.VVs[i + 1] - ts.VVs[i];
                    if (!VM[i] || deg == 0) continue;
                    double acc[3] = {0, 0, 0};
                    for (int q = ts.VVs[i]; q < ts.VVs[i + 1]; q++) {
                        int j = ts.VV[q];
                        double e[3];
                        sub3(VS + 3 * i, VS + 3 * j, e);
                        for (int r = 0; r < 3; r++) {
                            double re = 0;
                            for (int cc = 0; cc < 3; cc++)
                                re += 0.5 * (UR[9 * i + 3 * r + cc] + UR[9 * j + 3 * r + cc]) * e[cc];
                            acc[r] += P[3 * j + r] + re;
                        }
                    }
                    for (int r = 0; r < 3; r++)
                        P[3 * i + r] = (acc[r] + W[i] * U[3 * i + r]) / (deg + W[i]);
                }
            }
        }
        free(VM3); free(W);
    }
    free(UR); UR = NULL;
    /* fold removal: vertices of faces that point against the target (and
     * their one-rings) relax tangentially and are projected back */
    unsigned char *mark = calloc(nvs + 1, 1), *mark2 = calloc(nvs + 1, 1);
    double *NF = malloc(((size_t)nfs * 3 + 1) * sizeof *NF);
    for (int it = 0; it < p->relax; it++) {
        closest_points_hinted(TT, P, nvs, UF, U, UF, UB, NULL);
        face_normals(P, FS, nfs, NF);
        memset(mark, 0, nvs);
        int nflip = 0;
        for (int f = 0; f < nfs; f++) {
            double n[3] = {0, 0, 0}, m[3];
            for (int k2 = 0; k2 < 3; k2++) {
                int v = FS[3 * f + k2];
                interp_normal(NT, FT, UF[v], UB + 3 * v, m);
                for (int d = 0; d < 3; d++) n[d] += m[d];
            }
            if (dot3(n, NF + 3 * f) < 0) {
                nflip++;
                for (int k2 = 0; k2 < 3; k2++) mark[FS[3 * f + k2]] = 1;
            }
        }
        if (!nflip) break;
        memcpy(mark2, mark, nvs);
        for (int i = 0; i < nvs; i++)
            if (mark[i])
                for (int q = ts.VVs[i]; q < ts.VVs[i + 1]; q++) mark2[ts.VV[q]] = 1;
        for (int l = 0; l < nl; l++) mark2[lm_src[l]] = 0;   /* landmarks (tips) stay */
        vertex_normals(P, FS, nvs, nfs, NS);
        memcpy(Pold, P, (size_t)nvs * 3 * sizeof *P);
        for (int i = 0; i < nvs; i++) {
            int deg = ts.VVs[i + 1] - ts.VVs[i];
            if (!mark2[i] || deg == 0) continue;
            double m[3] = {0, 0, 0}, *n = NS + 3 * i;
            for (int q = ts.VVs[i]; q < ts.VVs[i + 1]; q++)
                for (int d = 0; d < 3; d++) m[d] += Pold[3 * ts.VV[q] + d] / deg;
            double dv[3];
            sub3(m, Pold + 3 * i, dv);
            double dn = dot3(dv, n);
            for (int d = 0; d < 3; d++) P[3 * i + d] = Pold[3 * i + d] + 0.5 * (dv[d] - dn * n[d]);
        }
        vertex_normals(P, FS, nvs, nfs, NS);
        closest_points_hinted(TT, P, nvs, UF, U, UF, UB, NULL);
        for (int i = 0; i < nvs; i++) {
            if (!mark2[i]) continue;
            double n[3];
            interp_normal(NT, FT, UF[i], UB + 3 * i, n);
            double dd = dist3(P + 3 * i, U + 3 * i);
            int bad = on_boundary(&tt, FT, UF[i], UB + 3 * i) ||
                      dot3(n, NS + 3 * i) < cosmax * norm3(n) * norm3(NS + 3 * i) ||
                      (p->max_dist > 0 && dd > p->max_dist);
            if (!bad) memcpy(P + 3 * i, U + 3 * i, 3 * sizeof *P);
        }
    }
    free(mark); free(mark2); free(NF);
    if (p->untangle > 0) {
        if (!TT0) TT0 = closest_point_tree_new(VT0, nvt, FT, nft);
        if (!TT0) goto done;
        for (int i = 0; i < nvs; i++)
            for (int d = 0; d < 3; d++) Xout[3 * i + d] = P[3 * i + d] * sc + c[d];
        nflip = flipped_face_flags(Xout, FS, nfs, VT0, FT, TT0, NULL);
    } else nflip = 0;
    if (nbest < 0 || nflip < nbest) { nbest = nflip; memcpy(Pbest, P, (size_t)nvs * 3 * sizeof *P); }
    if (!nflip) break;
    }
    memcpy(P, Pbest, (size_t)nvs * 3 * sizeof *P);
    free(Pbest);
    for (int i = 0; i < nvs; i++)
        for (int d = 0; d < 3; d++) Xout[3 * i + d] = P[3 * i + d] * sc + c[d];
    rc = 0;
done:
    spd_free(L);
    closest_point_tree_free(TT);
    closest_point_tree_free(TT0);
    system_free(&S);
    topology_free(&ts);
    topology_free(&tt);
    free(VS); free(VT); free(LD); free(X); free(B); free(P); free(Pold); free(NS); free(NT);
    free(U); free(UB); free(UF); free(TB); free(TC); free(TF);
    free(FL); free(VM); free(VM2);
    return rc;
}
