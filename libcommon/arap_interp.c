/* arap_interp.c -- see arap_interp.h */
#include "arap_interp.h"
#include "cm_error.h"
#include "geometry.h"
#include "polar.h"
#include "rotation.h"
#include "spd.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct arap_interp {
    int nv, nf;
    const int *F;
    double *W;        /* #F by 12: V*_T (3 by 4, row-major) */
    double *area;     /* #F */
    double *rot;      /* #F by 3 rotation vectors (branch chosen) */
    double *S;        /* #F by 9 stretch */
    int nc;           /* connected components */
    int *vcomp;       /* #V component of each vertex, -1 isolated */
    double *c0, *c1;  /* nc by 3 component centroids in the two poses */
    const double *V0, *V1;
    struct quad_solver *Q;
    double *b, *x;    /* (#V + #F) by 3 work */
};

void tet_fourth_vertex(const double *a, const double *b, const double *c, double *out)
{
    double e1[3], e2[3], n[3];
    sub3(b, a, e1);
    sub3(c, b, e2);
    cross3(e1, e2, n);
    double s = sqrt(norm3(n));
    for (int k = 0; k < 3; k++)
        out[k] = (a[k] + b[k] + c[k]) / 3 + (s > 0 ? n[k] / s : 0);
}

/* E: 3 by 3 rows P_k - P_3 of the tetrahedron of face f */
static void tet_edges(const double *V, const int *f, double E[9])
{
    double p4[3];
    const double *a = V + 3 * f[0], *b = V + 3 * f[1], *c = V + 3 * f[2];
    tet_fourth_vertex(a, b, c, p4);
    sub3(a, p4, E);
    sub3(b, p4, E + 3);
    sub3(c, p4, E + 6);
}

double arap_interp_max_angle(const struct arap_interp *a)
{
    double m = 0;
    for (int f = 0; f < a->nf; f++) {
        double th = norm3(a->rot + 3 * f);
        if (th > m) m = th;
    }
    return m;
}

/* breadth-first over faces through shared edges: each face's rotation
 * vector on the branch closest to the face it was reached from */
static int choose_branches(struct arap_interp *a)
{
    struct topology t;
    if (topology_build(a->F, a->nf, a->nv, &t) < 0) return -1;
    int *queue = malloc((a->nf + 1) * sizeof *queue);
    unsigned char *seen = calloc(a->nf + 1, 1);
    for (int root = 0; root < a->nf; root++) {
        if (seen[root]) continue;
        int head = 0, tail = 0;
        queue[tail++] = root;
        seen[root] = 1;
        while (head < tail) {
            int f = queue[head++];
            for (int c = 0; c < 3; c++) {
                int e = t.FE[3 * f + c];
                for (int s = 0; s < 2; s++) {
                    int g = t.EF[2 * e + s];
                    if (g < 0 || seen[g]) continue;
                    double out[3];
                    rot_branch_closest(a->rot + 3 * g, a->rot + 3 * f, out);
                    memcpy(a->rot + 3 * g, out, sizeof out);
                    seen[g] = 1;
                    queue[tail++] = g;
                }
            }
        }
    }
    free(queue);
    free(seen);
    topology_free(&t);
    return 0;
}

