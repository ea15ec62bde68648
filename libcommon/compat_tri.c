/* compat_tri.c -- see compat_tri.h */
#include "compat_tri.h"
#include "cm_error.h"
#include "rings.h"
#include "topology.h"
#include "predicates2.h"
#include "cdt2.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include "parallel.h"

/* ------------------------------------------------------------------ */
/* storage */

int compat_reserve_vertices(struct compat *c, int nv)
{
    if (nv <= c->cap) return 0;
    int cap = c->cap ? c->cap : 64;
    while (cap < nv) cap *= 2;
    for (int s = 0; s < c->N; s++) {
        double *x = realloc(c->X[s], 2 * (size_t)cap * sizeof *x);
        if (!x) return cm_seterr("out of memory");
        c->X[s] = x;
    }
    c->cap = cap;
    return 0;
}

static int add_face(struct compat *c, int a, int b, int d)
{
    if (c->nf == c->fcap) {
        int cap = c->fcap ? 2 * c->fcap : 256;
        int *F = realloc(c->F, 3 * (size_t)cap * sizeof *F);
        if (!F) return cm_seterr("out of memory");
        c->F = F; c->fcap = cap;
    }
    c->F[3 * c->nf] = a; c->F[3 * c->nf + 1] = b; c->F[3 * c->nf + 2] = d;
    c->nf++;
    return 0;
}

void compat_free(struct compat *c)
{
    for (int s = 0; s < c->N; s++) {
        if (c->X) free(c->X[s]);
        if (c->B) free(c->B[s]);
    }
    free(c->X); free(c->B); free(c->F);
    free(c->ring_start); free(c->ring_parent); free(c->pt_ring);
    free(c->bidx); free(c->bpin);
    memset(c, 0, sizeof *c);
}

static double diag2(const double *P, int n)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < n; i++)
        for (int d = 0; d < 2; d++) {
            lo[d] = fmin(lo[d], P[2 * i + d]);
            hi[d] = fmax(hi[d], P[2 * i + d]);
        }
    double dx = hi[0] - lo[0], dy = hi[1] - lo[1];
    return sqrt(dx * dx + dy * dy);
}

/* ------------------------------------------------------------------ */
/* boundary matching */

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* point at normalized arc length t in [0,1] along the polyline
 * P[i0], P[i0+1], ..., P[i1] (indices mod n) of total length len */
static void polyline_at(const double *P, int n, int i0, int len_pts, const double *cum, double t,
                        double *out)
{
    double L = cum[len_pts - 1] * t;
    int k = 0;
    while (k < len_pts - 2 && cum[k + 1] < L) k++;
    double seg = cum[k + 1] - cum[k];
    double u = seg > 0 ? (L - cum[k]) / seg : 0;
    if (u < 0) u = 0;
    if (u > 1) u = 1;
    const double *a = P + 2 * ((i0 + k) % n), *b = P + 2 * ((i0 + k + 1) % n);
    out[0] = a[0] + u * (b[0] - a[0]);
    out[1] = a[1] + u * (b[1] - a[1]);
}

int compat_match(int N, double *const *P, const int *n, const int *corr, int ncorr,
                 struct compat *c, unsigned char **keep)
{
    memset(c, 0, sizeof *c);
    if (N < 1) return cm_seterr("no shapes");
    if (ncorr < 1) return cm_seterr("no correspondence points");
    /* check cyclic order: after rotating so that row 0 comes first, the
     * indices must increase strictly along every ring */
    for (int s = 0; s < N; s++) {
        int base = corr[s];
        int prev = -1;
        for (int k = 0; k < ncorr; k++) {
            int v = corr[k * N + s];
            if (v < 0 || v >= n[s])
                return cm_seterr("correspondence %d: index %d out of range for shape %d (0..%d)",
                                 k + 1, v, s, n[s] - 1);
            int r = ((v - base) % n[s] + n[s]) % n[s];
            if (k > 0 && r <= prev)
                return cm_seterr("correspondence %d: shape %d: points are not in the same order "
                                 "along every outline (or repeat a vertex)", k + 1, s);
            prev = r;
        }
    }
    c->N = N;
    c->bidx = NULL;
    c->bpin = NULL;
    c->X = calloc(N, sizeof *c->X);
    c->B = calloc(N, sizeof *c->B);
    if (!c->X || !c->B) return cm_seterr("out of memory");
    /* per segment: union of parameter values */
    int maxn = 0, total = 0;
    for (int s = 0; s < N; s++) { if (n[s] > maxn) maxn = n[s]; total += n[s]; }
    double *T = malloc((size_t)(total + 1) * sizeof *T);
    double *cum = malloc((size_t)(maxn + 2) * sizeof *cum);
    unsigned char *kp = NULL;
    int M = 0, kcap = 0;
    if (!T || !cum) { free(T); free(cum); return cm_seterr("out of memory"); }
    for (int pass = 0; pass < 2; pass++) {
        /* pass 0 counts, pass 1 fills */
        M = 0;
        for (int k = 0; k < ncorr; k++) {
            int nt = 0;
            for (int s = 0; s < N; s++) {
                int a = corr[k * N + s], b = corr[((k + 1) % ncorr) * N + s];
                int len = ((b - a) % n[s] + n[s]) % n[s];
                if (len == 0) len = n[s];      /* one correspondence: whole ring */
                cum[0] = 0;
                for (int i = 0; i < len; i++) {
                    const double *p = P[s] + 2 * ((a + i) % n[s]), *q = P[s] + 2 * ((a + i + 1) % n[s]);
                    cum[i + 1] = cum[i] + hypot(q[0] - p[0], q[1] - p[1]);
                }
                for (int i = 0; i < len; i++) T[nt++] = cum[i] / cum[len];
            }
            qsort(T, nt, sizeof *T, cmp_double);
            int u = 0;
            for (int i = 0; i < nt; i++)
                if (u == 0 || T[i] - T[u - 1] > 1e-6) T[u++] = T[i];
            if (pass == 1) {
                for (int s = 0; s < N; s++) {
                    int a = corr[k * N + s], b = corr[((k + 1) % ncorr) * N + s];
                    int len = ((b - a) % n[s] + n[s]) % n[s];
                    if (len == 0) len = n[s];
                    cum[0] = 0;
                    for (int i = 0; i < len; i++) {
                        const double *p = P[s] + 2 * ((a + i) % n[s]), *q = P[s] + 2 * ((a + i + 1) % n[s]);
                        cum[i + 1] = cum[i] + hypot(q[0] - p[0], q[1] - p[1]);
                    }
                    for (int i = 0; i < u; i++)
                        polyline_at(P[s], n[s], a, len + 1, cum, T[i], c->X[s] + 2 * (size_t)(M + i));
                    /* the shape's own vertices exactly (a parameter merged
                     * within 1e-6 with another shape's, or rounded) */
                    for (int i = 0, x = 0; i < len; i++) {
                        double ti = cum[i] / cum[len];
                        while (x + 1 < u && fabs(T[x + 1] - ti) < fabs(T[x] - ti)) x++;
                        if (fabs(T[x] - ti) <= 1e-6) {
                            const double *p = P[s] + 2 * ((a + i) % n[s]);
                            c->X[s][2 * (size_t)(M + x)] = p[0];
                            c->X[s][2 * (size_t)(M + x) + 1] = p[1];
                        }
                    }
                }
                for (int i = 0; i < u; i++) kp[M + i] = i == 0;
            }
            M += u;
        }
        if (pass == 0) {
            kcap = M;
            if (compat_reserve_vertices(c, M) < 0) { free(T); free(cum); return -1; }
            kp = calloc(kcap, 1);
        }
    }
    free(T); free(cum);
    c->nv = c->nb = c->nm = M;
    for (int s = 0; s < N; s++) {
        c->B[s] = malloc(2 * (size_t)M * sizeof *c->B[s]);
        if (!c->B[s]) { free(kp); return cm_seterr("out of memory"); }
        memcpy(c->B[s], c->X[s], 2 * (size_t)M * sizeof *c->B[s]);
    }
    if (keep) *keep = kp; else free(kp);
    return 0;
}

int compat_corr_order(int N, const int *n, int *corr, int ncorr)
{
    /* +1: every shape increasing cyclically, -1: every shape decreasing */
    int dir = 0;
    for (int s = 0; s < N; s++) {
        for (int k = 0; k < ncorr; k++) {
            int v = corr[k * N + s];
            if (v < 0 || v >= n[s])
                return cm_seterr("correspondence %d: index %d out of range for shape %d (0..%d)",
                                 k + 1, v, s, n[s] - 1);
            for (int l = 0; l < k; l++)
                if (corr[l * N + s] == v)
                    return cm_seterr("correspondences %d and %d: shape %d: both are vertex %d", l + 1, k + 1, s, v);
        }
        if (ncorr < 3) continue;
        int d = 0;
        for (int sign = 1; sign >= -1 && !d; sign -= 2) {
            int ok = 1, base = corr[s], prev = 0;
            for (int k = 1; k < ncorr && ok; k++) {
                int r = ((sign * (corr[k * N + s] - base)) % n[s] + n[s]) % n[s];
                if (r <= prev) ok = 0;
                prev = r;
            }
            if (ok) d = sign;
        }
        if (!d)
            return cm_seterr("shape %d: the correspondence points are not in one cyclic order along its "
                             "outline (rows must list them in the same order for every shape)", s);
        if (dir && d != dir)
            return cm_seterr("shape %d: the correspondence points run the other way round its outline "
                             "than in shape 0", s);
        dir = d;
    }
    if (dir >= 0) return 0;
    for (int a = 0, b = ncorr - 1; a < b; a++, b--)
        for (int s = 0; s < N; s++) {
            int t = corr[a * N + s];
            corr[a * N + s] = corr[b * N + s];
            corr[b * N + s] = t;
        }
    return 1;
}


/* distance from p to the closed polyline R (n points), or any value <=
 * floor once one segment is that close (the caller keeps a maximum that is
 * already floor); the scan starts at segment *hint (the closest segment of
 * the caller's previous point, usually close again) and leaves the closest
 * one found there */
static double ring_dist(const double *p, const double *R, int n, double floor, int *hint)
{
    double d = INFINITY;
    int h0 = *hint;
    for (int k = 0; k < n; k++) {
        int i = (h0 + k) % n;
        double x = compat_seg_dist(p, R + 2 * i, R + 2 * ((i + 1) % n));
        if (x < d) { d = x; *hint = i; }
        if (d <= floor) break;
    }
    return d;
}

double compat_outline_error(const struct compat *c, int s, const double *P, int n)
{
    const double *X = c->X[s];
    int nb = c->nb, hint = 0;
    double h = 0;
    for (int i = 0; i < n; i++) h = fmax(h, ring_dist(P + 2 * i, X, nb, h, &hint));
    /* the other direction: 16 points along every simplified edge */
    hint = 0;
    for (int i = 0; i < nb; i++) {
        const double *a = X + 2 * i, *b = X + 2 * ((i + 1) % nb);
        for (int t = 0; t < 16; t++) {
            double u = t / 16.0, q[2] = {a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1])};
            h = fmax(h, ring_dist(q, P, n, h, &hint));
        }
    }
    return h / diag2(P, n);
}

/* ------------------------------------------------------------------ */
/* simplification */

