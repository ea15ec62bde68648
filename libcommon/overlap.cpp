// overlap.cpp -- see overlap.h
#include "overlap.h"
#include "cm_error.h"
#include "surface_mesh_build.hpp"
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;

static int build(const double *V, int nv, const int *F, int nf, const char *which, Mesh &m)
{
    int f, r = surface_mesh_build(V, nv, F, nf, m, &f);
    if (r < 0) return cm_seterr("%s: face %d has a vertex index out of range", which, f);
    if (r == 0) return cm_seterr("%s: face %d makes the mesh non-manifold (mesh-clean first)", which, f);
    if (!CGAL::is_closed(m))
        return cm_seterr("%s is not closed: a volume is needed (mesh-clean closes holes)", which);
    if (PMP::does_self_intersect(m))
        return cm_seterr("%s intersects itself: no volume is defined", which);
    if (!PMP::is_outward_oriented(m)) PMP::reverse_face_orientations(m);
    return 0;
}

extern "C" int volume_overlap(const double *VA, int nva, const int *FA, int nfa,
                              const double *VB, int nvb, const int *FB, int nfb,
                              double *ratio, double *va, double *vb, double *vi)
{
    try {
        Mesh a, b, out;
        if (build(VA, nva, FA, nfa, "the source", a) < 0) return -1;
        if (build(VB, nvb, FB, nfb, "the target", b) < 0) return -1;
        double A = CGAL::to_double(PMP::volume(a)), B = CGAL::to_double(PMP::volume(b));
        if (!PMP::corefine_and_compute_intersection(a, b, out))
            return cm_seterr("the intersection is not a closed volume (corefinement failed)");
        double I = CGAL::to_double(PMP::volume(out));
        if (!(A > 0)) return cm_seterr("the source encloses no volume");
        *ratio = I / A;
        if (va) *va = A;
        if (vb) *vb = B;
        if (vi) *vi = I;
        return 0;
    } catch (const std::exception &e) {
        return cm_seterr("overlap failed: %s", e.what());
    }
}

extern "C" const char *overlap_scale(double r)
{
    return r >= 0.8 ? "small" : r >= 0.4 ? "intermediate" : "large";
}
