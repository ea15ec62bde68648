/* boundary_match.c -- see boundary_match.h */
#include "boundary_match.h"
#include "cm_error.h"
#include "parallel.h"
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void bmatch_defaults(struct bmatch_params *prm)
{
    *prm = (struct bmatch_params){0};   /* every field set, the ones not named below 0 */
    prm->mode = BMATCH_MULTISCALE;
    prm->samples = 256;
    prm->bend = 0.03;
    prm->start_bend = 0.3;
    prm->feature = 10;
    prm->spread = 0;
    prm->threads = 1;
}

/* a closed polygon with cumulative arc lengths */
struct outline {
    const double *P;
    int n;
    double *cum;      /* n + 1: cum[i] = arc position of vertex i, cum[n] = L */
    double L;
};

static int outline_init(struct outline *o, const double *P, int n)
{
    o->P = P; o->n = n;
    o->cum = malloc((n + 1) * sizeof *o->cum);
    if (!o->cum) return cm_seterr("out of memory");
    o->cum[0] = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        o->cum[i + 1] = o->cum[i] + hypot(P[2 * j] - P[2 * i], P[2 * j + 1] - P[2 * i + 1]);
    }
    o->L = o->cum[n];
    if (!(o->L > 0)) { free(o->cum); return cm_seterr("outline of zero length"); }
    return 0;
}

static double wrap(double s, double L)
{
    s = fmod(s, L);
    return s < 0 ? s + L : s;
}

/* point at arc position s (any real, taken modulo L) */
static void outline_point(const struct outline *o, double s, double q[2])
{
    s = wrap(s, o->L);
    int lo = 0, hi = o->n;           /* cum[lo] <= s < cum[hi] */
    while (hi - lo > 1) {
        int mid = (lo + hi) / 2;
        if (o->cum[mid] <= s) lo = mid; else hi = mid;
    }
    int j = (lo + 1) % o->n;
    double len = o->cum[lo + 1] - o->cum[lo], t = len > 0 ? (s - o->cum[lo]) / len : 0;
    q[0] = o->P[2 * lo] + t * (o->P[2 * j] - o->P[2 * lo]);
    q[1] = o->P[2 * lo + 1] + t * (o->P[2 * j + 1] - o->P[2 * lo + 1]);
}

/* direction angle of the chord (s - d, s + d) */
static double chord_angle(const struct outline *o, double s, double d)
{
    double a[2], b[2];
    outline_point(o, s - d, a);
    outline_point(o, s + d, b);
    return atan2(b[1] - a[1], b[0] - a[0]);
}

/* tangent angles at m + 1 samples s0 + k len / m, unwrapped (continuous) */
static void sample_angles(const struct outline *o, double s0, double len, int m, double *th)
{
    double d = 0.005 * o->L;
    for (int k = 0; k <= m; k++) {
        th[k] = chord_angle(o, s0 + len * k / m, d);
        if (k) {
            double dd = th[k] - th[k - 1];
            dd -= 2 * M_PI * floor((dd + M_PI) / (2 * M_PI));
            th[k] = th[k - 1] + dd;
        }
    }
}

/* multi-scale turning: at each of m + 1 samples s0 + k len / m, the signed
 * angle between the chords p(s - h) -> p(s) and p(s) -> p(s + h) for the
 * BMATCH_SCALES scales h, divided by pi (so in [-1, 1]) */
static const double SCALES[BMATCH_SCALES] = {0.01, 0.02, 0.04, 0.08};

static void sample_turning(const struct outline *o, double s, double *d)
{
    double b[2];
    outline_point(o, s, b);
    for (int k = 0; k < BMATCH_SCALES; k++) {
        double h = SCALES[k] * o->L, a[2], c[2];
        outline_point(o, s - h, a);
        outline_point(o, s + h, c);
        double ux = b[0] - a[0], uy = b[1] - a[1], vx = c[0] - b[0], vy = c[1] - b[1];
        d[k] = atan2(ux * vy - uy * vx, ux * vx + uy * vy) / M_PI;
    }
}

static void sample_desc(const struct outline *o, double s0, double len, int m, double *D)
{
    for (int k = 0; k <= m; k++) sample_turning(o, s0 + len * k / m, D + (size_t)k * BMATCH_SCALES);
}

static double desc_dist(const double *a, const double *b)
{
    double d = 0;
    for (int k = 0; k < BMATCH_SCALES; k++) d += fabs(a[k] - b[k]);
    return d / BMATCH_SCALES;
}

