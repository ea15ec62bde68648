/* compat_holes.c -- see compat_holes.h */
#include "compat_holes.h"
#include "cm_error.h"
#include "predicates2.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------ */
/* exact point in polygon */

/* is q strictly inside the closed polyline X[cyc[0..m-1]] (crossing rule,
 * exact orientation; q must not lie on it) */
static int inside_cycle(const double *X, const int *cyc, int m, const double *q)
{
    int in = 0;
    for (int i = 0; i < m; i++) {
        const double *a = X + 2 * cyc[i], *b = X + 2 * cyc[(i + 1) % m];
        if (a[1] <= q[1] && q[1] < b[1]) { if (orient2_sign(a, b, q) > 0) in ^= 1; }
        else if (b[1] <= q[1] && q[1] < a[1]) { if (orient2_sign(a, b, q) < 0) in ^= 1; }
    }
    return in;
}

/* does q lie on the closed segment ab (exact) */
static int on_seg(const double *a, const double *b, const double *q)
{
    return orient2_sign(a, b, q) == 0 && fmin(a[0], b[0]) <= q[0] && q[0] <= fmax(a[0], b[0]) &&
           fmin(a[1], b[1]) <= q[1] && q[1] <= fmax(a[1], b[1]);
}

static int ring_contains(const struct rings *r, int k, const double *q)
{
    int n = rings_count(r, k), *cyc = malloc(n * sizeof *cyc);
    for (int i = 0; i < n; i++) cyc[i] = r->start[k] + i;
    int in = inside_cycle(r->P, cyc, n, q);
    free(cyc);
    return in;
}

int compat_ring_inside(const struct rings *r, int b, int a)
{
    const double *A = rings_ring(r, a), *B = rings_ring(r, b);
    int na = rings_count(r, a), nb = rings_count(r, b);
    for (int i = 0; i < nb; i++)
        for (int j = 0; j < na; j++)
            if (segments_intersect(B + 2 * i, B + 2 * ((i + 1) % nb), A + 2 * j, A + 2 * ((j + 1) % na))) return 0;
    for (int i = 0; i < nb; i++)
        if (!ring_contains(r, a, B + 2 * i)) return 0;
    return 1;
}

/* ------------------------------------------------------------------ */
/* nesting */

double *compat_ring_ccw(const struct rings *r, int k, int hole)
{
    int n = rings_count(r, k);
    double *P = malloc(2 * (size_t)n * sizeof *P);
    if (!P) return NULL;
    const double *Q = rings_ring(r, k);
    for (int i = 0; i < n; i++) {
        int j = hole ? n - 1 - i : i;
        P[2 * i] = Q[2 * j]; P[2 * i + 1] = Q[2 * j + 1];
    }
    return P;
}

int compat_is_hole(const int *parent, int k)
{
    int d = 0;
    for (int p = parent[k]; p >= 0; p = parent[p]) d++;
    return d & 1;
}

/* innermost ring of r holding point q (exclude ring `self`), -1 if none */
static int innermost(const struct rings *r, int self, const double *q)
{
    int best = -1;
    double ba = INFINITY;
    for (int j = 0; j < r->nrings; j++) {
        if (j == self || !ring_contains(r, j, q)) continue;
        double a = fabs(rings_area(r, j));
        if (a < ba) { ba = a; best = j; }
    }
    return best;
}

/* every shape has shape 0's ring count; -1 (cm_errmsg) if not */
static int same_ring_counts(int N, const struct rings *R)
{
    for (int s = 1; s < N; s++)
        if (R[s].nrings != R[0].nrings)
            return cm_seterr("shape %d has %d ring%s, but shape 0 has %d (rings are matched by order)", s,
                             R[s].nrings, R[s].nrings == 1 ? "" : "s", R[0].nrings);
    return 0;
}

int compat_nest(int N, struct rings *R, int *parent, unsigned char *flipped)
{
    int nr = R[0].nrings;
    if (same_ring_counts(N, R) < 0) return -1;
    int *par = malloc(nr * sizeof *par);
    for (int s = 0; s < N; s++) {
        struct rings *r = &R[s];
        for (int k = 0; k < nr; k++) par[k] = innermost(r, k, rings_ring(r, k));
        for (int k = 0; k < nr; k++) {
            if (s == 0) parent[k] = par[k];
            else if (par[k] != parent[k]) {
                char wa[32] = "in no ring", wb[32] = "in no ring";
                if (par[k] >= 0) snprintf(wa, sizeof wa, "in ring %d", par[k] + 1);
                if (parent[k] >= 0) snprintf(wb, sizeof wb, "in ring %d", parent[k] + 1);
                cm_seterr("shape %d: ring %d lies %s, but in shape 0 %s (rings are matched by order: "
                          "same rings, same nesting in every shape)", s, k + 1, wa, wb);
                free(par);
                return -1;
            }
        }
        for (int k = 0; k < nr; k++) {
            int a = rings_orientation(r, k);   /* exact */
            int hole = compat_is_hole(parent, k);
            flipped[(size_t)s * nr + k] = 0;
            if ((!hole && a < 0) || (hole && a > 0)) {
                rings_reverse(r, k);
                flipped[(size_t)s * nr + k] = 1;
            }
        }
    }
    free(par);
    return 0;
}

int compat_layers(int N, struct rings *R, int *parent, unsigned char *flipped)
{
    int nr = R[0].nrings;
    if (same_ring_counts(N, R) < 0) return -1;
    for (int k = 0; k < nr; k++) parent[k] = COMPAT_LAYER;
    for (int s = 0; s < N; s++)
        for (int k = 0; k < nr; k++) {
            flipped[(size_t)s * nr + k] = rings_orientation(&R[s], k) < 0;   /* exact */
            if (flipped[(size_t)s * nr + k]) rings_reverse(&R[s], k);
        }
    return 0;
}

int compat_stack(const struct compat *parts, int n, struct compat *c)
{
    memset(c, 0, sizeof *c);
    if (n < 1) return cm_seterr("no layer to stack");
    int N = parts[0].N, nv = 0, nf = 0, nb = 0;
    for (int r = 0; r < n; r++) { nv += parts[r].nv; nf += parts[r].nf; nb += parts[r].nb; }
    c->N = N;
    c->X = calloc(N, sizeof *c->X);
    c->F = malloc(3 * ((size_t)nf + 1) * sizeof *c->F);
    c->ring_start = malloc(((size_t)n + 1) * sizeof *c->ring_start);
    c->ring_parent = malloc(((size_t)n + 1) * sizeof *c->ring_parent);
    if (!c->X || !c->F || !c->ring_start || !c->ring_parent) goto oom;
    for (int s = 0; s < N; s++)
        if (!(c->X[s] = malloc(2 * ((size_t)nv + 1) * sizeof **c->X))) goto oom;
    c->cap = nv + 1;
    c->fcap = nf + 1;
    c->nrings = n;
    int b = 0, v = nb;
    for (int r = 0; r < n; r++) {
        c->ring_start[r] = b;
        c->ring_parent[r] = COMPAT_LAYER;
        for (int s = 0; s < N; s++) {
            memcpy(c->X[s] + 2 * (size_t)b, parts[r].X[s], 2 * (size_t)parts[r].nb * sizeof **c->X);
            memcpy(c->X[s] + 2 * (size_t)v, parts[r].X[s] + 2 * (size_t)parts[r].nb,
                   2 * (size_t)(parts[r].nv - parts[r].nb) * sizeof **c->X);
        }
        for (int f = 0; f < 3 * parts[r].nf; f++) {
            int x = parts[r].F[f];
            c->F[3 * (size_t)c->nf + f] = x < parts[r].nb ? b + x : v + x - parts[r].nb;
        }
        c->nf += parts[r].nf;
        b += parts[r].nb;
        v += parts[r].nv - parts[r].nb;
        c->nsteiner += parts[r].nsteiner;
        c->nrefine += parts[r].nrefine;
        for (int k = 0; k < 3; k++) c->stage_count[k] += parts[r].stage_count[k];
    }
    c->ring_start[n] = nb;
    c->nv = v;
    c->nb = c->nm = nb;
    return 0;
oom:
    compat_free(c);
    return cm_seterr("out of memory");
}

