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

/* As symmetric_distance()'s Hausdorff distance, with the samples of B
 * that lie over A where A already fits left out (correspond_overlay(): a
 * sample t of B whose closest point c of A has A's own distance to B,
 * interpolated from A's vertices, below ratio |t - c|, while |t - c| is
 * more than tau_factor times the RMS distance of A's samples): surface of
 * a scan that the registered mesh A has no part for (a cap that mesh-clean
 * laid across a hole of a face mask).  ratio <= 0: nothing left out.
 * left_out (may be NULL): how many samples of B were.  Returns 0, -1 on
 * error. */
int overlay_distance(const double *VA, int nva, const int *FA, int nfa,
                     const struct closest_point_tree *TA,
                     const double *VB, int nvb, const int *FB, int nfb,
                     const struct closest_point_tree *TB, double ratio, double tau_factor,
                     double *hausdorff, int *left_out);

/* Faces of A that point against B: the normal of a face of A points
 * against the whole normal cone of B at the point closest to the face's
 * centroid, i.e. has a negative dot product with B's face normal there
 * inside a face, with both face normals on an edge, with all the incident
 * face normals at a vertex.  So a face that lies across a sharp crease of B
 * (cutting its corner) is judged against both sides, not against whichever
 * side happened to be nearest.  Where B is thinner than the distance of A
 * to it (an ear, a fin) either side may be nearest, so with tol > 0 a face
 * is not counted when a face of B within its distance + tol faces its way
 * (normal dot > 0).  VB: #VB by 3 (nvb), FB: #FB by 3 (nfb), TB: the tree
 * of B, tol: a distance (0: no allowance).  Returns the count, or -1 (out
 * of memory). */

/* The tools' allowance for thin parts: this fraction of B's bounding-box
 * diagonal (about a tenth of an edge on a 10k-face scan). */
#define FLIP_THIN_TOL 1e-3

int flipped_faces(const double *VA, const int *FA, int nfa, const double *VB, int nvb,
                  const int *FB, int nfb, const struct closest_point_tree *TB, double tol);

/* The same test per face: flip (#FA, out, may be NULL) gets 1 for every
 * flipped face of A, 0 otherwise; returns their number. */
int flipped_face_flags(const double *VA, const int *FA, int nfa, const double *VB, int nvb,
                       const int *FB, int nfb, const struct closest_point_tree *TB,
                       double tol, unsigned char *flip);

/* Many frames against one reference (mesh-metrics): the reference's tree,
 * topology, samples and normals are built once; the closest faces found
 * for one frame start the next frame's queries, so a coherent animation
 * (or a registration with the reference's connectivity) costs a fraction
 * of a cold search.  The results are those of one_sided_distance() both
 * ways and flipped_face_flags() with A = the frame, B = the reference.
 *
 *   C = frame_compare_new(VR, nvr, FR, nfr);    VR must outlive C
 *   for each frame X: frame_compare_run(C, X, nv, F, nf, tol, &d, flip, face_fit);
 *   frame_compare_free(C);
 */
struct frame_compare;
struct frame_distance {
    struct one_sided fit;    /* the frame's samples to the reference */
    struct one_sided cover;  /* the reference's samples to the frame */
    int flipped;             /* faces of the frame pointing against the reference */
    int flipped_zone;        /* of those, the faces whose centroid's closest reference point
                                lies on a face of the zone (frame_compare_set_zone; 0 without) */
    double cover_clear;      /* the largest distance to the frame of a reference sample off
                                the zone (cover.max without a zone) */
};
/* VR: #VR by 3 (nvr), FR: #FR by 3 (nfr).  NULL on error (cm_errmsg). */
struct frame_compare *frame_compare_new(const double *VR, int nvr, const int *FR, int nfr);
/* X: #V by 3 (nv), F: #F by 3 (nf), any connectivity (it may change from
 * call to call; hints are kept while it stays the same); tol: the thin-part
 * allowance of flipped_face_flags() (a distance); out: the distances and
 * flipped count; flip (#F, may be NULL): 1 for flipped faces; face_fit (#F,
 * may be NULL): per face the largest distance of its samples (corners,
 * centroid, edge midpoints) to the reference.  Returns 0, -1 on error. */
int frame_compare_run(struct frame_compare *C, const double *X, int nv, const int *F, int nf,
                      double tol, struct frame_distance *out, unsigned char *flip, double *face_fit);
void frame_compare_free(struct frame_compare *C);
/* A zone of the reference reported apart by frame_compare_run() (e.g. the
 * reference's buried skin, buried.h): zone (#F of the reference, copied)
 * flags its faces; a sample of the reference is in the zone when a face
 * it lies on is (a vertex: any incident face).  NULL: no zone.  Returns 0,
 * -1 (out of memory). */
int frame_compare_set_zone(struct frame_compare *C, const unsigned char *zone);

#ifdef __cplusplus
}
#endif
#endif
