/* replib_sketch.c -- one-pass low-rank sketch of an animation (see replib_sketch.h). */
#include "replib_sketch.h"
#include "cm_error.h"
#include "rng.h"
#include <cblas.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

extern void dgeqrf_(const int *m, const int *n, double *a, const int *lda, double *tau, double *work,
                    const int *lwork, int *info);
extern void dorgqr_(const int *m, const int *n, const int *k, double *a, const int *lda, const double *tau,
                    double *work, const int *lwork, int *info);
extern void dgels_(const char *trans, const int *m, const int *n, const int *nrhs, double *a, const int *lda,
                   double *b, const int *ldb, double *work, const int *lwork, int *info);

#define BATCH 64

void replib_sketch_free(struct replib_sketch *S)
{
    free(S->ref); free(S->sw); free(S->Om); free(S->Y); free(S->W); free(S->zz); free(S->dd);
    free(S->cut); free(S->Xk); free(S->xbase); free(S->kb); free(S->zb); free(S->zprev); free(S->V);
    memset(S, 0, sizeof *S);
}

int replib_sketch_init(struct replib_sketch *S, int nv, int k, const double *w, size_t keep_bytes,
                       uint64_t seed)
{
    memset(S, 0, sizeof *S);
    if (nv < 1 || k < 1) return cm_seterr("replib_sketch: %d vertices, rank %d", nv, k);
    int m3 = S->m3 = 3 * nv;
    S->nv = nv; S->k = k; S->s = 2 * k + 1; S->seed = seed;
    S->keep_bytes = keep_bytes; S->keeping = keep_bytes > 0;
    S->ref = malloc(sizeof(double) * m3);
    S->Om = malloc(sizeof(double) * (size_t)m3 * k);
    S->W = calloc((size_t)S->s * m3, sizeof(double));
    S->zb = malloc(sizeof(double) * (size_t)BATCH * m3);
    S->zprev = malloc(sizeof(double) * m3);
    if (!S->ref || !S->Om || !S->W || !S->zb || !S->zprev) goto oom;
    if (S->keeping && !(S->kb = malloc(sizeof(double) * (size_t)REPLIB_KEEP_CHUNK * m3))) goto oom;
    if (w) {
        double sum = 0;
        for (int i = 0; i < nv; i++) {
            if (!isfinite(w[i]) || w[i] < 0) {
                replib_sketch_free(S);
                return cm_seterr("weight of vertex %d is %g: weights must be finite and >= 0", i, w[i]);
            }
            sum += w[i];
        }
        if (!(sum > 0)) { replib_sketch_free(S); return cm_seterr("all weights are zero"); }
        if (!(S->sw = malloc(sizeof(double) * m3))) goto oom;
        for (int i = 0; i < nv; i++) S->sw[3 * i] = S->sw[3 * i + 1] = S->sw[3 * i + 2] = sqrt(w[i]);
    }
    struct rng g;
    rng_seed(&g, seed ^ 0x0e6a5eedULL);
    for (size_t t = 0; t < (size_t)m3 * k; t++) S->Om[t] = rng_normal(&g);
    return 0;
oom:
    replib_sketch_free(S);
    return cm_seterr("replib_sketch: out of memory (%d vertices, rank %d)", nv, k);
}

/* column f of Psi (s values) */
static void psi_col(const struct replib_sketch *S, int f, double *p)
{
    struct rng g;
    rng_seed(&g, S->seed * 0x9E3779B97F4A7C15ULL + 0x5107c4ULL + (uint64_t)f);
    for (int i = 0; i < S->s; i++) p[i] = rng_normal(&g);
}

static int flush(struct replib_sketch *S)
{
    int nb = S->nb, m3 = S->m3, k = S->k, s = S->s, f0 = S->n - nb;
    if (nb == 0) return 0;
    cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasNoTrans, nb, k, m3, 1.0, S->zb, m3, S->Om, k, 0.0,
                S->Y + (size_t)f0 * k, k);
    double *Pb = malloc(sizeof(double) * (size_t)nb * s);
    if (!Pb) return cm_seterr("replib_sketch: out of memory");
    for (int b = 0; b < nb; b++) psi_col(S, f0 + b, Pb + (size_t)b * s);
    /* W += Psi_b^T Z_b  (s by nb times nb by 3#V) */
    cblas_dgemm(CblasRowMajor, CblasTrans, CblasNoTrans, s, m3, nb, 1.0, Pb, s, S->zb, m3, 1.0, S->W, m3);
    free(Pb);
    S->nb = 0;
    return 0;
}

