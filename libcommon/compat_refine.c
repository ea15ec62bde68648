/* compat_refine.c -- see compat_refine.h */
#include "compat_refine.h"
#include "cm_error.h"
#include "predicates2.h"
#include "topology.h"
#include "arap_deform2d.h"
#include "rings.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* ------------------------------------------------------------------ */
/* per-triangle measures */

/* angle at corner o of the triangle (o, u, v) */
static double corner_angle(const double *o, const double *u, const double *v)
{
    double ux = u[0] - o[0], uy = u[1] - o[1], vx = v[0] - o[0], vy = v[1] - o[1];
    return atan2(fabs(ux * vy - uy * vx), ux * vx + uy * vy);
}

static int positive(const struct compat *c, int a, int b, int d)
{
    for (int s = 0; s < c->N; s++) {
        const double *X = c->X[s];
        if (orient2_sign(X + 2 * a, X + 2 * b, X + 2 * d) <= 0) return 0;
    }
    return 1;
}

void compat_pose_quality(const struct compat *c, int s, double *min_angle, double *under10, double *under20)
{
    double mn = INFINITY;
    int n10 = 0, n20 = 0;
    const double *X = c->X[s];
    for (int f = 0; f < c->nf; f++) {
        const int *F = c->F + 3 * f;
        double q = INFINITY;
        for (int k = 0; k < 3; k++)
            q = fmin(q, corner_angle(X + 2 * F[k], X + 2 * F[(k + 1) % 3], X + 2 * F[(k + 2) % 3]));
        if (orient2_sign(X + 2 * F[0], X + 2 * F[1], X + 2 * F[2]) <= 0) q = 0;
        mn = fmin(mn, q);
        n10 += q < 10 * M_PI / 180;
        n20 += q < 20 * M_PI / 180;
    }
    if (min_angle) *min_angle = mn;
    if (under10) *under10 = c->nf ? (double)n10 / c->nf : 0;
    if (under20) *under20 = c->nf ? (double)n20 / c->nf : 0;
}

/* opening of every boundary corner in every shape: open[s*nv+v] (2 pi for
 * interior vertices) and the number of triangles at v: cnt[v] */
static void corner_openings(const struct compat *c, const unsigned char *bnd, double *open, int *cnt)
{
    int nv = c->nv;
    memset(cnt, 0, nv * sizeof *cnt);
    for (int s = 0; s < c->N; s++)
        for (int v = 0; v < nv; v++) open[(size_t)s * nv + v] = bnd[v] ? 0 : 2 * M_PI;
    for (int f = 0; f < c->nf; f++) {
        const int *F = c->F + 3 * f;
        for (int k = 0; k < 3; k++) {
            int v = F[k];
            cnt[v]++;
            if (!bnd[v]) continue;
            for (int s = 0; s < c->N; s++) {
                const double *X = c->X[s];
                open[(size_t)s * nv + v] += corner_angle(X + 2 * v, X + 2 * F[(k + 1) % 3], X + 2 * F[(k + 2) % 3]);
            }
        }
    }
}

double compat_sharpest_corner(const struct compat *c)
{
    struct topology t;
    if (topology_build(c->F, c->nf, c->nv, &t) < 0) return 0;
    unsigned char *bnd = calloc(c->nv, 1);
    double *open = malloc((size_t)c->N * c->nv * sizeof *open);
    int *cnt = malloc(c->nv * sizeof *cnt);
    double mn = M_PI;
    if (bnd && open && cnt) {
        for (int e = 0; e < t.ne; e++)
            if (t.EFn[e] == 1) bnd[t.E[2 * e]] = bnd[t.E[2 * e + 1]] = 1;
        corner_openings(c, bnd, open, cnt);
        for (int s = 0; s < c->N; s++)
            for (int v = 0; v < c->nv; v++)
                if (bnd[v]) mn = fmin(mn, open[(size_t)s * c->nv + v]);
    } else mn = 0;
    free(bnd); free(open); free(cnt);
    topology_free(&t);
    return mn;
}

/* ------------------------------------------------------------------ */
/* storage */

struct work {
    struct compat *c;
    double *diag;         /* N bounding-box diagonals of the boundary */
    unsigned char *bnd;   /* cap: 1 for boundary (fixed) vertices */
    int *bsucc;           /* cap: next boundary vertex along the outline */
    int *seg;             /* cap by 2: for a vertex made by splitting an
                             outline edge, the outline vertices at the ends
                             of the input segment it lies on (it may slide
                             along it, shape by shape); -1 -1 otherwise */
    int vcap;
};

static int grow_v(struct work *w, int nv)
{
    if (compat_reserve_vertices(w->c, nv) < 0) return -1;
    if (nv > w->vcap) {
        int cap = w->vcap ? w->vcap : 64;
        while (cap < nv) cap *= 2;
        unsigned char *b = realloc(w->bnd, cap);
        if (!b) return cm_seterr("out of memory");
        w->bnd = b;
        int *n = realloc(w->bsucc, cap * sizeof *n);
        if (!n) return cm_seterr("out of memory");
        w->bsucc = n;
        int *g = realloc(w->seg, 2 * (size_t)cap * sizeof *g);
        if (!g) return cm_seterr("out of memory");
        w->seg = g;
        w->vcap = cap;
    }
    return 0;
}

static int grow_f(struct compat *c, int nf)
{
    if (nf <= c->fcap) return 0;
    int cap = c->fcap ? c->fcap : 256;
    while (cap < nf) cap *= 2;
    int *F = realloc(c->F, 3 * (size_t)cap * sizeof *F);
    if (!F) return cm_seterr("out of memory");
    c->F = F; c->fcap = cap;
    return 0;
}

static void set_face(struct compat *c, int f, int a, int b, int d)
{
    c->F[3 * f] = a; c->F[3 * f + 1] = b; c->F[3 * f + 2] = d;
}

/* corner (0..2) of vertex v in face f (v must be in f) */
static int corner(const int *F, int f, int v)
{
    return F[3 * f] == v ? 0 : F[3 * f + 1] == v ? 1 : 2;
}

