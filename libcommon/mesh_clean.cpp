// mesh_clean.cpp -- see mesh_clean.h
#include "mesh_clean.h"
#include "cm_error.h"
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <iterator>
#include <map>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;

static double tri_area2(const double *a, const double *b, const double *c)
{
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double x = u[1] * v[2] - u[2] * v[1], y = u[2] * v[0] - u[0] * v[2], z = u[0] * v[1] - u[1] * v[0];
    return x * x + y * y + z * z;
}

extern "C" int mesh_clean(const double *V, int nv, const int *F, int nf,
                          const struct mesh_clean_opts *o, double **Vout, int *nvout, int **Fout,
                          int *nfout, struct mesh_clean_report *rep)
{
    *rep = mesh_clean_report();
    try {
        // 1-2: degenerate and duplicate faces, on the soup
        std::map<std::array<int, 3>, std::vector<int>> bykey;
        std::vector<int> keep;
        for (int f = 0; f < nf; f++) {
            const int *t = F + 3 * f;
            if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= nv || t[1] >= nv || t[2] >= nv)
                return cm_seterr("face %d has a vertex index out of range 0..%d", f, nv - 1);
            if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] ||
                !(tri_area2(V + 3 * t[0], V + 3 * t[1], V + 3 * t[2]) > 0)) {
                rep->degenerate++;
                continue;
            }
            std::array<int, 3> k = {t[0], t[1], t[2]};
            std::sort(k.begin(), k.end());
            bykey[k].push_back(f);
        }
        for (auto &kv : bykey) {
            std::vector<int> &fs = kv.second;
            if (fs.size() == 1) { keep.push_back(fs[0]); continue; }
            // orientation of each copy relative to the first: even permutation = same
            auto orient = [&](int f) {
                const int *t = F + 3 * f, *s = F + 3 * fs[0];
                int r = t[0] == s[0] ? 0 : t[0] == s[1] ? 1 : 2;   // rotation aligning t[0]
                return t[1] == s[(r + 1) % 3] ? 1 : -1;
            };
            int pos = 0, neg = 0;
            for (int f : fs) (orient(f) > 0 ? pos : neg)++;
            if (pos > 0 && neg > 0) {
                rep->fins += (int)fs.size();           // fin: all copies go
            } else {
                keep.push_back(fs[0]);
                rep->duplicate += (int)fs.size() - 1;
            }
        }
        std::sort(keep.begin(), keep.end());
        if (keep.empty()) return cm_seterr("no faces left after removing degenerate and duplicate faces");
        // 3: repair, orient, to a halfedge mesh
        std::vector<Point> pts;
        pts.reserve(nv);
        for (int v = 0; v < nv; v++) pts.emplace_back(V[3 * v], V[3 * v + 1], V[3 * v + 2]);
        std::vector<std::vector<std::size_t>> polys;
        for (int f : keep)
            polys.push_back({(std::size_t)F[3 * f], (std::size_t)F[3 * f + 1], (std::size_t)F[3 * f + 2]});
        PMP::repair_polygon_soup(pts, polys);
        PMP::orient_polygon_soup(pts, polys);
        Mesh m;
        PMP::polygon_soup_to_polygon_mesh(pts, polys, m);
        if (o->min_component > 0) {
            std::size_t nfm = m.number_of_faces();
            std::size_t thr = (std::size_t)std::ceil(o->min_component * (double)nfm);
            if (thr > 1)
                rep->components_removed = (int)PMP::keep_large_connected_components(m, thr);
            m.collect_garbage();
            if (m.number_of_faces() == 0) return cm_seterr("no faces left after removing small components");
        }
        // 4: holes
        std::vector<Mesh::Halfedge_index> borders;
        PMP::extract_boundary_cycles(m, std::back_inserter(borders));
        for (Mesh::Halfedge_index h : borders) {
            int len = 0;
            for (Mesh::Halfedge_index g : CGAL::halfedges_around_face(h, m)) { (void)g; len++; }
            if (!o->fill_holes || (o->max_hole > 0 && len > o->max_hole)) { rep->holes_left++; continue; }
            std::vector<Mesh::Face_index> nfcs;
            std::vector<Mesh::Vertex_index> nvs;
            bool ok = std::get<0>(PMP::triangulate_refine_and_fair_hole(
                m, h, std::back_inserter(nfcs), std::back_inserter(nvs)));
            if (ok) rep->holes_filled++; else rep->holes_left++;
        }
        // 5: remeshing
        if (o->edge_length > 0)
            PMP::isotropic_remeshing(faces(m), o->edge_length, m,
                                     CGAL::parameters::number_of_iterations(o->iterations > 0 ? o->iterations : 3));
        m.collect_garbage();
        // export
        int n = (int)m.number_of_vertices(), k = (int)m.number_of_faces();
        double *VO = (double *)malloc((size_t)n * 3 * sizeof(double) + 1);
        int *FO = (int *)malloc((size_t)k * 3 * sizeof(int) + 1);
        std::map<Mesh::Vertex_index, int> id;
        int i = 0;
        for (Mesh::Vertex_index v : m.vertices()) {
            const Point &p = m.point(v);
            VO[3 * i] = p.x(); VO[3 * i + 1] = p.y(); VO[3 * i + 2] = p.z();
            id[v] = i++;
        }
        int j = 0;
        for (Mesh::Face_index f : m.faces()) {
            int c = 0;
            for (Mesh::Vertex_index v : CGAL::vertices_around_face(m.halfedge(f), m))
                if (c < 3) FO[3 * j + c++] = id[v];
            if (c == 3) j++;
        }
        *Vout = VO; *nvout = n; *Fout = FO; *nfout = j;
        rep->nv = n; rep->nf = j;
        return 0;
    } catch (const std::exception &e) {
        return cm_seterr("mesh cleanup failed: %s", e.what());
    }
}
