// cdt2.cpp -- see cdt2.h.  CGAL constrained Delaunay + Delaunay_mesher_2.
#include "cdt2.h"
#include "cm_error.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesher_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>

#include <algorithm>
#include <array>
#include <climits>
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

// ---------------------------------------------------------------------
// overlay of N triangulations of one polygon (see cdt2.h)

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Constrained_triangulation_plus_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <cmath>
#include <set>
#include <cstring>

namespace {
typedef CGAL::Triangulation_vertex_base_with_info_2<int, K> PVb;
typedef CGAL::Triangulation_face_base_with_info_2<int, K> PFi;
typedef CGAL::Constrained_triangulation_face_base_2<K, PFi> PFb;
typedef CGAL::Triangulation_data_structure_2<PVb, PFb> PTds;
typedef CGAL::Constrained_Delaunay_triangulation_2<K, PTds, CGAL::Exact_predicates_tag> PCDT;

// the m-2 triangles of a simple polygon (corners 0..m-1), no new points
int polygon_triangles(int m, const double *X, std::vector<int> &T)
{
    PCDT cdt;
    std::vector<PCDT::Vertex_handle> vh(m);
    for (int i = 0; i < m; i++) {
        vh[i] = cdt.insert(PCDT::Point(X[2 * i], X[2 * i + 1]));
        vh[i]->info() = i;
    }
    if ((int)cdt.number_of_vertices() != m) return cm_seterr("overlay: repeated corner");
    for (int i = 0; i < m; i++) cdt.insert_constraint(vh[i], vh[(i + 1) % m]);
    if ((int)cdt.number_of_vertices() != m) return cm_seterr("overlay: piece is not simple");
    // inside: odd nesting (flood from the infinite face across constraints)
    for (auto f = cdt.all_faces_begin(); f != cdt.all_faces_end(); ++f) f->info() = -1;
    std::vector<PCDT::Face_handle> stack{cdt.infinite_face()};
    cdt.infinite_face()->info() = 0;
    std::vector<PCDT::Face_handle> next;
    for (int level = 0; !stack.empty(); level++) {
        while (!stack.empty()) {
            auto f = stack.back(); stack.pop_back();
            for (int e = 0; e < 3; e++) {
                auto g = f->neighbor(e);
                if (g->info() >= 0) continue;
                if (f->is_constrained(e)) next.push_back(g);
                else { g->info() = level; stack.push_back(g); }
            }
        }
        for (auto g : next) if (g->info() < 0) { g->info() = level + 1; stack.push_back(g); }
        next.clear();
    }
    T.clear();
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
        if (f->info() % 2 == 1)
            for (int k = 0; k < 3; k++) T.push_back(f->vertex(k)->info());
    if ((int)T.size() != 3 * (m - 2)) return cm_seterr("overlay: piece is not a simple polygon");
    return 0;
}


// Is corner j strictly inside the interior angle at corner i of the
// counter-clockwise polygon X (exact orientation tests)?
bool in_cone(int m, const double *X, int i, int j)
{
    K::Point_2 p(X[2 * ((i + m - 1) % m)], X[2 * ((i + m - 1) % m) + 1]), c(X[2 * i], X[2 * i + 1]),
        n(X[2 * ((i + 1) % m)], X[2 * ((i + 1) % m) + 1]), q(X[2 * j], X[2 * j + 1]);
    CGAL::Orientation turn = CGAL::orientation(p, c, n);
    if (turn == CGAL::LEFT_TURN)        // convex: left of c->n and right of c->p
        return CGAL::orientation(c, n, q) == CGAL::LEFT_TURN && CGAL::orientation(c, q, p) == CGAL::LEFT_TURN;
    if (turn == CGAL::COLLINEAR)        // flat: the left half-plane
        return CGAL::orientation(c, n, q) == CGAL::LEFT_TURN;
    // reflex: outside the closed exterior cone from c->p to c->n
    return !(CGAL::orientation(c, p, q) != CGAL::RIGHT_TURN && CGAL::orientation(c, q, n) != CGAL::RIGHT_TURN);
}

// Is i-j a diagonal of the simple counter-clockwise polygon X: inside
// both corners' angles, and no edge not at i or j meets the closed segment?
bool is_diagonal(int m, const double *X, int i, int j)
{
    if (!in_cone(m, X, i, j) || !in_cone(m, X, j, i)) return false;
    K::Segment_2 d(K::Point_2(X[2 * i], X[2 * i + 1]), K::Point_2(X[2 * j], X[2 * j + 1]));
    for (int e = 0; e < m; e++) {
        int f = (e + 1) % m;
        if (e == i || e == j || f == i || f == j) continue;
        if (CGAL::do_intersect(d, K::Segment_2(K::Point_2(X[2 * e], X[2 * e + 1]), K::Point_2(X[2 * f], X[2 * f + 1]))))
            return false;
    }
    return true;
}

// Each shape's triangulation chosen to cross the other shapes' as little
// as possible once the corners are on the circle (where two chords cross
// iff their ends interleave): for shape s in turn, the triangulation of
// least weight over its own diagonals (Klincsek's O(m^3) dynamic
// program), a diagonal weighing the number of the other shapes' distinct
// chords it crosses (times m) plus 1 if it is not in s's constrained
// Delaunay triangulation (ties go to the Delaunay diagonals), over the
// triangles no thinner than the Delaunay triangulation's thinnest.  A
// shape's turn never raises the crossings; rounds until none changes (at
// most 4).  On the six flamingo poses with seven given points (the legs
// merged in some poses, apart in others) a 60-gon's overlay went from
// 3347 crossings to about 1000.
// T: in, each shape's constrained Delaunay triangles; out: the chosen ones.
void fewest_crossings(int m, int N, const double *const *X, std::vector<std::vector<int>> &T)
{
    if (N < 2 || m < 5) return;
    size_t mm = (size_t)m * m;
    std::vector<std::vector<unsigned char>> ok(N), cdt(N);
    for (int s = 0; s < N; s++) {
        ok[s].assign(mm, 0);
        cdt[s].assign(mm, 0);
        for (size_t t = 0; t < T[s].size(); t += 3)
            for (int e = 0; e < 3; e++) {
                int a = T[s][t + e], b = T[s][t + (e + 1) % 3];
                if (a > b) std::swap(a, b);
                cdt[s][(size_t)a * m + b] = 1;
            }
        for (int i = 0; i < m; i++)
            for (int j = i + 1; j < m; j++)
                ok[s][(size_t)i * m + j] = j == i + 1 || (i == 0 && j == m - 1) || cdt[s][(size_t)i * m + j] ||
                                           is_diagonal(m, X[s], i, j);
    }
    // no triangle thinner than the Delaunay triangulation's thinnest (the
    // largest smallest angle any triangulation of the shape has): thinner
    // ones would take the crossings mapped into them to slivers
    std::vector<double> floor_(N);
    auto tri_min = [&](int s, int a, int b, int c) {
        const double *P[3] = {X[s] + 2 * a, X[s] + 2 * b, X[s] + 2 * c};
        double mn = M_PI;
        for (int k = 0; k < 3; k++) {
            const double *o = P[k], *u = P[(k + 1) % 3], *v = P[(k + 2) % 3];
            double ux = u[0] - o[0], uy = u[1] - o[1], vx = v[0] - o[0], vy = v[1] - o[1];
            mn = std::min(mn, std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy));
        }
        return mn;
    };
    for (int s = 0; s < N; s++) {
        double f = M_PI;
        for (size_t t = 0; t < T[s].size(); t += 3) f = std::min(f, tri_min(s, T[s][t], T[s][t + 1], T[s][t + 2]));
        floor_[s] = f * (1 - 1e-9);
    }
    std::vector<long long> W(mm), w(mm);
    std::vector<int> arg(mm);
    for (int round = 0; round < 4; round++) {
        int changed = 0;
        for (int s = 0; s < N; s++) {
            // the other shapes' distinct diagonals
            std::vector<unsigned char> other(mm, 0);
            std::vector<std::pair<int, int>> ch;
            for (int t = 0; t < N; t++) {
                if (t == s) continue;
                for (size_t q = 0; q < T[t].size(); q += 3)
                    for (int e = 0; e < 3; e++) {
                        int a = T[t][q + e], b = T[t][q + (e + 1) % 3];
                        if (a > b) std::swap(a, b);
                        if (b - a == 1 || (a == 0 && b == m - 1) || other[(size_t)a * m + b]) continue;
                        other[(size_t)a * m + b] = 1;
                        ch.push_back({a, b});
                    }
            }
            for (int i = 0; i < m; i++)
                for (int j = i + 2; j < m; j++) {
                    long long c = 0;
                    for (auto &h : ch) c += (h.first < i && i < h.second && h.second < j) ||
                                            (i < h.first && h.first < j && j < h.second);
                    w[(size_t)i * m + j] = (i == 0 && j == m - 1) ? 0 : c * m + !cdt[s][(size_t)i * m + j];
                }
            const long long INF = LLONG_MAX / 4;
            for (int i = 0; i + 1 < m; i++) W[(size_t)i * m + i + 1] = 0;
            for (int len = 2; len < m; len++)
                for (int i = 0; i + len < m; i++) {
                    int j = i + len;
                    long long best = INF;
                    int bk = -1;
                    if (ok[s][(size_t)i * m + j])
                        for (int k = i + 1; k < j; k++) {
                            long long a = W[(size_t)i * m + k], b = W[(size_t)k * m + j];
                            if (a >= INF || b >= INF) continue;
                            if (!ok[s][(size_t)i * m + k] || !ok[s][(size_t)k * m + j]) continue;
                            if (tri_min(s, i, k, j) < floor_[s]) continue;
                            if (a + b < best) { best = a + b; bk = k; }
                        }
                    W[(size_t)i * m + j] = bk < 0 ? INF : best + w[(size_t)i * m + j];
                    arg[(size_t)i * m + j] = bk;
                }
            if (W[m - 1] >= INF) continue;          // (cannot happen: the Delaunay triangles are there)
            std::vector<int> tri;
            std::vector<std::pair<int, int>> todo{{0, m - 1}};
            while (!todo.empty()) {
                auto [i, j] = todo.back();
                todo.pop_back();
                if (j - i < 2) continue;
                int k = arg[(size_t)i * m + j];
                tri.push_back(i); tri.push_back(k); tri.push_back(j);
                todo.push_back({k, j});
                todo.push_back({i, k});
            }
            std::vector<int> a = tri, b = T[s];
            auto canon = [](std::vector<int> &v) {
                std::vector<std::array<int, 3>> t;
                for (size_t q = 0; q < v.size(); q += 3) {
                    std::array<int, 3> x{v[q], v[q + 1], v[q + 2]};
                    std::sort(x.begin(), x.end());
                    t.push_back(x);
                }
                std::sort(t.begin(), t.end());
                return t;
            };
            if (canon(a) != canon(b)) { T[s] = tri; changed = 1; }
        }
        if (!changed) break;
    }
}

}

