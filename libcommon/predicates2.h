/* predicates2.h -- exact 2D orientation predicates (CGAL's
 * Exact_predicates_inexact_constructions_kernel: a floating-point filter
 * with an exact fallback), for the 2D tools' combinatorial decisions
 * (which side of a line, do two segments meet).  The inputs are taken as
 * the exact doubles they are; the answers are never wrong by rounding.
 */
#ifndef CM_PREDICATES2_H
#define CM_PREDICATES2_H
#ifdef __cplusplus
extern "C" {
#endif

/* Sign of the orientation of points a, b, c (each 2 doubles):
 * +1 counter-clockwise, -1 clockwise, 0 exactly collinear. */
int orient2_sign(const double *a, const double *b, const double *c);

/* Do the closed segments ab and cd share a point?  (exact) */
int segments_meet(const double *a, const double *b, const double *c, const double *d);

/* Does the open segment ab meet the closed segment cd?  (exact; a touch at
 * a or b does not count) */
int open_segment_meets(const double *a, const double *b, const double *c, const double *d);

#ifdef __cplusplus
}
#endif
#endif