double compat_seg_dist(const double *p, const double *a, const double *b)
{
    double dx = b[0] - a[0], dy = b[1] - a[1], L2 = dx * dx + dy * dy;
    double t = L2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L2 : 0;
    if (t < 0) t = 0;
    if (t > 1) t = 1;
    return hypot(a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
}

int compat_polyline_locate(const double *B, int M, int home, const double *p, double eps, double *t)
{
    for (int d = 0; d <= M / 2; d++)
        for (int sg = 0; sg < (d ? 2 : 1); sg++) {
            int i = ((home + (sg ? -d : d)) % M + M) % M;
            const double *a = B + 2 * i, *b = B + 2 * ((i + 1) % M);
            if (compat_seg_dist(p, a, b) > eps) continue;
            double dx = b[0] - a[0], dy = b[1] - a[1], L2 = dx * dx + dy * dy;
            double u = L2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / L2 : 0;
            *t = fmin(fmax(u, 0), 1);
            return i;
        }
    return -1;
}

int compat_simplify(struct compat *c, double err, const unsigned char *keep)
{
    int M = c->nb, N = c->N;
    if (M <= 3) return M;
    int *prv = malloc(M * sizeof *prv), *nxt = malloc(M * sizeof *nxt);
    double *cost = malloc(M * sizeof *cost), *dg = malloc(N * sizeof *dg);
    unsigned char *alive = malloc(M);
    for (int i = 0; i < M; i++) { prv[i] = (i + M - 1) % M; nxt[i] = (i + 1) % M; alive[i] = 1; }
    double *area = calloc(N, sizeof *area);
    for (int s = 0; s < N; s++) {
        dg[s] = diag2(c->B[s], c->nm);
        for (int i = 0; i < M; i++) {
            int j = (i + 1) % M;
            area[s] += 0.5 * (c->B[s][2 * i] * c->B[s][2 * j + 1] - c->B[s][2 * j] * c->B[s][2 * i + 1]);
        }
    }
    int count = M;
#define COST(i) do { \
        int a_ = prv[i], b_ = nxt[i]; double e_ = 0; \
        if (keep && keep[i]) e_ = INFINITY; \
        else for (int s_ = 0; s_ < N; s_++) { \
            const double *A_ = c->B[s_] + 2 * a_, *B_ = c->B[s_] + 2 * b_; \
            for (int j_ = (a_ + 1) % M; j_ != b_; j_ = (j_ + 1) % M) { \
                double d_ = compat_seg_dist(c->B[s_] + 2 * j_, A_, B_) / dg[s_]; \
                if (d_ > e_) e_ = d_; } } \
        cost[i] = e_; } while (0)
    for (int i = 0; i < M; i++) COST(i);
    for (;;) {
        if (count <= 4) break;
        int best = -1;
        for (int i = 0; i < M; i++)
            if (alive[i] && (best < 0 || cost[i] < cost[best])) best = i;
        if (best < 0 || !(cost[best] <= err)) break;
        /* would the chord prv-nxt cross any other edge in some shape? */
        int a = prv[best], b = nxt[best], bad = 0;
        for (int s = 0; s < N && !bad; s++) {
            const double *A = c->B[s] + 2 * a, *Bp = c->B[s] + 2 * b;
            for (int i = nxt[b]; i != a && !bad; i = nxt[i]) {
                int j = nxt[i];
                if (segments_meet(A, Bp, c->B[s] + 2 * i, c->B[s] + 2 * j)) {
                    /* edges sharing an endpoint with the chord only touch there */
                    if (j == a && orient2_sign(A, Bp, c->B[s] + 2 * i) != 0) continue;
                    bad = 1;
                }
            }
            /* edge b -> nxt[b] shares b: reject a collinear continuation
             * (conservative: it could fold back onto the chord) */
            if (!bad && orient2_sign(A, Bp, c->B[s] + 2 * nxt[b]) == 0) bad = 1;
            /* the polygon must stay counter-clockwise */
            if (!bad && area[s] - 0.5 * orient2(A, c->B[s] + 2 * best, Bp) <= 0) bad = 1;
        }
        if (bad) { cost[best] = INFINITY; continue; }
        alive[best] = 0;
        for (int s = 0; s < N; s++) area[s] -= 0.5 * orient2(c->B[s] + 2 * a, c->B[s] + 2 * best, c->B[s] + 2 * b);
        nxt[a] = b; prv[b] = a;
        count--;
        COST(a);
        COST(b);
    }
#undef COST
    /* compact */
    int *map = malloc(M * sizeof *map), m = 0;
    for (int i = 0; i < M; i++) map[i] = alive[i] ? m++ : -1;
    for (int s = 0; s < N; s++) {
        int k = 0;
        for (int i = 0; i < M; i++)
            if (alive[i]) { c->X[s][2 * k] = c->B[s][2 * i]; c->X[s][2 * k + 1] = c->B[s][2 * i + 1]; k++; }
    }
    c->nv = c->nb = m;
    free(c->bidx);
    c->bidx = malloc((m ? m : 1) * sizeof *c->bidx);
    if (c->bidx)
        for (int i = 0, k = 0; i < M; i++)
            if (alive[i]) c->bidx[k++] = i;
    free(map); free(prv); free(nxt); free(cost); free(dg); free(alive); free(area);
    return m;
}

/* ------------------------------------------------------------------ */
/* visibility inside a sub-polygon */

/* ccw angle from u to v in [0, 2pi) */
static double ccw_angle(double ux, double uy, double vx, double vy)
{
    double a = atan2(ux * vy - uy * vx, ux * vx + uy * vy);
    return a < 0 ? a + 2 * M_PI : a;
}

/* a number in [0, 4) that grows with the ccw angle atan2(y, x) mod 2 pi */
static double ccw_pseudo(double y, double x)
{
    double d = fabs(x) + fabs(y);
    if (!(d > 0)) return 0;
    return y >= 0 ? 1 - x / d : 3 + x / d;
}

struct edge_grid;

struct sub {
    int m;            /* polygon size */
    const int *poly;  /* m vertex ids */
    const double *X;  /* positions of the shape */
    const struct edge_grid *grid;   /* the edges by cell (NULL: small piece, every edge is tested) */
};

static const double *V(const struct sub *p, int i) { return p->X + 2 * p->poly[i]; }

/* The edges of a piece in a uniform grid of about m cells over its
 * bounding box, for seg_inside: a segment is tested against the edges of
 * the cells it passes, not all m.  Cells are closed and the ranges on both
 * sides (an edge's bounding box, a segment's span in a row of cells) are
 * widened by GRID_SLACK cells, so every edge that meets the segment shares
 * a listed cell with it despite rounding: the exact tests then give the
 * same answer as the test of every edge.  An edge in several cells the
 * segment passes is tested once per cell. */
#define GRID_SLACK 1e-4
#define GRID_MIN_CORNERS 40   /* smaller pieces: every edge */

struct edge_grid {
    int gx, gy;       /* cells */
    double lo[2];     /* the box's lower corner */
    double inv[2];    /* cells per unit length */
    int *start;       /* gx * gy + 1: the cell's edges are edge[start[c] .. start[c+1]-1] */
    int *edge;        /* edge e runs from corner e to corner e + 1 */
};

/* cell range [*a, *b] of the interval [x0, x1] on axis d, widened */
static void grid_span(const struct edge_grid *g, int d, double x0, double x1, int *a, int *b)
{
    int n = d ? g->gy : g->gx;
    double u0 = (x0 - g->lo[d]) * g->inv[d] - GRID_SLACK, u1 = (x1 - g->lo[d]) * g->inv[d] + GRID_SLACK;
    *a = u0 <= 0 ? 0 : u0 >= n - 1 ? n - 1 : (int)u0;
    *b = u1 <= 0 ? 0 : u1 >= n - 1 ? n - 1 : (int)u1;
}

static void grid_free(struct edge_grid *g)
{
    free(g->start);
    free(g->edge);
}

/* the grid of piece p (0; -1 out of memory or a box of no area: use no grid) */
static int grid_build(struct edge_grid *g, const struct sub *p)
{
    int m = p->m;
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < m; i++)
        for (int d = 0; d < 2; d++) {
            lo[d] = fmin(lo[d], V(p, i)[d]);
            hi[d] = fmax(hi[d], V(p, i)[d]);
        }
    double w = hi[0] - lo[0], h = hi[1] - lo[1];
    if (!(w > 0 && h > 0)) return -1;
    double cell = sqrt(w * h / m);
    g->gx = (int)fmin(fmax(ceil(w / cell), 1), 4 * sqrt(m));
    g->gy = (int)fmin(fmax(ceil(h / cell), 1), 4 * sqrt(m));
    g->lo[0] = lo[0]; g->lo[1] = lo[1];
    g->inv[0] = g->gx / w; g->inv[1] = g->gy / h;
    size_t nc = (size_t)g->gx * g->gy;
    g->start = calloc(nc + 1, sizeof *g->start);
    g->edge = NULL;
    if (!g->start) return -1;
    for (int pass = 0; pass < 2; pass++) {   /* count, then fill */
        for (int e = 0; e < m; e++) {
            const double *a = V(p, e), *b = V(p, (e + 1) % m);
            int x0, x1, y0, y1;
            grid_span(g, 0, fmin(a[0], b[0]), fmax(a[0], b[0]), &x0, &x1);
            grid_span(g, 1, fmin(a[1], b[1]), fmax(a[1], b[1]), &y0, &y1);
            for (int y = y0; y <= y1; y++)
                for (int x = x0; x <= x1; x++) {
                    size_t c = (size_t)y * g->gx + x;
                    if (pass) g->edge[g->start[c]++] = e;
                    else g->start[c + 1]++;
                }
        }
        if (pass) break;
        for (size_t c = 0; c < nc; c++) g->start[c + 1] += g->start[c];
        if (!(g->edge = malloc(((size_t)g->start[nc] + 1) * sizeof *g->edge))) { free(g->start); return -1; }
    }
    /* the fill advanced each start to the next cell's: shift back */
    memmove(g->start + 1, g->start, nc * sizeof *g->start);
    g->start[0] = 0;
    return 0;
}

/* direction q strictly inside the interior angle at polygon corner i
 * (exact predicates: a corner whose neighbours are collinear with it to
 * the last bit is still a corner, and q on one of its edges is outside) */
static int incone(const struct sub *p, int i, const double *q)
{
    const double *a = V(p, i), *pr = V(p, (i + p->m - 1) % p->m), *nx = V(p, (i + 1) % p->m);
    int o1 = orient2_sign(a, nx, q), o2 = orient2_sign(pr, a, q);
    if (orient2_sign(pr, a, nx) > 0) return o1 > 0 && o2 > 0;
    return o1 > 0 || o2 > 0;
}

/* smallest of the two angles the direction q makes at corner i; an angle
 * clearly at most cut (by pseudo-angles, with a margin for rounding) is
 * returned as 0 without its atan2 (cut <= 0: always the angle) */
/* the pseudo-angle below which cone_quality_cut calls an angle clearly at
 * most cut (-1: no cut) */
static double cone_cut_pseudo(double cut)
{
    return cut > 0 && cut < M_PI ? ccw_pseudo(sin(cut), cos(cut)) * (1 - 1e-9) : -1;
}

/* the parts of cone_quality_cut at corner i for direction q: *pm the
 * smaller pseudo-angle, and the angle itself (0: q within rounding of an
 * edge; with angle = 0, *pm is not set) */
static double cone_parts(const struct sub *p, int i, const double *q, double *pm, int with_angle)
{
    const double *a = V(p, i), *pr = V(p, (i + p->m - 1) % p->m), *nx = V(p, (i + 1) % p->m);
    /* the smaller by pseudo-angles (monotone in the ccw angle), then one atan2 */
    double ux = nx[0] - a[0], uy = nx[1] - a[1], qx = q[0] - a[0], qy = q[1] - a[1];
    double vx = pr[0] - a[0], vy = pr[1] - a[1];
    double p1 = ccw_pseudo(ux * qy - uy * qx, ux * qx + uy * qy);
    double p2 = ccw_pseudo(qx * vy - qy * vx, qx * vx + qy * vy);
    /* q within rounding of an edge: the rounded cross product can put it
     * on the far side, a full turn (pseudo-angle near 4) instead of a
     * sliver; either angle wider than the corner is that case */
    double pa = ccw_pseudo(ux * vy - uy * vx, ux * vx + uy * vy);
    if (p1 > pa || p2 > pa) return 0;
    *pm = fmin(p1, p2);
    if (!with_angle) return 1;
    return p1 <= p2 ? ccw_angle(ux, uy, qx, qy) : ccw_angle(qx, qy, vx, vy);
}

static double cone_quality_cut(const struct sub *p, int i, const double *q, double cut)
{
    double pm, pc = cone_cut_pseudo(cut);
    if (cone_parts(p, i, q, &pm, 0) == 0) return 0;
    if (pm < pc) return 0;
    return cone_parts(p, i, q, &pm, 1);
}



/* edge e (corner e to corner e + 1) of the polygon meets the segment P-Q
 * (corners i, j, or free if < 0; bounding box lo0..hi0 by lo1..hi1): the
 * edges at i or j are the cone tests' business, and an edge whose bounding
 * box misses the segment's cannot meet it */
static inline int edge_meets(const struct sub *p, int e, int i, int j, const double *P, const double *Q,
                             double lo0, double hi0, double lo1, double hi1)
{
    int f = e + 1 == p->m ? 0 : e + 1;
    if (e == i || f == i || e == j || f == j) return 0;
    const double *a = V(p, e), *b = V(p, f);
    if ((a[0] < lo0 && b[0] < lo0) || (a[0] > hi0 && b[0] > hi0) || (a[1] < lo1 && b[1] < lo1) ||
        (a[1] > hi1 && b[1] > hi1)) return 0;
    return segments_meet(P, Q, a, b);
}

/* segment from P (corner i, or a free interior point if i < 0) to Q (corner
 * j or free) lies in the open interior of the polygon */
static int seg_inside(const struct sub *p, int i, const double *P, int j, const double *Q)
{
    if (i >= 0 && !incone(p, i, Q)) return 0;
    if (j >= 0 && !incone(p, j, P)) return 0;
    int m = p->m;
    /* edges whose bounding box misses the segment's cannot meet it */
    double lo0 = fmin(P[0], Q[0]), hi0 = fmax(P[0], Q[0]), lo1 = fmin(P[1], Q[1]), hi1 = fmax(P[1], Q[1]);
    const struct edge_grid *g = p->grid;
    if (g) {   /* the cells the segment passes, row by row */
        int y0, y1;
        grid_span(g, 1, lo1, hi1, &y0, &y1);
        double dy = Q[1] - P[1];
        for (int y = y0; y <= y1; y++) {
            /* the segment's x range within the row's band of y (widened) */
            double b0 = g->lo[1] + (y - GRID_SLACK) / g->inv[1], b1 = g->lo[1] + (y + 1 + GRID_SLACK) / g->inv[1];
            double xa = lo0, xb = hi0;
            if (dy != 0) {
                double t0 = (fmax(b0, lo1) - P[1]) / dy, t1 = (fmin(b1, hi1) - P[1]) / dy;
                double u0 = P[0] + t0 * (Q[0] - P[0]), u1 = P[0] + t1 * (Q[0] - P[0]);
                xa = fmax(lo0, fmin(u0, u1));
                xb = fmin(hi0, fmax(u0, u1));
            }
            int x0, x1;
            grid_span(g, 0, xa, xb, &x0, &x1);
            for (int x = x0; x <= x1; x++) {
                size_t c = (size_t)y * g->gx + x;
                for (int k = g->start[c]; k < g->start[c + 1]; k++)
                    if (edge_meets(p, g->edge[k], i, j, P, Q, lo0, hi0, lo1, hi1)) return 0;
            }
        }
        return 1;
    }
    for (int e = 0; e < m; e++)
        if (edge_meets(p, e, i, j, P, Q, lo0, hi0, lo1, hi1)) return 0;
    /* corners i adjacent to edges we skipped: a corner other than i, j lying
     * on PQ was caught by the edges around it unless both its edges were
     * skipped, i.e. it sits between i and j: ruled out by the cone tests */
    return 1;
}

