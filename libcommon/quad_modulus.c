/* quad_modulus.c -- see quad_modulus.h. */
#include "quad_modulus.h"
#include "cdt2.h"
#include "cm_error.h"
#include "spd.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

struct quad_modulus {
    int n;              /* polygon corners */
    double *P;          /* n by 2 */
    int idx[4];         /* a, b, c, d */
    int nv, nf, vcap, fcap;
    double *V;          /* #V by 2 */
    int *F;             /* #F by 3, counter-clockwise */
    int *Nb;            /* #F by 3: the triangle across the edge opposite corner k, -1 on the boundary */
    int *ed;            /* #V: polygon edge the boundary vertex lies on (a corner k: k), -1 inside */
    int *corner;        /* #V: polygon corner index, or -1 */
    double *u, *v;      /* #V: the solution and the conjugate solution */
    double Eu, Ev;      /* their energies */
};

/* ---- mesh storage ---- */

static int grow(struct quad_modulus *q, int nv, int nf)
{
    if (nv > q->vcap) {
        int c = q->vcap ? q->vcap : 64;
        while (c < nv) c *= 2;
        double *V = realloc(q->V, 2 * (size_t)c * sizeof *V);
        if (V) q->V = V;
        int *ed = V ? realloc(q->ed, c * sizeof *ed) : NULL;
        if (ed) q->ed = ed;
        int *co = ed ? realloc(q->corner, c * sizeof *co) : NULL;
        if (co) q->corner = co;
        double *u = co ? realloc(q->u, c * sizeof *u) : NULL;
        if (u) q->u = u;
        double *v = u ? realloc(q->v, c * sizeof *v) : NULL;
        if (!v) return cm_seterr("out of memory");
        q->v = v;
        q->vcap = c;
    }
    if (nf > q->fcap) {
        int c = q->fcap ? q->fcap : 64;
        while (c < nf) c *= 2;
        int *F = realloc(q->F, 3 * (size_t)c * sizeof *F);
        if (F) q->F = F;
        int *Nb = F ? realloc(q->Nb, 3 * (size_t)c * sizeof *Nb) : NULL;
        if (!Nb) return cm_seterr("out of memory");
        q->Nb = Nb;
        q->fcap = c;
    }
    return 0;
}

struct hedge { int a, b, f, k; };   /* edge key (a < b), its triangle and the corner opposite */

static int hedge_cmp(const void *x, const void *y)
{
    const struct hedge *p = x, *r = y;
    if (p->a != r->a) return p->a < r->a ? -1 : 1;
    if (p->b != r->b) return p->b < r->b ? -1 : 1;
    return p->f < r->f ? -1 : p->f > r->f;
}

/* neighbours across every edge (Nb), by sorting the edges */
static int build_adjacency(struct quad_modulus *q)
{
    int nf = q->nf;
    struct hedge *H = malloc(3 * (size_t)nf * sizeof *H + 1);
    if (!H) return cm_seterr("out of memory");
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) {
            int a = q->F[3 * f + (k + 1) % 3], b = q->F[3 * f + (k + 2) % 3];
            H[3 * f + k] = (struct hedge){a < b ? a : b, a < b ? b : a, f, k};
            q->Nb[3 * f + k] = -1;
        }
    qsort(H, 3 * (size_t)nf, sizeof *H, hedge_cmp);
    for (size_t i = 0; i < 3 * (size_t)nf; i++) {
        size_t j = i;
        while (j + 1 < 3 * (size_t)nf && H[j + 1].a == H[i].a && H[j + 1].b == H[i].b) j++;
        if (j - i > 1) { free(H); return cm_seterr("quadrilateral mesh is not a manifold"); }
        if (j == i + 1) {
            q->Nb[3 * H[i].f + H[i].k] = H[j].f;
            q->Nb[3 * H[j].f + H[j].k] = H[i].f;
        }
        i = j;
    }
    free(H);
    return 0;
}

static int cmp_corner(const void *x, const void *y, const double *P)
{
    int i = *(const int *)x, j = *(const int *)y;
    if (P[2 * i] != P[2 * j]) return P[2 * i] < P[2 * j] ? -1 : 1;
    if (P[2 * i + 1] != P[2 * j + 1]) return P[2 * i + 1] < P[2 * j + 1] ? -1 : 1;
    return (i > j) - (i < j);
}
static const double *sort_P;
static int cmp_corner_q(const void *x, const void *y) { return cmp_corner(x, y, sort_P); }