/* the vertex of face f other than a and b */
static int third(const int *F, int f, int a, int b)
{
    return F[3 * f + 3 - corner(F, f, a) - corner(F, f, b)];
}

/* does face f run a -> b? */
static int runs(const int *F, int f, int a, int b)
{
    return corner(F, f, b) == (corner(F, f, a) + 1) % 3;
}

/* ------------------------------------------------------------------ */
/* smoothing */

/* measures of one triangle for a vertex's star */
typedef double (*tri_measure)(const double *a, const double *b, const double *d);

/* smallest measure over v's star in shape s with v at p */
static double star_min(const struct compat *c, const struct topology *t, int s, int v, const double *p,
                       tri_measure fn)
{
    const double *X = c->X[s];
    double q = INFINITY;
    for (int k = t->VFs[v]; k < t->VFs[v + 1]; k++) {
        const int *F = c->F + 3 * t->VF[k];
        const double *P[3];
        for (int j = 0; j < 3; j++) P[j] = F[j] == v ? p : X + 2 * F[j];
        q = fmin(q, fn(P[0], P[1], P[2]));
    }
    return q;
}

/* sin_min, -1 if the triangle is not positive (exact) */
static double sin_min_valid(const double *a, const double *b, const double *d)
{
    double x = compat_sin_min_angle(a, b, d);
    /* a sine above 1e-9 cannot come from a wrongly signed area */
    if (x <= 0 || (x < 1e-9 && orient2_sign(a, b, d) <= 0)) return -1;
    return x;
}

/* smallest sin_min of v's star in shape s with v at p; -1 if a triangle is
 * not positive (exact) */
static double star_quality(const struct compat *c, const struct topology *t, int s, int v, const double *p)
{
    return star_min(c, t, s, v, p, sin_min_valid);
}

/* mark v and its neighbours for the next visit (dirty: #V flags of one shape) */
static void touch_star(const struct topology *t, int v, unsigned char *dirty)
{
    dirty[v] = 1;
    for (int k = t->VVs[v]; k < t->VVs[v + 1]; k++) dirty[t->VV[k]] = 1;
}

/* dirty: N by #V flags; a vertex is visited only if it or a neighbour moved
 * since its last visit (else the visit would find the same: no move) */
static int smooth_pass(struct compat *c, const struct topology *t, const unsigned char *bnd, unsigned char *dirty)
{
    int moves = 0;
    for (int s = 0; s < c->N; s++) {
        double *X = c->X[s];
        unsigned char *dy = dirty + (size_t)s * c->nv;
        for (int v = 0; v < c->nv; v++) {
            if (!dy[v]) continue;
            dy[v] = 0;
            if (bnd[v] || t->VFs[v + 1] == t->VFs[v]) continue;
            double old = star_quality(c, t, s, v, X + 2 * v);
            /* candidates: mean of the equilateral apexes, neighbour centroid */
            double cand[6][2], ix = 0, iy = 0, gx = 0, gy = 0;
            int nfv = t->VFs[v + 1] - t->VFs[v];
            for (int k = t->VFs[v]; k < t->VFs[v + 1]; k++) {
                const int *F = c->F + 3 * t->VF[k];
                int j = F[0] == v ? 0 : F[1] == v ? 1 : 2;
                const double *a = X + 2 * F[(j + 1) % 3], *b = X + 2 * F[(j + 2) % 3];
                double dx = b[0] - a[0], dy = b[1] - a[1];
                ix += 0.5 * (a[0] + b[0]) - dy * 0.8660254037844386;
                iy += 0.5 * (a[1] + b[1]) + dx * 0.8660254037844386;
            }
            int nn = t->VVs[v + 1] - t->VVs[v];
            for (int k = t->VVs[v]; k < t->VVs[v + 1]; k++) { gx += X[2 * t->VV[k]]; gy += X[2 * t->VV[k] + 1]; }
            ix /= nfv; iy /= nfv; gx /= nn; gy /= nn;
            double ox = X[2 * v], oy = X[2 * v + 1];
            cand[0][0] = ix; cand[0][1] = iy;
            cand[1][0] = gx; cand[1][1] = gy;
            cand[2][0] = 0.5 * (ix + ox); cand[2][1] = 0.5 * (iy + oy);
            cand[3][0] = 0.5 * (gx + ox); cand[3][1] = 0.5 * (gy + oy);
            cand[4][0] = 0.8 * ox + 0.2 * ix; cand[4][1] = 0.8 * oy + 0.2 * iy;
            cand[5][0] = 0.5 * (ix + gx); cand[5][1] = 0.5 * (iy + gy);
            int best = -1;
            double bq = old;
            for (int k = 0; k < 6; k++) {
                double q = star_quality(c, t, s, v, cand[k]);
                if (q > bq * (1 + 1e-9) + 1e-15) { bq = q; best = k; }
            }
            if (best >= 0) { X[2 * v] = cand[best][0]; X[2 * v + 1] = cand[best][1]; moves++; touch_star(t, v, dy); }
        }
    }
    return moves;
}

/* ------------------------------------------------------------------ */
/* splits */

/* worst ratio (angle / what the corner allows) of face f over the shapes;
 * *ws gets the shape where it is worst */
static double face_ratio(const struct compat *c, int f, double goal, const double *open, const int *cnt,
                         int *ws)
{
    const int *F = c->F + 3 * f;
    double r = INFINITY;
    int nv = c->nv;
    for (int s = 0; s < c->N; s++) {
        const double *X = c->X[s];
        for (int k = 0; k < 3; k++) {
            int v = F[k];
            double an = corner_angle(X + 2 * v, X + 2 * F[(k + 1) % 3], X + 2 * F[(k + 2) % 3]);
            double o = open[(size_t)s * nv + v], req = goal;
            if (o < 2 * goal) req = fmin(goal, o / cnt[v]);
            double x = an / req;
            if (x < r) { r = x; *ws = s; }
        }
    }
    return r;
}

struct bad { double r; int f, s; };

static int cmp_bad(const void *x, const void *y)
{
    const struct bad *a = x, *b = y;
    if (a->r != b->r) return a->r < b->r ? -1 : 1;
    return a->f - b->f;
}

