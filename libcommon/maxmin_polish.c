/* maxmin_polish.c -- see maxmin_polish.h */
#include "maxmin_polish.h"
#include "cm_error.h"
#include "compat_tri.h"
#include "predicates2.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

void maxmin_defaults(struct maxmin_params *p)
{
    memset(p, 0, sizeof *p);
    p->iters = 100;
    p->nbeta = 4;
    p->beta[0] = 120; p->beta[1] = 240; p->beta[2] = 480; p->beta[3] = 960;
}

struct mm {
    int nv, nf, n;
    const int *F;
    const unsigned char *fixed;
    const unsigned char *still;   /* nf: 1 for a face none of whose corners moves */
    const int *seg;
    double beta, m0;
    int raw;          /* soft leaves the gradient by position, undivided (the curve mode) */
    double sum;       /* soft's last sum */
};

/* soft minimum's negative, (1/beta) log sum exp(-beta (theta - m0)), of
 * the mesh at P and its gradient g (free directions only); *mn: the true
 * smallest angle.  INFINITY where a triangle is not positive (rounded;
 * the result is checked exactly at the end). */
static double soft(struct mm *m, const double *P, double *g, double *mn)
{
    double sum = 0, lo = INFINITY;
    /* an angle above m0 + 40 / beta weighs below 1e-17 of the smallest:
     * it is skipped (its cosine below cskip) without atan2 and exp, as
     * long as it is not the smallest seen (lo is then only needed as
     * long as it is below that bound) */
    double thr = m->m0 + 40 / m->beta, cskip = thr < M_PI ? cos(thr) : -2;
    memset(g, 0, m->n * sizeof *g);
    for (int f = 0; f < m->nf; f++) {
        if (m->still[f]) continue;
        const int *T = m->F + 3 * f;
        for (int k = 0; k < 3; k++) {
            int io = T[k], iu = T[(k + 1) % 3], iw = T[(k + 2) % 3];
            const double *o = P + 2 * io, *u = P + 2 * iu, *w = P + 2 * iw;
            double ax = u[0] - o[0], ay = u[1] - o[1], bx = w[0] - o[0], by = w[1] - o[1];
            double cr = ax * by - ay * bx;
            if (!(cr > 0)) return INFINITY;
            double dt = ax * bx + ay * by, la = ax * ax + ay * ay, lb = bx * bx + by * by;
            if (lo < thr && dt < cskip * sqrt(la * lb)) continue;
            double th = atan2(cr, dt);
            if (th < lo) lo = th;
            double x = m->beta * (th - m->m0);
            if (x > 40) continue;   /* below 1e-17 of the smallest's weight */
            double e = exp(-x);
            sum += e;
            /* d theta / d u = (ay, -ax) / |a|^2, d theta / d w = (-by, bx) / |b|^2 */
            double gux = ay / la, guy = -ax / la, gwx = -by / lb, gwy = bx / lb;
            g[2 * iu] -= e * gux; g[2 * iu + 1] -= e * guy;
            g[2 * iw] -= e * gwx; g[2 * iw + 1] -= e * gwy;
            g[2 * io] += e * (gux + gwx); g[2 * io + 1] += e * (guy + gwy);
        }
    }
    *mn = lo;
    if (!(sum > 0)) return INFINITY;
    if (m->raw) { m->sum = sum; return log(sum) / m->beta; }
    for (int v = 0; v < m->nv; v++) {
        double *gv = g + 2 * v;
        if (!m->fixed[v]) { gv[0] /= sum; gv[1] /= sum; continue; }
        if (m->seg && m->seg[2 * v] >= 0) {   /* along the segment only */
            const double *A = P + 2 * m->seg[2 * v], *B = P + 2 * m->seg[2 * v + 1];
            double ux = B[0] - A[0], uy = B[1] - A[1], uu = ux * ux + uy * uy;
            double d = (gv[0] * ux + gv[1] * uy) / (uu * sum);
            gv[0] = d * ux; gv[1] = d * uy;
        } else gv[0] = gv[1] = 0;
    }
    return log(sum) / m->beta;
}

