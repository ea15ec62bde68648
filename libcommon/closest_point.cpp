// closest_point.cpp -- see closest_point.h.  A bounding volume hierarchy
// of the triangles built by the surface area heuristic (sah() below),
// walked nearest box first with our own triangle test (Nearest below):
// about 3x faster than CGAL's AABB_tree closest_point_and_primitive(), the
// same distances, and 10-15% fewer boxes a query than CGAL's median split
// (the camel in-betweens of bench/b-metrics.sh: 22 against 24 nodes).
// CGAL's AABB tree (Simple_cartesian<double>: exact predicates are not
// needed for distances) is kept for the box query of
// closest_point_faces_within(), built on its first call.
#include "closest_point.h"
#include "cm_error.h"
#include <CGAL/Simple_cartesian.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <algorithm>
#include <cstring>
#include <cmath>
#include <thread>
#include <mutex>
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

// The binary tree, in one array in depth-first order for the
// nearest-point walk (the nodes of a query's path then sit
// next to each other in memory).  A node holds the boxes of its two
// children (a child is a node index >= 0 or a face -1 - f; a face's box is
// its triangle's), so a step of the walk reads one cache line and never
// the children themselves: lo[s] hi[s] child[s], s = 0, 1.
struct alignas(64) flat_node { float lo[2][3], hi[2][3]; int child[2]; };  // 56 (64) bytes

// The same tree with four children a node (widen(): a node's children,
// the largest box opened until four), for closest_points_batch(): the
// four boxes in single precision side by side, so one set of vector
// operations gives all four distances.  child[s]: a wide node >= 0, a
// face -1 - f, or NONE (an empty slot, its box empty).
struct alignas(64) wide_node { float lo[3][4], hi[3][4]; int child[4]; };  // 112 (128) bytes
enum { NONE = -2147483647 - 1 };

struct closest_point_tree {
    int nf;
    std::vector<wide_node> wide;
    std::vector<double> P;      // #F by 9: the triangles' corners
    std::vector<flat_node> nodes;
    float root_lo[3], root_hi[3];   // the root's box
    // CGAL's tree, for closest_point_faces_within() only: built by its
    // first call
    mutable std::once_flag cgal_once;
    mutable std::vector<Triangle> tris;
    mutable Tree tree;
};

// single precision, rounded outward: the boxes still contain their triangles
static void float_box(const double l[3], const double h[3], float lo[3], float hi[3])
{
    for (int d = 0; d < 3; d++) {
        lo[d] = std::nextafter((float)l[d], -HUGE_VALF);
        hi[d] = std::nextafter((float)h[d], HUGE_VALF);
    }
}

