/* compat_tri.h -- N-way compatible triangulation of simple polygons
 * (Baxter, Barla, Anjyo, "N-way morphing for 2D animation", Sec. 3.1,
 * extending Baxter et al. 2008 "Compatible embedding for 2D shape
 * animation").
 *
 * Pipeline (each step a function):
 *   compat_match      boundary matching of every shape to shape 0: between
 *                     consecutive correspondence points, vertices are
 *                     placed by normalized arc length; the union of all
 *                     shapes' parameter values gives one common boundary
 *                     of M points, so no shape loses a vertex.
 *   compat_simplify   greedy removal of corresponding vertex N-tuples: the
 *                     tuple whose removal has the smallest error (the max
 *                     over shapes of the distance of the spanned original
 *                     points to the new chord, relative to the shape's
 *                     bounding-box diagonal) goes first, while the error is
 *                     below a threshold and every shape stays simple.
 *   compat_triangulate  divide and conquer: split the (sub)polygon by the
 *                     best vertex pair visible in all N shapes (stage I);
 *                     else by a pair joined through one interior Steiner
 *                     point in every shape (stage II); else by the pair
 *                     whose link path through interior candidate points
 *                     needs the fewest Steiner points over all shapes
 *                     (stage III, breadth-first link distances).
 *   compat_improve    compatible refinement (interior edge splits down to
 *                     a target length), compatible edge flips that raise
 *                     the minimum angle over all shapes, and smoothing of
 *                     interior vertices that never inverts a triangle.
 *
 * All positions are kept per shape: X[s] is #V by 2 for shape s.
 */
