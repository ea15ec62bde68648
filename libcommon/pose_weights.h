/* pose_weights.h -- N-way scattered-data interpolation in a 2D pose space by
 * mesh-based least squares (Baxter, Barla, Anjyo, N-way morphing Sec. 4.1).
 *
 * The pose space is tessellated (cdt2.h); the weight field W (#V by N, one
 * column per base pose) minimizes
 *
 *   sum over triangle pairs (j,k) sharing an edge  || J_j(W) - J_k(W) ||^2     (Eq. 1)
 *   + eps * sum over triangles i  area_i || J_i(W) ||^2
 *
 * with J_j(W) = [Pa-Pc; Pb-Pc]^-1 [1 0 -1; 0 1 -1] [Wa; Wb; Wc]        (Eq. 2)
 * subject to W(pose i) = e_i, by eliminating the constrained rows
 * (quad_solver, CHOLMOD).  The first term is a discrete biharmonic energy
 * (thin-plate-like near the data), the second makes the system definite for
 * collinear poses and levels the weights out far from the data.  The
 * paper's epsilon term is unweighted; the area weight here makes eps
 * independent of the mesh size (coordinates are normalized so the poses
 * span 1).  Rows of W sum to 1 because constants are in the null space.
 */
#ifndef CM_POSE_WEIGHTS_H
#define CM_POSE_WEIGHTS_H
#ifdef __cplusplus
extern "C" {
#endif

struct pose_weights {
    int N;            /* number of base poses */
    int nv, nf;       /* pose-space mesh */
    double *V;        /* #V by 2, in input coordinates */
    int *F;           /* #F by 3 */
    double *W;        /* #V by N weights */
    double lo[2], hi[2]; /* the meshed box */
};

/* Poses closer than this fraction of the poses' extent (the larger side of
 * their bounding box) are refused as nearly coincident: at 1e-3 the weights
 * on a grid around the poses reach 105 in magnitude (measured on 4 poses;
 * 14 at 1e-2, 4.3 at 0.05), at 1e-6 CHOLMOD finds the system singular. */
#define POSE_WEIGHTS_MIN_SEPARATION 1e-3

/* P: N by 2 pose points, pairwise at least POSE_WEIGHTS_MIN_SEPARATION
 * times their extent apart (else -1 with a message naming the two poses).  margin: box margin as a multiple of the
 * poses' extent; size: target edge length as a fraction of the extent;
 * eps: weight of the gradient term.  Returns -1 on failure. */
int pose_weights_build(struct pose_weights *pw, const double *P, int N, double margin,
                       double size, double eps);
/* Weights at point q (N values into w); points outside the box are clamped
 * onto it. */
void pose_weights_eval(const struct pose_weights *pw, const double q[2], double *w);
void pose_weights_free(struct pose_weights *pw);

#ifdef __cplusplus
}
#endif
#endif