// The binary tree built here by the surface area heuristic (binned, 16
// bins an axis: Wald, On fast construction of SAH-based bounding volume
// hierarchies, 2007): a split minimises area(left) * #left + area(right) *
// #right, which for a surface mesh gives tighter boxes than a median split
// and so fewer boxes near a query point.  R[lo..hi): the faces, each with
// its box and centre (reordered in place); returns the child reference
// (a node >= 0, or a face -1 - f) and its box in blo, bhi.
struct sah_face { float lo[3], hi[3], c[3]; int f; };
static float half_area(const float *lo, const float *hi)
{
    float e[3] = {hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]};
    return e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
}
static inline __attribute__((always_inline)) void box_grow(float *lo, float *hi, const float *l, const float *h)
{
    for (int d = 0; d < 3; d++) { lo[d] = std::min(lo[d], l[d]); hi[d] = std::max(hi[d], h[d]); }
}
static int sah_node(closest_point_tree *T, sah_face *R, int lo, int mid, int hi, float *blo, float *bhi);
static int sah(closest_point_tree *T, sah_face *R, int lo, int hi, float *blo, float *bhi)
{
    if (hi - lo == 1) {
        for (int d = 0; d < 3; d++) { blo[d] = R[lo].lo[d]; bhi[d] = R[lo].hi[d]; }
        return -1 - R[lo].f;
    }
    // the centres' box picks the bins
    float clo[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF}, chi[3] = {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF};
    box_grow(clo, chi, R[lo].c, R[lo].c);
    for (int i = lo + 1; i < hi; i++) box_grow(clo, chi, R[i].c, R[i].c);
    int mid = (lo + hi) / 2;
    if (hi - lo <= 8) {
        // a few faces: halves along the centres' longest extent (binning
        // costs more than it saves this low in the tree)
        int d = chi[1] - clo[1] > chi[0] - clo[0] ? 1 : 0;
        if (chi[2] - clo[2] > chi[d] - clo[d]) d = 2;
        std::nth_element(R + lo, R + mid, R + hi,
                         [d](const sah_face &a, const sah_face &b) { return a.c[d] < b.c[d]; });
        return sah_node(T, R, lo, mid, hi, blo, bhi);
    }
    enum { NB = 16 };
    float lb[3][NB][3], hb[3][NB][3], sc[3];
    int cnt[3][NB] = {{0}};
    for (int d = 0; d < 3; d++) {
        sc[d] = chi[d] > clo[d] ? NB / (chi[d] - clo[d]) : 0;
        for (int b = 0; b < NB; b++)
            for (int e = 0; e < 3; e++) { lb[d][b][e] = HUGE_VALF; hb[d][b][e] = -HUGE_VALF; }
    }
    auto bin = [&](const sah_face &r, int d) { return std::min(NB - 1, (int)((r.c[d] - clo[d]) * sc[d])); };
    for (int i = lo; i < hi; i++)
        for (int d = 0; d < 3; d++) {
            int b = bin(R[i], d);
            cnt[d][b]++;
            box_grow(lb[d][b], hb[d][b], R[i].lo, R[i].hi);
        }
    int axis = -1, cut = 0;
    float bestc = HUGE_VALF;
    for (int d = 0; d < 3; d++) {
        if (!(chi[d] > clo[d])) continue;
        // areas of the unions from the right, then the sweep from the left
        float ra[NB], rl[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF}, rh[3] = {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF};
        int rc[NB], n = 0;
        for (int b = NB - 1; b > 0; b--) {
            if (cnt[d][b]) box_grow(rl, rh, lb[d][b], hb[d][b]);
            n += cnt[d][b]; rc[b] = n; ra[b] = n ? half_area(rl, rh) : 0;
        }
        float ll[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF}, lh[3] = {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF};
        n = 0;
        for (int b = 0; b < NB - 1; b++) {
            if (cnt[d][b]) box_grow(ll, lh, lb[d][b], hb[d][b]);
            n += cnt[d][b];
            if (n == 0 || rc[b + 1] == 0) continue;
            float c = half_area(ll, lh) * n + ra[b + 1] * rc[b + 1];
            if (c < bestc) { bestc = c; axis = d; cut = b + 1; }
        }
    }
    if (axis >= 0) {          // else all centres equal: any halves
        auto left = [&](const sah_face &r) { return bin(r, axis) < cut; };
        mid = (int)(std::partition(R + lo, R + hi, left) - R);
        if (mid == lo || mid == hi) mid = (lo + hi) / 2;
    }
    return sah_node(T, R, lo, mid, hi, blo, bhi);
}

// a node of faces R[lo..mid) and R[mid..hi): see sah()
static int sah_node(closest_point_tree *T, sah_face *R, int lo, int mid, int hi, float *blo, float *bhi)
{
    int k = (int)T->nodes.size();
    T->nodes.emplace_back();
    flat_node x;
    x.child[0] = sah(T, R, lo, mid, x.lo[0], x.hi[0]);
    x.child[1] = sah(T, R, mid, hi, x.lo[1], x.hi[1]);
    for (int d = 0; d < 3; d++) {
        blo[d] = std::min(x.lo[0][d], x.lo[1][d]);
        bhi[d] = std::max(x.hi[0][d], x.hi[1][d]);
    }
    T->nodes[k] = x;
    return k;
}

