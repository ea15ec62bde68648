/* arap_deform2d.c -- see arap_deform2d.h */
#include "arap_deform2d.h"
#include "cm_error.h"
#include "sparse.h"
#include "spd.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct arap_deform2d {
    int nv, nf, nh;
    int *F, *H;
    double *R;           /* #V by 2 rest positions */
    struct quad_solver *S1, *S2;
    double *y1, *x1, *y2, *x2, *b2;
};

void arap_deform2d_free(struct arap_deform2d *D)
{
    if (!D) return;
    quad_solver_free(D->S1); quad_solver_free(D->S2);
    free(D->F); free(D->H); free(D->R); free(D->y1); free(D->x1); free(D->y2); free(D->x2); free(D->b2);
    free(D);
}

/* every connected component (a separate piece of a drawing) has 2 handles
 * in range and every vertex is in a triangle: else the similarity step
 * leaves that piece's place, rotation or scale free (a singular system).
 * 0, or -1 with the piece named (cm_errmsg). */
static int pieces_handled(int nv, const int *F, int nf, const int *H, int nh)
{
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0) return -1;
    for (int v = 0; v < nv; v++)
        if (t.VFs[v + 1] == t.VFs[v]) {
            topology_free(&t);
            return cm_seterr("vertex %d is in no triangle (nothing places it)", v);
        }
    int *comp = malloc(((size_t)nf + 1) * sizeof *comp), *vc = malloc(((size_t)nv + 1) * sizeof *vc);
    int nc = comp && vc ? connected_components(&t, F, comp) : -1;
    int *cnt = nc > 0 ? calloc(nc, sizeof *cnt) : NULL, *size = nc > 0 ? calloc(nc, sizeof *size) : NULL;
    int *low = nc > 0 ? malloc(nc * sizeof *low) : NULL;
    int rc = 0;
    if (!comp || !vc || nc < 1 || !cnt || !size || !low) rc = cm_seterr("out of memory");
    else {
        for (int f = 0; f < nf; f++)
            for (int j = 0; j < 3; j++) vc[F[3 * f + j]] = comp[f];
        for (int k = 0; k < nc; k++) low[k] = nv;
        for (int v = nv - 1; v >= 0; v--) { size[vc[v]]++; low[vc[v]] = v; }
        for (int h = 0; h < nh; h++)
            if (H[h] >= 0 && H[h] < nv) cnt[vc[H[h]]]++;
        for (int k = 0; k < nc && !rc; k++)
            if (cnt[k] < 2)
                rc = cm_seterr("piece %d of %d (%d vertices, the first %d) has %d handle%s: each separate piece needs 2 "
                               "(the pieces are not connected)", k + 1, nc, size[k], low[k], cnt[k], cnt[k] == 1 ? "" : "s");
    }
    free(comp); free(vc); free(cnt); free(size); free(low);
    topology_free(&t);
    return rc;
}

