/* quad_modulus.h -- a guaranteed bracket of the conformal modulus of a
 * polygon quadrilateral: a simple polygon with four marked corners
 * a, b, c, d in counter-clockwise order.
 *
 * The modulus M is the Dirichlet energy of the harmonic function u with
 * u = 0 on the boundary arc a..b, u = 1 on the arc c..d and zero normal
 * derivative on the arcs b..c and d..a (for the rectangle [0,w] x [0,h]
 * with a, b, c, d its corners from (0,h) counter-clockwise: u = x / w and
 * M = h / w).  It is the extremal length of the curves joining arc b..c
 * to arc d..a, a conformal invariant, and a K-quasiconformal map changes
 * it by at most a factor K.
 *
 * Bounds (both rigorous up to floating-point rounding of the energies):
 *   hi = the energy of the conforming P1 finite-element solution (the
 *        harmonic function minimizes the energy among all functions with
 *        those boundary values, the P1 solution is one of them);
 *   lo = 1 / (the same on the conjugate quadrilateral b, c, d, a, whose
 *        modulus is exactly 1 / M).
 * hi / lo - 1 measures the discretization error.  The mesh is a CGAL
 * Delaunay mesh of the polygon (cdt2_mesh_polygon) refined adaptively by
 * longest-edge bisection (Rivara) where the Prager-Synge indicator
 * |grad u - M J grad v|^2 (v the conjugate solution, J the rotation by 90
 * degrees) is largest, which grades the mesh toward the singularities at
 * the marked points and the re-entrant corners.  The sparse solves use
 * CHOLMOD (spd.h).  Deterministic: the same input gives the same bits.
 */
#ifndef CM_QUAD_MODULUS_H
#define CM_QUAD_MODULUS_H
#ifdef __cplusplus
extern "C" {
#endif

struct quad_modulus;   /* a quadrilateral, its mesh and its current bracket */

/* Mesh the polygon and compute the first bracket.
 * P      n by 2 corners of a simple counter-clockwise polygon (copied)
 * n      corner count (>= 3)
 * idx    4 corner indices a, b, c, d (0..n-1), distinct, in increasing
 *        cyclic order counter-clockwise (a < b < c < d after a rotation)
 * Returns NULL (cm_errmsg set) on a clockwise or degenerate polygon, bad
 * indices, a failed mesh or solve. */
struct quad_modulus *quad_modulus_new(const double *P, int n, const int idx[4]);

/* The same polygon with other corners, starting from q's current mesh
 * (the polygon is meshed once for many quadruples).
 * q      a quadrilateral of quad_modulus_new (its mesh is copied)
 * idx    4 corner indices, as for quad_modulus_new
 * Returns NULL (cm_errmsg set) on bad indices, out of memory, a failed solve. */
struct quad_modulus *quad_modulus_recorner(const struct quad_modulus *q, const int idx[4]);

/* Refine until hi <= (1 + tol) lo or the mesh has max_nv vertices (the
 * bracket is then looser than asked; not an error).
 * tol     relative width wanted (e.g. 0.02)
 * max_nv  vertex budget of the mesh (e.g. 200000)
 * Returns 0, or -1 (cm_errmsg set) on out of memory or a failed solve. */
int quad_modulus_refine(struct quad_modulus *q, double tol, int max_nv);

/* The current bracket lo <= M <= hi, and the mesh size (out, may be NULL). */
void quad_modulus_bracket(const struct quad_modulus *q, double *lo, double *hi, int *nv);

void quad_modulus_free(struct quad_modulus *q);

/* All in one: quad_modulus_new + quad_modulus_refine; lo, hi out.
 * Returns 0 or -1 (cm_errmsg set). */
int quad_modulus(const double *P, int n, const int idx[4], double tol, int max_nv, double *lo,
                 double *hi);

#ifdef __cplusplus
}
#endif
#endif
