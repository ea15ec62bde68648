/* cdt2.h -- quality triangulation of a planar domain: CGAL constrained
 * Delaunay triangulation refined by the CGAL 2D mesher (Delaunay_mesher_2,
 * Ruppert/Shewchuk-style: angle bound and edge-size bound), used to
 * tessellate pose space for biharm-weights (N-way morphing Sec. 4.1, where
 * the paper used Shewchuk's Triangle).
 */
#ifndef CM_CDT2_H
#define CM_CDT2_H
#ifdef __cplusplus
extern "C" {
#endif

/* Mesh the axis-aligned box lo..hi with the points P as vertices.
 * lo, hi   2 box corners
 * P        np by 2 points strictly inside the box (distinct)
 * size     upper bound on edge length
 * V        out: #V by 2 vertex positions (malloc'd)
 * F        out: #F by 3 counter-clockwise triangles (malloc'd)
 * pidx     out: np vertex indices, pidx[i] = vertex of point i
 * Returns -1 on failure (cm_errmsg set). */
int cdt2_mesh_box(const double lo[2], const double hi[2], const double *P, int np, double size,
                  double **V, int *nv, int **F, int *nf, int *pidx);

/* Compatible triangulation of one polygon given in N shapes, by overlay
 * (Aronov, Seidel, Souvaine 1993): every shape's polygon is triangulated
 * without new points (constrained Delaunay), the m corners are put on a
 * circle in the same order, where every shape's diagonals become chords;
 * the chords of all shapes are overlaid (constrained triangulation with
 * exact intersections), and every vertex of the overlay is mapped back
 * into each shape through the barycentric coordinates of the shape's
 * triangle that holds it.  Each overlay triangle lies in one triangle of
 * every shape, so it is positive in all of them (up to the rounding of the
 * mapped points to doubles, which the caller checks).  Always succeeds on
 * simple counter-clockwise polygons; costs Steiner points (the chord
 * crossings), so it is the fallback for pieces the divide and conquer
 * cannot split.
 * With fewest != 0 each shape's triangulation is chosen, among those no
 * thinner than its constrained Delaunay one's thinnest triangle, to cross
 * the other shapes' as little as possible on the circle (coordinate
 * descent over the shapes, each step an exact O(m^3) dynamic program over
 * the shape's diagonals): fewer Steiner points than with every shape's
 * Delaunay triangulation as in Aronov et al. (fewest = 0).
 * m        corners
 * N        shapes
 * X        N arrays of m by 2 corner positions (simple, counter-clockwise)
 * fewest   1: triangulations with the fewest crossings; 0: each shape's
 *          constrained Delaunay triangulation
 * S        out: N arrays (malloc'd, stacked: *S is N by k by 2) of the k new
 *          vertices' positions, shape by shape
 * k        out: number of new vertices (numbered m .. m+k-1)
 * F        out: #F by 3 counter-clockwise triangles over 0..m+k-1 (malloc'd)
 * Returns -1 on failure (cm_errmsg set). */
int cdt2_overlay(int m, int N, const double *const *X, int fewest, double **S, int *k, int **F, int *nf);

/* Quality mesh of one simple polygon (CGAL Delaunay_mesher_2, the
 * baseline compat-tri's refinement is measured against in bench/).
 * P        n by 2 corners, simple (either orientation)
 * shape    CGAL's shape bound B = sin^2 of the smallest angle (0.125:
 *          about 20.7 degrees)
 * size     upper bound on edge length (0: none)
 * V, nv    out: #V by 2 positions (the corners among them; malloc'd)
 * F, nf    out: #F by 3 counter-clockwise triangles (malloc'd)
 * Returns -1 on failure (cm_errmsg set). */
int cdt2_mesh_polygon(const double *P, int n, double shape, double size,
                      double **V, int *nv, int **F, int *nf);

/* The m - 2 triangles of a simple polygon without new points (CGAL
 * constrained Delaunay triangulation with exact predicates; inside = odd
 * nesting).  Unique for corners in general position (no four cocircular).
 * X        m by 2 corners in order (either orientation)
 * F        out: (m - 2) by 3 corner indices, counter-clockwise (malloc'd)
 * Returns 0, or -1 (cm_errmsg set) when a corner repeats or the polygon is
 * not simple (edges cross). */
int cdt2_polygon(int m, const double *X, int **F);

#ifdef __cplusplus
}
#endif
#endif
