/* patch_unflip.c -- see patch_unflip.h */
#include "patch_unflip.h"
#include "cm_error.h"
#include "geometry.h"
#include "mesh_distance.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void patch_unflip_defaults(struct patch_unflip_params *p)
{
    *p = (struct patch_unflip_params){0};   /* every field set, the ones not named below 0 */
    p->rings = 2;
    p->rounds = 1;
    p->iters = 30;
    p->wdata = 10;
    p->lambda = 1;
    p->wface = 100;
    p->wback = 100;
    p->max_verts = 2000;
    p->max_flipped = 0.03;
    p->tol = 0;
}

/* everything one patch needs, sized for the whole mesh once */
struct work {
    const double *R, *VT, *NT;
    const int *F, *FT;
    int nv, nf, nvt, nft;
    const struct closest_point_tree *TT;
    const struct topology *t;
    double tol, h0, allow, wdata, lambda, wfacep;
    int refit;                    /* patch_refit: seeded patches, kept where closer */
    unsigned char *flip;          /* #F current flags (updated when a patch is kept) */
    int *lid;                     /* #V global -> local, -1 */
    unsigned char *fin;           /* #F: face in the patch */
    int *verts, *faces;           /* local vertices (free first), patch faces */
    int *FS;                      /* patch faces in local indices (npf by 3) */
    double *X3;                   /* local positions (the fixed ones read from here) */
    double *Dinv, *A;             /* per patch face: inverse rest matrix (2x2), rest area */
    double *TF;                   /* per patch face: tangent frame t1, t2 of its target normal */
    double *C, *M, *a;            /* per free vertex: closest target point, its normal, area */
    double *CF, *MF;              /* per patch face: the same for its centroid */
    double wface;                 /* data weight of a face centroid per unit area */
    const struct closest_point_tree *TS;   /* the pose at the start (which target vertices
                                              a patch covers) */
    unsigned char *tmark;         /* #VT scratch */
    int *bt, nbt;                 /* target vertices the patch covers */
    int *bf;                      /* their closest patch face (local) */
    double *bb, *Xl;              /* their barycentrics; all local positions */
    double wbackp, wback;
    double *Q;                    /* scratch: face centroids */
    int *I, *cand;
    unsigned char *fsub;
    int ncand_max;
    double eps;
    int nfree, npf;
};

/* chi of Garanzha et al. 2021: a smooth positive stand-in for det J */
static double chi(double D, double eps) { return 0.5 * (D + sqrt(eps * eps + D * D)); }

/* Per patch face: J the map from its rest triangle to the triangle
 * projected on the tangent plane of the target under it; the untangling
 * energy (|J|^2 + lambda (det^2 + 1)) / chi(det, eps), the data term
 * wdata a_i ((x_i - c_i) . m_i)^2 per free vertex.  x: 3 nfree, g: its
 * gradient (may be NULL).  *dmin (may be NULL): the smallest det. */