/* bisect edge a-b (faces f1 = (a, b, p) and, if f2 >= 0, f2 = (b, a, q));
 * returns 1 if done, 0 if a new triangle would not be positive, -1 on
 * out of memory */
static int bisect(struct work *w, int f1, int f2, int a, int b)
{
    struct compat *c = w->c;
    if (grow_v(w, c->nv + 1) < 0 || grow_f(c, c->nf + 2) < 0) return -1;
    int m = c->nv;
    for (int s = 0; s < c->N; s++) {
        double *X = c->X[s];
        X[2 * m] = 0.5 * (X[2 * a] + X[2 * b]);
        X[2 * m + 1] = 0.5 * (X[2 * a + 1] + X[2 * b + 1]);
    }
    int p = third(c->F, f1, a, b), q = f2 >= 0 ? third(c->F, f2, a, b) : -1;
    if (!positive(c, a, m, p) || !positive(c, m, b, p)) return 0;
    if (f2 >= 0 && (!positive(c, b, m, q) || !positive(c, m, a, q))) return 0;
    c->nv++;
    w->bnd[m] = f2 < 0;
    w->bsucc[m] = -1;
    w->seg[2 * m] = w->seg[2 * m + 1] = -1;
    if (f2 < 0) {
        w->bsucc[m] = b; w->bsucc[a] = m;
        w->seg[2 * m] = w->seg[2 * a] >= 0 ? w->seg[2 * a] : a;
        w->seg[2 * m + 1] = w->seg[2 * b + 1] >= 0 ? w->seg[2 * b + 1] : b;
    }
    set_face(c, f1, a, m, p);
    set_face(c, c->nf++, m, b, p);
    if (f2 >= 0) {
        set_face(c, f2, b, m, q);
        set_face(c, c->nf++, m, a, q);
    }
    return 1;
}

static int split_pass(struct work *w, const struct compat_refine_params *pa, int *nsplit, int *nbsplit)
{
    double goal = pa->goal;
    int max_nv = pa->max_nv;
    struct compat *c = w->c;
    struct topology t;
    if (topology_build(c->F, c->nf, c->nv, &t) < 0) return -1;
    int nf0 = c->nf, rc = 0;
    double *open = malloc((size_t)c->N * c->nv * sizeof *open);
    int *cnt = malloc(c->nv * sizeof *cnt);
    struct bad *B = malloc(nf0 * sizeof *B);
    unsigned char *touched = calloc(nf0, 1);
    if (!open || !cnt || !B || !touched) { rc = cm_seterr("out of memory"); goto done; }
    corner_openings(c, w->bnd, open, cnt);
    int nb = 0;
    for (int f = 0; f < nf0; f++) {
        int s = 0;
        double r = face_ratio(c, f, goal, open, cnt, &s);
        if (r < 1 - 1e-9) { B[nb].r = r; B[nb].f = f; B[nb].s = s; nb++; continue; }
        if (pa->size <= 0) continue;
        /* too large: after every triangle below the goal, largest first */
        const int *F = c->F + 3 * f;
        double big = 0;
        for (int t2 = 0; t2 < c->N; t2++)
            for (int k = 0; k < 3; k++) {
                const double *u = c->X[t2] + 2 * F[k], *v = c->X[t2] + 2 * F[(k + 1) % 3];
                double l = hypot(v[0] - u[0], v[1] - u[1]) / (pa->size * w->diag[t2]);
                if (l > big) { big = l; s = t2; }
            }
        if (big > 1) { B[nb].r = 1 + 1 / big; B[nb].f = f; B[nb].s = s; nb++; }
    }
    qsort(B, nb, sizeof *B, cmp_bad);
    for (int i = 0; i < nb && c->nv < max_nv; i++) {
        int f = B[i].f, s = B[i].s;
        if (touched[f]) continue;
        /* longest edge of f in shape s */
        const int *F = c->F + 3 * f;
        const double *X = c->X[s];
        int kbest = 0;
        double lbest = -1;
        for (int k = 0; k < 3; k++) {
            const double *u = X + 2 * F[k], *v = X + 2 * F[(k + 1) % 3];
            double l = (v[0] - u[0]) * (v[0] - u[0]) + (v[1] - u[1]) * (v[1] - u[1]);
            if (l > lbest) { lbest = l; kbest = k; }
        }
        int e = t.FE[3 * f + kbest];
        int a = F[kbest], b = F[(kbest + 1) % 3];
        int f2 = -1;
        if (t.EFn[e] == 2) {
            f2 = t.EF[2 * e] == f ? t.EF[2 * e + 1] : t.EF[2 * e];
            if (touched[f2]) continue;
        } else if (t.EFn[e] != 1) continue;
        int x = bisect(w, f, f2, a, b);
        if (x < 0) { rc = -1; goto done; }
        if (x == 0) continue;
        touched[f] = 1;
        if (f2 >= 0) { touched[f2] = 1; (*nsplit)++; } else (*nbsplit)++;
        rc++;
    }
done:
    free(open); free(cnt); free(B); free(touched);
    topology_free(&t);
    return rc;
}

/* boundary first (the old boundary order with the new boundary vertices
 * after the vertex that precedes them), then the interior */
static int renumber(struct work *w, int nb0, int nv0)
{
    struct compat *c = w->c;
    int nv = c->nv;
    int *map = malloc(nv * sizeof *map);
    double *tmp = malloc(2 * (size_t)nv * sizeof *tmp);
    if (!map || !tmp) { free(map); free(tmp); return cm_seterr("out of memory"); }
    for (int v = 0; v < nv; v++) map[v] = -1;
    int k = 0;
    for (int i = 0; i < nb0; i++) {
        map[i] = k++;
        for (int v = w->bsucc[i]; v >= nv0 && map[v] < 0; v = w->bsucc[v]) map[v] = k++;
    }
    int nb = k;
    for (int v = 0; v < nv; v++)
        if (map[v] < 0) map[v] = k++;
    for (int s = 0; s < c->N; s++) {
        double *X = c->X[s];
        for (int v = 0; v < nv; v++) { tmp[2 * map[v]] = X[2 * v]; tmp[2 * map[v] + 1] = X[2 * v + 1]; }
        memcpy(X, tmp, 2 * (size_t)nv * sizeof *X);
    }
    for (int f = 0; f < 3 * c->nf; f++) c->F[f] = map[c->F[f]];
    /* several rings: each ring now starts where its first vertex went; the
     * interior points (after the last ring) keep their order */
    if (c->nrings > 0) {
        int end = c->ring_start[c->nrings];
        for (int r = 0; r < c->nrings; r++) c->ring_start[r] = map[c->ring_start[r]];
        c->ring_start[c->nrings] = c->npts > 0 ? map[end] : nb;
    }
    c->nrefine += (nv - nv0) - (nb - nb0);
    c->nb = nb;
    free(map); free(tmp);
    return 0;
}