#define STAGE2_MIN (2 * M_PI / 180)
#define CLEARANCE_MIN (0.5 * M_PI / 180)
#define STAGE1_MIN 1e-6

/* the pseudo-angle 1 - x / d (d = |x| + |y|) is surely above the smallest
 * so far, pmin, given t = 1 - pmin (-INFINITY: none yet): x <= (t - 1e-9)
 * d puts x / d at least 1e-9 below t, far beyond the roundings of the
 * division, the subtractions and the product (d normal: no underflow), so
 * 1 - x / d > pmin in floating point too.  The clearance loops then skip
 * the corner's divisions: they would change nothing. */
static inline int pseudo_above(double x, double d, double t)
{
    return d > 1e-280 && d < 1e280 && x <= (t - 1e-9) * d;
}

/* how far the segment P-Q (corners i, j, or free if < 0) keeps from the
 * other corners, as an angle: the smallest over corners v of the smaller
 * of the angles v-P-Q and v-Q-P (a corner close to the segment makes a
 * sliver in one of the pieces) */
static double clearance_cut(const struct sub *p, int i, const double *P, int j, const double *Q, double cut)
{
    /* below the pseudo-angle of cut (with a margin for rounding): a value
     * below cut is all the caller needs */
    double pcut = -1;
    if (cut > 0 && cut < M_PI) pcut = (1 - cos(cut) / (fabs(cos(cut)) + sin(cut))) * (1 - 1e-9);
    double ux = Q[0] - P[0], uy = Q[1] - P[1];
    /* the smallest angle by a pseudo-angle 1 - x / (|x| + y) (monotone in
     * atan2(y, x) for y >= 0): one atan2 per call instead of two per corner */
    double pmin = INFINITY, my = 0, mx = -1, t = -INFINITY;
    int m = p->m;
    for (int v = 0; v < m; v++) {
        if (v == i || v == j) continue;
        /* the neighbours of corners are the cone angles' business */
        if (i >= 0 && (v == (i + 1) % m || v == (i + m - 1) % m)) continue;
        if (j >= 0 && (v == (j + 1) % m || v == (j + m - 1) % m)) continue;
        const double *x = V(p, v);
        double ax = x[0] - P[0], ay = x[1] - P[1], bx = x[0] - Q[0], by = x[1] - Q[1];
        double y1 = fabs(ux * ay - uy * ax), x1 = ux * ax + uy * ay;
        double y2 = fabs(ux * by - uy * bx), x2 = -(ux * bx + uy * by);
        double d1 = fabs(x1) + y1, d2 = fabs(x2) + y2;
        if (pseudo_above(x1, d1, t) && pseudo_above(x2, d2, t)) continue;
        double p1 = d1 > 0 ? 1 - x1 / d1 : 0, p2 = d2 > 0 ? 1 - x2 / d2 : 0;
        if (p1 < pmin) { pmin = p1; my = y1; mx = x1; }
        if (p2 < pmin) { pmin = p2; my = y2; mx = x2; }
        t = 1 - pmin;
        if (pmin < pcut) break;
    }
    return pmin == INFINITY ? M_PI : atan2(my, mx);
}

/* clearance_cut(p, i, V(p, i), -1, q, 0) in *from and clearance_cut(p,
 * -1, q, i, V(p, i), 0) in *to, in one pass: the two see the same corners
 * and the same two angles at each (the second's terms are the first's
 * swapped, bit for bit: negation is exact), so the smallest is the same;
 * each keeps the first smallest term in its own order for the atan2. */
static void clearance_pair(const struct sub *p, int i, const double *q, double *from, double *to)
{
    const double *P = V(p, i);
    double ux = q[0] - P[0], uy = q[1] - P[1];
    double pf = INFINITY, fy = 0, fx = -1, pt = INFINITY, ty = 0, tx = -1, t = -INFINITY;
    int m = p->m;
    for (int v = 0; v < m; v++) {
        if (v == i || v == (i + 1) % m || v == (i + m - 1) % m) continue;
        const double *x = V(p, v);
        double ax = x[0] - P[0], ay = x[1] - P[1], bx = x[0] - q[0], by = x[1] - q[1];
        double y1 = fabs(ux * ay - uy * ax), x1 = ux * ax + uy * ay;
        double y2 = fabs(ux * by - uy * bx), x2 = -(ux * bx + uy * by);
        double d1 = fabs(x1) + y1, d2 = fabs(x2) + y2;
        /* (pf and pt are the same value: the smallest of the same terms) */
        if (pseudo_above(x1, d1, t) && pseudo_above(x2, d2, t)) continue;
        double p1 = d1 > 0 ? 1 - x1 / d1 : 0, p2 = d2 > 0 ? 1 - x2 / d2 : 0;
        if (p1 < pf) { pf = p1; fy = y1; fx = x1; }
        if (p2 < pf) { pf = p2; fy = y2; fx = x2; }
        if (p2 < pt) { pt = p2; ty = y2; tx = x2; }
        if (p1 < pt) { pt = p1; ty = y1; tx = x1; }
        t = 1 - pf;
    }
    *from = pf == INFINITY ? M_PI : atan2(fy, fx);
    *to = pt == INFINITY ? M_PI : (pt == pf && ty == fy && tx == fx) ? *from : atan2(ty, tx);
}

/* Does the free point x lie within STAGE1_MIN of an edge, as an angle:
 * atan(d / (L / 2)) < STAGE1_MIN for some edge of length L at distance d
 * (the smallest angle of the triangle edge-x when x is above the middle)?
 * Such a Steiner point passes the exact inside tests but lies within
 * rounding of the outline; its pieces have slivers that no double can
 * triangulate (the overlay's images of its crossings flip), as stage I
 * leaves a diagonal along a run of collinear corners to the overlay. */
static int hugs_edge(const struct sub *p, const double *x)
{
    const double t = tan(STAGE1_MIN) * tan(STAGE1_MIN) / 4;
    for (int e = 0; e < p->m; e++) {
        const double *a = V(p, e), *b = V(p, (e + 1) % p->m);
        double dx = b[0] - a[0], dy = b[1] - a[1], L2 = dx * dx + dy * dy;
        double u = L2 > 0 ? ((x[0] - a[0]) * dx + (x[1] - a[1]) * dy) / L2 : 0;
        u = u < 0 ? 0 : u > 1 ? 1 : u;
        double ex = a[0] + u * dx - x[0], ey = a[1] + u * dy - x[1];
        if (ex * ex + ey * ey < t * L2) return 1;
    }
    return 0;
}

/* a Steiner point near the middle of the inside segment a-b (a is corner
 * ia or free if ia < 0, likewise b), pushed off the segment so that the
 * pieces on both sides get a real corner there instead of a flat one:
 * offsets of 0.15, 0.075, ... times |ab| to either side, then the plain
 * midpoint; the first whose two links are inside the polygon (exact
 * tests: a rounded midpoint can fall outside a thin piece).  Returns -1 if
 * none is. */
static int bent_point(const struct sub *p, int ia, const double *a, int ib, const double *b, double *q)
{
    double mx = 0.5 * (a[0] + b[0]), my = 0.5 * (a[1] + b[1]);
    double nx = -(b[1] - a[1]), ny = b[0] - a[0];
    for (double h = 0.15; h > 1e-3; h *= 0.5)
        for (int side = 1; side >= -1; side -= 2) {
            q[0] = mx + side * h * nx; q[1] = my + side * h * ny;
            if (seg_inside(p, ia, a, -1, q) && seg_inside(p, -1, q, ib, b)) return 0;
        }
    q[0] = mx; q[1] = my;
    if (seg_inside(p, ia, a, -1, q) && seg_inside(p, -1, q, ib, b)) return 0;
    return -1;
}

/* ear-clipping triangulation of the sub-polygon: candidate interior
 * points (triangle centroids, and 1/4, 1/2, 3/4 points of diagonals) */
static int candidates(const struct sub *p, double **out)
{
    int m = p->m;
    int *idx = malloc(m * sizeof *idx), n = m;
    for (int i = 0; i < m; i++) idx[i] = i;
    double *C = malloc(sizeof *C * 2 * (size_t)(5 * m + 4));
    int nc = 0, guard = 0;
    while (n > 3 && guard < 4 * m * m) {
        int found = 0;
        for (int k = 0; k < n && !found; k++) {
            int a = idx[(k + n - 1) % n], b = idx[k], d = idx[(k + 1) % n];
            if (orient2_sign(V(p, a), V(p, b), V(p, d)) <= 0) continue;
            int inside = 0;
            for (int t = 0; t < n && !inside; t++) {
                int w = idx[t];
                if (w == a || w == b || w == d) continue;
                const double *q = V(p, w);
                if (orient2_sign(V(p, a), V(p, b), q) >= 0 && orient2_sign(V(p, b), V(p, d), q) >= 0 &&
                    orient2_sign(V(p, d), V(p, a), q) >= 0) inside = 1;
            }
            if (inside) continue;
            const double *A = V(p, a), *B = V(p, b), *D = V(p, d);
            C[2 * nc] = (A[0] + B[0] + D[0]) / 3; C[2 * nc + 1] = (A[1] + B[1] + D[1]) / 3; nc++;
            for (int q = 1; q <= 3; q++) {
                C[2 * nc] = A[0] + 0.25 * q * (D[0] - A[0]);
                C[2 * nc + 1] = A[1] + 0.25 * q * (D[1] - A[1]);
                nc++;
            }
            memmove(idx + k, idx + k + 1, (n - k - 1) * sizeof *idx);
            n--;
            found = 1;
        }
        guard++;
        if (!found) break;
    }
    if (n == 3) {
        const double *A = V(p, idx[0]), *B = V(p, idx[1]), *D = V(p, idx[2]);
        C[2 * nc] = (A[0] + B[0] + D[0]) / 3; C[2 * nc + 1] = (A[1] + B[1] + D[1]) / 3; nc++;
    }
    free(idx);
    *out = C;
    return nc;
}

/* ------------------------------------------------------------------ */
/* divide and conquer */

struct split {
    int i, j;         /* corners (indices into poly) */
    int k;            /* Steiner points on the path */
    double *path;     /* N by k by 2 positions */
    int stage;
};

static double balance(int i, int j, int m)
{
    int a = (j - i + m) % m, b = m - a;
    return (double)(a < b ? a : b) / m;
}

static double pair_score(double q, int i, int j, int m)
{
    if (q > M_PI / 3) q = M_PI / 3;
    return q * (1 + 0.25 * balance(i, j, m));
}

/* does the path corner i -> pts (k points) -> corner j cross itself? */
static int path_crosses(const struct sub *p, int i, int j, const double *pts, int k)
{
    for (int t = 0; t <= k; t++)
        for (int u = t + 2; u <= k; u++) {
            const double *a = t ? pts + 2 * (t - 1) : V(p, i), *b = t < k ? pts + 2 * t : V(p, j);
            const double *e = pts + 2 * (u - 1), *f = u < k ? pts + 2 * u : V(p, j);
            if (segments_meet(a, b, e, f)) return 1;
        }
    return 0;
}



/* quality of path corner i -> points -> corner j in one shape: min angle
 * (0 if an end angle is clearly below cut > 0: the callers drop such paths) */
static double path_quality(const struct sub *p, int i, int j, const double *pts, int k, double cut)
{
    /* the end angles first: one clearly at most cut (0 from
     * cone_quality_cut) decides without the rest */
    double q = cone_quality_cut(p, i, k ? pts : V(p, j), cut);
    if (q > 0) q = fmin(q, cone_quality_cut(p, j, k ? pts + 2 * (k - 1) : V(p, i), cut));
    if (q == 0) return 0;
    for (int t = 0; t < k; t++) {
        const double *a = t ? pts + 2 * (t - 1) : V(p, i), *b = t + 1 < k ? pts + 2 * (t + 1) : V(p, j);
        const double *x = pts + 2 * t;
        double an = ccw_angle(a[0] - x[0], a[1] - x[1], b[0] - x[0], b[1] - x[1]);
        q = fmin(q, fmin(an, 2 * M_PI - an));
    }
    return q;
}

#define PAIR_SEARCH_PARALLEL 32   /* pieces of fewer corners: one thread */

/* cone_quality_cut of the candidate points of stage II, worked out once per
 * candidate and corner (the pair search asks each many times).  The caches
 * of stage II are shared by the threads of the pair search: an entry is
 * worked out by whichever thread first needs it (two may both do it: the
 * same value), so they are atomics, written and read without ordering
 * except the angle, which publishes its pseudo-angle. */
struct cone_cache {
    const struct sub *sp;
    double *const *C;     /* N: candidate points of each shape */
    int m;
    const int *nc;        /* N: candidates of each shape */
    struct cone_val { _Atomic double an, pm; } **v;
                          /* N: m by nc[s] (corner-major: the pair search runs
                           * over the candidates), the angle (cache_unset: not yet) and
                           * the smaller pseudo-angle side by side, one stream */
    _Atomic double **from, **to;
                          /* N: m by nc[s], clearance_cut of corner i -> a and of
                           * a -> corner i, in full (cache_unset: not yet) */
};

/* The caches start as zero bytes (calloc: the pages a search never
 * touches are never written; a piece of 300 corners has some 3000
 * candidates, 14 MB of entries a shape, and a large piece is cut many
 * times), so an entry of all zero bits is "not yet": a value worked out
 * as +0 is kept as -0, which compares and computes as +0 does. */
