/* nricp_untangle.c -- see nricp_untangle.h */
#include "nricp_untangle.h"
#include "cm_error.h"
#include "geometry.h"
#include "mesh_distance.h"
#include "topology.h"
#include <stdlib.h>
#include <string.h>

void nricp_untangle_defaults(struct nricp_untangle_params *p)
{
    *p = (struct nricp_untangle_params){0};   /* every field set, the ones not named below 0 */
    p->rings = 1;
    p->iters = 60;
    p->check = 5;
    p->max_move = 1;
    p->tol = 0;
}

/* the vertices of the flagged faces and `rings` rings around them */
static void grow_region(const struct topology *t, const int *F, int nf, const unsigned char *flip,
                        int rings, unsigned char *in, unsigned char *tmp)
{
    memset(in, 0, (size_t)t->nv);
    for (int f = 0; f < nf; f++)
        if (flip[f]) for (int c = 0; c < 3; c++) in[F[3 * f + c]] = 1;
    for (int g = 0; g < rings; g++) {
        memcpy(tmp, in, (size_t)t->nv);
        for (int i = 0; i < t->nv; i++)
            if (tmp[i]) for (int q = t->VVs[i]; q < t->VVs[i + 1]; q++) in[t->VV[q]] = 1;
    }
}

/* one Jacobi sweep over the vertices flagged in: the tangential part (the
 * target's face normal NT at the vertex's closest point) of the move to
 * the umbrella mean, projected onto the target, at most cap (> 0) from
 * the start P0; Q, idx, I: #V scratch */
static void sweep(const struct topology *t, const unsigned char *in, const double *P0, double cap,
                  const double *NT, const struct closest_point_tree *TT, double *P, double *Q,
                  int *idx, int *I)
{
    int m = 0;
    for (int i = 0; i < t->nv; i++) {
        if (!in[i] || t->VVs[i + 1] == t->VVs[i]) continue;
        idx[m] = i;
        memcpy(Q + 3 * m, P + 3 * i, 3 * sizeof *Q);
        m++;
    }
    closest_points(TT, Q, m, NULL, I, NULL, NULL);
    for (int k = 0; k < m; k++) {
        int i = idx[k];
        double a[3] = {0, 0, 0};
        for (int q = t->VVs[i]; q < t->VVs[i + 1]; q++)
            for (int d = 0; d < 3; d++) a[d] += P[3 * t->VV[q] + d];
        double w = 1.0 / (t->VVs[i + 1] - t->VVs[i]);
        for (int d = 0; d < 3; d++) a[d] = a[d] * w - P[3 * i + d];
        const double *n = NT + 3 * I[k];
        double an = dot3(a, n);
        for (int d = 0; d < 3; d++) Q[3 * k + d] = P[3 * i + d] + a[d] - an * n[d];
    }
    closest_points(TT, Q, m, Q, NULL, NULL, NULL);
    for (int k = 0; k < m; k++) {
        /* a pleat is ironed out locally; farther, vertices slide out of
         * the target's creases and leave them uncovered */
        double *q = Q + 3 * k, dv[3];
        const double *p0 = P0 + 3 * idx[k];
        sub3(q, p0, dv);
        double l = norm3(dv);
        if (cap > 0 && l > cap) {
            double c[3];
            for (int d = 0; d < 3; d++) q[d] = p0[d] + dv[d] * cap / l;
            closest_point_query(TT, q, c, NULL, NULL);
            memcpy(q, c, sizeof c);
        }
        memcpy(P + 3 * idx[k], q, 3 * sizeof *P);
    }
}

/* Which moved regions to keep: the connected pieces of the moved vertices
 * (moved: #V flags) are put back to P0 where a target vertex attributed
 * to them (its closest face on P0 or on P has a corner in the piece) lies
 * farther from P than h0, the symmetric Hausdorff distance before: a piece
 * that untangled by pulling a thin tip off the target.  comp, queue: #V
 * scratch.  Returns the number of pieces put back, or -1. */