/* which polygon corner or edge each boundary vertex of the mesh is on:
 * the corners are found by their exact coordinates, then the boundary is
 * walked counter-clockwise from corner 0 */
static int label_boundary(struct quad_modulus *q)
{
    int n = q->n, nv = q->nv;
    int *ord = malloc(n * sizeof *ord), *next = malloc(nv * sizeof *next);
    if (!ord || !next) { free(ord); free(next); return cm_seterr("out of memory"); }
    for (int i = 0; i < n; i++) ord[i] = i;
    sort_P = q->P;
    qsort(ord, n, sizeof *ord, cmp_corner_q);
    for (int v = 0; v < nv; v++) { q->corner[v] = -1; q->ed[v] = -1; next[v] = -1; }
    int found = 0;
    for (int v = 0; v < nv; v++) {
        int lo = 0, hi = n - 1;
        while (lo <= hi) {
            int m = (lo + hi) / 2, c = ord[m];
            double dx = q->V[2 * v] - q->P[2 * c], dy = q->V[2 * v + 1] - q->P[2 * c + 1];
            if (dx == 0 && dy == 0) { q->corner[v] = c; found++; break; }
            if (dx < 0 || (dx == 0 && dy < 0)) hi = m - 1; else lo = m + 1;
        }
    }
    free(ord);
    if (found != n) { free(next); return cm_seterr("quadrilateral mesh lost %d polygon corners", n - found); }
    /* boundary edges a -> b (counter-clockwise: the triangle on the left) */
    int nbe = 0;
    for (int f = 0; f < q->nf; f++)
        for (int k = 0; k < 3; k++)
            if (q->Nb[3 * f + k] < 0) {
                int a = q->F[3 * f + (k + 1) % 3], b = q->F[3 * f + (k + 2) % 3];
                if (next[a] >= 0) { free(next); return cm_seterr("quadrilateral mesh boundary is not one ring"); }
                next[a] = b;
                nbe++;
            }
    int start = -1;
    for (int v = 0; v < nv; v++) if (q->corner[v] == 0) start = v;
    int v = start, e = 0, steps = 0, want = 0;
    do {
        if (v < 0 || steps > nbe) { free(next); return cm_seterr("quadrilateral mesh boundary is not one ring"); }
        if (q->corner[v] >= 0) {
            if (q->corner[v] != want) { free(next); return cm_seterr("quadrilateral mesh boundary misses corner %d", want); }
            e = want++;
        }
        q->ed[v] = e;
        v = next[v];
        steps++;
    } while (v != start);
    free(next);
    if (steps != nbe || want != n) return cm_seterr("quadrilateral mesh boundary is not one ring");
    return 0;
}

/* ---- longest-edge bisection ---- */

static double len2(const struct quad_modulus *q, int a, int b)
{
    double dx = q->V[2 * a] - q->V[2 * b], dy = q->V[2 * a + 1] - q->V[2 * b + 1];
    return dx * dx + dy * dy;
}

/* the longest edge of triangle f (as the corner opposite it): a total
 * order on edges (length, then vertex ids), the same seen from both sides */
static int longest(const struct quad_modulus *q, int f)
{
    int best = 0;
    double bl = -1;
    int ba = 0, bb = 0;
    for (int k = 0; k < 3; k++) {
        int a = q->F[3 * f + (k + 1) % 3], b = q->F[3 * f + (k + 2) % 3];
        if (a > b) { int t = a; a = b; b = t; }
        double l = len2(q, a, b);
        if (l > bl || (l == bl && (a < ba || (a == ba && b < bb)))) { bl = l; best = k; ba = a; bb = b; }
    }
    return best;
}

static void set_tri(struct quad_modulus *q, int f, int v0, int v1, int v2, int n0, int n1, int n2)
{
    int *F = q->F + 3 * f, *N = q->Nb + 3 * f;
    F[0] = v0; F[1] = v1; F[2] = v2;
    N[0] = n0; N[1] = n1; N[2] = n2;
}

static void repoint(struct quad_modulus *q, int f, int from, int to)
{
    if (f < 0) return;
    for (int k = 0; k < 3; k++)
        if (q->Nb[3 * f + k] == from) q->Nb[3 * f + k] = to;
}