/* ------------------------------------------------------------------ */
/* matching, simplification, stacking */

/* do the simplified rings of shape s stay apart, keep their nesting and
 * hold the interior points in their pieces? */
static int layout_ok(struct compat *cr, int nr, const int *parent, int s, const double *pts, int npts,
                     int N, const int *ptring)
{
    for (int a = 0; a < nr; a++)
        for (int b = a + 1; b < nr; b++) {
            if (parent[a] == COMPAT_LAYER && parent[b] == COMPAT_LAYER) continue;   /* layers may cross */
            const double *A = cr[a].X[s], *B = cr[b].X[s];
            int na = cr[a].nb, nb = cr[b].nb;
            for (int i = 0; i < na; i++)
                for (int j = 0; j < nb; j++)
                    if (segments_meet(A + 2 * i, A + 2 * ((i + 1) % na), B + 2 * j, B + 2 * ((j + 1) % nb)))
                        return 0;
        }
    int **cyc = malloc(nr * sizeof *cyc);
    for (int r = 0; r < nr; r++) {
        cyc[r] = malloc(cr[r].nb * sizeof **cyc);
        for (int i = 0; i < cr[r].nb; i++) cyc[r][i] = i;
    }
    int ok = 1;
    for (int k = 0; k < nr && ok; k++)
        if (parent[k] >= 0 && !inside_cycle(cr[parent[k]].X[s], cyc[parent[k]], cr[parent[k]].nb, cr[k].X[s]))
            ok = 0;
    for (int i = 0; i < npts && ok; i++) {
        const double *q = pts + 2 * ((size_t)i * N + s);
        for (int r = 0; r < nr && ok; r++) {
            int in = inside_cycle(cr[r].X[s], cyc[r], cr[r].nb, q);
            for (int j = 0; j < cr[r].nb; j++)
                if (on_seg(cr[r].X[s] + 2 * j, cr[r].X[s] + 2 * ((j + 1) % cr[r].nb), q)) ok = 0;
            /* inside its piece, outside the piece's holes */
            if (r == ptring[i] && !in) ok = 0;
            if (r != ptring[i] && parent[r] == ptring[i] && in) ok = 0;
        }
    }
    for (int r = 0; r < nr; r++) free(cyc[r]);
    free(cyc);
    return ok;
}