static double energy(const struct work *w, const double *x, double *g, double *dmin)
{
    int nfree = w->nfree;
    double E = 0, dm = INFINITY, lam = w->lambda, eps = w->eps;
    if (g) memset(g, 0, (size_t)nfree * 3 * sizeof *g);
    for (int q = 0; q < w->npf; q++) {
        const int *v = w->FS + 3 * q;
        const double *p[3];
        for (int k = 0; k < 3; k++) p[k] = v[k] < nfree ? x + 3 * v[k] : w->X3 + 3 * v[k];
        const double *t1 = w->TF + 6 * q, *t2 = t1 + 3;
        double e1[3], e2[3];
        sub3(p[1], p[0], e1);
        sub3(p[2], p[0], e2);
        double s00 = dot3(e1, t1), s10 = dot3(e1, t2), s01 = dot3(e2, t1), s11 = dot3(e2, t2);
        const double *Mi = w->Dinv + 4 * q;
        double J00 = s00 * Mi[0] + s01 * Mi[2], J01 = s00 * Mi[1] + s01 * Mi[3];
        double J10 = s10 * Mi[0] + s11 * Mi[2], J11 = s10 * Mi[1] + s11 * Mi[3];
        double D = J00 * J11 - J01 * J10;
        if (D < dm) dm = D;
        double n2 = J00 * J00 + J01 * J01 + J10 * J10 + J11 * J11, a = w->A[q];
        double sq = sqrt(eps * eps + D * D), c = 0.5 * (D + sq), num = n2 + lam * (D * D + 1);
        E += a * num / c;
        if (!g) continue;
        double dc = 0.5 * (1 + D / sq);
        double c1 = 2 * a / c, c2 = a * (2 * lam * D / c - num / (c * c) * dc);
        double G00 = c1 * J00 + c2 * J11, G01 = c1 * J01 - c2 * J10;
        double G10 = c1 * J10 - c2 * J01, G11 = c1 * J11 + c2 * J00;
        double H00 = G00 * Mi[0] + G01 * Mi[1], H01 = G00 * Mi[2] + G01 * Mi[3];
        double H10 = G10 * Mi[0] + G11 * Mi[1], H11 = G10 * Mi[2] + G11 * Mi[3];
        /* dE/de1 = H00 t1 + H10 t2, dE/de2 = H01 t1 + H11 t2 */
        for (int d = 0; d < 3; d++) {
            double g1 = H00 * t1[d] + H10 * t2[d], g2 = H01 * t1[d] + H11 * t2[d];
            if (v[1] < nfree) g[3 * v[1] + d] += g1;
            if (v[2] < nfree) g[3 * v[2] + d] += g2;
            if (v[0] < nfree) g[3 * v[0] + d] -= g1 + g2;
        }
    }
    for (int q = 0; q < w->npf && w->wface > 0; q++) {
        const int *v = w->FS + 3 * q;
        double r[3];
        for (int d = 0; d < 3; d++) {
            double s = 0;
            for (int k = 0; k < 3; k++) s += v[k] < nfree ? x[3 * v[k] + d] : w->X3[3 * v[k] + d];
            r[d] = s / 3 - w->CF[3 * q + d];
        }
        const double *m = w->MF + 3 * q;
        double h = dot3(r, m), k = w->wface * w->A[q];
        E += k * h * h;
        if (g)
            for (int c = 0; c < 3; c++)
                if (v[c] < nfree) for (int d = 0; d < 3; d++) g[3 * v[c] + d] += 2 * k * h * m[d] / 3;
    }
    for (int j = 0; j < w->nbt && w->wback > 0; j++) {
        const int *v = w->FS + 3 * w->bf[j];
        const double *b = w->bb + 3 * j, *y = w->VT + 3 * w->bt[j];
        double r[3];
        for (int d = 0; d < 3; d++) {
            double s = 0;
            for (int k = 0; k < 3; k++) s += b[k] * (v[k] < nfree ? x[3 * v[k] + d] : w->X3[3 * v[k] + d]);
            r[d] = s - y[d];
        }
        E += w->wback * dot3(r, r);
        if (g)
            for (int k = 0; k < 3; k++)
                if (v[k] < nfree) for (int d = 0; d < 3; d++) g[3 * v[k] + d] += 2 * w->wback * b[k] * r[d];
    }
    for (int l = 0; l < nfree; l++) {
        double r[3];
        sub3(x + 3 * l, w->C + 3 * l, r);
        const double *m = w->M + 3 * l;
        double h = dot3(r, m), k = w->wdata * w->a[l];
        E += k * h * h;
        if (g) for (int d = 0; d < 3; d++) g[3 * l + d] += 2 * k * h * m[d];
    }
    if (dmin) *dmin = dm;
    return E;
}

