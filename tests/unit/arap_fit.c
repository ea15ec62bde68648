/* arap_fit.c -- unit tests of unfold_faces, flipped_faces (normal cones,
 * thin parts) and arap_fit on small grids. */
#include "tap.h"
#include "testmesh.h"
#include "arap_fit.h"
#include "closest_point.h"
#include "geometry.h"
#include "mesh_distance.h"
#include "unfold.h"
#include <string.h>

/* the faces whose normal points down (-z) */
static int down_faces(const double *V, const int *F, int nf)
{
    double *N = malloc(sizeof(double) * 3 * nf);
    face_normals(V, F, nf, N);
    int n = 0;
    for (int f = 0; f < nf; f++) n += N[3 * f + 2] < 0;
    free(N);
    return n;
}

/* on a flat n x n grid, vertex (i, j) moved just across the edge from
 * (i+1, j) to (i+1, j+1): the face of those three turns over, alone */
static void fold_one(double *V, int n, int i, int j)
{
    double *a = V + 3 * (j * (n + 1) + i);
    a[0] = (i + 1.1) / n;
    a[1] = (j + 0.5) / n;
}

int main(void)
{
    const int n = 10;
    double *V, *V0;
    int *F, nv, nf;
    grid_mesh(n, n, 0, 1, &V, &F, &nv, &nf);
    V0 = malloc(sizeof(double) * 3 * nv);
    memcpy(V0, V, sizeof(double) * 3 * nv);

    /* unfold_faces */
    fold_one(V, n, 4, 4);
    ok(down_faces(V, F, nf) == 1, "setup: one face turned over (%d)", down_faces(V, F, nf));
    int found = -1, left = unfold_faces(V, F, nv, nf, -0.5, 20, &found);
    ok(found == 1 && left == 0, "unfold_faces: found %d, left %d", found, left);
    ok(down_faces(V, F, nf) == 0, "unfold_faces: no face turned over after (%d)", down_faces(V, F, nf));
    double moved = 0;
    for (int v = 0; v < nv; v++) moved += dist3(V + 3 * v, V0 + 3 * v) > 1e-12;
    ok(moved <= 3, "unfold_faces: only the fold-over's corners moved (%g)", moved);
    memcpy(V, V0, sizeof(double) * 3 * nv);
    found = -1;
    ok(unfold_faces(V, F, nv, nf, -0.5, 20, &found) == 0 && found == 0 &&
       !memcmp(V, V0, sizeof(double) * 3 * nv), "unfold_faces: a clean grid is left alone");

    /* flipped_faces */
    struct closest_point_tree *T = closest_point_tree_new(V0, nv, F, nf);
    int *R = malloc(sizeof(int) * 3 * nf);
    for (int f = 0; f < nf; f++) { R[3 * f] = F[3 * f]; R[3 * f + 1] = F[3 * f + 2]; R[3 * f + 2] = F[3 * f + 1]; }
    ok(flipped_faces(V0, F, nf, V0, nv, F, nf, T, 0) == 0, "flipped_faces: a mesh against itself: 0");
    ok(flipped_faces(V0, R, nf, V0, nv, F, nf, T, 0) == nf, "flipped_faces: reversed: all %d", nf);
    /* a thin plate: the grid (up) and a reversed copy 1e-4 below (down) */
    double *P2 = malloc(sizeof(double) * 6 * nv);
    int *F2 = malloc(sizeof(int) * 6 * nf);
    memcpy(P2, V0, sizeof(double) * 3 * nv);
    for (int v = 0; v < nv; v++) {
        memcpy(P2 + 3 * (nv + v), V0 + 3 * v, sizeof(double) * 3);
        P2[3 * (nv + v) + 2] = -1e-4;
    }
    memcpy(F2, F, sizeof(int) * 3 * nf);
    for (int k = 0; k < 3 * nf; k++) F2[3 * nf + k] = R[k] + nv;
    struct closest_point_tree *T2 = closest_point_tree_new(P2, 2 * nv, F2, 2 * nf);
    double *A = malloc(sizeof(double) * 3 * nv);
    memcpy(A, V0, sizeof(double) * 3 * nv);
    for (int v = 0; v < nv; v++) A[3 * v + 2] = 2e-5;      /* just above the top side */
    int f0 = flipped_faces(A, R, nf, P2, 2 * nv, F2, 2 * nf, T2, 0);
    int f1 = flipped_faces(A, R, nf, P2, 2 * nv, F2, 2 * nf, T2, 1e-3);
    ok(f0 == nf && f1 == 0, "flipped_faces: a downward sheet on a thin plate: %d without, %d with "
       "the thin-part allowance", f0, f1);

    /* a ridge (the grid folded to z = 0.5 - |x - 0.5|, a 90 degree crease
     * along x = 0.5): a triangle standing over the crease whose normal is
     * within 90 degrees of one side's normal only is not flipped; turned
     * against both sides, it is */
    double *Vr = malloc(sizeof(double) * 3 * nv);
    memcpy(Vr, V0, sizeof(double) * 3 * nv);
    for (int v = 0; v < nv; v++) Vr[3 * v + 2] = 0.5 - fabs(Vr[3 * v] - 0.5);
    struct closest_point_tree *Tr = closest_point_tree_new(Vr, nv, F, nf);
    /* centroid (0.5, 0.45, 0.6), normal ~ (1, 0, -0.2) */
    double tri[9] = {0.5 - 0.02, 0.35, 0.6 - 0.1, 0.5 + 0.02, 0.35, 0.6 + 0.1, 0.5, 0.65, 0.6};
    int t1[3] = {0, 1, 2}, t2[3] = {0, 2, 1};
    double nt[3];
    face_normals(tri, t1, 1, nt);
    int fa = flipped_faces(tri, t1, 1, Vr, nv, F, nf, Tr, 0), fb = flipped_faces(tri, t2, 1, Vr, nv, F, nf, Tr, 0);
    ok(fabs(nt[0]) > 0.9 && nt[0] * nt[2] < 0 && fa == 0, "flipped_faces: across a crease, facing one side: not flipped (normal %.2f %.2f %.2f)",
       nt[0], nt[1], nt[2]);
    ok(fb == 0, "flipped_faces: across a crease, facing the other side: not flipped either");
    double tri2[9] = {0.45, 0.35, 0.6, 0.55, 0.35, 0.6, 0.5, 0.6, 0.6};   /* flat, facing +z */
    ok(flipped_faces(tri2, t1, 1, Vr, nv, F, nf, Tr, 0) == 0 &&
       flipped_faces(tri2, t2, 1, Vr, nv, F, nf, Tr, 0) == 1,
       "flipped_faces: over a crease, facing up: fine; facing down: flipped");
    closest_point_tree_free(Tr);
    free(Vr);

    /* arap_fit: start folded and noisy, target = the rest grid */
    struct rng r;
    rng_seed(&r, 7);
    double *X = malloc(sizeof(double) * 3 * nv);
    memcpy(X, V0, sizeof(double) * 3 * nv);
    fold_one(X, n, 4, 4);
    fold_one(X, n, 2, 6);
    for (int k = 0; k < 3 * nv; k++) X[k] += 0.02 / n * (rng_uniform(&r) - 0.5);
    ok(down_faces(X, F, nf) >= 2, "arap_fit setup: %d faces turned over", down_faces(X, F, nf));
    struct arap_fit_params p;
    arap_fit_defaults(&p);
    p.iters = 20;
    ok(arap_fit(V0, F, nv, nf, V0, F, nv, nf, T, &p, X, NULL, NULL) == 0, "arap_fit runs");
    ok(flipped_faces(X, F, nf, V0, nv, F, nf, T, 0) == 0, "arap_fit: no flipped face (%d)",
       flipped_faces(X, F, nf, V0, nv, F, nf, T, 0));
    /* (the boundary's correspondences are rejected: only the interior is pulled) */
    double dmax = 0;
    for (int j = 1; j < n; j++)
        for (int i = 1; i < n; i++) {
            double c[3], d = closest_point_query(T, X + 3 * (j * (n + 1) + i), c, NULL, NULL);
            if (d > dmax) dmax = d;
        }
    ok(dmax < 2e-4, "arap_fit: the interior lies on the target (max distance %.2g)", dmax);

    closest_point_tree_free(T);
    closest_point_tree_free(T2);
    free(V); free(V0); free(F); free(R); free(P2); free(F2); free(A); free(X);
    return tap_done();
}