int compat_multi(int N, struct rings *R, const int *parent, const unsigned char *flipped,
                 const int *corr, int ncorr, const double *pts, int npts, double err,
                 struct compat *c, double stats[4])
{
    memset(c, 0, sizeof *c);
    int nr = R[0].nrings, rc = -1, nfirst = 0;
    int *ptring = malloc((npts + 1) * sizeof *ptring);
    struct compat *cr = calloc(nr, sizeof *cr);
    unsigned char **keep = calloc(nr, sizeof *keep);
    int *cc = malloc(((size_t)ncorr + 1) * N * sizeof *cc), *nn = malloc(N * sizeof *nn);
    double **P = malloc(N * sizeof *P), *dpose = malloc(N * sizeof *dpose);
    for (int s = 0; s < N; s++) dpose[s] = polygon_diagonal(R[s].P, R[s].start[nr]);
    /* every correspondence row names one ring in all shapes */
    int *rowring = malloc((ncorr + 1) * sizeof *rowring);
    for (int k = 0; k < ncorr; k++)
        for (int s = 0; s < N; s++) {
            int v = corr[(size_t)k * N + s], r = 0;
            if (v < 0 || v >= R[s].start[nr]) {
                cm_seterr("row %d: %d is not a vertex index of shape %d (0..%d)", k + 1, v, s, R[s].start[nr] - 1);
                goto out;
            }
            while (v >= R[s].start[r + 1]) r++;
            if (s == 0) rowring[k] = r;
            else if (r != rowring[k]) {
                cm_seterr("row %d: vertex %d of shape %d is on ring %d, but the row's vertex of shape 0 on "
                          "ring %d", k + 1, v, s, r + 1, rowring[k] + 1);
                goto out;
            }
        }
    /* interior points: one piece, the same in every shape */
    for (int i = 0; i < npts; i++)
        for (int s = 0; s < N; s++) {
            const double *q = pts + 2 * ((size_t)i * N + s);
            for (int r = 0; r < nr; r++)
                for (int j = 0; j < rings_count(&R[s], r); j++) {
                    const double *a = rings_ring(&R[s], r) + 2 * j;
                    const double *b = rings_ring(&R[s], r) + 2 * ((j + 1) % rings_count(&R[s], r));
                    if (on_seg(a, b, q)) {
                        cm_seterr("row %d: point (%.17g, %.17g) of shape %d lies on its outline (ring %d)", i + 1,
                                  q[0], q[1], s, r + 1);
                        goto out;
                    }
                }
            int r = innermost(&R[s], -1, q);
            if (r < 0 || compat_is_hole(parent, r)) {
                cm_seterr("row %d: point (%.17g, %.17g) of shape %d lies outside its outline%s", i + 1, q[0], q[1],
                          s, r < 0 ? "" : " (in a hole)");
                goto out;
            }
            if (s == 0) ptring[i] = r;
            else if (r != ptring[i]) {
                cm_seterr("row %d: point of shape %d lies in ring %d, but in shape 0 in ring %d", i + 1, s, r + 1,
                          ptring[i] + 1);
                goto out;
            }
            for (int j = 0; j < i; j++) {
                const double *p = pts + 2 * ((size_t)j * N + s);
                if (p[0] == q[0] && p[1] == q[1]) {
                    cm_seterr("row %d: point of shape %d is the same as row %d's", i + 1, s, j + 1);
                    goto out;
                }
            }
        }
    /* match every ring on its own */
    for (int r = 0; r < nr; r++) {
        /* holes are matched and simplified counter-clockwise (reversed
         * copies), and turned back when stacked */
        int k = 0, hole = compat_is_hole(parent, r);
        for (int row = 0; row < ncorr; row++) {
            if (rowring[row] != r) continue;
            for (int s = 0; s < N; s++) {
                int v = corr[(size_t)row * N + s] - R[s].start[r], n = rings_count(&R[s], r);
                cc[(size_t)k * N + s] = flipped[(size_t)s * nr + r] != hole ? n - 1 - v : v;
            }
            k++;
        }
        if (k == 0) {
            for (int s = 0; s < N; s++) cc[s] = 0;
            k = 1;
            nfirst++;
        }
        for (int s = 0; s < N; s++) {
            nn[s] = rings_count(&R[s], r);
            if (!(P[s] = compat_ring_ccw(&R[s], r, hole))) {
                for (int q = 0; q < s; q++) free(P[q]);
                cm_seterr("out of memory");
                goto out;
            }
        }
        int rm = compat_corr_order(N, nn, cc, k) < 0 || compat_match(N, P, nn, cc, k, &cr[r], &keep[r]) < 0;
        for (int s = 0; s < N; s++) free(P[s]);
        if (rm) {
            cm_seterr("ring %d: %s", r + 1, cm_errmsg());
            goto out;
        }
    }
    /* simplify, halving the tolerance while rings touch or points fall out */
    double e = err;
    for (int attempt = 0;; attempt++) {
        for (int r = 0; r < nr; r++) {
            double f = INFINITY;
            for (int s = 0; s < N; s++) f = fmin(f, dpose[s] / polygon_diagonal(cr[r].B[s], cr[r].nm));
            cr[r].nb = cr[r].nv = cr[r].nm;
            for (int s = 0; s < N; s++) memcpy(cr[r].X[s], cr[r].B[s], 2 * (size_t)cr[r].nm * sizeof(double));
            if (e > 0) compat_simplify(&cr[r], e * f, keep[r]);
        }
        int ok = 1;
        for (int s = 0; s < N && ok; s++) ok = layout_ok(cr, nr, parent, s, pts, npts, N, ptring);
        if (ok) break;
        if (e == 0) {
            cm_seterr("the matched rings touch each other (internal error)");
            goto out;
        }
        e = attempt < 10 ? 0.5 * e : 0;
    }
    /* stack */
    int total = npts;
    for (int r = 0; r < nr; r++) total += cr[r].nb;
    c->N = N;
    c->X = calloc(N, sizeof *c->X);
    c->B = calloc(N, sizeof *c->B);
    c->ring_start = malloc((nr + 1) * sizeof *c->ring_start);
    c->ring_parent = malloc(nr * sizeof *c->ring_parent);
    c->pt_ring = malloc((npts + 1) * sizeof *c->pt_ring);
    int cap = 64;
    while (cap < total) cap *= 2;
    for (int s = 0; s < N; s++) c->X[s] = malloc(2 * (size_t)cap * sizeof(double));
    c->cap = cap;
    c->nrings = nr;
    c->npts = npts;
    int v = 0;
    double hmax = 0;
    int hs = 0;
    for (int r = 0; r < nr; r++) {
        c->ring_start[r] = v;
        c->ring_parent[r] = parent[r];
        int hole = compat_is_hole(parent, r), m = cr[r].nb;
        for (int s = 0; s < N; s++) {
            for (int i = 0; i < m; i++) {
                int j = hole ? m - 1 - i : i;
                c->X[s][2 * (v + i)] = cr[r].X[s][2 * j];
                c->X[s][2 * (v + i) + 1] = cr[r].X[s][2 * j + 1];
            }
            double h = compat_outline_error(&cr[r], s, rings_ring(&R[s], r), rings_count(&R[s], r)) *
                       polygon_diagonal(rings_ring(&R[s], r), rings_count(&R[s], r)) / dpose[s];
            if (h > hmax) { hmax = h; hs = s; }
        }
        v += cr[r].nb;
    }
    c->ring_start[nr] = v;
    for (int i = 0; i < npts; i++) {
        c->pt_ring[i] = ptring[i];
        for (int s = 0; s < N; s++) {
            c->X[s][2 * v] = pts[2 * ((size_t)i * N + s)];
            c->X[s][2 * v + 1] = pts[2 * ((size_t)i * N + s) + 1];
        }
        v++;
    }
    c->nv = c->nb = c->nm = v;
    if (stats) { stats[0] = e; stats[1] = hmax; stats[2] = hs; stats[3] = nfirst; }
    rc = 0;
out:
    for (int r = 0; r < nr; r++) { compat_free(&cr[r]); free(keep[r]); }
    free(cr); free(keep); free(cc); free(nn); free(P); free(dpose); free(rowring); free(ptring);
    return rc;
}

int compat_boundary_next(const struct compat *c, int i)
{
    if (i < 0 || i >= c->nb) return -1;
    if (c->nrings <= 0) return (i + 1) % c->nb;
    if (i >= c->ring_start[c->nrings]) return -1;
    int r = 0;
    while (i >= c->ring_start[r + 1]) r++;
    return i + 1 < c->ring_start[r + 1] ? i + 1 : c->ring_start[r];
}

/* ------------------------------------------------------------------ */
/* cuts */

struct cyc {
    int *v;           /* vertex ids */
    int m;
    int label;        /* ring index (>= 0) or -1 - point index */
};

struct region {
    struct cyc outer;
    int nh;
    struct cyc *holes;
};

/* direction to q strictly inside the domain's angle at corner i of cycle y
 * (the domain is on the left of every cycle); a one-vertex cycle (a point)
 * sees every direction */
static int incone(const double *X, const struct cyc *y, int i, const double *q)
{
    if (y->m == 1) return 1;
    const double *a = X + 2 * y->v[i], *pr = X + 2 * y->v[(i + y->m - 1) % y->m],
                 *nx = X + 2 * y->v[(i + 1) % y->m];
    int o1 = orient2_sign(a, nx, q), o2 = orient2_sign(pr, a, q);
    if (orient2_sign(pr, a, nx) > 0) return o1 > 0 && o2 > 0;
    return o1 > 0 || o2 > 0;
}

static double ccw_angle(double ux, double uy, double vx, double vy)
{
    double a = atan2(ux * vy - uy * vx, ux * vx + uy * vy);
    return a < 0 ? a + 2 * M_PI : a;
}

/* smallest angle the direction to q makes with the edges at corner i */
static double cone_q(const double *X, const struct cyc *y, int i, const double *q)
{
    if (y->m == 1) return M_PI;
    const double *a = X + 2 * y->v[i], *pr = X + 2 * y->v[(i + y->m - 1) % y->m],
                 *nx = X + 2 * y->v[(i + 1) % y->m];
    return fmin(ccw_angle(nx[0] - a[0], nx[1] - a[1], q[0] - a[0], q[1] - a[1]),
                ccw_angle(q[0] - a[0], q[1] - a[1], pr[0] - a[0], pr[1] - a[1]));
}

/* does the segment AB stay off the region's rings: it meets no ring edge
 * and no interior point except at ring vertices ua, ub (-1: none; AB's
 * ends where they are ring vertices) (exact) */
static int seg_clear(const double *X, const struct region *g, const double *A, const double *B, int ua, int ub)
{
    for (int y = -1; y < g->nh; y++) {
        const struct cyc *C = y < 0 ? &g->outer : &g->holes[y];
        if (C->m == 1) {
            if (C->v[0] != ua && C->v[0] != ub && on_seg(A, B, X + 2 * C->v[0])) return 0;
            continue;
        }
        for (int e = 0; e < C->m; e++) {
            int a = C->v[e], b = C->v[(e + 1) % C->m];
            if (a == ua || b == ua || a == ub || b == ub) continue;
            if (segments_meet(A, B, X + 2 * a, X + 2 * b)) return 0;
        }
    }
    return 1;
}

