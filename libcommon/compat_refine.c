/* compat_refine.c -- see compat_refine.h */
#include "compat_refine.h"
#include "cm_error.h"
#include "predicates2.h"
#include "topology.h"
#include "arap_deform2d.h"
#include "rings.h"
#include "parallel.h"
#include "maxmin_polish.h"
#include <math.h>
#include <stdlib.h>
#include <limits.h>
#include <string.h>
#include <time.h>

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
    double *stol;         /* N: pa->slide in each shape's units (NULL: no
                             outline vertex slides along its input outline;
                             a sliding vertex has seg[2v] = -2 - its index
                             in c->B) */
    int slide_now;        /* the passes that let them slide (stol set) */
    double *pose_cost;    /* 3 by N: CPU seconds of each pose's last smoothing job of each
                             kind (run_poses): a round's MIPS and smoothing, its polish,
                             the final smoothing and polish */
    int *id;              /* cap: a number that stays with the vertex
                             (vertex indices change when collapses compact) */
    unsigned long long *sig; /* cap: signature of the vertex's star at the
                             last smoothing (star_sigs) */
    int nextid;
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
        int *id = realloc(w->id, cap * sizeof *id);
        if (!id) return cm_seterr("out of memory");
        w->id = id;
        unsigned long long *sg = realloc(w->sig, cap * sizeof *sg);
        if (!sg) return cm_seterr("out of memory");
        w->sig = sg;
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

/* smallest measure over v's star in shape s with v at p; stops early (with
 * a value <= floor) as soon as a triangle is at or below floor (-INFINITY:
 * the exact smallest) */