/* L-BFGS on x (3 nfree) for at most iters iterations */
static void minimize(const struct work *w, double *x, int iters)
{
    enum { M = 7 };
    int n = 3 * w->nfree;
    double *g = malloc((size_t)n * sizeof *g), *d = malloc((size_t)n * sizeof *d);
    double *xn = malloc((size_t)n * sizeof *xn), *gn = malloc((size_t)n * sizeof *gn);
    double *S = malloc((size_t)n * M * sizeof *S), *Y = malloc((size_t)n * M * sizeof *Y);
    double rho[M], al[M];
    if (!g || !d || !xn || !gn || !S || !Y) goto done;
    double E = energy(w, x, g, NULL);
    int m = 0, head = 0;
    for (int it = 0; it < iters && isfinite(E); it++) {
        for (int i = 0; i < n; i++) d[i] = -g[i];
        for (int k = 0; k < m; k++) {
            int j = (head - 1 - k + 2 * M) % M;
            double s = 0;
            for (int i = 0; i < n; i++) s += S[j * n + i] * d[i];
            al[j] = rho[j] * s;
            for (int i = 0; i < n; i++) d[i] -= al[j] * Y[j * n + i];
        }
        double gg = 0;
        for (int i = 0; i < n; i++) gg += g[i] * g[i];
        if (m > 0) {
            int j = (head - 1 + M) % M;
            double sy = 0, yy = 0;
            for (int i = 0; i < n; i++) { sy += S[j * n + i] * Y[j * n + i]; yy += Y[j * n + i] * Y[j * n + i]; }
            for (int i = 0; i < n; i++) d[i] *= sy / yy;
        } else {
            double s = 1e-4 / (sqrt(gg) + 1e-300);
            for (int i = 0; i < n; i++) d[i] *= s;
        }
        for (int k = m - 1; k >= 0; k--) {
            int j = (head - 1 - k + 2 * M) % M;
            double s = 0;
            for (int i = 0; i < n; i++) s += Y[j * n + i] * d[i];
            double b = rho[j] * s;
            for (int i = 0; i < n; i++) d[i] += (al[j] - b) * S[j * n + i];
        }
        double gd = 0;
        for (int i = 0; i < n; i++) gd += g[i] * d[i];
        if (!(gd < 0)) {
            m = 0;
            double s = 1e-4 / (sqrt(gg) + 1e-300);
            for (int i = 0; i < n; i++) d[i] = -g[i] * s;
            gd = -gg * s;
            if (!(gd < 0)) break;
        }
        double t = 1, En = INFINITY;
        int ok = 0;
        for (int ls = 0; ls < 40; ls++, t *= 0.5) {
            for (int i = 0; i < n; i++) xn[i] = x[i] + t * d[i];
            En = energy(w, xn, gn, NULL);
            if (isfinite(En) && En <= E + 1e-4 * t * gd) { ok = 1; break; }
        }
        if (!ok) break;
        double sy = 0;
        for (int i = 0; i < n; i++) {
            S[head * n + i] = xn[i] - x[i];
            Y[head * n + i] = gn[i] - g[i];
            sy += S[head * n + i] * Y[head * n + i];
        }
        if (sy > 1e-300) {
            rho[head] = 1 / sy;
            head = (head + 1) % M;
            if (m < M) m++;
        }
        double dE = E - En;
        memcpy(x, xn, (size_t)n * sizeof *x);
        memcpy(g, gn, (size_t)n * sizeof *g);
        E = En;
        if (dE < 1e-12 * fabs(E)) break;
    }
done:
    free(g); free(d); free(xn); free(gn); free(S); free(Y);
}

/* the target under the free vertices (closest points and normals) and
 * under the patch faces (tangent frames of the normal at the centroid's
 * closest point) */
static void target_frames(struct work *w, const double *x)
{
    int nfree = w->nfree, npf = w->npf;
    if (w->nbt > 0) {
        int nloc = 0;
        for (int q = 0; q < 3 * npf; q++) if (w->FS[q] + 1 > nloc) nloc = w->FS[q] + 1;
        memcpy(w->Xl, x, (size_t)nfree * 3 * sizeof *x);
        memcpy(w->Xl + 3 * nfree, w->X3 + 3 * nfree, (size_t)(nloc - nfree) * 3 * sizeof *x);
        struct closest_point_tree *TP = closest_point_tree_new(w->Xl, nloc, w->FS, npf);
        if (TP) {
            for (int j = 0; j < w->nbt; j++) {
                double c[3];
                closest_point_query(TP, w->VT + 3 * w->bt[j], c, w->bf + j, w->bb + 3 * j);
            }
            closest_point_tree_free(TP);
        } else
            w->nbt = 0;
    }
    closest_points(w->TT, x, nfree, w->C, w->I, NULL, NULL);
    for (int l = 0; l < nfree; l++) memcpy(w->M + 3 * l, w->NT + 3 * w->I[l], 3 * sizeof *w->M);
    for (int q = 0; q < npf; q++) {
        const int *v = w->FS + 3 * q;
        for (int d = 0; d < 3; d++) {
            double s = 0;
            for (int k = 0; k < 3; k++) s += (v[k] < nfree ? x[3 * v[k] + d] : w->X3[3 * v[k] + d]);
            w->Q[3 * q + d] = s / 3;
        }
    }
    closest_points(w->TT, w->Q, npf, w->CF, w->I, NULL, NULL);
    for (int q = 0; q < npf; q++) {
        const double *n = w->NT + 3 * w->I[q];
        memcpy(w->MF + 3 * q, n, 3 * sizeof *n);
        double *t1 = w->TF + 6 * q, *t2 = t1 + 3, ax[3] = {1, 0, 0};
        if (fabs(n[0]) > 0.6) { ax[0] = 0; ax[1] = 1; }
        cross3(n, ax, t1);
        double l1 = norm3(t1);
        for (int d = 0; d < 3; d++) t1[d] /= l1;
        cross3(n, t1, t2);
    }
}