extern "C" int cdt2_polygon(int m, const double *X, int **F)
{
    *F = NULL;
    if (m < 3) return cm_seterr("polygon of %d corners", m);
    try {
        std::vector<int> T;
        if (polygon_triangles(m, X, T) < 0)
            return cm_seterr("the polygon is not simple (%s)",
                             strstr(cm_errmsg(), "repeated") ? "a corner repeats" : "its edges cross");
        *F = (int *)malloc(sizeof(int) * T.size() + 1);
        if (!*F) return cm_seterr("out of memory");
        std::copy(T.begin(), T.end(), *F);
        return 0;
    } catch (const std::exception &e) {
        return cm_seterr("polygon triangulation failed: %s", e.what());
    }
}

namespace {
typedef CGAL::Exact_predicates_exact_constructions_kernel EK;
typedef CGAL::Triangulation_vertex_base_with_info_2<int, EK> EVb;
typedef CGAL::Constrained_triangulation_face_base_2<EK> EFb;
typedef CGAL::Triangulation_data_structure_2<EVb, EFb> ETds;
typedef CGAL::Constrained_triangulation_plus_2<
    CGAL::Constrained_Delaunay_triangulation_2<EK, ETds, CGAL::Exact_intersections_tag>> ECDT;
}

extern "C" int cdt2_overlay(int m, int N, const double *const *X, int fewest, double **Sout, int *kout,
                            int **Fout, int *nfout)
{
    try {
        std::vector<std::vector<int>> T(N);
        for (int s = 0; s < N; s++)
            if (polygon_triangles(m, X[s], T[s]) < 0) return -1;
        if (fewest) fewest_crossings(m, N, X, T);
        // corners on the unit circle at their mean arc-length position
        // (not evenly: the diagonals of a regular polygon meet three at a
        // point, and rounded, in tiny triangles)
        std::vector<double> t(m + 1, 0.0);
        for (int s = 0; s < N; s++) {
            double L = 0;
            std::vector<double> c(m + 1, 0.0);
            for (int i = 0; i < m; i++) {
                const double *a = X[s] + 2 * i, *b = X[s] + 2 * ((i + 1) % m);
                L += std::hypot(b[0] - a[0], b[1] - a[1]);
                c[i + 1] = L;
            }
            for (int i = 0; i <= m; i++) t[i] += c[i] / L / N;
        }
        std::vector<EK::Point_2> D(m);
        for (int i = 0; i < m; i++) {
            // at least a quarter of the even spacing between neighbours
            double u = 0.5 * t[i] + 0.5 * (double)i / m;
            D[i] = EK::Point_2(std::cos(2 * M_PI * u), std::sin(2 * M_PI * u));
        }
        ECDT cdt;
        std::vector<ECDT::Vertex_handle> vh(m);
        for (int i = 0; i < m; i++) { vh[i] = cdt.insert(D[i]); vh[i]->info() = i; }
        std::set<std::pair<int, int>> done;
        for (int i = 0; i < m; i++) cdt.insert_constraint(vh[i], vh[(i + 1) % m]);
        for (int s = 0; s < N; s++)
            for (size_t t = 0; t < T[s].size(); t += 3)
                for (int e = 0; e < 3; e++) {
                    int a = T[s][t + e], b = T[s][t + (e + 1) % 3];
                    if (a > b) std::swap(a, b);
                    if (b - a == 1 || (a == 0 && b == m - 1)) continue;
                    if (!done.insert({a, b}).second) continue;
                    cdt.insert_constraint(vh[a], vh[b]);
                }
        int k = 0;
        std::vector<ECDT::Vertex_handle> extra;
        std::set<ECDT::Vertex_handle> corner(vh.begin(), vh.end());
        for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
            ECDT::Vertex_handle h = v;
            if (!corner.count(h)) { h->info() = m + k++; extra.push_back(h); }
        }
        double *S = (double *)malloc(2 * (size_t)N * k * sizeof(double) + 1);
        if (!S) return cm_seterr("out of memory");
        // the exact values of the corners and crossings, computed once: the
        // barycentric blends below are done in the exact number type, not
        // as lazy expressions (each of whose evaluations costs a
        // std::call_once, a futex system call)
        typedef EK::Exact_kernel XK;
        std::vector<XK::Point_2> XD(m), XP(k);
        for (int i = 0; i < m; i++) XD[i] = CGAL::exact(D[i]);
        for (int q = 0; q < k; q++) XP[q] = CGAL::exact(extra[q]->point());
        for (int s = 0; s < N; s++)
            for (int q = 0; q < k; q++) {
                const EK::Point_2 &p = extra[q]->point();
                int found = 0;
                for (size_t t = 0; t < T[s].size() && !found; t += 3) {
                    const EK::Point_2 &A = D[T[s][t]], &B = D[T[s][t + 1]], &C = D[T[s][t + 2]];
                    // the shape's triangles are ccw in the shape, so ccw on the circle too
                    if (CGAL::orientation(A, B, p) == CGAL::RIGHT_TURN ||
                        CGAL::orientation(B, C, p) == CGAL::RIGHT_TURN ||
                        CGAL::orientation(C, A, p) == CGAL::RIGHT_TURN) continue;
                    // the image in the shape, computed exactly and rounded
                    // once (a rounded barycentric blend can flip a sliver
                    // between nearby crossings)
                    const XK::Point_2 &xA = XD[T[s][t]], &xB = XD[T[s][t + 1]], &xC = XD[T[s][t + 2]];
                    XK::FT area = CGAL::area(xA, xB, xC);
                    XK::FT la = CGAL::area(XP[q], xB, xC) / area, lb = CGAL::area(xA, XP[q], xC) / area;
                    XK::FT lc = 1 - la - lb;
                    const double *xa = X[s] + 2 * T[s][t], *xb = X[s] + 2 * T[s][t + 1], *xc = X[s] + 2 * T[s][t + 2];
                    double *o = S + 2 * ((size_t)s * k + q);
                    for (int d = 0; d < 2; d++) {
                        XK::FT x = la * xa[d] + lb * xb[d] + lc * xc[d];
                        o[d] = CGAL::to_double(x);
                    }
                    found = 1;
                }
                if (!found) { free(S); return cm_seterr("overlay: a crossing lies in no triangle"); }
            }
        std::vector<int> F;
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
            for (int e = 0; e < 3; e++) F.push_back(f->vertex(e)->info());
        *Fout = (int *)malloc(F.size() * sizeof(int) + 1);
        if (!*Fout) { free(S); return cm_seterr("out of memory"); }
        std::copy(F.begin(), F.end(), *Fout);
        *nfout = (int)(F.size() / 3);
        *Sout = S;
        *kout = k;
        return 0;
    } catch (const std::exception &e) {
        return cm_seterr("overlay triangulation failed: %s", e.what());
    }
}