static int keep_pieces(const struct topology *t, const int *F, int nf, const unsigned char *moved,
                       const double *P0, double *P, const double *VT, int nvt, double h0,
                       int *comp, int *queue)
{
    int nv = t->nv, nc = 0, back = 0;
    for (int i = 0; i < nv; i++) comp[i] = -1;
    for (int i = 0; i < nv; i++) {
        if (!moved[i] || comp[i] >= 0) continue;
        int head = 0, tail = 0;
        comp[i] = nc;
        queue[tail++] = i;
        while (head < tail) {
            int v = queue[head++];
            for (int q = t->VVs[v]; q < t->VVs[v + 1]; q++) {
                int u = t->VV[q];
                if (moved[u] && comp[u] < 0) { comp[u] = nc; queue[tail++] = u; }
            }
        }
        nc++;
    }
    if (nc == 0) return 0;
    struct closest_point_tree *T0 = closest_point_tree_new(P0, nv, F, nf);
    struct closest_point_tree *T1 = closest_point_tree_new(P, nv, F, nf);
    int *I0 = malloc(((size_t)nvt + 1) * sizeof *I0), *I1 = malloc(((size_t)nvt + 1) * sizeof *I1);
    double *D1 = malloc(((size_t)nvt + 1) * sizeof *D1);
    unsigned char *bad = calloc((size_t)nc + 1, 1);
    if (!T0 || !T1 || !I0 || !I1 || !D1 || !bad) {
        back = -1;
        if (T0 && T1) cm_seterr("out of memory");
        goto done;
    }
    closest_points(T0, VT, nvt, NULL, I0, NULL, NULL);
    closest_points(T1, VT, nvt, NULL, I1, NULL, D1);
    for (int j = 0; j < nvt; j++) {
        if (!(D1[j] > h0)) continue;
        for (int c = 0; c < 3; c++) {
            int a = comp[F[3 * I0[j] + c]], b = comp[F[3 * I1[j] + c]];
            if (a >= 0) bad[a] = 1;
            if (b >= 0) bad[b] = 1;
        }
    }
    for (int c = 0; c < nc; c++) back += bad[c];
    for (int i = 0; i < nv; i++)
        if (comp[i] >= 0 && bad[comp[i]]) memcpy(P + 3 * i, P0 + 3 * i, 3 * sizeof *P);
done:
    closest_point_tree_free(T0);
    closest_point_tree_free(T1);
    free(I0); free(I1); free(D1); free(bad);
    return back;
}

/* the flipped faces now: those of F0 (the flags at the start) away from the
 * moved vertices, recounted on the faces touching them (FS, nfs: scratch
 * #F by 3, fid: #F) */
static int count_flips(const double *P, const int *F, int nf, const unsigned char *moved,
                       const unsigned char *flip0, const double *VT, int nvt, const int *FT,
                       int nft, const struct closest_point_tree *TT, double tol, int *FS, int *fid,
                       unsigned char *fsub, unsigned char *flip)
{
    int m = 0, n = 0;
    for (int f = 0; f < nf; f++) {
        const int *v = F + 3 * f;
        if (moved[v[0]] || moved[v[1]] || moved[v[2]]) {
            memcpy(FS + 3 * m, v, 3 * sizeof *FS);
            fid[m++] = f;
        } else
            n += flip[f] = flip0[f];
    }
    int k = flipped_face_flags(P, FS, m, VT, nvt, FT, nft, TT, tol, fsub);
    if (k < 0) return -1;
    for (int q = 0; q < m; q++) flip[fid[q]] = fsub[q];
    return n + k;
}

