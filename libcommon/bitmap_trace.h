/* bitmap_trace.h -- outlines of the regions of a binary image: the pixel
 * boundaries (crack edges) between inside and outside pixels, linked into
 * closed loops with the inside on the left (y up), so outer boundaries run
 * counter-clockwise and holes clockwise.  Diagonal contacts are resolved
 * toward 4-connected inside regions (two pixels touching at a corner are
 * separate pieces).  Collinear runs are merged.
 */
#ifndef CM_BITMAP_TRACE_H
#define CM_BITMAP_TRACE_H
#include "rings.h"
#ifdef __cplusplus
extern "C" {
#endif

/* in: h by w flags (row-major, top row first), nonzero = inside.
 * out: rings in pixel units, x = column, y = h - row (y up), the outer
 * boundary of largest area first; loops of |area| < min_area dropped;
 * tol > 0: Douglas-Peucker simplification of each loop to that tolerance. */
int bitmap_trace(const unsigned char *in, int w, int h, double min_area, double tol,
                 struct rings *out);

#ifdef __cplusplus
}
#endif
#endif
