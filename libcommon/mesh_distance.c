/* mesh_distance.c -- see mesh_distance.h */
#include "mesh_distance.h"
#include "cm_error.h"
#include "correspond.h"
#include "geometry.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* vertices, centroids, edge midpoints of (V, F) into S ((nv + nf + ne) by 3) */
static void samples(const double *V, int nv, const int *F, int nf, const struct topology *t, double *S)
{
    int k = 0;
    for (int v = 0; v < nv; v++, k++)
        for (int d = 0; d < 3; d++) S[3 * k + d] = V[3 * v + d];
    for (int f = 0; f < nf; f++, k++)
        for (int d = 0; d < 3; d++)
            S[3 * k + d] = (V[3 * F[3 * f] + d] + V[3 * F[3 * f + 1] + d] + V[3 * F[3 * f + 2] + d]) / 3;
    for (int e = 0; e < t->ne; e++, k++)
        for (int d = 0; d < 3; d++) S[3 * k + d] = 0.5 * (V[3 * t->E[2 * e] + d] + V[3 * t->E[2 * e + 1] + d]);
}

int one_sided_distance(const double *V, int nv, const int *F, int nf,
                       const struct closest_point_tree *B, struct one_sided *out)
{
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0) return -1;
    int ns = nv + nf + t.ne;
    double *P = malloc((size_t)ns * 3 * sizeof *P + 1), *D = malloc((size_t)ns * sizeof *D + 1);
    samples(V, nv, F, nf, &t, P);
    topology_free(&t);
    closest_points(B, P, ns, NULL, NULL, NULL, D);
    out->max = 0; out->sumsq = 0; out->n = ns;
    for (int i = 0; i < ns; i++) {
        if (D[i] > out->max) out->max = D[i];
        out->sumsq += D[i] * D[i];
    }
    free(P);
    free(D);
    return 0;
}

int symmetric_distance(const double *VA, int nva, const int *FA, int nfa,
                       const struct closest_point_tree *TA,
                       const double *VB, int nvb, const int *FB, int nfb,
                       const struct closest_point_tree *TB, double *hausdorff, double *rms)
{
    struct one_sided ab, ba;
    if (one_sided_distance(VA, nva, FA, nfa, TB, &ab) < 0) return -1;
    if (one_sided_distance(VB, nvb, FB, nfb, TA, &ba) < 0) return -1;
    *hausdorff = ab.max > ba.max ? ab.max : ba.max;
    *rms = sqrt((ab.sumsq + ba.sumsq) / (ab.n + ba.n));
    return 0;
}

int overlay_distance(const double *VA, int nva, const int *FA, int nfa,
                     const struct closest_point_tree *TA,
                     const double *VB, int nvb, const int *FB, int nfb,
                     const struct closest_point_tree *TB, double ratio, double tau_factor,
                     double *hausdorff, int *left_out)
{
    struct topology ta, tb;
    if (topology_build(FA, nfa, nva, &ta) < 0) return -1;
    if (topology_build(FB, nfb, nvb, &tb) < 0) { topology_free(&ta); return -1; }
    int na = nva + nfa + ta.ne, nb = nvb + nfb + tb.ne, rc = -1;
    double *PA = malloc((size_t)na * 3 * sizeof *PA + 1), *DA = malloc((size_t)na * sizeof *DA + 1);
    double *PB = malloc((size_t)nb * 3 * sizeof *PB + 1), *DB = malloc((size_t)nb * sizeof *DB + 1);
    double *BB = malloc((size_t)nb * 3 * sizeof *BB + 1);
    int *IB = malloc((size_t)nb * sizeof *IB + 1);
    if (!PA || !DA || !PB || !DB || !BB || !IB) { cm_seterr("out of memory"); goto done; }
    samples(VA, nva, FA, nfa, &ta, PA);
    samples(VB, nvb, FB, nfb, &tb, PB);
    closest_points(TB, PA, na, NULL, NULL, NULL, DA);
    closest_points(TA, PB, nb, NULL, IB, BB, DB);
    double h = 0, s2 = 0;
    for (int i = 0; i < na; i++) {
        if (DA[i] > h) h = DA[i];
        s2 += DA[i] * DA[i];
    }
    double tau = tau_factor * sqrt(s2 / (na ? na : 1));
    int out = 0;
    for (int i = 0; i < nb; i++) {
        /* DA's first nva entries: A's vertices' distances to B */
        if (ratio > 0 && correspond_overlay(FA, IB[i], BB + 3 * i, DA, DB[i], ratio, tau)) {
            out++;
            continue;
        }
        if (DB[i] > h) h = DB[i];
    }
    *hausdorff = h;
    if (left_out) *left_out = out;
    rc = 0;
done:
    topology_free(&ta);
    topology_free(&tb);
    free(PA); free(DA); free(PB); free(DB); free(BB); free(IB);
    return rc;
}