static inline int cache_unset(double v)
{
    uint64_t b;
    memcpy(&b, &v, sizeof b);
    return b == 0;
}

static inline double cache_value(double v)
{
    return v == 0 ? -0.0 : v;
}

/* cone_quality_cut(corner i, candidate a of shape s, cut), pc =
 * cone_cut_pseudo(cut) */
static inline double cone_cached(struct cone_cache *cc, int s, int a, int i, double pc)
{
    size_t k = (size_t)i * cc->nc[s] + a;
    struct cone_val *x = cc->v[s] + k;
    double e = atomic_load_explicit(&x->an, memory_order_acquire), pm;
    if (cache_unset(e)) {
        pm = 0;
        e = cache_value(cone_parts(&cc->sp[s], i, cc->C[s] + 2 * a, &pm, 1));
        atomic_store_explicit(&x->pm, pm, memory_order_relaxed);
        atomic_store_explicit(&x->an, e, memory_order_release);
    } else pm = atomic_load_explicit(&x->pm, memory_order_relaxed);
    return e == 0 || pm < pc ? 0 : e;
}

/* clearance_cut of the segment corner i -> candidate a (to = 0) or
 * candidate a -> corner i (to = 1) of shape s, in full: where the pair
 * search cuts it short, the value only rules the pair out, which the full
 * value does as well */
static double clearance_cached(struct cone_cache *cc, int s, int a, int i, int to)
{
    size_t k = (size_t)i * cc->nc[s] + a;
    _Atomic double *x = (to ? cc->to : cc->from)[s] + k;
    double v = atomic_load_explicit(x, memory_order_relaxed);
    if (cache_unset(v)) {   /* both ways at once (clearance_pair) */
        double f, t;
        clearance_pair(&cc->sp[s], i, cc->C[s] + 2 * a, &f, &t);
        f = cache_value(f);
        t = cache_value(t);
        atomic_store_explicit(cc->from[s] + k, f, memory_order_relaxed);
        atomic_store_explicit(cc->to[s] + k, t, memory_order_relaxed);
        v = to ? t : f;
    }
    return v;
}

/* Visibility of stage II and III.  Between corners: tested when first
 * asked and kept (0: not asked yet, 1: no, 2: yes; shared by the threads
 * of the pair search, as the cone cache).  From candidates to corners:
 * every candidate against every corner, up front (vis_bits_build), a bit
 * set per corner, so that the pair search runs over the candidates both
 * corners see (an AND of two rows) instead of testing each. */
struct vis_cache {
    const struct sub *sp; /* N shapes of the piece */
    int m;
    atomic_uchar *cc;     /* N by m by m: corner i sees corner j */
    double *const *C;     /* N: candidate points of each shape */
    const int *nc;        /* N: candidates of each shape */
    int *words;           /* N: 64-bit words per row, (nc[s] + 63) / 64 */
    uint64_t **bits;      /* N: m by words[s]: bit a of row i, candidate a sees corner i */
};

/* corners i and j of shape s see each other through the piece's interior */
static int vis_corners(struct vis_cache *vc, int s, int i, int j)
{
    int m = vc->m;
    if (i > j) { int t = i; i = j; j = t; }
    atomic_uchar *x = vc->cc + ((size_t)s * m + i) * m + j;
    unsigned char v = atomic_load_explicit(x, memory_order_relaxed);
    if (!v) {
        const struct sub *p = &vc->sp[s];
        v = (i == 0 && j == m - 1) || j < i + 2 ? 1 : 1 + seg_inside(p, i, V(p, i), j, V(p, j));
        atomic_store_explicit(x, v, memory_order_relaxed);
    }
    return v == 2;
}

/* the candidates of shape s that see corner i, a bit each */
static const uint64_t *vis_row(const struct vis_cache *vc, int s, int i)
{
    return vc->bits[s] + (size_t)i * vc->words[s];
}

/* candidate point a of shape s sees corner i */
static int vis_cand(const struct vis_cache *vc, int s, int a, int i)
{
    return vis_row(vc, s, i)[a >> 6] >> (a & 63) & 1;
}

/* job (shape, corner) of the bit sets: k = s * m + i */
static void vis_bits_job(void *ctx, int k)
{
    struct vis_cache *vc = ctx;
    int s = k / vc->m, i = k % vc->m;
    const struct sub *p = &vc->sp[s];
    uint64_t *row = vc->bits[s] + (size_t)i * vc->words[s];
    for (int a = 0; a < vc->nc[s]; a++)
        if (seg_inside(p, i, V(p, i), -1, vc->C[s] + 2 * a)) row[a >> 6] |= (uint64_t)1 << (a & 63);
}

/* fills vc->words and vc->bits (zeroed, N by m by words) on threads */
static int vis_bits_build(struct vis_cache *vc, int N, int threads)
{
    for (int s = 0; s < N; s++) {
        vc->words[s] = (vc->nc[s] + 63) / 64;
        if (!(vc->bits[s] = calloc((size_t)vc->m * vc->words[s] + 1, sizeof **vc->bits))) return -1;
    }
    parallel_run(N * vc->m, vc->m >= PAIR_SEARCH_PARALLEL ? threads : 1, vis_bits_job, vc);
    return 0;
}

/* The pair search of stages I and II, one row (corner i, every j > i) per
 * job on c->threads threads.  The split is the pair of the highest score,
 * the first in (i, j) order among equal ones, as a search of the rows in
 * order gives it.  Each row keeps its first best pair; pruning uses the
 * row's best and the best score any row has found so far, lowered by a
 * relative 1e-9 so that a pair equal to it is still worked out in full:
 * the pair chosen, its score and its path do not depend on the threads or
 * on which row finished first (a pair is only pruned if its score is at
 * most a score some pair has, and the winner's is worked out exactly). */
struct pair_search {
    const struct compat *c;
    const struct sub *sp;   /* N shapes of the piece */
    int N, m;
    _Atomic double bound;   /* the best score found so far by any row */
    double *row_score;      /* m: the row's best score (-1: none) */
    int *row_j;             /* m: its pair */
    /* stage II */
    struct vis_cache *vc;
    struct cone_cache *cones;
    double *const *C;       /* N: candidate points of each shape */
    const int *nc;
    uint64_t *const *nohug;  /* N: a bit per candidate, set if it does not hug an edge (hugs_edge) */
    double *row_path;       /* m by N by 2: the Steiner point of the row's best pair */
    double *row_tmp;        /* m by N by 2: the row's scratch for its current pair */
    int *row_ord;           /* m by N: the row's order of the shapes */
};

/* the score a pair must beat: the row's best, or just under the best of
 * any row */
static double search_bound(struct pair_search *ps, double rowbest)
{
    double b = atomic_load_explicit(&ps->bound, memory_order_relaxed);
    b = b > 0 ? b * (1 - 1e-9) : -1;
    return rowbest > b ? rowbest : b;
}

static void search_publish(struct pair_search *ps, double sc)
{
    double b = atomic_load_explicit(&ps->bound, memory_order_relaxed);
    while (sc > b && !atomic_compare_exchange_weak_explicit(&ps->bound, &b, sc, memory_order_relaxed,
                                                            memory_order_relaxed)) {}
}

/* stage I, row i: a diagonal i-j inside every shape */
static void stage1_row(void *ctx, int i)
{
    struct pair_search *ps = ctx;
    const struct sub *sp = ps->sp;
    int N = ps->N, m = ps->m, mode = ps->c->split_mode, rj = -1;
    double rowbest = -1;
    int *ord = ps->row_ord + (size_t)N * i;
    for (int s = 0; s < N; s++) ord[s] = s;
    for (int j = i + 2; j < m; j++) {
        if (i == 0 && j == m - 1) continue;
        double best = search_bound(ps, rowbest);
        double q = INFINITY;
        int all = 1, o;
        /* cheapest test first: the cone angles at both ends; stop at
         * the first shape where the pair does not see itself */
        for (o = 0; o < N; o++) {
            int s = ord[o];
            if (!incone(&sp[s], i, V(&sp[s], j)) || !incone(&sp[s], j, V(&sp[s], i))) { all = 0; break; }
            /* a cone angle that cannot beat the best score needs no
             * atan2 (cone_quality_cut gives 0: rejected below) */
            double cq = best > 0 ? best / (1 + 0.25 * balance(i, j, m)) : 0;
            double qq = cone_quality_cut(&sp[s], i, V(&sp[s], j), cq);
            if (qq > 0) qq = fmin(qq, cone_quality_cut(&sp[s], j, V(&sp[s], i), cq));
            /* a diagonal along a run of (nearly) collinear corners cuts off
             * a zero-width sliver: leave such pieces to the overlay */
            if (qq < STAGE1_MIN && mode != COMPAT_LINKPATH) { all = 0; break; }
            /* a pair that cannot beat the best score needs no edge tests */
            if (pair_score(fmin(q, qq), i, j, m) <= best) { all = 0; break; }
            /* the clearance first, cut short where the pair cannot win
             * (score <= best), then the edge tests */
            double cut = best > 0 ? best / (1 + 0.25 * balance(i, j, m)) : 0;
            if (cut >= M_PI / 3) cut = 0;
            /* below CLEARANCE_MIN the pair is out too: the loop over the
             * corners may stop there (a value it returns early is below
             * the cut it was given, the full value is too) */
            double ccut = mode != COMPAT_LINKPATH && cut < CLEARANCE_MIN ? CLEARANCE_MIN : cut;
            double cl = clearance_cut(&sp[s], i, V(&sp[s], i), j, V(&sp[s], j), ccut);
            if (cut > 0 && cl <= cut) { all = 0; break; }
            /* a diagonal grazing another corner makes a sliver piece */
            if (cl < CLEARANCE_MIN && mode != COMPAT_LINKPATH) { all = 0; break; }
            if (seg_inside(&sp[s], i, V(&sp[s], i), j, V(&sp[s], j))) q = fmin(q, fmin(qq, cl));
            else { all = 0; break; }
        }
        /* the shape that ruled the pair out is tried first next time, as
         * in stage II (the order changes the work, not the result: a pair
         * is kept only if every shape passes, its score is the smallest
         * over all of them, and the cut-offs depend on best alone) */
        if (!all && o > 0) { int s = ord[o]; memmove(ord + 1, ord, o * sizeof *ord); ord[0] = s; }
        if (all) {
            double sc = pair_score(q, i, j, m);
            if (sc > best) { rowbest = sc; rj = j; search_publish(ps, sc); }
        }
    }
    ps->row_score[i] = rowbest;
    ps->row_j[i] = rj;
}

/* stage II, row i: a path i -> one Steiner point -> j in every shape, the
 * point the best of the candidates (or a point off the middle of i-j) */
static void stage2_row(void *ctx, int i)
{
    struct pair_search *ps = ctx;
    const struct sub *sp = ps->sp;
    int N = ps->N, m = ps->m, rj = -1;
    double *const *C = ps->C;
    double rowbest = -1;
    double *tmp = ps->row_tmp + 2 * (size_t)N * i;
    int *ord = ps->row_ord + (size_t)N * i;
    for (int s = 0; s < N; s++) ord[s] = s;
    for (int j = i + 2; j < m; j++) {
        if (i == 0 && j == m - 1) continue;
        double best = search_bound(ps, rowbest);
        double q = INFINITY;
        int all = 1;
        /* a pair whose quality is at most qcut cannot beat the best:
         * clearances are cut short there (same choice, less work) */
        double qcut = best > 0 ? best / (1 + 0.25 * balance(i, j, m)) : 0;
        if (qcut >= M_PI / 3) qcut = 0;
        for (int o = 0; o < N && all; o++) {
            int s = ord[o];
            double bq = -1;
            if (vis_corners(ps->vc, s, i, j)) {
                const double *A = V(&sp[s], i), *B = V(&sp[s], j);
                double mid[2];
                if (bent_point(&sp[s], i, A, j, B, mid) == 0) {
                    bq = hugs_edge(&sp[s], mid) ? -1 : path_quality(&sp[s], i, j, mid, 1, qcut);
                    if (bq > qcut) bq = fmin(bq, clearance_cut(&sp[s], i, A, -1, mid, qcut));
                    if (bq > qcut) bq = fmin(bq, clearance_cut(&sp[s], -1, mid, j, B, qcut));
                    tmp[2 * s] = mid[0]; tmp[2 * s + 1] = mid[1];
                }
            }
            double lastcut = NAN, pc = -1;
            /* the candidates both corners see, in order, except those
             * that hug an edge */
            const uint64_t *vi = vis_row(ps->vc, s, i), *vj = vis_row(ps->vc, s, j), *nh = ps->nohug[s];
            for (int w = 0; w < ps->vc->words[s]; w++)
            for (uint64_t bits = vi[w] & vj[w] & nh[w]; bits; bits &= bits - 1) {
                int a = 64 * w + __builtin_ctzll(bits);
                const double *x = C[s] + 2 * a;
                double cut = fmax(bq, qcut);
                if (cut != lastcut) { pc = cone_cut_pseudo(cut); lastcut = cut; }
                double ci = cone_cached(ps->cones, s, a, i, pc), cj = ci > 0 ? cone_cached(ps->cones, s, a, j, pc) : 0;
                /* an end angle at most cut > 0 leaves the pair below
                 * the best either way: no visibility test needed */
                if (cut > 0 && cj == 0) continue;
                /* nor one whose end angles cannot beat this shape's
                 * best path (its quality is at most them) */
                if (cj > 0 && fmin(ci, cj) <= bq) continue;
                /* path_quality of corner i -> x -> corner j */
                double pq = 0;
                if (cj > 0) {
                    const double *A = V(&sp[s], i), *B = V(&sp[s], j);
                    double an = ccw_angle(A[0] - x[0], A[1] - x[1], B[0] - x[0], B[1] - x[1]);
                    pq = fmin(fmin(ci, cj), fmin(an, 2 * M_PI - an));
                }
                if (pq > cut) pq = fmin(pq, clearance_cached(ps->cones, s, a, i, 0));
                if (pq > cut) pq = fmin(pq, clearance_cached(ps->cones, s, a, j, 1));
                if (pq > bq) { bq = pq; tmp[2 * s] = C[s][2 * a]; tmp[2 * s + 1] = C[s][2 * a + 1]; }
            }
            if (bq < 0) all = 0;
            q = fmin(q, bq);
            /* the other shapes can only lower q: a pair already at
             * or below the best is out */
            if (best >= 0 && pair_score(q, i, j, m) <= best) all = 0;
            /* the shape that ruled the pair out is tried first next
             * time (the order changes the work, not the result: a pair
             * that wins has every shape's best path) */
            if (!all && o > 0) { memmove(ord + 1, ord, o * sizeof *ord); ord[0] = s; }
        }
        if (all) {
            double sc = pair_score(q, i, j, m);
            if (sc > best) {
                rowbest = sc; rj = j;
                memcpy(ps->row_path + 2 * (size_t)N * i, tmp, 2 * (size_t)N * sizeof *tmp);
                search_publish(ps, sc);
            }
        }
    }
    ps->row_score[i] = rowbest;
    ps->row_j[i] = rj;
}

