/* pose_weights.c -- see pose_weights.h */
#include "pose_weights.h"
#include "cdt2.h"
#include "cm_error.h"
#include "sparse.h"
#include "spd.h"
#include "topology.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* gradient operator of triangle (a, b, c): G (2 by 3) for columns a, b, c */
static double grad_op(const double *Pa, const double *Pb, const double *Pc, double G[6])
{
    double e1x = Pa[0] - Pc[0], e1y = Pa[1] - Pc[1], e2x = Pb[0] - Pc[0], e2y = Pb[1] - Pc[1];
    double det = e1x * e2y - e1y * e2x;
    /* E^-1 = 1/det [e2y -e1y; -e2x e1x] */
    G[0] = e2y / det;  G[1] = -e1y / det;
    G[3] = -e2x / det; G[4] = e1x / det;
    G[2] = -G[0] - G[1];
    G[5] = -G[3] - G[4];
    return 0.5 * det;
}

int pose_weights_build(struct pose_weights *pw, const double *P, int N, double margin,
                       double size, double eps)
{
    memset(pw, 0, sizeof *pw);
    pw->N = N;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < N; i++)
        for (int d = 0; d < 2; d++) { lo[d] = fmin(lo[d], P[2 * i + d]); hi[d] = fmax(hi[d], P[2 * i + d]); }
    double ext = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(ext > 0)) ext = 1;
    /* the closest pair of poses, in the user's terms if it is too close */
    int ci = -1, cj = -1;
    double dmin = INFINITY;
    for (int i = 0; i < N; i++)
        for (int j = 0; j < i; j++) {
            double d = hypot(P[2 * i] - P[2 * j], P[2 * i + 1] - P[2 * j + 1]);
            if (d < dmin) { dmin = d; ci = j; cj = i; }
        }
    if (N > 1 && !(dmin > POSE_WEIGHTS_MIN_SEPARATION * ext)) {
        if (dmin == 0)
            return cm_seterr("poses %d and %d are at the same place (%.17g %.17g) in pose space; a place "
                             "can have only one pose: drop one of them, or move one to its own place",
                             ci + 1, cj + 1, P[2 * ci], P[2 * ci + 1]);
        return cm_seterr("poses %d and %d nearly coincide: %.3g apart, %.2g of the poses' extent (below "
                         "%g), so their weights would swing by hundreds between them; drop one of them, "
                         "or move them at least %.3g apart (a twentieth of the extent keeps the weights "
                         "within about [-3, 4])", ci + 1, cj + 1, dmin, dmin / ext,
                         POSE_WEIGHTS_MIN_SEPARATION, POSE_WEIGHTS_MIN_SEPARATION * ext);
    }
    /* normalized coordinates: poses centred, extent 1 */
    double cx = 0.5 * (lo[0] + hi[0]), cy = 0.5 * (lo[1] + hi[1]);
    double *Pn = malloc(2 * (size_t)N * sizeof *Pn);
    for (int i = 0; i < N; i++) { Pn[2 * i] = (P[2 * i] - cx) / ext; Pn[2 * i + 1] = (P[2 * i + 1] - cy) / ext; }
    double h = 0.5 + margin;
    double blo[2] = {-h, -h}, bhi[2] = {h, h};
    int *pidx = malloc((N + 1) * sizeof *pidx);
    double *V;
    int *F, nv, nf;
    if (cdt2_mesh_box(blo, bhi, Pn, N, size, &V, &nv, &F, &nf, pidx) < 0) { free(Pn); free(pidx); return -1; }
    free(Pn);
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0) { free(V); free(F); free(pidx); return -1; }
    double *G = malloc(6 * (size_t)nf * sizeof *G);
    struct triplets T;
    triplets_init(&T, nv, nv);
    for (int f = 0; f < nf; f++) {
        const int *Fi = F + 3 * f;
        double area = grad_op(V + 2 * Fi[0], V + 2 * Fi[1], V + 2 * Fi[2], G + 6 * f);
        for (int r = 0; r < 2; r++)
            for (int a = 0; a < 3; a++)
                for (int b = 0; b < 3; b++)
                    triplets_add(&T, Fi[a], Fi[b], eps * area * G[6 * f + 3 * r + a] * G[6 * f + 3 * r + b]);
    }
    for (int e = 0; e < t.ne; e++) {
        if (t.EFn[e] != 2) continue;
        int fj = t.EF[2 * e], fk = t.EF[2 * e + 1];
        int idx[6];
        double D[2][6];
        int n = 0;
        for (int a = 0; a < 3; a++) {
            idx[n] = F[3 * fj + a];
            D[0][n] = G[6 * fj + a]; D[1][n] = G[6 * fj + 3 + a];
            n++;
        }
        for (int a = 0; a < 3; a++) {
            int v = F[3 * fk + a], found = -1;
            for (int b = 0; b < n; b++) if (idx[b] == v) found = b;
            if (found < 0) { found = n; idx[n] = v; D[0][n] = D[1][n] = 0; n++; }
            D[0][found] -= G[6 * fk + a];
            D[1][found] -= G[6 * fk + 3 + a];
        }
        for (int r = 0; r < 2; r++)
            for (int a = 0; a < n; a++)
                for (int b = 0; b < n; b++) triplets_add(&T, idx[a], idx[b], D[r][a] * D[r][b]);
    }
    topology_free(&t);
    free(G);
    cholmod_sparse *Q = triplets_to_sparse(&T, 1);
    triplets_free(&T);
    unsigned char *fixed = calloc(nv, 1);
    double *Y = calloc((size_t)nv * N, sizeof *Y);
    for (int i = 0; i < N; i++) { fixed[pidx[i]] = 1; Y[(size_t)pidx[i] * N + i] = 1; }
    struct quad_solver *S = quad_solver_new(Q, fixed);
    sparse_free(&Q);
    free(fixed);
    if (!S) {
        free(Y); free(V); free(F); free(pidx);
        if (N > 1)
            return cm_seterr("the weights have no unique solution (%s); the closest poses are %d and %d, "
                             "%.3g apart (%.2g of the extent): move them apart or drop one", cm_errmsg(),
                             ci + 1, cj + 1, dmin, dmin / ext);
        return -1;
    }
    double *W = malloc((size_t)nv * N * sizeof *W);
    int rc = quad_solver_solve(S, NULL, Y, W, N);
    quad_solver_free(S);
    free(Y); free(pidx);
    if (rc < 0) { free(W); free(V); free(F); return -1; }
    /* back to input coordinates */
    for (int v = 0; v < nv; v++) { V[2 * v] = cx + ext * V[2 * v]; V[2 * v + 1] = cy + ext * V[2 * v + 1]; }
    pw->nv = nv; pw->nf = nf; pw->V = V; pw->F = F; pw->W = W;
    pw->lo[0] = cx - ext * h; pw->lo[1] = cy - ext * h;
    pw->hi[0] = cx + ext * h; pw->hi[1] = cy + ext * h;
    return 0;
}