struct arap_interp *arap_interp_new(const double *V0, const double *V1, const int *F,
                                    int nv, int nf)
{
    struct arap_interp *a = calloc(1, sizeof *a);
    int n = nv + nf;
    a->nv = nv; a->nf = nf; a->F = F;
    a->W = malloc((size_t)nf * 12 * sizeof *a->W);
    a->area = malloc((size_t)nf * sizeof *a->area);
    a->rot = malloc((size_t)nf * 3 * sizeof *a->rot);
    a->S = malloc((size_t)nf * 9 * sizeof *a->S);
    a->b = malloc((size_t)n * 3 * sizeof *a->b);
    a->x = malloc((size_t)n * 3 * sizeof *a->x);
    face_areas(V0, F, nf, a->area);
    struct triplets T;
    triplets_init(&T, n, n);
    for (int f = 0; f < nf; f++) {
        double Es[9], Et[9], Ei[9], A[9], M[9], R[9];
        tet_edges(V0, F + 3 * f, Es);
        tet_edges(V1, F + 3 * f, Et);
        if (!(a->area[f] > 0) || mat3_inverse(Es, Ei) < 0) {
            cm_seterr("face %d of the source is degenerate (zero area)", f);
            goto fail;
        }
        /* V* = Es^-1 D, D = [I | -1]: columns 0..2 = Ei, column 3 = -rowsum */
        double *W = a->W + 12 * f;
        for (int i = 0; i < 3; i++) {
            W[4 * i] = Ei[3 * i]; W[4 * i + 1] = Ei[3 * i + 1]; W[4 * i + 2] = Ei[3 * i + 2];
            W[4 * i + 3] = -(Ei[3 * i] + Ei[3 * i + 1] + Ei[3 * i + 2]);
        }
        /* row convention: Es A = Et; column map M = A^T = R S */
        mat3_mul(Ei, Et, A);
        mat3_transpose(A, M);
        polar3(M, R, a->S + 9 * f);
        rot_log(R, a->rot + 3 * f);
        /* H_T = a_T V*^T V* (Eq. 3.3), scattered */
        int id[4] = {F[3 * f], F[3 * f + 1], F[3 * f + 2], nv + f};
        for (int p = 0; p < 4; p++)
            for (int q = 0; q < 4; q++) {
                double h = 0;
                for (int k = 0; k < 3; k++) h += W[4 * k + p] * W[4 * k + q];
                triplets_add(&T, id[p], id[q], a->area[f] * h);
            }
    }
    if (choose_branches(a) < 0) goto fail;
    a->V0 = V0; a->V1 = V1;
    {
        /* fix one unknown per connected piece: vertex F[0] suffices for a
         * connected mesh; other components are fixed at their own first vertex */
        unsigned char *fixed = calloc(n, 1);
        struct topology t;
        if (topology_build(F, nf, nv, &t) < 0) { free(fixed); triplets_free(&T); goto fail; }
        int *comp = malloc((nf + 1) * sizeof *comp);
        int nc = connected_components(&t, F, comp);
        unsigned char *done = calloc(nc + 1, 1);
        for (int f = 0; f < nf; f++)
            if (!done[comp[f]]) { done[comp[f]] = 1; fixed[F[3 * f]] = 1; }
        for (int v = 0; v < nv; v++)
            if (t.VFs[v + 1] == t.VFs[v]) fixed[v] = 1;   /* isolated vertices */
        a->nc = nc;
        a->vcomp = malloc((nv + 1) * sizeof *a->vcomp);
        for (int v = 0; v < nv; v++) a->vcomp[v] = -1;
        for (int f = 0; f < nf; f++)
            for (int k = 0; k < 3; k++) a->vcomp[F[3 * f + k]] = comp[f];
        a->c0 = calloc(3 * (nc + 1), sizeof *a->c0);
        a->c1 = calloc(3 * (nc + 1), sizeof *a->c1);
        int *cnt = calloc(nc + 1, sizeof *cnt);
        for (int v = 0; v < nv; v++) {
            int c = a->vcomp[v];
            if (c < 0) continue;
            cnt[c]++;
            for (int k = 0; k < 3; k++) { a->c0[3 * c + k] += V0[3 * v + k]; a->c1[3 * c + k] += V1[3 * v + k]; }
        }
        for (int c = 0; c < nc; c++)
            for (int k = 0; k < 3; k++) { a->c0[3 * c + k] /= cnt[c]; a->c1[3 * c + k] /= cnt[c]; }
        free(cnt);
        free(done);
        free(comp);
        topology_free(&t);
        cholmod_sparse *H = triplets_to_sparse(&T, 0);
        triplets_free(&T);
        a->Q = quad_solver_new(H, fixed);
        sparse_free(&H);
        free(fixed);
        if (!a->Q) goto fail;
    }
    return a;
fail:
    arap_interp_free(a);
    return NULL;
}

int arap_interp_pose(struct arap_interp *a, double t, double *X)
{
    int nv = a->nv, n = nv + a->nf;
    memset(a->b, 0, (size_t)n * 3 * sizeof *a->b);
    for (int f = 0; f < a->nf; f++) {
        double r[3], R[9], St[9], M[9];
        for (int k = 0; k < 3; k++) r[k] = t * a->rot[3 * f + k];
        rot_exp(r, R);
        const double *S = a->S + 9 * f;
        for (int k = 0; k < 9; k++) St[k] = t * S[k] + (k % 4 == 0 ? 1 - t : 0);
        mat3_mul(R, St, M);
        /* G_T = a_T V*^T A(t), A(t) = M^T (Eq. 3.4) */
        const double *W = a->W + 12 * f;
        int id[4] = {a->F[3 * f], a->F[3 * f + 1], a->F[3 * f + 2], nv + f};
        for (int p = 0; p < 4; p++)
            for (int c = 0; c < 3; c++) {
                double g = 0;
                for (int k = 0; k < 3; k++) g += W[4 * k + p] * M[3 * c + k];
                a->b[3 * id[p] + c] += a->area[f] * g;
            }
    }
    if (quad_solver_solve(a->Q, a->b, NULL, a->x, 3) < 0) return -1;
    /* translation of each component: its interpolated centroid */
    double *c = calloc(3 * (a->nc + 1), sizeof *c);
    int *cnt = calloc(a->nc + 1, sizeof *cnt);
    for (int v = 0; v < nv; v++) {
        int k = a->vcomp[v];
        if (k < 0) continue;
        cnt[k]++;
        for (int d = 0; d < 3; d++) c[3 * k + d] += a->x[3 * v + d];
    }
    for (int v = 0; v < nv; v++) {
        int k = a->vcomp[v];
        for (int d = 0; d < 3; d++)
            X[3 * v + d] = k < 0 ? (1 - t) * a->V0[3 * v + d] + t * a->V1[3 * v + d]
                                 : a->x[3 * v + d] - c[3 * k + d] / cnt[k] +
                                       (1 - t) * a->c0[3 * k + d] + t * a->c1[3 * k + d];
    }
    free(c);
    free(cnt);
    return 0;
}

void arap_interp_free(struct arap_interp *a)
{
    if (!a) return;
    quad_solver_free(a->Q);
    free(a->vcomp); free(a->c0); free(a->c1);
    free(a->W); free(a->area); free(a->rot); free(a->S); free(a->b); free(a->x);
    free(a);
}