static const int STEPS[9][2] = {{1, 1}, {1, 0}, {0, 1}, {1, 2}, {2, 1}, {1, 3}, {3, 1}, {2, 3}, {3, 2}};

/* one step's cost in dp_align's loop (the same sum in the same order), or
 * INFINITY where the loop would not take it (not below INFINITY) */
static inline double dp_cost(double prev, double stretch, double R, double a, double b, double f5, double half)
{
    double c = prev + stretch + R * fabs(a - b) + f5 * half;
    return c < INFINITY ? c : INFINITY;
}

/* Dynamic program from (0,0) to (mA, mB).  thA: mA + 1, thB: mB + 1 angles;
 * hA, hB: step lengths as fractions of the perimeters.  path (may be NULL):
 * out, up to mA + mB + 1 pairs, *plen of them.  Returns the cost.  D and
 * from: (mA + 1) by (mB + 1) scratch; without a path (and mA >= 3) D needs
 * only 4 by (mB + 1): the last four rows are kept (a step goes back at most
 * three rows), which stay in the cache, and from is not used (may be NULL). */
static double dp_align(const double *thA, int mA, double hA, const double *thB, int mB, double hB, double R,
                       const double *dA, const double *dB, double wf, double S,
                       int *path, int *plen, double *D, unsigned char *from)
{
    int W = mB + 1;
    double stretch[9], half[9];   /* per step: |dsA - dsB| (+ the spread term) and (dsA + dsB) / 2 without f */
    for (int k = 0; k < 9; k++) {
        stretch[k] = fabs(STEPS[k][0] * hA - STEPS[k][1] * hB);
        half[k] = STEPS[k][0] * hA + STEPS[k][1] * hB;
        if (S > 0) {
            /* the step's ratio against the segment's mean ratio mA hA / (mB hB)
             * (a side that does not move counts as a quarter sample) */
            double ea = STEPS[k][0] ? STEPS[k][0] : 0.25, eb = STEPS[k][1] ? STEPS[k][1] : 0.25;
            stretch[k] += S * 0.5 * half[k] * fabs(log(ea / eb) - log((double)mA / mB));
        }
    }
    int rows = path || mA < 3 ? mA + 1 : 4;
    for (int i = 0; i <= mA; i++) {
        /* Dr[d]: row i - d */
        double *Dr[4];
        for (int d = 0; d < 4; d++) Dr[d] = D + (size_t)((i - d + 4 * rows) % rows) * W;
        unsigned char *Fr = path ? from + (size_t)i * W : NULL;
        double last = 0;   /* Dr[0][j - 1], kept in a register */
        for (int j = 0; j <= mB; j++) {
            if (!i && !j) { D[0] = 0; if (Fr) Fr[0] = 255; continue; }
            double best = INFINITY;
            int bs = 255;
            double f = dA ? wf * desc_dist(dA + (size_t)i * BMATCH_SCALES, dB + (size_t)j * BMATCH_SCALES) : 0;
            if (i >= 3 && j >= 3 && R > 0) {
                /* every step inside: all nine costs (each summed in the
                 * order of the loop below), then the first smallest below
                 * INFINITY, as that loop finds it, by a tree of pairwise
                 * choices (the earlier step wins ties): the costs do not
                 * wait for each other, and the one step from this row's
                 * previous cell (k = 2) joins last */
                double tAi = thA[i], tBj = thB[j], f5 = f * 0.5;
                const double *D1 = Dr[1], *D2 = Dr[2], *D3 = Dr[3];
                double a0 = tAi - thA[i], a1 = tAi - thA[i - 1], a2 = tAi - thA[i - 2], a3 = tAi - thA[i - 3];
                double b0 = tBj - thB[j], b1 = tBj - thB[j - 1], b2 = tBj - thB[j - 2], b3 = tBj - thB[j - 3];
                double c0 = dp_cost(D1[j - 1], stretch[0], R, a1, b1, f5, half[0]);
                double c1 = dp_cost(D1[j], stretch[1], R, a1, b0, f5, half[1]);
                double c3 = dp_cost(D1[j - 2], stretch[3], R, a1, b2, f5, half[3]);
                double c4 = dp_cost(D2[j - 1], stretch[4], R, a2, b1, f5, half[4]);
                double c5 = dp_cost(D1[j - 3], stretch[5], R, a1, b3, f5, half[5]);
                double c6 = dp_cost(D3[j - 1], stretch[6], R, a3, b1, f5, half[6]);
                double c7 = dp_cost(D2[j - 3], stretch[7], R, a2, b3, f5, half[7]);
                double c8 = dp_cost(D3[j - 2], stretch[8], R, a3, b2, f5, half[8]);
                double m01 = c1 < c0 ? c1 : c0;
                int k01 = c1 < c0 ? 1 : 0;
                double m34 = c4 < c3 ? c4 : c3;
                int k34 = c4 < c3 ? 4 : 3;
                double m56 = c6 < c5 ? c6 : c5;
                int k56 = c6 < c5 ? 6 : 5;
                double m78 = c8 < c7 ? c8 : c7;
                int k78 = c8 < c7 ? 8 : 7;
                double m36 = m56 < m34 ? m56 : m34;
                int k36 = m56 < m34 ? k56 : k34;
                double m38 = m78 < m36 ? m78 : m36;
                int k38 = m78 < m36 ? k78 : k36;
                double c2 = dp_cost(last, stretch[2], R, a0, b1, f5, half[2]);
                double m02 = c2 < m01 ? c2 : m01;
                int k02 = c2 < m01 ? 2 : k01;
                best = m38 < m02 ? m38 : m02;
                bs = m38 < m02 ? k38 : k02;
                if (!(best < INFINITY)) bs = 255;
            } else
            for (int k = 0; k < 9; k++) {
                int pi = i - STEPS[k][0], pj = j - STEPS[k][1];
                if (pi < 0 || pj < 0) continue;
                double prev = Dr[STEPS[k][0]][pj];
                if (!(prev < best)) continue;
                double c = prev + stretch[k] +
                           (R > 0 ? R * fabs((thA[i] - thA[pi]) - (thB[j] - thB[pj])) : 0) +
                           f * 0.5 * half[k];
                if (c < best) { best = c; bs = k; }
            }
            Dr[0][j] = last = best;
            if (Fr) Fr[j] = (unsigned char)bs;
        }
    }
    double cost = D[(size_t)(mA % rows) * W + mB];
    if (path) {
        int i = mA, j = mB, n = 0;
        while (1) {
            path[2 * n] = i; path[2 * n + 1] = j; n++;
            if (!i && !j) break;
            int k = from[(size_t)i * W + j];
            i -= STEPS[k][0]; j -= STEPS[k][1];
        }
        for (int a = 0, b = n - 1; a < b; a++, b--) {
            int t0 = path[2 * a], t1 = path[2 * a + 1];
            path[2 * a] = path[2 * b]; path[2 * a + 1] = path[2 * b + 1];
            path[2 * b] = t0; path[2 * b + 1] = t1;
        }
        *plen = n;
    }
    return cost;
}