/* stage II's preparation of shape s: its candidate points, the ones that
 * hug an edge, and the cone and clearance caches (empty) */
struct stage2_prep {
    const struct sub *sp;
    double **C;                 /* N: out, candidate points */
    int *nc;                    /* N: out, their numbers */
    uint64_t **nohug;           /* N: out, a bit per candidate that does not hug an edge */
    struct cone_cache *cones;   /* v, from, to: out */
    atomic_int oom;
};

static void stage2_prep_job(void *ctx, int s)
{
    struct stage2_prep *pp = ctx;
    struct cone_cache *cc = pp->cones;
    const struct sub *p = &pp->sp[s];
    int m = p->m, n = pp->nc[s] = candidates(p, &pp->C[s]);
    uint64_t *nh = pp->nohug[s] = calloc((size_t)(n + 63) / 64 + 1, sizeof *nh);
    cc->v[s] = calloc((size_t)n * m + 1, sizeof **cc->v);   /* "not yet" (cache_unset) */
    cc->from[s] = calloc((size_t)n * m + 1, sizeof **cc->from);
    cc->to[s] = calloc((size_t)n * m + 1, sizeof **cc->to);
    if (!pp->C[s] || !nh || !cc->v[s] || !cc->from[s] || !cc->to[s]) { atomic_store(&pp->oom, 1); return; }
    for (int a = 0; a < n; a++)
        if (!hugs_edge(p, pp->C[s] + 2 * a)) nh[a >> 6] |= (uint64_t)1 << (a & 63);
}

/* the rows of the search on the threads (small pieces: this thread); the
 * first row of the highest score, -1 if no row has a pair */
static int pair_search_run(struct pair_search *ps, void (*row)(void *, int), double *best)
{
    int m = ps->m, bi = -1;
    atomic_init(&ps->bound, -1);
    parallel_run(m, m >= PAIR_SEARCH_PARALLEL ? ps->c->threads : 1, row, ps);
    *best = -1;
    for (int i = 0; i < m; i++)
        if (ps->row_j[i] >= 0 && ps->row_score[i] > *best) { *best = ps->row_score[i]; bi = i; }
    return bi;
}

static int choose_split(struct compat *c, const int *poly, int m, struct split *out)
{
    int N = c->N;
    struct sub *sp = malloc(N * sizeof *sp);
    struct edge_grid *grid = malloc(N * sizeof *grid);
    for (int s = 0; s < N; s++) {
        sp[s].m = m; sp[s].poly = poly; sp[s].X = c->X[s]; sp[s].grid = NULL;
        if (m >= GRID_MIN_CORNERS && !c->exhaustive && grid_build(&grid[s], &sp[s]) == 0) sp[s].grid = &grid[s];
    }
    struct pair_search ps = {.c = c, .sp = sp, .N = N, .m = m};
    ps.row_score = malloc(m * sizeof *ps.row_score);
    ps.row_j = malloc(m * sizeof *ps.row_j);
    ps.row_ord = malloc((size_t)N * m * sizeof *ps.row_ord);
    if (!ps.row_score || !ps.row_j || !ps.row_ord) {
        free(ps.row_score); free(ps.row_j); free(ps.row_ord);
        for (int s = 0; s < N; s++) if (sp[s].grid) grid_free(&grid[s]);
        free(grid); free(sp);
        return cm_seterr("out of memory");
    }
    /* stage I */
    double best;
    int bi = pair_search_run(&ps, stage1_row, &best), bj = bi >= 0 ? ps.row_j[bi] : -1;
    if (bi >= 0) {
        out->i = bi; out->j = bj; out->k = 0; out->path = NULL; out->stage = 0;
        free(ps.row_score); free(ps.row_j); free(ps.row_ord);
        for (int s = 0; s < N; s++) if (sp[s].grid) grid_free(&grid[s]);
        free(grid); free(sp);
        return 0;
    }
    /* stage II: candidates per shape; visibility between corners and from
     * candidates to corners is tested when first needed (vis_cache) */
    atomic_uchar *vis = calloc((size_t)N * m * m, sizeof *vis);
    double **C = calloc(N, sizeof *C);
    int *nc = calloc(N, sizeof *nc);
    uint64_t **nohug = calloc(N, sizeof *nohug);
    struct cone_cache cones = {sp, C, m, nc, calloc(N, sizeof *cones.v), calloc(N, sizeof *cones.from),
                               calloc(N, sizeof *cones.to)};
    int oom = !vis || !C || !nc || !nohug || !cones.v || !cones.from || !cones.to;
    /* each shape's candidates, the ones that hug an edge and the empty
     * caches: one job per shape */
    struct stage2_prep prep = {sp, C, nc, nohug, &cones, 0};
    if (!oom) parallel_run(N, m >= PAIR_SEARCH_PARALLEL ? c->threads : 1, stage2_prep_job, &prep);
    oom |= prep.oom;
    struct vis_cache vc = {sp, m, vis, C, nc, malloc(N * sizeof *vc.words), calloc(N, sizeof *vc.bits)};
    if (!oom) oom = !vc.words || !vc.bits || vis_bits_build(&vc, N, c->threads) < 0;
    ps.vc = &vc; ps.cones = &cones; ps.C = C; ps.nc = nc; ps.nohug = nohug;
    ps.row_path = malloc(2 * (size_t)N * m * sizeof *ps.row_path);
    ps.row_tmp = malloc(2 * (size_t)N * m * sizeof *ps.row_tmp);
    oom |= !ps.row_path || !ps.row_tmp;
    bi = oom ? -1 : pair_search_run(&ps, stage2_row, &best);
    bj = bi >= 0 ? ps.row_j[bi] : -1;
    double *bestpath = malloc(2 * (size_t)N * sizeof *bestpath);
    if (bi >= 0) memcpy(bestpath, ps.row_path + 2 * (size_t)N * bi, 2 * (size_t)N * sizeof *bestpath);
    free(ps.row_path); free(ps.row_tmp); free(ps.row_ord); free(ps.row_score); free(ps.row_j);
    for (int s = 0; s < N; s++) {
        if (cones.v) free(cones.v[s]);
        if (cones.from) free(cones.from[s]);
        if (cones.to) free(cones.to[s]);
    }
    free(cones.v); free(cones.from); free(cones.to);
    int rc = 0;
    if (oom) { free(bestpath); rc = cm_seterr("out of memory"); goto done; }
    /* a Steiner point squeezed into a sliver only makes thinner pieces: below
     * STAGE2_MIN the overlay does better */
    if (bi >= 0 && (best >= STAGE2_MIN || c->split_mode == COMPAT_LINKPATH)) {
        out->i = bi; out->j = bj; out->k = 1; out->path = bestpath; out->stage = 1;
        goto done;
    }
    free(bestpath);
    if (c->split_mode != COMPAT_LINKPATH) { rc = 1; goto done; }
    /* stage III: link distances through candidate points */
    {
        int **dist = malloc(N * sizeof *dist);   /* dist[s][i*m + j]: links */
        unsigned char **cc = malloc(N * sizeof *cc);
        for (int s = 0; s < N; s++) {
            int n = nc[s];
            cc[s] = malloc((size_t)n * n + 1);
            for (int a = 0; a < n; a++)
                for (int b = 0; b < n; b++)
                    cc[s][(size_t)a * n + b] = a != b && (b < a ? cc[s][(size_t)b * n + a]
                        : seg_inside(&sp[s], -1, C[s] + 2 * a, -1, C[s] + 2 * b));
            dist[s] = malloc((size_t)m * m * sizeof **dist);
            int *d = malloc((n + 1) * sizeof *d), *queue = malloc((n + 1) * sizeof *queue);
            for (int i = 0; i < m; i++) {
                for (int a = 0; a < n; a++) d[a] = -1;
                int qh = 0, qt = 0;
                for (int a = 0; a < n; a++)
                    if (vis_cand(&vc, s, a, i)) { d[a] = 1; queue[qt++] = a; }
                while (qh < qt) {
                    int a = queue[qh++];
                    for (int b = 0; b < n; b++)
                        if (d[b] < 0 && cc[s][(size_t)a * n + b]) { d[b] = d[a] + 1; queue[qt++] = b; }
                }
                for (int j = 0; j < m; j++) {
                    int L = j != i && vis_corners(&vc, s, i, j) ? 1 : 1 << 29;
                    for (int a = 0; a < n; a++)
                        if (d[a] > 0 && d[a] + 1 < L && vis_cand(&vc, s, a, j)) L = d[a] + 1;
                    dist[s][(size_t)i * m + j] = L;
                }
            }
            free(d); free(queue);
        }
        int bestL = 1 << 29;
        double bb = -1;
        for (int i = 0; i < m; i++)
            for (int j = i + 2; j < m; j++) {
                if (i == 0 && j == m - 1) continue;
                int L = 0;
                for (int s = 0; s < N; s++) if (dist[s][(size_t)i * m + j] > L) L = dist[s][(size_t)i * m + j];
                double b = balance(i, j, m);
                if (L < bestL || (L == bestL && b > bb)) { bestL = L; bb = b; bi = i; bj = j; }
            }
        if (bestL >= 1 << 29) {
            rc = cm_seterr("compatible triangulation failed: no path between any two corners of a %d-gon", m);
        } else {
            int k = bestL - 1;
            out->i = bi; out->j = bj; out->k = k; out->stage = 2;
            out->path = malloc(2 * (size_t)N * k * sizeof *out->path);
            int n0 = 0;
            for (int s = 0; s < N; s++) if (nc[s] > n0) n0 = nc[s];
            int *d = malloc((n0 + 1) * sizeof *d), *par = malloc((n0 + 1) * sizeof *par),
                *queue = malloc((n0 + 1) * sizeof *queue);
            for (int s = 0; s < N && rc == 0; s++) {
                int n = nc[s];
                double *pts = out->path + 2 * (size_t)s * k;
                int L = dist[s][(size_t)bi * m + bj], have = 0;
                if (L > 1) {
                    for (int a = 0; a < n; a++) { d[a] = -1; par[a] = -1; }
                    int qh = 0, qt = 0;
                    for (int a = 0; a < n; a++)
                        if (vis_cand(&vc, s, a, bi)) { d[a] = 1; queue[qt++] = a; }
                    int end = -1;
                    while (qh < qt && end < 0) {
                        int a = queue[qh++];
                        if (d[a] == L - 1 && vis_cand(&vc, s, a, bj)) { end = a; break; }
                        for (int b = 0; b < n; b++)
                            if (d[b] < 0 && cc[s][(size_t)a * n + b]) { d[b] = d[a] + 1; par[b] = a; queue[qt++] = b; }
                    }
                    if (end < 0) { rc = cm_seterr("compatible triangulation failed (stage III path)"); break; }
                    have = L - 1;
                    for (int t = have - 1, a = end; t >= 0; t--, a = par[a]) {
                        pts[2 * t] = C[s][2 * a]; pts[2 * t + 1] = C[s][2 * a + 1];
                    }
                }
                /* pad: split the longest link that can take a point (inside
                 * the piece, path still simple) until the shape has k points */
                while (have < k && rc == 0) {
                    double tried = INFINITY;
                    int placed = 0;
                    while (!placed) {
                        int bt = -1;
                        double bl = -1;
                        for (int t = 0; t <= have; t++) {
                            const double *a = t ? pts + 2 * (t - 1) : V(&sp[s], bi);
                            const double *b = t < have ? pts + 2 * t : V(&sp[s], bj);
                            double l = hypot(b[0] - a[0], b[1] - a[1]);
                            if (l > bl && l < tried) { bl = l; bt = t; }
                        }
                        if (bt < 0) break;
                        tried = bl;
                        const double *a = bt ? pts + 2 * (bt - 1) : V(&sp[s], bi);
                        const double *b = bt < have ? pts + 2 * bt : V(&sp[s], bj);
                        double mid[2];
                        if (bent_point(&sp[s], bt ? -1 : bi, a, bt < have ? -1 : bj, b, mid) < 0) continue;
                        memmove(pts + 2 * (bt + 1), pts + 2 * bt, 2 * (size_t)(have - bt) * sizeof *pts);
                        pts[2 * bt] = mid[0]; pts[2 * bt + 1] = mid[1];
                        have++;
                        placed = 1;
                        if (path_crosses(&sp[s], bi, bj, pts, have)) {
                            memmove(pts + 2 * bt, pts + 2 * (bt + 1), 2 * (size_t)(have - 1 - bt) * sizeof *pts);
                            have--;
                            placed = 0;
                        }
                    }
                    if (!placed) rc = cm_seterr("compatible triangulation failed: no room for a Steiner point "
                                                "on a path in shape %d", s);
                }
                /* the path must not cross itself */
                for (int t = 0; t <= k && rc == 0; t++)
                    for (int u = t + 2; u <= k; u++) {
                        const double *a = t ? pts + 2 * (t - 1) : V(&sp[s], bi);
                        const double *b = t < k ? pts + 2 * t : V(&sp[s], bj);
                        const double *e = u ? pts + 2 * (u - 1) : V(&sp[s], bi);
                        const double *f = u < k ? pts + 2 * u : V(&sp[s], bj);
                        if (segments_meet(a, b, e, f)) {
                            rc = cm_seterr("compatible triangulation failed: stage III path crosses itself");
                            break;
                        }
                    }
            }
            free(d); free(par); free(queue);
            if (rc < 0) { free(out->path); out->path = NULL; }
        }
        for (int s = 0; s < N; s++) { free(dist[s]); free(cc[s]); }
        free(dist); free(cc);
    }
done:
    for (int s = 0; s < N; s++) {
        if (C) free(C[s]);
        if (vc.bits) free(vc.bits[s]);
        if (nohug) free(nohug[s]);
    }
    free(C); free(nc); free(vc.bits); free(vc.words); free(nohug); free(vis);
    for (int s = 0; s < N; s++) if (sp[s].grid) grid_free(&grid[s]);
    free(grid); free(sp);
    return rc;
}