// flat node k and its descendants as wide node(s); returns its index.
// The four slots: start from k's two children and open the one with the
// largest box surface until four (the usual collapse of a binary tree,
// which keeps the boxes a query walks into small)
static int widen(closest_point_tree *T, int k)
{
    int w = (int)T->wide.size();
    T->wide.emplace_back();
    struct slot { float lo[3], hi[3]; int child; };   // child: flat node >= 0 or face < 0
    slot sl[4];
    int ns = 0;
    auto open_node = [&](int c, int at) {     // flat node c's two children into slots at, ns
        const flat_node &m = T->nodes[c];
        for (int t = 0; t < 2; t++) {
            slot &z = sl[t == 0 ? at : ns++];
            for (int d = 0; d < 3; d++) { z.lo[d] = m.lo[t][d]; z.hi[d] = m.hi[t][d]; }
            z.child = m.child[t];
        }
    };
    ns = 1;
    open_node(k, 0);
    while (ns < 4) {
        int best = -1;
        float ba = -1;
        for (int s = 0; s < ns; s++) {
            if (sl[s].child < 0) continue;
            float e[3];
            for (int d = 0; d < 3; d++) e[d] = sl[s].hi[d] - sl[s].lo[d];
            float a = e[0] * e[1] + e[1] * e[2] + e[2] * e[0];
            if (a > ba) { ba = a; best = s; }
        }
        if (best < 0) break;
        open_node(sl[best].child, best);
    }
    wide_node x;
    for (int s = 0; s < 4; s++) {
        for (int d = 0; d < 3; d++) {
            x.lo[d][s] = s < ns ? sl[s].lo[d] : HUGE_VALF;
            x.hi[d][s] = s < ns ? sl[s].hi[d] : -HUGE_VALF;
        }
        x.child[s] = s < ns ? (sl[s].child < 0 ? sl[s].child : 0) : NONE;
    }
    for (int s = 0; s < ns; s++)
        if (sl[s].child >= 0) x.child[s] = widen(T, sl[s].child);
    T->wide[w] = x;
    return w;
}

// The closest point to p on triangle a b c (Ericson, Real-Time Collision
// Detection 5.1.5, by Voronoi regions): c (out) and its barycentrics b
// (out); returns the squared distance.  Degenerate triangles are fine.
static double tri_closest(const double *t, const double p[3], double c[3], double b[3])
{
    const double *A = t, *B = t + 3, *C = t + 6;
    double ab[3], ac[3], ap[3], bp[3], cp[3];
    for (int d = 0; d < 3; d++) {
        ab[d] = B[d] - A[d]; ac[d] = C[d] - A[d]; ap[d] = p[d] - A[d];
        bp[d] = p[d] - B[d]; cp[d] = p[d] - C[d];
    }
    auto dot = [](const double *u, const double *v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
    double d1 = dot(ab, ap), d2 = dot(ac, ap), d3 = dot(ab, bp), d4 = dot(ac, bp);
    double d5 = dot(ab, cp), d6 = dot(ac, cp);
    double u, v, w;
    double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (d1 <= 0 && d2 <= 0) { u = 1; v = w = 0; }
    else if (d3 >= 0 && d4 <= d3) { v = 1; u = w = 0; }
    else if (d6 >= 0 && d5 <= d6) { w = 1; u = v = 0; }
    else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
        v = d1 - d3 > 0 ? d1 / (d1 - d3) : 0; u = 1 - v; w = 0;
    } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
        w = d2 - d6 > 0 ? d2 / (d2 - d6) : 0; u = 1 - w; v = 0;
    } else if (va <= 0 && d4 - d3 >= 0 && d5 - d6 >= 0) {
        double den = (d4 - d3) + (d5 - d6);
        w = den > 0 ? (d4 - d3) / den : 0; v = 1 - w; u = 0;
    } else if (va + vb + vc > 0) {
        double den = 1 / (va + vb + vc);
        v = vb * den; w = vc * den; u = 1 - v - w;
    } else {
        // a sliver the tests above did not place: the best of its corners
        double best = 1e300;
        u = v = w = 0;
        for (int k = 0; k < 3; k++) {
            const double *q = t + 3 * k;
            double e = (p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                       (p[2] - q[2]) * (p[2] - q[2]);
            if (e < best) { best = e; u = k == 0; v = k == 1; w = k == 2; }
        }
    }
    double s2 = 0;
    for (int d = 0; d < 3; d++) {
        c[d] = u * A[d] + v * B[d] + w * C[d];
        s2 += (p[d] - c[d]) * (p[d] - c[d]);
    }
    b[0] = u; b[1] = v; b[2] = w;
    return s2;
}