static double star_min(const struct compat *c, const struct topology *t, int s, int v, const double *p,
                       tri_measure fn, double floor)
{
    const double *X = c->X[s];
    double q = INFINITY;
    for (int k = t->VFs[v]; k < t->VFs[v + 1]; k++) {
        const int *F = c->F + 3 * t->VF[k];
        const double *P[3];
        for (int j = 0; j < 3; j++) P[j] = F[j] == v ? p : X + 2 * F[j];
        double x = fn(P[0], P[1], P[2]);
        if (x < q) q = x;   /* fmin without the call (x is never NaN) */
        if (q <= floor) break;
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
    return star_min(c, t, s, v, p, sin_min_valid, -INFINITY);
}

/* star_quality, or any value <= floor once it is clear that it is at or
 * below floor (the candidate searches only ask whether it beats floor) */
static double star_quality_above(const struct compat *c, const struct topology *t, int s, int v, const double *p,
                                 double floor)
{
    return star_min(c, t, s, v, p, sin_min_valid, floor);
}

/* v's star in one shape, for the candidate searches that evaluate many
 * positions p of v: the corners of each triangle in face order (NULL where
 * v is), and the triangle to try first.  A search mostly asks whether a
 * position beats a floor, and the answer is mostly no, found at the
 * triangle that blocked the position before; trying it first stops the
 * evaluation early.  The smallest value over the whole star, where it is
 * computed, does not depend on the order. */
#define STAR_MAX 32
struct star {
    int n, first;
    const double *Q[STAR_MAX][3];
    unsigned char at[STAR_MAX];   /* v's corner in each triangle */
};

/* loads v's star in shape s; 0 if it has more than STAR_MAX triangles */
static int star_load(const struct compat *c, const struct topology *t, int s, int v, struct star *st)
{
    const double *X = c->X[s];
    int n = t->VFs[v + 1] - t->VFs[v];
    if (n > STAR_MAX) return 0;
    st->n = n;
    st->first = 0;
    for (int k = 0; k < n; k++) {
        const int *F = c->F + 3 * t->VF[t->VFs[v] + k];
        for (int j = 0; j < 3; j++) {
            st->Q[k][j] = F[j] == v ? NULL : X + 2 * F[j];
            if (F[j] == v) st->at[k] = (unsigned char)j;
        }
    }
    return 1;
}

/* star_quality_above on a loaded star (the same value where it is above
 * floor); remembers the triangle that stopped it */
static double star_above(struct star *st, const double *p, double floor)
{
    double q = INFINITY;
    /* a triangle's sine area2 / sqrt(pp) is surely below a positive floor
     * where area2^2 <= floor^2 (1 - 1e-9) pp (the roundings of either side
     * are far below 1e-9; both sides normal and finite): then the square
     * root and the division are not needed to say so.  A candidate
     * position is mostly turned down by the triangle tried first. */
    double fl2 = floor > 0 ? floor * floor * (1 - 1e-9) : -1;
    for (int i = 0, k = st->first; i < st->n; i++, k = k + 1 == st->n ? 0 : k + 1) {
        const double *const *Q = st->Q[k];
        const double *a = Q[0] ? Q[0] : p, *b = Q[1] ? Q[1] : p, *d = Q[2] ? Q[2] : p;
        /* sin_min_valid(a, b, d), compat_sin_min_angle's terms */
        double e0x = b[0] - a[0], e0y = b[1] - a[1], e1x = d[0] - b[0], e1y = d[1] - b[1];
        double e2x = a[0] - d[0], e2y = a[1] - d[1];
        double l0 = e0x * e0x + e0y * e0y, l1 = e1x * e1x + e1y * e1y, l2 = e2x * e2x + e2y * e2y;
        double area2 = e0x * (d[1] - a[1]) - e0y * (d[0] - a[0]);
        double x = -1;
        if (area2 > 0) {
            double pp = l0 <= l1 && l0 <= l2 ? l1 * l2 : l1 <= l2 ? l0 * l2 : l0 * l1;
            double a2 = area2 * area2, rhs = fl2 * pp;
            if (fl2 > 0 && a2 > 1e-290 && rhs > 1e-290 && rhs < 1e290 && a2 <= rhs) { st->first = k; return -1; }
            x = area2 / sqrt(pp);
            if (x <= 0 || (x < 1e-9 && orient2_sign(a, b, d) <= 0)) x = -1;
        }
        if (x < q) q = x;
        if (q <= floor) { st->first = k; break; }
    }
    return q;
}

/* mark v and its neighbours for the next visit (dirty: #V flags of one shape) */
static void touch_star(const struct topology *t, int v, unsigned char *dirty)
{
    dirty[v] = 1;
    for (int k = t->VVs[v]; k < t->VVs[v + 1]; k++) dirty[t->VV[k]] = 1;
}

/* one pass over shape s; dy: #V flags, a vertex is visited only if it or a
 * neighbour moved since its last visit (else the visit would find the same:
 * no move) */
static int smooth_pass(struct compat *c, const struct topology *t, const unsigned char *bnd, int s, unsigned char *dy)
{
    int moves = 0;
    {
        double *X = c->X[s];
        for (int v = 0; v < c->nv; v++) {
            if (!dy[v]) continue;
            dy[v] = 0;
            if (bnd[v] || t->VFs[v + 1] == t->VFs[v]) continue;
            struct star st;
            int big = !star_load(c, t, s, v, &st);
            /* the whole star's smallest (no floor: star_quality's value) */
            double old = big ? star_quality(c, t, s, v, X + 2 * v) : star_above(&st, X + 2 * v, -INFINITY);
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
                double thr = bq * (1 + 1e-9) + 1e-15;
                double q = big ? star_quality_above(c, t, s, v, cand[k], thr) : star_above(&st, cand[k], thr);
                if (q > thr) { bq = q; best = k; }
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

/* sine above which a triangle's smallest angle is at least 1.02 goal (2 if
 * no triangle can be: its smallest angle is at most 60 degrees) */
static double clear_sine(double goal)
{
    return goal * 1.02 < M_PI / 3 ? sin(goal * 1.02) : 2;
}

/* face f is clear of the goal in every shape: its smallest angle is at
 * least 1.02 goal (sclear = clear_sine(goal)), so face_ratio is at least
 * 1.02 (minus rounding).  The sine costs no atan2, and most faces are
 * clear once the refinement is under way. */
static int face_clear(const struct compat *c, int f, double sclear)
{
    const int *F = c->F + 3 * f;
    for (int s = 0; s < c->N; s++) {
        const double *X = c->X[s];
        if (!(compat_sin_min_angle(X + 2 * F[0], X + 2 * F[1], X + 2 * F[2]) >= sclear)) return 0;
    }
    return 1;
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
    w->id[m] = w->nextid++;
    w->sig[m] = 0;
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

/* the edge of face f whose bisection gives the new triangles the largest
 * smallest angle over every shape (kdef on a tie or if none is valid) */
static int lookahead_edge(const struct compat *c, const struct topology *t, int f, int kdef, const unsigned char *touched)
{
    const int *F = c->F + 3 * f;
    int kbest = kdef;
    double qbest = -2;
    for (int k0 = 0; k0 < 3; k0++) {
        int k = (kdef + k0) % 3;
        int e = t->FE[3 * f + k];
        int a = F[k], b = F[(k + 1) % 3], p = F[(k + 2) % 3], q = -1;
        if (t->EFn[e] == 2) {
            int f2 = t->EF[2 * e] == f ? t->EF[2 * e + 1] : t->EF[2 * e];
            if (touched[f2]) continue;
            q = third(c->F, f2, a, b);
        } else if (t->EFn[e] != 1) continue;
        double qk = INFINITY;
        for (int s = 0; s < c->N && qk > qbest; s++) {
            const double *X = c->X[s];
            double m[2] = {0.5 * (X[2 * a] + X[2 * b]), 0.5 * (X[2 * a + 1] + X[2 * b + 1])};
            double x = fmin(sin_min_valid(X + 2 * a, m, X + 2 * p), sin_min_valid(m, X + 2 * b, X + 2 * p));
            if (q >= 0) x = fmin(x, fmin(sin_min_valid(X + 2 * b, m, X + 2 * q), sin_min_valid(m, X + 2 * a, X + 2 * q)));
            qk = fmin(qk, x);
        }
        if (qk > qbest + 1e-12) { qbest = qk; kbest = k; }
    }
    return kbest;
}

static int split_pass(struct work *w, const struct compat_refine_params *pa, double frac, int look, int *nsplit, int *nbsplit)
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
    double sclear = clear_sine(goal);
    for (int f = 0; f < nf0; f++) {
        int s = 0;
        double r = face_clear(c, f, sclear) ? 2 : face_ratio(c, f, goal, open, cnt, &s);
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
    if (frac < 1) {   /* only the worst share of the triangles below the goal
                         (they come first; the too large ones after them) */
        int nl = 0;
        while (nl < nb && B[nl].r < 1 - 1e-9) nl++;
        int keep = (int)ceil(frac * nl);
        if (keep < 1) keep = 1;
        if (keep < nl) nb = keep;
    }
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
        if (look) kbest = lookahead_edge(c, &t, f, kbest, touched);
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
        for (int v = w->bsucc[i]; v >= nb0 && map[v] < 0; v = w->bsucc[v]) map[v] = k++;
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

/* what the per-pose smoothing jobs share (read-only but for their own
 * pose's positions, moves[s] and their own dirty flags) */
struct pose_jobs {
    struct compat *c;
    const struct topology *t;
    const unsigned char *bnd, *seed;
    const int *seg;
    const int *bsucc;     /* next outline vertex (for the sliding ones) */
    const int *be;        /* nbe: the outline edges' first vertices a (bnd[a], bsucc[a] >= 0), ascending */
    int nbe;
    const double *stol;   /* work.stol */
    int mips, smooth, polish; /* sweeps of each part of pose_job (0: none) */
    double goal;
    int threads;          /* compat_refine_params.threads */
    int *moves;           /* N: moves made in each pose */
    unsigned char *dirty; /* N by #V scratch flags */
    double *cost;         /* N: CPU seconds of each pose's last job (in: the order; out: measured) */
    int *order;           /* N: the poses in the order the threads take them */
};

static void pose_job(void *ctx, int s);

static double thread_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* pose_job of the i-th pose in pj->order, timed */
static void pose_job_timed(void *ctx, int i)
{
    struct pose_jobs *pj = ctx;
    int s = pj->order[i];
    double t0 = thread_seconds();
    pose_job(ctx, s);
    pj->cost[s] = thread_seconds() - t0;
}

/* pose_job over the N poses (in parallel: the poses' positions are
 * independent), the costliest in the last call first so that no long one
 * is left for the end (the time decides only which thread smooths which
 * pose, not the result); returns the sum of moves[], -1 if out of memory */
static int run_poses(struct pose_jobs *pj)
{
    struct compat *c = pj->c;
    int N = c->N;
    pj->moves = calloc(N, sizeof *pj->moves);
    pj->dirty = malloc((size_t)N * c->nv + 1);
    pj->order = malloc(N * sizeof *pj->order);
    if (!pj->moves || !pj->dirty || !pj->order) {
        free(pj->moves); free(pj->dirty); free(pj->order);
        return cm_seterr("out of memory");
    }
    for (int s = 0; s < N; s++) {   /* insertion sort by cost, descending (ties: index) */
        int k = s;
        for (; k > 0 && pj->cost[pj->order[k - 1]] < pj->cost[s]; k--) pj->order[k] = pj->order[k - 1];
        pj->order[k] = s;
    }
    parallel_run(N, pj->threads, pose_job_timed, pj);
    int m = 0;
    for (int s = 0; s < N; s++) m += pj->moves[s];
    free(pj->moves); free(pj->dirty); free(pj->order);
    return m;
}

static void smooth_job(void *ctx, int s)
{
    struct pose_jobs *pj = ctx;
    unsigned char *dy = pj->dirty + (size_t)s * pj->c->nv;
    seed_dirty(pj->t, pj->c->nv, pj->seed, dy);
    /* a pass without a move leaves no flag set: the later passes would
     * do nothing (so sweeping each pose on its own is what sweeping all
     * poses in turn did) */
    for (int k = 0; k < pj->smooth; k++) {
        int m = smooth_pass(pj->c, pj->t, pj->bnd, s, dy);
        pj->moves[s] += m;
        if (!m) break;
    }
}

/* MIPS-type energy of v's star in shape s with v at p: the sum over the
 * star of (S / (4 sqrt3 A))^2, S the sum of squared edge lengths and A the
 * area (1 for an equilateral triangle, growing without bound as a triangle
 * degenerates); gradient in g (may be NULL).  INFINITY if a triangle of the
 * star is not positive (exact).  Stops early (returning a value >= ceiling)
 * once the sum reaches ceiling (INFINITY: the whole sum). */
static double star_mips(const struct compat *c, const struct topology *t, int s, int v, const double *p,
                        double *g, double ceiling)
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
        if (E >= ceiling) return E;   /* the caller only asks whether E is below */
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

/* v's star in one shape for the MIPS step (star_mips on many positions p
 * of v): each triangle's two other corners a, b (in the triangle's order
 * after v) and what does not depend on p: a - b and its squares.  The
 * terms below are star_mips's, bit for bit: a - p = -(p - a) exactly (the
 * rounding is symmetric), so the area (a - p) x (b - p) is (p - a) x (p - b)
 * with the same products. */
struct mstar {
    int n, first;
    const double *a[STAR_MAX], *b[STAR_MAX];
    double ax[STAR_MAX], ay[STAR_MAX], bx[STAR_MAX], by[STAR_MAX];
    double abx[STAR_MAX], aby[STAR_MAX], abx2[STAR_MAX], aby2[STAR_MAX];
};

/* loads v's star in shape s; 0 if it has more than STAR_MAX triangles */
static int mstar_load(const struct compat *c, const struct topology *t, int s, int v, struct mstar *st)
{
    const double *X = c->X[s];
    int n = t->VFs[v + 1] - t->VFs[v];
    if (n > STAR_MAX) return 0;
    st->n = n;
    st->first = 0;
    for (int i = 0; i < n; i++) {
        const int *F = c->F + 3 * t->VF[t->VFs[v] + i];
        int j = F[0] == v ? 0 : F[1] == v ? 1 : 2;
        const double *a = X + 2 * F[(j + 1) % 3], *b = X + 2 * F[(j + 2) % 3];
        st->a[i] = a; st->b[i] = b;
        st->ax[i] = a[0]; st->ay[i] = a[1]; st->bx[i] = b[0]; st->by[i] = b[1];
        st->abx[i] = a[0] - b[0]; st->aby[i] = a[1] - b[1];
        st->abx2[i] = st->abx[i] * st->abx[i]; st->aby2[i] = st->aby[i] * st->aby[i];
    }
    return 1;
}

/* star_mips(c, t, s, v, p, g, INFINITY) on a loaded star: the same value
 * and gradient */
static double mstar_mips(const struct mstar *st, const double *p, double *g)
{
    double E = 0, gx = 0, gy = 0, k = 1 / (4 * sqrt(3.0));
    for (int i = 0; i < st->n; i++) {
        double pax = p[0] - st->ax[i], pay = p[1] - st->ay[i], pbx = p[0] - st->bx[i], pby = p[1] - st->by[i];
        double S = pax * pax + pay * pay + pbx * pbx + pby * pby + st->abx2[i] + st->aby2[i];
        double A = 0.5 * (pax * pby - pay * pbx);
        if (!(A > 1e-12 * S) && (A <= 0 || orient2_sign(p, st->a[i], st->b[i]) <= 0)) return INFINITY;
        double e = k * S / A;
        E += e * e;
        if (E >= INFINITY) return E;
        /* (b_x - a_x) = -(a_x - b_x) exactly */
        double dex = k * (2 * (pax + pbx) / A - S * 0.5 * st->aby[i] / (A * A));
        double dey = k * (2 * (pay + pby) / A - S * 0.5 * -st->abx[i] / (A * A));
        gx += 2 * e * dex; gy += 2 * e * dey;
    }
    g[0] = gx; g[1] = gy;
    return E;
}

/* star_mips(c, t, s, v, p, NULL, ceiling) on a loaded star: the same
 * value where it is below ceiling, else a value >= ceiling.  A step that
 * overshoots is stopped by the triangle it squeezes; that triangle's term
 * alone, looked at first, mostly reaches the ceiling already (a term is at
 * most the sum, also in floating point: the rounding of a sum of
 * non-negative terms is monotone), and the triangle is remembered.  That
 * term is surely at least ceiling where (k S)^2 >= ceiling A^2 (1 + 1e-9)
 * (the roundings of either side are far below 1e-9; the squares stay
 * normal and finite): then the division is not needed to say so. */
static double mstar_below(struct mstar *st, const double *p, double ceiling)
{
    double k = 1 / (4 * sqrt(3.0));
    for (int pass = 0; pass < 2; pass++) {
        double E = 0;
        for (int i = pass ? 0 : st->first; i < (pass ? st->n : st->first + 1); i++) {
            double pax = p[0] - st->ax[i], pay = p[1] - st->ay[i], pbx = p[0] - st->bx[i], pby = p[1] - st->by[i];
            double S = pax * pax + pay * pay + pbx * pbx + pby * pby + st->abx2[i] + st->aby2[i];
            double A = 0.5 * (pax * pby - pay * pbx);
            if (!(A > 1e-12 * S) && (A <= 0 || orient2_sign(p, st->a[i], st->b[i]) <= 0)) {
                st->first = i;
                return INFINITY;
            }
            double kS = k * S;
            if (!pass) {
                double kS2 = kS * kS, A2 = A * A;
                if (A2 > 1e-200 && kS2 < 1e200 && kS2 >= ceiling * A2 * (1 + 1e-9)) return INFINITY;
            }
            double e = kS / A;
            E += e * e;
            if (E >= ceiling) { st->first = i; return E; }
        }
        if (pass) return E;
    }
    return INFINITY;   /* not reached */
}

/* |(x, y)|: hypot without its care for overflow and for the last bit,
 * which took 9% of a profile of six stick-horse poses (coordinates here are
 * far from 1e150) */
static inline double len2(double x, double y)
{
    return sqrt(x * x + y * y);
}

/* Per-shape smoothing by the MIPS energy of star_mips: every interior
 * vertex takes a gradient step (backtracking from a quarter of its mean
 * edge length) that lowers its star's energy and keeps every triangle
 * positive (exact).  The energy is a barrier, so no triangle ever inverts;
 * it evens out the triangles of each shape as a whole, where the
 * smallest-angle smoothing only moves one vertex to a few candidates.
 * pj->mips sweeps of pose s; the moves go to pj->moves[s]. */
static void mips_job(void *ctx, int s)
{
    struct pose_jobs *pj = ctx;
    struct compat *c = pj->c;
    const struct topology *t = pj->t;
    const unsigned char *bnd = pj->bnd;
    const int *seg = pj->seg;
    unsigned char *dy = pj->dirty + (size_t)s * c->nv;
    {
        double *X = c->X[s];
        seed_dirty(t, c->nv, pj->seed, dy);
        for (int k = 0; k < pj->mips; k++) {
            int m = 0;
            for (int v = 0; v < c->nv; v++) {
                if (!dy[v]) continue;
                dy[v] = 0;
                int sl = seg && seg[2 * v] >= 0;   /* slides along its outline segment */
                if ((bnd[v] && !sl) || t->VFs[v + 1] == t->VFs[v]) continue;
                double g[2] = {0, 0}, *x = X + 2 * v;
                struct mstar st;
                st.first = st.n = 0;
                int big = !mstar_load(c, t, s, v, &st);
                double E0 = big ? star_mips(c, t, s, v, x, g, INFINITY) : mstar_mips(&st, x, g);
                double gn = len2(g[0], g[1]);
                if (!(gn > 0) || !isfinite(E0)) continue;
                double L = 0;
                int nn = t->VVs[v + 1] - t->VVs[v];
                for (int i = t->VVs[v]; i < t->VVs[v + 1]; i++)
                    L += len2(X[2 * t->VV[i]] - x[0], X[2 * t->VV[i] + 1] - x[1]);
                L /= nn;
                const double *A = sl ? X + 2 * seg[2 * v] : NULL, *B = sl ? X + 2 * seg[2 * v + 1] : NULL;
                double ux = 0, uy = 0, tv = 0, lab = 1;
                if (sl) {   /* the gradient along the segment A-B; v = A + tv (B - A) */
                    ux = B[0] - A[0]; uy = B[1] - A[1];
                    lab = len2(ux, uy);
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
                    double ceil = E0 * (1 - 1e-6);
                    if ((big ? star_mips(c, t, s, v, p, NULL, ceil) : mstar_below(&st, p, ceil)) < ceil) {
                        x[0] = p[0]; x[1] = p[1]; m++;
                        /* a step under 1% of the mean edge does not wake
                         * the neighbours (nor v): the sweeps stay where
                         * something changed */
                        if (h >= 0.01 * L) touch_star(t, v, dy);
                        break;
                    }
                }
            }
            pj->moves[s] += m;
            if (!m) break;
        }
    }
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
    struct star st;
    int big = !star_load(c, t, s, v, &st);
    double q = big ? star_quality(c, t, s, v, x) : star_above(&st, x, -INFINITY);
    if (!(q > 0)) return 0;
    int nn = t->VVs[v + 1] - t->VVs[v];
    if (!nn) return 0;
    double L = 0;
    for (int i = t->VVs[v]; i < t->VVs[v + 1]; i++)
        L += len2(X[2 * t->VV[i]] - x[0], X[2 * t->VV[i] + 1] - x[1]);
    L /= nn;
    const double *A = sl ? X + 2 * seg[2 * v] : NULL, *B = sl ? X + 2 * seg[2 * v + 1] : NULL;
    double ux = 0, uy = 0, lab = 1;
    if (sl) {
        ux = B[0] - A[0]; uy = B[1] - A[1];
        lab = len2(ux, uy);
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
            double thr = bq * (1 + 1e-9);
            double cq = big ? star_quality_above(c, t, s, v, cp, thr) : star_above(&st, cp, thr);
            if (cq > thr) { bq = cq; bp[0] = cp[0]; bp[1] = cp[1]; found = 1; }
        }
        if (found) { q = bq; p[0] = bp[0]; p[1] = bp[1]; moved = 1; }
        else h *= 0.5;
    }
    if (moved) { x[0] = p[0]; x[1] = p[1]; }
    return moved;
}

/* ---- outline vertices that slide along their input outline ---- */

/* position of the parameter u (index into B, M points, cyclic) */
static void bpoint(const double *B, int M, double u, double *p)
{
    int i = (int)floor(u);
    double t = u - i;
    i %= M;
    if (i < 0) i += M;
    const double *a = B + 2 * i, *b = B + 2 * ((i + 1) % M);
    p[0] = a[0] + t * (b[0] - a[0]);
    p[1] = a[1] + t * (b[1] - a[1]);
}

/* parameter of the point p of the polyline B near index home: the segment
 * nearest home (searching outwards) that p lies on (to rounding) */
static double bparam(const double *B, int M, int home, const double *p, double eps)
{
    double t;
    int i = compat_polyline_locate(B, M, home, p, eps, &t);
    return i < 0 ? -1 : i + t;
}

/* the parameter arc length d (signed) along B from u, clamped to [lo, hi] */
static double bseglen(const double *B, int M, double i)
{
    int k = (((int)i % M) + M) % M;
    const double *a = B + 2 * k, *b = B + 2 * ((k + 1) % M);
    return len2(b[0] - a[0], b[1] - a[1]);
}

static double bwalk(const double *B, int M, double u, double d, double lo, double hi)
{
    if (d > 0) {
        for (;;) {
            double i = floor(u), L = bseglen(B, M, i), room = (1 - (u - i)) * L;
            if (room >= d) { if (L > 0) u += d / L; break; }
            d -= room; u = i + 1;
            if (u >= hi) return hi;
        }
    } else {
        d = -d;
        for (;;) {
            double i = ceil(u) - 1, L = bseglen(B, M, i), room = (u - i) * L;
            if (room >= d) { if (L > 0) u -= d / L; break; }
            d -= room; u = i;
            if (u <= lo) return lo;
        }
    }
    return u > hi ? hi : u < lo ? lo : u;
}

/* the chord from parameter ua to ub (ua < ub) within tol of every point of
 * B strictly between them */
static int chord_ok(const double *B, int M, double ua, double ub, double tol)
{
    double pa[2], pb[2];
    bpoint(B, M, ua, pa);
    bpoint(B, M, ub, pb);
    for (int i = (int)floor(ua) + 1; i < ub; i++)
        if (compat_seg_dist(B + 2 * (((i % M) + M) % M), pa, pb) > tol) return 0;
    return 1;
}

/* Max-min polish of an outline vertex v of shape s that slides along the
 * shape's input outline (pj->seg[2v] <= -2), between the input outline
 * vertices before and after it (ap, an).  Outline vertices made by splits
 * between ap and v (and v and an) lie on the edge's segment; they keep
 * their fraction of it, so they move with v.  The pattern search of
 * polish_vertex on the arc length maximises the smallest angle over the
 * stars of every vertex that moves; each step is kept only if those stars
 * stay positive (exact), both outline edges ap-v and v-an stay within the
 * tolerance of the input points they span and cross no other outline
 * edge.  Returns 1 if v moved. */
#define SLIDE_CHAIN 64
static int polish_slide(const struct pose_jobs *pj, int s, int v)
{
    struct compat *c = pj->c;
    const struct topology *t = pj->t;
    const int *seg = pj->seg;
    double *X = c->X[s], *x = X + 2 * v;
    int M = c->nm, nx = pj->bsucc[v], pv = -1;
    const double *B = c->B[s];
    for (int i = t->VVs[v]; i < t->VVs[v + 1]; i++)
        if (pj->bnd[t->VV[i]] && pj->bsucc[t->VV[i]] == v) pv = t->VV[i];
    if (pv < 0 || nx < 0) return 0;
    int ap = seg[2 * pv] >= 0 ? seg[2 * pv] : pv, an = seg[2 * nx] >= 0 ? seg[2 * nx + 1] : nx;
    if (ap >= c->nb || an >= c->nb || ap == an || seg[2 * ap] >= 0 || seg[2 * an] >= 0) return 0;
    /* the split vertices on ap-v and v-an and their fractions */
    int ch[2 * SLIDE_CHAIN], side[2 * SLIDE_CHAIN], nch = 0;
    double fr[2 * SLIDE_CHAIN];
    for (int sd = 0; sd < 2; sd++) {
        int from = sd ? v : ap, to = sd ? an : v;
        const double *A = X + 2 * from, *Bq = X + 2 * to;
        double dx = Bq[0] - A[0], dy = Bq[1] - A[1], L2 = dx * dx + dy * dy;
        if (!(L2 > 0)) return 0;
        for (int u = pj->bsucc[from], k = 0; u != to; u = pj->bsucc[u], k++) {
            if (u < 0 || k >= SLIDE_CHAIN || seg[2 * u] < 0) return 0;
            ch[nch] = u; side[nch] = sd;
            fr[nch++] = ((X[2 * u] - A[0]) * dx + (X[2 * u + 1] - A[1]) * dy) / L2;
        }
    }
    double eps = 1e-9 * pj->stol[s] + 1e-12;
    int hv = -2 - seg[2 * v];
    int hp = seg[2 * ap] <= -2 ? -2 - seg[2 * ap] : c->bidx[ap];
    int hn = seg[2 * an] <= -2 ? -2 - seg[2 * an] : c->bidx[an];
    double uv = bparam(B, M, hv, x, eps), up = bparam(B, M, hp, X + 2 * ap, eps), un = bparam(B, M, hn, X + 2 * an, eps);
    if (uv < 0 || up < 0 || un < 0) return 0;
    /* unwrap: up < uv < un */
    while (up > uv) up -= M;
    while (un < uv) un += M;
    if (!(up < uv && uv < un) || un - up >= M) return 0;
    /* the smallest angle over the stars of v and the chain at their positions in X */
    #define SLIDE_Q(q_) do { \
        q_ = star_quality(c, t, s, v, x); \
        for (int i_ = 0; i_ < nch && q_ > 0; i_++) q_ = fmin(q_, star_quality(c, t, s, ch[i_], X + 2 * ch[i_])); \
    } while (0)
    double q;
    SLIDE_Q(q);
    if (!(q > 0)) return 0;
    double save[2 * 2 * SLIDE_CHAIN];
    for (int i = 0; i < nch; i++) { save[2 * i] = X[2 * ch[i]]; save[2 * i + 1] = X[2 * ch[i] + 1]; }
    double L = 0.5 * (hypot(X[2 * ap] - x[0], X[2 * ap + 1] - x[1]) + hypot(X[2 * an] - x[0], X[2 * an + 1] - x[1]));
    if (nch) L /= 1 + nch / 2.0;
    double u = uv, p[2] = {x[0], x[1]};
    int moved = 0;
    double lo = up + 1e-6, hi = un - 1e-6;
    for (double h = 0.2 * L; h > 1e-3 * L;) {
        double bq = q, bu = u, bp[2] = {0, 0};
        int found = 0;
        for (int k = 0; k < 2; k++) {
            double cu = bwalk(B, M, u, k ? -h : h, lo, hi), cp[2];
            if (cu == u || !(cu > up && cu < un)) continue;
            bpoint(B, M, cu, cp);
            /* v and the chain there */
            x[0] = cp[0]; x[1] = cp[1];
            for (int i = 0; i < nch; i++) {
                const double *A = side[i] ? cp : X + 2 * ap, *Bq = side[i] ? X + 2 * an : cp;
                X[2 * ch[i]] = A[0] + fr[i] * (Bq[0] - A[0]);
                X[2 * ch[i] + 1] = A[1] + fr[i] * (Bq[1] - A[1]);
            }
            double cq;
            SLIDE_Q(cq);
            int ok = cq > bq * (1 + 1e-9) && chord_ok(B, M, up, cu, pj->stol[s]) && chord_ok(B, M, cu, un, pj->stol[s]);
            /* no other outline edge touched by the two new edges */
            for (int e = 0; e < pj->nbe && ok; e++) {
                int a = pj->be[e], b = pj->bsucc[a];
                if (a == v || b == v) continue;
                int inch = 0;
                for (int i = 0; i < nch && !inch; i++) inch = a == ch[i] || b == ch[i];
                if (inch) continue;
                const double *A = X + 2 * a, *Bq = X + 2 * b;
                if (a != ap && b != ap && segments_meet(X + 2 * ap, cp, A, Bq)) ok = 0;
                else if (a != an && b != an && segments_meet(cp, X + 2 * an, A, Bq)) ok = 0;
            }
            if (ok) { bq = cq; bu = cu; bp[0] = cp[0]; bp[1] = cp[1]; found = 1; }
            /* back to the current position */
            x[0] = p[0]; x[1] = p[1];
            for (int i = 0; i < nch; i++) {
                const double *A = side[i] ? p : X + 2 * ap, *Bq = side[i] ? X + 2 * an : p;
                X[2 * ch[i]] = A[0] + fr[i] * (Bq[0] - A[0]);
                X[2 * ch[i] + 1] = A[1] + fr[i] * (Bq[1] - A[1]);
            }
            if (!moved)   /* exactly where they were */
                for (int i = 0; i < nch; i++) { X[2 * ch[i]] = save[2 * i]; X[2 * ch[i] + 1] = save[2 * i + 1]; }
        }
        if (found) {
            q = bq; u = bu; p[0] = bp[0]; p[1] = bp[1]; moved = 1;
            x[0] = p[0]; x[1] = p[1];
            for (int i = 0; i < nch; i++) {
                const double *A = side[i] ? p : X + 2 * ap, *Bq = side[i] ? X + 2 * an : p;
                X[2 * ch[i]] = A[0] + fr[i] * (Bq[0] - A[0]);
                X[2 * ch[i] + 1] = A[1] + fr[i] * (Bq[1] - A[1]);
            }
        }
        else h *= 0.5;
    }
    #undef SLIDE_Q
    return moved;
}

/* Polish of pose s: the movable vertices of triangles whose smallest
 * angle in that pose is below goal (and their neighbours) get
 * polish_vertex, in up to pj->polish sweeps while something moves; the
 * moves go to pj->moves[s]. */
static void polish_job(void *ctx, int s)
{
    struct pose_jobs *pj = ctx;
    struct compat *c = pj->c;
    const struct topology *t = pj->t;
    unsigned char *dy = pj->dirty + (size_t)s * c->nv;
    const double *X = c->X[s];
    double sg = sin(pj->goal);
    for (int k = 0; k < pj->polish; k++) {
        memset(dy, 0, c->nv);
        int any = 0;
        for (int f = 0; f < c->nf; f++) {
            const int *F = c->F + 3 * f;
            if (compat_sin_min_angle(X + 2 * F[0], X + 2 * F[1], X + 2 * F[2]) >= sg) continue;
            for (int j = 0; j < 3; j++) { touch_star(t, F[j], dy); any = 1; }
        }
        if (!any) break;
        int m = 0;
        for (int v = 0; v < c->nv; v++) {
            if (!dy[v] || t->VFs[v + 1] == t->VFs[v]) continue;
            if (pj->bnd[v] && pj->stol && pj->seg[2 * v] <= -2) { m += polish_slide(pj, s, v); continue; }
            if (pj->bnd[v] && !(pj->seg && pj->seg[2 * v] >= 0)) continue;
            m += polish_vertex(c, t, s, v, pj->seg);
        }
        pj->moves[s] += m;
        if (!m) break;
    }
}

/* The smoothing of one pose: the MIPS sweeps, then the candidate
 * smoothing, then the max-min polish (each with its number of sweeps in pj,
 * 0: skipped).  A pose's parts follow each other without waiting for the
 * other poses: each part reads only the topology and its own pose, so the
 * mesh is the one of running each part over every pose in turn, and the
 * threads wait for each other once instead of once per part. */
static void pose_job(void *ctx, int s)
{
    struct pose_jobs *pj = ctx;
    if (pj->mips) mips_job(ctx, s);
    if (pj->smooth) smooth_job(ctx, s);
    if (pj->polish) polish_job(ctx, s);
}

/* pose_job on every pose (mips, smooth, polish: sweeps of each part; seed:
 * #V flags of the vertices whose neighbourhood changed since the last
 * smoothing, NULL: all; the MIPS and candidate smoothing visit only them
 * and whatever their moves disturb; cost: N, each pose's CPU seconds in
 * the last call, updated).  Returns the number of moves, -1 on error. */
static int smooth_poses(struct compat *c, const struct work *w, const unsigned char *seed,
                        double goal, int mips, int smooth, int polish, int threads, double *cost)
{
    struct topology t;
    int *be = malloc((c->nv ? c->nv : 1) * sizeof *be), nbe = 0;
    if (!be) return cm_seterr("out of memory");
    for (int a = 0; a < c->nv; a++)
        if (w->bnd[a] && w->bsucc[a] >= 0) be[nbe++] = a;
    if (topology_build(c->F, c->nf, c->nv, &t) < 0) { free(be); return -1; }
    struct pose_jobs pj = {.c = c, .t = &t, .bnd = w->bnd, .seed = seed, .seg = w->seg, .bsucc = w->bsucc,
                           .be = be, .nbe = nbe,
                           .stol = w->slide_now ? w->stol : NULL, .mips = mips, .smooth = smooth,
                           .polish = polish, .goal = goal, .threads = threads, .cost = cost};
    int moves = run_poses(&pj);
    topology_free(&t);
    free(be);
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
    return compat_flip_passes(c, 50, nflips);
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

/* One pass of compatible edge collapses: a vertex v is merged into a
 * neighbour u (v's triangles that hold u vanish, the others take u for v)
 * if the link condition holds (u and v share exactly two neighbours, one
 * for an outline edge), every changed triangle stays positive in every
 * shape (exact) and
 *   coarsen == 0: v is in a triangle below goal (in some shape) and the
 *                 smallest angle over the changed triangles and shapes is
 *                 larger than that of v's star (undoes the tiny pieces
 *                 that overlays leave, and splits that did not help);
 *   coarsen == 1: any such v, and that smallest angle is not below the
 *                 smaller of v's star's and the goal (good triangles stay
 *                 good, none gets worse than it was): fewer vertices.
 * v is an interior vertex, or an outline vertex made by a split (it lies
 * on an input outline segment and is merged into its neighbour along the
 * outline, so the outline is unchanged).  Input outline vertices and
 * interior correspondence points stay.  Of the u that qualify the one
 * giving the best smallest angle is taken.  Vertices near a collapse wait
 * for the next pass (the topology is stale there).  dead: #V flags of
 * removed vertices.  Returns the number of collapses, -1 on error. */
static int collapse_pass(struct work *w, unsigned char *dead, double goal, int coarsen, int maxid)
{
    struct compat *c = w->c;
    struct topology t;
    if (topology_build(c->F, c->nf, c->nv, &t) < 0) return -1;
    unsigned char *lock = calloc(c->nv ? c->nv : 1, 1);
    /* face_sin of every face as the pass starts: a vertex that is looked
     * at is not locked, so no collapse has changed a face of its star (the
     * faces a collapse changes hold only the locked vertices) */
    double *fq = malloc((c->nf ? c->nf : 1) * sizeof *fq);
    if (!lock || !fq) { free(lock); free(fq); topology_free(&t); return cm_seterr("out of memory"); }
    for (int f = 0; f < c->nf; f++) fq[f] = face_sin(c, c->F[3 * f], c->F[3 * f + 1], c->F[3 * f + 2]);
    double sg = sin(goal);
    int n = 0;
    for (int v = 0; v < c->nv; v++) {
        int onb = w->bnd[v];
        if (onb && w->seg[2 * v] < 0) continue;   /* input outline vertex */
        if (dead[v] || lock[v] || t.VFs[v + 1] == t.VFs[v] || w->id[v] >= maxid) continue;
        double old = INFINITY;
        for (int k = t.VFs[v]; k < t.VFs[v + 1]; k++) old = fmin(old, fq[t.VF[k]]);
        if (!coarsen && !(old < sg)) continue;
        int bu = -1, pred = -1;
        double floor = coarsen ? fmin(old, sg) : old, bq = -1;
        for (int i = t.VVs[v]; i < t.VVs[v + 1]; i++) {
            int u = t.VV[i];
            if (dead[u] || lock[u]) continue;
            if (w->bsucc[u] == v) pred = u;
            int e = topology_edge(&t, u, v);
            if (onb != (t.EFn[e] == 1)) continue;       /* an outline vertex moves along the outline */
            /* link condition */
            int common = 0;
            for (int j = t.VVs[v]; j < t.VVs[v + 1]; j++)
                if (topology_edge(&t, u, t.VV[j]) >= 0) common++;
            if (common != (onb ? 1 : 2)) continue;
            double q = INFINITY;
            int gone = 0;
            for (int k = t.VFs[v]; k < t.VFs[v + 1] && q > floor && q > bq; k++) {
                const int *F = c->F + 3 * t.VF[k];
                if (F[0] == u || F[1] == u || F[2] == u) { gone++; continue; }
                int G[3];
                for (int j = 0; j < 3; j++) G[j] = F[j] == v ? u : F[j];
                q = fmin(q, face_sin(c, G[0], G[1], G[2]));
            }
            if (gone != (onb ? 1 : 2)) continue;
            if ((coarsen ? q >= floor : q > floor) && q > 0 && q > bq) { bq = q; bu = u; }
        }
        if (bu < 0) continue;
        if (onb) {   /* keep the outline order */
            if (w->bsucc[v] == bu) { if (pred < 0) continue; w->bsucc[pred] = bu; }
            else w->bsucc[bu] = w->bsucc[v];
        }
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
    free(lock); free(fq);
    topology_free(&t);
    return n;
}

/* collapses (collapse_pass) until none is made, then the removed vertices
 * are dropped (vertices keep their order, so the fixed ones 0..nb-1 keep
 * their numbers); only vertices whose id is below maxid are removed.
 * *nv0: vertices below it are the input's (outline,
 * Steiner points); it is lowered by the input vertices removed.  Returns
 * the number of vertices removed, -1 on error. */
static int collapse_all(struct work *w, double goal, int coarsen, int maxid, int *nv0)
{
    struct compat *c = w->c;
    unsigned char *dead = calloc(c->nv ? c->nv : 1, 1);
    if (!dead) return cm_seterr("out of memory");
    int total = 0;
    for (int pass = 0; pass < 50; pass++) {
        int n = collapse_pass(w, dead, goal, coarsen, maxid);
        if (n < 0) { free(dead); return -1; }
        total += n;
        if (!n) break;
    }
    if (total) {
        int *map = malloc(c->nv * sizeof *map), k = 0, lost = 0;
        if (!map) { free(dead); return cm_seterr("out of memory"); }
        for (int v = 0; v < c->nv; v++) {
            map[v] = dead[v] ? -1 : k++;
            lost += dead[v] && v < *nv0;
        }
        for (int v = 0; v < c->nv; v++) {
            if (dead[v]) continue;
            for (int s = 0; s < c->N; s++) {
                c->X[s][2 * map[v]] = c->X[s][2 * v];
                c->X[s][2 * map[v] + 1] = c->X[s][2 * v + 1];
            }
            w->bnd[map[v]] = w->bnd[v];
            w->bsucc[map[v]] = w->bsucc[v] >= 0 ? map[w->bsucc[v]] : -1;
            w->id[map[v]] = w->id[v];
            w->sig[map[v]] = w->sig[v];
            w->seg[2 * map[v]] = w->seg[2 * v];           /* input outline vertices: */
            w->seg[2 * map[v] + 1] = w->seg[2 * v + 1];   /* never removed, same numbers */
        }
        for (int f = 0; f < 3 * c->nf; f++) c->F[f] = map[c->F[f]];
        c->nv = k;
        *nv0 -= lost;
        free(map);
    }
    free(dead);
    return total;
}

static unsigned long long mix64(unsigned long long x)
{
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

/* signature of every vertex's star (sum of a hash of each incident face's
 * vertex ids, in the face's cyclic order from its smallest id): it changes
 * when a split, flip or collapse changes the star, whatever the vertex
 * numbers.  out: #V */
static void star_sigs(const struct work *w, unsigned long long *out)
{
    const struct compat *c = w->c;
    memset(out, 0, c->nv * sizeof *out);
    for (int f = 0; f < c->nf; f++) {
        const int *F = c->F + 3 * f;
        int a = w->id[F[0]], b = w->id[F[1]], d = w->id[F[2]], k = a < b ? (a < d ? 0 : 2) : (b < d ? 1 : 2);
        int I[3] = {a, b, d};
        unsigned long long h = mix64(mix64(mix64((unsigned)I[k]) ^ (unsigned)I[(k + 1) % 3]) ^ (unsigned)I[(k + 2) % 3]);
        for (int j = 0; j < 3; j++) out[F[j]] += h;
    }
}

/* Worst face of the mesh measured against what each corner allows
 * (face_ratio): returns that ratio (1: every angle reaches the goal or all
 * its corner can give), *wf / *ws the face and shape where it is, *nbad
 * the number of faces below 1 (the goal).  -1 on
 * out of memory. */
static double worst_ratio(struct work *w, double goal, int *wf, int *ws, int *nbad)
{
    struct compat *c = w->c;
    double *open = malloc((size_t)c->N * (c->nv ? c->nv : 1) * sizeof *open);
    int *cnt = malloc((c->nv ? c->nv : 1) * sizeof *cnt);
    if (!open || !cnt) { free(open); free(cnt); cm_seterr("out of memory"); return -1; }
    corner_openings(c, w->bnd, open, cnt);
    double r = INFINITY, sclear = clear_sine(goal);
    *wf = *ws = *nbad = 0;
    /* faces clear of the goal (ratio >= 1.02) can be neither the worst nor
     * below the goal while some face is under 1.01: skip them, and look at
     * every face only when none is */
    for (int pass = 0; pass < 2 && !(r <= 1.01); pass++) {
        r = INFINITY;
        *wf = *ws = *nbad = 0;
        for (int f = 0; f < c->nf; f++) {
            if (!pass && face_clear(c, f, sclear)) continue;
            int s = 0;
            double x = face_ratio(c, f, goal, open, cnt, &s);
            if (x < r) { r = x; *wf = f; *ws = s; }
            *nbad += x < 1 - 1e-9;
        }
    }
    free(open); free(cnt);
    return r;
}

/* the mesh and the work arrays, for going back to the best round */
struct best { int nv, nf, nv0; double **X; int *F; unsigned char *bnd; int *bsucc, *seg; };

static int best_take(const struct work *w, int nv0, struct best *b)
{
    const struct compat *c = w->c;
    size_t nv = c->nv ? c->nv : 1;
    if (!b->X && !(b->X = calloc(c->N, sizeof *b->X))) return cm_seterr("out of memory");
    for (int s = 0; s < c->N; s++) {
        double *x = realloc(b->X[s], 2 * nv * sizeof *x);
        if (!x) return cm_seterr("out of memory");
        b->X[s] = x;
        memcpy(x, c->X[s], 2 * (size_t)c->nv * sizeof *x);
    }
    int *F = realloc(b->F, 3 * (size_t)(c->nf ? c->nf : 1) * sizeof *F);
    unsigned char *bn = realloc(b->bnd, nv);
    if (F) b->F = F;
    if (bn) b->bnd = bn;
    int *bs = realloc(b->bsucc, nv * sizeof *bs);
    if (bs) b->bsucc = bs;
    int *sg = realloc(b->seg, 2 * nv * sizeof *sg);
    if (sg) b->seg = sg;
    if (!F || !bn || !bs || !sg) return cm_seterr("out of memory");
    memcpy(b->F, c->F, 3 * (size_t)c->nf * sizeof *F);
    memcpy(b->bnd, w->bnd, c->nv);
    memcpy(b->bsucc, w->bsucc, c->nv * sizeof *bs);
    memcpy(b->seg, w->seg, 2 * (size_t)c->nv * sizeof *sg);
    b->nv = c->nv; b->nf = c->nf; b->nv0 = nv0;
    return 0;
}

/* back to b (c has room: it only grew since) */
static void best_restore(struct work *w, const struct best *b, int *nv0)
{
    struct compat *c = w->c;
    c->nv = b->nv; c->nf = b->nf; *nv0 = b->nv0;
    for (int s = 0; s < c->N; s++) memcpy(c->X[s], b->X[s], 2 * (size_t)b->nv * sizeof **b->X);
    memcpy(c->F, b->F, 3 * (size_t)b->nf * sizeof *c->F);
    memcpy(w->bnd, b->bnd, b->nv);
    memcpy(w->bsucc, b->bsucc, b->nv * sizeof *w->bsucc);
    memcpy(w->seg, b->seg, 2 * (size_t)b->nv * sizeof *w->seg);
}

static void best_free(int N, struct best *b)
{
    if (b->X) for (int s = 0; s < N; s++) free(b->X[s]);
    free(b->X); free(b->F); free(b->bnd); free(b->bsucc); free(b->seg);
}

/* how anisotropic the maps between the shapes are on face f: the largest
 * ratio of the singular values of the affine map from shape s to shape t
 * over all pairs (1: every shape a similar copy) */
static double face_stretch(const struct compat *c, int f)
{
    const int *F = c->F + 3 * f;
    double worst = 1;
    for (int s = 0; s < c->N; s++) {
        const double *X = c->X[s];
        double a = X[2 * F[1]] - X[2 * F[0]], b = X[2 * F[2]] - X[2 * F[0]];
        double cc = X[2 * F[1] + 1] - X[2 * F[0] + 1], d = X[2 * F[2] + 1] - X[2 * F[0] + 1];
        double det = a * d - b * cc;
        if (!(det != 0)) continue;
        /* inverse of [a b; cc d] */
        double ia = d / det, ib = -b / det, ic = -cc / det, id = a / det;
        for (int t = 0; t < c->N; t++) {
            if (t == s) continue;
            const double *Y = c->X[t];
            double p = Y[2 * F[1]] - Y[2 * F[0]], q = Y[2 * F[2]] - Y[2 * F[0]];
            double r = Y[2 * F[1] + 1] - Y[2 * F[0] + 1], u = Y[2 * F[2] + 1] - Y[2 * F[0] + 1];
            /* M = [p q; r u] * inverse */
            double m0 = p * ia + q * ic, m1 = p * ib + q * id, m2 = r * ia + u * ic, m3 = r * ib + u * id;
            double fro = m0 * m0 + m1 * m1 + m2 * m2 + m3 * m3, dt = fabs(m0 * m3 - m1 * m2);
            double disc = sqrt(fmax(0, fro * fro - 4 * dt * dt));
            double s1 = sqrt(0.5 * (fro + disc)), s2 = sqrt(fmax(0, 0.5 * (fro - disc)));
            if (s2 > 0) worst = fmax(worst, s1 / s2);
            else worst = INFINITY;
        }
    }
    return worst;
}

/* the state of one refinement between rounds (compat_refine_begin) */
struct compat_refiner {
    struct compat *c;
    struct compat_refine_params pa;
    struct compat_refine_stats *st, own;
    struct snapshot snap;     /* the input, kept if refinement made it worse */
    struct best best;         /* the round with the best worst angle */
    struct best polished;     /* the polished mesh of the last stall */
    double wpolished;         /* its worst ratio to the goal */
    int cycles;               /* stalls answered by a polish and more rounds */
    struct work w;
    double q0;                /* the input's worst angle (sine) */
    double wbest, wcur;       /* best and last worst ratio to the goal */
    int nb0, nv0;             /* the input's boundary and vertex counts */
    int full;                 /* 1 until the first round: smooth everything */
    int remesh;               /* pa.mips > 0: collapses, stall rule, best round */
    int nvin;                 /* vertices below it are the input's */
    int stall, wf, ws, capped, nbad, nbest;
    int nbad_prev;            /* nbad after the round before (INT_MAX: none) */
    int done;                 /* 1 once the splitting stopped (st->stop) */
    unsigned char *seed;
    unsigned long long *sig;
    /* the second pass (pa.split_share < 1): the first pass's result, the
     * start to go back to, and the rounds of the current pass */
    int pass;                 /* 0: every bad triangle split; 1: the share */
    int prounds;              /* rounds of the current pass */
    struct best start;        /* the mesh after compat_refine_begin */
    int start_nvin, start_nextid;
    int *start_id;
    unsigned long long *start_sig;
    struct best alt;          /* the best earlier pass's result (settled, or
                                 not yet: alt_raw) */
    double walt;              /* its worst ratio to the goal */
    int alt_raw;              /* 1: alt is a first pass cut short
                                 (COMPAT_REFINE_GROWING), its best round
                                 without the final polish (settle_alt) */
    struct compat_refine_stats alt_stats;   /* the first pass's stop reason */
    int settled;              /* 1: the first pass settled at the goal (finish
                                 must not polish it again) */
};

static void refiner_free(struct compat_refiner *r)
{
    struct work *w = &r->w;
    snap_free(r->c->N, &r->snap);
    best_free(r->c->N, &r->best);
    best_free(r->c->N, &r->polished);
    best_free(r->c->N, &r->start);
    best_free(r->c->N, &r->alt);
    free(r->start_id); free(r->start_sig);
    free(w->bnd); free(w->bsucc); free(w->seg); free(w->diag); free(w->stol); free(w->pose_cost); free(w->id); free(w->sig);
    free(r->sig); free(r->seed);
    free(r);
}

struct compat_refiner *compat_refine_begin(struct compat *c, const struct compat_refine_params *pa,
                                           struct compat_refine_stats *st)
{
    struct compat_refiner *r = calloc(1, sizeof *r);
    if (!r) { cm_seterr("out of memory"); return NULL; }
    r->c = c;
    r->pa = *pa;
    r->st = st ? st : &r->own;
    memset(r->st, 0, sizeof *r->st);
    r->q0 = compat_min_angle(c, NULL);
    r->w = (struct work){.c = c};
    r->nb0 = c->nb;
    r->nv0 = c->nv;
    struct work *w = &r->w;
    w->diag = malloc(c->N * sizeof *w->diag);
    w->pose_cost = calloc(3 * (size_t)c->N, sizeof *w->pose_cost);
    if (!w->diag || !w->pose_cost) { cm_seterr("out of memory"); goto fail; }
    for (int s = 0; s < c->N; s++) w->diag[s] = polygon_diagonal(c->X[s], c->nb);
    if (snap_take(c, &r->snap) < 0 || grow_v(w, c->nv) < 0) goto fail;
    /* boundary flags and successors from the faces */
    memset(w->bnd, 0, c->nv);
    for (int v = 0; v < c->nv; v++) {
        w->bsucc[v] = w->seg[2 * v] = w->seg[2 * v + 1] = -1;
        w->id[v] = v;
        w->sig[v] = 0;
    }
    w->nextid = c->nv;
    if (pa->slide > 0 && pa->mips > 0 && c->bidx && c->B && c->nrings == 0 && c->npts == 0 && c->nb >= 3) {
        /* outline vertices that slide along their input outline */
        w->stol = malloc(c->N * sizeof *w->stol);
        if (!w->stol) { cm_seterr("out of memory"); goto fail; }
        for (int s = 0; s < c->N; s++) w->stol[s] = pa->slide * polygon_diagonal(c->B[s], c->nm);
        for (int v = 0; v < c->nb; v++)
            if (!(c->bpin && c->bpin[v])) w->seg[2 * v] = -2 - c->bidx[v];
        w->slide_now = pa->slide_first;
    }
    {
        struct topology t;
        if (topology_build(c->F, c->nf, c->nv, &t) < 0) goto fail;
        for (int e = 0; e < t.ne; e++) {
            if (t.EFn[e] != 1) continue;
            int a = t.E[2 * e], b = t.E[2 * e + 1], f = t.EF[2 * e];
            if (!runs(c->F, f, a, b)) { int x = a; a = b; b = x; }
            w->bnd[a] = w->bnd[b] = 1;
            w->bsucc[a] = b;
        }
        topology_free(&t);
        /* interior correspondence points (compat_holes) never move either */
        for (int v = 0; v < c->nb; v++) w->bnd[v] = 1;
    }
    /* after the first round only what splits, flips and collapses changed
     * is smoothed (seed: vertices whose star signature differs from w.sig,
     * taken after the last smoothing; new vertices) */
    r->full = 1;
    r->remesh = pa->mips > 0;
    r->nvin = r->nv0;
    if (r->remesh) {
        int k = collapse_all(w, pa->goal, 0, INT_MAX, &r->nvin);
        if (k < 0) goto fail;
        r->st->collapses = k;
    }
    r->wbest = r->wcur = -1;
    r->nbest = r->nbad_prev = INT_MAX;
    r->st->stop = COMPAT_REFINE_ROUNDS;
    r->done = pa->rounds <= 0;
    if (r->remesh && pa->split_share > 0 && pa->split_share < 1) {   /* for the second pass */
        if (best_take(w, r->nvin, &r->start) < 0) goto fail;
        r->start_id = malloc((c->nv ? c->nv : 1) * sizeof *r->start_id);
        r->start_sig = malloc((c->nv ? c->nv : 1) * sizeof *r->start_sig);
        if (!r->start_id || !r->start_sig) { cm_seterr("out of memory"); goto fail; }
        memcpy(r->start_id, w->id, c->nv * sizeof *w->id);
        memcpy(r->start_sig, w->sig, c->nv * sizeof *w->sig);
        r->start_nvin = r->nvin;
        r->start_nextid = w->nextid;
    }
    return r;
fail:
    refiner_free(r);
    return NULL;
}

/* the global max-min polish (maxmin_polish) of every pose whose smallest
 * angle is below the goal, the poses on the threads (their positions are
 * independent) */
struct gpolish { struct compat *c; const unsigned char *bnd; const int *seg; double goal; int *rc;
                 const int *bsucc; const double *stol; };

static void gpolish_job(void *ctx, int s)
{
    struct gpolish *gp = ctx;
    struct compat *c = gp->c;
    double mn;
    compat_pose_quality(c, s, &mn, NULL, NULL);
    if (mn >= gp->goal) return;
    struct maxmin_params mp;
    maxmin_defaults(&mp);
    if (!gp->stol) {
        gp->rc[s] = maxmin_polish(c->X[s], c->nv, c->F, c->nf, gp->bnd, gp->seg, &mp, NULL, NULL);
        return;
    }
    /* the outline vertices that are not given points slide along the
     * pose's input outline too (their home: the index in c->B they were
     * simplified to; the given points' knots are fixed on theirs) */
    int nv = c->nv, *home = malloc((nv ? nv : 1) * sizeof *home);
    unsigned char *sl = malloc(nv ? nv : 1);
    if (!home || !sl) { free(home); free(sl); gp->rc[s] = cm_seterr("out of memory"); return; }
    for (int v = 0; v < nv; v++) {
        int sv = gp->seg[2 * v];
        sl[v] = gp->bsucc[v] >= 0 && sv <= -2;
        home[v] = gp->bsucc[v] < 0 || sv >= 0 ? -1 : sl[v] ? -2 - sv : v < c->nb ? c->bidx[v] : -1;
    }
    struct maxmin_curve cv = {.B = c->B[s], .M = c->nm, .bsucc = gp->bsucc, .home = home, .slides = sl,
                              .tol = gp->stol[s]};
    gp->rc[s] = maxmin_polish_curve(c->X[s], nv, c->F, c->nf, gp->bnd, gp->seg, &cv, &mp, NULL, NULL);
    free(home);
    free(sl);
}

/* returns the number of poses moved, -1 on error */
static int global_polish(struct compat *c, const unsigned char *bnd, const int *seg, const int *bsucc,
                         const double *stol, double goal, int threads)
{
    int *rc = calloc(c->N, sizeof *rc), n = 0;
    if (!rc) return cm_seterr("out of memory");
    struct gpolish gp = {.c = c, .bnd = bnd, .seg = seg, .goal = goal, .rc = rc, .bsucc = bsucc, .stol = stol};
    parallel_run(c->N, threads, gpolish_job, &gp);
    for (int s = 0; s < c->N; s++) {
        if (rc[s] < 0) n = -1;
        if (n >= 0) n += rc[s];
    }
    free(rc);
    return n;
}

/* The final polish: with remeshing, edge collapses that keep every good
 * triangle good and make no triangle worse first.  Four sweeps, then
 * (remeshing, still below the goal) more while each raises the worst
 * angle by COMPAT_REFINE_GAIN: the max-min polish is local, and where the
 * maps are stretched it goes on gaining for a while.  0, or -1 on error. */
static int final_polish(struct compat_refiner *r)
{
    struct compat *c = r->c;
    struct compat_refine_stats *st = r->st;
    const struct compat_refine_params *pa = &r->pa;
    struct work *w = &r->w;
    double goal = pa->goal;
    double wprev = -1;
    for (int k = 0; k < COMPAT_REFINE_POLISH_MAX; k++) {
        if (k >= 4) {
            if (!r->remesh) break;
            int wf, ws, nb;
            double wk = worst_ratio(w, goal, &wf, &ws, &nb);
            if (wk < 0) return -1;
            if (wk >= 1 || (wprev >= 0 && wk < wprev + COMPAT_REFINE_GAIN / goal)) break;
            wprev = wk;
        }
        int m = 0;
        if (r->remesh) {
            m = collapse_all(w, goal, 1, INT_MAX, &r->nvin);
            if (m < 0) return -1;
            st->collapses += m;
            st->coarsened += m;
        }
        /* the candidate smoothing, then (with MIPS) the polish */
        int m1 = smooth_poses(c, w, NULL, goal, 0, 8, pa->mips > 0 ? 4 : 0, pa->threads, w->pose_cost + 2 * c->N);
        if (m1 < 0) return -1;
        st->moves += m1;
        m += m1;
        int f0 = st->flips;
        if (flips_until_done(c, &st->flips) < 0) return -1;
        if (st->flips == f0 && m == 0) break;
    }
    return 0;
}

static int refine_round(struct compat_refiner *r)
{
    if (r->done) return 0;
    struct compat *c = r->c;
    struct compat_refine_stats *st = r->st;
    const struct compat_refine_params *pa = &r->pa;
    struct work *w = &r->w;
    double goal = pa->goal;
    st->rounds++;
    r->prounds++;
    if (flips_until_done(c, &st->flips) < 0) return -1;
    free(r->seed);
    r->seed = NULL;
    if (!r->full) {
        r->seed = malloc(c->nv);
        unsigned long long *sn = realloc(r->sig, c->nv * sizeof *sn);
        if (sn) r->sig = sn;
        if (!r->seed || !sn) return cm_seterr("out of memory");
        star_sigs(w, r->sig);
        for (int v = 0; v < c->nv; v++) r->seed[v] = r->sig[v] != w->sig[v];
    }
    int m = smooth_poses(c, w, r->seed, goal, pa->mips > 0 ? pa->mips : 0, 8, 0, pa->threads, w->pose_cost);
    if (m < 0) return -1;
    st->moves += m;
    if (pa->mips > 0) {
        if (flips_until_done(c, &st->flips) < 0) return -1;
        m = smooth_poses(c, w, NULL, goal, 0, 0, 4, pa->threads, w->pose_cost + c->N);
        if (m < 0) return -1;
        st->moves += m;
    }
    /* the ARAP transfer between shapes: with the MIPS smoothing it was
     * never kept (creature and elephant poses), so it runs without */
    int tc = pa->mips > 0 ? 0 : transfer(c, w->bnd, goal, &st->moves);
    if (tc < 0) return -1;
    if (tc > 0) {   /* whole shapes moved */
        m = smooth_poses(c, w, NULL, goal, 0, 8, 0, pa->threads, w->pose_cost + 2 * c->N);
        if (m < 0) return -1;
        st->moves += m;
    }
    r->full = 0;
    if (flips_until_done(c, &st->flips) < 0) return -1;
    if (r->remesh) {   /* the input's pieces that smoothing left bad (undoing
                          splits here would only have them made again) */
        int k = collapse_all(w, goal, 0, r->nv0, &r->nvin);
        if (k < 0) return -1;
        st->collapses += k;
        if (k && flips_until_done(c, &st->flips) < 0) return -1;
    }
    r->wcur = worst_ratio(w, goal, &r->wf, &r->ws, &r->nbad);
    if (r->wcur < 0) return -1;
    if (r->wcur >= 1) { st->stop = COMPAT_REFINE_GOAL; r->done = 1; return 0; }
    /* the first pass of a refinement with a second (split_share): its bad
     * triangles grow with its vertices (COMPAT_REFINE_GROWING) */
    int growing = pa->grow && r->pass == 0 && r->remesh && r->start.nv && r->prounds >= COMPAT_REFINE_GROW_ROUND &&
                  r->nbad > r->nbad_prev && 2 * (long)r->nbad >= c->nv;
    r->nbad_prev = r->nbad;
    if (growing) { st->stop = COMPAT_REFINE_GROWING; st->grown = r->prounds; r->done = 1; return 0; }
    /* progress: the worst angle rose, or fewer triangles are below
     * the goal (where the maps between the shapes are stretched,
     * splits only make more bad triangles) */
    int better = r->nbad < 0.95 * r->nbest;
    if (r->nbad < r->nbest) r->nbest = r->nbad;
    if (r->wcur > r->wbest + COMPAT_REFINE_GAIN / goal) {
        r->wbest = r->wcur;
        better = 1;
        if (r->remesh && best_take(w, r->nvin, &r->best) < 0) return -1;
    }
    /* stalled: several rounds without progress that doubled the best
     * round's vertices (cheap local rounds go on longer: near the
     * goal the worst angle and the bad count jitter for a while) */
    if (better) r->stall = 0;
    else if (++r->stall >= COMPAT_REFINE_STALL && r->remesh &&
             (c->nv > 2 * r->best.nv || r->stall >= 4 * COMPAT_REFINE_STALL)) {
        if (r->cycles < COMPAT_REFINE_CYCLES) {
            /* stalled: back to the best round, the final polish on it
             * (kept as the result unless later rounds beat it), then
             * rounds again from the polished mesh.  The polish moves
             * vertices the rounds' smoothing left, the coarsening takes
             * out splits that did not help, and the next splits start
             * from there. */
            r->cycles++;
            st->cycles = r->cycles;
            if (r->best.nv && r->wbest > r->wcur) best_restore(w, &r->best, &r->nvin);
            if (final_polish(r) < 0) return -1;
            r->wcur = worst_ratio(w, goal, &r->wf, &r->ws, &r->nbad);
            if (r->wcur < 0) return -1;
            if (r->wcur >= 1) { st->stop = COMPAT_REFINE_GOAL; r->done = 1; return 0; }
            if (best_take(w, r->nvin, &r->polished) < 0) return -1;
            r->wpolished = r->wcur;
            if (r->wcur > r->wbest && best_take(w, r->nvin, &r->best) < 0) return -1;
            if (r->wcur > r->wbest) r->wbest = r->wcur;
            r->stall = 0;
            r->nbest = r->nbad;
            r->full = 1;
        } else {
            st->stop = COMPAT_REFINE_STALLED;
            r->done = 1;
            return 0;
        }
    }
    if (c->nv >= pa->max_nv || r->capped) { st->stop = COMPAT_REFINE_MAXNV; r->done = 1; return 0; }
    star_sigs(w, w->sig);
    /* after the first rounds, only the worst share of the triangles below
     * the goal (compat_refine_params.split_share) */
    double frac = 1;
    if (r->pass && r->prounds > COMPAT_REFINE_FULL_SPLITS) frac = pa->split_share;
    int n = split_pass(w, pa, frac, r->pass == 2, &st->splits, &st->bsplits);
    if (n < 0) return -1;
    if (n == 0) { st->stop = COMPAT_REFINE_NOSPLIT; r->done = 1; return 0; }
    r->capped = c->nv >= pa->max_nv;   /* smoothed once more, then stop */
    if (st->rounds >= pa->rounds) { r->done = 1; return 0; }
    return 1;
}

/* the end of a pass: back to the best round if the later ones only added
 * vertices, then (polish) the final polish, and back to the polished mesh
 * of a stall if the later rounds ended below it.  0 or -1. */
static int settle(struct compat_refiner *r, int polish)
{
    struct work *w = &r->w;
    double goal = r->pa.goal;
    if (r->remesh && r->best.nv && r->wbest > r->wcur) {
        best_restore(w, &r->best, &r->nvin);
        r->st->restored = 1;
    }
    if (!polish) return 0;
    if (final_polish(r) < 0) return -1;
    if (r->polished.nv) {
        int wf, ws, nb;
        double wk = worst_ratio(w, goal, &wf, &ws, &nb);
        if (wk < 0) return -1;
        if (r->wpolished >= wk) {
            best_restore(w, &r->polished, &r->nvin);
            r->st->restored = 1;
        }
    }
    return 0;
}

/* the final polish of alt kept raw (alt_raw), as settle gives it at the end
 * of its pass; the working mesh is back as it was after it.  0 or -1. */
static int settle_alt(struct compat_refiner *r)
{
    struct work *w = &r->w;
    struct compat *c = r->c;
    struct best cur;
    memset(&cur, 0, sizeof cur);
    int *id = malloc((c->nv ? c->nv : 1) * sizeof *id), nv = c->nv, slide = w->slide_now, rc = -1;
    if (!id) return cm_seterr("out of memory");
    memcpy(id, w->id, nv * sizeof *id);
    if (best_take(w, r->nvin, &cur) < 0) goto out;
    best_restore(w, &r->alt, &r->nvin);
    w->slide_now = w->stol && r->pa.slide_first;   /* as in the first pass */
    rc = final_polish(r);
    w->slide_now = slide;
    if (rc == 0) {
        int wf, ws, nb;
        r->walt = worst_ratio(w, r->pa.goal, &wf, &ws, &nb);
        rc = r->walt < 0 ? -1 : best_take(w, r->nvin, &r->alt);
    }
    best_restore(w, &cur, &r->nvin);
    memcpy(w->id, id, nv * sizeof *id);
    r->alt_raw = 0;
out:
    best_free(c->N, &cur);
    free(id);
    return rc;
}

/* back to the mesh after compat_refine_begin for the next pass */
static int restart(struct compat_refiner *r, int pass)
{
    struct work *w = &r->w;
    struct compat *c = r->c;
    struct compat_refine_stats *st = r->st;
    best_restore(w, &r->start, &r->nvin);
    memcpy(w->id, r->start_id, c->nv * sizeof *w->id);
    memcpy(w->sig, r->start_sig, c->nv * sizeof *w->sig);
    w->nextid = r->start_nextid;
    r->nvin = r->start_nvin;
    best_free(c->N, &r->best);
    best_free(c->N, &r->polished);
    memset(&r->best, 0, sizeof r->best);
    memset(&r->polished, 0, sizeof r->polished);
    r->wpolished = 0;
    r->cycles = 0;
    r->wbest = r->wcur = -1;
    r->nbest = r->nbad_prev = INT_MAX;
    r->stall = r->capped = 0;
    r->full = 1;
    r->prounds = 0;
    r->pass = pass;
    w->slide_now = w->stol && (pass >= 1 || r->pa.slide_first);
    r->done = r->st->rounds >= r->pa.rounds;
    st->stop = COMPAT_REFINE_ROUNDS;
    st->cycles = 0;
    st->restored = 0;
    st->rerun = pass == 1 ? 1 : 3;
    return r->done ? 0 : 1;
}

int compat_refine_step(struct compat_refiner *r)
{
    int k = refine_round(r);
    struct compat_refine_stats *st = r->st;
    if (k != 0 || r->pass == 2 || (r->pass == 1 && !r->pa.lookahead) || !r->start.nv ||
        st->stop == COMPAT_REFINE_GOAL || st->stop == COMPAT_REFINE_ROUNDS)
        return k;
    /* the first pass ended below the goal: its result is kept aside and
     * the refinement starts again from the beginning, splitting only the
     * worst share of the bad triangles after the first rounds; the better
     * of the two is the result (a tie keeps the first).  With
     * pa->lookahead, a second pass below the goal is followed the same way
     * by a third that splits the edge each bad triangle is best split at
     * over every pose, the best of the three kept. */
    struct work *w = &r->w;
    st->stalled = r->stall;
    /* a first pass cut short (its bad triangles grew with its vertices)
     * is kept aside as its best round: its final polish runs only where a
     * later pass ends below the goal and is compared with it (settle_alt;
     * the first pass so cut short was never the result, compat-tri(1),
     * and its polish cost 0.09-0.27 s of t0587's six horse poses' 1.6 s);
     * one with a stall's polished mesh is settled now */
    int raw = r->pass == 0 && st->stop == COMPAT_REFINE_GROWING && !r->polished.nv;
    if (settle(r, !raw) < 0) return -1;
    int wf, ws, nb;
    double wk = worst_ratio(w, r->pa.goal, &wf, &ws, &nb);
    if (wk < 0) return -1;
    r->settled = 1;
    if (wk >= 1) return 0;   /* the final polish reached the goal */
    r->settled = 0;
    if (r->alt_raw && settle_alt(r) < 0) return -1;   /* compared settled */
    if (r->pass == 0 || wk > r->walt) {   /* the best pass so far */
        r->walt = wk;
        r->alt_raw = raw;
        if (best_take(w, r->nvin, &r->alt) < 0) return -1;
        r->alt_stats = *st;
        r->alt_stats.rerun = r->pass == 0 ? 2 : 1;
    }
    return restart(r, r->pass + 1);
}

void compat_refine_progress(const struct compat_refiner *r, double *worst, int *nbad, int *fewest)
{
    if (r->pass) {   /* the second pass: like a finished refinement, at
                        least the first pass's result */
        double wk = r->wcur;
        if (r->cycles) wk = fmax(wk, r->wpolished);
        if (worst) *worst = fmax(r->walt, wk) * r->pa.goal;
        if (nbad) *nbad = INT_MAX;
        if (fewest) *fewest = r->nbest;
        return;
    }
    if (r->cycles) {   /* after a stall's polish: like a finished refinement,
                          its polished mesh (the result at least that good) */
        if (worst) *worst = fmax(r->wpolished, r->wcur) * r->pa.goal;
        if (nbad) *nbad = INT_MAX;
        if (fewest) *fewest = r->nbest;
        return;
    }
    if (worst) *worst = r->wcur < 0 ? 0 : r->wcur * r->pa.goal;
    if (nbad) *nbad = r->wcur < 0 ? INT_MAX : r->nbad;
    if (fewest) *fewest = r->nbest;
}

void compat_refine_pass(const struct compat_refiner *r, int *pass, int *rounds, double *worst, int *nbad)
{
    if (pass) *pass = r->pass;
    if (rounds) *rounds = r->prounds;
    if (worst) *worst = r->wcur < 0 ? 0 : r->wcur * r->pa.goal;
    if (nbad) *nbad = r->wcur < 0 ? INT_MAX : r->nbad;
}

/* back to the best earlier pass (r->alt): its stop reason, the counts of
 * all passes.  0 or -1. */
static int keep_alt(struct compat_refiner *r)
{
    struct compat_refine_stats *st = r->st;
    best_restore(&r->w, &r->alt, &r->nvin);
    int rounds = st->rounds, splits = st->splits, bsplits = st->bsplits, flips = st->flips, moves = st->moves,
        collapses = st->collapses, coarsened = st->coarsened;
    *st = r->alt_stats;
    st->rounds = rounds; st->splits = splits; st->bsplits = bsplits; st->flips = flips;
    st->moves = moves; st->collapses = collapses; st->coarsened = coarsened;
    return 0;
}

/* below the goal: the global max-min polish of the poses, and flips,
 * while that raises the worst angle (it only moves vertices where a
 * pose's smallest angle rises, and flips only raise the worst angle, so
 * the result is never worse than the mesh it starts from).  Returns the worst ratio to the
 * goal after it, -1 on error. */
static double final_gpolish(struct compat_refiner *r)
{
    struct compat *c = r->c;
    struct compat_refine_stats *st = r->st;
    struct work *w = &r->w;
    double goal = r->pa.goal;
    int wf, ws, nb;
    double wk = worst_ratio(w, goal, &wf, &ws, &nb);
    if (wk < 0) return -1;
    if (wk < 1) st->gpolish[0] = st->gpolish[1] = compat_min_angle(c, NULL);
    for (int it = 0; it < COMPAT_REFINE_GPOLISH && wk < 1; it++) {
        int g = global_polish(c, w->bnd, w->seg, w->bsucc, NULL, goal, r->pa.threads);
        if (g < 0) return -1;
        if (!g) break;
        st->gpolish[1] = compat_min_angle(c, NULL);
        int f0 = st->flips;
        if (flips_until_done(c, &st->flips) < 0) return -1;
        if (st->flips == f0) break;
        double wn = worst_ratio(w, goal, &wf, &ws, &nb);
        if (wn < 0) return -1;
        st->gpolish[1] = compat_min_angle(c, NULL);
        if (wn < wk + COMPAT_REFINE_GAIN / goal) break;
        wk = wn;
    }
    /* then (pa->slide) the same with the outline vertices that are not
     * given points sliding along their input outline as well, while it
     * raises the worst angle (after the polish above, so a mesh it
     * brings to the goal keeps its bytes) */
    if (w->stol && r->pa.slide_global) {
        wk = worst_ratio(w, goal, &wf, &ws, &nb);
        if (wk < 0) return -1;
        if (wk < 1) st->gslide[0] = st->gslide[1] = compat_min_angle(c, NULL);
        for (int it = 0; it < COMPAT_REFINE_GPOLISH && wk < 1; it++) {
            int g = global_polish(c, w->bnd, w->seg, w->bsucc, w->stol, goal, r->pa.threads);
            if (g < 0) return -1;
            if (!g) break;
            st->gslide[1] = compat_min_angle(c, NULL);
            int f0 = st->flips;
            if (flips_until_done(c, &st->flips) < 0) return -1;
            double wn = worst_ratio(w, goal, &wf, &ws, &nb);
            if (wn < 0) return -1;
            st->gslide[1] = compat_min_angle(c, NULL);
            if (st->flips == f0 || wn < wk + COMPAT_REFINE_GAIN / goal) break;
            wk = wn;
        }
    }
    return worst_ratio(w, goal, &wf, &ws, &nb);
}

int compat_refine_finish(struct compat_refiner *r)
{
    struct compat *c = r->c;
    struct compat_refine_stats *st = r->st;
    const struct compat_refine_params *pa = &r->pa;
    struct work *w = &r->w;
    double goal = pa->goal;
    int rc = -1;
    if (!r->settled) {
        st->stalled = r->stall;
        if (settle(r, 1) < 0) goto out;
    }
    /* a later pass not better than the best earlier one: back to that */
    int gdone = 0;   /* the global polish done */
    if (r->pass) {
        int wf, ws, nb;
        double wk = worst_ratio(w, goal, &wf, &ws, &nb);
        if (wk < 0) goto out;
        if (r->alt_raw && wk < 1 && settle_alt(r) < 0) goto out;   /* compared settled */
        if (r->walt >= wk) {
            if (keep_alt(r) < 0) goto out;
        } else if (r->pass == 2 && r->remesh && wk < 1) {
            /* the third pass is better before the global polish; both are
             * polished and the third kept only if still better after it
             * (the polish can gain more on the other) */
            struct best third;
            struct compat_refine_stats st3;
            memset(&third, 0, sizeof third);
            double w3 = final_gpolish(r);
            if (w3 < 0 || best_take(w, r->nvin, &third) < 0) { best_free(c->N, &third); goto out; }
            st3 = *st;
            if (keep_alt(r) < 0) { best_free(c->N, &third); goto out; }
            double wa = final_gpolish(r);
            if (wa < 0) { best_free(c->N, &third); goto out; }
            if (w3 > wa) {
                best_restore(w, &third, &r->nvin);
                *st = st3;
            }
            best_free(c->N, &third);
            gdone = 1;
        }
    }
    if (r->remesh && !gdone && final_gpolish(r) < 0) goto out;
    /* where the worst triangle is and how stretched the maps are there */
    r->wcur = worst_ratio(w, goal, &r->wf, &r->ws, &r->nbad);
    if (r->wcur < 0) goto out;
    if (c->nf > 0) {
        const int *F = c->F + 3 * r->wf;
        const double *X = c->X[r->ws];
        st->worst_shape = r->ws;
        for (int d = 0; d < 2; d++) st->worst_at[d] = (X[2 * F[0] + d] + X[2 * F[1] + d] + X[2 * F[2] + d]) / 3;
        st->stretch = face_stretch(c, r->wf);
    }
    /* the input's Steiner points that collapses removed */
    {
        int lost = r->nv0 - r->nvin;
        c->nsteiner = c->nsteiner > lost ? c->nsteiner - lost : 0;
    }
    if (renumber(w, r->nb0, r->nvin) < 0) goto out;
    double minarea, q1 = compat_min_angle(c, &minarea);
    if (!(minarea > 0) || q1 < r->q0) {
        snap_restore(c, &r->snap);
        st->kept_input = 1;
    } else if (r->wcur >= 1)
        st->stop = COMPAT_REFINE_GOAL;   /* the final or the global polish reached it */
    rc = 0;
out:
    refiner_free(r);
    return rc;
}

void compat_refine_threads(struct compat_refiner *r, int threads)
{
    r->pa.threads = threads;
}

void compat_refine_abandon(struct compat_refiner *r)
{
    if (r) refiner_free(r);
}

int compat_refine(struct compat *c, const struct compat_refine_params *pa, struct compat_refine_stats *st)
{
    struct compat_refiner *r = compat_refine_begin(c, pa, st);
    if (!r) return -1;
    int k;
    while ((k = compat_refine_step(r)) > 0) {}
    if (k < 0) { compat_refine_abandon(r); return -1; }
    return compat_refine_finish(r);
}
