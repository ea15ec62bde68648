/* topology: edge_counts, one_rings_sorted_and_symmetric, edge_lookup,
 * boundary_loops (grid, cylinder, icosahedron), euler_characteristic,
 * components, nonmanifold detection */
#include "topology.h"
#include "tap.h"
#include "testmesh.h"
#include <stdlib.h>
#include <string.h>

static int euler(const struct topology *t) { return t->nv - t->nisolated - t->ne + t->nf; }

/* every edge of every face found by topology_edge and in FE */
static int edges_consistent(const struct topology *t, const int *F)
{
    for (int f = 0; f < t->nf; f++)
        for (int c = 0; c < 3; c++) {
            int a = F[3 * f + c], b = F[3 * f + (c + 1) % 3];
            int e = topology_edge(t, a, b);
            if (e < 0 || e != t->FE[3 * f + c] || topology_edge(t, b, a) != e) return 0;
            int lo = a < b ? a : b, hi = a < b ? b : a;
            if (t->E[2 * e] != lo || t->E[2 * e + 1] != hi) return 0;
            if (t->EF[2 * e] != f && t->EF[2 * e + 1] != f && t->EFn[e] <= 2) return 0;
        }
    return 1;
}

static int rings_ok(const struct topology *t)
{
    for (int v = 0; v < t->nv; v++)
        for (int k = t->VVs[v]; k < t->VVs[v + 1]; k++) {
            int w = t->VV[k];
            if (k > t->VVs[v] && t->VV[k - 1] >= w) return 0;       /* sorted, unique */
            int found = 0;                                          /* symmetric */
            for (int q = t->VVs[w]; q < t->VVs[w + 1]; q++) found |= t->VV[q] == v;
            if (!found || topology_edge(t, v, w) < 0) return 0;
        }
    return t->VVs[t->nv] == 2 * t->ne;
}

static int vf_ok(const struct topology *t, const int *F)
{
    for (int v = 0; v < t->nv; v++)
        for (int k = t->VFs[v]; k < t->VFs[v + 1]; k++) {
            int f = t->VF[k];
            if (F[3 * f] != v && F[3 * f + 1] != v && F[3 * f + 2] != v) return 0;
        }
    return t->VFs[t->nv] == 3 * t->nf;
}

