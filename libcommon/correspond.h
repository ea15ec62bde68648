/* correspond.h -- closest-point correspondences with the usual rejections
 * of ICP-style registration (nricp.h, arap_fit.h).
 *
 * For every query point q_i with normal m_i, the closest point c_i on a
 * surface (V, F with vertex normals N) and whether the pair is kept:
 * rejected when c_i lies on the surface's boundary, when the surface normal
 * at c_i (N interpolated with the barycentrics) and m_i are more than
 * max_angle apart, or when |q_i - c_i| > max_dist.
 */
#ifndef CM_CORRESPOND_H
#define CM_CORRESPOND_H
#include "closest_point.h"
#include "topology.h"
#ifdef __cplusplus
extern "C" {
#endif

/* T: tree of the surface (V #V by 3, F #F by 3); N: #V by 3 vertex
 * normals (any length); t: its topology (for the boundary test);
 * Q: n by 3 query points, M: n by 3 their normals;
 * cosmax: cos(max_angle); max_dist <= 0: no distance test;
 * search > 0: when the closest point's normal disagrees, take instead the
 * nearest point within its distance + search whose normal agrees (the other
 * side of a thin part), if any;
 * I: n (in: hints, face ids from a previous call when hinted != 0; out: the
 * closest faces), C: n by 3 closest points, B: n by 3 their barycentrics,
 * ok: n flags (out; may be NULL).  Returns the number of rejected pairs. */
int correspond(const struct closest_point_tree *T, const int *F, const double *N,
               const struct topology *t, const double *Q, const double *M,
               int n, double cosmax, double max_dist, double search, int hinted, double *C,
               int *I, double *B, unsigned char *ok);

/* The surface normal at barycentrics b of face f: sum_k b_k N[F[f][k]]. */
void correspond_normal(const double *N, const int *F, int f, const double *b, double n[3]);

/* Does the point with barycentrics b in face f lie on the boundary of the
 * surface (on an edge with one face)? */
int correspond_on_boundary(const struct topology *t, int f, const double *b);

#ifdef __cplusplus
}
#endif
#endif