/* is the segment from hole corner (h, i) to outer corner j inside the
 * region's domain in shape X (exact) */
static int cut_inside(const double *X, const struct region *g, int h, int i, int j)
{
    const struct cyc *H = &g->holes[h], *O = &g->outer;
    int u = H->v[i], w = O->v[j];
    const double *U = X + 2 * u, *W = X + 2 * w;
    return incone(X, H, i, W) && incone(X, O, j, U) && seg_clear(X, g, U, W, u, w);
}

struct cand { int i, j; double score; };

static int cmp_cand(const void *a, const void *b)
{
    double x = ((const struct cand *)a)->score, y = ((const struct cand *)b)->score;
    return (x < y) - (x > y);
}

/* vertices of cycle y from position i forward to position j (inclusive) */
static int walk(const struct cyc *y, int i, int j, int *out)
{
    int n = 0;
    for (int k = i;; k = (k + 1) % y->m) {
        out[n++] = y->v[k];
        if (k == j) break;
    }
    return n;
}

static void region_free(struct region *g)
{
    free(g->outer.v);
    for (int h = 0; h < g->nh; h++) free(g->holes[h].v);
    free(g->holes);
}

static int solve(struct compat *c, struct region *g, int depth);

/* ------------------------------------------------------------------ */
/* bent cuts */

/* A cut from hole vertex H->v[i] to outer vertex O->v[j] through k new
 * vertices (0: straight) at P (N by k by 2: P[2 * (s * k + t)] is point t
 * of shape s, from the hole's end) */
struct bcut { int i, j, k; double score; double *P; };

/* exact point in polygon of explicit points (q not on it) */
static int inside_pts(const double *P, int m, const double *q)
{
    int in = 0;
    for (int i = 0; i < m; i++) {
        const double *a = P + 2 * i, *b = P + 2 * ((i + 1) % m);
        if (a[1] <= q[1] && q[1] < b[1]) { if (orient2_sign(a, b, q) > 0) in ^= 1; }
        else if (b[1] <= q[1] && q[1] < a[1]) { if (orient2_sign(a, b, q) < 0) in ^= 1; }
    }
    return in;
}

/* The region's ring vertices (outer cycle and holes of 2 or more
 * vertices) as the nodes of a visibility graph: node k is position ix[k]
 * of cycle cy[k] (-1: the outer cycle, else a hole) */
struct vgraph {
    const struct region *g;
    int n, *cy, *ix;
    int *hnode;   /* node of position 0 of hole h (-1: a point) */
};

static const struct cyc *vg_cyc(const struct vgraph *G, int k)
{
    return G->cy[k] < 0 ? &G->g->outer : &G->g->holes[G->cy[k]];
}

static const double *vg_pt(const double *X, const struct vgraph *G, int k)
{
    return X + 2 * vg_cyc(G, k)->v[G->ix[k]];
}

/* are nodes a and b joined by a segment inside the domain of shape X (vis:
 * n by n cache, -1 unknown) */
static int vg_sees(const double *X, const struct vgraph *G, signed char *vis, int a, int b)
{
    signed char *v = vis + (size_t)a * G->n + b;
    if (*v < 0) {
        const struct cyc *Ca = vg_cyc(G, a), *Cb = vg_cyc(G, b);
        const double *A = vg_pt(X, G, a), *B = vg_pt(X, G, b);
        int ok = a != b && incone(X, Ca, G->ix[a], B) && incone(X, Cb, G->ix[b], A) &&
                 seg_clear(X, G->g, A, B, Ca->v[G->ix[a]], Cb->v[G->ix[b]]);
        *v = vis[(size_t)b * G->n + a] = (signed char)ok;
    }
    return *v;
}

/* shortest paths inside the domain of shape X from node src to every node
 * (Dijkstra on the visibility graph): dist (INFINITY: none), prev */
static void vg_paths(const double *X, const struct vgraph *G, signed char *vis, int src, double *dist, int *prev,
                     unsigned char *done)
{
    int n = G->n;
    for (int k = 0; k < n; k++) { dist[k] = INFINITY; prev[k] = -1; done[k] = 0; }
    dist[src] = 0;
    for (;;) {
        int a = -1;
        for (int k = 0; k < n; k++)
            if (!done[k] && dist[k] < INFINITY && (a < 0 || dist[k] < dist[a])) a = k;
        if (a < 0) break;
        done[a] = 1;
        const double *A = vg_pt(X, G, a);
        for (int b = 0; b < n; b++) {
            if (done[b]) continue;
            const double *B = vg_pt(X, G, b);
            double d = dist[a] + hypot(B[0] - A[0], B[1] - A[1]);
            if (d < dist[b] && vg_sees(X, G, vis, a, b)) { dist[b] = d; prev[b] = a; }
        }
    }
}

/* the bends of path (np nodes, hole end first) in shape X moved off the
 * rings into the domain along each corner's bisector, as far as the
 * segments stay inside (a share of the shorter edge there); the np - 2
 * points in out.  0, or 1 if no share fits. */
static int vg_bends(const double *X, const struct vgraph *G, const int *path, int np, double *out)
{
    static const double share[] = {0.9, 0.6, 0.3, 0.1, 0.03, 0.01, 0.001};
    int nb = np - 2;
    if (nb == 0) return 0;
    const struct cyc *Cu = vg_cyc(G, path[0]), *Cw = vg_cyc(G, path[np - 1]);
    int u = Cu->v[G->ix[path[0]]], w = Cw->v[G->ix[path[np - 1]]];
    const double *U = X + 2 * u, *W = X + 2 * w;
    for (size_t f = 0; f < sizeof share / sizeof *share; f++) {
        for (int t = 1; t <= nb; t++) {
            const struct cyc *C = vg_cyc(G, path[t]);
            int i = G->ix[path[t]];
            const double *a = X + 2 * C->v[i], *pr = X + 2 * C->v[(i + C->m - 1) % C->m],
                         *nx = X + 2 * C->v[(i + 1) % C->m];
            double d1x = a[0] - pr[0], d1y = a[1] - pr[1], d2x = nx[0] - a[0], d2y = nx[1] - a[1];
            double l1 = hypot(d1x, d1y), l2 = hypot(d2x, d2y);
            d1x /= l1; d1y /= l1; d2x /= l2; d2y /= l2;
            /* the domain is on the left of every cycle */
            double bx = -d1y - d2y, by = d1x + d2x, lb = hypot(bx, by);
            if (lb < 1e-9) {   /* a hairpin: straight on at a notch, back at a spike */
                int reflex = orient2_sign(pr, a, nx) <= 0;
                bx = reflex ? d1x : -d1x; by = reflex ? d1y : -d1y; lb = 1;
            }
            const double *q = vg_pt(X, G, path[t - 1]), *r = vg_pt(X, G, path[t + 1]);
            double len = fmin(fmin(l1, l2), fmin(hypot(q[0] - a[0], q[1] - a[1]), hypot(r[0] - a[0], r[1] - a[1])));
            out[2 * (t - 1)] = a[0] + share[f] * len * bx / lb;
            out[2 * (t - 1) + 1] = a[1] + share[f] * len * by / lb;
        }
        /* every segment inside, the path simple */
        int ok = incone(X, Cu, G->ix[path[0]], out) && incone(X, Cw, G->ix[path[np - 1]], out + 2 * (nb - 1));
        for (int t = 0; t <= nb && ok; t++) {
            const double *A = t ? out + 2 * (t - 1) : U, *B = t < nb ? out + 2 * t : W;
            ok = seg_clear(X, G->g, A, B, t ? -1 : u, t < nb ? -1 : w);
            for (int e = 0; e + 1 < t && ok; e++)
                ok = !segments_meet(e ? out + 2 * (e - 1) : U, out + 2 * e, A, B);
        }
        if (ok) return 0;
    }
    return 1;
}

