/* mesh_clean.h -- the cleanup of scanned meshes (thesis Sec. 3.2: "makes the
 * meshes watertight, 2-manifolds"), with CGAL Polygon Mesh Processing:
 *   1. degenerate faces (a repeated corner or zero area) are removed;
 *   2. duplicate faces are removed: copies with the same orientation are
 *      kept once, and a pair of opposite orientation (a zero-volume fin,
 *      common in scans) is removed entirely;
 *   3. the soup is repaired and oriented (PMP::repair_polygon_soup,
 *      orient_polygon_soup: non-manifold vertices are split) and becomes a
 *      halfedge mesh; unreferenced vertices disappear, so vertex indices
 *      change;
 *   3b. connected components with fewer than min_component of the faces
 *      (debris, and pieces split off at non-manifold vertices) are removed;
 *   4. holes (boundary loops) with at most max_hole edges are closed by
 *      PMP::triangulate_refine_and_fair_hole;
 *   5. optionally, isotropic remeshing to a target edge length
 *      (PMP::isotropic_remeshing).
 */
#ifndef CM_MESH_CLEAN_H
#define CM_MESH_CLEAN_H
#ifdef __cplusplus
extern "C" {
#endif

struct mesh_clean_opts {
    int fill_holes;        /* 1: close holes */
    int max_hole;          /* largest hole to close, in boundary edges (<= 0: any) */
    double edge_length;    /* > 0: isotropic remeshing to this edge length */
    int iterations;        /* remeshing iterations (default 3) */
    double min_component;  /* remove components with fewer faces than this fraction of
                              all faces (e.g. 0.01; 0 keeps all) */
};

struct mesh_clean_report {
    int degenerate, duplicate, fins;   /* faces removed in steps 1-2 */
    int holes_filled, holes_left;      /* boundary loops after step 3 */
    int components_removed;            /* small pieces removed */
    int nv, nf;                        /* result sizes */
};

/* V: #V by 3, F: #F by 3 in; *Vout (#Vout by 3), *Fout (#Fout by 3) out,
 * malloc'd.  Returns -1 (cm_errmsg set) when nothing is left or CGAL fails. */
int mesh_clean(const double *V, int nv, const int *F, int nf, const struct mesh_clean_opts *o,
               double **Vout, int *nvout, int **Fout, int *nfout, struct mesh_clean_report *rep);

#ifdef __cplusplus
}
#endif
#endif
