/* maxmin_polish.h -- raise the smallest angle of one planar triangle mesh
 * by moving all its free vertices at once.
 *
 * The smallest angle over a mesh is not smooth, and a vertex-by-vertex
 * search on it (compat_refine's polish) stops where every single vertex
 * is held by a triangle it cannot improve alone, though a joint move of
 * several would.  maxmin_polish ascends a smooth stand-in instead, the
 * soft minimum -(1/beta) log sum exp(-beta theta) over every angle theta
 * of every triangle, for all free vertices together (L-BFGS, backtracking
 * line search, no step that makes a triangle non-positive), for a rising
 * sequence of beta (the soft minimum tends to the minimum as beta grows).
 * The positions with the largest true smallest angle seen are kept, and
 * only if they beat the start and every triangle is positive by the exact
 * predicate.  Triangles whose three corners all stay are left out (their
 * angles cannot change: a sharp outline corner must not hold the rest). */
#ifndef CM_MAXMIN_POLISH_H
#define CM_MAXMIN_POLISH_H

struct maxmin_params {
    int iters;            /* L-BFGS steps per beta at most (default 100) */
    int nbeta;            /* number of betas (default 4) */
    double beta[8];       /* per radian, rising (default 120 240 480 960) */
};

void maxmin_defaults(struct maxmin_params *p);

/* X: 2 nv coordinates (changed in place), F: nf counter-clockwise faces;
 * fixed: nv flags of vertices that stay; seg: NULL, or 2 nv entries:
 * a fixed vertex v with seg[2v] >= 0 slides instead along the segment
 * from vertex seg[2v] to vertex seg[2v+1] (both fixed), strictly inside
 * it.  *before, *after (may be NULL): the smallest angle (radians) over
 * the triangles with a corner that moves, before and after (-INFINITY if
 * a triangle is not positive: nothing is done).  Returns 1 if the
 * vertices moved, 0 if not, -1 out of memory (cm_error). */
int maxmin_polish(double *X, int nv, const int *F, int nf, const unsigned char *fixed, const int *seg,
                  const struct maxmin_params *p, double *before, double *after);

/* The outline of a one-ring mesh whose vertices slide along the mesh's
 * input outline B (a closed polyline of M points, counter-clockwise like
 * the mesh) in maxmin_polish_curve. */
struct maxmin_curve {
    const double *B;
    int M;
    const int *bsucc;        /* nv: the next outline vertex along the outline,
                                -1 for an interior vertex */
    const int *home;         /* nv: for an outline vertex not made by a split
                                (a knot: seg[2v] < 0), an index of B near
                                which it lies on B (the point is found on the
                                B segment nearest that index that it lies on
                                to rounding), -1 otherwise */
    const unsigned char *slides; /* nv: 1 for a knot that slides along B */
    double tol;              /* the chord between two consecutive knots stays
                                within tol of every point of B it spans */
};

/* maxmin_polish in which the knots with slides[v] move along B as well:
 * each by its arc-length position on B (piecewise linear), and every
 * vertex made by a split (seg[2v] >= 0: its ends seg[2v], seg[2v+1] are
 * the knots before and after it) by its fraction of the chord between its
 * ends, which may move.  Every step of the line search keeps the knots in
 * their order along B (so between the fixed knots on either side), the
 * split vertices in theirs, each chord within tol of the points of B it
 * spans and crossing no other chord (exact), and every triangle positive;
 * the result is checked again (exact).  All other arguments and the result
 * as maxmin_polish; cv NULL is maxmin_polish. */
int maxmin_polish_curve(double *X, int nv, const int *F, int nf, const unsigned char *fixed, const int *seg,
                        const struct maxmin_curve *cv, const struct maxmin_params *p, double *before,
                        double *after);

#endif