int flipped_faces(const double *VA, const int *FA, int nfa, const double *VB, int nvb,
                  const int *FB, int nfb, const struct closest_point_tree *TB, double tol)
{
    return flipped_face_flags(VA, FA, nfa, VB, nvb, FB, nfb, TB, tol, NULL);
}

/* for closest_point_faces_within_visit(): does face f of B (normals NF)
 * face the way of n? */
struct facing { const double *NF, *n; };
static int faces_this_way(int f, void *ctx)
{
    const struct facing *c = ctx;
    return dot3(c->NF + 3 * f, c->n) > 0;
}

/* the flip test of one face of A given the closest point on B to its
 * centroid (face g, barycentrics b, distance d); NF: B's face normals,
 * t: B's topology */
static int face_flipped(const double *nf, const double *p, int g, const double *b, double d,
                        const int *FB, const double *NF, const struct topology *t,
                        const struct closest_point_tree *TB, double tol)
{
    /* the normal cone of the closest feature: the face's normal inside a
     * face, both face normals on an edge, all of them at a vertex; the
     * face is flipped when it points against every one of them */
    const double eps = 1e-9;
    int zeros = (b[0] < eps) + (b[1] < eps) + (b[2] < eps);
    int fl = dot3(NF + 3 * g, nf) < 0;
    if (fl && zeros >= 2) {
        int c = b[0] >= b[1] && b[0] >= b[2] ? 0 : b[1] >= b[2] ? 1 : 2, v = FB[3 * g + c];
        for (int q = t->VFs[v]; q < t->VFs[v + 1] && fl; q++)
            if (dot3(NF + 3 * t->VF[q], nf) >= 0) fl = 0;
    } else if (fl && zeros == 1) {
        int c = b[0] < eps ? 0 : b[1] < eps ? 1 : 2;
        int e = t->FE[3 * g + (c + 1) % 3];        /* the edge opposite corner c */
        for (int q = 0; q < 2 && fl; q++)
            if (t->EF[2 * e + q] >= 0 && dot3(NF + 3 * t->EF[2 * e + q], nf) >= 0) fl = 0;
    }
    if (fl && tol > 0) {
        /* a thin part of B (an ear, a fin): is a side facing this way near too? */
        struct facing fc = {NF, nf};
        if (closest_point_faces_within_visit(TB, p, d + tol, faces_this_way, &fc)) fl = 0;
    }
    return fl;
}

int flipped_face_flags(const double *VA, const int *FA, int nfa, const double *VB, int nvb,
                       const int *FB, int nfb, const struct closest_point_tree *TB,
                       double tol, unsigned char *flip)
{
    double *P = malloc((size_t)nfa * 3 * sizeof *P + 1), *N = malloc((size_t)nfa * 3 * sizeof *N + 1);
    double *Bc = malloc((size_t)nfa * 3 * sizeof *Bc + 1);
    double *NF = malloc((size_t)nfb * 3 * sizeof *NF + 1);
    double *D = malloc((size_t)nfa * sizeof *D + 1);
    int *I = malloc((size_t)nfa * sizeof *I + 1);
    struct topology t = {0};
    int flipped = -1;
    if (topology_build(FB, nfb, nvb, &t) < 0) goto done;
    face_normals(VA, FA, nfa, N);
    face_normals(VB, FB, nfb, NF);
    for (int f = 0; f < nfa; f++)
        for (int d = 0; d < 3; d++)
            P[3 * f + d] = (VA[3 * FA[3 * f] + d] + VA[3 * FA[3 * f + 1] + d] + VA[3 * FA[3 * f + 2] + d]) / 3;
    closest_points(TB, P, nfa, NULL, I, Bc, D);
    flipped = 0;
    for (int f = 0; f < nfa; f++) {
        int fl = face_flipped(N + 3 * f, P + 3 * f, I[f], Bc + 3 * f, D[f], FB, NF, &t, TB, tol);
        flipped += fl;
        if (flip) flip[f] = (unsigned char)fl;
    }
done:
    topology_free(&t);
    free(P); free(D); free(N); free(Bc); free(NF); free(I);
    return flipped;
}

/* ---- many frames against one reference */