/* ------------------------------------------------------------------ */

struct snapshot { int nv, nf, nb, nrefine; double **X; int *F; int *ring_start; };

static int snap_take(const struct compat *c, struct snapshot *p)
{
    p->nv = c->nv; p->nf = c->nf; p->nb = c->nb; p->nrefine = c->nrefine;
    p->ring_start = NULL;
    if (c->nrings > 0) {
        p->ring_start = malloc((c->nrings + 1) * sizeof *p->ring_start);
        if (!p->ring_start) return cm_seterr("out of memory");
        memcpy(p->ring_start, c->ring_start, (c->nrings + 1) * sizeof *p->ring_start);
    }
    p->X = calloc(c->N, sizeof *p->X);
    p->F = malloc(3 * (size_t)c->nf * sizeof *p->F);
    if (!p->X || !p->F) return cm_seterr("out of memory");
    memcpy(p->F, c->F, 3 * (size_t)c->nf * sizeof *p->F);
    for (int s = 0; s < c->N; s++) {
        p->X[s] = malloc(2 * (size_t)c->nv * sizeof **p->X);
        if (!p->X[s]) return cm_seterr("out of memory");
        memcpy(p->X[s], c->X[s], 2 * (size_t)c->nv * sizeof **p->X);
    }
    return 0;
}

static void snap_restore(struct compat *c, struct snapshot *p)
{
    c->nv = p->nv; c->nf = p->nf; c->nb = p->nb; c->nrefine = p->nrefine;
    if (p->ring_start) memcpy(c->ring_start, p->ring_start, (c->nrings + 1) * sizeof *p->ring_start);
    memcpy(c->F, p->F, 3 * (size_t)c->nf * sizeof *p->F);
    for (int s = 0; s < c->N; s++) memcpy(c->X[s], p->X[s], 2 * (size_t)c->nv * sizeof **p->X);
}

static void snap_free(int N, struct snapshot *p)
{
    if (p->X) for (int s = 0; s < N; s++) free(p->X[s]);
    free(p->X); free(p->F); free(p->ring_start);
}

/* dirty flags of one shape from seed (#V flags, NULL: every vertex): the
 * seeded vertices and their neighbours */
static void seed_dirty(const struct topology *t, int nv, const unsigned char *seed, unsigned char *dy)
{
    if (!seed) { memset(dy, 1, nv); return; }
    memset(dy, 0, nv);
    for (int v = 0; v < nv; v++)
        if (seed[v]) touch_star(t, v, dy);
}

/* seed: #V flags of the vertices whose neighbourhood changed since the last
 * smoothing (NULL: all); only they and whatever their moves disturb are
 * visited */
static int smooth_sweeps(struct compat *c, const unsigned char *bnd, int sweeps, const unsigned char *seed)
{
    struct topology t;
    if (topology_build(c->F, c->nf, c->nv, &t) < 0) return -1;
    int moves = 0;
    unsigned char *dirty = malloc((size_t)c->N * c->nv);
    if (!dirty) { topology_free(&t); return cm_seterr("out of memory"); }
    for (int s = 0; s < c->N; s++) seed_dirty(&t, c->nv, seed, dirty + (size_t)s * c->nv);
    for (int k = 0; k < sweeps; k++) {
        int m = smooth_pass(c, &t, bnd, dirty);
        moves += m;
        if (!m) break;
    }
    free(dirty);
    topology_free(&t);
    return moves;
}

/* MIPS-type energy of v's star in shape s with v at p: the sum over the
 * star of (S / (4 sqrt3 A))^2, S the sum of squared edge lengths and A the
 * area (1 for an equilateral triangle, growing without bound as a triangle
 * degenerates); gradient in g (may be NULL).  INFINITY if a triangle of the
 * star is not positive (exact). */
static double star_mips(const struct compat *c, const struct topology *t, int s, int v, const double *p,
                        double *g)
{
    const double *X = c->X[s];
    double E = 0, gx = 0, gy = 0, k = 1 / (4 * sqrt(3.0));
    for (int i = t->VFs[v]; i < t->VFs[v + 1]; i++) {
        const int *F = c->F + 3 * t->VF[i];
        int j = F[0] == v ? 0 : F[1] == v ? 1 : 2;
        const double *a = X + 2 * F[(j + 1) % 3], *b = X + 2 * F[(j + 2) % 3];
        double pax = p[0] - a[0], pay = p[1] - a[1], pbx = p[0] - b[0], pby = p[1] - b[1];
        double abx = a[0] - b[0], aby = a[1] - b[1];
        double S = pax * pax + pay * pay + pbx * pbx + pby * pby + abx * abx + aby * aby;
        double A = 0.5 * ((a[0] - p[0]) * (b[1] - p[1]) - (a[1] - p[1]) * (b[0] - p[0]));
        if (!(A > 1e-12 * S) && (A <= 0 || orient2_sign(p, a, b) <= 0)) return INFINITY;
        double e = k * S / A;
        E += e * e;
        if (g) {
            /* de/dp = k (dS/dp / A - S dA/dp / A^2), dA/dp = (a_y - b_y, b_x - a_x) / 2 */
            double dex = k * (2 * (pax + pbx) / A - S * 0.5 * (a[1] - b[1]) / (A * A));
            double dey = k * (2 * (pay + pby) / A - S * 0.5 * (b[0] - a[0]) / (A * A));
            gx += 2 * e * dex; gy += 2 * e * dey;
        }
    }
    if (g) { g[0] = gx; g[1] = gy; }
    return E;
}

