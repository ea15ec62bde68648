/* sample_fit.c -- see sample_fit.h */
#include "sample_fit.h"
#include "arap_fit.h"
#include "cm_error.h"
#include "correspond.h"
#include "geometry.h"
#include "mesh_distance.h"
#include "sparse.h"
#include "spd.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void sample_fit_defaults(struct sample_fit_params *p)
{
    *p = (struct sample_fit_params){0};   /* every field set, min_dot 0 among them */
    p->iters = 12;
    p->mu = 30;
    p->cover = 1;
    p->gain = 30;
    p->power = 4;
    p->plane = 0.9;
    p->damping = 1;
    p->halvings = 6;
    p->memory = 0.8;
    p->tol = 0;
}

/* the samples of a mesh in mesh-metrics' order (vertices, centroids, edge
 * midpoints) as corner indices I and barycentrics B (3 each) */
static void sample_table(const int *F, int nv, int nf, const struct topology *t, int *I, double *B)
{
    for (int v = 0; v < nv; v++) {
        I[3 * v] = I[3 * v + 1] = I[3 * v + 2] = v;
        B[3 * v] = 1; B[3 * v + 1] = B[3 * v + 2] = 0;
    }
    for (int f = 0; f < nf; f++) {
        size_t s = (size_t)nv + f;
        for (int k = 0; k < 3; k++) { I[3 * s + k] = F[3 * f + k]; B[3 * s + k] = 1.0 / 3; }
    }
    for (int e = 0; e < t->ne; e++) {
        size_t s = (size_t)nv + nf + e;
        I[3 * s] = t->E[2 * e]; I[3 * s + 1] = I[3 * s + 2] = t->E[2 * e + 1];
        B[3 * s] = B[3 * s + 1] = 0.5; B[3 * s + 2] = 0;
    }
}

/* the normal of a sample of a mesh with face normals N: its face's; a
 * vertex's and an edge's: the sum of its faces' (normalised) */
static void sample_normals(int nv, int nf, const struct topology *t, const double *N,
                           double *NS)
{
    for (int v = 0; v < nv; v++) {
        double s[3] = {0, 0, 0};
        for (int q = t->VFs[v]; q < t->VFs[v + 1]; q++)
            for (int d = 0; d < 3; d++) s[d] += N[3 * t->VF[q] + d];
        double l = norm3(s);
        for (int d = 0; d < 3; d++) NS[3 * v + d] = l > 0 ? s[d] / l : 0;
    }
    for (int f = 0; f < nf; f++)
        memcpy(NS + 3 * ((size_t)nv + f), N + 3 * f, 3 * sizeof *NS);
    for (int e = 0; e < t->ne; e++) {
        double s[3] = {0, 0, 0};
        for (int k = 0; k < 2; k++)
            if (t->EF[2 * e + k] >= 0)
                for (int d = 0; d < 3; d++) s[d] += N[3 * t->EF[2 * e + k] + d];
        double l = norm3(s);
        size_t o = 3 * ((size_t)nv + nf + e);
        for (int d = 0; d < 3; d++) NS[o + d] = l > 0 ? s[d] / l : 0;
    }
}

/* the reweighting of one sample: u (in/out) its running share of the
 * largest distances, averaged over the iterations (weights computed from
 * one iteration alone swing between the two sides of the distance) */
static double irls(double d, double H, double *u, const struct sample_fit_params *p)
{
    double r = H > 0 ? d / H : 0;
    *u = p->memory * *u + (1 - p->memory) * pow(r, p->power);
    return 1 + p->gain * *u;
}

/* the Hausdorff distance that decides what is kept: frame_compare's, or
 * with p->overlay > 0 overlay_distance()'s (the target's overlay samples
 * left out) */
static int kept_distance(const struct frame_distance *fd, const double *X, const int *F, int nv,
                         int nf, const double *VT, const int *FT, int nvt, int nft,
                         const struct closest_point_tree *TT, const struct sample_fit_params *p,
                         double *H)
{
    if (!(p->overlay > 0)) {
        *H = fd->fit.max > fd->cover.max ? fd->fit.max : fd->cover.max;
        return 0;
    }
    struct closest_point_tree *TX = closest_point_tree_new(X, nv, F, nf);
    if (!TX) return -1;
    int rc = overlay_distance(X, nv, F, nf, TX, VT, nvt, FT, nft, TT, p->overlay,
                              SAMPLE_FIT_OVERLAY_TAU, H, NULL);
    closest_point_tree_free(TX);
    return rc;
}