/* the points of cut (k of them) in shape s, ends included, into out
 * (k + 2 points) */
static void cut_points(const struct compat *c, const struct region *g, int h, const struct bcut *cu, int s, double *out)
{
    const double *X = c->X[s];
    memcpy(out, X + 2 * g->holes[h].v[cu->i], 2 * sizeof *out);
    memcpy(out + 2, cu->P + 2 * (size_t)s * cu->k, 2 * (size_t)cu->k * sizeof *out);
    memcpy(out + 2 * (cu->k + 1), X + 2 * g->outer.v[cu->j], 2 * sizeof *out);
}

/* do the cuts a and b (each k + 2 points, from the hole) keep apart; from
 * the same point (a hole of one vertex) they meet only there */
static int cuts_apart(const double *a, int ka, const double *b, int kb, int point)
{
    for (int x = 0; x <= ka; x++)
        for (int y = 0; y <= kb; y++) {
            if (point && x == 0 && y == 0) {
                if (orient2_sign(a + 2, a, b + 2) == 0) return 0;
                continue;
            }
            if (segments_meet(a + 2 * x, a + 2 * x + 2, b + 2 * y, b + 2 * y + 2)) return 0;
        }
    return 1;
}

static int cmp_bcut(const void *a, const void *b)
{
    double x = ((const struct bcut *)a)->score, y = ((const struct bcut *)b)->score;
    return (x < y) - (x > y);
}

/* Two cuts that may bend for hole h of region g (no two straight ones fit;
 * dg: the shapes' diagonals): the shortest paths inside every shape
 * between hole and outer vertices, the pairs tried as cut_hole tries
 * straight ones.  0 with c1, c2 (P malloc'd) and side (every other hole's
 * side, as cut_hole), 1 if none. */
#define BENT_MAX 12      /* bends a cut may have */
#define BENT_TRY 400     /* cuts realised, shortest first */
#define BENT_KEEP 48     /* of them kept for the pairs */
static int bent_cuts(const struct compat *c, const struct region *g, int h, const double *dg, struct bcut *c1,
                     struct bcut *c2, unsigned char *side)
{
    int N = c->N, rc = 1;
    const struct cyc *H = &g->holes[h], *O = &g->outer;
    int mh = H->m, mo = O->m;
    struct vgraph G = {g, 0, NULL, NULL, NULL};
    /* the nodes; a point (a hole of one vertex) cut off is a node of its
     * own, last, where its paths start */
    int pt = mh == 1, n = mo + pt;
    for (int y = 0; y < g->nh; y++) n += g->holes[y].m > 1 ? g->holes[y].m : 0;
    G.cy = malloc(n * sizeof *G.cy);
    G.ix = malloc(n * sizeof *G.ix);
    G.hnode = malloc((g->nh + 1) * sizeof *G.hnode);
    for (int i = 0; i < mo; i++) { G.cy[G.n] = -1; G.ix[G.n++] = i; }
    for (int y = 0; y < g->nh; y++) {
        G.hnode[y] = -1;
        if (g->holes[y].m < 2) continue;
        G.hnode[y] = G.n;
        for (int i = 0; i < g->holes[y].m; i++) { G.cy[G.n] = y; G.ix[G.n++] = i; }
    }
    if (pt) { G.hnode[h] = G.n; G.cy[G.n] = h; G.ix[G.n++] = 0; }
    int src0 = G.hnode[h];
    double *dist = malloc((size_t)N * mh * n * sizeof *dist);
    int *prev = malloc((size_t)N * mh * n * sizeof *prev);
    unsigned char *done = malloc(n);
    struct bcut *cd = calloc((size_t)mh * mo, sizeof *cd);
    int ncd = 0;
    signed char *vis = malloc((size_t)n * n);
    if (!G.cy || !G.ix || !G.hnode || !dist || !prev || !done || !cd || !vis) {
        free(vis); free(dist); free(prev); free(done); free(cd); free(G.cy); free(G.ix); free(G.hnode);
        return cm_seterr("out of memory (bent cuts of a hole of %d vertices in a piece of %d ring vertices)", mh, n);
    }
    for (int s = 0; s < N; s++) {
        memset(vis, -1, (size_t)n * n);
        for (int i = 0; i < mh; i++)
            vg_paths(c->X[s], &G, vis, src0 + i, dist + ((size_t)s * mh + i) * n, prev + ((size_t)s * mh + i) * n, done);
    }
    /* every pair with a path in every shape, shortest (over the shapes) first */
    for (int i = 0; i < mh; i++)
        for (int j = 0; j < mo; j++) {
            double len = 0;
            for (int s = 0; s < N && len < INFINITY; s++) len = fmax(len, dist[((size_t)s * mh + i) * n + j] / dg[s]);
            if (len < INFINITY) { cd[ncd].i = i; cd[ncd].j = j; cd[ncd].score = -len; ncd++; }
        }
    qsort(cd, ncd, sizeof *cd, cmp_bcut);
    int *path = malloc((n + 2) * sizeof *path);
    double *bend = malloc(2 * (size_t)N * (BENT_MAX + 1) * sizeof *bend);
    int *nbend = malloc(N * sizeof *nbend), nk = 0;
    for (int x = 0; x < ncd && x < BENT_TRY && nk < BENT_KEEP; x++) {
        int i = cd[x].i, j = cd[x].j, k = 0, ok = 1;
        for (int s = 0; s < N && ok; s++) {
            const int *pv = prev + ((size_t)s * mh + i) * n;
            int np = 0;
            for (int v = j; v >= 0 && np <= BENT_MAX + 2; v = pv[v]) path[np++] = v;
            if (np > BENT_MAX + 2) { ok = 0; break; }
            for (int a = 0, b = np - 1; a < b; a++, b--) { int t = path[a]; path[a] = path[b]; path[b] = t; }
            ok = vg_bends(c->X[s], &G, path, np, bend + 2 * (size_t)s * BENT_MAX) == 0;
            nbend[s] = np - 2;
            if (nbend[s] > k) k = nbend[s];
        }
        if (!ok) continue;
        struct bcut *cu = &cd[nk];
        double sc = -cd[x].score;
        cu->i = i; cu->j = j; cu->k = k;
        cu->P = malloc(2 * (size_t)N * (k ? k : 1) * sizeof *cu->P);
        double q = M_PI;
        for (int s = 0; s < N; s++) {
            /* as many points in every shape: a shape whose path bends less
             * gets the others at the middle of its longest segments */
            double *Q = cu->P + 2 * (size_t)s * k, *B = bend + 2 * (size_t)s * BENT_MAX;
            const double *U = c->X[s] + 2 * H->v[i], *W = c->X[s] + 2 * O->v[j];
            int m = nbend[s];
            memcpy(Q, B, 2 * (size_t)m * sizeof *Q);
            while (m < k) {
                int best = 0;
                double bl = -1;
                for (int t = 0; t <= m; t++) {
                    const double *A = t ? Q + 2 * (t - 1) : U, *E = t < m ? Q + 2 * t : W;
                    double l = hypot(E[0] - A[0], E[1] - A[1]);
                    if (l > bl) { bl = l; best = t; }
                }
                const double *A = best ? Q + 2 * (best - 1) : U, *E = best < m ? Q + 2 * best : W;
                double mid[2] = {0.5 * (A[0] + E[0]), 0.5 * (A[1] + E[1])};
                memmove(Q + 2 * (best + 1), Q + 2 * best, 2 * (size_t)(m - best) * sizeof *Q);
                memcpy(Q + 2 * best, mid, sizeof mid);
                m++;
            }
            q = fmin(q, fmin(cone_q(c->X[s], H, i, k ? Q : W), cone_q(c->X[s], O, j, k ? Q + 2 * (k - 1) : U)));
        }
        cu->score = fmin(q, M_PI / 4) - 0.5 * sc - 0.05 * k;
        nk++;
    }
    for (int x = nk; x < ncd; x++) cd[x].P = NULL;
    qsort(cd, nk, sizeof *cd, cmp_bcut);
    /* the pair: as cut_hole's */
    double *pa = malloc(2 * (size_t)(BENT_MAX + 2) * sizeof *pa), *pb = malloc(2 * (size_t)(BENT_MAX + 2) * sizeof *pb);
    double *poly = malloc(2 * ((size_t)mh + mo + 2 * BENT_MAX + 4) * sizeof *poly);
    unsigned char *sd = malloc(g->nh + 1);
    int b1 = -1, b2 = -1;
    double best = -INFINITY;
    for (int x = 0; x < nk; x++) {
        for (int y = 0; y < nk; y++) {
            const struct bcut *u1 = &cd[x], *u2 = &cd[y];
            if (u2->j == u1->j || (mh > 1 && u2->i == u1->i)) continue;
            int fo = ((u2->j - u1->j) % mo + mo) % mo;
            double bal = 2 * fmin((double)fo / mo, 1 - (double)fo / mo);
            if (mh > 1) {
                double fh = (double)(((u1->i - u2->i) % mh + mh) % mh) / mh;
                bal = 0.5 * bal + fmin(fh, 1 - fh);
            }
            double sc = u1->score + u2->score + 0.3 * bal;
            if (sc <= best) continue;
            int ok = 1;
            for (int s = 0; s < N && ok; s++) {
                cut_points(c, g, h, u1, s, pa);
                cut_points(c, g, h, u2, s, pb);
                if (!(ok = cuts_apart(pa, u1->k, pb, u2->k, pt))) break;
                /* piece A: outer j1 -> j2, cut 2 back to the hole, hole
                 * i2 -> i1, cut 1 out; every other hole on one side */
                int m = 0;
                for (int t = u1->j;; t = (t + 1) % mo) {
                    memcpy(poly + 2 * m++, c->X[s] + 2 * O->v[t], 2 * sizeof *poly);
                    if (t == u2->j) break;
                }
                for (int t = u2->k; t >= 1; t--) memcpy(poly + 2 * m++, pb + 2 * t, 2 * sizeof *poly);
                for (int t = u2->i;; t = (t + 1) % mh) {
                    memcpy(poly + 2 * m++, c->X[s] + 2 * H->v[t], 2 * sizeof *poly);
                    if (t == u1->i) break;
                }
                for (int t = 1; t <= u1->k; t++) memcpy(poly + 2 * m++, pa + 2 * t, 2 * sizeof *poly);
                for (int q = 0; q < g->nh && ok; q++) {
                    if (q == h) continue;
                    int in = inside_pts(poly, m, c->X[s] + 2 * g->holes[q].v[0]);
                    if (s == 0) sd[q] = (unsigned char)in;
                    else if (in != sd[q]) ok = 0;
                }
            }
            if (!ok) continue;
            best = sc; b1 = x; b2 = y;
            memcpy(side, sd, g->nh + 1);
        }
        if (b1 >= 0 && x >= 3) break;
    }
    if (b1 >= 0) {
        *c1 = cd[b1]; *c2 = cd[b2];
        cd[b1].P = cd[b2].P = NULL;
        rc = 0;
    }
    for (int x = 0; x < nk; x++) free(cd[x].P);
    free(cd); free(path); free(bend); free(nbend); free(pa); free(pb); free(poly); free(sd);
    free(vis); free(dist); free(prev); free(done); free(G.cy); free(G.ix); free(G.hnode);
    return rc;
}