/* how a segment is aligned: mode (BMATCH_*), bending weight R, feature weight wf, spread weight S */
struct dpset {
    int mode;
    double R, wf, S;
};

/* the samples one side of the dynamic program needs: m + 1 tangent angles
 * and (multi-scale mode) m + 1 descriptors */
struct dpside {
    double *th, *d;
};

static void dpside_fill(struct dpside *q, const struct outline *o, double s0, double len, int m, const struct dpset *ds)
{
    q->th = malloc((m + 1) * sizeof *q->th);
    sample_angles(o, s0, len, m, q->th);
    q->d = NULL;
    if (ds->mode == BMATCH_MULTISCALE) {
        q->d = malloc((size_t)(m + 1) * BMATCH_SCALES * sizeof *q->d);
        sample_desc(o, s0, len, m, q->d);
    }
}

static void dpside_free(struct dpside *q) { free(q->th); free(q->d); }

/* dp_align of side a (mA steps) against side b from sample t on (mB steps) */
static double dp_run(const struct dpside *a, int mA, double hA, const struct dpside *b, int t, int mB, double hB,
                     const struct dpset *ds, int *path, int *plen, double *D, unsigned char *from)
{
    return dp_align(a->th, mA, hA, b->th + t, mB, hB, ds->R, a->d, b->d ? b->d + (size_t)t * BMATCH_SCALES : NULL,
                    ds->wf, ds->S, path, plen, D, from);
}

