/* maxmin_polish.c -- see maxmin_polish.h */
#include "maxmin_polish.h"
#include "cm_error.h"
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
};

/* soft minimum's negative, (1/beta) log sum exp(-beta (theta - m0)), of
 * the mesh at P and its gradient g (free directions only); *mn: the true
 * smallest angle.  INFINITY where a triangle is not positive (rounded;
 * the result is checked exactly at the end). */
static double soft(const struct mm *m, const double *P, double *g, double *mn)
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

#define MEM 8

int maxmin_polish(double *X, int nv, const int *F, int nf, const unsigned char *fixed, const int *seg,
                  const struct maxmin_params *p, double *before, double *after)
{
    struct mm m = {.nv = nv, .nf = nf, .n = 2 * nv, .F = F, .fixed = fixed, .seg = seg};
    int n = m.n, rc = 0;
    double *buf = malloc((size_t)(6 + 2 * MEM) * (n ? n : 1) * sizeof *buf);
    if (!buf) return cm_seterr("out of memory");
    double *P = buf, *g = P + n, *d = g + n, *xn = d + n, *gn = xn + n, *best = gn + n, *S = best + n,
           *Y = S + (size_t)MEM * n;
    double rho[MEM], al[MEM];
    unsigned char *still = malloc(nf ? nf : 1);
    if (!still) { free(buf); return cm_seterr("out of memory"); }
    for (int f = 0; f < nf; f++) {
        still[f] = 1;
        for (int k = 0; k < 3; k++) {
            int v = F[3 * f + k];
            if (!fixed[v] || (seg && seg[2 * v] >= 0)) still[f] = 0;
        }
    }
    m.still = still;
    memcpy(P, X, n * sizeof *P);
    memcpy(best, X, n * sizeof *P);
    double lo0 = INFINITY, lo;
    m.beta = 1; m.m0 = 0;
    if (!isfinite(soft(&m, P, g, &lo0))) lo0 = -INFINITY;
    double lbest = lo0, mean_edge = 0;
    for (int f = 0; f < nf; f++)
        for (int k = 0; k < 3; k++) {
            const double *a = P + 2 * F[3 * f + k], *b = P + 2 * F[3 * f + (k + 1) % 3];
            mean_edge += hypot(b[0] - a[0], b[1] - a[1]);
        }
    mean_edge /= nf ? 3 * nf : 1;
    for (int b = 0; b < p->nbeta && isfinite(lo0); b++) {
        m.beta = p->beta[b];
        m.m0 = lbest;
        memcpy(P, best, n * sizeof *P);
        double f = soft(&m, P, g, &lo);
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
            int ok = 0;
            for (int ls = 0; ls < 30; ls++) {
                for (int k = 0; k < n; k++) xn[k] = P[k] - t * d[k];
                fn = soft(&m, xn, gn, &ln);
                if (fn <= f - 1e-4 * t * gd) { ok = 1; break; }
                t *= 0.5;
            }
            if (!ok) break;
            double *Sh = S + (size_t)head * n, *Yh = Y + (size_t)head * n;
            for (int k = 0; k < n; k++) { Sh[k] = xn[k] - P[k]; Yh[k] = gn[k] - g[k]; }
            double sy = dot(Sh, Yh, n);
            if (sy > 1e-300) { rho[head] = 1 / sy; head = (head + 1) % MEM; mk++; }
            memcpy(P, xn, n * sizeof *P);
            memcpy(g, gn, n * sizeof *g);
            double df = f - fn;
            f = fn;
            if (ln > lbest) { lbest = ln; memcpy(best, P, n * sizeof *P); }
            if (df < 1e-12 * fabs(f) + 1e-15) break;
        }
    }
    if (lbest > lo0 && isfinite(lo0)) {
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
    free(buf);
    free(still);
    return rc;
}