struct arap_deform2d *arap_deform2d_new(const double *V, int nv, const int *F, int nf,
                                        const int *H, int nh)
{
    if (nh < 2) { cm_seterr("at least 2 handles are needed (1 leaves rotation and scale free)"); return NULL; }
    if (pieces_handled(nv, F, nf, H, nh) < 0) return NULL;
    struct arap_deform2d *D = calloc(1, sizeof *D);
    D->nv = nv; D->nf = nf; D->nh = nh;
    D->F = malloc(3 * (size_t)nf * sizeof *D->F); memcpy(D->F, F, 3 * (size_t)nf * sizeof *F);
    D->H = malloc(nh * sizeof *D->H); memcpy(D->H, H, nh * sizeof *H);
    D->R = malloc(2 * (size_t)nv * sizeof *D->R);
    for (int v = 0; v < nv; v++) { D->R[2 * v] = V[3 * v]; D->R[2 * v + 1] = V[3 * v + 1]; }
    struct triplets T1, T2;
    triplets_init(&T1, 2 * nv, 2 * nv);
    triplets_init(&T2, nv, nv);
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) {
            int a = F[3 * f + k], b = F[3 * f + (k + 1) % 3], c = F[3 * f + (k + 2) % 3];
            double ex = D->R[2 * b] - D->R[2 * a], ey = D->R[2 * b + 1] - D->R[2 * a + 1];
            double dx = D->R[2 * c] - D->R[2 * a], dy = D->R[2 * c + 1] - D->R[2 * a + 1];
            double L2 = ex * ex + ey * ey;
            if (!(L2 > 0)) { cm_seterr("triangle %d has a zero-length edge", f); triplets_free(&T1); triplets_free(&T2); arap_deform2d_free(D); return NULL; }
            double x = (dx * ex + dy * ey) / L2, y = (dy * ex - dx * ey) / L2;   /* R90 e = (-ey, ex) */
            int idx[6] = {2 * a, 2 * a + 1, 2 * b, 2 * b + 1, 2 * c, 2 * c + 1};
            double rx[6] = {-1 + x, -y, -x, y, 1, 0};
            double ry[6] = {y, -1 + x, -y, -x, 0, 1};
            for (int i = 0; i < 6; i++)
                for (int j = 0; j < 6; j++)
                    triplets_add(&T1, idx[i], idx[j], rx[i] * rx[j] + ry[i] * ry[j]);
            /* step 2: edge (a, b) */
            triplets_add(&T2, a, a, 1); triplets_add(&T2, b, b, 1);
            triplets_add(&T2, a, b, -1); triplets_add(&T2, b, a, -1);
        }
    cholmod_sparse *Q1 = triplets_to_sparse(&T1, 1), *Q2 = triplets_to_sparse(&T2, 1);
    triplets_free(&T1); triplets_free(&T2);
    unsigned char *fx1 = calloc(2 * (size_t)nv, 1), *fx2 = calloc(nv, 1);
    for (int h = 0; h < nh; h++) {
        if (H[h] < 0 || H[h] >= nv) { cm_seterr("handle vertex %d out of range", H[h]); free(fx1); free(fx2); sparse_free(&Q1); sparse_free(&Q2); arap_deform2d_free(D); return NULL; }
        if (fx2[H[h]]) { cm_seterr("handle vertex %d given twice", H[h]); free(fx1); free(fx2); sparse_free(&Q1); sparse_free(&Q2); arap_deform2d_free(D); return NULL; }
        fx1[2 * H[h]] = fx1[2 * H[h] + 1] = 1; fx2[H[h]] = 1;
    }
    D->S1 = quad_solver_new(Q1, fx1);
    D->S2 = D->S1 ? quad_solver_new(Q2, fx2) : NULL;
    free(fx1); free(fx2); sparse_free(&Q1); sparse_free(&Q2);
    if (!D->S1 || !D->S2) { arap_deform2d_free(D); return NULL; }
    D->y1 = calloc(2 * (size_t)nv, sizeof *D->y1);
    D->x1 = malloc(2 * (size_t)nv * sizeof *D->x1);
    D->y2 = calloc(2 * (size_t)nv, sizeof *D->y2);
    D->x2 = malloc(2 * (size_t)nv * sizeof *D->x2);
    D->b2 = malloc(2 * (size_t)nv * sizeof *D->b2);
    return D;
}

int arap_deform2d_solve(struct arap_deform2d *D, const double *P, double *out)
{
    int nv = D->nv;
    for (int h = 0; h < D->nh; h++) {
        D->y1[2 * D->H[h]] = P[2 * h]; D->y1[2 * D->H[h] + 1] = P[2 * h + 1];
        D->y2[2 * D->H[h]] = P[2 * h]; D->y2[2 * D->H[h] + 1] = P[2 * h + 1];
    }
    if (quad_solver_solve(D->S1, NULL, D->y1, D->x1, 1) < 0) return -1;
    memset(D->b2, 0, 2 * (size_t)nv * sizeof *D->b2);
    for (int f = 0; f < D->nf; f++) {
        const int *t = D->F + 3 * f;
        /* rotation fitting the rest triangle to its step-1 image */
        double rc[2] = {0, 0}, dc[2] = {0, 0};
        for (int k = 0; k < 3; k++)
            for (int d = 0; d < 2; d++) { rc[d] += D->R[2 * t[k] + d] / 3; dc[d] += D->x1[2 * t[k] + d] / 3; }
        double sxx = 0, sxy = 0;
        for (int k = 0; k < 3; k++) {
            double px = D->R[2 * t[k]] - rc[0], py = D->R[2 * t[k] + 1] - rc[1];
            double qx = D->x1[2 * t[k]] - dc[0], qy = D->x1[2 * t[k] + 1] - dc[1];
            sxx += px * qx + py * qy;
            sxy += px * qy - py * qx;
        }
        double th = atan2(sxy, sxx), c = cos(th), s = sin(th);
        double fit[3][2];
        for (int k = 0; k < 3; k++) {
            double px = D->R[2 * t[k]] - rc[0], py = D->R[2 * t[k] + 1] - rc[1];
            fit[k][0] = c * px - s * py; fit[k][1] = s * px + c * py;
        }
        for (int k = 0; k < 3; k++) {
            int a = t[k], b = t[(k + 1) % 3];
            for (int d = 0; d < 2; d++) {
                double e = fit[(k + 1) % 3][d] - fit[k][d];
                D->b2[2 * b + d] += e;
                D->b2[2 * a + d] -= e;
            }
        }
    }
    if (quad_solver_solve(D->S2, D->b2, D->y2, D->x2, 2) < 0) return -1;
    for (int v = 0; v < nv; v++) { out[3 * v] = D->x2[2 * v]; out[3 * v + 1] = D->x2[2 * v + 1]; out[3 * v + 2] = 0; }
    return 0;
}
