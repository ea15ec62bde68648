// geodesic.cpp -- heat-method geodesic distances (CGAL Heat_method_3 on the
// intrinsic Delaunay triangulation), one solver per connected component.
// See geodesic.h.
#define CGAL_EIGEN3_ENABLED 1
#include "geodesic.h"
#include "cm_error.h"
#include "topology.h"

#include <CGAL/Simple_cartesian.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>

#include <cmath>
#include <memory>
#include <queue>
#include <utility>
#include <vector>

typedef CGAL::Simple_cartesian<double> K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index VI;
typedef CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<
    Mesh, CGAL::Heat_method_3::Intrinsic_Delaunay> Heat;

namespace {
struct Component {
    Mesh mesh;
    std::vector<int> global;              // local vertex -> global vertex
    std::unique_ptr<Heat> heat;
};
}

struct geodesic {
    int nv;
    std::vector<int> comp;                // global vertex -> component (-1: isolated)
    std::vector<int> local;               // global vertex -> local index in its component
    std::vector<std::unique_ptr<Component>> comps;
};

extern "C" struct geodesic *geodesic_new(const double *V, const int *F, int nv, int nf)
{
    if (nv < 1 || nf < 1) {
        cm_seterr("geodesic: empty mesh");
        return nullptr;
    }
    for (int i = 0; i < 3 * nf; i++)
        if (F[i] < 0 || F[i] >= nv) {
            cm_seterr("geodesic: face %d: vertex index %d out of range", i / 3, F[i]);
            return nullptr;
        }
    for (int i = 0; i < 3 * nv; i++)
        if (!std::isfinite(V[i])) {
            cm_seterr("geodesic: vertex %d: coordinate is not finite", i / 3);
            return nullptr;
        }
    struct topology t;
    if (topology_build(F, nf, nv, &t) < 0) return nullptr;
    std::vector<int> fcomp(nf);
    int nc = connected_components(&t, F, fcomp.data());
    topology_free(&t);

    std::unique_ptr<geodesic> g(new geodesic);
    g->nv = nv;
    g->comp.assign(nv, -1);
    g->local.assign(nv, -1);
    try {
        for (int c = 0; c < nc; c++) g->comps.emplace_back(new Component);
        // vertices in face order, so the local numbering is deterministic
        for (int f = 0; f < nf; f++) {
            Component &C = *g->comps[fcomp[f]];
            for (int k = 0; k < 3; k++) {
                int v = F[3 * f + k];
                if (g->comp[v] >= 0) continue;
                g->comp[v] = fcomp[f];
                g->local[v] = (int)C.global.size();
                C.global.push_back(v);
                C.mesh.add_vertex(Point(V[3 * v], V[3 * v + 1], V[3 * v + 2]));
            }
        }
        for (int f = 0; f < nf; f++) {
            Component &C = *g->comps[fcomp[f]];
            int a = F[3 * f], b = F[3 * f + 1], c = F[3 * f + 2];
            if (a == b || b == c || a == c) {
                cm_seterr("geodesic: face %d repeats a vertex", f);
                return nullptr;
            }
            if (C.mesh.add_face(VI(g->local[a]), VI(g->local[b]), VI(g->local[c])) ==
                Mesh::null_face()) {
                cm_seterr("geodesic: face %d makes the mesh non-manifold or "
                          "inconsistently oriented", f);
                return nullptr;
            }
        }
        for (auto &C : g->comps) C->heat.reset(new Heat(C->mesh));
    } catch (const std::exception &e) {
        cm_seterr("geodesic: heat method setup failed: %s", e.what());
        return nullptr;
    } catch (...) {
        cm_seterr("geodesic: heat method setup failed");
        return nullptr;
    }
    return g.release();
}

extern "C" int geodesic_solve(struct geodesic *g, const int *S, int ns, double *D)
{
    if (ns < 1) return cm_seterr("geodesic: no source");
    for (int i = 0; i < ns; i++)
        if (S[i] < 0 || S[i] >= g->nv)
            return cm_seterr("geodesic: source vertex %d out of range (0..%d)", S[i], g->nv - 1);
    for (int v = 0; v < g->nv; v++) D[v] = INFINITY;
    try {
        for (size_t c = 0; c < g->comps.size(); c++) {
            Component &C = *g->comps[c];
            C.heat->clear_sources();
            int any = 0;
            for (int i = 0; i < ns; i++)
                if (g->comp[S[i]] == (int)c) {
                    C.heat->add_source(VI(g->local[S[i]]));
                    any = 1;
                }
            if (!any) continue;
            auto dist = C.mesh.add_property_map<VI, double>("v:geodesic", 0).first;
            C.heat->estimate_geodesic_distances(dist);
            for (size_t l = 0; l < C.global.size(); l++) {
                double d = dist[VI((Mesh::size_type)l)];
                D[C.global[l]] = std::isfinite(d) ? (d > 0 ? d : 0) : INFINITY;
            }
            C.mesh.remove_property_map(dist);
            for (int i = 0; i < ns; i++)
                if (g->comp[S[i]] == (int)c) D[S[i]] = 0;
        }
    } catch (const std::exception &e) {
        return cm_seterr("geodesic: heat method failed: %s", e.what());
    } catch (...) {
        return cm_seterr("geodesic: heat method failed");
    }
    return 0;
}

