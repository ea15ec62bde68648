/* compat_holes.h -- compatible triangulation of N shapes made of several
 * rings: outer rings (pieces, e.g. a body and a separate tail), holes
 * (eyes, the gap between two legs) and interior correspondence points,
 * matched ring by ring across the shapes (beyond Baxter, Barla, Anjyo,
 * "N-way morphing for 2D animation", whose limitations name both).
 *
 * Method (cuts, then the simple-polygon pipeline of compat_tri.h):
 *   compat_nest       classifies every ring as a piece or a hole by exact
 *                     containment (a ring inside an odd number of rings is a
 *                     hole), orients pieces counter-clockwise and holes
 *                     clockwise, and checks that every shape has the same
 *                     rings nested the same way (ring k matches ring k).
 *   compat_multi      matches and simplifies every ring on its own
 *                     (compat_match, compat_simplify with the tolerance
 *                     taken relative to the shape's bounding-box diagonal),
 *                     halving the tolerance until no two rings touch and
 *                     every interior point stays inside its piece, and
 *                     stacks rings and interior points as fixed vertices.
 *   compat_multi_triangulate
 *                     cuts every hole (and every interior point, a hole of
 *                     one vertex) off its piece by two straight cuts from
 *                     hole vertices to outer vertices that are inside the
 *                     domain in every shape (exact predicates), so each
 *                     piece with k holes becomes k+1 simple polygons with
 *                     corresponding corners; those are triangulated by
 *                     compat_triangulate_poly (diagonals, Steiner points,
 *                     overlay).  The two cuts of a hole are chosen to keep
 *                     the angles they make with the rings large, to be short
 *                     and to split the hole and the outline evenly.  Where
 *                     no hole of a piece has two straight cuts that fit,
 *                     cuts may bend: each follows the shortest path inside
 *                     every shape (visibility graph of the ring vertices,
 *                     Dijkstra), its bends moved off the rings into the
 *                     domain and made new vertices, as many in every shape;
 *                     a pair is kept where the pieces have the same cycles
 *                     and holes in every shape (c->nbent, c->nbend).
 */
#ifndef CM_COMPAT_HOLES_H
#define CM_COMPAT_HOLES_H
#include "compat_tri.h"
#include "rings.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Nesting and orientation of N shapes' rings.
 * R        N ring sets (modified: rings reversed to CCW pieces, CW holes)
 * parent   out: R[0].nrings entries, the innermost ring holding ring k, or
 *          -1 for a top-level piece (pieces inside holes are pieces again)
 * flipped  out: N by nrings flags, 1 where the ring was reversed
 * Returns -1 if the shapes have different ring counts or nestings
 * (cm_errmsg names the shape and ring). */
int compat_nest(int N, struct rings *R, int *parent, unsigned char *flipped);

/* The parent of a layer (compat_layers): a piece that may overlap the
 * other layers of its shape (never a hole, holds no hole). */
#define COMPAT_LAYER (-2)

/* Every ring a layer: parent[k] = COMPAT_LAYER, every ring made
 * counter-clockwise (flipped as for compat_nest).  Layers are matched by
 * order and triangulated each on its own, so they may cross each other
 * (a leg drawn over the body in one pose and apart in another); each
 * ring must be simple (rings_check_each_simple).  Returns -1 if the
 * shapes have different ring counts. */
int compat_layers(int N, struct rings *R, int *parent, unsigned char *flipped);

/* The meshes of n layers, each meshed on its own as one outer ring
 * (compat_triangulate, boundary vertices 0..nb-1 first), stacked into
 * one mesh c of the same N shapes: every layer's outline first, layer by
 * layer (ring r is layer r's: ring_start, parent COMPAT_LAYER), then the
 * layers' interior vertices in the same order; the faces layer by layer,
 * the first layer's first.  c: out (compat_free); parts are left as they
 * are.  Returns -1 out of memory or n < 1. */
int compat_stack(const struct compat *parts, int n, struct compat *c);

/* Ring b of r lies inside ring a: no edge of b meets an edge of a and
 * every vertex of b is strictly inside a (exact predicates). */
int compat_ring_inside(const struct rings *r, int b, int a);

/* Put every shape's rings in shape 0's order (for traced frames, whose
 * rings come in an order of their own, e.g. img2rings: by area): the
 * top-level rings, then recursively the rings inside matched rings, are
 * paired with shape 0's by the smallest sum of distances between their
 * mean vertices, taken relative to each shape's bounding box (exhaustive
 * up to 8 rings per level, greedy above).
 * R        N ring sets (rings of shapes 1.. reordered in place)
 * corr     ncorr by N global vertex indices (remapped in place)
 * moved    out: number of shapes whose order changed
 * order    out (N by nrings, or NULL): order[s * nrings + k] is the ring
 *          of shape s's file now at position k (k where unmoved)
 * Returns -1 if the shapes have different ring counts at some level. */
int compat_order_rings(int N, struct rings *R, int *corr, int ncorr, int *moved, int *order);

/* Is ring k of a nesting a hole (inside an odd number of rings)? */
int compat_is_hole(const int *parent, int k);

/* Ring k of r (oriented by compat_nest) as a counter-clockwise polygon: a
 * copy, reversed if it is a hole (clockwise).  rings_count(r, k) by 2,
 * malloc'd; NULL if out of memory. */
double *compat_ring_ccw(const struct rings *r, int k, int hole);

/* Matched, simplified rings and interior points of N shapes.
 * R        N oriented ring sets (compat_nest)
 * parent   nrings nesting (compat_nest); flipped: N by nrings
 * corr     ncorr by N row-major vertex indices counting the points of all
 *          rings in file order (before reversal); every row must name one
 *          ring in all shapes; a ring with no row gets its first vertex
 * pts      npts by N by 2 interior points (point i in shape s at
 *          pts[2*(i*N+s)]), each strictly inside one piece (not in its
 *          holes), the same piece in every shape; may be NULL if npts = 0
 * err      outline tolerance, fraction of each shape's bounding-box diagonal
 * c        out: rings stacked (c->ring_start), then the points, all fixed
 *          (c->nb = every ring vertex + npts); no faces yet
 * stats    out (may be NULL): [0] tolerance actually used (halved while
 *          rings touch), [1] largest two-sided Hausdorff distance over rings
 *          and shapes relative to the shape's diagonal, [2] its shape,
 *          [3] rings that had no correspondence row
 * Returns -1 with cm_errmsg "row K: ..." for a bad correspondence or point
 * row (K 1-based), other messages otherwise. */
int compat_multi(int N, struct rings *R, const int *parent, const unsigned char *flipped,
                 const int *corr, int ncorr, const double *pts, int npts, double err,
                 struct compat *c, double stats[4]);

/* Triangulate c (from compat_multi): cuts, then compat_triangulate_poly
 * on every simple piece.  Returns -1 if some hole or point has no pair of
 * cuts inside the domain in every shape (cm_errmsg names it). */
int compat_multi_triangulate(struct compat *c);

/* Next boundary vertex after vertex i along its ring (c->ring_start; one
 * ring 0..nb-1 if c->nrings is 0); -1 for interior points and vertices. */
int compat_boundary_next(const struct compat *c, int i);

#ifdef __cplusplus
}
#endif
#endif