/* bisect the edge opposite corner k of f (and of its neighbour) at its midpoint */
static int bisect(struct quad_modulus *q, int f, int k)
{
    int g = q->Nb[3 * f + k];
    if (grow(q, q->nv + 1, q->nf + 2) < 0) return -1;
    int c = q->F[3 * f + k], a = q->F[3 * f + (k + 1) % 3], b = q->F[3 * f + (k + 2) % 3];
    int n_ca = q->Nb[3 * f + (k + 2) % 3], n_bc = q->Nb[3 * f + (k + 1) % 3];
    int m = q->nv++;
    q->V[2 * m] = 0.5 * (q->V[2 * a] + q->V[2 * b]);
    q->V[2 * m + 1] = 0.5 * (q->V[2 * a + 1] + q->V[2 * b + 1]);
    q->corner[m] = -1;
    q->ed[m] = g < 0 ? q->ed[a] : -1;   /* a boundary edge runs a -> b counter-clockwise */
    int f2 = q->nf++;
    int g2 = g < 0 ? -1 : q->nf++;
    set_tri(q, f, c, a, m, g2, f2, n_ca);
    set_tri(q, f2, c, m, b, g, n_bc, f);
    repoint(q, n_bc, f, f2);
    if (g >= 0) {
        int kg = 0;
        while (q->Nb[3 * g + kg] != f) kg++;
        int d = q->F[3 * g + kg];
        int n_db = q->Nb[3 * g + (kg + 2) % 3], n_ad = q->Nb[3 * g + (kg + 1) % 3];
        set_tri(q, g, d, b, m, f2, g2, n_db);
        set_tri(q, g2, d, m, a, f, n_ad, g);
        repoint(q, n_ad, g, g2);
    }
    return 0;
}

/* bisect f by its longest edge, first refining the neighbours whose
 * longest edge is another one (Rivara's longest-edge propagation path),
 * so that the mesh stays conforming */
static int refine_tri(struct quad_modulus *q, int f)
{
    for (;;) {
        int k = longest(q, f), g = q->Nb[3 * f + k];
        if (g < 0) return bisect(q, f, k);
        int kg = 0;
        while (q->Nb[3 * g + kg] != f) kg++;
        if (longest(q, g) == kg) return bisect(q, f, k);
        if (refine_tri(q, g) < 0) return -1;
    }
}

/* ---- finite elements ---- */

/* is boundary vertex w on the closed arc from corner s to corner t (counter-clockwise)? */
static int on_arc(const struct quad_modulus *q, int w, int s, int t)
{
    int n = q->n, span = ((t - s) % n + n) % n;
    if (q->corner[w] >= 0) return ((q->corner[w] - s) % n + n) % n <= span;
    if (q->ed[w] < 0) return 0;
    return ((q->ed[w] - s) % n + n) % n < span;
}

/* gradient of the P1 function x on triangle f; returns twice the area */
static double grad(const struct quad_modulus *q, int f, const double *x, double g[2])
{
    const int *F = q->F + 3 * f;
    const double *p0 = q->V + 2 * F[0], *p1 = q->V + 2 * F[1], *p2 = q->V + 2 * F[2];
    double e1x = p1[0] - p0[0], e1y = p1[1] - p0[1], e2x = p2[0] - p0[0], e2y = p2[1] - p0[1];
    double d1 = x[F[1]] - x[F[0]], d2 = x[F[2]] - x[F[0]];
    double det = e1x * e2y - e1y * e2x;
    g[0] = (d1 * e2y - d2 * e1y) / det;
    g[1] = (e1x * d2 - e2x * d1) / det;
    return det;
}

/* the Dirichlet energy of x (sum of area * |grad|^2 over the triangles) */
static double energy(const struct quad_modulus *q, const double *x)
{
    double E = 0, c = 0;   /* Kahan sum */
    for (int f = 0; f < q->nf; f++) {
        double g[2], det = grad(q, f, x, g);
        double y = 0.5 * det * (g[0] * g[0] + g[1] * g[1]) - c, t = E + y;
        c = (t - E) - y;
        E = t;
    }
    return E;
}