/* Per-shape smoothing by the MIPS energy of star_mips: every interior
 * vertex takes a gradient step (backtracking from a quarter of its mean
 * edge length) that lowers its star's energy and keeps every triangle
 * positive (exact).  The energy is a barrier, so no triangle ever inverts;
 * it evens out the triangles of each shape as a whole, where the
 * smallest-angle smoothing only moves one vertex to a few candidates.
 * Returns the number of moves, -1 on error. */
static int mips_sweeps(struct compat *c, const unsigned char *bnd, const int *seg, int sweeps,
                       const unsigned char *seed)
{
    struct topology t;
    if (topology_build(c->F, c->nf, c->nv, &t) < 0) return -1;
    int moves = 0;
    unsigned char *dy = malloc(c->nv);
    if (!dy) { topology_free(&t); return cm_seterr("out of memory"); }
    for (int s = 0; s < c->N; s++) {
        double *X = c->X[s];
        seed_dirty(&t, c->nv, seed, dy);
        for (int k = 0; k < sweeps; k++) {
            int m = 0;
            for (int v = 0; v < c->nv; v++) {
                if (!dy[v]) continue;
                dy[v] = 0;
                int sl = seg && seg[2 * v] >= 0;   /* slides along its outline segment */
                if ((bnd[v] && !sl) || t.VFs[v + 1] == t.VFs[v]) continue;
                double g[2], *x = X + 2 * v;
                double E0 = star_mips(c, &t, s, v, x, g), gn = hypot(g[0], g[1]);
                if (!(gn > 0) || !isfinite(E0)) continue;
                double L = 0;
                int nn = t.VVs[v + 1] - t.VVs[v];
                for (int i = t.VVs[v]; i < t.VVs[v + 1]; i++)
                    L += hypot(X[2 * t.VV[i]] - x[0], X[2 * t.VV[i] + 1] - x[1]);
                L /= nn;
                const double *A = sl ? X + 2 * seg[2 * v] : NULL, *B = sl ? X + 2 * seg[2 * v + 1] : NULL;
                double ux = 0, uy = 0, tv = 0, lab = 1;
                if (sl) {   /* the gradient along the segment A-B; v = A + tv (B - A) */
                    ux = B[0] - A[0]; uy = B[1] - A[1];
                    lab = hypot(ux, uy);
                    if (!(lab > 0)) continue;
                    tv = ((x[0] - A[0]) * ux + (x[1] - A[1]) * uy) / (lab * lab);
                    gn = (g[0] * ux + g[1] * uy) / lab;
                    if (gn == 0) continue;
                }
                for (double h = 0.25 * L; h > 1e-4 * L; h *= 0.5) {
                    double p[2] = {x[0] - h * g[0] / gn, x[1] - h * g[1] / gn};
                    if (sl) {
                        double tn = tv - h / lab * (gn > 0 ? 1 : -1);
                        if (!(tn > 0 && tn < 1)) continue;
                        p[0] = A[0] + tn * ux; p[1] = A[1] + tn * uy;
                    }
                    if (star_mips(c, &t, s, v, p, NULL) < E0 * (1 - 1e-6)) {
                        x[0] = p[0]; x[1] = p[1]; m++;
                        /* a step under 1% of the mean edge does not wake
                         * the neighbours (nor v): the sweeps stay where
                         * something changed */
                        if (h >= 0.01 * L) touch_star(&t, v, dy);
                        break;
                    }
                }
            }
            moves += m;
            if (!m) break;
        }
    }
    free(dy);
    topology_free(&t);
    return moves;
}

/* Max-min polish of one vertex v in shape s: a pattern search (eight
 * directions, or the two along its outline segment for a vertex that
 * slides) on the smallest angle of v's star, from a fifth of the mean edge
 * length down to 1/1000 of it; every step keeps the star positive (exact).
 * The MIPS and candidate smoothing above optimise proxies (energy, a few
 * fixed candidates); this raises the one angle that is worst.  Returns 1 if
 * v moved. */
static int polish_vertex(struct compat *c, const struct topology *t, int s, int v, const int *seg)
{
    double *X = c->X[s], *x = X + 2 * v;
    int sl = seg && seg[2 * v] >= 0;
    double q = star_quality(c, t, s, v, x);
    if (!(q > 0)) return 0;
    int nn = t->VVs[v + 1] - t->VVs[v];
    if (!nn) return 0;
    double L = 0;
    for (int i = t->VVs[v]; i < t->VVs[v + 1]; i++)
        L += hypot(X[2 * t->VV[i]] - x[0], X[2 * t->VV[i] + 1] - x[1]);
    L /= nn;
    const double *A = sl ? X + 2 * seg[2 * v] : NULL, *B = sl ? X + 2 * seg[2 * v + 1] : NULL;
    double ux = 0, uy = 0, lab = 1;
    if (sl) {
        ux = B[0] - A[0]; uy = B[1] - A[1];
        lab = hypot(ux, uy);
        if (!(lab > 0)) return 0;
    }
    static const double D[8][2] = {{1, 0}, {0.7071067811865476, 0.7071067811865476}, {0, 1},
                                   {-0.7071067811865476, 0.7071067811865476}, {-1, 0},
                                   {-0.7071067811865476, -0.7071067811865476}, {0, -1},
                                   {0.7071067811865476, -0.7071067811865476}};
    double p[2] = {x[0], x[1]};
    int moved = 0;
    for (double h = 0.2 * L; h > 1e-3 * L;) {
        double bq = q, bp[2] = {0, 0};
        int nd = sl ? 2 : 8, found = 0;
        for (int k = 0; k < nd; k++) {
            double cp[2];
            if (sl) {
                double tv = ((p[0] - A[0]) * ux + (p[1] - A[1]) * uy) / (lab * lab);
                double tn = tv + (k ? -h : h) / lab;
                if (!(tn > 0 && tn < 1)) continue;
                cp[0] = A[0] + tn * ux; cp[1] = A[1] + tn * uy;
            } else {
                cp[0] = p[0] + h * D[k][0]; cp[1] = p[1] + h * D[k][1];
            }
            double cq = star_quality(c, t, s, v, cp);
            if (cq > bq * (1 + 1e-9)) { bq = cq; bp[0] = cp[0]; bp[1] = cp[1]; found = 1; }
        }
        if (found) { q = bq; p[0] = bp[0]; p[1] = bp[1]; moved = 1; }
        else h *= 0.5;
    }
    if (moved) { x[0] = p[0]; x[1] = p[1]; }
    return moved;
}

