// cdt2.cpp -- see cdt2.h.  CGAL constrained Delaunay + Delaunay_mesher_2.
#include "cdt2.h"
#include "cm_error.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>

#include <cstdlib>
#include <map>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Delaunay_mesh_vertex_base_2<K> Vb;
typedef CGAL::Delaunay_mesh_face_base_2<K> Fb;
typedef CGAL::Triangulation_data_structure_2<Vb, Fb> Tds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, Tds> CDT;
typedef CGAL::Delaunay_mesh_size_criteria_2<CDT> Criteria;
typedef CDT::Vertex_handle VH;
typedef CDT::Point Point;

extern "C" int cdt2_mesh_box(const double lo[2], const double hi[2], const double *P, int np,
                             double size, double **Vout, int *nvout, int **Fout, int *nfout, int *pidx)
{
    try {
        CDT cdt;
        Point c[4] = {Point(lo[0], lo[1]), Point(hi[0], lo[1]), Point(hi[0], hi[1]), Point(lo[0], hi[1])};
        VH cv[4];
        for (int k = 0; k < 4; k++) cv[k] = cdt.insert(c[k]);
        for (int k = 0; k < 4; k++) cdt.insert_constraint(cv[k], cv[(k + 1) % 4]);
        std::vector<VH> ph(np);
        for (int i = 0; i < np; i++) ph[i] = cdt.insert(Point(P[2 * i], P[2 * i + 1]));
        // 0.125 = sin^2 of the smallest angle bound (about 20.7 degrees)
        CGAL::refine_Delaunay_mesh_2(cdt, Criteria(0.125, size));
        std::map<VH, int> index;
        std::vector<double> V;
        std::vector<int> F;
        for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
            index[v] = (int)(V.size() / 2);
            V.push_back(v->point().x());
            V.push_back(v->point().y());
        }
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
            if (!f->is_in_domain()) continue;
            for (int k = 0; k < 3; k++) F.push_back(index[f->vertex(k)]);
        }
        for (int i = 0; i < np; i++) pidx[i] = index[ph[i]];
        *nvout = (int)(V.size() / 2);
        *nfout = (int)(F.size() / 3);
        *Vout = (double *)malloc(V.size() * sizeof(double) + 1);
        *Fout = (int *)malloc(F.size() * sizeof(int) + 1);
        if (!*Vout || !*Fout) return cm_seterr("out of memory");
        std::copy(V.begin(), V.end(), *Vout);
        std::copy(F.begin(), F.end(), *Fout);
        return 0;
    } catch (const std::exception &e) {
        return cm_seterr("2D meshing failed: %s", e.what());
    }
}