/* minimize the energy with x = 0 on arc s0..s1 and 1 on arc t0..t1 */
static int solve(const struct quad_modulus *q, const cholmod_sparse *K, int s0, int s1, int t0, int t1, double *x)
{
    int nv = q->nv;
    unsigned char *fixed = calloc(nv, 1);
    double *y = calloc(nv, sizeof *y);
    if (!fixed || !y) { free(fixed); free(y); return cm_seterr("out of memory"); }
    for (int w = 0; w < nv; w++) {
        if (on_arc(q, w, s0, s1)) fixed[w] = 1;
        else if (on_arc(q, w, t0, t1)) { fixed[w] = 1; y[w] = 1; }
    }
    struct quad_solver *S = quad_solver_new(K, fixed);
    int rc = S ? quad_solver_solve(S, NULL, y, x, 1) : -1;
    quad_solver_free(S);
    free(fixed);
    free(y);
    return rc;
}

/* stiffness matrix (the negated cot Laplacian) and both solutions */
static int solve_both(struct quad_modulus *q)
{
    struct triplets T;
    triplets_init(&T, q->nv, q->nv);
    for (int f = 0; f < q->nf; f++) {
        const int *F = q->F + 3 * f;
        double det = 0;
        for (int k = 0; k < 3; k++) {
            const double *p = q->V + 2 * F[k], *a = q->V + 2 * F[(k + 1) % 3], *b = q->V + 2 * F[(k + 2) % 3];
            double ux = a[0] - p[0], uy = a[1] - p[1], vx = b[0] - p[0], vy = b[1] - p[1];
            det = ux * vy - uy * vx;
            double w = 0.5 * (ux * vx + uy * vy) / det;   /* cot of the angle at p, halved */
            int i = F[(k + 1) % 3], j = F[(k + 2) % 3];
            triplets_add(&T, i, j, -w);
            triplets_add(&T, j, i, -w);
            triplets_add(&T, i, i, w);
            triplets_add(&T, j, j, w);
        }
        if (!(det > 0)) { triplets_free(&T); return cm_seterr("quadrilateral mesh has a degenerate triangle"); }
    }
    cholmod_sparse *K = triplets_to_sparse(&T, 0);
    triplets_free(&T);
    if (!K) return cm_seterr("out of memory");
    const int *I = q->idx;
    int rc = solve(q, K, I[0], I[1], I[2], I[3], q->u);
    if (rc == 0) rc = solve(q, K, I[1], I[2], I[3], I[0], q->v);
    sparse_free(&K);
    if (rc < 0) return -1;
    q->Eu = energy(q, q->u);
    q->Ev = energy(q, q->v);
    return 0;
}

/* ---- the adaptive loop ---- */

struct mark { double eta; int f; };

static int mark_cmp(const void *x, const void *y)
{
    const struct mark *a = x, *b = y;
    if (a->eta != b->eta) return a->eta > b->eta ? -1 : 1;
    return (a->f > b->f) - (a->f < b->f);
}

/* refine the triangles holding half of the Prager-Synge indicator */
static int refine_step(struct quad_modulus *q)
{
    int nf = q->nf;
    struct mark *Mk = malloc((size_t)nf * sizeof *Mk + 1);
    if (!Mk) return cm_seterr("out of memory");
    /* the sign of J grad v against grad u: their integral is +-1 exactly */
    double cross = 0;
    for (int f = 0; f < nf; f++) {
        double gu[2], gv[2], det = grad(q, f, q->u, gu);
        grad(q, f, q->v, gv);
        cross += 0.5 * det * (-gu[0] * gv[1] + gu[1] * gv[0]);
    }
    double s = (cross < 0 ? -1 : 1) * sqrt(q->Eu / q->Ev), total = 0;
    for (int f = 0; f < nf; f++) {
        double gu[2], gv[2], det = grad(q, f, q->u, gu);
        grad(q, f, q->v, gv);
        double dx = gu[0] + s * gv[1], dy = gu[1] - s * gv[0];
        Mk[f] = (struct mark){0.5 * det * (dx * dx + dy * dy), f};
        total += Mk[f].eta;
    }
    qsort(Mk, nf, sizeof *Mk, mark_cmp);
    double acc = 0;
    int rc = 0;
    for (int i = 0; i < nf && acc < 0.5 * total && rc == 0; i++) {
        acc += Mk[i].eta;
        rc = refine_tri(q, Mk[i].f);
    }
    free(Mk);
    return rc;
}

void quad_modulus_free(struct quad_modulus *q)
{
    if (!q) return;
    free(q->P); free(q->V); free(q->F); free(q->Nb); free(q->ed); free(q->corner); free(q->u); free(q->v);
    free(q);
}