/* x (3 nfree; in: the solved free vertices, out: moved onto the target)
 * projected on the target by closest points, no patch face turned over by
 * that move: closest-point projection is not injective where the target is
 * thin and creased (a fetlock), and projecting every vertex fully folded
 * patches the solve had untangled (camel 01 -> 03, Sandybridge's kernel: a
 * patch solved with no flipped face had 7, 6 and 4 after it).  The
 * vertices of a face flipped after the move and not before it move half as
 * far, PROJECT_HALVINGS times, then stay where the solve put them; the flip
 * test is per face, so no face ends flipped that the solve left unflipped.
 * FG: the patch faces (global ids); P: the whole pose, its free vertices
 * set to x (w->fsub the patch faces' flags).  Returns the patch's flipped
 * faces, or -1 (cm_errmsg set). */
#define PROJECT_HALVINGS 6
static int project_guarded(struct work *w, double *x, const int *FG, double *P)
{
    int nfree = w->nfree, npf = w->npf, after = -1;
    double *xs = malloc(((size_t)nfree * 3 + 1) * sizeof *xs);
    double *xp = malloc(((size_t)nfree * 3 + 1) * sizeof *xp);
    int *nh = calloc((size_t)nfree + 1, sizeof *nh);
    unsigned char *fs = malloc((size_t)npf + 1), *mk = calloc((size_t)nfree + 1, 1);
    if (!xs || !xp || !nh || !fs || !mk) {
        cm_seterr("out of memory");
        goto done;
    }
    memcpy(xs, x, (size_t)nfree * 3 * sizeof *x);
    for (int l = 0; l < nfree; l++) memcpy(P + 3 * w->verts[l], xs + 3 * l, 3 * sizeof *P);
    if (flipped_face_flags(P, FG, npf, w->VT, w->nvt, w->FT, w->nft, w->TT, w->tol, fs) < 0) {
        cm_seterr("out of memory");
        goto done;
    }
    closest_points(w->TT, xs, nfree, xp, NULL, NULL, NULL);
    for (;;) {
        for (int l = 0; l < nfree; l++) {
            double t = nh[l] > PROJECT_HALVINGS ? 0 : ldexp(1, -nh[l]);
            for (int d = 0; d < 3; d++) x[3 * l + d] = xs[3 * l + d] + t * (xp[3 * l + d] - xs[3 * l + d]);
            memcpy(P + 3 * w->verts[l], x + 3 * l, 3 * sizeof *P);
        }
        after = flipped_face_flags(P, FG, npf, w->VT, w->nvt, w->FT, w->nft, w->TT, w->tol, w->fsub);
        if (after < 0) {
            cm_seterr("out of memory");
            goto done;
        }
        int held = 0;
        for (int q = 0; q < npf; q++)
            if (w->fsub[q] && !fs[q])
                for (int k = 0; k < 3; k++) {
                    int l = w->FS[3 * q + k];
                    if (l < nfree && nh[l] <= PROJECT_HALVINGS && !mk[l]) mk[l] = held = 1;
                }
        if (!held) break;
        for (int l = 0; l < nfree; l++)
            if (mk[l]) {
                nh[l]++;
                mk[l] = 0;
            }
    }
done:
    free(xs); free(xp); free(nh); free(fs); free(mk);
    return after;
}

static void clear_patch(struct work *w, int nloc, int npf)
{
    for (int l = 0; l < nloc; l++) w->lid[w->verts[l]] = -1;
    for (int q = 0; q < npf; q++) w->fin[w->faces[q]] = 0;
}

/* One patch: free: the free vertices (global ids, nfree of them).
 * Returns 1 kept, 0 not kept, -1 error. */
