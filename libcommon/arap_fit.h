/* arap_fit.h -- fit a mesh to a target surface, as rigidly as possible:
 * closest-point data terms with an ARAP regularizer (Sorkine & Alexa 2007)
 * relative to a rest shape.  The last stage of nricp: the affine
 * non-rigid ICP of Amberg et al. brings the source close to the target, but
 * at low stiffness its per-vertex affine maps may fold triangles over where
 * several vertices crowd into a crease.  An affine map can mirror; the
 * rotations of ARAP cannot, so a folded triangle costs energy here and
 * the fit unfolds it while it stays on the target.
 *
 * Each iteration minimizes over the pose P (#V by 3)
 *   E(P) = sum_edges |(p_i - p_j) - (R_i + R_j)/2 (r_i - r_j)|^2
 *        + mu sum_i |p_i - g_i|^2
 * with r the rest shape (smoothed rest_smooth times) and g_i the goal of
 * vertex i, the weighted mean of
 *   - its closest point u_i on the target, moved back along the target's
 *     tangent plane by the fraction 'plane' of the tangential offset
 *     (point-to-plane: the mesh may slide along the target), weight 1,
 *     unless rejected (normals more than max_angle apart and no agreeing
 *     point within search farther, on the target's boundary, farther than
 *     max_dist: correspond.h);
 *   - for every target vertex t whose closest point c on the current mesh
 *     lies in a face with corner i (barycentric b_i): p_i + (t - c), weight
 *     backward * b_i * #V / #T (coverage: every part of the target pulls);
 *   - its own position when it has neither, or when it was released
 *     (release_mean: the mean of its neighbours' positions when released).
 * So every vertex has one goal of weight mu and the matrix is L + mu I, L
 * the graph Laplacian of the edges: CHOLMOD factors it once per data weight
 * (levels of them, mu_min .. mu_max geometrically: first the shape, then
 * the fit) and each iteration is one solve with three right-hand sides.
 * Local step: R_i the rotation closest to sum_j (p_i - p_j)(r_i - r_j)^T
 * (polar.h).  After each iteration, folded faces (normal against the rest
 * normal turned by the mean rotation of the corners) release their
 * vertices and release_rings rings around them: no goal next time, so the
 * rotations unfold them.
 */
#ifndef CM_ARAP_FIT_H
#define CM_ARAP_FIT_H
#include "closest_point.h"
#ifdef __cplusplus
extern "C" {
#endif

struct arap_fit_params {
    int iters;          /* correspondence updates (default 30) */
    int inner;          /* local/global iterations per update (default 1) */
    double mu_min;      /* first data weight, per vertex against one edge's ARAP term (default 0.1) */
    double mu_max;      /* last data weight (default 30) */
    double backward;    /* weight of the target -> mesh terms relative to mu (default 1; 0 off) */
    double max_angle;   /* rejection angle between normals, degrees (default 60) */
    double max_dist;    /* rejection distance, same units as the points (<= 0: off) */
    double search;      /* a closest point whose normal disagrees is replaced by the
                           nearest agreeing one within its distance + search (the other
                           side of a thin part; correspond.h), same units (default 0: off) */
    int levels;         /* distinct data weights, mu_min .. mu_max geometrically, each
                           used for iters / levels iterations (default 6) */
    double plane;       /* 0: point-to-point goals; s in (0, 1]: the goal keeps the
                           fraction s of the tangential offset from the closest
                           point, so the mesh slides along the target (default 0.9) */
    int rest_smooth;    /* sweeps of Laplacian smoothing of the rest shape, each moving
                           every vertex half way to the mean of its neighbours (default
                           1): the fit keeps the shape, not the remeshing noise (turned
                           triangles, knife-edge rims) that the target does not share */
    int release_rings;  /* folded faces free their vertices and this many rings around
                           them from the data terms for the next iteration (default 1) */
    int release_mean;   /* 0: a released vertex keeps its own place as its goal (default);
                           1: the mean of its neighbours (a membrane): a flap of surplus
                           skin folded off the target is ironed flat instead of held where
                           it is, but a folded thin tip may be pulled in (nricp
                           --fit-release tries both) */
    double overlay;     /* > 0: a target vertex pulls no corner when it lies over mesh that
                           already fits (correspond_overlay with this ratio, tau OVERLAY_TAU
                           RMS distances of the mesh's pairs; nricp sets it for a source
                           with parts; default 0: off) */
    int rest_keep;      /* 1: the rest smoothing moves no boundary vertex (an open rim
                           would shrink along the surface) and each sweep is followed by an
                           inflating one (Taubin's lambda|mu, -0.53): small parts (teeth,
                           eyes) keep their size (default 0) */
};

/* the overlay test's tau, in RMS distances of the mesh's pairs (nricp.h's OVERLAY_TAU) */
#define ARAP_FIT_OVERLAY_TAU 3

void arap_fit_defaults(struct arap_fit_params *p);

/* ARAP's local step: Q (out, #V by 9, row-major 3x3) the rotation closest
 * (polar.h) to sum_j (p_i - p_j)(r_i - r_j)^T over the one-ring of every
 * vertex i (t: the mesh's topology.h adjacency; the identity for an
 * isolated vertex); R: #V by 3 rest shape, P: #V by 3 pose, nv = #V. */
struct topology;
void arap_ring_rotations(const struct topology *t, const double *R, const double *P, int nv,
                         double *Q);

/* Called after every correspondence update with the iteration, mu, the
 * number of rejected forward correspondences, the number of folded faces
 * (normal against the rest normal turned by the corners' rotations) and
 * the pose (#V by 3);
 * return nonzero to stop. */
typedef int (*arap_fit_step_fn)(void *ctx, int iter, double mu, int rejected, int folded,
                                const double *P);

/* R: #V by 3 rest shape (copied, then smoothed); F: #F by 3 faces (nv, nf);
 * VT: #VT by 3 target vertices, FT: #FT by 3 its faces, TT: a tree of them
 * (closest_point.h);
 * P: #V by 3, in: the start pose (close to the target), out: the fit.
 * Returns 0, or -1 (cm_errmsg set). */
int arap_fit(const double *R, const int *F, int nv, int nf,
             const double *VT, const int *FT, int nvt, int nft,
             const struct closest_point_tree *TT, const struct arap_fit_params *p,
             double *P, arap_fit_step_fn cb, void *ctx);

#ifdef __cplusplus
}
#endif
#endif