/* region g cut by c1 and c2 (from hole h; their points become new
 * vertices), both pieces solved; side: every other hole's piece (1: the
 * one from c1's outer end to c2's) */
static int split_region(struct compat *c, const struct region *g, int h, const struct bcut *c1, const struct bcut *c2,
                        const unsigned char *side, int depth)
{
    const struct cyc *H = &g->holes[h], *O = &g->outer;
    int mh = H->m, mo = O->m, v1 = c->nv, v2 = c->nv + c1->k;
    if (c1->k + c2->k) {
        if (compat_reserve_vertices(c, c->nv + c1->k + c2->k) < 0) return -1;
        c->nsteiner += c1->k + c2->k;
        c->nbent += (c1->k > 0) + (c2->k > 0);
        c->nbend += c1->k + c2->k;
        for (int s = 0; s < c->N; s++) {
            memcpy(c->X[s] + 2 * v1, c1->P + 2 * (size_t)s * c1->k, 2 * (size_t)c1->k * sizeof(double));
            memcpy(c->X[s] + 2 * v2, c2->P + 2 * (size_t)s * c2->k, 2 * (size_t)c2->k * sizeof(double));
        }
        c->nv += c1->k + c2->k;
    }
    struct region ga = {0}, gb = {0};
    int cap = mh + mo + 2 + c1->k + c2->k;
    ga.outer.v = malloc(cap * sizeof(int));
    gb.outer.v = malloc(cap * sizeof(int));
    /* A: outer j1 -> j2, cut 2 inwards, hole i2 -> i1, cut 1 outwards */
    ga.outer.m = walk(O, c1->j, c2->j, ga.outer.v);
    for (int t = c2->k - 1; t >= 0; t--) ga.outer.v[ga.outer.m++] = v2 + t;
    ga.outer.m += walk(H, c2->i, c1->i, ga.outer.v + ga.outer.m);
    for (int t = 0; t < c1->k; t++) ga.outer.v[ga.outer.m++] = v1 + t;
    /* B: outer j2 -> j1, cut 1 inwards, hole i1 -> i2, cut 2 outwards */
    gb.outer.m = walk(O, c2->j, c1->j, gb.outer.v);
    for (int t = c1->k - 1; t >= 0; t--) gb.outer.v[gb.outer.m++] = v1 + t;
    gb.outer.m += walk(H, c1->i, c2->i, gb.outer.v + gb.outer.m);
    for (int t = 0; t < c2->k; t++) gb.outer.v[gb.outer.m++] = v2 + t;
    ga.holes = malloc((g->nh + 1) * sizeof *ga.holes);
    gb.holes = malloc((g->nh + 1) * sizeof *gb.holes);
    for (int k = 0; k < g->nh; k++) {
        if (k == h) continue;
        struct region *t = side[k] ? &ga : &gb;
        t->holes[t->nh] = g->holes[k];
        t->holes[t->nh].v = malloc(g->holes[k].m * sizeof(int));
        memcpy(t->holes[t->nh].v, g->holes[k].v, g->holes[k].m * sizeof(int));
        t->nh++;
    }
    int rc = solve(c, &ga, depth + 1);
    if (rc == 0) rc = solve(c, &gb, depth + 1);
    region_free(&ga); region_free(&gb);
    return rc;
}