/* Align the segment of A from arc sA of length lenA with the segment of B
 * from sB of length lenB (M samples per perimeter); map A's vertices whose
 * arc offset from sA lies in [0, lenA) into tB.  Returns the cost. */
static double align_segment(const struct outline *A, double sA, double lenA, const struct outline *B, double sB,
                            double lenB, int M, const struct dpset *ds, double *tB)
{
    int mA = (int)ceil(M * lenA / A->L), mB = (int)ceil(M * lenB / B->L);
    if (mA < 1) mA = 1;
    if (mB < 1) mB = 1;
    int *path = NULL, plen = 2;
    double cost = 0;
    if (ds->mode == BMATCH_ARCLENGTH) {
        path = malloc(4 * sizeof *path);
        path[0] = path[1] = 0; path[2] = mA; path[3] = mB;
    } else {
        struct dpside a, b;
        dpside_fill(&a, A, sA, lenA, mA, ds);
        dpside_fill(&b, B, sB, lenB, mB, ds);
        double *D = malloc((size_t)(mA + 1) * (mB + 1) * sizeof *D);
        unsigned char *from = malloc((size_t)(mA + 1) * (mB + 1));
        path = malloc(2 * (size_t)(mA + mB + 1) * sizeof *path);
        cost = dp_run(&a, mA, lenA / A->L / mA, &b, 0, mB, lenB / B->L / mB, ds, path, &plen, D, from);
        dpside_free(&a); dpside_free(&b);
        free(D); free(from);
    }
    /* piecewise-linear map along the path */
    for (int v = 0; v < A->n; v++) {
        double off = wrap(A->cum[v] - sA, A->L);
        if (off >= lenA) continue;
        double u = off / lenA * mA;      /* sample coordinate on A */
        int k = 0;
        while (k + 1 < plen - 1 && path[2 * (k + 1)] <= u) k++;
        double i0 = path[2 * k], j0 = path[2 * k + 1], i1 = path[2 * k + 2], j1 = path[2 * k + 3];
        double t = i1 > i0 ? (u - i0) / (i1 - i0) : 0;
        if (t < 0) t = 0;
        if (t > 1) t = 1;
        double w = j0 + t * (j1 - j0);
        tB[v] = wrap(sB + w / mB * lenB, B->L);
    }
    free(path);
    return cost;
}

/* the start search's closed alignments, one job each (parallel_run): the
 * coarse shifts of the doubled sides b, or the fine starts s[i] */
struct start_jobs {
    const struct outline *const *B;   /* the outlines searched */
    const struct dpside *a, *b;   /* coarse: A's side and each B's doubled side */
    const struct dpset *ds;
    int M, Mc;                    /* samples of a job's alignment (coarse: M = Mc) */
    const double *s;              /* fine: start arcs (NULL: coarse, job i = shift i % Mc of B[i / Mc]) */
    const int *who;               /* fine: the B of each start */
    double *cost;                 /* out, one per job */
};

static void start_job(void *ctx, int i)
{
    struct start_jobs *j = ctx;
    int M = j->M;   /* >= 16: four rows of D (dp_align without a path) */
    double *D = malloc(4 * (size_t)(M + 1) * sizeof *D);
    if (!j->s) {
        j->cost[i] = dp_run(j->a, j->Mc, 1.0 / j->Mc, &j->b[i / j->Mc], i % j->Mc, j->Mc, 1.0 / j->Mc, j->ds, NULL,
                            NULL, D, NULL);
    } else {
        const struct outline *B = j->B[j->who[i]];
        struct dpside b;
        dpside_fill(&b, B, j->s[i], B->L, M, j->ds);
        j->cost[i] = dp_run(j->a, M, 1.0 / M, &b, 0, M, 1.0 / M, j->ds, NULL, NULL, D, NULL);
        dpside_free(&b);
    }
    free(D);
}

/* For each of the nb outlines B[q]: the cost of the closed alignment from
 * A's sA with B[q]'s start at every coarse shift, then at the fine shifts
 * around the three best; out[q] gets the best start arc on B[q].  The
 * coarse alignments of every B are the jobs of one parallel_run on
 * `threads` threads, the fine ones of another (so several maps keep both
 * threads busy to the end); the choices are made in order after all of
 * them, so they do not depend on the threads.  0 or -1 (out of memory). */