/* Is local face f = (a, b, d) positive in every shape?  Y[s] holds the
 * piece's local positions in shape s (exact predicate). */
static int local_positive(int N, double *const *Y, int a, int b, int d)
{
    for (int s = 0; s < N; s++)
        if (orient2_sign(Y[s] + 2 * a, Y[s] + 2 * b, Y[s] + 2 * d) <= 0) return 0;
    return 1;
}

/* The smallest sine of an angle, over every shape, of the faces that
 * collapsing Steiner vertex v onto its neighbour u would leave around u;
 * -1 if the collapse is not allowed: a face would not be positive in some
 * shape, or the link condition fails (u and v share a neighbour other than
 * the apexes of their common faces, so the collapse would pinch the disc). */
static double collapse_score(int N, double *const *Y, const int *F, int nf, int nvl, int v, int u,
                             unsigned char *mark)
{
    memset(mark, 0, (size_t)nvl);
    for (int f = 0; f < nf; f++) {
        const int *t = F + 3 * f;
        if (t[0] == u || t[1] == u || t[2] == u)
            for (int e = 0; e < 3; e++) mark[t[e]] |= 1;
    }
    int apex = 0;
    for (int f = 0; f < nf; f++) {
        const int *t = F + 3 * f;
        int hv = t[0] == v || t[1] == v || t[2] == v, hu = t[0] == u || t[1] == u || t[2] == u;
        if (hv && hu) {
            for (int e = 0; e < 3; e++)
                if (t[e] != u && t[e] != v) { mark[t[e]] |= 4; apex++; }
        } else if (hv)
            for (int e = 0; e < 3; e++)
                if (t[e] != v) mark[t[e]] |= 2;
    }
    if (apex == 0) return -1;
    for (int w = 0; w < nvl; w++)
        if ((mark[w] & 3) == 3 && !(mark[w] & 4) && w != u && w != v) return -1;
    double q = 2;
    for (int f = 0; f < nf; f++) {
        const int *t = F + 3 * f;
        if (t[0] != v && t[1] != v && t[2] != v) continue;
        if (t[0] == u || t[1] == u || t[2] == u) continue;
        int w[3];
        for (int e = 0; e < 3; e++) w[e] = t[e] == v ? u : t[e];
        if (!local_positive(N, Y, w[0], w[1], w[2])) return -1;
        for (int s = 0; s < N; s++) {
            double a = compat_sin_min_angle(Y[s] + 2 * w[0], Y[s] + 2 * w[1], Y[s] + 2 * w[2]);
            if (a < q) q = a;
        }
    }
    return q;
}

/* The smallest sine of an angle of the faces around vertex v in shape s
 * (positions Ys, #V by 2) with v moved to p; -1 if one of them is not
 * positive (exact predicate). */
static double moved_star_score(const double *Ys, const int *F, int nf, int v, const double *p)
{
    double q = 2;
    for (int f = 0; f < nf; f++) {
        const int *t = F + 3 * f;
        int k = t[0] == v ? 0 : t[1] == v ? 1 : t[2] == v ? 2 : -1;
        if (k < 0) continue;
        const double *b = Ys + 2 * t[(k + 1) % 3], *d = Ys + 2 * t[(k + 2) % 3];
        if (orient2_sign(p, b, d) <= 0) return -1;
        q = fmin(q, compat_sin_min_angle(p, b, d));
    }
    return q;
}

/* A new position in shape s for vertex v whose star is not positive
 * there: the mean of its neighbours, or a point on the way to it (1/2,
 * 1/4, ... of the way); the one whose star has the largest smallest angle
 * goes to p.  Returns that score, or -1 if none is positive. */
static double relocate(const double *Ys, const int *F, int nf, int v, double *p)
{
    double mx = 0, my = 0;
    int n = 0;
    for (int f = 0; f < nf; f++) {
        const int *t = F + 3 * f;
        int k = t[0] == v ? 0 : t[1] == v ? 1 : t[2] == v ? 2 : -1;
        if (k < 0) continue;
        const double *b = Ys + 2 * t[(k + 1) % 3];
        mx += b[0]; my += b[1]; n++;
    }
    if (!n) return -1;
    mx /= n; my /= n;
    const double *o = Ys + 2 * v;
    double best = -1;
    for (double w = 1; w > 1e-6; w *= 0.5) {
        double c[2] = {o[0] + w * (mx - o[0]), o[1] + w * (my - o[1])};
        double q = moved_star_score(Ys, F, nf, v, c);
        if (q > best) { best = q; p[0] = c[0]; p[1] = c[1]; }
    }
    return best;
}

/* Rounding the overlay's crossings to doubles can leave a triangle between
 * nearly coincident crossings, or a crossing on a nearly flat corner, with
 * zero or negative area in some shape (exactly, it is positive).  Such a
 * triangle is repaired through one of its Steiner vertices (local index >=
 * m): moved in that shape only (relocate) if its star becomes positive
 * there, else collapsed onto a neighbour, choosing the collapse whose new
 * faces have the largest smallest angle, and only if every new face is
 * positive in every shape (exact predicate) and the disc stays a disc.  F and *nf are updated; removed vertices get dead[v] = 1.
 * Returns the number of collapses, or -1 when a bad face has no allowed
 * collapse (cm_errmsg set). */
static int overlay_repair(int N, double *const *Y, int m, int nvl, int *F, int *nf, unsigned char *dead)
{
    unsigned char *mark = malloc((size_t)nvl + 1);
    if (!mark) return cm_seterr("out of memory");
    int ncol = 0;
    for (;;) {
        int found = 0, fixed = 0, badshape = 0, bv = -1, bu = -1;
        double best = -1;
        for (int f = 0; f < *nf && !fixed; f++) {
            const int *t = F + 3 * f;
            if (local_positive(N, Y, t[0], t[1], t[2])) continue;
            int bs = 0;
            while (orient2_sign(Y[bs] + 2 * t[0], Y[bs] + 2 * t[1], Y[bs] + 2 * t[2]) > 0) bs++;
            if (!found) badshape = bs;
            found = 1;
            double rbest = -1, rp[2] = {0, 0}, p[2] = {0, 0};
            int rv = -1;
            for (int e = 0; e < 3; e++) {
                if (t[e] < m) continue;
                double q = relocate(Y[bs], F, *nf, t[e], p);
                if (q > rbest) { rbest = q; rv = t[e]; rp[0] = p[0]; rp[1] = p[1]; }
            }
            if (rv >= 0) {
                Y[bs][2 * rv] = rp[0];
                Y[bs][2 * rv + 1] = rp[1];
                fixed = 2;
                break;
            }
            for (int e = 0; e < 3; e++) {
                int v = t[e];
                if (v < m) continue;
                /* candidates: every neighbour of v */
                for (int g = 0; g < *nf; g++) {
                    const int *r = F + 3 * g;
                    int k = r[0] == v ? 0 : r[1] == v ? 1 : r[2] == v ? 2 : -1;
                    if (k < 0) continue;
                    int u = r[(k + 1) % 3];
                    double q = collapse_score(N, Y, F, *nf, nvl, v, u, mark);
                    if (q > best) { best = q; bv = v; bu = u; }
                }
            }
            if (bv >= 0) fixed = 1;
        }
        if (!found) break;
        if (fixed == 2) continue;
        if (!fixed) {
            free(mark);
            return cm_seterr("a %d-gon piece is too thin in shape %d (an overlay triangle rounds to zero area "
                             "and no move or collapse removes it)", m, badshape);
        }
        int w = 0;
        for (int f = 0; f < *nf; f++) {
            int *t = F + 3 * f;
            int hv = t[0] == bv || t[1] == bv || t[2] == bv, hu = t[0] == bu || t[1] == bu || t[2] == bu;
            if (hv && hu) continue;
            for (int e = 0; e < 3; e++) F[3 * w + e] = t[e] == bv ? bu : t[e];
            w++;
        }
        *nf = w;
        dead[bv] = 1;
        ncol++;
    }
    free(mark);
    return ncol;
}

/* triangulate the piece by overlay (cdt2_overlay): always possible; the
 * chord crossings become Steiner points (crossings that round into
 * slivers are collapsed away: overlay_repair) */
static int overlay_piece(struct compat *c, const int *poly, int m)
{
    int N = c->N;
    double **X = calloc(N, sizeof *X);
    for (int s = 0; s < N && X; s++)
        if (!(X[s] = malloc(2 * (size_t)m * sizeof **X))) {
            for (int t = 0; t < s; t++) free(X[t]);
            free(X);
            X = NULL;
        }
    if (!X) return cm_seterr("out of memory");
    for (int s = 0; s < N; s++) {
        for (int i = 0; i < m; i++) {
            X[s][2 * i] = c->X[s][2 * poly[i]];
            X[s][2 * i + 1] = c->X[s][2 * poly[i] + 1];
        }
    }
    double *S = NULL;
    int k = 0, nf = 0, *F = NULL;
    int rc = cdt2_overlay(m, N, (const double *const *)X, c->split_mode == COMPAT_OVERLAY_FEWEST, &S, &k, &F, &nf);
    if (rc < 0) {
        for (int s = 0; s < N; s++) free(X[s]);
        free(X);
        return -1;
    }
    /* local positions: the m corners, then the k crossings */
    int nvl = m + k;
    unsigned char *dead = calloc((size_t)nvl + 1, 1);
    int *id = malloc(((size_t)nvl + 1) * sizeof *id);
    for (int s = 0; s < N && dead && id; s++) {
        double *Y = realloc(X[s], 2 * ((size_t)nvl + 1) * sizeof *Y);
        if (!Y) { rc = cm_seterr("out of memory"); break; }
        memcpy(Y + 2 * (size_t)m, S + 2 * (size_t)s * k, 2 * (size_t)k * sizeof *S);
        X[s] = Y;
    }
    free(S);
    if (!dead || !id) rc = cm_seterr("out of memory");
    if (rc == 0 && overlay_repair(N, X, m, nvl, F, &nf, dead) < 0)
        rc = cm_seterr("compatible triangulation failed: %s", cm_errmsg());
    int base = c->nv, kept = 0;
    if (rc == 0) {
        for (int v = 0; v < nvl; v++) id[v] = v < m ? poly[v] : dead[v] ? -1 : base + kept++;
        rc = compat_reserve_vertices(c, c->nv + kept);
    }
    if (rc == 0) {
        for (int s = 0; s < N; s++)
            for (int v = m; v < nvl; v++)
                if (!dead[v]) memcpy(c->X[s] + 2 * (size_t)id[v], X[s] + 2 * (size_t)v, 2 * sizeof(double));
        c->nv += kept;
        c->nsteiner += kept;
    }
    for (int f = 0; f < nf && rc == 0; f++)
        rc = add_face(c, id[F[3 * f]], id[F[3 * f + 1]], id[F[3 * f + 2]]);
    for (int s = 0; s < N; s++) free(X[s]);
    free(X); free(F); free(dead); free(id);
    return rc;
}

/* The pieces the recursion leaves for later on several threads: those too
 * small for the pair search's threads (fewer than PAIR_SEARCH_PARALLEL
 * corners) and the overlays.  Each is triangulated on its own (struct
 * compat holding only its corners), in parallel, and then spliced in at
 * the place where the recursion left it: its new vertices and faces come
 * where they would have come in the order of the one-thread recursion, so
 * the mesh is the same bit for bit (a piece's triangulation depends only
 * on its corners' positions, in its own numbering).  On one thread the
 * recursion does every piece itself. */
