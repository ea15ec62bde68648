// surface_mesh_build.hpp -- a CGAL Surface_mesh from indexed triangles (C++,
// internal to libcommon: solid.cpp and overlap.cpp word their own errors).
//
//   V   #V by 3 vertex positions (row-major), nv = #V
//   F   #F by 3 vertex indices, 0-based (row-major), nf = #F
//   m   out: the mesh, one Surface_mesh vertex per row of V
//   bad out: the face that stopped the build (when the return is not 1)
// Returns 1 on success, -1 when face *bad has an index outside [0, nv),
// 0 when face *bad would make the mesh non-manifold (add_face refuses it).
#ifndef STOPMO_SURFACE_MESH_BUILD_HPP
#define STOPMO_SURFACE_MESH_BUILD_HPP
#include <vector>

template <class Mesh>
static int surface_mesh_build(const double *V, int nv, const int *F, int nf, Mesh &m, int *bad)
{
    typedef typename Mesh::Point Point;
    std::vector<typename Mesh::Vertex_index> vi;
    vi.reserve(nv);
    for (int v = 0; v < nv; v++) vi.push_back(m.add_vertex(Point(V[3 * v], V[3 * v + 1], V[3 * v + 2])));
    for (int f = 0; f < nf; f++) {
        const int *t = F + 3 * f;
        *bad = f;
        if (t[0] < 0 || t[1] < 0 || t[2] < 0 || t[0] >= nv || t[1] >= nv || t[2] >= nv) return -1;
        if (m.add_face(vi[t[0]], vi[t[1]], vi[t[2]]) == Mesh::null_face()) return 0;
    }
    return 1;
}
#endif