// squared distance from q to the box lo..hi
template <typename R>
static inline double box_d2(const double *q, const R *lo, const R *hi)
{
    // branch-free: the outcome of each comparison is a coin toss
    double s = 0;
    for (int d = 0; d < 3; d++) {
        double e = std::max(std::max((double)lo[d] - q[d], q[d] - (double)hi[d]), 0.0);
        s += e * e;
    }
    return s;
}

// For the walks of the wide tree: q rounded down (qd) and up (qu) to
// single precision, each broadcast to four lanes; the box distances of
// box4_d2() are then never larger than the exact ones, less rounding.
typedef float v4 __attribute__((vector_size(16)));
static void query_bounds(const double q[3], v4 qd[3], v4 qu[3])
{
    for (int d = 0; d < 3; d++) {
        float f = (float)q[d], lo = f, hi = f;
        if ((double)f > q[d]) lo = std::nextafter(f, -HUGE_VALF);
        if ((double)f < q[d]) hi = std::nextafter(f, HUGE_VALF);
        qd[d] = (v4){lo, lo, lo, lo}; qu[d] = (v4){hi, hi, hi, hi};
    }
}
// the squared distances from the query (query_bounds()) to n's four boxes
static inline v4 box4_d2(const wide_node &n, const v4 qd[3], const v4 qu[3])
{
    const v4 zero = {0, 0, 0, 0};
    v4 s2 = zero;
    for (int d = 0; d < 3; d++) {
        v4 lo, hi;
        memcpy(&lo, n.lo[d], sizeof lo); memcpy(&hi, n.hi[d], sizeof hi);
        v4 a = lo - qu[d], b = qd[d] - hi;
        v4 e = a > b ? a : b;
        e = e > zero ? e : zero;
        s2 += e * e;
    }
    return s2;
}