extern "C" void geodesic_free(struct geodesic *g) { delete g; }

// ---- points on faces: insert them into a copy of the mesh ----

namespace {
struct Soup {
    std::vector<double> V;
    std::vector<int> F;
    std::vector<int> origin;            // current face -> input face
    int addv(const double p[3])
    {
        V.insert(V.end(), p, p + 3);
        return (int)(V.size() / 3) - 1;
    }
    int addf(int a, int b, int c, int o)
    {
        F.push_back(a); F.push_back(b); F.push_back(c);
        origin.push_back(o);
        return (int)(F.size() / 3) - 1;
    }
    void setf(int f, int a, int b, int c)
    {
        F[3 * f] = a; F[3 * f + 1] = b; F[3 * f + 2] = c;
    }
};

// barycentric coordinates of p (in the plane of a, b, c)
static bool bary(const double *a, const double *b, const double *c, const double *p, double w[3])
{
    double v0[3], v1[3], v2[3];
    for (int d = 0; d < 3; d++) { v0[d] = b[d] - a[d]; v1[d] = c[d] - a[d]; v2[d] = p[d] - a[d]; }
    auto dot = [](const double *x, const double *y) { return x[0]*y[0] + x[1]*y[1] + x[2]*y[2]; };
    double d00 = dot(v0, v0), d01 = dot(v0, v1), d11 = dot(v1, v1);
    double d20 = dot(v2, v0), d21 = dot(v2, v1), den = d00 * d11 - d01 * d01;
    if (!(den > 0)) return false;
    w[1] = (d11 * d20 - d01 * d21) / den;
    w[2] = (d00 * d21 - d01 * d20) / den;
    w[0] = 1 - w[1] - w[2];
    return true;
}

// insert the point of input face f at barycentric b; returns its vertex
static int insert_point(Soup &s, const double *V0, const int *F0, int f, const double *b0)
{
    double b[3], sum = 0;
    for (int k = 0; k < 3; k++) { b[k] = b0[k] > 0 ? b0[k] : 0; sum += b[k]; }
    if (!(sum > 0)) { b[0] = b[1] = b[2] = 1.0 / 3; sum = 1; }
    double p[3] = {0, 0, 0};
    for (int k = 0; k < 3; k++)
        for (int d = 0; d < 3; d++) p[d] += b[k] / sum * V0[3 * F0[3 * f + k] + d];
    // the current sub-triangle of f that contains p (largest min coordinate)
    int best = -1;
    double bw[3] = {0, 0, 0}, bmin = -1e300;
    for (size_t t = 0; t < s.origin.size(); t++) {
        if (s.origin[t] != f) continue;
        const int *T = &s.F[3 * t];
        double w[3];
        if (!bary(&s.V[3 * T[0]], &s.V[3 * T[1]], &s.V[3 * T[2]], p, w)) continue;
        double m = std::min(w[0], std::min(w[1], w[2]));
        if (m > bmin) { bmin = m; best = (int)t; bw[0] = w[0]; bw[1] = w[1]; bw[2] = w[2]; }
    }
    if (best < 0) {   // degenerate input face: its first corner stands in
        return F0[3 * f];
    }
    int T[3] = {s.F[3 * best], s.F[3 * best + 1], s.F[3 * best + 2]};
    const double eps = 1e-9;
    int nsmall = 0, zk = -1;
    for (int k = 0; k < 3; k++)
        if (bw[k] < eps) { nsmall++; zk = k; }
    if (nsmall >= 2) {            // at a corner
        int k = bw[0] > bw[1] ? (bw[0] > bw[2] ? 0 : 2) : (bw[1] > bw[2] ? 1 : 2);
        return T[k];
    }
    int nvtx = s.addv(p);
    if (nsmall == 0) {            // inside: 1 -> 3
        s.setf(best, T[0], T[1], nvtx);
        s.addf(T[1], T[2], nvtx, f);
        s.addf(T[2], T[0], nvtx, f);
        return nvtx;
    }
    // on the edge opposite corner zk: split this face and its neighbour
    int a = T[(zk + 1) % 3], c = T[(zk + 2) % 3], o = T[zk];
    s.setf(best, o, a, nvtx);
    s.addf(o, nvtx, c, f);
    size_t nfc = s.origin.size();
    for (size_t t = 0; t < nfc; t++) {
        if ((int)t == best) continue;
        int *U = &s.F[3 * t];
        for (int k = 0; k < 3; k++)
            if (U[k] == c && U[(k + 1) % 3] == a) {      // oriented neighbour c -> a
                int q = U[(k + 2) % 3], of = s.origin[t];
                s.setf((int)t, c, nvtx, q);
                s.addf(nvtx, a, q, of);
                t = nfc;
                break;
            }
    }
    return nvtx;
}
}