static int search_starts(const struct outline *A, double sA, const struct outline *const *B, int nb, int M,
                         const struct dpset *ds, int threads, double *out)
{
    int Mc = M / 4 < 16 ? 16 : M / 4, r = M / Mc, per = 3 * (2 * r + 1);
    struct dpside a, *b = malloc(nb * sizeof *b);
    double *cost = malloc((size_t)nb * (Mc > per ? Mc : per) * sizeof *cost);
    double *s = malloc((size_t)nb * per * sizeof *s);
    int *who = malloc((size_t)nb * per * sizeof *who), *first = malloc((nb + 1) * sizeof *first);
    if (!b || !cost || !s || !who || !first) {
        free(b); free(cost); free(s); free(who); free(first);
        return cm_seterr("out of memory");
    }
    dpside_fill(&a, A, sA, A->L, Mc, ds);
    for (int q = 0; q < nb; q++) dpside_fill(&b[q], B[q], 0, 2 * B[q]->L, 2 * Mc, ds);
    struct start_jobs sj = {.B = B, .a = &a, .b = b, .ds = ds, .M = Mc, .Mc = Mc, .cost = cost};
    parallel_run(nb * Mc, threads, start_job, &sj);
    /* fine: M samples, shifts within one coarse step of the three best */
    int ns = 0;
    for (int q = 0; q < nb; q++) {
        double best[3] = {INFINITY, INFINITY, INFINITY};
        int bi[3] = {0, 0, 0};
        for (int t = 0; t < Mc; t++) {
            double c = cost[(size_t)q * Mc + t];
            for (int k = 0; k < 3; k++)
                if (c < best[k]) {
                    for (int l = 2; l > k; l--) { best[l] = best[l - 1]; bi[l] = bi[l - 1]; }
                    best[k] = c; bi[k] = t;
                    break;
                }
        }
        first[q] = ns;
        for (int k = 0; k < 3; k++) {
            if (!isfinite(best[k])) continue;
            for (int d = -r; d <= r; d++) {
                /* the three best are often neighbours: a start already in
                 * the list is aligned once (the first of equal costs wins
                 * either way) */
                double t = wrap((bi[k] * r + d) * B[q]->L / M, B[q]->L);
                int seen = 0;
                for (int u = first[q]; u < ns && !seen; u++) seen = s[u] == t;
                if (!seen) { s[ns] = t; who[ns] = q; ns++; }
            }
        }
    }
    first[nb] = ns;
    dpside_free(&a);
    for (int q = 0; q < nb; q++) dpside_free(&b[q]);
    dpside_fill(&a, A, sA, A->L, M, ds);
    struct start_jobs fj = {.B = B, .a = &a, .ds = ds, .M = M, .Mc = Mc, .s = s, .who = who, .cost = cost};
    parallel_run(ns, threads, start_job, &fj);
    for (int q = 0; q < nb; q++) {
        double bestc = INFINITY, bests = 0;
        for (int i = first[q]; i < first[q + 1]; i++)
            if (cost[i] < bestc) { bestc = cost[i]; bests = s[i]; }
        out[q] = bests;
    }
    dpside_free(&a);
    free(b); free(cost); free(s); free(who); free(first);
    return 0;
}

static int check_pairs(const int *pairs, int npairs, int na, int nb)
{
    for (int side = 0; side < 2; side++) {
        int n = side ? nb : na, prev = 0;
        for (int k = 0; k < npairs; k++) {
            int v = pairs[2 * k + side];
            if (v < 0 || v >= n) return cm_seterr("pair %d: vertex %d out of range 0..%d", k + 1, v, n - 1);
            int r = ((v - pairs[side]) % n + n) % n;
            if (k && r <= prev)
                return cm_seterr("pair %d: vertex %d repeats or breaks the cyclic order", k + 1, v);
            prev = r;
        }
    }
    return 0;
}

/* the parameters of a map with npairs given pairs */
static int params_check(const struct bmatch_params *prm, int npairs)
{
    if (prm->samples < 16 || prm->samples > 4096) return cm_seterr("samples must be in 16..4096");
    if (!(prm->bend >= 0 && prm->bend < 1e6) || !(prm->start_bend >= 0 && prm->start_bend < 1e6))
        return cm_seterr("bending weight must be >= 0");
    if (!(prm->feature >= 0 && prm->feature < 1e6)) return cm_seterr("feature weight must be >= 0");
    if (!(prm->spread >= 0 && prm->spread < 1e6)) return cm_seterr("spread weight must be >= 0");
    if (prm->mode == BMATCH_ARCLENGTH && npairs < 1)
        return cm_seterr("arc-length matching needs a given correspondence point");
    return 0;
}

