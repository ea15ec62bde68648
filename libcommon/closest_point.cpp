// closest_point.cpp -- see closest_point.h.  CGAL AABB tree over the
// triangles (Simple_cartesian<double>: exact predicates are not needed for
// distance queries), queried with closest_point_and_primitive().
#include "closest_point.h"
#include "cm_error.h"
#include <CGAL/Simple_cartesian.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <cmath>
#include <thread>
#include <vector>

namespace {
typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_3 Point;
typedef K::Triangle_3 Triangle;
typedef std::vector<Triangle>::const_iterator Iter;
typedef CGAL::AABB_triangle_primitive<K, Iter> Primitive;
typedef CGAL::AABB_traits<K, Primitive> Traits;
typedef CGAL::AABB_tree<Traits> Tree;
}

struct closest_point_tree {
    std::vector<Triangle> tris;
    Tree tree;
};

// barycentric coordinates of q (on or near the plane of a b c)
static void barycentric(const Triangle &t, const Point &q, double b[3])
{
    K::Vector_3 v0 = t[1] - t[0], v1 = t[2] - t[0], v2 = q - t[0];
    double d00 = v0 * v0, d01 = v0 * v1, d11 = v1 * v1, d20 = v2 * v0, d21 = v2 * v1;
    double den = d00 * d11 - d01 * d01;
    if (!(std::fabs(den) > 0)) { b[0] = 1; b[1] = b[2] = 0; return; }
    double v = (d11 * d20 - d01 * d21) / den, w = (d00 * d21 - d01 * d20) / den;
    if (v < 0) v = 0;
    if (w < 0) w = 0;
    if (v + w > 1) { double s = v + w; v /= s; w /= s; }
    b[0] = 1 - v - w; b[1] = v; b[2] = w;
}

extern "C" struct closest_point_tree *closest_point_tree_new(const double *V, int nv, const int *F,
                                                             int nf)
{
    if (nf < 1) { cm_seterr("closest point: the mesh has no faces"); return nullptr; }
    for (long h = 0; h < 3L * nf; h++)
        if (F[h] < 0 || F[h] >= nv) {
            cm_seterr("closest point: face %ld has vertex index %d out of range 0..%d",
                      h / 3, F[h], nv - 1);
            return nullptr;
        }
    closest_point_tree *T = new closest_point_tree;
    T->tris.reserve(nf);
    for (int f = 0; f < nf; f++) {
        const double *a = V + 3 * F[3 * f], *b = V + 3 * F[3 * f + 1], *c = V + 3 * F[3 * f + 2];
        T->tris.emplace_back(Point(a[0], a[1], a[2]), Point(b[0], b[1], b[2]),
                             Point(c[0], c[1], c[2]));
    }
    T->tree.insert(T->tris.begin(), T->tris.end());
    T->tree.build();
    T->tree.accelerate_distance_queries();
    return T;
}

extern "C" void closest_point_tree_free(struct closest_point_tree *T) { delete T; }

extern "C" double closest_point_query(const struct closest_point_tree *T, const double p[3],
                                      double c[3], int *face, double bary[3])
{
    Point q(p[0], p[1], p[2]);
    Tree::Point_and_primitive_id pp = T->tree.closest_point_and_primitive(q);
    const Point &x = pp.first;
    int f = (int)(pp.second - T->tris.begin());
    if (c) { c[0] = x.x(); c[1] = x.y(); c[2] = x.z(); }
    if (face) *face = f;
    if (bary) barycentric(T->tris[f], x, bary);
    return std::sqrt(CGAL::squared_distance(q, x));
}

static double query_hinted(const closest_point_tree *T, const double p[3], int h, double c[3],
                           int *face, double bary[3])
{
    Point q(p[0], p[1], p[2]);
    Tree::Point_and_primitive_id pp;
    if (h >= 0 && h < (int)T->tris.size()) {
        Tree::Point_and_primitive_id hint(T->tris[h][0], T->tris.begin() + h);
        pp = T->tree.closest_point_and_primitive(q, hint);
    } else {
        pp = T->tree.closest_point_and_primitive(q);
    }
    const Point &x = pp.first;
    int f = (int)(pp.second - T->tris.begin());
    c[0] = x.x(); c[1] = x.y(); c[2] = x.z();
    *face = f;
    barycentric(T->tris[f], x, bary);
    return std::sqrt(CGAL::squared_distance(q, x));
}

extern "C" void closest_points(const struct closest_point_tree *T, const double *P, int n,
                               double *C, int *I, double *B, double *D)
{
    closest_points_hinted(T, P, n, NULL, C, I, B, D);
}

extern "C" void closest_points_hinted(const struct closest_point_tree *T, const double *P, int n,
                                      const int *H, double *C, int *I, double *B, double *D)
{
    auto work = [&](int lo, int hi) {
        for (int i = lo; i < hi; i++) {
            double c[3], b[3];
            int f;
            double d = query_hinted(T, P + 3 * (size_t)i, H ? H[i] : -1, c, &f, b);
            if (C) { C[3 * (size_t)i] = c[0]; C[3 * (size_t)i + 1] = c[1]; C[3 * (size_t)i + 2] = c[2]; }
            if (I) I[i] = f;
            if (B) { B[3 * (size_t)i] = b[0]; B[3 * (size_t)i + 1] = b[1]; B[3 * (size_t)i + 2] = b[2]; }
            if (D) D[i] = d;
        }
    };
    if (n < 2000) { work(0, n); return; }
    std::thread th(work, 0, n / 2);
    work(n / 2, n);
    th.join();
}

extern "C" int closest_point_faces_within(const struct closest_point_tree *T, const double p[3],
                                          double r, int *out, int max)
{
    Point q(p[0], p[1], p[2]);
    CGAL::Bbox_3 box(p[0] - r, p[1] - r, p[2] - r, p[0] + r, p[1] + r, p[2] + r);
    std::vector<Tree::Primitive_id> hits;
    T->tree.all_intersected_primitives(box, std::back_inserter(hits));
    int n = 0;
    for (const Tree::Primitive_id &id : hits)
        if (CGAL::squared_distance(q, *id) <= r * r) {
            if (n < max) out[n] = (int)(id - T->tris.begin());
            n++;
        }
    return n;
}

extern "C" double closest_point_on_face(const struct closest_point_tree *T, int f, const double p[3],
                                        double c[3], double bary[3])
{
    Point q(p[0], p[1], p[2]);
    Point x = K().construct_projected_point_3_object()(T->tris[f], q);
    if (c) { c[0] = x.x(); c[1] = x.y(); c[2] = x.z(); }
    if (bary) barycentric(T->tris[f], x, bary);
    return std::sqrt(CGAL::squared_distance(q, x));
}