static double dot(const double *a, const double *b, int n)
{
    double s = 0;
    for (int i = 0; i < n; i++) s += a[i] * b[i];
    return s;
}

/* every face positive by the exact predicate */
static int all_positive(const double *P, const int *F, int nf)
{
    for (int f = 0; f < nf; f++)
        if (orient2_sign(P + 2 * F[3 * f], P + 2 * F[3 * f + 1], P + 2 * F[3 * f + 2]) <= 0) return 0;
    return 1;
}

/* ---- the curve mode: knots by arc length along B, split vertices by
 * their fraction of the chord between their ends ---- */
struct crv {
    const struct maxmin_curve *cv;
    const double *X0;     /* the positions at the start (fixed vertices) */
    const unsigned char *fixed;
    const int *seg;
    const unsigned char *sl;  /* the caller's slides */
    int nv;
    double *C, L;         /* M + 1 cumulative arc lengths of B, its length */
    int *ring, nr;        /* the outline vertices in order, from a knot */
    double *sk;           /* nv: a fixed knot's arc position (unwrapped) */
    double *L0;           /* nv: a split vertex's chord length at the start
                             (its variable is the fraction times this) */
    int *kn, K;           /* the knots in order (vertex numbers) */
    double *ks;           /* K: their arc positions (check's scratch) */
    int *ord;             /* K: chords sorted by left end (check's scratch) */
    double *bb;           /* 4 K: chord bounding boxes (scratch) */
    unsigned char *frozen;/* nv: outline variables held for the rest of a
                             beta (a step broke a constraint with them) */
    unsigned char *rev;   /* nv: reverted by the last repair */
};

static int seg_at(const struct crv *r, double s, double *u)
{
    double L = r->L, x = fmod(s, L);
    if (x < 0) x += L;
    int lo = 0, hi = r->cv->M;   /* C[lo] <= x < C[hi] */
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (r->C[mid] <= x) lo = mid; else hi = mid;
    }
    *u = x;
    return lo;
}

static void curve_point(const struct crv *r, double s, double *p, double *tg)
{
    double x;
    int i = seg_at(r, s, &x), M = r->cv->M;
    const double *a = r->cv->B + 2 * i, *b = r->cv->B + 2 * ((i + 1) % M);
    double len = r->C[i + 1] - r->C[i], t = len > 0 ? (x - r->C[i]) / len : 0;
    if (p) { p[0] = a[0] + t * (b[0] - a[0]); p[1] = a[1] + t * (b[1] - a[1]); }
    if (tg) { tg[0] = len > 0 ? (b[0] - a[0]) / len : 0; tg[1] = len > 0 ? (b[1] - a[1]) / len : 0; }
}

/* the arc position of the point p on B near index home (-1: not on B) */
static double curve_param(const struct crv *r, int home, const double *p, double eps)
{
    double t;
    int i = compat_polyline_locate(r->cv->B, r->cv->M, home, p, eps, &t);
    return i < 0 ? -1 : r->C[i] + t * (r->C[i + 1] - r->C[i]);
}

static int is_knot(const struct crv *r, int v) { return r->seg[2 * v] < 0; }

/* positions P from the variables z */
static void place(const struct crv *r, const double *z, double *P)
{
    for (int v = 0; v < r->nv; v++) {
        if (!r->fixed[v]) { P[2 * v] = z[2 * v]; P[2 * v + 1] = z[2 * v + 1]; }
        else if (r->sl[v]) curve_point(r, z[2 * v], P + 2 * v, NULL);
        else if (r->seg[2 * v] < 0) { P[2 * v] = r->X0[2 * v]; P[2 * v + 1] = r->X0[2 * v + 1]; }
    }
    for (int v = 0; v < r->nv; v++)
        if (r->fixed[v] && r->seg[2 * v] >= 0) {
            const double *A = P + 2 * r->seg[2 * v], *B = P + 2 * r->seg[2 * v + 1];
            double t = z[2 * v] / r->L0[v];
            P[2 * v] = A[0] + t * (B[0] - A[0]);
            P[2 * v + 1] = A[1] + t * (B[1] - A[1]);
        }
}