int bmatch_map(const double *Ap, int na, const double *Bp, int nb, const int *pairs, int npairs,
               const struct bmatch_params *prm, double *tB, double *cost)
{
    if (params_check(prm, npairs) < 0) return -1;
    if (check_pairs(pairs, npairs, na, nb) < 0) return -1;
    struct outline A, B;
    if (outline_init(&A, Ap, na) < 0) return -1;
    if (outline_init(&B, Bp, nb) < 0) { free(A.cum); return -1; }
    double c = 0;
    int M = prm->samples;
    struct dpset ds = {prm->mode, prm->bend, prm->feature, prm->spread};
    if (npairs == 0) {
        struct dpset ss = ds;
        if (ss.mode == BMATCH_ELASTIC) ss.R = prm->start_bend;
        const struct outline *Bs = &B;
        double s;
        if (search_starts(&A, 0, &Bs, 1, M, &ss, prm->threads, &s) < 0) { free(A.cum); free(B.cum); return -1; }
        c = align_segment(&A, 0, A.L, &B, s, B.L, M, &ds, tB);
    } else {
        for (int k = 0; k < npairs; k++) {
            int a0 = pairs[2 * k], b0 = pairs[2 * k + 1];
            int a1 = pairs[2 * ((k + 1) % npairs)], b1 = pairs[2 * ((k + 1) % npairs) + 1];
            double lA = wrap(A.cum[a1] - A.cum[a0], A.L), lB = wrap(B.cum[b1] - B.cum[b0], B.L);
            if (npairs == 1) { lA = A.L; lB = B.L; }
            c += align_segment(&A, A.cum[a0], lA, &B, B.cum[b0], lB, M, &ds, tB);
        }
    }
    if (cost) *cost = c;
    free(A.cum); free(B.cum);
    return 0;
}

/* vertex of o nearest to arc position t (by arc length) */
static int nearest_vertex(const struct outline *o, double t)
{
    int best = 0;
    double bd = INFINITY;
    for (int i = 0; i < o->n; i++) {
        double d = fabs(o->cum[i] - t);
        d = fmin(d, o->L - d);
        if (d < bd) { bd = d; best = i; }
    }
    return best;
}

/* bmatch_corr's maps of shape 0 onto shapes 1..N-1, one job each */
struct map_jobs {
    int N;
    double *const *P;
    const int *n, *given;
    int ngiven;
    const struct bmatch_params *prm;
    double *tB;                   /* row s: shape 0's vertices on shape s */
    double *cost;                 /* N */
    char (*err)[256];             /* N messages ("" if the map succeeded) */
};

static void map_job(void *ctx, int i)
{
    struct map_jobs *j = ctx;
    int s = i + 1, N = j->N;
    int *pairs = malloc(2 * (j->ngiven + 1) * sizeof *pairs);
    if (!pairs) { snprintf(j->err[s], sizeof j->err[s], "out of memory"); return; }
    for (int k = 0; k < j->ngiven; k++) { pairs[2 * k] = j->given[k * N]; pairs[2 * k + 1] = j->given[k * N + s]; }
    if (bmatch_map(j->P[0], j->n[0], j->P[s], j->n[s], pairs, j->ngiven, j->prm, j->tB + (size_t)s * j->n[0],
                   &j->cost[s]) < 0)
        snprintf(j->err[s], sizeof j->err[s], "%s", cm_errmsg());
    free(pairs);
}

/* bmatch_corr's maps of shape 0 (O[0]) onto shapes 1..N-1 (O[s]) when no
 * point is given: bmatch_map's start search and alignment, with the start
 * searches of all the maps on the threads at once (search_starts), then
 * each map's alignment a job; the same maps as bmatch_map's, whose jobs
 * (one per map) left a thread idle at the end (five maps on two threads) */
struct align_jobs {
    const struct outline *A, *const *B;   /* B[i]: shape i + 1 */
    const double *start;                  /* the start arc on each B */
    const struct dpset *ds;
    int M, n0;
    double *tB, *cost;                    /* rows / entries by shape */
};

static void align_job(void *ctx, int i)
{
    struct align_jobs *j = ctx;
    j->cost[i + 1] = align_segment(j->A, 0, j->A->L, j->B[i], j->start[i], j->B[i]->L, j->M, j->ds,
                                   j->tB + (size_t)(i + 1) * j->n0);
}