/* cut hole h off region g by the best pair of straight cuts (bent: of
 * cuts that may bend, bent_cuts); 1 if none exists */
static int cut_hole(struct compat *c, struct region *g, int h, int depth, int bent)
{
    int N = c->N;
    const struct cyc *H = &g->holes[h], *O = &g->outer;
    int mh = H->m, mo = O->m;
    double *dg = malloc(N * sizeof *dg);
    for (int s = 0; s < N; s++) dg[s] = polygon_diagonal(c->X[s], c->nb);
    struct cand *cd = malloc((size_t)mh * mo * sizeof *cd);
    int nc = 0;
    for (int i = 0; i < mh && !bent; i++)
        for (int j = 0; j < mo; j++) {
            double q = M_PI, len = 0;
            int ok = 1;
            for (int s = 0; s < N && ok; s++) {
                const double *X = c->X[s], *U = X + 2 * H->v[i], *W = X + 2 * O->v[j];
                if (!cut_inside(X, g, h, i, j)) { ok = 0; break; }
                q = fmin(q, fmin(cone_q(X, H, i, W), cone_q(X, O, j, U)));
                len = fmax(len, hypot(W[0] - U[0], W[1] - U[1]) / dg[s]);
            }
            if (ok) { cd[nc].i = i; cd[nc].j = j; cd[nc].score = fmin(q, M_PI / 4) - 0.5 * len; nc++; }
        }
    qsort(cd, nc, sizeof *cd, cmp_cand);
    int b1 = -1, b2 = -1;
    double best = -INFINITY;
    unsigned char *side = malloc(g->nh + 1), *bside = malloc(g->nh + 1);
    int *A = malloc((mh + mo + 2) * sizeof *A);
    struct bcut c1b = {0}, c2b = {0};
    for (int x = 0; x < nc && x < 24; x++) {
        int i1 = cd[x].i, j1 = cd[x].j;
        for (int y = 0; y < nc; y++) {
            int i2 = cd[y].i, j2 = cd[y].j;
            if (j2 == j1 || (mh > 1 && i2 == i1)) continue;
            double fo = (double)(((j2 - j1) % mo + mo) % mo) / mo, bal = 2 * fmin(fo, 1 - fo);
            if (mh > 1) {
                double fh = (double)(((i1 - i2) % mh + mh) % mh) / mh;
                bal = 0.5 * bal + fmin(fh, 1 - fh);
            }
            double sc = cd[x].score + cd[y].score + 0.3 * bal;
            if (sc <= best) continue;
            /* the cuts stay apart (a point's two cuts meet only there) */
            int ok = 1;
            for (int s = 0; s < N && ok; s++) {
                const double *X = c->X[s];
                const double *U1 = X + 2 * H->v[i1], *W1 = X + 2 * O->v[j1];
                const double *U2 = X + 2 * H->v[i2], *W2 = X + 2 * O->v[j2];
                if (mh == 1) ok = orient2_sign(W1, U1, W2) != 0;
                else ok = !segments_meet(U1, W1, U2, W2);
            }
            if (!ok) continue;
            /* piece A: outer j1 -> j2, hole i2 -> i1; every other hole on the
             * same side in every shape */
            int na = walk(O, j1, j2, A);
            na += walk(H, i2, i1, A + na);
            for (int s = 0; s < N && ok; s++)
                for (int k = 0; k < g->nh && ok; k++) {
                    if (k == h) continue;
                    int in = inside_cycle(c->X[s], A, na, c->X[s] + 2 * g->holes[k].v[0]);
                    if (s == 0) side[k] = in;
                    else if (in != side[k]) ok = 0;
                }
            if (!ok) continue;
            best = sc; b1 = x; b2 = y;
            memcpy(bside, side, g->nh + 1);
        }
        if (b1 >= 0 && x >= 3) break;
    }
    int rc = 1;
    if (b1 >= 0) {
        struct bcut c1 = {cd[b1].i, cd[b1].j, 0, 0, NULL}, c2 = {cd[b2].i, cd[b2].j, 0, 0, NULL};
        rc = split_region(c, g, h, &c1, &c2, bside, depth);
    } else if (bent) {
        rc = bent_cuts(c, g, h, dg, &c1b, &c2b, bside);
        if (rc == 0) rc = split_region(c, g, h, &c1b, &c2b, bside, depth);
        free(c1b.P); free(c2b.P);
    }
    free(cd); free(dg); free(side); free(bside); free(A);
    return rc;
}

static int solve(struct compat *c, struct region *g, int depth)
{
    if (g->nh == 0) {
        if (g->outer.m < 3) return cm_seterr("internal: degenerate piece after cutting holes");
        return compat_triangulate_poly(c, g->outer.v, g->outer.m);
    }
    if (depth > 10000) return cm_seterr("internal: too many cuts");
    /* rings first (largest first), then points */
    int *order = malloc(g->nh * sizeof *order);
    for (int k = 0; k < g->nh; k++) order[k] = k;
    for (int a = 1; a < g->nh; a++)
        for (int b = a; b > 0 && g->holes[order[b]].m > g->holes[order[b - 1]].m; b--) {
            int t = order[b]; order[b] = order[b - 1]; order[b - 1] = t;
        }
    int rc = 1;
    /* straight cuts for any hole first; cuts that bend only where no hole
     * has two straight ones */
    for (int k = 0; k < g->nh && rc == 1; k++) rc = cut_hole(c, g, order[k], depth, 0);
    for (int k = 0; k < g->nh && rc == 1; k++) rc = cut_hole(c, g, order[k], depth, 1);
    if (rc == 1) {
        int l = g->holes[order[0]].label;
        if (l >= 0)
            cm_seterr("compatible triangulation failed: hole ring %d: no two cuts to its outline, straight or "
                      "bent, lie inside the shape in every pose with the other holes on the same side", l + 1);
        else
            cm_seterr("compatible triangulation failed: interior point %d: no two cuts to the outline, straight "
                      "or bent, lie inside the shape in every pose with the other holes on the same side", -l);
        rc = -1;
    }
    free(order);
    return rc;
}

