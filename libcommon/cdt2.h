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

#ifdef __cplusplus
}
#endif
#endif