static int maps_unanchored(int N, const struct outline *O, const int *n, const struct bmatch_params *prm,
                           double *tB, double *cost)
{
    if (params_check(prm, 0) < 0) return cm_seterr("shape 1: %s", cm_errmsg());
    struct dpset ds = {prm->mode, prm->bend, prm->feature, prm->spread}, ss = ds;
    if (ss.mode == BMATCH_ELASTIC) ss.R = prm->start_bend;
    const struct outline **B = malloc((N - 1) * sizeof *B);
    double *start = malloc((N - 1) * sizeof *start);
    int rc = B && start ? 0 : cm_seterr("out of memory");
    for (int s = 1; s < N && rc == 0; s++) B[s - 1] = &O[s];
    if (rc == 0) rc = search_starts(&O[0], 0, B, N - 1, prm->samples, &ss, prm->threads, start);
    if (rc == 0) {
        struct align_jobs aj = {&O[0], B, start, &ds, prm->samples, n[0], tB, cost};
        parallel_run(N - 1, prm->threads, align_job, &aj);
    }
    free(B); free(start);
    return rc;
}

int bmatch_corr(int N, double *const *P, const int *n, const int *given, int ngiven, const int *want,
                int nwant, int K, const struct bmatch_params *prm, int **corr_out, int *ncorr, double *cost)
{
    *corr_out = NULL; *ncorr = 0;
    if (K < 3) return cm_seterr("need at least 3 points (K = %d)", K);
    if (K < ngiven + nwant) K = ngiven + nwant;
    for (int k = 0; k < nwant; k++) {
        if (want[k] < 0 || want[k] >= n[0]) return cm_seterr("point %d: vertex %d out of range 0..%d", k + 1, want[k], n[0] - 1);
        for (int l = 0; l < ngiven; l++)
            if (given[l * N] == want[k]) return cm_seterr("point %d: vertex %d of shape 0 is given twice", k + 1, want[k]);
        for (int l = 0; l < k; l++)
            if (want[l] == want[k]) return cm_seterr("points %d and %d: both are vertex %d of shape 0", l + 1, k + 1, want[k]);
    }
    struct outline *O = calloc(N, sizeof *O);
    double *tB = malloc((size_t)N * n[0] * sizeof *tB);   /* row s: shape 0's vertices on shape s */
    int rc = 0, s;
    for (s = 0; s < N && rc == 0; s++)
        if (outline_init(&O[s], P[s], n[s]) < 0) rc = -1;
    int ninit = s - (rc < 0);
    /* the maps of shape 0 onto every shape: one job each where there are
     * more maps than one, else the one map's start search takes the threads;
     * without a given point the start searches of all maps share them */
    if (cost) cost[0] = 0;
    if (rc == 0) {
        struct bmatch_params one = *prm;
        one.threads = 1;
        struct map_jobs mj = {N, P, n, given, ngiven, N > 2 ? &one : prm, tB, malloc(N * sizeof *mj.cost),
                              calloc(N, sizeof *mj.err)};
        if (!mj.cost || !mj.err) rc = cm_seterr("out of memory");
        else if (ngiven == 0 && N > 2 && prm->mode != BMATCH_ARCLENGTH) {
            rc = maps_unanchored(N, O, n, prm, tB, mj.cost);
            for (s = 1; s < N && rc == 0; s++) if (cost) cost[s] = mj.cost[s];
        } else {
            parallel_run(N - 1, N > 2 ? prm->threads : 1, map_job, &mj);
            for (s = 1; s < N && rc == 0; s++)
                if (mj.err[s][0]) rc = cm_seterr("shape %d: %s", s, mj.err[s]);
                else if (cost) cost[s] = mj.cost[s];
        }
        free(mj.cost); free(mj.err);
    }
    if (rc < 0) {
        for (s = 0; s < ninit; s++) free(O[s].cum);
        free(O); free(tB);
        return -1;
    }
    const struct outline *A = &O[0];
    /* salience of shape 0's vertices: turning between the chords of +-3% */
    double *sal = malloc(n[0] * sizeof *sal);
    int *order = malloc(n[0] * sizeof *order);
    for (int i = 0; i < n[0]; i++) {
        double w = 0.03 * A->L, p[2], q[2], r[2];
        outline_point(A, A->cum[i] - w, p);
        outline_point(A, A->cum[i], q);
        outline_point(A, A->cum[i] + w, r);
        double t = atan2(r[1] - q[1], r[0] - q[0]) - atan2(q[1] - p[1], q[0] - p[0]);
        t -= 2 * M_PI * floor((t + M_PI) / (2 * M_PI));
        sal[i] = fabs(t);
        order[i] = i;
    }
    for (int a = 1; a < n[0]; a++)      /* by salience, stable */
        for (int b = a; b > 0 && sal[order[b]] > sal[order[b - 1]]; b--) {
            int t = order[b]; order[b] = order[b - 1]; order[b - 1] = t;
        }
    /* anchors on shape 0 with their vertices in every shape: the given
     * points, the wanted ones, then the most salient vertices */
    int *anc = malloc(K * sizeof *anc), na = 0;
    int *cand = malloc((size_t)K * N * sizeof *cand);
    int *row = malloc(N * sizeof *row);
    unsigned char *isgiven = calloc(n[0], 1);
    for (int k = 0; k < ngiven + nwant; k++) {
        int v = k < ngiven ? given[k * N] : want[k - ngiven];
        if (k < ngiven) isgiven[v] = 1;
        anc[na] = v;
        for (s = 0; s < N; s++) {
            cand[(size_t)na * N + s] = k < ngiven ? given[k * N + s]
                                     : s == 0 ? v : nearest_vertex(&O[s], tB[(size_t)s * n[0] + v]);
        }
        na++;
    }
    double sep = 0.5 * A->L / K;
    for (int oi = 0; oi < n[0] && na < K; oi++) {
        int i = order[oi], ok = 1;
        for (int k = 0; k < na && ok; k++) {
            double d = fabs(A->cum[i] - A->cum[anc[k]]);
            if (fmin(d, A->L - d) < sep) ok = 0;
        }
        if (!ok) continue;
        row[0] = i;
        for (s = 1; s < N; s++) row[s] = nearest_vertex(&O[s], tB[(size_t)s * n[0] + i]);
        anc[na] = i;
        memcpy(cand + (size_t)na * N, row, N * sizeof *row);
        na++;
    }
    free(sal); free(order); free(row);
    for (s = 0; s < N; s++) free(O[s].cum);
    free(O); free(tB);
    /* order the rows along shape 0 from the first given point (or the first) */
    int origin = ngiven ? given[0] : anc[0];
    for (int a = 1; a < na; a++)
        for (int b = a; b > 0; b--) {
            int rb = (anc[b] - origin + n[0]) % n[0], ra = (anc[b - 1] - origin + n[0]) % n[0];
            if (rb >= ra) break;
            int t = anc[b]; anc[b] = anc[b - 1]; anc[b - 1] = t;
            for (s = 0; s < N; s++) {
                int u = cand[(size_t)b * N + s];
                cand[(size_t)b * N + s] = cand[(size_t)(b - 1) * N + s];
                cand[(size_t)(b - 1) * N + s] = u;
            }
        }
    /* keep the rows that increase strictly along every outline, given rows always */
    int *corr = malloc((size_t)na * N * sizeof *corr), nc = 0;
    for (int a = 0; a < na; a++) {
        const int *row = cand + (size_t)a * N;
        int keep = 1, given_row = isgiven[row[0]];
        for (int s = 0; s < N && keep && nc > 0 && !given_row; s++) {
            int r = ((row[s] - corr[s]) % n[s] + n[s]) % n[s];
            int rp = ((corr[(size_t)(nc - 1) * N + s] - corr[s]) % n[s] + n[s]) % n[s];
            if (r <= rp) keep = 0;
            /* before the next given row (or the end of the loop) */
            for (int b = a + 1; b < na && keep; b++)
                if (isgiven[cand[(size_t)b * N]]) {
                    int rg = ((cand[(size_t)b * N + s] - corr[s]) % n[s] + n[s]) % n[s];
                    if (r >= rg) keep = 0;
                    break;
                }
        }
        if (keep) { memcpy(corr + (size_t)nc * N, row, N * sizeof *row); nc++; }
    }
    free(anc); free(isgiven); free(cand);
    if (nc < 3) {
        free(corr);
        return cm_seterr("only %d distinct correspondence points could be placed; give more points "
                         "or finer outlines", nc);
    }
    *corr_out = corr;
    *ncorr = nc;
    return 0;
}