/* Polish every shape: the movable vertices of triangles whose smallest
 * angle in that shape is below goal (and their neighbours) get
 * polish_vertex, in sweeps while something moves.  Returns the number of
 * moves, -1 on error. */
static int polish(struct compat *c, const unsigned char *bnd, const int *seg, double goal, int sweeps)
{
    struct topology t;
    if (topology_build(c->F, c->nf, c->nv, &t) < 0) return -1;
    unsigned char *dy = malloc(c->nv ? c->nv : 1);
    if (!dy) { topology_free(&t); return cm_seterr("out of memory"); }
    double sg = sin(goal);
    int moves = 0;
    for (int s = 0; s < c->N; s++) {
        const double *X = c->X[s];
        for (int k = 0; k < sweeps; k++) {
            memset(dy, 0, c->nv);
            int any = 0;
            for (int f = 0; f < c->nf; f++) {
                const int *F = c->F + 3 * f;
                if (compat_sin_min_angle(X + 2 * F[0], X + 2 * F[1], X + 2 * F[2]) >= sg) continue;
                for (int j = 0; j < 3; j++) { touch_star(&t, F[j], dy); any = 1; }
            }
            if (!any) break;
            int m = 0;
            for (int v = 0; v < c->nv; v++) {
                if (!dy[v] || (bnd[v] && !(seg && seg[2 * v] >= 0)) || t.VFs[v + 1] == t.VFs[v]) continue;
                m += polish_vertex(c, &t, s, v, seg);
            }
            moves += m;
            if (!m) break;
        }
    }
    free(dy);
    topology_free(&t);
    return moves;
}

/* quality of shape s for acceptance: smallest sin_min and the number of
 * triangles whose smallest angle is below the goal */
static void shape_score(const struct compat *c, int s, double sgoal, double *mn, int *nbad)
{
    const double *X = c->X[s];
    *mn = INFINITY; *nbad = 0;
    for (int f = 0; f < c->nf; f++) {
        const int *F = c->F + 3 * f;
        double q = compat_sin_min_angle(X + 2 * F[0], X + 2 * F[1], X + 2 * F[2]);
        *mn = fmin(*mn, q);
        *nbad += q < sgoal;
    }
}

/* Transfer: the shape whose triangles are best (reference r) is carried to
 * every other shape s by as-rigid-as-possible deformation with all
 * boundary vertices as handles at their places in s (arap_deform2d); the
 * interior vertices of s then walk to those targets in sweeps, a vertex
 * moving (fully, or half-way) only where its star stays positive (exact).
 * Shape s keeps the result if its smallest angle grows or fewer triangles
 * stay below the goal.  Returns the number of shapes changed, -1 on error. */
static int transfer(struct compat *c, const unsigned char *bnd, double goal, int *moves)
{
    int N = c->N, nv = c->nv, changed = 0;
    if (N < 2) return 0;
    double sg = sin(goal), best = -INFINITY;
    int r = 0;
    for (int s = 0; s < N; s++) {
        double mn; int nbad;
        shape_score(c, s, sg, &mn, &nbad);
        double score = mn - nbad;   /* fewest bad triangles, then the best worst one */
        if (score > best) { best = score; r = s; }
    }
    int nh = 0;
    int *H = malloc(nv * sizeof *H);
    double *V = malloc(3 * (size_t)nv * sizeof *V), *Y = malloc(3 * (size_t)nv * sizeof *Y);
    double *P = malloc(2 * (size_t)nv * sizeof *P), *keep = malloc(2 * (size_t)nv * sizeof *keep);
    struct topology t;
    int rc = -1, topo = 0;
    struct arap_deform2d *D = NULL;
    if (!H || !V || !Y || !P || !keep) { cm_seterr("out of memory"); goto out; }
    for (int v = 0; v < nv; v++) {
        if (bnd[v]) H[nh++] = v;
        V[3 * v] = c->X[r][2 * v]; V[3 * v + 1] = c->X[r][2 * v + 1]; V[3 * v + 2] = 0;
    }
    if (nh == nv) { rc = 0; goto out; }
    D = arap_deform2d_new(V, nv, c->F, c->nf, H, nh);
    if (!D) goto out;
    if (topology_build(c->F, c->nf, nv, &t) < 0) goto out;
    topo = 1;
    for (int s = 0; s < N; s++) {
        if (s == r) continue;
        double *X = c->X[s];
        for (int h = 0; h < nh; h++) { P[2 * h] = X[2 * H[h]]; P[2 * h + 1] = X[2 * H[h] + 1]; }
        if (arap_deform2d_solve(D, P, Y) < 0) goto out;
        double mn0, mn1; int nb0, nb1;
        shape_score(c, s, sg, &mn0, &nb0);
        memcpy(keep, X, 2 * (size_t)nv * sizeof *X);
        int mv = 0;
        for (int sweep = 0; sweep < 12; sweep++) {
            int m = 0;
            for (int v = 0; v < nv; v++) {
                if (bnd[v] || t.VFs[v + 1] == t.VFs[v]) continue;
                double *x = X + 2 * v, *y = Y + 3 * v;
                if (x[0] == y[0] && x[1] == y[1]) continue;
                double p[2] = {y[0], y[1]};
                for (int k = 0; k < 3; k++) {
                    if (star_quality(c, &t, s, v, p) > 0) { x[0] = p[0]; x[1] = p[1]; m++; break; }
                    p[0] = 0.5 * (p[0] + x[0]); p[1] = 0.5 * (p[1] + x[1]);
                }
            }
            mv += m;
            if (!m) break;
        }
        shape_score(c, s, sg, &mn1, &nb1);
        if (mn1 > mn0 || nb1 < nb0) { changed++; *moves += mv; }
        else memcpy(X, keep, 2 * (size_t)nv * sizeof *X);
    }
    rc = changed;
out:
    arap_deform2d_free(D);
    if (topo) topology_free(&t);
    free(H); free(V); free(Y); free(P); free(keep);
    return rc;
}

