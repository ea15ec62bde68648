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

/* Target surface over a part of the source that already fits: a face
 * scan's holes closed by mesh-clean (a cap across the mouth, or across a
 * part's opening, lying over the skin) or another part's surface (a lid
 * over an eye).  The backward pair (target point t, its closest point c of
 * the source) is such an overlay when the source's own distance to the
 * target at c is below ratio |t - c| while |t - c| exceeds tau: the source
 * there has a nearer partner, t has none in the source.  Where the source
 * is one closed surface every target point must be covered by it, so the
 * registrations test this only for sources with parts (correspond_parts).
 *
 * correspond_overlay: F the source's faces, f and b c's face and
 * barycentrics, d (#V) every source vertex's distance to the target, dist
 * |t - c|.  Returns 1 for an overlay. */
int correspond_overlay(const int *F, int f, const double *b, const double *d, double dist,
                       double ratio, double tau);

/* tau of correspond_overlay: factor times the RMS of |Q_i - C_i| over the
 * pairs with ok[i] (all when ok is NULL); n pairs. */
double correspond_overlay_scale(const double *Q, const double *C, const unsigned char *ok, int n,
                                double factor);

/* Does a mesh have parts: an open boundary (holes: a face mask's mouth and
 * eyes) or several connected components (eyes, teeth beside the skin)?
 * The registrations' precautions for such sources (correspond_overlay,
 * arap_fit's rest_keep) apply only then: a closed single surface (the
 * camel) registers as before.  Returns 1 (parts), 0 (none) or -1 (out of
 * memory; cm_errmsg). */
int correspond_parts(const struct topology *t, const int *F);

#ifdef __cplusplus
}
#endif
#endif