/* idx: 4 distinct corners of an n-gon in counter-clockwise order? */
static int check_corners(int n, const int idx[4])
{
    for (int k = 0; k < 4; k++)
        if (idx[k] < 0 || idx[k] >= n) return cm_seterr("quadrilateral corner %d out of range", idx[k]);
    int span = 0;
    for (int k = 0; k < 4; k++) {
        int d = ((idx[(k + 1) % 4] - idx[k]) % n + n) % n;
        if (d == 0) return cm_seterr("quadrilateral corners repeat");
        span += d;
    }
    if (span != n) return cm_seterr("quadrilateral corners are not in counter-clockwise order");
    return 0;
}

struct quad_modulus *quad_modulus_recorner(const struct quad_modulus *b, const int idx[4])
{
    if (check_corners(b->n, idx) < 0) return NULL;
    struct quad_modulus *q = calloc(1, sizeof *q);
    if (!q || !(q->P = malloc(2 * (size_t)b->n * sizeof *q->P)) || grow(q, b->nv, b->nf) < 0) {
        quad_modulus_free(q);
        cm_seterr("out of memory");
        return NULL;
    }
    q->n = b->n;
    memcpy(q->P, b->P, 2 * (size_t)b->n * sizeof *q->P);
    memcpy(q->idx, idx, sizeof q->idx);
    q->nv = b->nv;
    q->nf = b->nf;
    memcpy(q->V, b->V, 2 * (size_t)b->nv * sizeof *q->V);
    memcpy(q->ed, b->ed, (size_t)b->nv * sizeof *q->ed);
    memcpy(q->corner, b->corner, (size_t)b->nv * sizeof *q->corner);
    memcpy(q->F, b->F, 3 * (size_t)b->nf * sizeof *q->F);
    memcpy(q->Nb, b->Nb, 3 * (size_t)b->nf * sizeof *q->Nb);
    if (solve_both(q) < 0) { quad_modulus_free(q); return NULL; }
    return q;
}

struct quad_modulus *quad_modulus_new(const double *P, int n, const int idx[4])
{
    if (n < 3) { cm_seterr("quadrilateral polygon has %d corners", n); return NULL; }
    double area = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        area += P[2 * i] * P[2 * j + 1] - P[2 * j] * P[2 * i + 1];
    }
    if (!(area > 0)) { cm_seterr("quadrilateral polygon is not counter-clockwise"); return NULL; }
    if (check_corners(n, idx) < 0) return NULL;
    struct quad_modulus *q = calloc(1, sizeof *q);
    if (!q || !(q->P = malloc(2 * (size_t)n * sizeof *q->P))) { free(q); cm_seterr("out of memory"); return NULL; }
    memcpy(q->P, P, 2 * (size_t)n * sizeof *P);
    q->n = n;
    memcpy(q->idx, idx, sizeof q->idx);
    double *V;
    int *F, nv, nf;
    if (cdt2_mesh_polygon(P, n, 0.125, 0, &V, &nv, &F, &nf) < 0) { quad_modulus_free(q); return NULL; }
    int rc = grow(q, nv, nf);
    if (rc == 0) {
        memcpy(q->V, V, 2 * (size_t)nv * sizeof *V);
        memcpy(q->F, F, 3 * (size_t)nf * sizeof *F);
        q->nv = nv;
        q->nf = nf;
    }
    free(V);
    free(F);
    if (rc < 0 || build_adjacency(q) < 0 || label_boundary(q) < 0 || solve_both(q) < 0) {
        quad_modulus_free(q);
        return NULL;
    }
    return q;
}

int quad_modulus_refine(struct quad_modulus *q, double tol, int max_nv)
{
    while (q->Eu * q->Ev > 1 + tol && q->nv < max_nv)
        if (refine_step(q) < 0 || solve_both(q) < 0) return -1;
    return 0;
}

void quad_modulus_bracket(const struct quad_modulus *q, double *lo, double *hi, int *nv)
{
    if (lo) *lo = 1 / q->Ev;
    if (hi) *hi = q->Eu;
    if (nv) *nv = q->nv;
}

int quad_modulus(const double *P, int n, const int idx[4], double tol, int max_nv, double *lo, double *hi)
{
    struct quad_modulus *q = quad_modulus_new(P, n, idx);
    if (!q || quad_modulus_refine(q, tol, max_nv) < 0) { quad_modulus_free(q); return -1; }
    quad_modulus_bracket(q, lo, hi, NULL);
    quad_modulus_free(q);
    return 0;
}