static int grow(struct replib_sketch *S)
{
    int nc = S->cap ? 2 * S->cap : 1024;
    double *Y = realloc(S->Y, sizeof(double) * (size_t)nc * S->k);
    if (!Y) return -1;
    S->Y = Y;
    double *zz = realloc(S->zz, sizeof(double) * nc);
    if (!zz) return -1;
    S->zz = zz;
    double *dd = realloc(S->dd, sizeof(double) * nc);
    if (!dd) return -1;
    S->dd = dd;
    double *xo = realloc(S->xbase, sizeof(double) * (size_t)(nc / REPLIB_KEEP_CHUNK + 1) * S->m3);
    if (!xo) return -1;
    S->xbase = xo;
    unsigned char *c = realloc(S->cut, nc);
    if (!c) return -1;
    S->cut = c;
    S->cap = nc;
    return 0;
}

/* Encode the buffered frames of the chunk that ends before frame f1 into
 * the kept 32-bit frames: base = the midrange of each coordinate over the
 * chunk (on the input's grid), then integers of the step while every value
 * is on the grid and within +-2^31 steps, else floats (all kept frames
 * turned to floats once, in place). */
static void keep_chunk(struct replib_sketch *S, int f1)
{
    int m3 = S->m3, c = (f1 - 1) / REPLIB_KEEP_CHUNK, f0 = c * REPLIB_KEEP_CHUNK, nb = f1 - f0;
    double q = S->xstep, e = 0, *o = S->xbase + (size_t)c * m3;
    for (int t = 0; t < m3; t++) {
        double lo = S->kb[t], hi = lo;
        for (int g = 1; g < nb; g++) {
            double v = S->kb[(size_t)g * m3 + t];
            lo = v < lo ? v : lo;
            hi = v > hi ? v : hi;
        }
        o[t] = q > 0 ? nearbyint(0.5 * (lo + hi) / q) * q : 0.5 * (lo + hi);
    }
    for (int g = 0; g < nb && S->fixed; g++) {
        const double *x = S->kb + (size_t)g * m3;
        int32_t *xi = (int32_t *)S->Xk + (size_t)(f0 + g) * m3;
        for (int t = 0; t < m3; t++) {
            double v = x[t] - o[t], k = nearbyint(v / q), ek = fabs(k * q - v);
            if (!(fabs(k) <= 2147483647.0) || ek > 1e-3 * q) { S->fixed = 0; break; }
            xi[t] = (int32_t)k;
            if (ek > e) e = ek;
        }
    }
    if (!S->fixed && f0 > 0 && S->xstep > 0 && !S->floated) {
        /* off the grid or out of range: the earlier chunks to float, in place */
        for (size_t t = 0; t < (size_t)f0 * m3; t++) {
            int32_t k;
            memcpy(&k, (char *)S->Xk + 4 * t, 4);
            double v = k * q;
            float fv = (float)v;
            memcpy((char *)S->Xk + 4 * t, &fv, 4);
            if (fabs((double)fv - v) > e) e = fabs((double)fv - v);
        }
    }
    if (!S->fixed) {
        S->floated = 1;
        for (int g = 0; g < nb; g++) {
            const double *x = S->kb + (size_t)g * m3;
            float *xf = (float *)S->Xk + (size_t)(f0 + g) * m3;
            for (int t = 0; t < m3; t++) {
                double v = x[t] - o[t];
                xf[t] = (float)v;
                if (fabs((double)xf[t] - v) > e) e = fabs((double)xf[t] - v);
            }
        }
    }
    if (e > S->float_err) S->float_err = e;
}

