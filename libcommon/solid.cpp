// solid.cpp -- see solid.h
#include "solid.h"
#include "cm_error.h"
#include "surface_mesh_build.hpp"
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <cstdlib>
#include <iterator>
#include <vector>
#include <array>

namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

// Add the faces one by one: -1 on a bad index, 0 when a face would make the
// mesh non-manifold (add_face refuses it), 1 on success.
static int build(const double *V, int nv, const int *F, int nf, Mesh &m)
{
    int bad, r = surface_mesh_build(V, nv, F, nf, m, &bad);
    if (r < 0) return cm_seterr("face %d has a vertex index out of range", bad);
    return r;
}

extern "C" int solid_check(const double *V, int nv, const int *F, int nf, struct solid_info *info)
{
    *info = solid_info{0, 0, 0, 0};
    try {
        Mesh m;
        int r = build(V, nv, F, nf, m);
        if (r < 0) return -1;
        if (r == 0) return 0;
        info->manifold = 1;
        info->closed = CGAL::is_closed(m);
        std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
        PMP::self_intersections(m, std::back_inserter(pairs));
        info->self_intersections = (int)pairs.size();
        if (info->closed) info->volume = CGAL::to_double(PMP::volume(m));
        return 0;
    } catch (const std::exception &e) {
        return cm_seterr("solid check failed: %s", e.what());
    }
}

static int valid(const double *V, int nv, const int *F, int nf, const char *which, const char *what, Mesh &m)
{
    int r = build(V, nv, F, nf, m);
    if (r < 0) return cm_seterr("%s: %s: %s", what, which, cm_errmsg());
    if (r == 0) return cm_seterr("%s: %s is not manifold", what, which);
    if (!CGAL::is_closed(m)) return cm_seterr("%s: %s is not closed", what, which);
    if (PMP::does_self_intersect(m)) return cm_seterr("%s: %s intersects itself", what, which);
    if (!PMP::is_outward_oriented(m)) PMP::reverse_face_orientations(m);
    return 0;
}

static void extract(const Mesh &m, double **Vo, int *nvo, int **Fo, int *nfo)
{
    // Surface_mesh indices are compact after corefinement only if no element was removed
    std::vector<int> id(m.number_of_vertices() + m.number_of_removed_vertices(), -1);
    int n = 0;
    double *V = (double *)malloc(sizeof(double) * 3 * (m.number_of_vertices() + 1));
    for (Mesh::Vertex_index v : m.vertices()) {
        const K::Point_3 &p = m.point(v);
        V[3 * n] = p.x(); V[3 * n + 1] = p.y(); V[3 * n + 2] = p.z();
        id[v] = n++;
    }
    int *F = (int *)malloc(sizeof(int) * 3 * (m.number_of_faces() + 1)), k = 0;
    for (Mesh::Face_index f : m.faces()) {
        int c = 0;
        for (Mesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m)) if (c < 3) F[3 * k + c++] = id[v];
        k++;
    }
    *Vo = V; *nvo = n; *Fo = F; *nfo = k;
}

extern "C" int solid_boolean(enum solid_op op, const double *VA, int nva, const int *FA, int nfa,
                             const double *VB, int nvb, const int *FB, int nfb, const char *what,
                             double **Vo, int *nvo, int **Fo, int *nfo)
{
    try {
        Mesh a, b, out;
        if (valid(VA, nva, FA, nfa, "the piece", what, a) < 0) return -1;
        if (valid(VB, nvb, FB, nfb, "the tool", what, b) < 0) return -1;
        bool ok = op == SOLID_UNION ? PMP::corefine_and_compute_union(a, b, out)
                : op == SOLID_DIFFERENCE ? PMP::corefine_and_compute_difference(a, b, out)
                : PMP::corefine_and_compute_intersection(a, b, out);
        if (!ok) return cm_seterr("%s: the Boolean result does not bound a volume (corefinement failed)", what);
        if (!CGAL::is_triangle_mesh(out)) return cm_seterr("%s: the Boolean result is not a triangle mesh", what);
        extract(out, Vo, nvo, Fo, nfo);
        return 0;
    } catch (const std::exception &e) {
        return cm_seterr("%s: Boolean failed: %s", what, e.what());
    }
}

extern "C" int solid_touches_surface(const double *VT, int nvt, const int *FT, int nft,
                                     const double *VS, int nvs, const int *FS, int nfs)
{
    try {
        Mesh t, s;
        int r = build(VT, nvt, FT, nft, t);
        if (r < 0) return -1;
        if (r == 0) return cm_seterr("the tool is not a manifold mesh");
        r = build(VS, nvs, FS, nfs, s);
        if (r < 0) return -1;
        if (r == 0) return cm_seterr("the surface is not manifold");
        // triangles only: an open surface bounds nothing
        return PMP::do_intersect(t, s, CGAL::parameters::do_overlap_test_of_bounded_sides(false),
                                 CGAL::parameters::do_overlap_test_of_bounded_sides(false)) ? 1 : 0;
    } catch (const std::exception &e) {
        return cm_seterr("intersection test failed: %s", e.what());
    }
}