static int flips_until_done(struct compat *c, int *nflips)
{
    for (int k = 0; k < 50; k++) {
        int x = compat_flip_pass(c);
        if (x < 0) return -1;
        *nflips += x;
        if (!x) break;
    }
    return 0;
}

/* smallest sine of the smallest angle of face (a, b, d) over the shapes; -1
 * if it is not positive in some shape (exact) */
static double face_sin(const struct compat *c, int a, int b, int d)
{
    double q = INFINITY;
    for (int s = 0; s < c->N; s++) {
        const double *X = c->X[s];
        double x = sin_min_valid(X + 2 * a, X + 2 * b, X + 2 * d);
        if (x < 0) return -1;
        q = fmin(q, x);
    }
    return q;
}

/* One pass of compatible edge collapses: an interior vertex v in a
 * triangle below goal (in some shape) is merged into the neighbour u that
 * gives the best result, if the link condition holds (u and v share
 * exactly two neighbours), every changed triangle stays positive in every
 * shape (exact) and the smallest angle over the changed triangles and
 * shapes is larger than that of v's star.  Undoes the tiny pieces that
 * overlays leave.  Vertices near a collapse wait for the next pass
 * (the topology is stale there).  dead: #V flags of removed vertices.
 * Returns the number of collapses, -1 on error. */
static int collapse_pass(struct work *w, unsigned char *dead, double goal)
{
    struct compat *c = w->c;
    struct topology t;
    if (topology_build(c->F, c->nf, c->nv, &t) < 0) return -1;
    unsigned char *lock = calloc(c->nv, 1);
    if (!lock) { topology_free(&t); return cm_seterr("out of memory"); }
    double sg = sin(goal);
    int n = 0;
    for (int v = 0; v < c->nv; v++) {
        if (w->bnd[v] || dead[v] || lock[v] || t.VFs[v + 1] == t.VFs[v]) continue;
        double old = INFINITY;
        for (int k = t.VFs[v]; k < t.VFs[v + 1]; k++) {
            const int *F = c->F + 3 * t.VF[k];
            old = fmin(old, face_sin(c, F[0], F[1], F[2]));
        }
        if (!(old < sg)) continue;
        int bu = -1;
        double bq = old;
        for (int i = t.VVs[v]; i < t.VVs[v + 1]; i++) {
            int u = t.VV[i];
            if (dead[u] || lock[u]) continue;
            /* link condition: exactly two common neighbours */
            int common = 0;
            for (int j = t.VVs[v]; j < t.VVs[v + 1]; j++)
                if (topology_edge(&t, u, t.VV[j]) >= 0) common++;
            if (common != 2) continue;
            double q = INFINITY;
            for (int k = t.VFs[v]; k < t.VFs[v + 1] && q > bq; k++) {
                const int *F = c->F + 3 * t.VF[k];
                if (F[0] == u || F[1] == u || F[2] == u) continue;
                int G[3];
                for (int j = 0; j < 3; j++) G[j] = F[j] == v ? u : F[j];
                q = fmin(q, face_sin(c, G[0], G[1], G[2]));
            }
            if (q > bq) { bq = q; bu = u; }
        }
        if (bu < 0) continue;
        for (int k = t.VFs[v]; k < t.VFs[v + 1]; k++) {
            int *F = c->F + 3 * t.VF[k];
            if (F[0] == bu || F[1] == bu || F[2] == bu) { F[0] = F[1] = F[2] = -1; continue; }
            for (int j = 0; j < 3; j++) if (F[j] == v) F[j] = bu;
        }
        dead[v] = 1;
        lock[v] = lock[bu] = 1;
        for (int i = t.VVs[v]; i < t.VVs[v + 1]; i++) lock[t.VV[i]] = 1;
        n++;
    }
    /* drop the collapsed faces */
    int nf = 0;
    for (int f = 0; f < c->nf; f++)
        if (c->F[3 * f] >= 0) {
            memmove(c->F + 3 * nf, c->F + 3 * f, 3 * sizeof *c->F);
            nf++;
        }
    c->nf = nf;
    free(lock);
    topology_free(&t);
    return n;
}

/* collapses until none helps, then the removed vertices are dropped
 * (vertices keep their order, so the fixed ones 0..nb-1 keep their
 * numbers).  Returns the number of vertices removed, -1 on error. */
static int collapse_all(struct work *w, double goal)
{
    struct compat *c = w->c;
    unsigned char *dead = calloc(c->nv ? c->nv : 1, 1);
    if (!dead) return cm_seterr("out of memory");
    int total = 0;
    for (int pass = 0; pass < 50; pass++) {
        int n = collapse_pass(w, dead, goal);
        if (n < 0) { free(dead); return -1; }
        total += n;
        if (!n) break;
    }
    if (total) {
        int *map = malloc(c->nv * sizeof *map), k = 0;
        if (!map) { free(dead); return cm_seterr("out of memory"); }
        for (int v = 0; v < c->nv; v++) map[v] = dead[v] ? -1 : k++;
        for (int v = 0; v < c->nv; v++) {
            if (dead[v]) continue;
            for (int s = 0; s < c->N; s++) {
                c->X[s][2 * map[v]] = c->X[s][2 * v];
                c->X[s][2 * map[v] + 1] = c->X[s][2 * v + 1];
            }
            w->bnd[map[v]] = w->bnd[v];
            w->bsucc[map[v]] = w->bsucc[v] >= 0 ? map[w->bsucc[v]] : -1;
        }
        for (int f = 0; f < 3 * c->nf; f++) c->F[f] = map[c->F[f]];
        c->nv = k;
        free(map);
    }
    free(dead);
    return total;
}

