/* topology.h -- combinatorics of a triangle mesh: unique edges, edge-face
 * incidence, vertex-face and vertex-vertex adjacency (one-rings), boundary
 * loops, manifoldness, Euler characteristic.
 */
#ifndef CM_TOPOLOGY_H
#define CM_TOPOLOGY_H
#ifdef __cplusplus
extern "C" {
#endif

struct topology {
    int nv, nf, ne;
    int *E;          /* #E by 2 vertex indices, E[2e] < E[2e+1] */
    int *EF;         /* #E by 2 incident faces (first two found), -1 if none */
    int *EFn;        /* #E number of incident faces (1 boundary, 2 interior, >2 non-manifold) */
    int *FE;         /* #F by 3: FE[3f+c] = edge from corner c to corner c+1 */
    int *VFs, *VF;   /* CSR: faces of vertex v are VF[VFs[v] .. VFs[v+1]-1] */
    int *VVs, *VV;   /* CSR: neighbours of v are VV[VVs[v] .. VVs[v+1]-1] (sorted) */
    int *ES;         /* #V+1: the edges (v, w) with w > v are ES[v] .. ES[v+1]-1 */
    int nboundary;   /* number of boundary edges (EFn == 1) */
    int nnonmanifold;/* number of edges with EFn > 2 */
    int nisolated;   /* vertices in no face */
};

/* Build all tables.  F: #F by 3. */
int topology_build(const int *F, int nf, int nv, struct topology *t);
void topology_free(struct topology *t);

/* Edge index of the edge {a,b}, or -1. O(log degree). */
int topology_edge(const struct topology *t, int a, int b);

/* Boundary loops as CSR: loop l is L[Ls[l] .. Ls[l+1]-1], vertices in order
 * following face orientation.  Returns the number of loops, -1 if the
 * boundary is not a set of simple loops (non-manifold vertex). */
int boundary_loops(const struct topology *t, const int *F, int **Ls, int **L);

/* Number of connected components (of faces through shared vertices). */
int connected_components(const struct topology *t, const int *F, int *comp_of_face);

/* Is each vertex's fan a single disk or half-disk?  Returns the number of
 * non-manifold vertices. */
int nonmanifold_vertices(const struct topology *t, const int *F);

#ifdef __cplusplus
}
#endif
#endif
