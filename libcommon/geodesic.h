/* geodesic.h -- geodesic distance on a triangle mesh from a set of sources
 * (vertices, or points on faces), per vertex.
 *
 * Method: the heat method (Crane, Weischedel, Wardetzky 2013) as implemented
 * by CGAL (Heat_method_3::Surface_mesh_geodesic_distances_3) on the
 * intrinsic Delaunay triangulation of the mesh (Heat_method_3::
 * Intrinsic_Delaunay), which keeps the cot Laplacian well behaved on
 * skinny or obtuse triangles (scanned and captured meshes have many).
 *
 * Why the heat method and not exact geodesics (CGAL Surface_mesh_shortest_
 * path, MMP): the heat method factors two sparse matrices once per mesh and
 * then answers every new source set with two back-substitutions (linear in
 * the mesh size), which is what callers need (one source set per part in
 * seg-graphcut, many anchor sets for stiffness maps); exact geodesics cost
 * O(n^2 log n) in the worst case per source set and are sensitive to
 * near-degenerate triangles.  The price: distances are smooth approximations
 * (a few percent error at the mesh resolution, see tests/unit/geodesic.c),
 * and they are not exactly 0 at the sources.  Good enough for data terms
 * and weights; not for measuring.
 *
 * Meshes: any triangle mesh whose connected components are each an
 * oriented 2-manifold (with or without boundary).  Components are solved
 * separately; vertices of a component without a source, and vertices in no
 * face, get INFINITY.  Non-manifold or inconsistently oriented input is
 * refused (return -1, cm_errmsg names the face).
 *
 *   struct geodesic *g = geodesic_new(V, F, nv, nf);       factor once
 *   geodesic_solve(g, S, ns, D);                            many times
 *   geodesic_free(g);
 * or, one shot and with points on faces:
 *   geodesic_distance(V, F, nv, nf, S, ns, SF, SB, nsf, D);
 */
#ifndef CM_GEODESIC_H
#define CM_GEODESIC_H
#ifdef __cplusplus
extern "C" {
#endif

struct geodesic;

/* Precompute the heat-method operators.
 *   V   #V by 3 vertex positions (row-major)
 *   F   #F by 3 vertex indices (0-based, row-major)
 *   nv  #V,  nf  #F
 * Returns NULL (cm_errmsg set) on a non-manifold mesh, an index out of
 * range or a failed factorization. */
struct geodesic *geodesic_new(const double *V, const int *F, int nv, int nf);

/* Distances from the source vertex set.
 *   S   ns source vertex indices (duplicates allowed)
 *   D   #V output distances (INFINITY where no source is reachable)
 * Returns 0, or -1 (cm_errmsg set) on an index out of range or ns < 1. */
int geodesic_solve(struct geodesic *g, const int *S, int ns, double *D);

void geodesic_free(struct geodesic *g);

/* One shot, with sources that are vertices and/or points on faces.
 *   S    ns source vertex indices (may be NULL when ns == 0)
 *   SF   nsf faces containing a source point (may be NULL when nsf == 0)
 *   SB   nsf by 3 barycentric coordinates of the points in their faces
 *        (clamped to >= 0 and renormalized)
 *   D    #V output distances to the nearest source
 * Points on faces are inserted into a copy of the mesh (face split, edge
 * split when on an edge) so their distance is that of the point, not of
 * the face's corners.  Needs ns + nsf >= 1. */
int geodesic_distance(const double *V, const int *F, int nv, int nf,
                      const int *S, int ns, const int *SF, const double *SB, int nsf,
                      double *D);

/* Carry distances over to the vertices no source reaches (other
 * components), across bridges: shortest paths (Dijkstra) over the mesh
 * edges and the bridge edges, both with their Euclidean lengths, starting
 * from the vertices whose distance is already finite (kept as they are).
 *   V   #V by 3 vertex positions,  F  #F by 3 faces
 *   B   nb by 2 vertex pairs (bridge edges, e.g. corners of bridges.h pairs)
 *   D   #V in: distances, INFINITY where unknown; out: INFINITY only where
 *       no path leads
 * Returns the number of vertices still at INFINITY, or -1 (cm_errmsg set)
 * on an index out of range. */
int geodesic_extend(const double *V, const int *F, int nv, int nf, const int *B, int nb,
                    double *D);

#ifdef __cplusplus
}
#endif
#endif