int compat_refine(struct compat *c, const struct compat_refine_params *pa, struct compat_refine_stats *st)
{
    double goal = pa->goal;
    int rounds = pa->rounds, max_nv = pa->max_nv;
    struct compat_refine_stats z;
    if (!st) st = &z;
    memset(st, 0, sizeof *st);
    struct snapshot snap;
    memset(&snap, 0, sizeof snap);
    double q0 = compat_min_angle(c, NULL);
    struct work w = {c, NULL, NULL, NULL, NULL, 0};
    int nb0 = c->nb, nv0 = c->nv, rc = -1;
    int *Fsave = NULL;
    unsigned char *seed = NULL;
    w.diag = malloc(c->N * sizeof *w.diag);
    if (!w.diag) { cm_seterr("out of memory"); goto out; }
    for (int s = 0; s < c->N; s++) {
        double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
        for (int v = 0; v < c->nb; v++)
            for (int d = 0; d < 2; d++) { lo[d] = fmin(lo[d], c->X[s][2 * v + d]); hi[d] = fmax(hi[d], c->X[s][2 * v + d]); }
        w.diag[s] = hypot(hi[0] - lo[0], hi[1] - lo[1]);
    }
    if (snap_take(c, &snap) < 0 || grow_v(&w, c->nv) < 0) goto out;
    /* boundary flags and successors from the faces */
    memset(w.bnd, 0, c->nv);
    for (int v = 0; v < c->nv; v++) w.bsucc[v] = w.seg[2 * v] = w.seg[2 * v + 1] = -1;
    {
        struct topology t;
        if (topology_build(c->F, c->nf, c->nv, &t) < 0) goto out;
        for (int e = 0; e < t.ne; e++) {
            if (t.EFn[e] != 1) continue;
            int a = t.E[2 * e], b = t.E[2 * e + 1], f = t.EF[2 * e];
            if (!runs(c->F, f, a, b)) { int x = a; a = b; b = x; }
            w.bnd[a] = w.bnd[b] = 1;
            w.bsucc[a] = b;
        }
        topology_free(&t);
        /* interior correspondence points (compat_holes) never move either */
        for (int v = 0; v < c->nb; v++) w.bnd[v] = 1;
    }
    /* after the first round only what splits and flips changed is smoothed
     * (seed: vertices of faces that differ from Fsave, the faces after the
     * last smoothing; new vertices) */
    int nfsave = 0, nvsave = 0, full = 1;
    if (pa->mips > 0) {
        int k = collapse_all(&w, goal);
        if (k < 0) goto out;
        st->collapses = k;
        c->nsteiner = c->nsteiner > k ? c->nsteiner - k : 0;
        nv0 = c->nv;
    }
    for (int r = 0; r < rounds; r++) {
        st->rounds++;
        if (flips_until_done(c, &st->flips) < 0) goto out;
        free(seed);
        seed = NULL;
        if (!full) {
            seed = calloc(c->nv, 1);
            if (!seed) { cm_seterr("out of memory"); goto out; }
            for (int f = 0; f < c->nf; f++) {
                const int *F = c->F + 3 * f;
                if (f < nfsave && F[0] == Fsave[3 * f] && F[1] == Fsave[3 * f + 1] && F[2] == Fsave[3 * f + 2])
                    continue;
                seed[F[0]] = seed[F[1]] = seed[F[2]] = 1;
            }
            for (int v = nvsave; v < c->nv; v++) seed[v] = 1;
        }
        int m = pa->mips > 0 ? mips_sweeps(c, w.bnd, w.seg, pa->mips, seed) : 0;
        if (m < 0) goto out;
        st->moves += m;
        m = smooth_sweeps(c, w.bnd, 8, seed);
        if (m < 0) goto out;
        st->moves += m;
        if (pa->mips > 0) {
            if (flips_until_done(c, &st->flips) < 0) goto out;
            m = polish(c, w.bnd, w.seg, goal, 4);
            if (m < 0) goto out;
            st->moves += m;
        }
        /* the ARAP transfer between shapes: with the MIPS smoothing it was
         * never kept (creature and elephant poses), so it runs without */
        int tc = pa->mips > 0 ? 0 : transfer(c, w.bnd, goal, &st->moves);
        if (tc < 0) goto out;
        if (tc > 0) {   /* whole shapes moved */
            m = smooth_sweeps(c, w.bnd, 8, NULL);
            if (m < 0) goto out;
            st->moves += m;
        }
        full = 0;
        if (flips_until_done(c, &st->flips) < 0) goto out;
        if (c->nv >= max_nv) break;
        int *Fn = realloc(Fsave, 3 * (size_t)c->nf * sizeof *Fn);
        if (!Fn) { cm_seterr("out of memory"); goto out; }
        Fsave = Fn;
        memcpy(Fsave, c->F, 3 * (size_t)c->nf * sizeof *Fsave);
        nfsave = c->nf; nvsave = c->nv;
        int n = split_pass(&w, pa, &st->splits, &st->bsplits);
        if (n < 0) goto out;
        if (n == 0) break;
    }
    /* final polish */
    for (int k = 0; k < 4; k++) {
        int m = smooth_sweeps(c, w.bnd, 8, NULL);
        if (m < 0) goto out;
        st->moves += m;
        if (pa->mips > 0) {
            int m2 = polish(c, w.bnd, w.seg, goal, 4);
            if (m2 < 0) goto out;
            st->moves += m2;
            m += m2;
        }
        int f0 = st->flips;
        if (flips_until_done(c, &st->flips) < 0) goto out;
        if (st->flips == f0 && m == 0) break;
    }
    if (renumber(&w, nb0, nv0) < 0) goto out;
    double minarea, q1 = compat_min_angle(c, &minarea);
    if (!(minarea > 0) || q1 < q0) {
        snap_restore(c, &snap);
        st->kept_input = 1;
    }
    rc = 0;
out:
    snap_free(c->N, &snap);
    free(w.bnd); free(w.bsucc); free(w.seg); free(w.diag); free(Fsave); free(seed);
    return rc;
}