static int solve_patch(struct work *w, const int *free_v, int nfree, double *P, int iters)
{
    const struct topology *t = w->t;
    const int *F = w->F;
    int nloc = 0, npf = 0, rc = 0;
    for (int k = 0; k < nfree; k++) {
        w->verts[nloc] = free_v[k];
        w->lid[free_v[k]] = nloc++;
    }
    for (int k = 0; k < nfree; k++) {
        int v = free_v[k];
        for (int q = t->VFs[v]; q < t->VFs[v + 1]; q++) {
            int f = t->VF[q];
            if (w->fin[f]) continue;
            w->fin[f] = 1;
            w->faces[npf++] = f;
        }
    }
    for (int q = 0; q < npf; q++)
        for (int c = 0; c < 3; c++) {
            int v = F[3 * w->faces[q] + c];
            if (w->lid[v] < 0) { w->verts[nloc] = v; w->lid[v] = nloc++; }
        }
    for (int q = 0; q < npf; q++)
        for (int c = 0; c < 3; c++) w->FS[3 * q + c] = w->lid[F[3 * w->faces[q] + c]];
    w->nfree = nfree;
    w->npf = npf;
    for (int l = 0; l < nloc; l++) memcpy(w->X3 + 3 * l, P + 3 * w->verts[l], 3 * sizeof *w->X3);
    /* rest triangles, each in its own plane; vertex areas */
    double area = 0;
    for (int l = 0; l < nfree; l++) w->a[l] = 0;
    for (int q = 0; q < npf; q++) {
        const int *v = F + 3 * w->faces[q];
        double e1[3], e2[3], cc[3];
        sub3(w->R + 3 * v[1], w->R + 3 * v[0], e1);
        sub3(w->R + 3 * v[2], w->R + 3 * v[0], e2);
        double a = norm3(e1), b = dot3(e2, e1) / (a > 0 ? a : 1);
        cross3(e1, e2, cc);
        double c = norm3(cc) / (a > 0 ? a : 1);
        if (!(a > 0) || !(c > 1e-9 * a)) { rc = 0; goto out; }
        double *Mi = w->Dinv + 4 * q;
        Mi[0] = 1 / a; Mi[1] = -b / (a * c); Mi[2] = 0; Mi[3] = 1 / c;
        w->A[q] = 0.5 * a * c;
        area += w->A[q];
        for (int k = 0; k < 3; k++)
            if (w->FS[3 * q + k] < nfree) w->a[w->FS[3 * q + k]] += w->A[q] / 3;
    }
    /* the target vertices this patch covers: their closest point on the
     * pose at the start lies on a patch face */
    w->nbt = 0;
    if (w->wbackp > 0) {
        double o[3] = {0, 0, 0}, rad = 0;
        for (int l = 0; l < nloc; l++)
            for (int d = 0; d < 3; d++) o[d] += w->X3[3 * l + d] / nloc;
        for (int l = 0; l < nloc; l++) {
            double dd = dist3(w->X3 + 3 * l, o);
            if (dd > rad) rad = dd;
        }
        int nc = closest_point_faces_within(w->TT, o, rad, w->cand, w->ncand_max);
        if (nc > w->ncand_max) nc = w->ncand_max;
        for (int c = 0; c < nc; c++)
            for (int k = 0; k < 3; k++) {
                int j = w->FT[3 * w->cand[c] + k];
                if (w->tmark[j]) continue;
                w->tmark[j] = 1;
                double cp[3];
                int f;
                closest_point_query(w->TS, w->VT + 3 * j, cp, &f, NULL);
                if (w->fin[f]) w->bt[w->nbt++] = j;
            }
        for (int c = 0; c < w->nbt; c++) w->tmark[w->bt[c]] = 0;
        for (int c = 0; c < nc; c++)
            for (int k = 0; k < 3; k++) w->tmark[w->FT[3 * w->cand[c] + k]] = 0;
    }
    /* data weights per unit area against an edge length squared */
    double l2 = area / npf * 2;
    for (int l = 0; l < nfree; l++) w->a[l] *= w->wdata / l2;
    w->wface = w->wfacep / l2;
    int before = 0;
    for (int q = 0; q < npf; q++) before += w->flip[w->faces[q]];
    double *x = malloc(((size_t)nfree * 3 + 1) * sizeof *x);
    double *Pold = malloc(((size_t)nfree * 3 + 1) * sizeof *Pold);
    double *Pbest = malloc(((size_t)nfree * 3 + 1) * sizeof *Pbest);
    int *FG = malloc(((size_t)npf * 3 + 1) * sizeof *FG);
    unsigned char *fbest = malloc((size_t)npf + 1);
    if (!x || !Pold || !Pbest || !FG || !fbest) {
        free(x); free(Pold); free(Pbest); free(FG); free(fbest);
        cm_seterr("out of memory");
        rc = -1;
        goto out;
    }
    for (int l = 0; l < nfree; l++) memcpy(Pold + 3 * l, P + 3 * w->verts[l], 3 * sizeof *P);
    for (int q = 0; q < npf; q++) memcpy(FG + 3 * q, F + 3 * w->faces[q], 3 * sizeof *F);
    /* the pull of the covered target: three strengths tried, the best kept */
    static const double wmul[3] = {1, 0.1, 10};
    int best = before, found = 0;
    double bestd = INFINITY;
    for (int tr = 0; tr < 3; tr++) {
        w->wback = wmul[tr] * w->wbackp * (area / npf) / l2;
        if (tr > 0 && w->nbt == 0) break;
        memcpy(x, Pold, (size_t)nfree * 3 * sizeof *x);
        /* Garanzha et al.'s schedule of eps: untangle, then hold the barrier */
        double dmin;
        target_frames(w, x);
        w->eps = 1;
        energy(w, x, NULL, &dmin);
        double mu0 = 0.5 * chi(dmin, 1);
        w->eps = dmin < mu0 ? 2 * sqrt(mu0 * (mu0 - dmin)) : 1e-3;
        double Eprev = energy(w, x, NULL, NULL);
        for (int outer = 0; outer < iters; outer++) {
            minimize(w, x, 40);
            double E = energy(w, x, NULL, &dmin);
            target_frames(w, x);
            double sigma = 1 - E / Eprev;
            if (sigma < 0.1) sigma = 0.1;
            double mu = (1 - sigma) * chi(dmin, w->eps);
            if (dmin < mu) w->eps = 2 * sqrt(mu * (mu - dmin));
            else w->eps = 1e-3 * w->eps;
            Eprev = energy(w, x, NULL, NULL);
            if (dmin > 0 && outer > 3 && sigma <= 0.1) break;
        }
        /* onto the target, no face turned over by that move */
        int after = project_guarded(w, x, FG, P);
        if (after < 0) { rc = -1; break; }
        double worst = 0, fitw = 0;
        /* unflip: fewer flipped faces; refit: none more */
        if (w->refit ? after <= best : after < best || (after == best && after < before)) {
            /* the target vertices around the patch: none farther than h0 */
            double o[3] = {0, 0, 0}, rad = 0;
            for (int l = 0; l < nloc; l++)
                for (int d = 0; d < 3; d++) o[d] += P[3 * w->verts[l] + d] / nloc;
            for (int l = 0; l < nloc; l++) {
                double dd = dist3(P + 3 * w->verts[l], o);
                if (dd > rad) rad = dd;
            }
            int nc = closest_point_faces_within(w->TT, o, 1.5 * rad, w->cand, w->ncand_max);
            if (nc > w->ncand_max) nc = w->ncand_max;
            struct closest_point_tree *TS = closest_point_tree_new(P, w->nv, F, w->nf);
            if (!TS) { rc = -1; break; }
            for (int c = 0; c < nc; c++)
                for (int k = 0; k < 3; k++) {
                    double cp[3], dd = closest_point_query(TS, w->VT + 3 * w->FT[3 * w->cand[c] + k], cp, NULL, NULL);
                    if (dd > worst) worst = dd;
                }
            closest_point_tree_free(TS);
            /* and the patch faces' samples (centroid, edge midpoints) to the target */
            for (int q = 0; q < npf; q++) {
                const int *v = FG + 3 * q;
                for (int k = 0; k < 4; k++) {
                    double sp[3], cp[3];
                    for (int d = 0; d < 3; d++)
                        sp[d] = k == 3 ? (P[3 * v[0] + d] + P[3 * v[1] + d] + P[3 * v[2] + d]) / 3
                                       : 0.5 * (P[3 * v[k] + d] + P[3 * v[(k + 1) % 3] + d]);
                    double dd = closest_point_query(w->TT, sp, cp, NULL, NULL);
                    if (dd > fitw) fitw = dd;
                }
            }
            double dd = worst > fitw ? worst : fitw;
            double lim = w->allow > w->h0 ? w->allow : w->h0;
            int near = w->refit ? dd < w->h0 - 1e-9 * sqrt(l2) : dd <= lim + 1e-9 * sqrt(l2);
            if (near && (after < best || dd < bestd)) {
                found = 1;
                best = after;
                bestd = dd;
                memcpy(Pbest, x, (size_t)nfree * 3 * sizeof *x);
                memcpy(fbest, w->fsub, (size_t)npf);
            }
        }
        if (!w->refit && best == 0) break;
    }
    if (rc == 0 && found) {
        for (int l = 0; l < nfree; l++) memcpy(P + 3 * w->verts[l], Pbest + 3 * l, 3 * sizeof *P);
        for (int q = 0; q < npf; q++) w->flip[w->faces[q]] = fbest[q];
        rc = 1;
    } else
        for (int l = 0; l < nfree; l++) memcpy(P + 3 * w->verts[l], Pold + 3 * l, 3 * sizeof *P);
    free(x); free(Pold); free(Pbest); free(FG); free(fbest);
out:
    clear_patch(w, nloc, npf);
    return rc;
}

