/* sample_fit.h -- the last, local refinement of a registration: every
 * sample that mesh-metrics measures (vertices, face centroids, edge
 * midpoints), not only the vertices, pulled onto the target, and the
 * target's samples pulling their closest point of the mesh, weighted
 * toward the largest distances, with no face allowed to flip.
 *
 * The ARAP fit (arap_fit.h) pulls each vertex onto the target.  Where the
 * target bends more sharply than an edge of the mesh is long (a crease
 * between toes, the inside of a fetlock), vertices on the target still
 * leave the edge between them, or the face, standing off it; and where the
 * target has a feature narrower than a face (a hoof rim), its samples can
 * be off the mesh although every vertex is on the target.  The symmetric
 * Hausdorff distance is the largest of these.  So each iteration minimises
 * over the pose P (#V by 3)
 *   sum_edges |(p_i - p_j) - Q_ij (p0_i - p0_j)|^2            ARAP from the start P0
 * + damping sum_i |p_i - p_i'|^2                                 the previous pose p'
 * + mu #V/#S sum_s w_s |x_s(P) - g_s|^2                          the mesh's samples
 * + mu cover #V/#T sum_t w_t |y_t(P) - t|^2                      the target's samples
 * with x_s = sum_k b_sk p_k a sample of the mesh (barycentric b), g_s its
 * closest target point moved back along the target's tangent plane by the
 * fraction plane of the tangential offset (point-to-plane, as arap_fit),
 * y_t the closest point of the mesh to the target sample t, and the
 * weights w = 1 + gain (d / H)^power of each sample's distance d over the
 * largest H (iteratively reweighted: the sum leans toward the maximum).
 * Samples whose target normal points against the mesh's there are left
 * out (the other side of a thin part).  Q_ij is the mean of the corners'
 * rotations (polar of the one-ring map P0 -> P), so the refinement keeps the
 * start's shape but may bend it.  One matrix per iteration (the
 * barycentric terms change), three right-hand sides (spd.h).
 * Foldover guard: after every solve, the faces flipped against the target
 * (mesh-metrics' test, flipped_face_flags) that were not flipped at the
 * start halve the step of their corners and one ring around them (up to
 * halvings times, then those vertices keep their place).
 * Kept: the pose of the lowest symmetric Hausdorff distance with no more
 * flipped faces than the start (the start if none is lower), so the
 * distance cannot grow and no face flips that was not flipped.
 */
#ifndef CM_SAMPLE_FIT_H
#define CM_SAMPLE_FIT_H
#include "closest_point.h"
#ifdef __cplusplus
extern "C" {
#endif

struct sample_fit_params {
    int iters;        /* iterations (default 12) */
    double mu;        /* data weight per vertex against one edge's ARAP term (default 30) */
    double cover;     /* weight of the target's samples relative to the mesh's (default 1) */
    double gain;      /* reweighting: w = 1 + gain (d / H)^power (default 30) */
    double power;     /* (default 4) */
    double memory;    /* the reweighting's running mean: each iteration keeps this share
                         of a sample's earlier (d / H)^power (default 0.8) */
    double min_dot;   /* a sample whose normal and the other surface's normal there have a
                         lower dot product is left out (default 0) */
    double plane;     /* fraction of the tangential offset kept (default 0.9) */
    double damping;   /* per vertex, toward the previous iterate (default 1) */
    int halvings;     /* foldover guard: times the step of the vertices around a newly
                         flipped face is halved before they keep their place (default 6) */
    double tol;       /* thin-part allowance of the flip test (flipped_face_flags), in
                         the points' units */
    double overlay;   /* > 0: the target's samples lying over mesh that already fits
                         (correspond_overlay with this ratio, tau SAMPLE_FIT_OVERLAY_TAU
                         RMS distances of the mesh's samples: a cap mesh-clean laid
                         across a hole of a face mask) neither pull the mesh nor count in
                         the Hausdorff distance that decides what is kept
                         (overlay_distance); nricp sets it for a source with parts
                         (default 0: off) */
};

#define SAMPLE_FIT_OVERLAY_TAU 3

void sample_fit_defaults(struct sample_fit_params *p);

/* P: #V by 3 (in: the registration, out: refined), F: #F by 3 faces;
 * VT: #VT by 3 target, FT: #FT by 3, TT: its tree (closest_point.h).
 * stats (out, may be NULL): the symmetric Hausdorff distance before and
 * after, the flipped faces before and after.  Returns 0, or -1 (cm_errmsg
 * set). */
int sample_fit(double *P, const int *F, int nv, int nf, const double *VT, const int *FT, int nvt,
               int nft, const struct closest_point_tree *TT, const struct sample_fit_params *p,
               double stats[4]);

#ifdef __cplusplus
}
#endif
#endif