struct frame_compare {
    const double *VR; int nvr, nfr; int *FR;
    struct closest_point_tree *TR;
    struct topology tr;
    double *SR, *NR; int nsr;           /* the reference's samples, face normals */
    int *HC;                            /* nsr: closest frame face of each reference sample */
    int *OR;                            /* nsr: the order of the reference's samples */
    unsigned char *ZF, *ZS;             /* nfr, nsr: the zone's faces and samples (or NULL) */
    /* the frame side, kept while the connectivity stays the same */
    int nv, nf, nsx, have; int *F;
    struct topology tx;
    int *HX;                            /* nsx: closest reference face of each frame sample */
    int *OX, have_order;                /* nsx: an order of the frame's samples (the first frame's) */
    double *SX, *BX, *DX, *DC, *NX;
};

/* a face of a mesh with topology t next to each of its samples (the hint
 * when the other mesh has the same connectivity) */
static void sample_faces(const struct topology *t, int *H)
{
    int k = 0;
    for (int v = 0; v < t->nv; v++, k++) H[k] = t->VFs[v] < t->VFs[v + 1] ? t->VF[t->VFs[v]] : -1;
    for (int f = 0; f < t->nf; f++, k++) H[k] = f;
    for (int e = 0; e < t->ne; e++, k++) H[k] = t->EF[2 * e];
}

struct frame_compare *frame_compare_new(const double *VR, int nvr, const int *FR, int nfr)
{
    struct frame_compare *C = calloc(1, sizeof *C);
    if (!C) { cm_seterr("out of memory"); return NULL; }
    C->VR = VR; C->nvr = nvr; C->nfr = nfr;
    C->TR = closest_point_tree_new(VR, nvr, FR, nfr);
    if (!C->TR || topology_build(FR, nfr, nvr, &C->tr) < 0) { frame_compare_free(C); return NULL; }
    C->nsr = nvr + nfr + C->tr.ne;
    C->FR = malloc((size_t)nfr * 3 * sizeof *C->FR);
    C->SR = malloc((size_t)C->nsr * 3 * sizeof *C->SR);
    C->NR = malloc((size_t)nfr * 3 * sizeof *C->NR);
    C->HC = malloc((size_t)C->nsr * sizeof *C->HC);
    C->DC = malloc((size_t)C->nsr * sizeof *C->DC);
    C->OR = malloc((size_t)C->nsr * sizeof *C->OR);
    if (!C->FR || !C->SR || !C->NR || !C->HC || !C->DC || !C->OR) {
        cm_seterr("out of memory"); frame_compare_free(C); return NULL;
    }
    memcpy(C->FR, FR, (size_t)nfr * 3 * sizeof *FR);
    samples(VR, nvr, FR, nfr, &C->tr, C->SR);
    closest_points_order(C->SR, C->nsr, C->OR);
    face_normals(VR, FR, nfr, C->NR);
    return C;
}

void frame_compare_free(struct frame_compare *C)
{
    if (!C) return;
    closest_point_tree_free(C->TR);
    topology_free(&C->tr);
    topology_free(&C->tx);
    free(C->FR); free(C->SR); free(C->NR); free(C->HC); free(C->DC); free(C->OR);
    free(C->OX); free(C->ZF); free(C->ZS);
    free(C->F); free(C->HX); free(C->SX); free(C->BX); free(C->DX); free(C->NX);
    free(C);
}

int frame_compare_set_zone(struct frame_compare *C, const unsigned char *zone)
{
    free(C->ZF); free(C->ZS);
    C->ZF = C->ZS = NULL;
    if (!zone) return 0;
    C->ZF = malloc((size_t)C->nfr + 1);
    C->ZS = calloc((size_t)C->nsr + 1, 1);
    if (!C->ZF || !C->ZS) { cm_seterr("out of memory"); return -1; }
    memcpy(C->ZF, zone, (size_t)C->nfr);
    /* the samples in the order of samples(): vertices, centroids, edge midpoints */
    const struct topology *t = &C->tr;
    for (int v = 0; v < t->nv; v++)
        for (int q = t->VFs[v]; q < t->VFs[v + 1]; q++) C->ZS[v] |= zone[t->VF[q]];
    for (int f = 0; f < t->nf; f++) C->ZS[t->nv + f] = zone[f];
    for (int e = 0; e < t->ne; e++)
        for (int q = 0; q < 2; q++) {
            int f = t->EF[2 * e + q];
            if (f >= 0) C->ZS[t->nv + t->nf + e] |= zone[f];
        }
    return 0;
}