extern "C" int geodesic_distance(const double *V, const int *F, int nv, int nf,
                                 const int *S, int ns, const int *SF, const double *SB, int nsf,
                                 double *D)
{
    if (ns + nsf < 1) return cm_seterr("geodesic: no source");
    for (int i = 0; i < ns; i++)
        if (S[i] < 0 || S[i] >= nv)
            return cm_seterr("geodesic: source vertex %d out of range (0..%d)", S[i], nv - 1);
    for (int i = 0; i < nsf; i++)
        if (SF[i] < 0 || SF[i] >= nf)
            return cm_seterr("geodesic: source face %d out of range (0..%d)", SF[i], nf - 1);
    for (int i = 0; i < 3 * nf; i++)
        if (F[i] < 0 || F[i] >= nv)
            return cm_seterr("geodesic: face %d: vertex index %d out of range", i / 3, F[i]);
    if (nsf == 0) {
        struct geodesic *g = geodesic_new(V, F, nv, nf);
        if (!g) return -1;
        int r = geodesic_solve(g, S, ns, D);
        geodesic_free(g);
        return r;
    }
    Soup s;
    s.V.assign(V, V + 3 * (size_t)nv);
    s.F.assign(F, F + 3 * (size_t)nf);
    s.origin.resize(nf);
    for (int f = 0; f < nf; f++) s.origin[f] = f;
    std::vector<int> src(S, S + ns);
    for (int i = 0; i < nsf; i++) src.push_back(insert_point(s, V, F, SF[i], SB + 3 * i));
    int n2 = (int)(s.V.size() / 3);
    struct geodesic *g = geodesic_new(s.V.data(), s.F.data(), n2, (int)s.origin.size());
    if (!g) return -1;
    std::vector<double> D2(n2);
    int r = geodesic_solve(g, src.data(), (int)src.size(), D2.data());
    geodesic_free(g);
    if (r == 0)
        for (int v = 0; v < nv; v++) D[v] = D2[v];
    return r;
}

extern "C" int geodesic_extend(const double *V, const int *F, int nv, int nf, const int *B, int nb,
                               double *D)
{
    for (int i = 0; i < 3 * nf; i++)
        if (F[i] < 0 || F[i] >= nv)
            return cm_seterr("geodesic: face %d: vertex index %d out of range", i / 3, F[i]);
    for (int i = 0; i < 2 * nb; i++)
        if (B[i] < 0 || B[i] >= nv)
            return cm_seterr("geodesic: bridge %d: vertex index %d out of range", i / 2, B[i]);
    // adjacency (CSR) of mesh edges and bridges; an edge may appear twice
    std::vector<int> deg(nv + 1, 0), adj;
    auto each = [&](auto fn) {
        for (int f = 0; f < nf; f++)
            for (int k = 0; k < 3; k++) fn(F[3 * f + k], F[3 * f + (k + 1) % 3]);
        for (int i = 0; i < nb; i++) fn(B[2 * i], B[2 * i + 1]);
    };
    each([&](int a, int b) { deg[a + 1]++; deg[b + 1]++; });
    for (int v = 0; v < nv; v++) deg[v + 1] += deg[v];
    adj.resize(deg[nv]);
    std::vector<int> fill(deg.begin(), deg.end() - 1);
    each([&](int a, int b) { adj[fill[a]++] = b; adj[fill[b]++] = a; });
    typedef std::pair<double, int> Q;
    std::priority_queue<Q, std::vector<Q>, std::greater<Q>> q;
    std::vector<char> fixed(nv, 0);
    for (int v = 0; v < nv; v++)
        if (std::isfinite(D[v])) { fixed[v] = 1; q.push(Q(D[v], v)); }
    while (!q.empty()) {
        Q t = q.top();
        q.pop();
        int v = t.second;
        if (t.first > D[v]) continue;
        for (int i = deg[v]; i < deg[v + 1]; i++) {
            int u = adj[i];
            if (fixed[u]) continue;
            double l = 0;
            for (int k = 0; k < 3; k++) l += (V[3 * u + k] - V[3 * v + k]) * (V[3 * u + k] - V[3 * v + k]);
            double d = D[v] + std::sqrt(l);
            if (d < D[u]) { D[u] = d; q.push(Q(d, u)); }
        }
    }
    int left = 0;
    for (int v = 0; v < nv; v++) left += !std::isfinite(D[v]);
    return left;
}