int compat_multi_triangulate(struct compat *c)
{
    c->nf = 0;
    int nr = c->nrings;
    for (int r = 0; r < nr; r++) {
        if (c->ring_parent[r] >= 0 && compat_is_hole(c->ring_parent, r)) continue;
        struct region g = {0};
        g.outer.m = c->ring_start[r + 1] - c->ring_start[r];
        g.outer.v = malloc(g.outer.m * sizeof(int));
        g.outer.label = r;
        for (int i = 0; i < g.outer.m; i++) g.outer.v[i] = c->ring_start[r] + i;
        g.holes = malloc((nr + c->npts + 1) * sizeof *g.holes);
        for (int k = 0; k < nr; k++)
            if (c->ring_parent[k] == r) {
                struct cyc *y = &g.holes[g.nh++];
                y->m = c->ring_start[k + 1] - c->ring_start[k];
                y->v = malloc(y->m * sizeof(int));
                y->label = k;
                for (int i = 0; i < y->m; i++) y->v[i] = c->ring_start[k] + i;
            }
        for (int p = 0; p < c->npts; p++)
            if (c->pt_ring[p] == r) {
                struct cyc *y = &g.holes[g.nh++];
                y->m = 1;
                y->v = malloc(sizeof(int));
                y->v[0] = c->ring_start[nr] + p;
                y->label = -1 - p;
            }
        int rc = solve(c, &g, 0);
        region_free(&g);
        if (rc < 0) return -1;
    }
    return 0;
}

/* ------------------------------------------------------------------ */
/* ring order */

/* mean vertex of ring k, relative to the shape's bounding box */
static void ring_center(const struct rings *r, int k, double out[2])
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    int np = r->start[r->nrings];
    for (int i = 0; i < np; i++)
        for (int d = 0; d < 2; d++) { lo[d] = fmin(lo[d], r->P[2 * i + d]); hi[d] = fmax(hi[d], r->P[2 * i + d]); }
    double dg = hypot(hi[0] - lo[0], hi[1] - lo[1]), sx = 0, sy = 0;
    int n = rings_count(r, k);
    const double *P = rings_ring(r, k);
    for (int i = 0; i < n; i++) { sx += P[2 * i]; sy += P[2 * i + 1]; }
    out[0] = (sx / n - lo[0]) / dg;
    out[1] = (sy / n - lo[1]) / dg;
}

struct assign {
    int k;
    const double *D;  /* k by k costs */
    int *cur, *best;
    unsigned char *used;
    double bestc;
};

static void assign_rec(struct assign *a, int i, double c)
{
    if (c >= a->bestc) return;
    if (i == a->k) { a->bestc = c; memcpy(a->best, a->cur, a->k * sizeof *a->cur); return; }
    for (int j = 0; j < a->k; j++)
        if (!a->used[j]) {
            a->used[j] = 1; a->cur[i] = j;
            assign_rec(a, i + 1, c + a->D[i * a->k + j]);
            a->used[j] = 0;
        }
}

/* match the children of ring p0 in shape 0 to those of ring ps in shape s
 * (-1: top level); perm[k0] = matched ring of shape s */
static int match_children(const int *par0, const int *pars, int nr, int p0, int ps, double (*C0)[2],
                          double (*Cs)[2], int s, int *perm)
{
    int *a = malloc(nr * sizeof *a), *b = malloc(nr * sizeof *b), na = 0, nb = 0, rc = 0;
    for (int k = 0; k < nr; k++) {
        if (par0[k] == p0) a[na++] = k;
        if (pars[k] == ps) b[nb++] = k;
    }
    if (na != nb) {
        char where[32] = "at the top level";
        if (p0 >= 0) snprintf(where, sizeof where, "inside ring %d", p0 + 1);
        rc = cm_seterr("shape %d has %d ring%s %s, but shape 0 has %d", s, nb, nb == 1 ? "" : "s", where, na);
    } else if (na > 0) {
        double *D = malloc((size_t)na * na * sizeof *D);
        for (int i = 0; i < na; i++)
            for (int j = 0; j < na; j++)
                D[i * na + j] = hypot(C0[a[i]][0] - Cs[b[j]][0], C0[a[i]][1] - Cs[b[j]][1]);
        struct assign as = {na, D, malloc(na * sizeof(int)), malloc(na * sizeof(int)), calloc(na, 1), INFINITY};
        if (na <= 8) assign_rec(&as, 0, 0);
        else   /* greedy: nearest free ring */
            for (int i = 0; i < na; i++) {
                int bj = -1;
                for (int j = 0; j < na; j++)
                    if (!as.used[j] && (bj < 0 || D[i * na + j] < D[i * na + bj])) bj = j;
                as.used[bj] = 1; as.best[i] = bj;
            }
        for (int i = 0; i < na && rc == 0; i++) {
            perm[a[i]] = b[as.best[i]];
            rc = match_children(par0, pars, nr, a[i], b[as.best[i]], C0, Cs, s, perm);
        }
        free(D); free(as.cur); free(as.best); free(as.used);
    }
    free(a); free(b);
    return rc;
}

int compat_order_rings(int N, struct rings *R, int *corr, int ncorr, int *moved, int *order)
{
    int nr = R[0].nrings;
    *moved = 0;
    for (int i = 0; order && i < N * nr; i++) order[i] = i % nr;
    for (int s = 1; s < N; s++)
        if (R[s].nrings != nr)
            return cm_seterr("shape %d has %d ring%s, but shape 0 has %d", s, R[s].nrings,
                             R[s].nrings == 1 ? "" : "s", nr);
    int *par0 = malloc(nr * sizeof *par0), *pars = malloc(nr * sizeof *pars), *perm = malloc(nr * sizeof *perm);
    double (*C0)[2] = malloc(nr * sizeof *C0), (*Cs)[2] = malloc(nr * sizeof *Cs);
    int rc = 0;
    for (int k = 0; k < nr; k++) { par0[k] = innermost(&R[0], k, rings_ring(&R[0], k)); ring_center(&R[0], k, C0[k]); }
    for (int s = 1; s < N && rc == 0; s++) {
        struct rings *r = &R[s];
        for (int k = 0; k < nr; k++) { pars[k] = innermost(r, k, rings_ring(r, k)); ring_center(r, k, Cs[k]); }
        if ((rc = match_children(par0, pars, nr, -1, -1, C0, Cs, s, perm)) < 0) break;
        int same = 1;
        for (int k = 0; k < nr; k++) same &= perm[k] == k;
        if (order) memcpy(order + (size_t)s * nr, perm, nr * sizeof *perm);
        if (same) continue;
        (*moved)++;
        /* rebuild the rings in shape 0's order; remap the indices */
        int np = r->start[nr];
        double *P = malloc(2 * (size_t)np * sizeof *P);
        long *L = malloc((size_t)np * sizeof *L);
        int *start = malloc((nr + 1) * sizeof *start), *newstart = malloc(nr * sizeof *newstart);
        int v = 0;
        for (int k = 0; k < nr; k++) {
            int o = perm[k], n = rings_count(r, o);
            start[k] = v;
            newstart[o] = v;
            memcpy(P + 2 * v, rings_ring(r, o), 2 * (size_t)n * sizeof *P);
            memcpy(L + v, r->line + r->start[o], (size_t)n * sizeof *L);
            v += n;
        }
        start[nr] = v;
        for (int k = 0; k < ncorr; k++) {
            int g = corr[(size_t)k * N + s], o = 0;
            if (g < 0 || g >= np) continue;   /* compat_multi names it */
            while (g >= r->start[o + 1]) o++;
            corr[(size_t)k * N + s] = newstart[o] + g - r->start[o];
        }
        free(r->P); free(r->line); free(r->start);
        r->P = P; r->line = L; r->start = start;
        free(newstart);
    }
    free(par0); free(pars); free(perm); free(C0); free(Cs);
    return rc;
}