/* (re)make the frame side for connectivity F */
static int frame_side(struct frame_compare *C, int nv, const int *F, int nf)
{
    if (C->have && nv == C->nv && nf == C->nf && !memcmp(F, C->F, (size_t)nf * 3 * sizeof *F))
        return 0;
    topology_free(&C->tx);
    free(C->F); free(C->HX); free(C->SX); free(C->BX); free(C->DX); free(C->NX); free(C->OX);
    C->F = NULL; C->HX = C->OX = NULL; C->SX = C->BX = C->DX = C->NX = NULL;
    C->have = C->have_order = 0;
    if (topology_build(F, nf, nv, &C->tx) < 0) return -1;
    C->nv = nv; C->nf = nf; C->nsx = nv + nf + C->tx.ne;
    C->F = malloc((size_t)nf * 3 * sizeof *C->F);
    C->HX = malloc((size_t)C->nsx * sizeof *C->HX);
    C->SX = malloc((size_t)C->nsx * 3 * sizeof *C->SX);
    C->BX = malloc((size_t)C->nsx * 3 * sizeof *C->BX);
    C->DX = malloc((size_t)C->nsx * sizeof *C->DX);
    C->NX = malloc((size_t)nf * 3 * sizeof *C->NX);
    C->OX = malloc((size_t)C->nsx * sizeof *C->OX);
    if (!C->F || !C->HX || !C->SX || !C->BX || !C->DX || !C->NX || !C->OX) { cm_seterr("out of memory"); return -1; }
    memcpy(C->F, F, (size_t)nf * 3 * sizeof *F);
    /* first hints: the same-numbered face when the frame has the
     * reference's connectivity; otherwise the tree's own search */
    int same = nv == C->nvr && nf == C->nfr && !memcmp(F, C->FR, (size_t)nf * 3 * sizeof *F);
    if (same) {
        sample_faces(&C->tx, C->HX);
        sample_faces(&C->tr, C->HC);
    } else {
        for (int i = 0; i < C->nsx; i++) C->HX[i] = -1;
        for (int i = 0; i < C->nsr; i++) C->HC[i] = -1;
    }
    C->have = 1;
    return 0;
}

int frame_compare_run(struct frame_compare *C, const double *X, int nv, const int *F, int nf,
                      double tol, struct frame_distance *out, unsigned char *flip, double *face_fit)
{
    if (frame_side(C, nv, F, nf) < 0) return -1;
    struct closest_point_tree *TX = closest_point_tree_new(X, nv, F, nf);
    if (!TX) return -1;
    samples(X, nv, F, nf, &C->tx, C->SX);
    /* the frame's samples to the reference (fit), the reference's samples
     * to the frame (cover); each query starts from the previous frame's
     * answer, which for a coherent animation is at or next to the new one */
    if (!C->have_order) { closest_points_order(C->SX, C->nsx, C->OX); C->have_order = 1; }
    closest_points_batch(C->TR, C->SX, C->nsx, C->HX, C->OX, NULL, C->HX, C->BX, C->DX);
    closest_points_batch(TX, C->SR, C->nsr, C->HC, C->OR, NULL, C->HC, NULL, C->DC);
    struct one_sided *o[2] = {&out->fit, &out->cover};
    const double *Dd[2] = {C->DX, C->DC};
    int n[2] = {C->nsx, C->nsr};
    for (int s = 0; s < 2; s++) {
        o[s]->max = 0; o[s]->sumsq = 0; o[s]->n = n[s];
        for (int i = 0; i < n[s]; i++) {
            if (Dd[s][i] > o[s]->max) o[s]->max = Dd[s][i];
            o[s]->sumsq += Dd[s][i] * Dd[s][i];
        }
    }
    out->cover_clear = 0;
    for (int i = 0; i < C->nsr; i++)
        if (!(C->ZS && C->ZS[i]) && C->DC[i] > out->cover_clear) out->cover_clear = C->DC[i];
    /* flipped faces: the centroid samples (nv .. nv+nf-1) already know
     * their closest reference points */
    face_normals(X, F, nf, C->NX);
    out->flipped = out->flipped_zone = 0;
    for (int f = 0; f < nf; f++) {
        int k = nv + f;
        int fl = face_flipped(C->NX + 3 * f, C->SX + 3 * k, C->HX[k], C->BX + 3 * k, C->DX[k],
                              C->FR, C->NR, &C->tr, C->TR, tol);
        out->flipped += fl;
        if (fl && C->ZF && C->ZF[C->HX[k]]) out->flipped_zone++;
        if (flip) flip[f] = (unsigned char)fl;
        if (face_fit) {
            double m = C->DX[k];
            for (int c = 0; c < 3; c++) {
                double dv = C->DX[F[3 * f + c]], de = C->DX[nv + nf + C->tx.FE[3 * f + c]];
                if (dv > m) m = dv;
                if (de > m) m = de;
            }
            face_fit[f] = m;
        }
    }
    closest_point_tree_free(TX);
    return 0;
}
