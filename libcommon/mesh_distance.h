/* mesh_distance.h -- distances between two surfaces: one-sided and
 * symmetric Hausdorff distance and RMS distance, by closest points
 * (closest_point.h, CGAL AABB tree) from samples of one surface to the other.
 *
 * Samples of a surface: its vertices, face centroids and edge midpoints.
 * The Hausdorff distance so measured is a lower bound of the exact one that
 * is tight to within the distance of the samples to the far point
 * (for meshes of similar resolution, a small fraction of an edge length).
 */
#ifndef CM_MESH_DISTANCE_H
#define CM_MESH_DISTANCE_H
#include "closest_point.h"
#ifdef __cplusplus
extern "C" {
#endif

struct one_sided {
    double max;      /* largest sample distance (one-sided Hausdorff) */
    double sumsq;    /* sum of squared sample distances */
    int n;           /* number of samples */
};

/* Distances from the samples of mesh A (V: #V by 3, F: #F by 3) to the
 * surface in tree B. */
int one_sided_distance(const double *V, int nv, const int *F, int nf,
                       const struct closest_point_tree *B, struct one_sided *out);

/* Symmetric: H = max of both one-sided maxima, rms over all samples of both.
 * TA, TB: trees of A and B (built by the caller so they can be reused). */
int symmetric_distance(const double *VA, int nva, const int *FA, int nfa,
                       const struct closest_point_tree *TA,
                       const double *VB, int nvb, const int *FB, int nfb,
                       const struct closest_point_tree *TB, double *hausdorff, double *rms);

/* Faces of A whose normal points against the normal of the face of B
 * closest to their centroid (n_A . n_B < 0): "flipped" relative to B. */
int flipped_faces(const double *VA, const int *FA, int nfa, const double *VB, const int *FB,
                  const struct closest_point_tree *TB);

/* The same test per face: flip (#FA, out, may be NULL) gets 1 for every
 * flipped face of A, 0 otherwise; returns their number. */
int flipped_face_flags(const double *VA, const int *FA, int nfa, const double *VB, const int *FB,
                       const struct closest_point_tree *TB, unsigned char *flip);

#ifdef __cplusplus
}
#endif
#endif
