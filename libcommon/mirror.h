/* mirror.h -- mirror symmetry of a surface: the plane, the map of every
 * triangle to its mirror image, and how far a set of points (a seam) is
 * from its own mirror image.  Used by seg-graphcut --symmetric.
 *
 * A plane is 4 numbers (n_x, n_y, n_z, d) with |n| = 1: the points x with
 * n.x = d.  The mirror of x is S(x) = x - 2 (n.x - d) n.
 *
 * Finding the plane (mirror_plane_find): the three principal planes
 * through the area-weighted centroid (covariance eigenvectors by LAPACK
 * dsyev) are candidates; each is refined by ICP of the surface with its
 * reflection: reflect the vertices, take their closest points on the
 * surface (CGAL AABB tree), keep the closest 90% of the pairs, fit the
 * rigid motion (R, t) that maps the reflected points onto them
 * (procrustes.h), and read the new plane off the improper isometry
 * x -> R S(x) + t: n = eigenvector of the symmetric part of its linear map
 * with the lowest eigenvalue (-1 for a reflection), d = n.b / 2 with b its
 * translation.  The candidate with the lowest RMS of |S(v) - closest| wins.
 */
#ifndef CM_MIRROR_H
#define CM_MIRROR_H
#ifdef __cplusplus
extern "C" {
#endif

/* y (3, out) = S(x) for plane (4).  y may be x. */
void mirror_point(const double plane[4], const double x[3], double y[3]);

/* The plane of mirror symmetry of the surface V (nv by 3), F (nf by 3):
 * plane (4, out).  iterations: ICP steps per candidate (<= 0: 30).
 * *rms (out, may be NULL): RMS distance of the reflected vertices to the
 * surface at the found plane, *worst (out, may be NULL): the largest of
 * those distances in the kept 90%, both in model units.  Returns 0, or -1
 * with cm_errmsg (empty or degenerate mesh). */
int mirror_plane_find(const double *V, int nv, const int *F, int nf, int iterations,
                      double plane[4], double *rms, double *worst);

/* Plane (4, in/out) refined by ICP from the given one, as above. */
int mirror_plane_refine(const double *V, int nv, const int *F, int nf, int iterations,
                        double plane[4], double *rms, double *worst);

/* RMS distance of the reflected vertices to the surface for a given plane
 * (no refinement): how symmetric the surface is about it. */
double mirror_plane_rms(const double *V, int nv, const int *F, int nf, const double plane[4]);

/* mf (nf, out): for every face f, the face holding the closest surface
 * point to the reflection of f's centroid; dist (nf, out, may be NULL): that
 * distance.  Returns 0, or -1 with cm_errmsg. */
int mirror_faces(const double *V, int nv, const int *F, int nf, const double plane[4], int *mf,
                 double *dist);

/* Hausdorff distance between a polyline set (n segments, G: n by 6, the
 * two ends of each) and its reflection, sampled: the largest distance from
 * the reflection of a segment's ends and midpoint to the nearest segment
 * (S is an involution and an isometry, so the direction does not matter).
 * Exact at the samples; between them it may be larger by at most a
 * quarter of the longest segment.  0 for n = 0.  O(n^2). */
double mirror_hausdorff(const double *G, int n, const double plane[4]);

#ifdef __cplusplus
}
#endif
#endif
