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

/* orient2_sign and segments_meet by CGAL alone (the C inline versions
 * below answer the same, and call these only where their filter cannot
 * decide; C++ code calls these) */
int orient2_sign_exact(const double *a, const double *b, const double *c);
int segments_meet_exact(const double *a, const double *b, const double *c, const double *d);

#ifndef __cplusplus
#include <math.h>

/* Sign of the orientation of points a, b, c (each 2 doubles):
 * +1 counter-clockwise, -1 clockwise, 0 exactly collinear.
 * The determinant in doubles decides where it is farther from 0 than
 * Shewchuk's bound (3 + 16 eps) eps (|l| + |r|) on its rounding error
 * ("Adaptive precision floating-point arithmetic and fast robust
 * geometric predicates", 1997: orient2d's first stage; eps = 2^-53, no
 * fused multiply-add: ISO C, -ffp-contract=off); the terms are kept
 * normal and finite (an underflow inside the bound is far below it, and
 * no overflow).  Elsewhere CGAL's filtered exact predicate answers.  The
 * sign is the exact one either way, so the answers are CGAL's. */
static inline int orient2_sign(const double *a, const double *b, const double *c)
{
    double l = (a[0] - c[0]) * (b[1] - c[1]), r = (a[1] - c[1]) * (b[0] - c[0]);
    double det = l - r, sum = fabs(l) + fabs(r);
    if (sum > 1e-250 && sum < 1e300) {
        double eb = (3.0 + 16.0 * 0x1p-53) * 0x1p-53 * sum;
        if (det > eb) return 1;
        if (-det > eb) return -1;
    }
    return orient2_sign_exact(a, b, c);
}

/* Do the closed segments ab and cd share a point?  (exact: bounding
 * boxes, then the exact orientations; a collinear endpoint counts where
 * it lies in the other segment's box, i.e. on it) */
static inline int segments_meet(const double *a, const double *b, const double *c, const double *d)
{
    /* closed segments that meet have overlapping bounding boxes: most
     * pairs asked (an outline's chord against its other edges) are told
     * apart by comparisons alone */
    for (int k = 0; k < 2; k++) {
        double ab0 = a[k] < b[k] ? a[k] : b[k], ab1 = a[k] < b[k] ? b[k] : a[k];
        double cd0 = c[k] < d[k] ? c[k] : d[k], cd1 = c[k] < d[k] ? d[k] : c[k];
        if (ab1 < cd0 || cd1 < ab0) return 0;
    }
    int o1 = orient2_sign(a, b, c), o2 = orient2_sign(a, b, d);
    if (o1 && o1 == o2) return 0;
    int o3 = orient2_sign(c, d, a), o4 = orient2_sign(c, d, b);
    if (o3 && o3 == o4) return 0;
    if (o1 && o2 && o3 && o4) return 1;   /* a proper crossing */
    /* an endpoint on the other segment's line: on the segment iff in its box */
#define SEG_IN_BOX(p, q, x) ((((p)[0] <= (x)[0] && (x)[0] <= (q)[0]) || ((q)[0] <= (x)[0] && (x)[0] <= (p)[0])) && \
                             (((p)[1] <= (x)[1] && (x)[1] <= (q)[1]) || ((q)[1] <= (x)[1] && (x)[1] <= (p)[1])))
    int meet = (!o1 && SEG_IN_BOX(a, b, c)) || (!o2 && SEG_IN_BOX(a, b, d)) || (!o3 && SEG_IN_BOX(c, d, a)) ||
               (!o4 && SEG_IN_BOX(c, d, b));
#undef SEG_IN_BOX
    return meet;
}
#endif

/* Does the open segment ab meet the closed segment cd?  (exact; a touch at
 * a or b does not count) */
int open_segment_meets(const double *a, const double *b, const double *c, const double *d);

#ifdef __cplusplus
}
#endif
#endif