/* gP (by position, changed) to gz (by variable), both divided by sum */
static void pull(const struct crv *r, const double *z, const double *P, double *gP, double *gz, double sum)
{
    int nv = r->nv;
    for (int v = 0; v < nv; v++)
        if (r->fixed[v] && r->seg[2 * v] >= 0) {
            int a = r->seg[2 * v], b = r->seg[2 * v + 1];
            const double *A = P + 2 * a, *B = P + 2 * b;
            double t = z[2 * v] / r->L0[v], *g = gP + 2 * v;
            gz[2 * v] = (g[0] * (B[0] - A[0]) + g[1] * (B[1] - A[1])) / r->L0[v] / sum;
            gz[2 * v + 1] = 0;
            gP[2 * a] += (1 - t) * g[0]; gP[2 * a + 1] += (1 - t) * g[1];
            gP[2 * b] += t * g[0]; gP[2 * b + 1] += t * g[1];
        }
    for (int v = 0; v < nv; v++) {
        if (r->frozen[v]) gz[2 * v] = gz[2 * v + 1] = 0;
        else if (!r->fixed[v]) { gz[2 * v] = gP[2 * v] / sum; gz[2 * v + 1] = gP[2 * v + 1] / sum; }
        else if (r->sl[v]) {
            double tg[2];
            curve_point(r, z[2 * v], NULL, tg);
            gz[2 * v] = (gP[2 * v] * tg[0] + gP[2 * v + 1] * tg[1]) / sum;
            gz[2 * v + 1] = 0;
        } else if (r->seg[2 * v] < 0) gz[2 * v] = gz[2 * v + 1] = 0;
    }
}

/* the outline constraints at z (positions P): 1 if kept.  mark (NULL, or
 * nv flags): set for the vertices of every constraint broken (the knots
 * out of order or at the ends of a chord too far from B or meeting
 * another, the split vertices out of order), and all are looked at. */
#define BAD(v_) do { if (!mark) return 0; mark[v_] = 1; ok = 0; } while (0)
static int check(struct crv *r, const double *z, const double *P, unsigned char *mark)
{
    const struct maxmin_curve *cv = r->cv;
    int K = 0, M = cv->M, ok = 1, kprev = -1;
    double tprev = 0;
    for (int i = 0; i < r->nr; i++) {
        int v = r->ring[i];
        if (is_knot(r, v)) {
            double s = r->sl[v] ? z[2 * v] : r->sk[v];
            if (K && !(s > r->ks[K - 1])) { BAD(v); BAD(kprev); }
            r->ks[K++] = s;
            kprev = v;
            tprev = 0;
        } else {
            double t = z[2 * v] / r->L0[v];
            if (!(t > tprev && t < 1)) BAD(v);
            tprev = t;
        }
    }
    if (!(r->ks[K - 1] < r->ks[0] + r->L)) { BAD(r->kn[0]); BAD(r->kn[K - 1]); }
    if (!ok) return 0;
    /* every chord within tol of the points of B it spans */
    for (int k = 0; k < K; k++) {
        const double *a = P + 2 * r->kn[k], *b = P + 2 * r->kn[(k + 1) % K];
        double sa = r->ks[k], sb = k + 1 < K ? r->ks[k + 1] : r->ks[0] + r->L, x;
        int i = seg_at(r, sa, &x);
        double arc = sa - x + r->C[i + 1];   /* unwrapped arc of point i + 1 */
        for (int j = i + 1; arc < sb; j++) {
            int jj = j % M;
            if (compat_seg_dist(cv->B + 2 * jj, a, b) > cv->tol) { BAD(r->kn[k]); BAD(r->kn[(k + 1) % K]); break; }
            arc += r->C[jj + 1] - r->C[jj];
        }
        double *q = r->bb + 4 * k;
        q[0] = fmin(a[0], b[0]); q[1] = fmax(a[0], b[0]); q[2] = fmin(a[1], b[1]); q[3] = fmax(a[1], b[1]);
    }
    /* no two chords that do not share a knot meet (exact); the chords by
     * left end, insertion sort from the last call's order (the answer
     * does not depend on the order of ties) */
    for (int x = 1; x < K; x++) {
        int i = r->ord[x], y = x;
        for (; y > 0 && r->bb[4 * r->ord[y - 1]] > r->bb[4 * i]; y--) r->ord[y] = r->ord[y - 1];
        r->ord[y] = i;
    }
    for (int x = 0; x < K; x++) {
        int i = r->ord[x];
        const double *qi = r->bb + 4 * i;
        for (int y = x + 1; y < K; y++) {
            int j = r->ord[y];
            const double *qj = r->bb + 4 * j;
            if (qj[0] > qi[1]) break;
            if (qj[2] > qi[3] || qj[3] < qi[2]) continue;
            if (j == (i + 1) % K || i == (j + 1) % K) continue;
            if (segments_meet(P + 2 * r->kn[i], P + 2 * r->kn[(i + 1) % K], P + 2 * r->kn[j], P + 2 * r->kn[(j + 1) % K])) {
                BAD(r->kn[i]); BAD(r->kn[(i + 1) % K]); BAD(r->kn[j]); BAD(r->kn[(j + 1) % K]);
            }
        }
    }
    return ok;
}
#undef BAD