struct tri_leaf {
    int *poly, m, depth;  /* its corners (vertex ids), depth in the recursion */
    int overlay;          /* 1: choose_split found no split (overlay_piece) */
    int nv, nf;           /* c->nv, c->nf when it was left: its place in the order */
    struct compat loc;    /* the piece alone: its corners 0..m-1, then its new vertices */
    int base;             /* the final id of its first new vertex */
    char err[256];        /* "" if it was triangulated */
};

struct tri_defer {
    const struct compat *c;
    int n, cap;
    struct tri_leaf *leaf;
    int *order;           /* n: the leaves in the order the threads take them */
};

static int defer_leaf(struct compat *c, struct tri_defer *df, const int *poly, int m, int depth, int overlay)
{
    if (df->n == df->cap) {
        int cap = df->cap ? 2 * df->cap : 32;
        struct tri_leaf *l = realloc(df->leaf, cap * sizeof *l);
        if (!l) return cm_seterr("out of memory");
        df->leaf = l; df->cap = cap;
    }
    struct tri_leaf *L = df->leaf + df->n;
    memset(L, 0, sizeof *L);
    if (!(L->poly = malloc(m * sizeof *L->poly))) return cm_seterr("out of memory");
    memcpy(L->poly, poly, m * sizeof *poly);
    L->m = m; L->depth = depth; L->overlay = overlay;
    L->nv = c->nv; L->nf = c->nf;
    df->n++;
    return 0;
}

static int triangulate_rec(struct compat *c, int *poly, int m, int depth, struct tri_defer *df);

/* twice the area of the piece poly (m corners) in shape 0 */
static double piece_area2(const struct compat *c, const int *poly, int m)
{
    const double *X = c->X[0];
    double a = 0;
    for (int i = 0; i < m; i++) {
        const double *p = X + 2 * poly[i], *q = X + 2 * poly[(i + 1) % m];
        a += p[0] * q[1] - p[1] * q[0];
    }
    return a;
}

/* the piece poly (m corners) is done or left for the threads: the
 * progress callback told (struct compat.progress) */
static void piece_done(struct compat *c, const int *poly, int m)
{
    if (!c->progress || !(c->prog_total > 0)) return;
    c->prog_done += piece_area2(c, poly, m);
    c->progress(c->progress_ctx, fmin(1, c->prog_done / c->prog_total));
}

/* triangulates leaf order[i] of the struct tri_defer ctx on its own */
static void leaf_job(void *ctx, int i)
{
    struct tri_defer *df = ctx;
    const struct compat *c = df->c;
    struct tri_leaf *L = df->leaf + df->order[i];
    struct compat *lc = &L->loc;
    int N = c->N, m = L->m, rc = -1;
    lc->N = N; lc->split_mode = c->split_mode; lc->exhaustive = c->exhaustive; lc->threads = 1;
    lc->nb = m;
    int *lp = malloc(m * sizeof *lp);
    if (lp && (lc->X = calloc(N, sizeof *lc->X)) && compat_reserve_vertices(lc, m) == 0) {
        for (int s = 0; s < N; s++)
            for (int v = 0; v < m; v++) {
                lc->X[s][2 * v] = c->X[s][2 * L->poly[v]];
                lc->X[s][2 * v + 1] = c->X[s][2 * L->poly[v] + 1];
            }
        lc->nv = m;
        for (int v = 0; v < m; v++) lp[v] = v;
        rc = L->overlay ? overlay_piece(lc, lp, m) : triangulate_rec(lc, lp, m, L->depth, NULL);
    } else cm_seterr("out of memory");
    if (rc < 0) snprintf(L->err, sizeof L->err, "%s", cm_errmsg()[0] ? cm_errmsg() : "out of memory");
    free(lp);
}

/* the leaves' vertices and faces spliced into c in the recursion's order
 * (c->nv, c->nf: the vertices and faces the recursion made itself, from
 * nv0 on; ids below nv0 stay) */
static int splice_leaves(struct compat *c, struct tri_defer *df, int nv0)
{
    if (!df->n) return 0;
    int N = c->N, nv = c->nv, nf = c->nf, nv1 = nv, nf1 = nf;
    for (int l = 0; l < df->n; l++) {
        nv1 += df->leaf[l].loc.nv - df->leaf[l].m;
        nf1 += df->leaf[l].loc.nf;
    }
    int *map = malloc(((size_t)nv + 1) * sizeof *map), *F = malloc(3 * ((size_t)nf1 + 1) * sizeof *F);
    double **X = calloc(N, sizeof *X);
    int rc = map && F && X ? 0 : -1;
    for (int s = 0; s < N && rc == 0; s++)
        if (!(X[s] = malloc(2 * ((size_t)nv1 + 1) * sizeof **X))) rc = -1;
    if (rc < 0) {
        free(map); free(F);
        if (X) for (int s = 0; s < N; s++) free(X[s]);
        free(X);
        return cm_seterr("out of memory");
    }
    /* vertices: the recursion's up to each leaf's place, then the leaf's */
    int out = nv0, pos = nv0;
    for (int v = 0; v < nv0; v++) map[v] = v;
    for (int l = 0; l <= df->n; l++) {
        int upto = l < df->n ? df->leaf[l].nv : nv;
        for (; pos < upto; pos++) map[pos] = out++;
        if (l < df->n) { df->leaf[l].base = out; out += df->leaf[l].loc.nv - df->leaf[l].m; }
    }
    for (int s = 0; s < N; s++) {
        memcpy(X[s], c->X[s], 2 * (size_t)nv0 * sizeof **X);
        for (int v = nv0; v < nv; v++) memcpy(X[s] + 2 * (size_t)map[v], c->X[s] + 2 * (size_t)v, 2 * sizeof **X);
        for (int l = 0; l < df->n; l++) {
            const struct tri_leaf *L = df->leaf + l;
            memcpy(X[s] + 2 * (size_t)L->base, L->loc.X[s] + 2 * (size_t)L->m,
                   2 * (size_t)(L->loc.nv - L->m) * sizeof **X);
        }
    }
    /* faces likewise (the faces before the recursion's first are kept) */
    int of = 0, fpos = 0;
    for (int l = 0; l <= df->n; l++) {
        int upto = l < df->n ? df->leaf[l].nf : nf;
        for (; fpos < upto; fpos++, of++)
            for (int k = 0; k < 3; k++) F[3 * of + k] = map[c->F[3 * fpos + k]];
        if (l == df->n) break;
        const struct tri_leaf *L = df->leaf + l;
        for (int f = 0; f < L->loc.nf; f++, of++)
            for (int k = 0; k < 3; k++) {
                int u = L->loc.F[3 * f + k];
                F[3 * of + k] = u < L->m ? map[L->poly[u]] : L->base + u - L->m;
            }
    }
    for (int l = 0; l < df->n; l++) {
        c->nsteiner += df->leaf[l].loc.nsteiner;
        for (int k = 0; k < 3; k++) c->stage_count[k] += df->leaf[l].loc.stage_count[k];
    }
    for (int s = 0; s < N; s++) { free(c->X[s]); c->X[s] = X[s]; }
    free(X);
    free(c->F);
    c->F = F;
    c->fcap = nf1 + 1;
    c->cap = nv1 + 1;
    c->nv = nv1;
    c->nf = nf1;
    free(map);
    return 0;
}

/* the recursion from poly on; with several threads the small pieces and
 * the overlays are left for leaf_job (struct tri_defer) */
static int triangulate_top(struct compat *c, int *poly, int m)
{
    c->prog_done = 0;
    c->prog_total = c->progress ? piece_area2(c, poly, m) : 0;
    if (parallel_threads(c->threads) < 2) return triangulate_rec(c, poly, m, 0, NULL);
    struct tri_defer df = {c, 0, 0, NULL, NULL};
    int nv0 = c->nv;
    int rc = triangulate_rec(c, poly, m, 0, &df);
    /* the costliest first, so that no long one is left for the end: the
     * overlays (CGAL's exact arithmetic; on the 600-px walk an 18-corner
     * one took 0.06 s, the 246 small pieces 0.04 s together), larger
     * pieces before smaller ones (insertion sort: few leaves) */
    int oom = !(df.order = malloc((df.n + 1) * sizeof *df.order));
    for (int l = 0; !oom && l < df.n; l++) {
        int k = l;
        const struct tri_leaf *L = df.leaf + l;
        for (; k > 0; k--) {
            const struct tri_leaf *P = df.leaf + df.order[k - 1];
            if (P->overlay > L->overlay || (P->overlay == L->overlay && P->m >= L->m)) break;
            df.order[k] = df.order[k - 1];
        }
        df.order[k] = l;
    }
    if (!oom) parallel_run(df.n, c->threads, leaf_job, &df);
    /* the first failure in the recursion's order: a leaf's, or else
     * the recursion's own (which came after every leaf it left) */
    int failed = -1;
    for (int l = 0; !oom && l < df.n && failed < 0; l++)
        if (df.leaf[l].err[0]) failed = l;
    if (oom) rc = cm_seterr("out of memory");
    else if (failed >= 0) rc = cm_seterr("%s", df.leaf[failed].err);
    else if (rc == 0) rc = splice_leaves(c, &df, nv0);
    for (int l = 0; l < df.n; l++) {
        free(df.leaf[l].poly);
        compat_free(&df.leaf[l].loc);
    }
    free(df.leaf);
    free(df.order);
    return rc;
}

static int triangulate_rec(struct compat *c, int *poly, int m, int depth, struct tri_defer *df)
{
    if (m < 3) return cm_seterr("internal: degenerate sub-polygon");
    if (m == 3) {
        piece_done(c, poly, m);
        return add_face(c, poly[0], poly[1], poly[2]);
    }
    if (depth > 100000) return cm_seterr("compatible triangulation failed: recursion too deep");
    if (df && m < PAIR_SEARCH_PARALLEL) {
        piece_done(c, poly, m);
        return defer_leaf(c, df, poly, m, depth, 0);
    }
    struct split sp = {0};
    int rc0 = choose_split(c, poly, m, &sp);
    if (rc0 < 0) return -1;
    if (rc0 > 0) {
        c->stage_count[2]++;
        int rc = df ? defer_leaf(c, df, poly, m, depth, 1) : overlay_piece(c, poly, m);
        piece_done(c, poly, m);
        return rc;
    }
    c->stage_count[sp.stage]++;
    int k = sp.k, base = c->nv;
    if (k > 0) {
        if (compat_reserve_vertices(c, c->nv + k) < 0) { free(sp.path); return -1; }
        for (int s = 0; s < c->N; s++)
            memcpy(c->X[s] + 2 * (size_t)base, sp.path + 2 * (size_t)s * k, 2 * (size_t)k * sizeof(double));
        c->nv += k;
        c->nsteiner += k;
    }
    free(sp.path);
    int i = sp.i, j = sp.j;
    int m1 = j - i + 1 + k, m2 = m - (j - i) + 1 + k;
    int *p1 = malloc(m1 * sizeof *p1), *p2 = malloc(m2 * sizeof *p2);
    int t = 0;
    for (int a = i; a <= j; a++) p1[t++] = poly[a];
    for (int q = k - 1; q >= 0; q--) p1[t++] = base + q;
    t = 0;
    for (int a = j; a != (i + 1) % m; a = (a + 1) % m) p2[t++] = poly[a];
    for (int q = 0; q < k; q++) p2[t++] = base + q;
    int rc = triangulate_rec(c, p1, m1, depth + 1, df);
    if (rc == 0) rc = triangulate_rec(c, p2, m2, depth + 1, df);
    free(p1); free(p2);
    return rc;
}

int compat_triangulate_poly(struct compat *c, int *poly, int m)
{
    return triangulate_top(c, poly, m);
}

int compat_triangulate(struct compat *c)
{
    int m = c->nb;
    int *poly = malloc(m * sizeof *poly);
    for (int i = 0; i < m; i++) poly[i] = i;
    c->nf = 0;
    int rc = triangulate_top(c, poly, m);
    free(poly);
    return rc;
}

/* ------------------------------------------------------------------ */
/* quality */

static double tri_min_angle(const double *a, const double *b, const double *d)
{
    /* the smallest angle is opposite the shortest edge: one atan2 */
    const double *P[3] = {a, b, d};
    double l[3];
    for (int k = 0; k < 3; k++) {
        const double *u = P[(k + 1) % 3], *v = P[(k + 2) % 3];
        l[k] = (v[0] - u[0]) * (v[0] - u[0]) + (v[1] - u[1]) * (v[1] - u[1]);
    }
    int k = l[0] <= l[1] && l[0] <= l[2] ? 0 : l[1] <= l[2] ? 1 : 2;
    const double *o = P[k], *u = P[(k + 1) % 3], *v = P[(k + 2) % 3];
    double ux = u[0] - o[0], uy = u[1] - o[1], vx = v[0] - o[0], vy = v[1] - o[1];
    return atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy);
}

/* smallest angle over shapes of triangle (a,b,d) as its sine; -1 if
 * inverted in some shape (exact) */
/* face_quality, or any value <= floor once the smallest so far is at or
 * below it (the shapes after that can only lower it) */
static double face_quality_above(const struct compat *c, int a, int b, int d, double floor)
{
    double q = INFINITY;
    for (int s = 0; s < c->N; s++) {
        const double *X = c->X[s];
        double x = compat_sin_min_angle(X + 2 * a, X + 2 * b, X + 2 * d);
        /* a sine above 1e-9 cannot come from a wrongly signed area */
        if (x < 1e-9 && orient2_sign(X + 2 * a, X + 2 * b, X + 2 * d) <= 0) return -1;
        q = fmin(q, x);
        if (q <= floor) break;
    }
    return q;
}

