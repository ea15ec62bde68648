/* solid.h -- closed triangle solids with CGAL's Polygon_mesh_processing:
 * validity checks (is_closed, does_self_intersect, volume) and Booleans by
 * corefinement (corefine_and_compute_union / _difference).  Used to add
 * connectors (magnet pockets, plugs, sockets) and engraved ids to printable
 * pieces (piece-plug) and to check the solids it writes.
 *
 * A solid is a plain indexed triangle mesh: V #V by 3 positions, F #F by 3
 * vertex indices (0-based).  Outputs are malloc'd (free() them).
 */
#ifndef CM_SOLID_H
#define CM_SOLID_H
#ifdef __cplusplus
extern "C" {
#endif

/* What CGAL says about a triangle mesh (filled by solid_check). */
struct solid_info {
    int manifold;            /* 1 if every face could be added to a halfedge mesh */
    int closed;              /* 1 if CGAL::is_closed (no border edge) */
    int self_intersections;  /* number of intersecting face pairs (PMP::self_intersections) */
    double volume;           /* PMP::volume (signed: > 0 for outward faces), 0 unless closed */
};

/* Check V (#V by 3), F (#F by 3).  Returns -1 only on bad indices
 * (cm_errmsg); a non-manifold mesh gives info->manifold = 0 and the rest 0. */
int solid_check(const double *V, int nv, const int *F, int nf, struct solid_info *info);

enum solid_op { SOLID_UNION, SOLID_DIFFERENCE, SOLID_INTERSECTION };

/* A op B for closed, outward-oriented, self-intersection free solids A and
 * B (checked; B may have several disjoint components).  The result goes to
 * *Vo (#Vo by 3) and *Fo (#Fo by 3), malloc'd.  Returns -1 (cm_errmsg
 * naming 'what') when an input is not a valid solid or the result is not
 * one (corefinement failed). */
int solid_boolean(enum solid_op op, const double *VA, int nva, const int *FA, int nfa,
                  const double *VB, int nvb, const int *FB, int nfb, const char *what,
                  double **Vo, int *nvo, int **Fo, int *nfo);

/* Does the closed solid T (a tool) touch or cross the surface S (any
 * triangle set, open or closed)?  Exact predicates (PMP::do_intersect on
 * the triangles only, not the enclosed volumes).  Returns 1 or 0, -1 on bad
 * input (cm_errmsg). */
int solid_touches_surface(const double *VT, int nvt, const int *FT, int nft,
                          const double *VS, int nvs, const int *FS, int nfs);

#ifdef __cplusplus
}
#endif
#endif