void pose_weights_eval(const struct pose_weights *pw, const double q0[2], double *w)
{
    double q[2] = {fmin(fmax(q0[0], pw->lo[0]), pw->hi[0]), fmin(fmax(q0[1], pw->lo[1]), pw->hi[1])};
    int best = 0;
    double bestmin = -INFINITY, bl[3] = {1, 0, 0};
    for (int f = 0; f < pw->nf; f++) {
        const int *F = pw->F + 3 * f;
        const double *a = pw->V + 2 * F[0], *b = pw->V + 2 * F[1], *c = pw->V + 2 * F[2];
        double det = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
        double l1 = ((b[0] - q[0]) * (c[1] - q[1]) - (b[1] - q[1]) * (c[0] - q[0])) / det;
        double l2 = ((c[0] - q[0]) * (a[1] - q[1]) - (c[1] - q[1]) * (a[0] - q[0])) / det;
        double l3 = 1 - l1 - l2;
        double mn = fmin(l1, fmin(l2, l3));
        if (mn > bestmin) { bestmin = mn; best = f; bl[0] = l1; bl[1] = l2; bl[2] = l3; }
        if (mn >= 0) break;
    }
    const int *F = pw->F + 3 * best;
    for (int i = 0; i < pw->N; i++)
        w[i] = bl[0] * pw->W[(size_t)F[0] * pw->N + i] + bl[1] * pw->W[(size_t)F[1] * pw->N + i] +
               bl[2] * pw->W[(size_t)F[2] * pw->N + i];
}

void pose_weights_free(struct pose_weights *pw)
{
    free(pw->V); free(pw->F); free(pw->W);
    memset(pw, 0, sizeof *pw);
}