// the nearest triangle: a walk of the flat tree (or of the wide one),
// nearer child first, skipping every box (and triangle box) no nearer than
// the best so far
namespace {
struct Nearest {
    const closest_point_tree *T;
    double q[3], best, c[3], b[3];
    int face;
    void start(const closest_point_tree *t, const double p[3])
    {
        T = t; q[0] = p[0]; q[1] = p[1]; q[2] = p[2];
        best = HUGE_VAL; face = -1;
    }
    // face f; its box (in the parent node) is dd away: most leaves end
    // there.  Of faces equally near, the one with the smallest index wins,
    // so the answer is the same whatever the tree and the order of the walk
    // (a query on an edge or a vertex: a seed point, a mirror image); boxes
    // exactly as far as the best are therefore still entered
    void test(int f, double dd)
    {
        if (face >= 0 && (dd > best || f == face)) return;
        const double *t = &T->P[9 * (size_t)f];
        double cc[3], bb[3], d2 = tri_closest(t, q, cc, bb);
        if (d2 < best || face < 0 || (d2 == best && f < face)) {
            best = d2; face = f;
            for (int d = 0; d < 3; d++) { c[d] = cc[d]; b[d] = bb[d]; }
        }
    }
    // the walk of the wide tree: the same answer as walk()
    void walk4()
    {
        const std::vector<wide_node> &N = T->wide;
        if (N.empty()) { test(0, 0); return; }
        v4 qd[3], qu[3];
        query_bounds(q, qd, qu);
        int stack[128], top = 0;
        double sd[128];
        stack[top] = 0; sd[top++] = 0;
        while (top > 0) {
            --top;
            if (sd[top] > best && face >= 0) continue;
            const wide_node &n = N[stack[top]];
            v4 s2 = box4_d2(n, qd, qu);
            // a lower bound of each box's squared distance (the float
            // rounding of the sums above is far below 1e-5 relative; past
            // the float range, no bound)
            double lb[4];
            for (int s = 0; s < 4; s++)
                lb[s] = n.child[s] == NONE ? HUGE_VAL
                        : s2[s] < HUGE_VALF ? (double)s2[s] * (1 - 1e-5) : 0;
            // faces first, then the nodes (no sorting by distance: with a
            // good hint the best is tight from the start, and the sort
            // costs more than it saves)
            for (int s = 0; s < 4; s++)
                if (n.child[s] < 0 && n.child[s] != NONE) test(-1 - n.child[s], lb[s]);
            for (int s = 3; s >= 0; s--)
                if (n.child[s] >= 0 && (lb[s] <= best || face < 0) && top < 128) {
                    stack[top] = n.child[s]; sd[top++] = lb[s];
                }
        }
    }
    void walk()
    {
        const std::vector<flat_node> &N = T->nodes;
        if (N.empty()) { test(0, 0); return; }
        // the stack holds nodes with their box distances at the push
        int stack[128], top = 0;
        double sd[128];
        stack[top] = 0; sd[top++] = box_d2(q, T->root_lo, T->root_hi);
        while (top > 0) {
            --top;
            if (sd[top] > best && face >= 0) continue;
            const flat_node &n = N[stack[top]];
            double dd[2];
            for (int s = 0; s < 2; s++) {
                dd[s] = box_d2(q, n.lo[s], n.hi[s]);
                if (n.child[s] < 0) { test(-1 - n.child[s], dd[s]); dd[s] = HUGE_VAL; }
            }
            // push the farther child first, so the nearer one comes next
            int first = dd[1] < dd[0] ? 1 : 0;
            for (int s = 1; s >= 0; s--) {
                int w = s == 0 ? first : 1 - first;
                if (n.child[w] >= 0 && (dd[w] <= best || face < 0) && top < 128) {
                    stack[top] = n.child[w]; sd[top++] = dd[w];
                }
            }
        }
    }
};
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
    T->nf = nf;
    T->P.resize(9 * (size_t)nf);
    // each face's box (single precision, rounded outward) and its centre
    std::vector<sah_face> R(nf);
    for (int f = 0; f < nf; f++) {
        double *t = &T->P[9 * (size_t)f], lo[3], hi[3];
        for (int k = 0; k < 3; k++)
            for (int d = 0; d < 3; d++) t[3 * k + d] = V[3 * F[3 * f + k] + d];
        for (int d = 0; d < 3; d++) {
            lo[d] = std::min(t[d], std::min(t[3 + d], t[6 + d]));
            hi[d] = std::max(t[d], std::max(t[3 + d], t[6 + d]));
        }
        float_box(lo, hi, R[f].lo, R[f].hi);
        for (int d = 0; d < 3; d++) R[f].c[d] = 0.5f * (R[f].lo[d] + R[f].hi[d]);
        R[f].f = f;
    }
    if (nf >= 2) {
        T->nodes.reserve(nf);
        sah(T, R.data(), 0, nf, T->root_lo, T->root_hi);
        T->wide.reserve(nf / 2 + 1);
        widen(T, 0);
    }
    return T;
}