int replib_sketch_add(struct replib_sketch *S, const double *x, int cut)
{
    int m3 = S->m3, f = S->n;
    for (int t = 0; t < m3; t++)
        if (!isfinite(x[t])) return cm_seterr("frame %d: vertex %d: coordinate is not finite", f, t / 3);
    if (f == S->cap && grow(S) < 0) return cm_seterr("replib_sketch: out of memory at frame %d", f);
    if (f == 0) {
        memcpy(S->ref, x, sizeof(double) * m3);
        S->xstep = replib_input_step(x, m3);
        S->fixed = S->xstep > 0;
    }
    if (S->keeping) {
        size_t need = (size_t)(f + 1) * m3 * 4;
        if (need > S->keep_bytes) {
            free(S->Xk); S->Xk = NULL; S->keeping = 0;      /* too long: sketch only */
        } else {
            /* grow the kept frames geometrically, within the budget */
            void *nx = S->Xk;
            if (f == S->xcap) {
                size_t nc = S->xcap ? 2 * (size_t)S->xcap : 256, lim = S->keep_bytes / ((size_t)m3 * 4);
                if (nc > lim) nc = lim;
                nx = realloc(S->Xk, nc * m3 * 4);
                if (nx) S->xcap = (int)nc;
            }
            if (!nx) { free(S->Xk); S->Xk = NULL; S->keeping = 0; }
            else {
                S->Xk = nx;
                memcpy(S->kb + (size_t)(f % REPLIB_KEEP_CHUNK) * m3, x, sizeof(double) * m3);
                if (f % REPLIB_KEEP_CHUNK == REPLIB_KEEP_CHUNK - 1) keep_chunk(S, f + 1);
            }
        }
    }
    double *z = S->zb + (size_t)S->nb * m3;
    double zz = 0, dd = 0;
    for (int t = 0; t < m3; t++) {
        double v = x[t] - S->ref[t];
        if (S->sw) v *= S->sw[t];
        z[t] = v;
        zz += v * v;
        if (f > 0) dd += (v - S->zprev[t]) * (v - S->zprev[t]);
    }
    memcpy(S->zprev, z, sizeof(double) * m3);
    S->zz[f] = zz;
    S->cut[f] = f > 0 && cut;
    if (f > 0) S->dd[f - 1] = cut ? 0 : dd;
    S->dd[f] = 0;
    S->zn += zz;
    S->n++;
    S->nb++;
    if (S->nb == BATCH) return flush(S);
    return 0;
}