/* z (a step from the feasible zc) made feasible: the variables of the
 * outline vertices of a broken constraint go back to zc's until none is
 * (at most 32 times, then every outline variable).  Positions in P. */
static int repair(struct crv *r, const double *zc, double *z, double *P, unsigned char *mark)
{
    int nrev = 0;
    memset(r->rev, 0, r->nv);
    for (int it = 0; it < 32; it++) {
        place(r, z, P);
        memset(mark, 0, r->nv);
        if (check(r, z, P, mark)) return nrev;
        for (int v = 0; v < r->nv; v++)
            if (mark[v] && r->fixed[v]) { z[2 * v] = zc[2 * v]; z[2 * v + 1] = zc[2 * v + 1]; r->rev[v] = 1; nrev++; }
    }
    for (int i = 0; i < r->nr; i++) {
        int v = r->ring[i];
        z[2 * v] = zc[2 * v]; z[2 * v + 1] = zc[2 * v + 1];
        r->rev[v] = 1; nrev++;
    }
    place(r, z, P);
    return nrev;
}

static void crv_free(struct crv *r)
{
    free(r->C); free(r->ring); free(r->sk); free(r->L0); free(r->kn); free(r->ks); free(r->ord); free(r->bb);
    free(r->frozen); free(r->rev);
}

/* set up r and the variables z from X: 1, 0 if the outline is not as
 * expected (the plain maxmin_polish then), -1 out of memory */
