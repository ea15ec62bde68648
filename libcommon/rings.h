/* rings.h -- 2D outlines as polygon rings.  Format (man 5 stopmo-rings):
 *
 *   ring 4            a ring header with its point count (>= 3)
 *   0 0               one "x y" line per point; the ring closes itself
 *   1 0               (do not repeat the first point)
 *   1 1
 *   0 1
 *   ring 3            further rings: holes (or separate pieces)
 *   ...
 *
 * The first ring is the outer boundary, counter-clockwise; holes clockwise.
 * A ring inside an odd number of rings is a hole, any other ring a separate
 * piece (counter-clockwise); see compat_nest() in compat_holes.h.
 * '#' comments and blank lines are allowed.  The reader keeps the line of
 * every point so later checks (self-intersection) can name it.
 */
#ifndef CM_RINGS_H
#define CM_RINGS_H
#include <stdio.h>
#ifdef __cplusplus
extern "C" {
#endif

struct rings {
    int nrings;      /* number of rings */
    int *start;      /* nrings+1 offsets into P: ring r is points start[r] .. start[r+1]-1 */
    double *P;       /* #P by 2 point coordinates, row-major (#P = start[nrings]) */
    long *line;      /* #P source line of each point (0 if not read from a file) */
    char name[256];  /* file name used in messages */
};

/* Read a rings file (path NULL or "-": stdin).  Checks syntax, counts,
 * finite numbers, >= 3 points per ring, no zero-length edges.
 * Errors: "cannot read 'x': line N: problem". */
int rings_read(const char *path, struct rings *r);
/* Write all rings ("ring N" + N lines), shortest round-trip numbers. */
int rings_write(FILE *f, const struct rings *r);
/* Build from one ring of n points (P: n by 2, copied). */
int rings_from_points(struct rings *r, const double *P, int n);
/* Append one ring of n points (P: n by 2, copied). */
int rings_append(struct rings *r, const double *P, int n);
void rings_free(struct rings *r);

static inline int rings_count(const struct rings *r, int k) { return r->start[k + 1] - r->start[k]; }
static inline double *rings_ring(const struct rings *r, int k) { return r->P + 2 * (size_t)r->start[k]; }

/* Signed area of ring k (> 0: counter-clockwise), summed in double: its
 * sign can be wrong by cancellation (coordinates far from the origin
 * relative to the ring's size); decide orientation with rings_orientation. */
double rings_area(const struct rings *r, int k);

/* Exact orientation of ring k: the sign of orient2_sign(prev, v, next) at
 * its lexicographically lowest vertex v (least x, then least y; the first
 * such if v repeats).  +1 counter-clockwise, -1 clockwise, 0 when the ring
 * turns back on itself at v (prev, v, next collinear).  For a simple ring
 * (rings_check_simple) this is the sign of its area and never 0.  For a
 * self-intersecting ring it is, by definition, the direction in which the
 * ring passes its extreme vertex (a corner of its convex hull); the signed
 * area can then disagree (a figure eight has area 0 and an orientation). */
int rings_orientation(const struct rings *r, int k);

/* Is ring k degenerate: all its points on one line (exact), or its area
 * below 1e-12 of its bounding-box diagonal squared? */
int rings_degenerate(const struct rings *r, int k);

/* Are all points of ring k on one line (exact orientation tests)?  Such
 * a ring encloses no area at all (unlike a figure eight, whose signed
 * area is 0 but which fills two lobes). */
int rings_collinear(const struct rings *r, int k);

/* Check that no two edges of any rings cross or touch (other than
 * consecutive edges at their shared point) and that no edge folds back
 * onto its neighbour.  Error names both edges by file line. */
int rings_check_simple(const struct rings *r);

/* rings_check_simple within each ring only: rings may cross each other
 * (layers of a drawing, compat-tri --layers).  The error names the ring. */
int rings_check_each_simple(const struct rings *r);

/* The first crossing rings_check_simple would report: 1 and the start
 * points e1 < e2 of the two edges (edge e runs from point e to the next
 * point of its ring), 0 if the rings are simple, -1 if out of memory. */
int rings_first_crossing(const struct rings *r, int *e1, int *e2);

/* Make the first ring counter-clockwise and all others clockwise by
 * rings_orientation (exact; reverses rings as needed, leaves a ring of
 * orientation 0 as it is; returns the number of rings reversed). */
int rings_orient(struct rings *r);

/* Smallest corner angle of ring k in radians, (0, 2 pi), measured on the
 * left of its direction (the inside of a counter-clockwise ring, the
 * outside of a clockwise one): no triangle of a mesh of the inside whose
 * outline keeps that corner has a larger angle there.  A zero-length edge
 * (which rings_read refuses) counts as a corner of 0. */
double rings_sharpest_left(const struct rings *r, int k);

/* How round a polygon is: the isoperimetric quotient 4 pi A / L^2 of its
 * convex hull (1 for a circle, 0.84 for a 2:1 ellipse, 0.785 for a
 * square; a traced outline's pixel staircase hardly changes its hull)
 * times its solidity, area over the hull's area (a C has a round hull but
 * little solidity).  compat-tri turns a ring whose roundness is high as its
 * surroundings: its shape cannot show how it turns.  P: n by 2, either
 * orientation, n >= 3; hull by exact orientation tests.  Returns a value
 * in [0, 1] (0: no area), -1 on out of memory. */
double polygon_roundness(const double *P, int n);

/* The diagonal of the bounding box of n points P (n by 2). */
double polygon_diagonal(const double *P, int n);

/* Reverse the point order (and the source lines) of ring k. */
void rings_reverse(struct rings *r, int k);

/* Segment predicates shared by the 2D tools.
 * orient2: twice the signed area of (a, b, c), > 0 counter-clockwise. */
static inline double orient2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}
/* Do closed segments ab and cd share any point? */
int segments_intersect(const double *a, const double *b, const double *c, const double *d);

/* Is point q strictly inside polygon ring P (n by 2)?  (even-odd rule) */
int point_in_ring(const double *P, int n, const double *q);

#ifdef __cplusplus
}
#endif
#endif