int main(void)
{
    double *V;
    int *F, nv, nf, *Ls, *L;
    struct topology t;

    /* grid n x m */
    int n = 5, m = 3;
    grid_mesh(n, m, 0, 1, &V, &F, &nv, &nf);
    ok(topology_build(F, nf, nv, &t) == 0, "topology_build: grid");
    ok(t.ne == n * (m + 1) + m * (n + 1) + n * m, "grid: edge_count %d", t.ne);
    ok(t.nboundary == 2 * (n + m), "grid: boundary edges %d", t.nboundary);
    ok(t.nnonmanifold == 0 && t.nisolated == 0, "grid: no non-manifold edge, no isolated vertex");
    ok(euler(&t) == 1, "grid: euler_characteristic 1 (%d)", euler(&t));
    ok(edges_consistent(&t, F), "grid: edge lookup, FE and EF consistent");
    ok(rings_ok(&t), "grid: one_rings sorted and symmetric");
    ok(vf_ok(&t, F), "grid: vertex-face lists");
    int nl = boundary_loops(&t, F, &Ls, &L);
    ok(nl == 1 && Ls[1] == 2 * (n + m), "grid: one boundary loop of %d vertices", 2 * (n + m));
    /* the loop follows face orientation: consecutive vertices form
     * boundary edges traversed in the direction of their face */
    int follows = 1;
    for (int k = 0; k < Ls[1]; k++) {
        int a = L[k], b = L[(k + 1) % Ls[1]], e = topology_edge(&t, a, b);
        if (e < 0 || t.EFn[e] != 1) { follows = 0; break; }
        int f = t.EF[2 * e], dir = 0;
        for (int c = 0; c < 3; c++) dir |= F[3 * f + c] == a && F[3 * f + (c + 1) % 3] == b;
        follows &= dir;
    }
    ok(follows, "grid: boundary loop follows face orientation");
    ok(connected_components(&t, F, NULL) == 1, "grid: one component");
    ok(nonmanifold_vertices(&t, F) == 0, "grid: no non-manifold vertex");
    free(Ls); free(L);
    topology_free(&t);
    free(V); free(F);

    /* cylinder */
    cylinder_mesh(7, 4, &V, &F, &nv, &nf);
    topology_build(F, nf, nv, &t);
    ok(t.ne == 7 * 5 + 7 * 4 + 7 * 4, "cylinder: edge_count %d", t.ne);
    ok(euler(&t) == 0, "cylinder: euler_characteristic 0");
    nl = boundary_loops(&t, F, &Ls, &L);
    ok(nl == 2 && Ls[1] == 7 && Ls[2] == 14, "cylinder: two boundary loops of 7");
    ok(edges_consistent(&t, F) && rings_ok(&t) && vf_ok(&t, F), "cylinder: tables consistent");
    free(Ls); free(L);
    topology_free(&t);
    free(V); free(F);

    /* icosahedron */
    icosahedron(&V, &F, &nv, &nf);
    topology_build(F, nf, nv, &t);
    ok(t.ne == 30 && t.nboundary == 0, "icosahedron: 30 edges, no boundary");
    ok(euler(&t) == 2, "icosahedron: euler_characteristic 2");
    nl = boundary_loops(&t, F, &Ls, &L);
    ok(nl == 0, "icosahedron: no boundary loop");
    int deg5 = 1;
    for (int v = 0; v < nv; v++) deg5 &= t.VVs[v + 1] - t.VVs[v] == 5;
    ok(deg5, "icosahedron: every vertex has 5 neighbours");
    ok(edges_consistent(&t, F) && rings_ok(&t) && vf_ok(&t, F), "icosahedron: tables consistent");
    free(Ls); free(L);
    topology_free(&t);

    /* two icosahedra side by side plus an isolated vertex */
    int F2[120];
    for (int i = 0; i < 60; i++) { F2[i] = F[i]; F2[60 + i] = F[i] + 12; }
    topology_build(F2, 40, 25, &t);
    int comp[40];
    ok(connected_components(&t, F2, comp) == 2 && comp[0] == 0 && comp[39] == 1,
       "two icosahedra: two components");
    ok(t.nisolated == 1 && euler(&t) == 4, "two icosahedra + isolated vertex: euler 4");
    topology_free(&t);
    free(V); free(F);

    /* non-manifold: fin (three faces on one edge) and bow-tie vertex */
    int fin[9] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
    topology_build(fin, 3, 5, &t);
    ok(t.nnonmanifold == 1, "fin: one non-manifold edge");
    int e01 = topology_edge(&t, 0, 1);
    ok(e01 >= 0 && t.EFn[e01] == 3, "fin: edge 0-1 has three faces");
    /* the edges sorted by (lo, hi), a shared edge's faces in face order
     * (the order a stable sort of the half-edges gives) */
    int sorted = 1;
    for (int e = 1; e < t.ne; e++)
        if (t.E[2 * e - 2] > t.E[2 * e] || (t.E[2 * e - 2] == t.E[2 * e] && t.E[2 * e - 1] >= t.E[2 * e + 1])) sorted = 0;
    ok(sorted && t.EF[2 * e01] == 0 && t.EF[2 * e01 + 1] == 1, "fin: edges sorted, edge 0-1 lists faces 0 and 1");
    ok(topology_edge(&t, 2, 3) == -1 && topology_edge(&t, 3, 4) == -1 && topology_edge(&t, -1, 2) == -1 &&
       topology_edge(&t, 0, 7) == -1 && topology_edge(&t, 4, 0) >= 0, "fin: no edge 2-3, 3-4, none out of range");
    topology_free(&t);
    int bow[6] = {0, 1, 2, 0, 3, 4};
    topology_build(bow, 2, 5, &t);
    ok(nonmanifold_vertices(&t, bow) == 1, "bow-tie: one non-manifold vertex");
    nl = boundary_loops(&t, bow, &Ls, &L);
    ok(nl < 0, "bow-tie: boundary_loops reports the pinched boundary");
    if (nl >= 0) { free(Ls); free(L); }
    topology_free(&t);

    /* empty mesh */
    ok(topology_build(NULL, 0, 3, &t) == 0 && t.ne == 0 && t.nisolated == 3,
       "empty face list: 3 isolated vertices");
    topology_free(&t);
    return tap_done();
}