static int crv_init(struct crv *r, const struct maxmin_curve *cv, const double *X, int nv, const unsigned char *fixed,
                    const int *seg, double *z)
{
    memset(r, 0, sizeof *r);
    r->cv = cv; r->X0 = X; r->fixed = fixed; r->nv = nv; r->seg = seg; r->sl = cv->slides;
    int M = cv->M;
    r->C = malloc((M + 1) * sizeof *r->C);
    r->ring = malloc((nv ? nv : 1) * sizeof *r->ring);
    r->sk = malloc((nv ? nv : 1) * sizeof *r->sk);
    r->L0 = calloc(nv ? nv : 1, sizeof *r->L0);
    r->kn = malloc((nv ? nv : 1) * sizeof *r->kn);
    r->ks = malloc((nv ? nv : 1) * sizeof *r->ks);
    r->ord = malloc((nv ? nv : 1) * sizeof *r->ord);
    r->bb = malloc(4 * (nv ? nv : 1) * sizeof *r->bb);
    r->frozen = calloc(nv ? nv : 1, 1);
    r->rev = calloc(nv ? nv : 1, 1);
    if (!r->frozen || !r->rev || !r->C || !r->ring || !r->sk || !r->L0 || !r->kn || !r->ks || !r->ord || !r->bb) { crv_free(r); return -1; }
    r->C[0] = 0;
    for (int i = 0; i < M; i++) {
        const double *a = cv->B + 2 * i, *b = cv->B + 2 * ((i + 1) % M);
        r->C[i + 1] = r->C[i] + hypot(b[0] - a[0], b[1] - a[1]);
    }
    r->L = r->C[M];
    if (M < 3 || !(r->L > 0)) { crv_free(r); return 0; }
    /* the ring from a fixed knot if there is one */
    int v0 = -1;
    for (int v = 0; v < nv; v++)
        if (cv->bsucc[v] >= 0 && seg[2 * v] < 0 && cv->home[v] >= 0 && (v0 < 0 || (cv->slides[v0] && !cv->slides[v]))) v0 = v;
    if (v0 < 0) { crv_free(r); return 0; }
    for (int v = v0; r->nr == 0 || v != v0; v = cv->bsucc[v]) {
        if (v < 0 || r->nr >= nv || !fixed[v]) { crv_free(r); return 0; }
        r->ring[r->nr++] = v;
    }
    double eps = 1e-9 * r->L + 1e-12, prev = -INFINITY;
    for (int i = 0; i < r->nr; i++) {
        int v = r->ring[i];
        if (seg[2 * v] >= 0) continue;
        if (cv->home[v] < 0) { crv_free(r); return 0; }
        double s = curve_param(r, cv->home[v], X + 2 * v, eps);
        if (s < 0) { crv_free(r); return 0; }
        while (s <= prev) s += r->L;
        prev = s;
        r->kn[r->K++] = v;
        r->sk[v] = s;
        if (cv->slides[v]) z[2 * v] = s;
    }
    if (r->K < 3 || !(prev < r->sk[r->kn[0]] + r->L)) { crv_free(r); return 0; }
    for (int v = 0; v < nv; v++)
        if (fixed[v] && seg[2 * v] >= 0) {
            const double *A = X + 2 * seg[2 * v], *B = X + 2 * seg[2 * v + 1];
            double ux = B[0] - A[0], uy = B[1] - A[1], uu = ux * ux + uy * uy;
            if (!(uu > 0)) { crv_free(r); return 0; }
            r->L0[v] = sqrt(uu);
            z[2 * v] = ((X[2 * v] - A[0]) * ux + (X[2 * v + 1] - A[1]) * uy) / uu * r->L0[v];
            z[2 * v + 1] = 0;
        }
    for (int k = 0; k < r->K; k++) r->ord[k] = k;
    return 1;
}

#define MEM 8

/* the soft minimum at the variables z (positions in the plain mode) */
static double eval(struct mm *m, struct crv *r, const double *z, double *Pw, double *gPw, double *g, double *mn)
{
    if (!r) return soft(m, z, g, mn);
    place(r, z, Pw);
    if (!check(r, z, Pw, NULL)) { *mn = -INFINITY; return INFINITY; }
    double f = soft(m, Pw, gPw, mn);
    if (!isfinite(f)) return f;
    pull(r, z, Pw, gPw, g, m->sum);
    return f;
}

int maxmin_polish(double *X, int nv, const int *F, int nf, const unsigned char *fixed, const int *seg,
                  const struct maxmin_params *p, double *before, double *after)
{
    return maxmin_polish_curve(X, nv, F, nf, fixed, seg, NULL, p, before, after);
}