static int run(double *P, const double *R, const int *F, int nv, int nf,
               const double *VT, const int *FT, int nvt, int nft,
               const struct closest_point_tree *TT, const struct patch_unflip_params *p,
               const unsigned char *seed, int stats[4])
{
    int rc = -1, tried = 0, kept = 0;
    struct topology t = {0};
    struct work w = {0};
    struct closest_point_tree *TS = NULL;
    size_t n3 = (size_t)(nv > nf ? nv : nf) * 3 + 1;
    unsigned char *fixed = calloc((size_t)nv + 1, 1), *in = calloc((size_t)nv + 1, 1);
    unsigned char *tmp = calloc((size_t)nv + 1, 1), *done_v = calloc((size_t)nv + 1, 1);
    int *queue = malloc(((size_t)nv + 1) * sizeof *queue);
    double *NT = malloc(((size_t)nft * 3 + 1) * sizeof *NT);
    w.flip = malloc((size_t)nf + 1);
    w.fin = calloc((size_t)nf + 1, 1);
    w.fsub = malloc((size_t)nf + 1);
    w.lid = malloc(((size_t)nv + 1) * sizeof *w.lid);
    w.verts = malloc(((size_t)nv + 1) * sizeof *w.verts);
    w.faces = malloc(((size_t)nf + 1) * sizeof *w.faces);
    w.FS = malloc(((size_t)nf * 3 + 1) * sizeof *w.FS);
    w.ncand_max = (nft > nv ? nft : nv) + 1;
    w.cand = malloc((size_t)w.ncand_max * sizeof *w.cand);
    w.I = malloc(n3 * sizeof *w.I);
    w.X3 = malloc(((size_t)nv * 3 + 1) * sizeof *w.X3);
    w.Q = malloc(n3 * sizeof *w.Q);
    w.C = malloc(((size_t)nv * 3 + 1) * sizeof *w.C);
    w.M = malloc(((size_t)nv * 3 + 1) * sizeof *w.M);
    w.a = malloc(((size_t)nv + 1) * sizeof *w.a);
    w.TF = malloc(((size_t)nf * 6 + 1) * sizeof *w.TF);
    w.Dinv = malloc(((size_t)nf * 4 + 1) * sizeof *w.Dinv);
    w.A = malloc(((size_t)nf + 1) * sizeof *w.A);
    w.CF = malloc(((size_t)nf * 3 + 1) * sizeof *w.CF);
    w.tmark = calloc((size_t)nvt + 1, 1);
    w.bt = malloc(((size_t)nvt + 1) * sizeof *w.bt);
    w.bf = malloc(((size_t)nvt + 1) * sizeof *w.bf);
    w.bb = malloc(((size_t)nvt * 3 + 1) * sizeof *w.bb);
    w.Xl = malloc(((size_t)nv * 3 + 1) * sizeof *w.Xl);
    w.MF = malloc(((size_t)nf * 3 + 1) * sizeof *w.MF);
    if (!fixed || !in || !tmp || !done_v || !queue || !NT || !w.flip || !w.fin || !w.fsub ||
        !w.lid || !w.verts || !w.faces || !w.FS || !w.cand || !w.I || !w.X3 || !w.Q || !w.C ||
        !w.M || !w.a || !w.TF || !w.Dinv || !w.A || !w.CF || !w.MF || !w.tmark || !w.bt || !w.bf || !w.bb || !w.Xl) {
        cm_seterr("out of memory");
        goto done;
    }
    if (topology_build(F, nf, nv, &t) < 0) goto done;
    face_normals(VT, FT, nft, NT);
    for (int e = 0; e < t.ne; e++)
        if (t.EFn[e] != 2) fixed[t.E[2 * e]] = fixed[t.E[2 * e + 1]] = 1;
    for (int i = 0; i < nv; i++) w.lid[i] = -1;
    w.R = R; w.VT = VT; w.NT = NT; w.F = F; w.FT = FT; w.nv = nv; w.nf = nf; w.nvt = nvt; w.nft = nft;
    w.refit = seed != NULL;
    w.TT = TT; w.t = &t; w.tol = p->tol; w.allow = p->allow; w.wdata = p->wdata; w.lambda = p->lambda; w.wfacep = p->wface; w.wbackp = p->wback;
    int nfl = flipped_face_flags(P, F, nf, VT, nvt, FT, nft, TT, p->tol, w.flip);
    if (nfl < 0) goto done;
    if (stats) { stats[0] = stats[1] = nfl; stats[2] = stats[3] = 0; }
    if ((!seed && nfl == 0) || nfl > p->max_flipped * nf) { rc = 0; goto done; }
    double rms;
    TS = closest_point_tree_new(P, nv, F, nf);
    if (!TS || symmetric_distance(P, nv, F, nf, TS, VT, nvt, FT, nft, TT, &w.h0, &rms) < 0) goto done;
    w.TS = TS;
    /* round after round (one ring more each), on what is still flipped */
    for (int round = 0; round < p->rounds; round++) {
        int rings = p->rings + round, left = 0;
        for (int f = 0; f < nf; f++) left += w.flip[f];
        if (left == 0 && !seed) break;
        if (round > 0) {
            closest_point_tree_free(TS);
            TS = closest_point_tree_new(P, nv, F, nf);
            w.TS = TS;
            if (!TS) goto done;
        }
        memset(in, 0, (size_t)nv);
        memset(done_v, 0, (size_t)nv);
        /* the region: flipped faces' vertices and `rings` rings, in connected pieces */
        for (int f = 0; f < nf; f++)
            if (seed ? seed[f] : w.flip[f]) for (int c = 0; c < 3; c++) in[F[3 * f + c]] = 1;
        for (int g = 0; g < rings; g++) {
            memcpy(tmp, in, (size_t)nv);
            for (int i = 0; i < nv; i++)
                if (tmp[i]) for (int q = t.VVs[i]; q < t.VVs[i + 1]; q++) in[t.VV[q]] = 1;
        }
        for (int i = 0; i < nv; i++) in[i] &= !fixed[i];
        for (int s = 0; s < nv; s++) {
            if (!in[s] || done_v[s]) continue;
            int head = 0, tail = 0;
            queue[tail++] = s;
            done_v[s] = 1;
            while (head < tail) {
                int v = queue[head++];
                for (int q = t.VVs[v]; q < t.VVs[v + 1]; q++) {
                    int u = t.VV[q];
                    if (in[u] && !done_v[u]) { done_v[u] = 1; queue[tail++] = u; }
                }
            }
            if (tail > p->max_verts) continue;
            tried++;
            int r = solve_patch(&w, queue, tail, P, p->iters);
            if (r < 0) goto done;
            kept += r;
        }
    }
    nfl = 0;
    for (int f = 0; f < nf; f++) nfl += w.flip[f];
    if (stats) { stats[1] = nfl; stats[2] = tried; stats[3] = kept; }
    rc = 0;
done:
    closest_point_tree_free(TS);
    topology_free(&t);
    free(fixed); free(in); free(tmp); free(done_v); free(queue); free(NT);
    free(w.flip); free(w.fin); free(w.fsub); free(w.lid); free(w.verts); free(w.faces); free(w.FS);
    free(w.cand); free(w.I); free(w.X3); free(w.Q); free(w.C); free(w.M); free(w.a); free(w.TF);
    free(w.Dinv); free(w.A); free(w.CF); free(w.MF);
    free(w.tmark); free(w.bt); free(w.bf); free(w.bb); free(w.Xl);
    return rc;
}

int patch_unflip(double *P, const double *R, const int *F, int nv, int nf,
                 const double *VT, const int *FT, int nvt, int nft,
                 const struct closest_point_tree *TT, const struct patch_unflip_params *p,
                 int stats[4])
{
    return run(P, R, F, nv, nf, VT, FT, nvt, nft, TT, p, NULL, stats);
}

int patch_refit(double *P, const double *R, const int *F, int nv, int nf,
                const double *VT, const int *FT, int nvt, int nft,
                const struct closest_point_tree *TT, const struct patch_unflip_params *p,
                const unsigned char *seed, int stats[4])
{
    return run(P, R, F, nv, nf, VT, FT, nvt, nft, TT, p, seed, stats);
}