int nricp_untangle(double *P, const int *F, int nv, int nf,
                   const double *VT, const int *FT, int nvt, int nft,
                   const struct closest_point_tree *TT, const struct nricp_untangle_params *p,
                   int flipped[2])
{
    int rc = -1;
    struct topology t = {0};
    struct closest_point_tree *TS = NULL;
    unsigned char *flip = malloc((size_t)nf + 1), *in = malloc((size_t)nv + 1), *tmp = malloc((size_t)nv + 1);
    unsigned char *moved = calloc((size_t)nv + 1, 1), *fixed = calloc((size_t)nv + 1, 1);
    double *Q = malloc(((size_t)nv * 3 + 1) * sizeof *Q), *NT = malloc(((size_t)nft * 3 + 1) * sizeof *NT);
    double *Pbest = malloc(((size_t)nv * 3 + 1) * sizeof *Pbest), *P0 = malloc(((size_t)nv * 3 + 1) * sizeof *P0);
    int *idx = malloc(((size_t)nv + 1) * sizeof *idx), *I = malloc(((size_t)nv + 1) * sizeof *I);
    int *FS = malloc(((size_t)nf * 3 + 1) * sizeof *FS), *fid = malloc(((size_t)nf + 1) * sizeof *fid);
    unsigned char *flip0 = malloc((size_t)nf + 1), *fsub = malloc((size_t)nf + 1);
    if (!FS || !fid || !flip0 || !fsub || !fixed || !flip || !in || !tmp || !moved || !Q || !NT || !Pbest || !P0 || !idx || !I) {
        cm_seterr("out of memory");
        goto done;
    }
    if (topology_build(F, nf, nv, &t) < 0) goto done;
    face_normals(VT, FT, nft, NT);
    /* the source's own boundary stays put: smoothing would pull it in */
    for (int e = 0; e < t.ne; e++)
        if (t.EFn[e] != 2) fixed[t.E[2 * e]] = fixed[t.E[2 * e + 1]] = 1;
    int nfl = flipped_face_flags(P, F, nf, VT, nvt, FT, nft, TT, p->tol, flip);
    if (nfl < 0) goto done;
    if (flipped) flipped[0] = flipped[1] = nfl;
    if (nfl == 0) { rc = 0; goto done; }
    memcpy(flip0, flip, (size_t)nf);
    double h0, rms;
    TS = closest_point_tree_new(P, nv, F, nf);
    if (!TS || symmetric_distance(P, nv, F, nf, TS, VT, nvt, FT, nft, TT, &h0, &rms) < 0) goto done;
    memcpy(P0, P, (size_t)nv * 3 * sizeof *P);
    memcpy(Pbest, P, (size_t)nv * 3 * sizeof *P);
    double cap = 0;
    if (p->max_move > 0 && t.ne > 0) {
        for (int e = 0; e < t.ne; e++) cap += dist3(P + 3 * t.E[2 * e], P + 3 * t.E[2 * e + 1]);
        cap = p->max_move * cap / t.ne;
    }
    int check = p->check < 1 ? 1 : p->check, best = nfl;
    for (int s = 0; s < p->iters; s++) {
        if (s % check == 0) {
            if (s > 0) {
                nfl = count_flips(P, F, nf, moved, flip0, VT, nvt, FT, nft, TT, p->tol, FS, fid,
                                  fsub, flip);
                if (nfl < 0) goto done;
                if (nfl < best) {
                    best = nfl;
                    memcpy(Pbest, P, (size_t)nv * 3 * sizeof *P);
                }
                if (nfl == 0) break;
            }
            grow_region(&t, F, nf, flip, p->rings, in, tmp);
            for (int i = 0; i < nv; i++) {
                in[i] &= !fixed[i];
                moved[i] |= in[i];
            }
        }
        sweep(&t, in, P0, cap, NT, TT, P, Q, idx, I);
    }
    /* the sweeps after the last recount only if they helped */
    nfl = count_flips(P, F, nf, moved, flip0, VT, nvt, FT, nft, TT, p->tol, FS, fid, fsub, flip);
    if (nfl < 0) goto done;
    if (nfl > best) memcpy(P, Pbest, (size_t)nv * 3 * sizeof *P);
    /* no piece may leave the target farther uncovered than before */
    if (keep_pieces(&t, F, nf, moved, P0, P, VT, nvt, h0, idx, I) < 0) goto done;
    nfl = flipped_face_flags(P, F, nf, VT, nvt, FT, nft, TT, p->tol, flip);
    if (nfl < 0) goto done;
    if (flipped) flipped[1] = nfl;
    rc = 0;
done:
    closest_point_tree_free(TS);
    topology_free(&t);
    free(flip); free(in); free(tmp); free(moved); free(fixed); free(Q); free(NT); free(Pbest); free(P0);
    free(idx); free(I); free(FS); free(fid); free(flip0); free(fsub);
    return rc;
}
