/* seam.h -- part seams of a per-triangle part labeling (StopShop Sec. 3.2).
 *
 * A seam vertex is a vertex whose incident triangles carry more than one
 * label.  The homogenization of Eq. 4-9 fixes the seam vertices and their
 * one-ring (the discrete gradient condition, Eq. 6) to their average.
 *
 * F  #F by 3 vertex indices, P  #F part labels (any integers),
 * t  the topology of F (topology.h).
 */
#ifndef CM_SEAM_H
#define CM_SEAM_H
#include "topology.h"
#ifdef __cplusplus
extern "C" {
#endif

/* is_seam: #V flags (out): 1 if the faces around v carry more than one
 * label, else 0.  Returns the number of seam vertices. */
int seam_vertices(const struct topology *t, const int *P, unsigned char *is_seam);

/* Fail (return -1, cm_errmsg names the edge) if an edge with more than two
 * incident faces has a seam vertex as an endpoint: the seam of a
 * non-manifold edge has no well-defined side. */
int seam_check_manifold(const struct topology *t, const unsigned char *is_seam);

/* Grow a vertex set by `rings` rings of neighbours: flags #V in/out,
 * nonzero = in the set. */
void seam_grow(const struct topology *t, unsigned char *flags, int rings);

/* Vertex roles for seam homogenization.  role: #V (out):
 *   SEAM_FIXED  seam vertices and `rings` rings around them: set to the average
 *   SEAM_KEEP   vertices of a connected component that has no seam vertex
 *               (a whole component in one part) and isolated vertices: the
 *               displacement is 0 there, the minimizer of Eq. 4 without
 *               constraints (it also keeps the free block positive definite)
 *   SEAM_FREE   everything else: the unknowns of Eq. 4
 * F: #F by 3.  Returns the number of SEAM_FIXED vertices. */
enum { SEAM_FREE = 0, SEAM_FIXED = 1, SEAM_KEEP = 2 };
int seam_roles(const struct topology *t, const int *F, const unsigned char *is_seam,
               int rings, unsigned char *role);

/* Confine the homogenization to a band around the seam: vertices with
 * role SEAM_FREE whose geodesic distance (heat method on V, F, geodesic.h)
 * from the nearest seam vertex exceeds `width` become SEAM_KEEP (zero
 * displacement).  The squared-Laplacian minimizer then fades the seam's
 * correction smoothly (value and slope) to zero across the band, and
 * geometry beyond it stays exactly as it is in the input.
 *   V      #V by 3 positions (the average mesh),  F  #F by 3 faces,
 *   t      topology of F,  is_seam  #V flags (seam_vertices())
 *   width  band width (units of V, > 0)
 *   role   #V in/out (seam_roles())
 *   dist   #V (out, may be NULL): distance from the seam, INFINITY in
 *          components without a seam
 * Returns the number of vertices pinned, or -1 (cm_errmsg set). */
int seam_band(const double *V, const int *F, const struct topology *t,
              const unsigned char *is_seam, double width, unsigned char *role, double *dist);

#ifdef __cplusplus
}
#endif
#endif