// CGAL's tree of T's triangles, built by the first call
static const Tree &cgal_tree(const closest_point_tree *T)
{
    std::call_once(T->cgal_once, [T] {
        T->tris.reserve(T->nf);
        for (int f = 0; f < T->nf; f++) {
            const double *t = &T->P[9 * (size_t)f];
            T->tris.emplace_back(Point(t[0], t[1], t[2]), Point(t[3], t[4], t[5]),
                                 Point(t[6], t[7], t[8]));
        }
        T->tree.insert(T->tris.begin(), T->tris.end());
        T->tree.build();
        T->tree.do_not_accelerate_distance_queries();
    });
    return T->tree;
}

extern "C" void closest_point_tree_free(struct closest_point_tree *T) { delete T; }

// the nearest point to p, starting from face h (-1: none), into r
static void query_hinted(const closest_point_tree *T, const double p[3], int h, Nearest &r)
{
    r.start(T, p);
    if (h >= 0 && h < T->nf) r.test(h, 0);
    r.walk();
}

extern "C" double closest_point_query(const struct closest_point_tree *T, const double p[3],
                                      double c[3], int *face, double bary[3])
{
    Nearest r;
    query_hinted(T, p, -1, r);
    if (c) { c[0] = r.c[0]; c[1] = r.c[1]; c[2] = r.c[2]; }
    if (face) *face = r.face;
    if (bary) { bary[0] = r.b[0]; bary[1] = r.b[1]; bary[2] = r.b[2]; }
    return std::sqrt(r.best);
}

extern "C" void closest_points(const struct closest_point_tree *T, const double *P, int n,
                               double *C, int *I, double *B, double *D)
{
    closest_points_hinted(T, P, n, NULL, C, I, B, D);
}

// 30 bits of Morton code of a point in the box lo + [0, ext]^3
static unsigned morton(const double *p, const double lo[3], double ext)
{
    unsigned m = 0;
    unsigned c[3];
    for (int d = 0; d < 3; d++) {
        double t = ext > 0 ? (p[d] - lo[d]) / ext : 0;
        c[d] = (unsigned)(t < 0 ? 0 : t >= 1 ? 1023 : t * 1024);
    }
    for (int b = 9; b >= 0; b--)
        for (int d = 0; d < 3; d++) m = (m << 1) | ((c[d] >> b) & 1);
    return m;
}