static double face_quality(const struct compat *c, int a, int b, int d)
{
    return face_quality_above(c, a, b, d, -1);     /* q >= 0: never stops early */
}

double compat_min_angle(const struct compat *c, double *minarea)
{
    double q = INFINITY, ma = INFINITY;
    for (int s = 0; s < c->N; s++) {
        double dg = diag2(c->X[s], c->nv);
        for (int f = 0; f < c->nf; f++) {
            const int *F = c->F + 3 * f;
            const double *X = c->X[s];
            double ar = 0.5 * orient2(X + 2 * F[0], X + 2 * F[1], X + 2 * F[2]) / (dg * dg);
            if (ar < ma) ma = ar;
            q = fmin(q, tri_min_angle(X + 2 * F[0], X + 2 * F[1], X + 2 * F[2]));
        }
    }
    if (minarea) *minarea = ma;
    return q;
}

/* ------------------------------------------------------------------ */
/* improvement: splits, flips, smoothing */

static int opposite(const int *F, int f, int a, int b)
{
    for (int k = 0; k < 3; k++)
        if (F[3 * f + k] != a && F[3 * f + k] != b) return F[3 * f + k];
    return -1;
}

/* ordered so that (a, b, x) is the face's orientation */
static int oriented_edge(const int *F, int f, int a, int b)
{
    for (int k = 0; k < 3; k++)
        if (F[3 * f + k] == a && F[3 * f + (k + 1) % 3] == b) return 1;
    return 0;
}

/* what flip_pass does with interior edge e of t while its two triangles
 * are as they were at the start of the pass: FLIP_NONE, FLIP_DO, or
 * FLIP_AGAIN (not flipped because the other diagonal is an edge elsewhere) */
enum { FLIP_NONE, FLIP_DO, FLIP_AGAIN };

static int flip_decision(const struct compat *c, const struct topology *t, int e)
{
    int f1 = t->EF[2 * e], f2 = t->EF[2 * e + 1];
    int a = t->E[2 * e], b = t->E[2 * e + 1];
    if (!oriented_edge(c->F, f1, a, b)) { int x = f1; f1 = f2; f2 = x; }
    /* f1 = (a, b, p), f2 = (b, a, q) */
    int p = opposite(c->F, f1, a, b), q = opposite(c->F, f2, a, b);
    if (p == q) return FLIP_NONE;
    if (topology_edge(t, p, q) >= 0) return FLIP_AGAIN;
    double old = fmin(face_quality(c, a, b, p), face_quality(c, b, a, q));
    /* the second new face is looked at only if the first beats old */
    double n1 = face_quality_above(c, a, q, p, old + 1e-9);
    if (!(n1 > old + 1e-9)) return FLIP_NONE;
    double n2 = face_quality_above(c, b, p, q, old + 1e-9);
    return n2 > old + 1e-9 ? FLIP_DO : FLIP_NONE;
}

/* flip_decision of every interior edge, FLIP_BLOCK edges a job */
#define FLIP_BLOCK 256
struct flip_jobs {
    const struct compat *c;
    const struct topology *t;
    unsigned char *dec;   /* ne: out */
};

static void flip_job(void *ctx, int k)
{
    struct flip_jobs *j = ctx;
    int e1 = (k + 1) * FLIP_BLOCK < j->t->ne ? (k + 1) * FLIP_BLOCK : j->t->ne;
    for (int e = k * FLIP_BLOCK; e < e1; e++)
        j->dec[e] = j->t->EFn[e] == 2 ? (unsigned char)flip_decision(j->c, j->t, e) : FLIP_NONE;
}

/* compat_flip_pass; with seen != NULL only the edges with a triangle
 * flagged in seen (#F) are looked at (the others were looked at before with
 * the same two triangles and not flipped), changed (#F, may be NULL) flags
 * the triangles this pass rewrote and again (#F, with changed) those of
 * edges not flipped because the other diagonal is an edge elsewhere (that
 * edge may be gone by the next pass).  The edges are taken in order; one
 * whose triangle an earlier flip rewrote waits for the next pass, so an
 * edge that is looked at has the triangles, positions and (stale) topology
 * of the pass's start: on a full pass (seen NULL) with several threads
 * (c->threads) every edge's decision is worked out first on the threads,
 * the same decisions. */
static int flip_pass(struct compat *c, const unsigned char *seen, unsigned char *changed, unsigned char *again)
{
    struct topology t;
    if (topology_build(c->F, c->nf, c->nv, &t) < 0) return -1;
    unsigned char *touched = changed ? changed : malloc(c->nf + 1);
    if (!touched) { topology_free(&t); return cm_seterr("out of memory"); }
    memset(touched, 0, c->nf);
    if (again) memset(again, 0, c->nf);
    unsigned char *dec = NULL;
    if (!seen && t.ne > FLIP_BLOCK && parallel_threads(c->threads) > 1 && (dec = malloc(t.ne))) {
        struct flip_jobs fj = {c, &t, dec};
        parallel_run((t.ne + FLIP_BLOCK - 1) / FLIP_BLOCK, c->threads, flip_job, &fj);
    }
    int flips = 0;
    for (int e = 0; e < t.ne; e++) {
        if (t.EFn[e] != 2) continue;
        int f1 = t.EF[2 * e], f2 = t.EF[2 * e + 1];
        if (touched[f1] || touched[f2]) continue;
        if (seen && !seen[f1] && !seen[f2]) continue;
        int d = dec ? dec[e] : flip_decision(c, &t, e);
        if (d == FLIP_AGAIN) {
            if (again) again[f1] = again[f2] = 1;
            continue;
        }
        if (d != FLIP_DO) continue;
        int a = t.E[2 * e], b = t.E[2 * e + 1];
        if (!oriented_edge(c->F, f1, a, b)) { int x = f1; f1 = f2; f2 = x; }
        int p = opposite(c->F, f1, a, b), q = opposite(c->F, f2, a, b);
        int *F1 = c->F + 3 * f1, *F2 = c->F + 3 * f2;
        F1[0] = a; F1[1] = q; F1[2] = p;
        F2[0] = b; F2[1] = p; F2[2] = q;
        touched[f1] = touched[f2] = 1;
        flips++;
    }
    free(dec);
    if (!changed) free(touched);
    topology_free(&t);
    return flips;
}

int compat_flip_pass(struct compat *c)
{
    return flip_pass(c, NULL, NULL, NULL);
}

/* An edge whose two triangles no pass rewrote gives the same answer as in
 * the pass before (the positions do not change; an edge skipped because a
 * triangle was rewritten has that triangle flagged), so after the first
 * pass only the edges of rewritten triangles are looked at: the same
 * flips as full passes, in the same order. */
int compat_flip_passes(struct compat *c, int passes, int *nflips)
{
    unsigned char *fl[2] = {malloc(c->nf + 1), malloc(c->nf + 1)}, *again = malloc(c->nf + 1);
    int rc = 0;
    if (!fl[0] || !fl[1] || !again) rc = cm_seterr("out of memory");
    for (int k = 0; !rc && k < passes; k++) {
        unsigned char *seen = k ? fl[(k + 1) & 1] : NULL, *changed = fl[k & 1];
        int x = flip_pass(c, seen, changed, again);
        if (x < 0) rc = -1;
        else { *nflips += x; if (!x) break; }
        for (int f = 0; f < c->nf; f++) changed[f] |= again[f];
    }
    free(fl[0]);
    free(fl[1]);
    free(again);
    return rc;
}

static double edge_len_rel(const struct compat *c, int a, int b, const double *dg)
{
    double L = 0;
    for (int s = 0; s < c->N; s++) {
        const double *X = c->X[s];
        L = fmax(L, hypot(X[2 * b] - X[2 * a], X[2 * b + 1] - X[2 * a + 1]) / dg[s]);
    }
    return L;
}

static int split_pass(struct compat *c, double target, const double *dg)
{
    struct topology t;
    if (topology_build(c->F, c->nf, c->nv, &t) < 0) return -1;
    unsigned char *touched = calloc(c->nf, 1);
    int splits = 0;
    /* longest edges first: collect and sort */
    int ne = 0;
    int *E = malloc((t.ne + 1) * sizeof *E);
    double *L = malloc((t.ne + 1) * sizeof *L);
    for (int e = 0; e < t.ne; e++) {
        if (t.EFn[e] != 2) continue;
        double l = edge_len_rel(c, t.E[2 * e], t.E[2 * e + 1], dg);
        if (l > target) { E[ne] = e; L[ne] = l; ne++; }
    }
    for (int x = 1; x < ne; x++)   /* insertion sort, descending */
        for (int y = x; y > 0 && L[y] > L[y - 1]; y--) {
            double tl = L[y]; L[y] = L[y - 1]; L[y - 1] = tl;
            int te = E[y]; E[y] = E[y - 1]; E[y - 1] = te;
        }
    int nf0 = c->nf;
    for (int x = 0; x < ne; x++) {
        int e = E[x];
        int f1 = t.EF[2 * e], f2 = t.EF[2 * e + 1];
        if (touched[f1] || touched[f2]) continue;
        int a = t.E[2 * e], b = t.E[2 * e + 1];
        if (!oriented_edge(c->F, f1, a, b)) { int z = f1; f1 = f2; f2 = z; }
        int p = opposite(c->F, f1, a, b), q = opposite(c->F, f2, a, b);
        if (compat_reserve_vertices(c, c->nv + 1) < 0) break;
        int mv = c->nv++;
        for (int s = 0; s < c->N; s++) {
            c->X[s][2 * mv] = 0.5 * (c->X[s][2 * a] + c->X[s][2 * b]);
            c->X[s][2 * mv + 1] = 0.5 * (c->X[s][2 * a + 1] + c->X[s][2 * b + 1]);
        }
        c->nrefine++;
        int *F1 = c->F + 3 * f1;
        F1[0] = a; F1[1] = mv; F1[2] = p;
        int *F2 = c->F + 3 * f2;
        F2[0] = b; F2[1] = mv; F2[2] = q;
        touched[f1] = touched[f2] = 1;
        if (add_face(c, mv, b, p) < 0 || add_face(c, mv, a, q) < 0) break;
        splits++;
    }
    (void)nf0;
    free(E); free(L); free(touched);
    topology_free(&t);
    return splits;
}

/* one Laplacian smoothing pass of interior vertices, per shape; a move is
 * kept only if no incident triangle inverts and the smallest angle of the
 * vertex's star does not decrease */
static void smooth_pass(struct compat *c, const struct topology *t, int relaxed)
{
    for (int s = 0; s < c->N; s++) {
        double *X = c->X[s];
        for (int v = c->nb; v < c->nv; v++) {
            int d = t->VVs[v + 1] - t->VVs[v];
            if (d == 0) continue;
            double cx = 0, cy = 0;
            for (int k = t->VVs[v]; k < t->VVs[v + 1]; k++) { cx += X[2 * t->VV[k]]; cy += X[2 * t->VV[k] + 1]; }
            cx /= d; cy /= d;
            double old = INFINITY;
            for (int k = t->VFs[v]; k < t->VFs[v + 1]; k++) {
                const int *F = c->F + 3 * t->VF[k];
                old = fmin(old, tri_min_angle(X + 2 * F[0], X + 2 * F[1], X + 2 * F[2]));
            }
            double ox = X[2 * v], oy = X[2 * v + 1];
            for (int tries = 0; tries < 3; tries++) {
                X[2 * v] = cx; X[2 * v + 1] = cy;
                double nq = INFINITY;
                /* every incident triangle is tested (nq >= 0, not > 0: a sliver
                 * whose angle rounds to 0 must not end the test early; fuzz_compat) */
                for (int k = t->VFs[v]; k < t->VFs[v + 1] && nq >= 0; k++) {
                    const int *F = c->F + 3 * t->VF[k];
                    if (orient2_sign(X + 2 * F[0], X + 2 * F[1], X + 2 * F[2]) <= 0) nq = -1;
                    else nq = fmin(nq, tri_min_angle(X + 2 * F[0], X + 2 * F[1], X + 2 * F[2]));
                }
                if (nq >= old || (nq > 0 && nq > 0.5 * old && relaxed)) break;
                X[2 * v] = ox; X[2 * v + 1] = oy;
                cx = 0.5 * (cx + ox); cy = 0.5 * (cy + oy);
            }
        }
    }
}

int compat_improve(struct compat *c, double target, int iters)
{
    double *dg = malloc(c->N * sizeof *dg);
    for (int s = 0; s < c->N; s++) dg[s] = diag2(c->X[s], c->nb);
    if (target > 0)
        for (int r = 0; r < 30; r++) {
            /* flips and a little smoothing before every split round, so new
             * vertices spread out instead of piling up along slivers */
            { int nfl = 0; if (compat_flip_passes(c, 20, &nfl) < 0) { free(dg); return -1; } }
            struct topology t;
            if (topology_build(c->F, c->nf, c->nv, &t) < 0) { free(dg); return -1; }
            for (int k = 0; k < 3; k++) smooth_pass(c, &t, 1);
            topology_free(&t);
            int n = split_pass(c, target, dg);
            if (n < 0) { free(dg); return -1; }
            if (n == 0) break;
        }
    for (int it = 0; it < iters; it++) {
        struct topology t;
        if (topology_build(c->F, c->nf, c->nv, &t) < 0) { free(dg); return -1; }
        for (int k = 0; k < 5; k++) smooth_pass(c, &t, it < iters / 2);
        topology_free(&t);
        int nfl = 0;
        if (compat_flip_passes(c, 20, &nfl) < 0) { free(dg); return -1; }
        if (nfl == 0 && it > 2) break;
    }
    free(dg);
    return 0;
}