int replib_sketch_finish(struct replib_sketch *S, struct replib_data *D)
{
    if (flush(S) < 0) return -1;
    if (S->keeping && S->n % REPLIB_KEEP_CHUNK) keep_chunk(S, S->n);
    int n = S->n, k = S->k, s = S->s, m3 = S->m3, info = 0;
    if (n < 1) return cm_seterr("replib_sketch: no frames");
    if (!S->keeping && S->sw)
        for (int t = 0; t < m3; t++)
            if (S->sw[t] == 0)
                return cm_seterr("vertex %d has weight 0: its pieces cannot be recovered from the sketch "
                                 "(keep the frames: a larger memory budget)", t / 3);
    int r = k < n ? k : n;          /* rank of the result */
    free(S->Om); S->Om = NULL;      /* no more frames */
    /* Q = orth(Y): column-major n by k is Y^T row-major... transpose in */
    double *Qc = malloc(sizeof(double) * (size_t)n * k), *tau = malloc(sizeof(double) * k);
    double *Psi = malloc(sizeof(double) * (size_t)n * s);
    if (!Qc || !tau || !Psi) { free(Qc); free(tau); free(Psi); return cm_seterr("replib_sketch: out of memory"); }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < k; j++) Qc[(size_t)j * n + i] = S->Y[(size_t)i * k + j];
    int lwork = -1;
    double q;
    dgeqrf_(&n, &r, Qc, &n, tau, &q, &lwork, &info);
    lwork = (int)q > k * 64 ? (int)q : k * 64;
    double *work = malloc(sizeof(double) * lwork);
    if (!work) { free(Qc); free(tau); free(Psi); return cm_seterr("replib_sketch: out of memory"); }
    dgeqrf_(&n, &r, Qc, &n, tau, work, &lwork, &info);
    if (info == 0) dorgqr_(&n, &r, &r, Qc, &n, tau, work, &lwork, &info);
    free(work);
    if (info != 0) { free(Qc); free(tau); free(Psi); return cm_seterr("replib_sketch: QR failed (%d)", info); }
    /* M = Psi Q (s by r), column-major for dgels; Psi stored n by s row-major = s by n column-major */
    for (int f = 0; f < n; f++) psi_col(S, f, Psi + (size_t)f * s);
    double *M = malloc(sizeof(double) * (size_t)s * r);
    if (!M) { free(Qc); free(tau); free(Psi); return cm_seterr("replib_sketch: out of memory"); }
    /* M (col-major s x r) = Psi(col-major s x n) * Qc (col-major n x r) */
    cblas_dgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, s, r, n, 1.0, Psi, s, Qc, n, 0.0, M, s);
    free(Psi);
    /* B = M^+ W: W row-major s by 3#V is column-major 3#V by s; solve with
     * the transposed right-hand side W^T: dgels wants s by nrhs column-major
     * = row-major nrhs by s... transpose W into Wc (s by 3#V column-major). */
    double *Wc = malloc(sizeof(double) * (size_t)s * m3);
    if (!Wc) { free(Qc); free(tau); free(M); return cm_seterr("replib_sketch: out of memory"); }
    for (int i = 0; i < s; i++)
        for (int t = 0; t < m3; t++) Wc[(size_t)t * s + i] = S->W[(size_t)i * m3 + t];
    free(S->W); S->W = NULL;
    lwork = -1;
    dgels_("N", &s, &r, &m3, M, &s, Wc, &s, &q, &lwork, &info);
    lwork = (int)q > 1 ? (int)q : 1;
    work = malloc(sizeof(double) * lwork);
    if (!work) { free(Qc); free(tau); free(M); free(Wc); return cm_seterr("replib_sketch: out of memory"); }
    dgels_("N", &s, &r, &m3, M, &s, Wc, &s, work, &lwork, &info);
    free(work); free(M);
    if (info != 0) { free(Qc); free(tau); free(Wc); return cm_seterr("replib_sketch: least squares failed (%d)", info); }
    /* B (r by 3#V) = first r rows of each column of Wc; B^T (3#V by r, column-major) = V R */
    double *Bt = malloc(sizeof(double) * (size_t)m3 * r);
    if (!Bt) { free(Qc); free(tau); free(Wc); return cm_seterr("replib_sketch: out of memory"); }
    for (int t = 0; t < m3; t++)
        for (int j = 0; j < r; j++) Bt[(size_t)j * m3 + t] = Wc[(size_t)t * s + j];
    free(Wc);
    lwork = -1;
    dgeqrf_(&m3, &r, Bt, &m3, tau, &q, &lwork, &info);
    lwork = (int)q > r ? (int)q : r;
    work = malloc(sizeof(double) * lwork);
    double *Rt = calloc((size_t)r * r, sizeof(double));
    if (!work || !Rt) { free(work); free(Rt); free(Qc); free(tau); free(Bt); return cm_seterr("replib_sketch: out of memory"); }
    dgeqrf_(&m3, &r, Bt, &m3, tau, work, &lwork, &info);
    for (int i = 0; i < r; i++)          /* Rt row-major r x r: Rt[i][j] = R[j][i] (j <= i) */
        for (int j = 0; j <= i; j++) Rt[(size_t)i * r + j] = Bt[(size_t)j + (size_t)i * m3];
    if (info == 0) dorgqr_(&m3, &r, &r, Bt, &m3, tau, work, &lwork, &info);
    free(work); free(tau);
    if (info != 0) { free(Rt); free(Qc); free(Bt); return cm_seterr("replib_sketch: QR failed (%d)", info); }
    /* V (3#V by r row-major) from Bt (column-major 3#V by r) */
    S->V = malloc(sizeof(double) * (size_t)m3 * r);
    double *Zr = malloc(sizeof(double) * (size_t)n * r);
    if (!S->V || !Zr) { free(Zr); free(Rt); free(Qc); free(Bt); return cm_seterr("replib_sketch: out of memory"); }
    for (int t = 0; t < m3; t++)
        for (int j = 0; j < r; j++) S->V[(size_t)t * r + j] = Bt[(size_t)j * m3 + t];
    free(Bt);
    /* Zr = Q R^T: Q column-major n x r = row-major Q^T (r x n) */
    cblas_dgemm(CblasRowMajor, CblasTrans, CblasNoTrans, n, r, r, 1.0, Qc, n, Rt, r, 0.0, Zr, r);
    free(Qc); free(Rt);
    /* fill D as replib_prepare would */
    memset(D, 0, sizeof *D);
    D->n = D->N = n; D->nv = S->nv; D->m3 = m3; D->X = NULL;
    D->Xf = S->keeping && !S->fixed ? (const float *)S->Xk : NULL;
    D->Xi = S->keeping && S->fixed ? (const int32_t *)S->Xk : NULL;
    D->xstep = S->xstep; D->step = S->xstep; D->xbase = S->keeping ? S->xbase : NULL;
    D->ref = S->ref; D->V = S->V; D->sw = S->sw;
    D->link = calloc(n, 1);
    D->mean = calloc(m3, sizeof(double));
    D->zz = malloc(sizeof(double) * n);
    D->dd = calloc(n, sizeof(double));
    if (!D->link || !D->mean || !D->zz || !D->dd) { free(Zr); replib_data_free(D); return cm_seterr("replib_sketch: out of memory"); }
    D->cut = S->cut;
    for (int f = 0; f + 1 < n; f++) D->link[f] = !S->cut[f + 1];
    double zr = 0;
    for (int f = 0; f < n; f++) {
        const double *z = Zr + (size_t)f * r;
        D->zz[f] = cblas_ddot(r, z, 1, z, 1);
        zr += D->zz[f];
        if (f + 1 < n && D->link[f]) {
            double v = 0;
            for (int j = 0; j < r; j++) v += (z[r + j] - z[j]) * (z[r + j] - z[j]);
            D->dd[f] = v;
        }
    }
    S->captured = S->zn > 0 ? zr / S->zn : 1;
    D->Z = Zr; D->zdim = r; D->lowrank = r; D->gram = 0;
    return 0;
}