int sample_fit(double *P, const int *F, int nv, int nf, const double *VT, const int *FT, int nvt,
               int nft, const struct closest_point_tree *TT, const struct sample_fit_params *p,
               double stats[4])
{
    int rc = -1;
    struct topology t = {0}, tt = {0};
    struct frame_compare *FC = NULL;
    struct closest_point_tree *TP = NULL;
    if (topology_build(F, nf, nv, &t) < 0 || topology_build(FT, nft, nvt, &tt) < 0) {
        topology_free(&t);
        return -1;
    }
    const size_t ns = (size_t)nv + nf + t.ne, nts = (size_t)nvt + nft + tt.ne;
    int *SI = malloc(ns * 3 * sizeof *SI), *TI = malloc(nts * 3 * sizeof *TI);
    double *SB = malloc(ns * 3 * sizeof *SB), *TB = malloc(nts * 3 * sizeof *TB);
    double *XS = malloc(ns * 3 * sizeof *XS), *C = malloc(ns * 3 * sizeof *C);
    double *D = malloc(ns * sizeof *D), *NS = malloc(ns * 3 * sizeof *NS);
    int *I = malloc(ns * sizeof *I);
    double *YT = malloc(nts * 3 * sizeof *YT), *NTS = malloc(nts * 3 * sizeof *NTS);
    double *CT = malloc(nts * 3 * sizeof *CT), *BT = malloc(nts * 3 * sizeof *BT);
    double *DT = malloc(nts * sizeof *DT);
    int *IT = malloc(nts * sizeof *IT);
    double *NFT = malloc(((size_t)nft * 3 + 1) * sizeof *NFT), *NF = malloc(((size_t)nf * 3 + 1) * sizeof *NF);
    double *P0 = malloc(((size_t)nv * 3 + 1) * sizeof *P0), *Pp = malloc(((size_t)nv * 3 + 1) * sizeof *Pp);
    double *Pc = malloc(((size_t)nv * 3 + 1) * sizeof *Pc), *Pb = malloc(((size_t)nv * 3 + 1) * sizeof *Pb);
    double *rhs = malloc(((size_t)nv * 3 + 1) * sizeof *rhs), *Q = malloc(((size_t)nv * 9 + 1) * sizeof *Q);
    unsigned char *flip0 = malloc((size_t)nf + 1), *flip = malloc((size_t)nf + 1);
    unsigned char *back = malloc((size_t)nv + 1);
    double *US = calloc(ns + 1, sizeof *US), *UT = calloc(nts + 1, sizeof *UT);
    double *step = malloc(((size_t)nv + 1) * sizeof *step), *Ps = malloc(((size_t)nv * 3 + 1) * sizeof *Ps);
    if (!SI || !TI || !SB || !TB || !XS || !C || !D || !NS || !I || !YT || !NTS || !CT || !BT ||
        !DT || !IT || !NFT || !NF || !P0 || !Pp || !Pc || !Pb || !rhs || !Q || !flip0 || !flip || !back || !step || !Ps || !US || !UT) {
        cm_seterr("sample_fit: out of memory");
        goto done;
    }
    sample_table(F, nv, nf, &t, SI, SB);
    sample_table(FT, nvt, nft, &tt, TI, TB);
    face_normals(VT, FT, nft, NFT);
    sample_normals(nvt, nft, &tt, NFT, NTS);
    for (size_t s = 0; s < nts; s++)
        for (int d = 0; d < 3; d++) {
            double x = 0;
            for (int k = 0; k < 3; k++) x += TB[3 * s + k] * VT[3 * TI[3 * s + k] + d];
            YT[3 * s + d] = x;
        }
    FC = frame_compare_new(VT, nvt, FT, nft);
    if (!FC) goto done;
    struct frame_distance fd;
    if (frame_compare_run(FC, P, nv, F, nf, p->tol, &fd, flip0, NULL) < 0) goto done;
    double H0, Hb;
    if (kept_distance(&fd, P, F, nv, nf, VT, FT, nvt, nft, TT, p, &H0) < 0) goto done;
    Hb = H0;
    int flips0 = fd.flipped, flipsb = flips0;
    memcpy(P0, P, (size_t)nv * 3 * sizeof *P0);
    memcpy(Pb, P, (size_t)nv * 3 * sizeof *Pb);
    memcpy(Pp, P, (size_t)nv * 3 * sizeof *Pp);
    const double ws = p->mu * nv / (double)ns, wt = p->mu * p->cover * nv / (double)nts;
    for (int it = 0; it < p->iters; it++) {
        /* the mesh's samples onto the target */
        for (size_t s = 0; s < ns; s++)
            for (int d = 0; d < 3; d++) {
                double x = 0;
                for (int k = 0; k < 3; k++) x += SB[3 * s + k] * Pp[3 * SI[3 * s + k] + d];
                XS[3 * s + d] = x;
            }
        closest_points(TT, XS, (int)ns, C, I, NULL, D);
        face_normals(Pp, F, nf, NF);
        sample_normals(nv, nf, &t, NF, NS);
        /* the target's samples onto the mesh */
        closest_point_tree_free(TP);
        TP = closest_point_tree_new(Pp, nv, F, nf);
        if (!TP) goto done;
        closest_points(TP, YT, (int)nts, CT, IT, BT, DT);
        /* with overlay: the target's samples over mesh that already fits
         * are left out (DT < 0 marks them) */
        if (p->overlay > 0) {
            double s2 = 0;
            for (size_t s = 0; s < ns; s++) s2 += D[s] * D[s];
            double tau = SAMPLE_FIT_OVERLAY_TAU * sqrt(s2 / (double)ns);
            for (size_t s = 0; s < nts; s++)
                if (correspond_overlay(F, IT[s], BT + 3 * s, D, DT[s], p->overlay, tau)) DT[s] = -1;
        }
        double H = 0;
        for (size_t s = 0; s < ns; s++) if (D[s] > H) H = D[s];
        for (size_t s = 0; s < nts; s++) if (DT[s] > H) H = DT[s];
        /* the system: ARAP from P0 + damping + the samples' terms */
        struct triplets A;
        triplets_init(&A, nv, nv);
        arap_ring_rotations(&t, P0, Pp, nv, Q);
        for (int i = 0; i < nv; i++) {
            triplets_add(&A, i, i, p->damping);
            for (int d = 0; d < 3; d++) rhs[3 * i + d] = p->damping * Pp[3 * i + d];
        }
        for (int e = 0; e < t.ne; e++) {
            int i = t.E[2 * e], j = t.E[2 * e + 1];
            triplets_add(&A, i, i, 1); triplets_add(&A, j, j, 1);
            triplets_add(&A, i, j, -1); triplets_add(&A, j, i, -1);
            double r[3];
            sub3(P0 + 3 * i, P0 + 3 * j, r);
            for (int d = 0; d < 3; d++) {
                double g = 0;
                for (int c = 0; c < 3; c++) g += 0.5 * (Q[9 * i + 3 * d + c] + Q[9 * j + 3 * d + c]) * r[c];
                rhs[3 * i + d] += g;
                rhs[3 * j + d] -= g;
            }
        }
        for (size_t s = 0; s < ns; s++) {
            const double *n = NFT + 3 * I[s];
            if (dot3(n, NS + 3 * s) < p->min_dot) continue;   /* the other side of a thin part */
            double off[3], g[3];
            sub3(XS + 3 * s, C + 3 * s, off);
            double on = dot3(off, n);
            for (int d = 0; d < 3; d++) g[d] = C[3 * s + d] + p->plane * (off[d] - on * n[d]);
            double w = ws * irls(D[s], H, US + s, p);
            int nk = SB[3 * s + 1] == 0 ? 1 : SB[3 * s + 2] == 0 ? 2 : 3;
            for (int a = 0; a < nk; a++) {
                int ia = SI[3 * s + a];
                for (int b = 0; b < nk; b++)
                    triplets_add(&A, ia, SI[3 * s + b], w * SB[3 * s + a] * SB[3 * s + b]);
                for (int d = 0; d < 3; d++) rhs[3 * ia + d] += w * SB[3 * s + a] * g[d];
            }
        }
        for (size_t s = 0; s < nts; s++) {
            int f = IT[s];
            if (DT[s] < 0) continue;                             /* an overlay */
            if (dot3(NF + 3 * f, NTS + 3 * s) < p->min_dot) continue;
            double w = wt * irls(DT[s], H, UT + s, p);
            for (int a = 0; a < 3; a++) {
                int ia = F[3 * f + a];
                for (int b = 0; b < 3; b++)
                    triplets_add(&A, ia, F[3 * f + b], w * BT[3 * s + a] * BT[3 * s + b]);
                for (int d = 0; d < 3; d++) rhs[3 * ia + d] += w * BT[3 * s + a] * YT[3 * s + d];
            }
        }
        cholmod_sparse *M = triplets_to_sparse(&A, 0);
        triplets_free(&A);
        if (!M) goto done;
        struct spd_solver *S = spd_factor(M);
        sparse_free(&M);
        if (!S) goto done;
        int src = spd_solve(S, rhs, Pc, 3);
        spd_free(S);
        if (src < 0) goto done;
        /* foldover guard: where faces newly flip, their corners and a ring
         * around them take half the step, then a quarter ..., then none */
        for (int v = 0; v < nv; v++) step[v] = 1;
        memcpy(Ps, Pc, (size_t)nv * 3 * sizeof *Ps);
        int ok = 0;
        for (int tries = 0; tries <= p->halvings && !ok; tries++) {
            if (flipped_face_flags(Pc, F, nf, VT, nvt, FT, nft, TT, p->tol, flip) < 0) {
                cm_seterr("sample_fit: out of memory");
                goto done;
            }
            int nnew = 0;
            memset(back, 0, (size_t)nv);
            for (int f = 0; f < nf; f++)
                if (flip[f] && !flip0[f]) {
                    nnew++;
                    for (int k = 0; k < 3; k++) {
                        int v = F[3 * f + k];
                        back[v] = 1;
                        for (int q = t.VVs[v]; q < t.VVs[v + 1]; q++) back[t.VV[q]] = 1;
                    }
                }
            if (!nnew) { ok = 1; break; }
            for (int v = 0; v < nv; v++) {
                if (!back[v]) continue;
                step[v] = tries + 1 < p->halvings ? 0.5 * step[v] : 0;
                for (int d = 0; d < 3; d++)
                    Pc[3 * v + d] = Pp[3 * v + d] + step[v] * (Ps[3 * v + d] - Pp[3 * v + d]);
            }
        }
        if (!ok) break;
        if (frame_compare_run(FC, Pc, nv, F, nf, p->tol, &fd, NULL, NULL) < 0) goto done;
        double Hc;
        if (kept_distance(&fd, Pc, F, nv, nf, VT, FT, nvt, nft, TT, p, &Hc) < 0) goto done;
        memcpy(Pp, Pc, (size_t)nv * 3 * sizeof *Pp);
        /* fewer flipped faces first (no farther than the start), then closer */
        if ((fd.flipped < flipsb && Hc <= H0) || (fd.flipped == flipsb && Hc < Hb)) {
            Hb = Hc;
            flipsb = fd.flipped;
            memcpy(Pb, Pc, (size_t)nv * 3 * sizeof *Pb);
        }
    }
    memcpy(P, Pb, (size_t)nv * 3 * sizeof *P);
    if (stats) {
        if (frame_compare_run(FC, P, nv, F, nf, p->tol, &fd, NULL, NULL) < 0) goto done;
        stats[0] = H0;
        stats[1] = Hb;
        stats[2] = flips0;
        stats[3] = fd.flipped;
    }
    rc = 0;
done:
    closest_point_tree_free(TP);
    frame_compare_free(FC);
    topology_free(&t);
    topology_free(&tt);
    free(SI); free(TI); free(SB); free(TB); free(XS); free(C); free(D); free(NS); free(I);
    free(YT); free(NTS); free(CT); free(BT); free(DT); free(IT); free(NFT); free(NF);
    free(P0); free(Pp); free(Pc); free(Pb); free(rhs); free(Q); free(flip0); free(flip); free(back); free(step); free(Ps); free(US); free(UT);
    return rc;
}