// the queries P (n by 3) in Morton order: neighbours one after another
// walk the same tree nodes, which then stay in the cache
static std::vector<int> morton_order(const double *P, int n)
{
    std::vector<std::pair<unsigned, int>> order(n);
    double lo[3] = {HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi[3] = {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
    for (int i = 0; i < n; i++)
        for (int d = 0; d < 3; d++) {
            lo[d] = std::min(lo[d], P[3 * (size_t)i + d]);
            hi[d] = std::max(hi[d], P[3 * (size_t)i + d]);
        }
    double ext = std::max(hi[0] - lo[0], std::max(hi[1] - lo[1], hi[2] - lo[2]));
    for (int i = 0; i < n; i++) order[i] = std::make_pair(morton(P + 3 * (size_t)i, lo, ext), i);
    std::sort(order.begin(), order.end());
    std::vector<int> o(n);
    for (int i = 0; i < n; i++) o[i] = order[i].second;
    return o;
}

namespace {
// where the answers of a batch go (each array may be NULL)
struct answers {
    double *C, *B, *D; int *I;
    void put(int i, const Nearest &r) const
    {
        if (C) for (int d = 0; d < 3; d++) C[3 * (size_t)i + d] = r.c[d];
        if (I) I[i] = r.face;
        if (B) for (int d = 0; d < 3; d++) B[3 * (size_t)i + d] = r.b[d];
        if (D) D[i] = std::sqrt(r.best);
    }
};
}

// run work(lo, hi) over 0..n, on two threads when n is large
template <typename W> static void split2(int n, W work)
{
    if (n < 2000) { work(0, n); return; }
    std::thread th(work, 0, n / 2);
    work(n / 2, n);
    th.join();
}

extern "C" void closest_points_hinted(const struct closest_point_tree *T, const double *P, int n,
                                      const int *H, double *C, int *I, double *B, double *D)
{
    std::vector<int> order = morton_order(P, n);
    answers A = {C, B, D, I};
    split2(n, [&](int lo, int hi) {
        for (int j = lo; j < hi; j++) {
            int i = order[j];
            Nearest r;
            query_hinted(T, P + 3 * (size_t)i, H ? H[i] : -1, r);
            A.put(i, r);
        }
    });
}

extern "C" void closest_points_order(const double *P, int n, int *O)
{
    std::vector<int> o = morton_order(P, n);
    std::copy(o.begin(), o.end(), O);
}

extern "C" void closest_points_batch(const struct closest_point_tree *T, const double *P, int n,
                                     const int *H, const int *O, double *C, int *I, double *B,
                                     double *D)
{
    std::vector<int> own;
    if (!O) { own = morton_order(P, n); O = own.data(); }
    answers A = {C, B, D, I};
    int nf = T->nf;
    split2(n, [&](int lo, int hi) {
        int prev = -1;   // without a hint: the previous query's answer
        for (int j = lo; j < hi; j++) {
            int i = O[j], h = H ? H[i] : -1;
            if (h < 0 || h >= nf) h = prev;
            Nearest r;
            r.start(T, P + 3 * (size_t)i);
            if (h >= 0) r.test(h, 0);
            r.walk4();
            A.put(i, r);
            prev = r.face;
        }
    });
}

extern "C" int closest_point_faces_within_visit(const struct closest_point_tree *T,
                                                const double p[3], double r,
                                                int (*visit)(int f, void *ctx), void *ctx)
{
    // the wide tree's walk, every box within r (its float box rounded
    // outward and the query rounded both ways: no face within r is missed),
    // then the triangle's own distance
    double r2 = r * r;
    if (T->wide.empty()) {
        double c[3], b[3];
        return tri_closest(&T->P[0], p, c, b) <= r2 ? visit(0, ctx) : 0;
    }
    v4 qd[3], qu[3];
    query_bounds(p, qd, qu);
    std::vector<int> stack(1, 0);
    while (!stack.empty()) {
        const wide_node &n = T->wide[stack.back()];
        stack.pop_back();
        v4 s2 = box4_d2(n, qd, qu);
        for (int s = 0; s < 4; s++) {
            if (n.child[s] == NONE || (s2[s] < HUGE_VALF && (double)s2[s] * (1 - 1e-5) > r2)) continue;
            if (n.child[s] >= 0) { stack.push_back(n.child[s]); continue; }
            int f = -1 - n.child[s];
            double c[3], b[3];
            if (tri_closest(&T->P[9 * (size_t)f], p, c, b) <= r2) {
                int v = visit(f, ctx);
                if (v) return v;
            }
        }
    }
    return 0;
}

extern "C" int closest_point_faces_within(const struct closest_point_tree *T, const double p[3],
                                          double r, int *out, int max)
{
    Point q(p[0], p[1], p[2]);
    CGAL::Bbox_3 box(p[0] - r, p[1] - r, p[2] - r, p[0] + r, p[1] + r, p[2] + r);
    std::vector<Tree::Primitive_id> hits;
    cgal_tree(T).all_intersected_primitives(box, std::back_inserter(hits));
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
    double cc[3], bb[3], d2 = tri_closest(&T->P[9 * (size_t)f], p, cc, bb);
    if (c) { c[0] = cc[0]; c[1] = cc[1]; c[2] = cc[2]; }
    if (bary) { bary[0] = bb[0]; bary[1] = bb[1]; bary[2] = bb[2]; }
    return std::sqrt(d2);
}