#ifndef CM_COMPAT_TRI_H
#define CM_COMPAT_TRI_H
#include <math.h>
#ifdef __cplusplus
extern "C" {
#endif

struct compat {
    int N;            /* number of shapes */
    int nv;           /* #V vertices (same in every shape) */
    int nb;           /* vertices 0..nb-1 are the boundary, in CCW order */
    double **X;       /* N arrays, each #V by 2 */
    int nf;           /* #F triangles */
    int *F;           /* #F by 3, counter-clockwise in every shape */
    int nsteiner;     /* interior vertices added by stages II-III */
    int nrefine;      /* interior vertices added by refinement */
    int nbent, nbend; /* cuts joining holes to their pieces that bend
                       * (compat_multi_triangulate), and their bend points
                       * (counted in nsteiner too) */
    int stage_count[3]; /* splits made by stage I, II, III (or overlays) */
    int split_mode;   /* COMPAT_OVERLAY (default), COMPAT_OVERLAY_FEWEST or COMPAT_LINKPATH */
    int threads;      /* the split search runs on this many threads (0: one
                       * per processor); the mesh does not depend on it */
    int exhaustive;   /* 1: the split search's inside tests try every edge of
                       * a piece, not the edges of a grid's cells (tests: the
                       * mesh is the same) */
    int cap;          /* private: allocated vertices */
    int fcap;         /* private: allocated faces */
    /* private: the matched boundary before simplification (for errors) */
    int nm;           /* M merged boundary points */
    double **B;       /* N arrays, M by 2 */
    /* several rings (compat_holes.h; 0 / NULL for one outer ring 0..nb-1):
     * ring r is vertices ring_start[r] .. ring_start[r+1]-1 (pieces CCW,
     * holes CW), then npts interior correspondence points; all nb fixed */
    int nrings;
    int *ring_start;  /* nrings + 1 */
    int *ring_parent; /* nrings: enclosing ring, -1 for a piece */
    int npts;
    int *pt_ring;     /* npts: the piece (outer ring) holding each point */
    /* one outer ring (set by compat_simplify; NULL otherwise): bidx[v] is
     * the index in B of boundary vertex v (0..nb-1); bpin (nb flags, set by
     * the caller, NULL: none) marks the given correspondence points, which
     * never slide along the outline (compat_refine_params.slide) */
    int *bidx;
    unsigned char *bpin;
    /* progress of compat_triangulate (and _poly), NULL: none.  Called on
     * the calling thread (never from the split search's threads) with done,
     * the share (0..1) of the piece's area in shape 0 already in finished
     * triangles or in pieces left for the threads; for a progress bar of
     * a long triangulation (the first cuts of a large piece take longest) */
    void (*progress)(void *ctx, double done);
    void *progress_ctx;
    double prog_total, prog_done;   /* private: of the triangulation running */
};

/* Room for nv vertices in every shape's X (grows c->cap by doubling;
 * existing positions kept).  Returns -1 on out of memory (cm_errmsg set). */
int compat_reserve_vertices(struct compat *c, int nv);

/* Boundary matching.
 * N      number of shapes
 * P      N arrays: P[s] is n[s] by 2, a simple CCW polygon
 * n      N point counts
 * corr   ncorr by N indices (row-major): corr[k*N+s] is the vertex of shape s
 *        matching correspondence k; increasing cyclically along every ring
 * c      out: boundary of c->nv = c->nb = M points (no faces yet)
 * keep   out (may be NULL): M flags, 1 for correspondence points (malloc'd)
 * Returns -1 on invalid correspondences. */
int compat_match(int N, double *const *P, const int *n, const int *corr, int ncorr,
                 struct compat *c, unsigned char **keep);

/* Check and normalize the cyclic order of the correspondence rows (corr:
 * ncorr by N, as for compat_match; n: N ring sizes of counter-clockwise
 * rings).  Rows listed clockwise along every ring are reversed in place.
 * Returns 0 (as given), 1 (reversed), -1 (out of range, repeated vertex,
 * no single cyclic order, or shapes disagree; cm_errmsg says which). */
int compat_corr_order(int N, const int *n, int *corr, int ncorr);

/* Two-sided Hausdorff distance between shape s's boundary (c->X[s],
 * vertices 0..nb-1) and the input ring P (n by 2), divided by the ring's
 * bounding-box diagonal.  Input vertices to the boundary exactly; the
 * boundary to the ring at 16 points per boundary edge. */
double compat_outline_error(const struct compat *c, int s, const double *P, int n);

/* Distance from the point p (2) to the segment a-b (2 each, 2D). */
double compat_seg_dist(const double *p, const double *a, const double *b);

/* Where the point p (2) lies on the closed polyline B (M by 2): the segment
 * i -> i+1 (mod M) nearest the index home (searched outwards, both ways)
 * that p lies within eps of.  Returns i and sets *t to p's fraction along
 * it, clamped to [0, 1]; -1 when p is within eps of no segment. */
int compat_polyline_locate(const double *B, int M, int home, const double *p, double eps, double *t);

/* Greedy compatible simplification of the boundary; err: threshold as a
 * fraction of each shape's bounding-box diagonal; keep: M flags of points
 * never removed.  Returns the new boundary size. */
int compat_simplify(struct compat *c, double err, const unsigned char *keep);

/* What to do with a piece that no common diagonal and no single Steiner
 * point splits: triangulate it by overlay (cdt2_overlay: always succeeds)
 * of each shape's constrained Delaunay triangulation (COMPAT_OVERLAY,
 * Aronov et al.) or of the triangulations chosen to cross least
 * (COMPAT_OVERLAY_FEWEST), or, as in Baxter et al., split it along a path
 * of several Steiner points (link distances through candidate points; can
 * fail on thin pieces). */
enum { COMPAT_OVERLAY = 0, COMPAT_LINKPATH = 1, COMPAT_OVERLAY_FEWEST = 2 };

/* Compatible triangulation of the boundary polygons (interior Steiner
 * points appended after the boundary).  Returns -1 if it fails. */
int compat_triangulate(struct compat *c);

/* Compatible triangulation of one simple sub-polygon: poly lists m vertex
 * ids, counter-clockwise in every shape.  Faces and Steiner points are
 * appended (c->nf is not reset).  Returns -1 if it fails. */
int compat_triangulate_poly(struct compat *c, int *poly, int m);

/* Refinement to a target edge length (fraction of the bounding-box
 * diagonal, <= 0: none), flips and smoothing (iters rounds). */
int compat_improve(struct compat *c, double target, int iters);

/* One pass of compatible edge flips: an interior edge is flipped when the
 * new pair is positive in all shapes (exact) and its smallest angle over the
 * shapes is larger (by 1e-9 rad); each triangle flips at most once per pass.
 * Returns the number of flips, -1 on out of memory. */
int compat_flip_pass(struct compat *c);

/* compat_flip_pass until a pass flips nothing, at most passes passes (the
 * same flips, but after the first pass only the edges of triangles the
 * pass before rewrote are looked at); adds the flips to *nflips.  0, or -1
 * on out of memory. */
int compat_flip_passes(struct compat *c, int passes, int *nflips);

/* Minimum angle (radians) over all triangles of all shapes; *minarea gets
 * the smallest signed area divided by the shape's squared diagonal
 * (> 0 iff every triangle is positively oriented in every shape). */
double compat_min_angle(const struct compat *c, double *minarea);

/* Sine of the smallest angle of the triangle (a, b, d) (points of 2
 * coordinates); the smallest angle is at most 60 degrees, so the sine
 * orders triangles as the angle does.  0 if the floating-point signed area
 * is not positive (counter-clockwise is positive). */
static inline double compat_sin_min_angle(const double *a, const double *b, const double *d)
{
    double e0x = b[0] - a[0], e0y = b[1] - a[1], e1x = d[0] - b[0], e1y = d[1] - b[1];
    double e2x = a[0] - d[0], e2y = a[1] - d[1];
    double l0 = e0x * e0x + e0y * e0y, l1 = e1x * e1x + e1y * e1y, l2 = e2x * e2x + e2y * e2y;
    double area2 = e0x * (d[1] - a[1]) - e0y * (d[0] - a[0]);
    if (!(area2 > 0)) return 0;
    double p = l0 <= l1 && l0 <= l2 ? l1 * l2 : l1 <= l2 ? l0 * l2 : l0 * l1;
    return area2 / sqrt(p);
}

void compat_free(struct compat *c);

#ifdef __cplusplus
}
#endif
#endif