int maxmin_polish_curve(double *X, int nv, const int *F, int nf, const unsigned char *fixed, const int *seg,
                        const struct maxmin_curve *cv, const struct maxmin_params *p, double *before,
                        double *after)
{
    struct mm m = {.nv = nv, .nf = nf, .n = 2 * nv, .F = F, .fixed = fixed, .seg = seg};
    int n = m.n, rc = 0;
    double *buf = malloc((size_t)(8 + 2 * MEM) * (n ? n : 1) * sizeof *buf);
    if (!buf) return cm_seterr("out of memory");
    double *P = buf, *g = P + n, *d = g + n, *xn = d + n, *gn = xn + n, *best = gn + n, *S = best + n,
           *Y = S + (size_t)MEM * n, *Pw = Y + (size_t)MEM * n, *gPw = Pw + n;
    double rho[MEM], al[MEM];
    unsigned char *still = malloc(nf ? nf : 1), *mark = NULL;
    if (!still) { free(buf); return cm_seterr("out of memory"); }
    if (cv && seg && !(mark = malloc(nv ? nv : 1))) { free(buf); free(still); return cm_seterr("out of memory"); }
    memcpy(P, X, n * sizeof *P);
    struct crv crv, *rp = NULL;
    if (cv && seg) {
        int k = crv_init(&crv, cv, X, nv, fixed, seg, P);
        if (k < 0) { free(buf); free(still); free(mark); return cm_seterr("out of memory"); }
        if (k > 0) {
            place(&crv, P, Pw);
            if (check(&crv, P, Pw, NULL)) rp = &crv;
            else { crv_free(&crv); memcpy(P, X, n * sizeof *P); }
        } else memcpy(P, X, n * sizeof *P);
    }
    m.raw = rp != NULL;
    for (int f = 0; f < nf; f++) {
        still[f] = 1;
        for (int k = 0; k < 3; k++) {
            int v = F[3 * f + k];
            if (!fixed[v] || (seg && seg[2 * v] >= 0) || (rp && cv->slides[v])) still[f] = 0;
        }
    }
    m.still = still;
    memcpy(best, P, n * sizeof *P);
    double lo0 = INFINITY, lo;
    m.beta = 1; m.m0 = 0;
    if (!isfinite(soft(&m, X, rp ? gPw : g, &lo0))) lo0 = -INFINITY;
    double lbest = lo0, mean_edge = 0;
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) {
            const double *a = X + 2 * F[3 * f + k], *b = X + 2 * F[3 * f + (k + 1) % 3];
            mean_edge += hypot(b[0] - a[0], b[1] - a[1]);
        }
    mean_edge /= nf ? 3 * nf : 1;
    for (int b = 0; b < p->nbeta && isfinite(lo0); b++) {
        m.beta = p->beta[b];
        if (rp) memset(rp->frozen, 0, nv);
        m.m0 = lbest;
        memcpy(P, best, n * sizeof *P);
        double f = eval(&m, rp, P, Pw, gPw, g, &lo);
        if (!isfinite(f)) break;
        int mk = 0, head = 0;
        for (int it = 0; it < p->iters; it++) {
            /* L-BFGS direction: d = H g (descent of f along -d) */
            memcpy(d, g, n * sizeof *d);
            int cm = mk < MEM ? mk : MEM;
            for (int j = 0; j < cm; j++) {
                int i = (head - 1 - j + MEM) % MEM;
                al[i] = rho[i] * dot(S + (size_t)i * n, d, n);
                for (int k = 0; k < n; k++) d[k] -= al[i] * Y[(size_t)i * n + k];
            }
            double gg = dot(g, g, n);
            if (!(gg > 0)) break;
            if (cm) {
                int i = (head - 1 + MEM) % MEM;
                double *Si = S + (size_t)i * n, *Yi = Y + (size_t)i * n, sc = dot(Si, Yi, n) / dot(Yi, Yi, n);
                for (int k = 0; k < n; k++) d[k] *= sc;
            } else {   /* first step: the largest vertex move 1% of the mean edge */
                double gmax = 0;
                for (int k = 0; k < n; k++) gmax = fmax(gmax, fabs(g[k]));
                for (int k = 0; k < n; k++) d[k] *= 0.01 * mean_edge / gmax;
            }
            for (int j = cm - 1; j >= 0; j--) {
                int i = (head - 1 - j + MEM) % MEM;
                double bb = rho[i] * dot(Y + (size_t)i * n, d, n);
                for (int k = 0; k < n; k++) d[k] += S[(size_t)i * n + k] * (al[i] - bb);
            }
            double gd = dot(g, d, n);
            if (!(gd > 0)) { mk = 0; continue; }
            double t = 1, fn = INFINITY, ln = -INFINITY;
            int ok = 0, nrev = 0;
            for (int ls = 0; ls < 30; ls++) {
                for (int k = 0; k < n; k++) xn[k] = P[k] - t * d[k];
                double gdx = t * gd;
                if (rp) {   /* the outline's constraints kept: what broke one goes back */
                    nrev = repair(rp, P, xn, Pw, mark);
                    gdx = 0;
                    for (int k = 0; k < n; k++) gdx += g[k] * (P[k] - xn[k]);
                    if (!(gdx > 0)) { t *= 0.5; continue; }
                }
                fn = eval(&m, rp, xn, Pw, gPw, gn, &ln);
                if (fn <= f - 1e-4 * gdx) { ok = 1; break; }
                t *= 0.5;
            }
            if (!ok) break;
            if (nrev) {   /* held from now on (this beta): the memory starts again */
                for (int v = 0; v < nv; v++)
                    if (rp->rev[v]) { rp->frozen[v] = 1; gn[2 * v] = gn[2 * v + 1] = 0; }
                mk = 0;
            } else {
                double *Sh = S + (size_t)head * n, *Yh = Y + (size_t)head * n;
                for (int k = 0; k < n; k++) { Sh[k] = xn[k] - P[k]; Yh[k] = gn[k] - g[k]; }
                double sy = dot(Sh, Yh, n);
                if (sy > 1e-300) { rho[head] = 1 / sy; head = (head + 1) % MEM; mk++; }
            }
            memcpy(P, xn, n * sizeof *P);
            memcpy(g, gn, n * sizeof *g);
            double df = f - fn;
            f = fn;
            if (ln > lbest) { lbest = ln; memcpy(best, P, n * sizeof *P); }
            if (df < 1e-12 * fabs(f) + 1e-15) break;
        }
    }
    if (rp && lbest > lo0 && isfinite(lo0)) {
        struct mm m1 = m;
        m1.beta = 1; m1.m0 = 0;
        double l1;
        place(rp, best, Pw);
        if (check(rp, best, Pw, NULL) && all_positive(Pw, F, nf) && isfinite(soft(&m1, Pw, gPw, &l1)) && l1 > lo0) {
            memcpy(X, Pw, n * sizeof *X);
            lbest = l1;
            rc = 1;
        } else lbest = lo0;
    } else if (lbest > lo0 && isfinite(lo0)) {
        /* the sliding vertices back onto their segments exactly */
        if (seg)
            for (int v = 0; v < nv; v++) {
                if (!fixed[v] || seg[2 * v] < 0) continue;
                const double *A = best + 2 * seg[2 * v], *B = best + 2 * seg[2 * v + 1];
                double ux = B[0] - A[0], uy = B[1] - A[1];
                double tv = ((best[2 * v] - A[0]) * ux + (best[2 * v + 1] - A[1]) * uy) / (ux * ux + uy * uy);
                if (!(tv > 0 && tv < 1)) { tv = ((X[2 * v] - A[0]) * ux + (X[2 * v + 1] - A[1]) * uy) / (ux * ux + uy * uy); }
                best[2 * v] = A[0] + tv * ux; best[2 * v + 1] = A[1] + tv * uy;
            }
        struct mm m1 = m;
        m1.beta = 1; m1.m0 = 0;
        double l1;
        if (all_positive(best, F, nf) && isfinite(soft(&m1, best, g, &l1)) && l1 > lo0) {
            memcpy(X, best, n * sizeof *X);
            lbest = l1;
            rc = 1;
        } else lbest = lo0;
    }
    if (before) *before = lo0;
    if (after) *after = rc ? lbest : lo0;
    if (rp) crv_free(rp);
    free(mark);
    free(buf);
    free(still);
    return rc;
}