// ---------------------------------------------------------------------
// quality mesh of one simple polygon (see cdt2.h)

extern "C" int cdt2_mesh_polygon(const double *P, int n, double shape, double size,
                                 double **Vout, int *nvout, int **Fout, int *nfout)
{
    try {
        CDT cdt;
        std::vector<VH> vh(n);
        for (int i = 0; i < n; i++) vh[i] = cdt.insert(Point(P[2 * i], P[2 * i + 1]));
        for (int i = 0; i < n; i++) cdt.insert_constraint(vh[i], vh[(i + 1) % n]);
        // one seed inside the polygon: the centroid of a face of the
        // constrained triangulation that lies inside (crossing number)
        std::vector<Point> seeds;
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end() && seeds.empty(); ++f) {
            double x = 0, y = 0;
            for (int k = 0; k < 3; k++) { x += f->vertex(k)->point().x() / 3; y += f->vertex(k)->point().y() / 3; }
            int in = 0;
            for (int i = 0, j = n - 1; i < n; j = i++)
                if ((P[2 * i + 1] > y) != (P[2 * j + 1] > y) &&
                    x < (P[2 * j] - P[2 * i]) * (y - P[2 * i + 1]) / (P[2 * j + 1] - P[2 * i + 1]) + P[2 * i])
                    in = !in;
            if (in) seeds.push_back(Point(x, y));
        }
        if (seeds.empty()) return cm_seterr("2D meshing failed: no triangle inside the polygon");
        CGAL::refine_Delaunay_mesh_2(cdt, seeds.begin(), seeds.end(), Criteria(shape, size), true);
        std::map<VH, int> index;
        std::vector<double> V;
        std::vector<int> F;
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
            if (!f->is_in_domain()) continue;
            for (int k = 0; k < 3; k++) {
                VH v = f->vertex(k);
                auto it = index.find(v);
                if (it == index.end()) {
                    it = index.emplace(v, (int)(V.size() / 2)).first;
                    V.push_back(v->point().x());
                    V.push_back(v->point().y());
                }
                F.push_back(it->second);
            }
        }
        *nvout = (int)(V.size() / 2);
        *nfout = (int)(F.size() / 3);
        *Vout = (double *)malloc(V.size() * sizeof(double) + 1);
        *Fout = (int *)malloc(F.size() * sizeof(int) + 1);
        if (!*Vout || !*Fout) { free(*Vout); free(*Fout); return cm_seterr("out of memory"); }
        std::copy(V.begin(), V.end(), *Vout);
        std::copy(F.begin(), F.end(), *Fout);
        return 0;
    } catch (const std::exception &e) {
        return cm_seterr("2D meshing failed: %s", e.what());
    }
}
