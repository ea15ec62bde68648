/* replib.c -- replacement library by block coordinate descent (see replib.h). */
#include "replib.h"
#include "big_alloc.h"
#include "chainlabel.h"
#include "cm_error.h"
#include "rng.h"
#include "parallel.h"
#include <cblas.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <time.h>
#include <pthread.h>
#include <unistd.h>
#include <immintrin.h>

/* LAPACK (column-major Fortran interface, from OpenBLAS/liblapack) */
extern int openblas_get_num_threads(void);
extern void openblas_set_num_threads(int);
extern void dgeqrf_(const int *m, const int *n, double *a, const int *lda, double *tau, double *work,
                    const int *lwork, int *info);
extern void dorgqr_(const int *m, const int *n, const int *k, double *a, const int *lda, const double *tau,
                    double *work, const int *lwork, int *info);
extern void dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info);

static double wall(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

#define GRAM_AUTO_MAX 12000       /* N above this: K would exceed ~1.1 GB; use direct */
/* candidates per frame in the label steps of split/merge trials at lambda
 * > 0 (the cheapest pieces by data cost, plus the current label): on the
 * Monkey-size benchmark (d = 150) 8, 16 and 32 all gave the exact DP's
 * final energy, at 9.5, 11.1 and 12.8 s CPU against 15.7 s (8045066);
 * 8 gave the same final energies as 16 on the 16 cases of the dict tests
 * and benches (facecap parts, elephant, d 20-150, lambda 0 and 2) */
#define REPLIB_TRIAL_CANDIDATES 8
#define REPLIB_SAMPLE_MAX_BYTES (512.0 * 1048576)   /* copy of the sample's rows of Z */

/* Exact low-rank Gram matrix.  Blend-shape animations (faces) have a small
 * rank: facecap's 335 frames span 52 dimensions to rounding.  With a random
 * range finder (Halko et al. 2011) Y = Z Omega, Q = orth(Y), B = Q^T Z, the
 * residual E = Z - Q B is computed explicitly; if |E|_F <= 1e-12 |Z|_F the
 * Gram matrix is K = Q (B B^T) Q^T, at 6 N 3#V r flops instead of the
 * N^2 3#V of DSYRK.  Ranks r = 64, 128, ... up to N / 24 are tried (so a
 * failed attempt costs at most half a DSYRK).  Returns the rank used, 0 if
 * Z is not that low-rank (K untouched), -1 on allocation failure. */
/* Rows i0 .. i0+nb-1 of Z (centered, weighted frames and fixed pieces)
 * into out (nb by 3#V); sw: 3#V square roots of the weights or NULL. */
static void z_rows(const struct replib_data *D, const double *sw, int i0, int nb, double *out)
{
    int n = D->n, m3 = D->m3;
    const double *mu = D->mean;
    for (int g = i0; g < i0 + nb; g++) {
        const double *x = g < n ? D->X + (size_t)g * m3 : D->Rfix + (size_t)(g - n) * m3;
        double *z = out + (size_t)(g - i0) * m3;
        if (sw) for (int k = 0; k < m3; k++) z[k] = sw[k] * (x[k] - mu[k]);
        else for (int k = 0; k < m3; k++) z[k] = x[k] - mu[k];
    }
}

/* The Gram matrix K = Z Z^T (upper triangle) of the centred, weighted rows,
 * by blocks of GRAM_COLS columns: K is the sum over column blocks c of
 * Z[:, c] Z[:, c]^T, so each block of Z is made in a buffer of N x GRAM_COLS
 * that stays in cache and is added by one SYRK.  Z (N x 3#V) is never held
 * whole: on a 335 x 3510 facecap part that saves writing (and first touching)
 * 9.4 MB, a third of the preparation.  single: SSYRK into a float K, then
 * widened (gram == 2).  Returns -1 when out of memory. */
#define GRAM_COLS 256
static int gram_by_columns(struct replib_data *D, const double *sw, int single)
{
    int n = D->n, N = D->N, m3 = D->m3;
    const double *mu = D->mean;
    double *B = single ? NULL : malloc(sizeof(double) * (size_t)N * GRAM_COLS);
    float *Bf = single ? malloc(sizeof(float) * (size_t)N * GRAM_COLS) : NULL;
    float *Kf = single ? calloc((size_t)N * N, sizeof(float)) : NULL;
    if (single ? !Bf || !Kf : !B) { free(B); free(Bf); free(Kf); return -1; }
    for (int c0 = 0; c0 < m3; c0 += GRAM_COLS) {
        int cb = m3 - c0 < GRAM_COLS ? m3 - c0 : GRAM_COLS;
        for (int g = 0; g < N; g++) {
            const double *x = (g < n ? D->X + (size_t)g * m3 : D->Rfix + (size_t)(g - n) * m3) + c0;
            double *b = B + (size_t)g * cb;
            float *bf = Bf + (size_t)g * cb;
            for (int k = 0; k < cb; k++) {
                double z = sw ? sw[c0 + k] * (x[k] - mu[c0 + k]) : x[k] - mu[c0 + k];
                if (single) bf[k] = (float)z; else b[k] = z;
            }
        }
        if (single)
            cblas_ssyrk(CblasRowMajor, CblasUpper, CblasNoTrans, N, cb, 1.0f, Bf, cb, c0 ? 1.0f : 0.0f, Kf, N);
        else
            cblas_dsyrk(CblasRowMajor, CblasUpper, CblasNoTrans, N, cb, 1.0, B, cb, c0 ? 1.0 : 0.0, D->K, N);
    }
    if (single)
        for (size_t k = 0; k < (size_t)N * N; k++) D->K[k] = Kf[k];
    free(B); free(Bf); free(Kf);
    return 0;
}

/* The low-rank test streams Z by blocks of rows (never the whole N x 3#V). */
double replib_input_step(const double *X, size_t count)
{
    size_t stride = count / 65536 + 1;
    for (int k = 0; k <= 9; k++) {
        double p = pow(10.0, k);
        int okk = 1;
        for (size_t t = 0; t < count && okk; t += stride) {
            double v = X[t] * p;
            if (fabs(v) > 1e12 || fabs(v - nearbyint(v)) > 1e-3) okk = 0;
        }
        if (okk) return 1 / p;
    }
    return 0;
}

static int gram_lowrank(struct replib_data *D, const double *sw, double **Zr_out)
{
    int N = D->N, m3 = D->m3, blk = 256;
    double *Zb = malloc(sizeof(double) * (size_t)blk * m3);
    if (!Zb) return cm_seterr("replib: out of memory in the low-rank Gram matrix");
    double zn = 0;      /* |Z|_F^2, summed during the first pass */
    int rc = 0;
    /* the tolerance: what the input can represent.  Coordinates printed
     * with step q are known to +-q/2, so a residual of RMS q/2 per
     * (weighted) coordinate is below the input's precision; without a
     * decimal step (binary input), 1e-12 relative as before. */
    double q = replib_input_step(D->X, (size_t)D->n * m3), wsum = 0;
    for (int i = 0; i < D->nv; i++) wsum += D->w ? D->w[i] : 1;
    double tolq = (double)N * 3 * wsum * (q / 2) * (q / 2), eprev = INFINITY;
    D->step = q;
    for (int r = 64; r <= N / 24 && r < m3; r *= 2) {
        double *Om = malloc(sizeof(double) * (size_t)m3 * r), *Y = malloc(sizeof(double) * (size_t)N * r);
        double *Yc = malloc(sizeof(double) * (size_t)N * r), *tau = malloc(sizeof(double) * r);
        double *B = malloc(sizeof(double) * (size_t)r * m3);
        double *T = Zb;
        double *work = NULL;
        if (!Om || !Y || !Yc || !tau || !B) {
            free(Om); free(Y); free(Yc); free(tau); free(B); free(Zb);
            return cm_seterr("replib: out of memory in the low-rank Gram matrix");
        }
        struct rng g;
        rng_seed(&g, 0x5eed0000u + (uint64_t)r);
        for (size_t k = 0; k < (size_t)m3 * r; k++) Om[k] = rng_normal(&g);
        for (int i0 = 0; i0 < N; i0 += blk) {
            int nb = N - i0 < blk ? N - i0 : blk;
            z_rows(D, sw, i0, nb, Zb);
            if (r == 64) zn += cblas_ddot(nb * m3, Zb, 1, Zb, 1);
            cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasNoTrans, nb, r, m3, 1.0, Zb, m3, Om, r, 0.0,
                        Y + (size_t)i0 * r, r);
        }
        free(Om);
        if (!(zn > 0)) { free(Y); free(Yc); free(tau); free(B); break; }
        /* Q = orth(Y): LAPACK QR in column-major storage */
        for (int i = 0; i < N; i++)
            for (int j = 0; j < r; j++) Yc[(size_t)j * N + i] = Y[(size_t)i * r + j];
        int info = 0, lwork = -1;
        double q;
        dgeqrf_(&N, &r, Yc, &N, tau, &q, &lwork, &info);
        lwork = (int)q > r ? (int)q : r;
        work = malloc(sizeof(double) * lwork);
        if (!work) { free(Y); free(Yc); free(tau); free(B); free(Zb); return cm_seterr("replib: out of memory"); }
        dgeqrf_(&N, &r, Yc, &N, tau, work, &lwork, &info);
        if (info == 0) dorgqr_(&N, &r, &r, Yc, &N, tau, work, &lwork, &info);
        free(work); free(tau);
        if (info != 0) { free(Y); free(Yc); free(B); break; }
        double *Q = Y;   /* N by r row-major */
        for (int i = 0; i < N; i++)
            for (int j = 0; j < r; j++) Q[(size_t)i * r + j] = Yc[(size_t)j * N + i];
        free(Yc);
        for (int i0 = 0; i0 < N; i0 += blk) {
            int nb = N - i0 < blk ? N - i0 : blk;
            z_rows(D, sw, i0, nb, Zb);
            cblas_dgemm(CblasRowMajor, CblasTrans, CblasNoTrans, r, m3, nb, 1.0, Q + (size_t)i0 * r, r, Zb, m3,
                        i0 ? 1.0 : 0.0, B, m3);
        }
        /* |Z - Q B|_F^2 by blocks of rows */
        double en = 0;
        for (int i0 = 0; i0 < N; i0 += blk) {
            int nb = N - i0 < blk ? N - i0 : blk;
            z_rows(D, sw, i0, nb, T);
            cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasNoTrans, nb, m3, r, -1.0, Q + (size_t)i0 * r, r,
                        B, m3, 1.0, T, m3);
            for (size_t k = 0; k < (size_t)nb * m3; k++) en += T[k] * T[k];
        }
        D->lowrank_resid = sqrt(en / ((double)N * m3));
        if (en <= 1e-24 * zn || en <= tolq) {
            free(Zb);
            /* B^T = U R (QR of the 3#V x r matrix B^T, which is B in
             * column-major storage): B B^T = R^T R, so Zr = Q R^T has
             * Zr Zr^T = Q B B^T Q^T = K */
            double *tb = malloc(sizeof(double) * r), *Zr = malloc(sizeof(double) * (size_t)N * r);
            double *Rt = calloc((size_t)r * r, sizeof(double));
            int lw = -1, inf = 0;
            double qq;
            if (!tb || !Zr || !Rt) { free(tb); free(Zr); free(Rt); free(Q); free(B); return cm_seterr("replib: out of memory"); }
            dgeqrf_(&m3, &r, B, &m3, tb, &qq, &lw, &inf);
            lw = (int)qq > r ? (int)qq : r;
            double *wk = malloc(sizeof(double) * lw);
            if (!wk) { free(tb); free(Zr); free(Rt); free(Q); free(B); return cm_seterr("replib: out of memory"); }
            dgeqrf_(&m3, &r, B, &m3, tb, wk, &lw, &inf);
            free(wk); free(tb);
            if (inf != 0) { free(Zr); free(Rt); free(Q); free(B); return 0; }
            for (int i = 0; i < r; i++)          /* Rt[k][j] = R[j][k] = B[j + k m3] for j <= k */
                for (int j = 0; j <= i; j++) Rt[(size_t)i * r + j] = B[(size_t)j + (size_t)i * m3];
            cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasNoTrans, N, r, r, 1.0, Q, r, Rt, r, 0.0, Zr, r);
            free(Rt); free(Q); free(B);
            *Zr_out = Zr;
            return r;
        }
        free(Q); free(B);
        /* stop when doubling the rank did not cut the residual 4-fold: the
         * spectrum is flat there (noise), the next try would fail too */
        if (en > 0.25 * eprev || en > 1e-4 * zn) break;
        eprev = en;
    }
    free(Zb);
    return rc;
}

int replib_prepare(struct replib_data *D)
{
    int n = D->n, nv = D->nv;
    D->link = NULL; D->mean = D->Z = D->K = D->zz = D->dd = NULL;
    double t0 = wall();
    if (n < 1 || nv < 1) return cm_seterr("replib: empty animation (%d frames, %d vertices)", n, nv);
    if (D->nfix < 0 || (D->nfix > 0 && !D->Rfix)) return cm_seterr("replib: bad fixed pieces");
    if (!(D->swap_cost >= 0) || !isfinite(D->swap_cost))
        return cm_seterr("replib: swap cost %g is not a finite number >= 0", D->swap_cost);
    int m3 = D->m3 = 3 * nv, N = D->N = n + D->nfix;
    for (size_t k = 0; k < (size_t)D->nfix * m3; k++)
        if (!isfinite(D->Rfix[k]))
            return cm_seterr("fixed piece %zu: vertex %zu: coordinate is not finite", k / m3, (k % m3) / 3);
    if (D->w) {
        double s = 0;
        for (int i = 0; i < nv; i++) {
            if (!isfinite(D->w[i]) || D->w[i] < 0)
                return cm_seterr("weight of vertex %d is %g: weights must be finite and >= 0", i, D->w[i]);
            s += D->w[i];
        }
        if (!(s > 0)) return cm_seterr("all weights are zero");
    }
    D->link = calloc(n, 1);
    D->mean = calloc(m3, sizeof(double));
    D->zz = calloc(N, sizeof(double));
    D->dd = calloc(n, sizeof(double));
    if (!D->link || !D->mean || !D->zz || !D->dd) {
        replib_data_free(D);
        return cm_seterr("replib: out of memory (%d frames x %d vertices)", n, nv);
    }
    for (int f = 0; f + 1 < n; f++) D->link[f] = !(D->cut && D->cut[f + 1]);
    /* the mean frame and the finiteness check in one pass over X: a sum of
     * finite values is finite (coordinates are far below 1e308 / n) */
    for (int f = 0; f < n; f++)
        for (int k = 0; k < m3; k++) D->mean[k] += D->X[(size_t)f * m3 + k];
    for (int k = 0; k < m3; k++) {
        if (!isfinite(D->mean[k]))
            for (int f = 0; f < n; f++)
                if (!isfinite(D->X[(size_t)f * m3 + k])) {
                    replib_data_free(D);
                    return cm_seterr("frame %d: vertex %d: coordinate is not finite", f, k / 3);
                }
        if (!isfinite(D->mean[k])) {
            replib_data_free(D);
            return cm_seterr("vertex %d: coordinates too large (their sum over the frames overflows)", k / 3);
        }
        D->mean[k] /= n;
    }
    double *sw = NULL;
    if (D->w) {
        if (!(sw = malloc(sizeof(double) * m3))) { replib_data_free(D); return cm_seterr("replib: out of memory"); }
        for (int i = 0; i < nv; i++) sw[3 * i] = sw[3 * i + 1] = sw[3 * i + 2] = sqrt(D->w[i]);
    }
    int gram = D->gram;
    if (gram < 0) gram = N <= GRAM_AUTO_MAX;
    D->zdim = m3;
    if (!D->no_lowrank && N >= 24 * 64) {
        double *Zr = NULL;
        int lr = gram_lowrank(D, sw, &Zr);
        if (lr < 0) { free(sw); replib_data_free(D); return -1; }
        if (lr > 0) {
            /* exact reduced coordinates: the direct back end on r columns */
            D->Z = Zr;
            D->zdim = lr;
            D->lowrank = lr;
            gram = 0;
        }
    }
    if (gram) {
        /* lowrank has set gram = 0: the Gram back end holds K alone, never Z */
        D->K = big_alloc(sizeof(double) * (size_t)N * N);
        if (!D->K || gram_by_columns(D, sw, gram == 2) < 0) {
            free(sw); replib_data_free(D);
            return cm_seterr("replib: out of memory for the %d x %d Gram matrix", N, N);
        }
    } else if (!D->lowrank) {
        D->Z = big_alloc(sizeof(double) * (size_t)N * m3);
        if (!D->Z) {
            free(sw); replib_data_free(D);
            return cm_seterr("replib: out of memory (%d frames x %d vertices)", n, nv);
        }
        z_rows(D, sw, 0, N, D->Z);
    }
    free(sw);
    D->gram = gram;
    int zd = D->zdim;
    if (gram) {
        for (int i = 0; i < N; i++)
            for (int j = 0; j < i; j++) D->K[(size_t)i * N + j] = D->K[(size_t)j * N + i];
        for (int g = 0; g < N; g++) D->zz[g] = D->K[(size_t)g * N + g];
        for (int f = 0; f + 1 < n; f++)
            if (D->link[f])
                D->dd[f] = D->K[(size_t)f * N + f] + D->K[(size_t)(f + 1) * N + f + 1] -
                           2 * D->K[(size_t)f * N + f + 1];
    } else {
        for (int g = 0; g < N; g++) {
            const double *z = D->Z + (size_t)g * zd;
            D->zz[g] = cblas_ddot(zd, z, 1, z, 1);
        }
        for (int f = 0; f + 1 < n; f++) {
            if (!D->link[f]) continue;
            const double *a = D->Z + (size_t)f * zd, *b = a + zd;
            double s = 0;
            for (int k = 0; k < zd; k++) s += (b[k] - a[k]) * (b[k] - a[k]);
            D->dd[f] = s;
        }
    }
    D->prep_seconds = wall() - t0;
    return 0;
}

void replib_data_free(struct replib_data *D)
{
    free(D->link); free(D->mean); free(D->Z); free(D->K); free(D->zz); free(D->dd);
    D->link = NULL; D->mean = D->Z = D->K = D->zz = D->dd = NULL;
}

/* ---- the library: every piece is a row copy (src >= 0) or solved ---- */

struct lstate {
    int d, nfree;
    int *src;       /* d: source row in [0, N) or -1 when solved */
    int *fidx;      /* nfree solved pieces */
    double *Uf;     /* nfree by nfree: A_FF = Uf^T Uf (upper, row-major); if diag: A_FF itself */
    int diag;       /* A_FF is diagonal (lambda = 0 or no transitions): solves are scalings */
    int nnz, cap;   /* right-hand side triplets: row = position in fidx */
    int *ri, *ci;
    double *v;
    double *A;      /* d by d: the system A of the last library step (not copied by lstate_copy) */
};

static void lstate_free(struct lstate *s)
{
    free(s->src); free(s->fidx); free(s->Uf); free(s->ri); free(s->ci); free(s->v); free(s->A);
    memset(s, 0, sizeof *s);
}

static int lstate_init(struct lstate *s, int d)
{
    memset(s, 0, sizeof *s);
    s->d = d;
    s->src = malloc(sizeof(int) * d);
    s->fidx = malloc(sizeof(int) * d);
    if (!s->src || !s->fidx) { lstate_free(s); return cm_seterr("replib: out of memory"); }
    return 0;
}

static int push(struct lstate *s, int r, int c, double v)
{
    if (s->nnz == s->cap) {
        int nc = s->cap ? 2 * s->cap : 1024;
        int *ri = realloc(s->ri, sizeof(int) * nc), *ci;
        if (!ri) return -1;
        s->ri = ri;
        if (!(ci = realloc(s->ci, sizeof(int) * nc))) return -1;
        s->ci = ci;
        double *vv = realloc(s->v, sizeof(double) * nc);
        if (!vv) return -1;
        s->v = vv;
        s->cap = nc;
    }
    s->ri[s->nnz] = r; s->ci[s->nnz] = c; s->v[s->nnz] = v;
    s->nnz++;
    return 0;
}

/* Library step: build A and the sparse B for labels l.  cost (n) ranks
 * frames for re-seeding unused pieces (worst first).  *reseeded gets the
 * count. */
static int library_step(const struct replib_data *D, int d, double mu, const int *l,
                        const double *cost, struct lstate *s, int *reseeded)
{
    int n = D->n, nfix = D->nfix;
    s->nfree = 0; s->nnz = 0;
    free(s->Uf); s->Uf = NULL;
    int *count = calloc(d, sizeof(int)), *fpos = malloc(sizeof(int) * d);
    double *A = calloc((size_t)d * d, sizeof(double));
    int *order = NULL;
    if (!count || !fpos || !A) goto oom;
    for (int f = 0; f < n; f++) { count[l[f]]++; A[(size_t)l[f] * d + l[f]] += 1; }
    for (int f = 0; f + 1 < n; f++) {
        if (!D->link[f] || mu == 0) continue;
        int a = l[f], b = l[f + 1];
        if (a == b) continue;
        A[(size_t)a * d + a] += mu; A[(size_t)b * d + b] += mu;
        A[(size_t)a * d + b] -= mu; A[(size_t)b * d + a] -= mu;
    }
    int nres = 0;
    for (int a = 0; a < d; a++) {
        fpos[a] = -1;
        if (a < nfix) s->src[a] = n + a;
        else if (count[a] == 0) { s->src[a] = -2; nres++; }
        else { s->src[a] = -1; fpos[a] = s->nfree; s->fidx[s->nfree++] = a; }
    }
    if (nres) {
        /* re-seed unused pieces with the worst-fit frames (distinct) */
        order = malloc(sizeof(int) * n);
        if (!order) goto oom;
        for (int f = 0; f < n; f++) order[f] = f;
        for (int k = 0, a = 0; k < nres; k++) {
            /* partial selection sort: k-th worst */
            int best = k;
            for (int j = k + 1; j < n; j++)
                if (cost[order[j]] > cost[order[best]]) best = j;
            int t = order[k]; order[k] = order[best]; order[best] = t;
            while (s->src[a] != -2) a++;
            s->src[a] = order[k];
        }
    }
    *reseeded = nres;
    int nf = s->nfree;
    if (nf > 0) {
        s->Uf = malloc(sizeof(double) * (size_t)nf * nf);
        if (!s->Uf) goto oom;
        for (int p = 0; p < nf; p++)
            for (int q = 0; q < nf; q++)
                s->Uf[(size_t)p * nf + q] = A[(size_t)s->fidx[p] * d + s->fidx[q]];
        int info = 0;
        s->diag = 1;
        for (int p = 0; p < nf && s->diag; p++)
            for (int q = 0; q < nf; q++)
                if (p != q && s->Uf[(size_t)p * nf + q] != 0) { s->diag = 0; break; }
        if (!s->diag)
            dpotrf_("L", &nf, s->Uf, &nf, &info);   /* column-major lower = row-major upper */
        if (info != 0) {
            free(count); free(fpos); free(A); free(order);
            return cm_seterr("replib: library system not positive definite (info %d)", info);
        }
        /* B = S + mu S G G^T (free rows), minus A_{F,copies} for row copies */
        for (int f = 0; f < n; f++)
            if (fpos[l[f]] >= 0 && push(s, fpos[l[f]], f, 1) < 0) goto oom;
        if (mu != 0)
            for (int f = 0; f + 1 < n; f++) {
                if (!D->link[f]) continue;
                int a = l[f], b = l[f + 1];
                if (a == b) continue;
                if (fpos[b] >= 0 && (push(s, fpos[b], f + 1, mu) < 0 || push(s, fpos[b], f, -mu) < 0)) goto oom;
                if (fpos[a] >= 0 && (push(s, fpos[a], f + 1, -mu) < 0 || push(s, fpos[a], f, mu) < 0)) goto oom;
            }
        for (int p = 0; p < nf; p++)
            for (int j = 0; j < d; j++) {
                double v = A[(size_t)s->fidx[p] * d + j];
                if (s->src[j] >= 0 && v != 0 && push(s, p, s->src[j], -v) < 0) goto oom;
            }
    }
    free(count); free(fpos); free(order);
    free(s->A);
    s->A = A;
    return 0;
oom:
    free(count); free(fpos); free(A); free(order);
    return cm_seterr("replib: out of memory in the library step");
}

/* B (nfree by cols, row-major) = A_FF^-1 B */
static void lsolve(const struct lstate *s, int cols, double *B)
{
    int nf = s->nfree;
    if (s->diag) {
        for (int p = 0; p < nf; p++) cblas_dscal(cols, 1.0 / s->Uf[(size_t)p * nf + p], B + (size_t)p * cols, 1);
        return;
    }
    cblas_dtrsm(CblasRowMajor, CblasLeft, CblasUpper, CblasTrans, CblasNonUnit, nf, cols, 1.0, s->Uf, nf, B, cols);
    cblas_dtrsm(CblasRowMajor, CblasLeft, CblasUpper, CblasNoTrans, CblasNonUnit, nf, cols, 1.0, s->Uf, nf, B, cols);
}

/* out (d by cols) = library applied to rows: row g < n1 is Y1[g], else
 * Y2[g - n1] (both with row length cols). */
static int lstate_apply(const struct lstate *s, const double *Y1, int n1, const double *Y2,
                        int cols, double *out)
{
    int nf = s->nfree;
#define ROW(g) ((g) < n1 ? Y1 + (size_t)(g) * cols : Y2 + (size_t)((g) - n1) * cols)
    for (int a = 0; a < s->d; a++)
        if (s->src[a] >= 0) memcpy(out + (size_t)a * cols, ROW(s->src[a]), sizeof(double) * cols);
    if (nf == 0) return 0;
    double *tmp = calloc((size_t)nf * cols, sizeof(double));
    if (!tmp) return cm_seterr("replib: out of memory");
    for (int k = 0; k < s->nnz; k++)
        cblas_daxpy(cols, s->v[k], ROW(s->ci[k]), 1, tmp + (size_t)s->ri[k] * cols, 1);
#undef ROW
    lsolve(s, cols, tmp);
    for (int p = 0; p < nf; p++)
        memcpy(out + (size_t)s->fidx[p] * cols, tmp + (size_t)p * cols, sizeof(double) * cols);
    free(tmp);
    return 0;
}

/* library_out from the kept 32-bit frames, one block of columns per job:
 * every value is computed with the same operations in the same order as
 * frame by frame (x_g - ref = (b - ref) + kept q, then the right-hand
 * side entries in order), so the
 * bytes do not depend on the blocking or the threads; a block of the nf
 * solved rows stays in cache while the entries stream through it. */
#define KEPT_COLS 2048
struct kept_job {
    const struct replib_data *D;
    const struct lstate *s;
    double *R, *tmp;
};

/* o[t] (+)= v ((b[t] - ref[t]) + x[t] q) for t in [0, len), x int32
 * (xi), the same integer read from the frame where it lies (xm:
 * replib_kept_int of it, iq = 1 / q), or float (xf; then without q); add
 * = 0: o = ref + (...) instead (a row copy) */
__attribute__((optimize("O3"), target_clones("avx512f", "avx2", "default")))
static void kept_axpy(double *restrict o, double v, const double *restrict b, const double *restrict ref,
                      const int32_t *restrict xi, const mapped_double *restrict xm, const float *restrict xf,
                      double q, double iq, size_t len, int add)
{
    if (!add && xi) for (size_t t = 0; t < len; t++) o[t] = ref[t] + ((b[t] - ref[t]) + xi[t] * q);
    else if (!add && xm) for (size_t t = 0; t < len; t++) o[t] = ref[t] + ((b[t] - ref[t]) + replib_kept_int(xm[t], b[t], iq) * q);
    else if (!add) for (size_t t = 0; t < len; t++) o[t] = ref[t] + ((b[t] - ref[t]) + xf[t]);
    else if (xi) for (size_t t = 0; t < len; t++) o[t] += v * ((b[t] - ref[t]) + xi[t] * q);
    else if (xm) for (size_t t = 0; t < len; t++) o[t] += v * ((b[t] - ref[t]) + replib_kept_int(xm[t], b[t], iq) * q);
    else for (size_t t = 0; t < len; t++) o[t] += v * ((b[t] - ref[t]) + xf[t]);
}

static void kept_block(void *ctx, int i)
{
    const struct kept_job *j = ctx;
    const struct replib_data *D = j->D;
    const struct lstate *s = j->s;
    size_t m3 = D->m3, t0 = (size_t)i * KEPT_COLS, len = t0 + KEPT_COLS < m3 ? KEPT_COLS : m3 - t0;
    const double *ref = D->ref + t0;
    double q = D->xstep, iq = q > 0 ? 1 / q : 0;
#define BASE(g) ((D->xbase ? D->xbase + (size_t)((g) / REPLIB_KEEP_CHUNK) * m3 : D->ref) + t0)
#define XI(g) (D->Xi ? D->Xi + (size_t)(g) * m3 + t0 : NULL)
#define XM(g) (!D->Xi && D->Xm ? D->Xm[g] + t0 : NULL)
#define XF(g) (D->Xi || D->Xm ? NULL : D->Xf + (size_t)(g) * m3 + t0)
    for (int a = 0; a < s->d; a++) {
        int g = s->src[a];
        if (g >= 0) kept_axpy(j->R + (size_t)a * m3 + t0, 0, BASE(g), ref, XI(g), XM(g), XF(g), q, iq, len, 0);
    }
    for (int k = 0; k < s->nnz; k++) {
        int g = s->ci[k];
        kept_axpy(j->tmp + (size_t)s->ri[k] * m3 + t0, s->v[k], BASE(g), ref, XI(g), XM(g), XF(g), q, iq, len, 1);
    }
#undef BASE
#undef XI
#undef XM
#undef XF
}

/* The library from frames read where they lie (D->Xm), one piece per job:
 * a copied frame, or a free row's nonzeros in k order, so every value is
 * the sum kept_block forms, term by term in the same order (the same
 * bytes).  Each frame is read whole, and its pages are released after the
 * job that reads it last (jobs start in piece order), so the resident set
 * stays a window of the file instead of all of it. */
struct kept_rows {
    const struct replib_data *D;
    const struct lstate *s;
    double *R, *tmp;
    const int *row, *start, *ent, *last;    /* row[a]: free row of piece a or -1; CSR of the nonzeros by row
                                               (k order); last[g]: the last piece that reads frame g */
};

static int int_cmp(const void *a, const void *b)
{
    int x = *(const int *)a, y = *(const int *)b;
    return (x > y) - (x < y);
}

static void kept_row(void *ctx, int a)
{
    const struct kept_rows *j = ctx;
    const struct replib_data *D = j->D;
    const struct lstate *s = j->s;
    size_t m3 = D->m3;
    double q = D->xstep, iq = q > 0 ? 1 / q : 0;
#define BASE(g) (D->xbase ? D->xbase + (size_t)((g) / REPLIB_KEEP_CHUNK) * m3 : D->ref)
    int g = s->src[a], p = j->row[a];
    if (g >= 0) kept_axpy(j->R + (size_t)a * m3, 0, BASE(g), D->ref, NULL, D->Xm[g], NULL, q, iq, m3, 0);
    if (p >= 0)
        for (int e = j->start[p]; e < j->start[p + 1]; e++) {
            int k = j->ent[e];
            g = s->ci[k];
            kept_axpy(j->tmp + (size_t)p * m3, s->v[k], BASE(g), D->ref, NULL, D->Xm[g], NULL, q, iq, m3, 1);
        }
#undef BASE
    if (D->Xm_keep) return;
    /* the frames this piece reads last: their pages go, each run of
     * consecutive frames in one call (one TLB flush, not one per frame) */
    int nr = p >= 0 ? j->start[p + 1] - j->start[p] : 0, nd = 0;
    int *done = malloc(sizeof(int) * (size_t)(nr + 1));
    if (!done) return;              /* the pages stay: only the resident set is larger */
    if (s->src[a] >= 0 && j->last[s->src[a]] == a) done[nd++] = s->src[a];
    for (int e = 0; e < nr; e++) {
        g = s->ci[j->ent[j->start[p] + e]];
        if (j->last[g] == a) done[nd++] = g;
    }
    qsort(done, nd, sizeof(int), int_cmp);
    for (int i = 0; i < nd;) {
        int e = i;
        while (e + 1 < nd && done[e + 1] <= done[e] + 1) e++;
        mapped_release((const void *)D->Xm[done[i]], (const void *)(D->Xm[done[e]] + m3));
        i = e + 1;
    }
    free(done);
}

/* kept_row's jobs over every piece; tmp: nf by 3#V zeros.  Returns 0 or -1
 * (allocation). */
static int library_rows(const struct replib_data *D, const struct lstate *s, double *R, double *tmp, int threads)
{
    int d = s->d, nf = s->nfree, n = D->n;
    int *row = malloc(sizeof(int) * d), *start = calloc(nf + 2, sizeof(int));
    int *ent = malloc(sizeof(int) * (s->nnz + 1)), *last = malloc(sizeof(int) * n);
    if (!row || !start || !ent || !last) { free(row); free(start); free(ent); free(last); return cm_seterr("replib: out of memory"); }
    for (int a = 0; a < d; a++) row[a] = -1;
    for (int p = 0; p < nf; p++) row[s->fidx[p]] = p;
    for (int k = 0; k < s->nnz; k++) start[s->ri[k] + 2]++;
    for (int p = 0; p < nf; p++) start[p + 2] += start[p + 1];
    for (int k = 0; k < s->nnz; k++) ent[start[s->ri[k] + 1]++] = k;     /* start[p + 1] ends row p */
    for (int f = 0; f < n; f++) last[f] = -1;
    for (int a = 0; a < d; a++) if (s->src[a] >= 0 && s->src[a] < n && a > last[s->src[a]]) last[s->src[a]] = a;
    for (int k = 0; k < s->nnz; k++) {
        int a = s->fidx[s->ri[k]], g = s->ci[k];
        if (a > last[g]) last[g] = a;
    }
    struct kept_rows job = {D, s, R, tmp, row, start, ent, last};
    parallel_run(d, threads, kept_row, &job);
    free(row); free(start); free(ent); free(last);
    return 0;
}

/* The library in model coordinates (d by 3#V): from the frames (double or
 * single precision), or from the reduced coordinates and their basis. */
static int library_out(const struct replib_data *D, const struct lstate *s, double *R, int threads)
{
    int n = D->n, m3 = D->m3, d = s->d;
    if (D->X) return lstate_apply(s, D->X, n, D->Rfix, m3, R);
    if (D->Xf || D->Xi || D->Xm) {
        /* rows are frames only (no fixed pieces with the sketch) */
        int nf = s->nfree;
        double *tmp = nf ? big_calloc(sizeof(double) * (size_t)nf * m3) : NULL;
        if (nf && !tmp) return cm_seterr("replib: out of memory");
        if (D->Xm && !D->Xi) {
            if (library_rows(D, s, R, tmp, threads) < 0) { free(tmp); return -1; }
        } else {
            struct kept_job job = {D, s, R, tmp};
            parallel_run((m3 + KEPT_COLS - 1) / KEPT_COLS, threads, kept_block, &job);
        }
        if (nf) lsolve(s, m3, tmp);
        for (int p = 0; p < nf; p++) {
            double *o = R + (size_t)s->fidx[p] * m3;
            for (int t = 0; t < m3; t++) o[t] = D->ref[t] + tmp[(size_t)p * m3 + t];
        }
        free(tmp);
        return 0;
    }
    /* sketch only: r_a = ref + (C Zr)_a V^T / sqrt(w) */
    int r = D->zdim;
    double *Cr = malloc(sizeof(double) * (size_t)d * r);
    if (!Cr) return cm_seterr("replib: out of memory");
    if (lstate_apply(s, D->Z, n, NULL, r, Cr) < 0) { free(Cr); return -1; }
    cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasTrans, d, m3, r, 1.0, Cr, r, D->V, r, 0.0, R, m3);
    free(Cr);
    for (int a = 0; a < d; a++)
        for (int t = 0; t < m3; t++) {
            double *o = R + (size_t)a * m3 + t;
            *o = D->ref[t] + (D->sw ? *o / D->sw[t] : *o);
        }
    return 0;
}

/* ---- idle workers help the restarts still running ---- */

/* Restarts run one per worker thread; once no restart is left to start, a
 * worker that finished parks here and takes chunks of the row-wise products
 * of the restarts still running (the last restart would otherwise have the
 * machine to itself on one core).  A chunk is a block of rows (frames): its
 * numbers are computed by the same calls on the same rows wherever it runs
 * (BLAS never splits the inner dimension, zdim <= REPLIB_TEAM_MAXK), so the
 * result does not depend on who helps or on the thread count.  The caller
 * takes chunks too and never waits for a helper that has not started one
 * (a descheduled helper on a loaded machine costs nothing). */
#define REPLIB_TEAM_CHUNKS 8
#define REPLIB_TEAM_MINROWS 512   /* fewer frames: no help asked */
#define REPLIB_TEAM_MAXK 256      /* OpenBLAS's DGEMM does not split K up to this (checked bitwise) */
struct team {
    pthread_mutex_t mu;
    pthread_cond_t wake, done;
    int parked;                 /* workers waiting for chunks */
    int helped;                 /* chunks run by parked workers */
    int running;                /* workers still running restarts */
    int active, njobs, next, ndone;
    void (*fn)(void *ctx, int i);
    void *ctx;
};

/* fn(ctx, i) for i = 0..njobs-1, with the parked workers' help if any */
static void team_run(struct team *t, int njobs, void (*fn)(void *ctx, int i), void *ctx)
{
    if (t) {
        pthread_mutex_lock(&t->mu);
        if (t->parked > 0 && !t->active) {
            t->active = 1; t->fn = fn; t->ctx = ctx; t->njobs = njobs; t->next = 0; t->ndone = 0;
            pthread_cond_broadcast(&t->wake);
            while (t->next < njobs) {
                int i = t->next++;
                pthread_mutex_unlock(&t->mu);
                fn(ctx, i);
                pthread_mutex_lock(&t->mu);
                t->ndone++;
            }
            while (t->ndone < njobs) pthread_cond_wait(&t->done, &t->mu);
            t->active = 0;
            pthread_mutex_unlock(&t->mu);
            return;
        }
        pthread_mutex_unlock(&t->mu);
    }
    for (int i = 0; i < njobs; i++) fn(ctx, i);
}

/* A worker that will not help: no longer counted as running. */
static void team_leave(struct team *t)
{
    pthread_mutex_lock(&t->mu);
    if (--t->running == 0) pthread_cond_broadcast(&t->wake);
    pthread_mutex_unlock(&t->mu);
}

/* A worker with no restart left: help until every worker is done. */
static void team_help(struct team *t)
{
    pthread_mutex_lock(&t->mu);
    if (--t->running == 0) pthread_cond_broadcast(&t->wake);
    t->parked++;
    while (t->running > 0) {
        if (t->active && t->next < t->njobs) {
            int i = t->next++;
            void (*fn)(void *, int) = t->fn;
            void *ctx = t->ctx;
            pthread_mutex_unlock(&t->mu);
            fn(ctx, i);
            pthread_mutex_lock(&t->mu);
            t->helped++;
            if (++t->ndone == t->njobs) pthread_cond_signal(&t->done);
            continue;
        }
        pthread_cond_wait(&t->wake, &t->mu);
    }
    t->parked--;
    pthread_mutex_unlock(&t->mu);
}

/* rows [f0, f1) of chunk i of n rows */
static void chunk_rows(int n, int i, int *f0, int *f1)
{
    *f0 = (int)((long long)n * i / REPLIB_TEAM_CHUNKS);
    *f1 = (int)((long long)n * (i + 1) / REPLIB_TEAM_CHUNKS);
}

/* C (rows [f0, f1) of an m by L product, row stride ldc) = A B^T + beta C
 * by row blocks: A m by k (lda), B L by k (ldb) */
struct gemm_rows {
    int m, L, k, lda, ldb, ldc;
    const double *A, *B;
    double beta, *C;
};

static void gemm_rows_job(void *ctx, int i)
{
    const struct gemm_rows *g = ctx;
    int f0, f1;
    chunk_rows(g->m, i, &f0, &f1);
    if (f1 > f0)
        cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasTrans, f1 - f0, g->L, g->k, 1.0, g->A + (size_t)f0 * g->lda,
                    g->lda, g->B, g->ldb, g->beta, g->C + (size_t)f0 * g->ldc, g->ldc);
}

/* C = A B^T + beta C (m by L, row-major), split over rows when helped */
static void gemm_abt(struct team *t, int m, int L, int k, const double *A, int lda, const double *B, int ldb,
                     double beta, double *C, int ldc)
{
    if (t && m >= REPLIB_TEAM_MINROWS && k <= REPLIB_TEAM_MAXK) {
        struct gemm_rows g = {m, L, k, lda, ldb, ldc, A, B, beta, C};
        team_run(t, REPLIB_TEAM_CHUNKS, gemm_rows_job, &g);
    } else {
        cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasTrans, m, L, k, 1.0, A, lda, B, ldb, beta, C, ldc);
    }
}

/* ---- costs: P (N by d, z_g . r_a) and Q (d by d, r_a . r_b) ---- */

struct work {
    int d;
    double *P, *Q, *C, *Rw;     /* P: N by d; C: d by N (Gram); Rw: d by 3#V (direct) */
    double *U, *T, *H, *c;      /* chain terms */
    struct chain ch;
    int ncand;                  /* > 0: label steps restricted to this many candidates per frame (search trials) */
    double *qd;                 /* d: the diagonal of Q */
    double *Pb, *Qb;            /* P and Q of the best library of the search (restored when a trial fails) */
    double *Pspare;             /* a free N by d buffer for P; with pshared = 1, P and Pb are one
                                   buffer (saved or restored without a copy: P gets its own again,
                                   a copy only when it is about to be updated in place) */
    int pshared;
    /* incremental costs (direct back end): P, Q and Rw are those of the
     * library solved for the labels lw when have = 1 */
    int *lw, have, ninc;
    int *lwb, haveb;            /* the same for Pb, Qb, Rwb */
    double *Rwb;
    int *smark;                 /* d: position of a piece in the changed set, or -1 */
    /* U, H and c are derived from P only when needed (uh = 1: current);
     * the candidate label steps read P directly */
    const struct replib_data *D;
    double mu;
    int uh;                     /* bit 1: U current, bit 2: H and c current */
    int *cand, *nc;             /* n by ncand + 1, n: the candidates of the last candidate label step */
    double *hs;                 /* n by ncand + 1: its DP values */
    int cand_reuse;             /* 1: the next candidate label step keeps those candidates */
    struct team *team;          /* idle workers' help (NULL: none) */
    /* Gram back end, simple library system (gram_costs): the sums of K's
     * rows over each piece's frames, kept for pieces whose frames did not
     * change */
    double *ks;                 /* d by N: the sum for piece a (valid where ksf says so) */
    int *ksf;                   /* n: the piece whose sum holds frame f, or -1 */
    int *kmark;                 /* d: 1 = piece a's sum is to be made again */
};

static void work_free(struct work *w)
{
    free(w->P); free(w->Q); free(w->C); free(w->Rw); free(w->U); free(w->T); free(w->H); free(w->c);
    if (!w->pshared) free(w->Pb);
    free(w->Pspare); free(w->Qb); free(w->qd);
    free(w->lw); free(w->lwb); free(w->Rwb); free(w->smark);
    free(w->cand); free(w->nc); free(w->hs);
    free(w->ks); free(w->ksf); free(w->kmark);
    memset(w, 0, sizeof *w);
}

static int work_init(struct work *w, const struct replib_data *D, int d)
{
    memset(w, 0, sizeof *w);
    w->d = d;
    size_t N = D->N, n = D->n;
    /* the n by d arrays on huge pages (big_alloc.h) */
    w->P = big_alloc(sizeof(double) * N * d);
    w->Q = malloc(sizeof(double) * (size_t)d * d);
    w->U = big_alloc(sizeof(double) * n * d);
    w->T = malloc(sizeof(double) * (size_t)d * d);
    w->H = big_calloc(sizeof(double) * n * d);
    w->c = calloc(n, sizeof(double));
    w->qd = malloc(sizeof(double) * d);
    if (D->K) w->C = malloc(sizeof(double) * (size_t)d * N);
    else w->Rw = malloc(sizeof(double) * (size_t)d * D->zdim);
    w->lw = malloc(sizeof(int) * n);
    w->smark = malloc(sizeof(int) * d);
    w->D = D;
    if (!w->lw || !w->smark) { work_free(w); return cm_seterr("replib: out of memory (%d frames, %d pieces)", D->n, d); }
    for (int a = 0; a < d; a++) w->smark[a] = -1;
    if (!w->P || !w->Q || !w->qd || !w->U || !w->T || !w->H || !w->c || !(D->K ? (void *)w->C : (void *)w->Rw)) {
        work_free(w);
        return cm_seterr("replib: out of memory (%d frames, %d pieces)", D->n, d);
    }
    return 0;
}

/* P about to be written: all of it (keep = 0) or updated in place (keep
 * = 1).  While P is the search's saved buffer (pshared), it moves to the
 * spare one first, with a copy of the numbers only if they are kept. */
static double *p_write(struct work *w, int keep)
{
    if (w->pshared) {
        if (keep) memcpy(w->Pspare, w->P, sizeof(double) * (size_t)w->D->N * w->d);
        w->P = w->Pspare;
        w->Pspare = NULL;
        w->pshared = 0;
    }
    return w->P;
}

/* Gram back end: with r_a = sum_g C_ag z_g, P = K C^T and Q = C K C^T.
 * Row copies read K directly; solved pieces need only the sparse B:
 * P_F^T = A_FF^-1 (B K) (nnz N flops + two triangular solves), and
 * Q_F = A_FF^-1 (B P) -- never a dense N x N x d product. */
/* The library system is simple when A_FF is diagonal and its right-hand
 * side is one triplet (p, f, 1) per frame f of a free piece, in frame order
 * (lambda = 0, or no transitions between pieces): then row p before the
 * solve is the sum of K's rows over the frames of piece fidx[p]. */
static int simple_system(const struct lstate *s)
{
    if (!s->diag) return 0;
    for (int k = 0; k < s->nnz; k++)
        if (s->v[k] != 1 || (k > 0 && s->ci[k] <= s->ci[k - 1])) return 0;
    return 1;
}

/* Rows PT[a] = z_g . r_a of the free pieces with a simple system (above).
 * The sum of a piece whose frames are the same as at the last call is kept:
 * it is the same sum of the same rows in the same order, so the same bits
 * as making it again; late in a descent, or after a split/merge trial, most
 * pieces keep their frames.  A piece's sum is made by the same daxpy calls,
 * in the same order, as the general path below.  Returns -1 when out of
 * memory. */
static int gram_rows_kept(const struct replib_data *D, const struct lstate *s, struct work *w, double *PT)
{
    int n = D->n, N = D->N, d = w->d, nf = s->nfree;
    if (!w->ks) {
        w->ks = malloc(sizeof(double) * (size_t)d * N);
        w->ksf = malloc(sizeof(int) * n);
        w->kmark = malloc(sizeof(int) * d);
        if (!w->ks || !w->ksf || !w->kmark) return -1;
        for (int f = 0; f < n; f++) w->ksf[f] = -1;
        for (int a = 0; a < d; a++) w->kmark[a] = 1;     /* no sum made yet */
    }
    /* frames that moved mark their old and new pieces */
    int k = 0;
    for (int f = 0; f < n; f++) {
        int a = -1;
        if (k < s->nnz && s->ci[k] == f) a = s->fidx[s->ri[k++]];
        if (a != w->ksf[f]) {
            if (a >= 0) w->kmark[a] = 1;
            if (w->ksf[f] >= 0) w->kmark[w->ksf[f]] = 1;
            w->ksf[f] = a;
        }
    }
    for (int p = 0; p < nf; p++) {
        int a = s->fidx[p];
        double *row = w->ks + (size_t)a * N;
        if (w->kmark[a]) {
            memset(row, 0, sizeof(double) * N);
            for (int t = 0; t < s->nnz; t++)
                if (s->ri[t] == p) cblas_daxpy(N, s->v[t], D->K + (size_t)s->ci[t] * N, 1, row, 1);
            w->kmark[a] = 0;
        }
        memcpy(PT + (size_t)a * N, row, sizeof(double) * N);
        cblas_dscal(N, 1.0 / s->Uf[(size_t)p * nf + p], PT + (size_t)a * N, 1);   /* as lsolve */
    }
    /* a piece that is not free now has no valid sum */
    for (int a = 0; a < d; a++)
        if (s->src[a] >= 0) w->kmark[a] = 1;
    return 0;
}

/* 1: gram_costs keeps the sums of pieces whose frames did not change; 0
 * (STOPMO_DICT_NO_KEPT_SUMS=1, for tests): every sum is made again.  Asked
 * once, before the workers start (learn_run). */
static int kept_sums(void)
{
    static int kept = -1;
    if (kept < 0) {
        const char *e = getenv("STOPMO_DICT_NO_KEPT_SUMS");
        kept = !(e && *e && strcmp(e, "0"));
    }
    return kept;
}

static int gram_costs(const struct replib_data *D, const struct lstate *s, struct work *w)
{
    int N = D->N, d = w->d, nf = s->nfree;
    const double *K = D->K;
    double *PT = w->C;      /* d by N: PT[a][g] = z_g . r_a */
    for (int a = 0; a < d; a++)
        if (s->src[a] >= 0) memcpy(PT + (size_t)a * N, K + (size_t)s->src[a] * N, sizeof(double) * N);
    double *M = NULL;
    if (nf > 0) {
        M = calloc((size_t)nf * d, sizeof(double));
        if (!M) return cm_seterr("replib: out of memory");
        if (kept_sums() && simple_system(s)) {
            if (gram_rows_kept(D, s, w, PT) < 0) { free(M); return cm_seterr("replib: out of memory"); }
        } else {
            double *tmp = calloc((size_t)nf * N, sizeof(double));
            if (!tmp) { free(M); return cm_seterr("replib: out of memory"); }
            if (w->kmark) for (int a = 0; a < d; a++) w->kmark[a] = 1;
            for (int k = 0; k < s->nnz; k++)
                cblas_daxpy(N, s->v[k], K + (size_t)s->ci[k] * N, 1, tmp + (size_t)s->ri[k] * N, 1);
            lsolve(s, N, tmp);
            for (int p = 0; p < nf; p++)
                memcpy(PT + (size_t)s->fidx[p] * N, tmp + (size_t)p * N, sizeof(double) * N);
            free(tmp);
        }
    }
    p_write(w, 0);
    for (int g = 0; g < N; g++)
        for (int a = 0; a < d; a++) w->P[(size_t)g * d + a] = PT[(size_t)a * N + g];
    /* Q rows: a row copy a reads P at its source; solved rows via B P */
    for (int a = 0; a < d; a++)
        if (s->src[a] >= 0) memcpy(w->Q + (size_t)a * d, w->P + (size_t)s->src[a] * d, sizeof(double) * d);
    if (nf > 0) {
        for (int k = 0; k < s->nnz; k++)
            cblas_daxpy(d, s->v[k], w->P + (size_t)s->ci[k] * d, 1, M + (size_t)s->ri[k] * d, 1);
        lsolve(s, d, M);
        for (int p = 0; p < nf; p++)
            memcpy(w->Q + (size_t)s->fidx[p] * d, M + (size_t)p * d, sizeof(double) * d);
    }
    free(M);
    return 0;
}

/* The unary chain terms U from w->P (and qd), when they are not current
 * (w->uh bit 1): split_merge needs only these. */
__attribute__((optimize("tree-vectorize"), target_clones("avx512f", "avx2", "default")))
static void u_rows(struct work *w, int f0, int f1)
{
    const struct replib_data *D = w->D;
    int d = w->d;
    const double *P = w->P, *qd = w->qd;
    for (int f = f0; f < f1; f++) {
        const double *p = P + (size_t)f * d;
        double *u = w->U + (size_t)f * d, zf = D->zz[f];
        for (int a = 0; a < d; a++) u[a] = zf + qd[a] - 2 * p[a];
    }
}

static void u_job(void *ctx, int i)
{
    struct work *w = ctx;
    int f0, f1;
    chunk_rows(w->D->n, i, &f0, &f1);
    u_rows(w, f0, f1);
}

static void ensure_u(struct work *w)
{
    if (w->uh & 1) return;
    if (w->team && w->D->n >= REPLIB_TEAM_MINROWS) team_run(w->team, REPLIB_TEAM_CHUNKS, u_job, w);
    else u_rows(w, 0, w->D->n);
    w->uh |= 1;
}

/* The unary and linear chain terms U, H, c from w->P (and qd), when they
 * are not current (w->uh bits 1 and 2): every use of w->ch calls this
 * first. */
static void ensure_uh(struct work *w)
{
    if (w->uh == 3) return;
    ensure_u(w);
    const struct replib_data *D = w->D;
    int n = D->n, d = w->d;
    double mu = w->mu;
    const double *P = w->P;
    if (mu > 0)
        for (int f = 0; f + 1 < n; f++) {
            double *h = w->H + (size_t)f * d;
            if (!D->link[f]) { memset(h, 0, sizeof(double) * d); w->c[f] = 0; continue; }
            for (int a = 0; a < d; a++)
                h[a] = -2 * mu * (P[(size_t)(f + 1) * d + a] - P[(size_t)f * d + a]);
            w->c[f] = mu * D->dd[f];
        }
    w->uh = 3;
}

/* The chain terms from w->P and w->Q: qd and T now, U, H and c marked
 * stale (ensure_uh). */
__attribute__((optimize("tree-vectorize"), target_clones("avx512f", "avx2", "default")))
static void derive_costs(const struct replib_data *D, double mu, struct work *w)
{
    int n = D->n, d = w->d;
    const double *Q = w->Q;
    double *qd = w->qd;
    for (int a = 0; a < d; a++) qd[a] = Q[(size_t)a * d + a];
    w->mu = mu;
    w->uh = 0;
    w->ch.n = n; w->ch.d = d; w->ch.U = w->U; w->ch.link = D->link; w->ch.swap = D->swap_cost;
    if (mu > 0) {
        for (int a = 0; a < d; a++) {
            const double *q = Q + (size_t)a * d;
            double *t = w->T + (size_t)a * d, qa = qd[a];
            for (int b = 0; b < d; b++) {
                double v = mu * (qa + qd[b] - 2 * q[b]);
                t[b] = v > 0 ? v : 0;
            }
            t[a] = 0;
        }
        w->ch.T = w->T; w->ch.H = w->H; w->ch.c = w->c;
    } else {
        w->ch.T = NULL; w->ch.H = NULL; w->ch.c = NULL;
    }
}

/* Direct back end: P = Z Rw^T (frames only) and Q = Rw Rw^T from the
 * library w->Rw (d by zdim); Q from DSYRK's upper triangle, mirrored:
 * exactly symmetric. */
static void library_q(const struct replib_data *D, struct work *w)
{
    int d = w->d, m3 = D->zdim;
    cblas_dsyrk(CblasRowMajor, CblasUpper, CblasNoTrans, d, m3, 1.0, w->Rw, m3, 0.0, w->Q, d);
    for (int a = 0; a < d; a++)
        for (int b = 0; b < a; b++) w->Q[(size_t)a * d + b] = w->Q[(size_t)b * d + a];
}

static void direct_products(const struct replib_data *D, struct work *w)
{
    int n = D->n, d = w->d, m3 = D->zdim;
    gemm_abt(w->team, n, d, m3, D->Z, m3, w->Rw, m3, 0.0, p_write(w, 0), d);
    library_q(D, w);
}

static int compute_costs(const struct replib_data *D, const struct lstate *s, double mu, struct work *w)
{
    int N = D->N, d = w->d, m3 = D->zdim;
    w->have = 0;
    if (D->K) {
        if (gram_costs(D, s, w) < 0) return -1;
        /* symmetrize Q (the Gram product is symmetric only up to rounding) */
        for (int a = 0; a < d; a++)
            for (int b = 0; b < a; b++) {
                double v = 0.5 * (w->Q[(size_t)a * d + b] + w->Q[(size_t)b * d + a]);
                w->Q[(size_t)a * d + b] = w->Q[(size_t)b * d + a] = v;
            }
    } else {
        if (lstate_apply(s, D->Z, N, NULL, m3, w->Rw) < 0) return -1;
        direct_products(D, w);
    }
    derive_costs(D, mu, w);
    return 0;
}

/* Keep (save = 1) or restore (save = 0) the costs in w as those of the
 * search's best library: a failed trial goes back to them without
 * recomputing the products (same numbers as recomputing them). */
static int best_costs(const struct replib_data *D, double mu, struct work *w, int save)
{
    size_t np = (size_t)D->N * w->d, nq = (size_t)w->d * w->d, nr = D->K ? 0 : (size_t)w->d * D->zdim;
    if (!w->Qb) {
        w->Pspare = big_alloc(sizeof(double) * np);
        w->Qb = malloc(sizeof(double) * nq);
        w->lwb = malloc(sizeof(int) * D->n);
        w->Rwb = nr ? malloc(sizeof(double) * nr) : NULL;
        if (!w->Pspare || !w->Qb || !w->lwb || (nr && !w->Rwb))
            return cm_seterr("replib: out of memory (%d frames, %d pieces)", D->n, w->d);
    }
    /* P: the buffers change roles, no copy (p_write) */
    if (!w->pshared) {
        if (save) {                 /* the old saved buffer (if any) is the spare */
            double *old = w->Pb;
            w->Pb = w->P;
            if (old) w->Pspare = old;
        } else {
            if (!w->Pb) return cm_seterr("replib: internal: costs restored before any were saved");
            w->Pspare = w->P;
            w->P = w->Pb;
        }
        w->pshared = 1;
    }
    if (save) {
        memcpy(w->Qb, w->Q, sizeof(double) * nq);
        w->haveb = w->have;
        if (w->have) {
            memcpy(w->lwb, w->lw, sizeof(int) * D->n);
            memcpy(w->Rwb, w->Rw, sizeof(double) * nr);
        }
    } else {
        memcpy(w->Q, w->Qb, sizeof(double) * nq);
        w->have = w->haveb;
        w->ninc = 0;
        if (w->have) {
            memcpy(w->lw, w->lwb, sizeof(int) * D->n);
            memcpy(w->Rw, w->Rwb, sizeof(double) * nr);
        }
        derive_costs(D, mu, w);
    }
    return 0;
}

/* Costs of the library step s (just solved for labels l) from those of
 * the labels w->lw (w->have: w->P, w->Q, w->Rw hold them), when only a
 * few pieces' rows of A and B differ: with S those pieces (the old and new
 * labels of every changed frame and of its two neighbours), the old
 * library leaves the residual E = B Z - A Rw nonzero only in rows S, so
 * the new one is Rw + A_FF^-1 [., S] E_S and P changes by
 * (Z E_S^T) (A_FF^-1 [., S])^T: O(n |S| (r + d)) instead of the O(n r d)
 * of P = Z Rw^T (the same numbers up to rounding).  Direct back end only,
 * every non-fixed piece solved (no re-seeded row copies).  Returns 0 when
 * done (w->lw = l), 1 when the full products are needed, -1 on allocation
 * failure. */
static int costs_incremental(const struct replib_data *D, const struct lstate *s, double mu,
                             struct work *w, const int *l)
{
    int n = D->n, d = w->d, r = D->zdim, nfix = D->nfix, nf = s->nfree;
    if (D->K || !w->have || !s->A || nf != d - nfix || w->ninc >= 32) return 1;
    int *mark = w->smark, ns = 0, lim = d;
    int *sl = malloc(sizeof(int) * d);
    if (!sl) return -1;
#define ADD(a) do { int a_ = (a); if (a_ >= nfix && mark[a_] < 0) { mark[a_] = ns; sl[ns++] = a_; } } while (0)
    for (int f = 0; f < n && ns < lim; f++) {
        if (w->lw[f] == l[f]) continue;
        for (int g = f > 0 ? f - 1 : 0; g <= f + 1 && g < n; g++) { ADD(l[g]); ADD(w->lw[g]); }
    }
#undef ADD
    /* incremental only when clearly cheaper than the full product */
    if ((double)ns * (r + nf) * 2 > (double)r * nf) {
        for (int j = 0; j < ns; j++) mark[sl[j]] = -1;
        free(sl);
        return 1;
    }
    if (ns > 0) {
        double *E = calloc((size_t)ns * r, sizeof(double)), *M = calloc((size_t)nf * ns, sizeof(double));
        double *G = malloc(sizeof(double) * (size_t)n * ns);
        if (!E || !M || !G) {
            free(E); free(M); free(G);
            for (int j = 0; j < ns; j++) mark[sl[j]] = -1;
            free(sl);
            return -1;
        }
        const double *Z = D->Z;
        double *Rf = w->Rw + (size_t)nfix * r;
        /* E_S = (B Z)_S - A_{S,F} Rw_F (fidx[p] = nfix + p) */
        for (int k = 0; k < s->nnz; k++) {
            int j = mark[nfix + s->ri[k]];
            if (j >= 0) cblas_daxpy(r, s->v[k], Z + (size_t)s->ci[k] * r, 1, E + (size_t)j * r, 1);
        }
        for (int j = 0; j < ns; j++) {
            cblas_dgemv(CblasRowMajor, CblasTrans, nf, r, -1.0, Rf, r, s->A + (size_t)sl[j] * d + nfix, 1,
                        1.0, E + (size_t)j * r, 1);
            M[(size_t)(sl[j] - nfix) * ns + j] = 1;
        }
        lsolve(s, ns, M);                   /* M = A_FF^-1 [., S] */
        cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasNoTrans, nf, r, ns, 1.0, M, ns, E, r, 1.0, Rf, r);
        gemm_abt(w->team, n, ns, r, Z, r, E, r, 0.0, G, ns);
        gemm_abt(w->team, n, nf, ns, G, ns, M, ns, 1.0, p_write(w, 1) + nfix, d);
        library_q(D, w);
        free(E); free(M); free(G);
        w->ninc++;
    }
    for (int j = 0; j < ns; j++) mark[sl[j]] = -1;
    free(sl);
    memcpy(w->lw, l, sizeof(int) * n);
    derive_costs(D, mu, w);
    return 0;
}

/* The chain DP with frame f restricted to its K cheapest pieces by U
 * (lowest piece first on ties) and its current label: exact for that
 * restricted problem, O(n (d + K^2)) instead of O(n d^2).  The current
 * labels are among the candidates, so the energy never rises above
 * theirs: a weaker but valid label step for a descent.  l: n labels, in:
 * the current ones, out: the new ones.  Returns the energy, NAN on
 * allocation failure.  One pass over the frames: frame f's costs are
 * formed from its row of P (U and H are never stored), its candidates
 * selected while they are in cache, and the DP step from f - 1 to f
 * follows at once (T is symmetric: row b is read).  With w->cand_reuse
 * the candidates of the previous call are kept (a frame whose current
 * label is not among them and has no room left is selected again): the
 * label steps after an incremental library update, where the costs moved
 * little, skip the selection. */
__attribute__((optimize("tree-vectorize", "finite-math-only", "no-signed-zeros"), target_clones("avx512f", "avx2", "default")))
static double dp_candidates(struct work *w, int K, int *l)
{
    const struct replib_data *D = w->D;
    int n = D->n, d = w->d;
    if (K > d) K = d;
    int W = K + 1;
    const double *P = w->P, *qd = w->qd, *T = w->T, *zz = D->zz, *dd = D->dd;
    const unsigned char *link = D->link;
    double mu = w->mu, m2 = -2 * mu;
    if (!w->cand) {
        w->cand = malloc(sizeof(int) * (size_t)n * W);
        w->nc = malloc(sizeof(int) * n);
        w->hs = malloc(sizeof(double) * (size_t)n * W);
        if (!w->cand || !w->nc || !w->hs) {
            free(w->cand); free(w->nc); free(w->hs);
            w->cand = w->nc = NULL; w->hs = NULL;
            cm_seterr("replib: out of memory (%d frames, %d candidates)", n, W);
            return NAN;
        }
        w->cand_reuse = 0;
    }
    int *cand = w->cand, *nc = w->nc, reuse = w->cand_reuse;
    double *hs = w->hs;
    double *V = malloc(sizeof(double) * W), *Vn = malloc(sizeof(double) * W);
    double *ub = malloc(sizeof(double) * d);
    int *pool_buf = malloc(sizeof(int) * (d + 1));
    if (!V || !Vn || !ub || !pool_buf) {
        free(V); free(Vn); free(ub); free(pool_buf);
        cm_seterr("replib: out of memory (%d frames, %d candidates)", n, W);
        return NAN;
    }
    double total = 0, *u = ub;
    int start = 0;
    for (int f = 0; f < n; f++) {
        const double *p = P + (size_t)f * d;
        double zf = zz[f];
        int *c = cand + (size_t)f * W, k = 0, in = 0, m = d;
        if (reuse && f + 4 < n) {
            /* the kept candidates' costs of a frame 4 ahead: P is
             * streamed from memory and these loads are scattered */
            const int *cf = cand + (size_t)(f + 4) * W;
            const double *pf = P + (size_t)(f + 4) * d;
            for (int j = 0; j < nc[f + 4]; j++) __builtin_prefetch(pf + cf[j]);
        }
        if (reuse) {
            k = nc[f];
            for (int j = 0; j < k; j++) in |= c[j] == l[f];
            if (!in && k == W) k = 0;       /* select again */
            else if (!in) { c[k++] = l[f]; in = 1; }
        }
        if (k == 0 || !reuse) {
            for (int a = 0; a < d; a++) u[a] = zf + qd[a] - 2 * p[a];
            k = 0; in = 0;
            const int *pool = NULL;
            if (f > 0 && K < d) {
                /* the previous frame's first K candidates bound frame f's
                 * K-th smallest cost from above: only pieces at or below
                 * that bound can be among the K smallest (same set, same
                 * order) */
                const int *pc = cand + (size_t)(f - 1) * W;
                double tau = u[pc[0]];
                for (int j = 1; j < K; j++) tau = u[pc[j]] > tau ? u[pc[j]] : tau;
                m = 0;
                for (int a = 0; a < d; a++) { pool_buf[m] = a; m += u[a] <= tau; }
                if (m >= K) pool = pool_buf;
                else m = d;
            }
            for (int i = 0; i < m; i++) {
                int a = pool ? pool[i] : i;
                if (k == K && !(u[a] < u[c[K - 1]])) continue;
                int j = k < K ? k++ : K - 1;
                while (j > 0 && u[c[j - 1]] > u[a]) { c[j] = c[j - 1]; j--; }
                c[j] = a;
            }
            for (int j = 0; j < k; j++) in |= c[j] == l[f];
            if (!in) c[k++] = l[f];
        } else {
            for (int j = 0; j < k; j++) u[c[j]] = zf + qd[c[j]] - 2 * p[c[j]];
        }
        nc[f] = k;
        if (f == start) {
            for (int i = 0; i < k; i++) V[i] = u[c[i]];
        } else {
            /* DP step f - 1 -> f: H_g[a] = -2 mu (P_f[a] - P_g[a]) */
            int g = f - 1;
            const double *pg = P + (size_t)g * d;
            const int *ca = cand + (size_t)g * W;
            double *h = hs + (size_t)g * W, cg = mu * dd[g];
            for (int i = 0; i < nc[g]; i++) h[i] = V[i] - m2 * (p[ca[i]] - pg[ca[i]]);
            for (int j = 0; j < k; j++) {
                int b = c[j];
                double mn = INFINITY;
                const double *Tb = T + (size_t)b * d;
                for (int i = 0; i < nc[g]; i++) {
                    double v = h[i] + Tb[ca[i]];
                    mn = v < mn ? v : mn;
                }
                Vn[j] = mn + u[b] + cg + m2 * (p[b] - pg[b]);
            }
            double *t = V; V = Vn; Vn = t;
        }
        if (f == n - 1 || (link && !link[f])) {
            /* the clip start..f ends: best final label, then back */
            int end = f, best = 0;
            for (int i = 1; i < nc[end]; i++) if (V[i] < V[best]) best = i;
            total += V[best];
            l[end] = cand[(size_t)end * W + best];
            for (int g = end - 1; g >= start; g--) {
                const int *ca = cand + (size_t)g * W;
                const double *h = hs + (size_t)g * W;
                int b = l[g + 1], im = 0;
                double mn = INFINITY;
                for (int i = 0; i < nc[g]; i++) {
                    double v = h[i] + T[(size_t)b * d + ca[i]];
                    if (v < mn) { mn = v; im = i; }
                }
                l[g] = ca[im];
            }
            start = f + 1;
        }
    }
    free(V); free(Vn); free(ub); free(pool_buf);
    return total;
}

/* The energy of labels l and its parts from P (as chain_energy on the
 * terms ensure_uh would store, term by term the same arithmetic). */
static double energy_from_p(const struct work *w, const int *l, double *unary, double *pair)
{
    const struct replib_data *D = w->D;
    int n = D->n, d = w->d;
    const double *P = w->P;
    double mu = w->mu, eu = 0, ep = 0;
    for (int f = 0; f < n; f++) {
        int a = l[f];
        eu += D->zz[f] + w->qd[a] - 2 * P[(size_t)f * d + a];
        if (f + 1 < n && D->link[f] && mu > 0) {
            int b = l[f + 1];
            double v = 0;
            v += mu * D->dd[f];
            v += w->T[(size_t)a * d + b];
            v += -2 * mu * (P[(size_t)(f + 1) * d + b] - P[(size_t)f * d + b]) -
                 -2 * mu * (P[(size_t)(f + 1) * d + a] - P[(size_t)f * d + a]);
            ep += v;
        }
    }
    if (unary) *unary = eu;
    if (pair) *pair = ep;
    return eu + ep;
}

/* label step on the chain in w; l in/out (used as the start for moves) */
static double label_step(struct work *w, enum replib_method m, int *l, int have_start)
{
    if (m == REPLIB_DP && w->ncand > 0 && have_start && w->ch.T) {
        double E = dp_candidates(w, w->ncand, l);
        w->cand_reuse = 0;
        return E;
    }
    w->cand_reuse = 0;
    ensure_uh(w);
    if (!w->ch.T && !w->ch.H && !(w->ch.swap > 0)) {
        /* lambda = 0, no swap cost: every method gives the nearest piece (lowest on ties) */
        int n = w->ch.n, d = w->ch.d;
        double E = 0;
        for (int f = 0; f < n; f++) {
            const double *u = w->U + (size_t)f * d;
            int b = 0;
            for (int a = 1; a < d; a++) if (u[a] < u[b]) b = a;
            l[f] = b;
            E += u[b];
        }
        return E;
    }
    if (m == REPLIB_DP) return chain_dp(&w->ch, l);
    if (!have_start) {
        int n = w->ch.n, d = w->ch.d;
        for (int f = 0; f < n; f++) {
            int b = 0;
            for (int a = 1; a < d; a++) if (w->U[(size_t)f * d + a] < w->U[(size_t)f * d + b]) b = a;
            l[f] = b;
        }
    }
    if (m == REPLIB_EXPANSION) return chain_expansion(&w->ch, l, 0, NULL);
    return chain_swap(&w->ch, l, 0);
}

/* k-means++ seeding on the Gram matrix or on low-rank coordinates (fixed
 * pieces count as centers); Forgy (distinct random frames) in the direct
 * back end on full coordinates, where distances would cost a GEMM each. */
static int seed_pieces(const struct replib_data *D, int d, struct rng *r, struct lstate *s)
{
    int n = D->n, N = D->N, nfix = D->nfix;
    s->nfree = 0; s->nnz = 0;
    double *mind = malloc(sizeof(double) * n);
    unsigned char *used = calloc(n, 1);
    if (!mind || !used) { free(mind); free(used); return cm_seterr("replib: out of memory"); }
    for (int f = 0; f < n; f++) mind[f] = INFINITY;
    const double *K = D->K;
    int zd = D->zdim, useZ = !K && D->Z && zd <= 512;
    int K_ = K || useZ;
#define DIST(f, g) (D->zz[f] + D->zz[g] - 2 * (K ? K[(size_t)(f) * N + (g)] : \
                    cblas_ddot(zd, D->Z + (size_t)(f) * zd, 1, D->Z + (size_t)(g) * zd, 1)))
    for (int a = 0; a < d; a++) {
        int g;
        if (a < nfix) g = n + a;
        else {
            double tot = 0;
            if (K_ && a > 0)
                for (int f = 0; f < n; f++) if (!used[f]) tot += mind[f] > 0 ? mind[f] : 0;
            if (K_ && a > 0 && tot > 0) {
                double u = rng_uniform(r) * tot;
                g = -1;
                for (int f = 0; f < n; f++) {
                    if (used[f]) continue;
                    double m = mind[f] > 0 ? mind[f] : 0;
                    if (m <= 0) continue;
                    g = f;
                    if (u < m) break;
                    u -= m;
                }
            } else {
                int left = 0;
                for (int f = 0; f < n; f++) left += !used[f];
                int k = rng_int(r, left);
                for (g = 0; g < n; g++) if (!used[g] && k-- == 0) break;
            }
            used[g] = 1;
        }
        s->src[a] = g;
        if (K_)
            for (int f = 0; f < n; f++) {
                double dv = DIST(f, g);
                if (dv < mind[f]) mind[f] = dv;
            }
    }
#undef DIST
    free(mind); free(used);
    return 0;
}

/* One restart's outcome, kept until the best is chosen. */
struct restart {
    int rc;
    double E, data, velocity, label_seconds;
    int iterations, accepted;   /* descent iterations, split/merge trials kept */
    int *labels;
    struct lstate s;            /* the library the labels were optimised for */
    struct replib_iter *log;    /* buffered iteration records */
    int nlog, caplog;
};

static void keep_log(struct restart *r, const struct replib_iter *it)
{
    if (r->nlog == r->caplog) {
        int nc = r->caplog ? 2 * r->caplog : 16;
        struct replib_iter *p = realloc(r->log, sizeof *p * nc);
        if (!p) return;
        r->log = p;
        r->caplog = nc;
    }
    r->log[r->nlog++] = *it;
}

static int lstate_copy(struct lstate *dst, const struct lstate *src)
{
    lstate_free(dst);
    if (lstate_init(dst, src->d) < 0) return -1;
    int nf = src->nfree;
    dst->nfree = nf;
    dst->diag = src->diag;
    memcpy(dst->src, src->src, sizeof(int) * src->d);
    memcpy(dst->fidx, src->fidx, sizeof(int) * src->d);
    if (nf > 0) {
        dst->Uf = malloc(sizeof(double) * (size_t)nf * nf);
        if (!dst->Uf) return cm_seterr("replib: out of memory");
        memcpy(dst->Uf, src->Uf, sizeof(double) * (size_t)nf * nf);
    }
    for (int k = 0; k < src->nnz; k++)
        if (push(dst, src->ri[k], src->ci[k], src->v[k]) < 0) return cm_seterr("replib: out of memory");
    return 0;
}

/* kc (n) = z_f . z_g for every frame f (g: a frame or a fixed piece) */
static void kcol(const struct replib_data *D, int g, double *kc)
{
    int n = D->n;
    if (D->K) { memcpy(kc, D->K + (size_t)g * D->N, sizeof(double) * n); return; }
    int zd = D->zdim;
    cblas_dgemv(CblasRowMajor, CblasNoTrans, n, zd, 1.0, D->Z, zd, D->Z + (size_t)g * zd, 1, 0.0, kc, 1);
}

/* dist (n) = |z_f - z_g|^2 */
static void dcol(const struct replib_data *D, int g, double *kc, double *dist)
{
    kcol(D, g, kc);
    for (int f = 0; f < D->n; f++) {
        double v = D->zz[f] + D->zz[g] - 2 * kc[f];
        dist[f] = v > 0 ? v : 0;
    }
}

/* dist (L by n, row c) = |z_f - z_{g[c]}|^2 for L frames or fixed pieces
 * g at once: one GEMM on the reduced coordinates (or rows of K), by
 * blocks of frames when helped (team).  Returns 0 or -1 (allocation). */
struct dcols_job {
    const struct replib_data *D;
    const int *g;
    int L;
    const double *Zc;
    const double *ZcT;          /* zdim by 8: Zc transposed, zero-padded (dots_fma), or NULL */
    double *dist;
    const int *rows;            /* with ZcT: only these nrows frames (dcols_pruned), or NULL: all */
    int nrows;
};

/* dist[c n + f] = z_f . zc_c for the rows f = rows[i] of Z, i in [i0, i1)
 * (rows NULL: f = i; n: the row stride of dist, > every f), c < L <= 8: the
 * candidates in the 8 lanes of a vector, the coordinates in order, one
 * fused multiply-add each from 0.  Every entry is its own chain of fused
 * multiply-adds in coordinate order, so the lane width does not change a
 * bit: dots_avx512 (one 8-lane vector per row) and dots_avx2 (two 4-lane
 * halves) give the same numbers, and which rows are taken together does
 * not change a bit either.  These are also the operations of OpenBLAS's
 * SkylakeX DGEMM kernel for an inner dimension it does not split (<= 256:
 * checked bitwise), but not of its Haswell kernel (1,319 of 1.86M values
 * differ in the last bit at the Monkey size): the distances of dcols are
 * the same on every FMA machine whatever kernel OpenBLAS picked.  Without
 * packing Z for every call: 1.7x faster than DGEMM for the 7 candidates of
 * a greedy start at 2,653 x 128. */
__attribute__((target("avx512f,fma")))
static void dots_avx512(const double *Z, int zd, const int *rows, int i0, int i1, const double *ZcT, int L, int n,
                        double *dist)
{
    int i = i0;
    double t[32] __attribute__((aligned(64)));
#define ROW_(j) (rows ? rows[j] : (j))
    for (; i + 4 <= i1; i += 4) {
        int f[4] = {ROW_(i), ROW_(i + 1), ROW_(i + 2), ROW_(i + 3)};
        const double *z0 = Z + (size_t)f[0] * zd, *z1 = Z + (size_t)f[1] * zd, *z2 = Z + (size_t)f[2] * zd,
                     *z3 = Z + (size_t)f[3] * zd;
        __m512d a0 = _mm512_setzero_pd(), a1 = a0, a2 = a0, a3 = a0;
        for (int k = 0; k < zd; k++) {
            __m512d b = _mm512_load_pd(ZcT + (size_t)k * 8);
            a0 = _mm512_fmadd_pd(_mm512_set1_pd(z0[k]), b, a0);
            a1 = _mm512_fmadd_pd(_mm512_set1_pd(z1[k]), b, a1);
            a2 = _mm512_fmadd_pd(_mm512_set1_pd(z2[k]), b, a2);
            a3 = _mm512_fmadd_pd(_mm512_set1_pd(z3[k]), b, a3);
        }
        _mm512_store_pd(t, a0); _mm512_store_pd(t + 8, a1); _mm512_store_pd(t + 16, a2); _mm512_store_pd(t + 24, a3);
        for (int c = 0; c < L; c++)
            for (int q = 0; q < 4; q++) dist[(size_t)c * n + f[q]] = t[8 * q + c];
    }
    for (; i < i1; i++) {
        int f = ROW_(i);
        const double *z0 = Z + (size_t)f * zd;
        __m512d a0 = _mm512_setzero_pd();
        for (int k = 0; k < zd; k++) a0 = _mm512_fmadd_pd(_mm512_set1_pd(z0[k]), _mm512_load_pd(ZcT + (size_t)k * 8), a0);
        _mm512_store_pd(t, a0);
        for (int c = 0; c < L; c++) dist[(size_t)c * n + f] = t[c];
    }
#undef ROW_
}

__attribute__((target("avx2,fma")))
static void dots_avx2(const double *Z, int zd, const int *rows, int i0, int i1, const double *ZcT, int L, int n,
                      double *dist)
{
    double t[8] __attribute__((aligned(32)));
    for (int i = i0; i < i1; i++) {
        int f = rows ? rows[i] : i;
        const double *z0 = Z + (size_t)f * zd;
        __m256d lo = _mm256_setzero_pd(), hi = lo;
        for (int k = 0; k < zd; k++) {
            __m256d a = _mm256_set1_pd(z0[k]);
            lo = _mm256_fmadd_pd(a, _mm256_load_pd(ZcT + (size_t)k * 8), lo);
            if (L > 4) hi = _mm256_fmadd_pd(a, _mm256_load_pd(ZcT + (size_t)k * 8 + 4), hi);
        }
        _mm256_store_pd(t, lo); _mm256_store_pd(t + 4, hi);
        for (int c = 0; c < L; c++) dist[(size_t)c * n + f] = t[c];
    }
}

/* dots_avx512 or dots_avx2, whichever the CPU has (dots_ok) */
static int dots_wide = -1;      /* 1: AVX-512, 0: AVX2, -1: not yet asked */
static void dots_fma(const double *Z, int zd, const int *rows, int i0, int i1, const double *ZcT, int L, int n,
                     double *dist)
{
    if (dots_wide) dots_avx512(Z, zd, rows, i0, i1, ZcT, L, n, dist);
    else dots_avx2(Z, zd, rows, i0, i1, ZcT, L, n, dist);
}

static void dcols_block(void *ctx, int i)
{
    const struct dcols_job *j = ctx;
    const struct replib_data *D = j->D;
    int n = D->n, zd = D->zdim, L = j->L, f0 = 0, f1 = n;
    if (j->rows) {
        /* a block of the listed frames (dcols_pruned) */
        int i0 = 0, i1 = j->nrows;
        if (i >= 0) chunk_rows(j->nrows, i, &i0, &i1);
        if (i1 <= i0) return;
        dots_fma(D->Z, zd, j->rows, i0, i1, j->ZcT, L, n, j->dist);
        for (int c = 0; c < L; c++) {
            double *dc = j->dist + (size_t)c * n, zg = D->zz[j->g[c]];
            for (int r = i0; r < i1; r++) {
                int f = j->rows[r];
                double v = D->zz[f] + zg - 2 * dc[f];
                dc[f] = v > 0 ? v : 0;
            }
        }
        return;
    }
    if (i >= 0) chunk_rows(n, i, &f0, &f1);
    if (f1 <= f0) return;
    if (D->K) {
        for (int c = 0; c < L; c++)
            memcpy(j->dist + (size_t)c * n + f0, D->K + (size_t)j->g[c] * D->N + f0, sizeof(double) * (f1 - f0));
    } else if (j->ZcT) {
        dots_fma(D->Z, zd, NULL, f0, f1, j->ZcT, L, n, j->dist);
    } else {
        cblas_dgemm(CblasRowMajor, CblasNoTrans, CblasTrans, L, f1 - f0, zd, 1.0, j->Zc, zd, D->Z + (size_t)f0 * zd, zd,
                    0.0, j->dist + f0, n);
    }
    for (int c = 0; c < L; c++) {
        double *dc = j->dist + (size_t)c * n, zg = D->zz[j->g[c]];
        for (int f = f0; f < f1; f++) {
            double v = D->zz[f] + zg - 2 * dc[f];
            dc[f] = v > 0 ? v : 0;
        }
    }
}

/* dots_fma runs wherever the CPU has FMA and AVX2 or AVX-512, whatever
 * OpenBLAS's kernel (elsewhere dcols is the BLAS call: e.g. a CPU without
 * FMA); STOPMO_NO_AVX512 set (not 0) takes the AVX2 twin on an AVX-512
 * CPU, which must give the same bytes (t0327) */
static int dots_ok(void)
{
    static int ok = -1;     /* set once, before the workers start (seeding runs on them: see replib_learn) */
    if (ok < 0) {
        __builtin_cpu_init();
        int fma = __builtin_cpu_supports("fma");
        const char *e = getenv("STOPMO_NO_AVX512");     /* the AVX2 twin on an AVX-512 CPU (tests) */
        dots_wide = fma && __builtin_cpu_supports("avx512f") && !(e && *e && strcmp(e, "0"));
        ok = dots_wide || (fma && __builtin_cpu_supports("avx2"));
    }
    return ok;
}

/* ZcT (zdim by 8, 64-byte aligned, zero-padded) for dots_fma with the
 * L <= 8 rows g of Z, or NULL (allocation) */
static double *candidates_t(const struct replib_data *D, const int *g, int L)
{
    int zd = D->zdim;
    double *ZcT = aligned_alloc(64, sizeof(double) * 8 * (size_t)zd);
    if (ZcT)
        for (int k = 0; k < zd; k++)
            for (int c = 0; c < 8; c++) ZcT[(size_t)k * 8 + c] = c < L ? D->Z[(size_t)g[c] * zd + k] : 0;
    return ZcT;
}

static int dcols(const struct replib_data *D, struct team *t, const int *g, int L, double *dist)
{
    int zd = D->zdim;
    double *Zc = NULL, *ZcT = NULL;
    if (!D->K && L <= 8 && zd <= REPLIB_TEAM_MAXK && dots_ok()) {
        if (!(ZcT = candidates_t(D, g, L))) return -1;
    } else if (!D->K) {
        Zc = malloc(sizeof(double) * (size_t)L * zd);
        if (!Zc) return -1;
        for (int c = 0; c < L; c++) memcpy(Zc + (size_t)c * zd, D->Z + (size_t)g[c] * zd, sizeof(double) * zd);
    }
    struct dcols_job j = {D, g, L, Zc, ZcT, dist, NULL, 0};
    if (t && D->n >= REPLIB_TEAM_MINROWS && (D->K || zd <= REPLIB_TEAM_MAXK))
        team_run(t, REPLIB_TEAM_CHUNKS, dcols_block, &j);
    else
        dcols_block(&j, -1);
    free(Zc);
    free(ZcT);
    return 0;
}

/* dcols_pruned's bounds: need (out) = the frames to measure, returns
 * their count; the others' entries of dist are set to mind[f].  A frame
 * whose mind is not finite fails every comparison: measured.  dco: L rows
 * of stride N + 1, entry N of each -infinity (no owner).  Branch-free over
 * the frames, candidate by candidate (vectorized); scratch: sk (n), oi, nf,
 * ez (n each). */
__attribute__((optimize("tree-vectorize"), target_clones("avx512f", "avx2", "default")))
static int prune_frames(const struct replib_data *D, const int *g, int L, const double *mind, const int *owner,
                        const double *dco, int *need, double *dist, unsigned char *restrict sk, int *restrict oi,
                        double *restrict nf, double *restrict ez)
{
    int n = D->n, N = D->N, nn = 0;
    const double *zz = D->zz;
    for (int f = 0; f < n; f++) {
        int o = owner ? owner[f] : -1;
        oi[f] = o >= 0 ? o : N;
        ez[f] = zz[f] + (o >= 0 ? zz[o] : 0);
        nf[f] = sqrt(zz[f]);
        sk[f] = 1;
    }
    for (int c = 0; c < L; c++) {
        double zc = zz[g[c]], nc = sqrt(zc);
        const double *dc = dco + (size_t)c * (N + 1);
        for (int f = 0; f < n; f++) {
            double m = mind[f], dn = nf[f] - nc, E = 1e-10 * (ez[f] + zc), dcoo = dc[oi[f]];
            sk[f] &= (dn * dn >= m + E) | (dcoo - E >= 4 * (m + E));
        }
    }
    for (int f = 0; f < n; f++) {
        if (sk[f])
            for (int c = 0; c < L; c++) dist[(size_t)c * n + f] = mind[f];
        else
            need[nn++] = f;
    }
    return nn;
}

/* dcols for the candidates g of a greedy start or a split/merge proposal,
 * where the caller needs only min(dist, mind) per frame, or only whether
 * dist < mind and then dist: a frame whose distance to every
 * candidate provably is >= mind[f] as computed (the value it would get
 * from dcols, rounding included) is not measured, and its entries are set
 * to mind[f], which gives the same minimum.  The bounds, with
 * E = 1e-10 (|z_f|^2 + |z_c|^2 + |z_o|^2), far above the rounding of the
 * computed squared distances and norms (both from sums of at most zdim <=
 * 256 products: below 1e-13 times the squared norms):
 * |z_f - z_c| >= | |z_f| - |z_c| |, and the triangle inequality through
 * o = owner[f] (when owner is not NULL), the centre whose distance gave mind[f]:
 * |z_f - z_c| >= |z_c - z_o| - |z_f - z_o|, so that |z_c - z_o|^2 - E >=
 * 4 (mind[f] + E) implies |z_f - z_c|^2 >= mind[f] + E (Elkan 2003).  The
 * distances |z_c - z_o| to the centres come first (a few rows); the
 * frames left are measured by the same kernel (dots_fma: each row's
 * sums are its own), so every entry the caller reads from a measured frame
 * has the bits dcols gives it.  Measured at the Monkey size (2,653 frames,
 * d = 150): two thirds of the frames are not measured in the greedy
 * starts, half of them in the split/merge proposals (norm bound only: the
 * pieces are not frames).  mind (n): the thresholds (not finite: the
 * frame is measured); owner (n, or NULL): the centre row of each frame's
 * mind (< N), or -1.  Only where dcols uses dots_fma (else it is
 * dcols).  Returns 0 or -1 (allocation). */
static int dcols_pruned(const struct replib_data *D, struct team *t, const int *g, int L, const double *mind,
                        const int *owner, double *dist)
{
    int n = D->n, N = D->N, zd = D->zdim;
    if (D->K || L > 8 || zd > REPLIB_TEAM_MAXK || !dots_ok()) return dcols(D, t, g, L, dist);
    double *ZcT = candidates_t(D, g, L);
    int *slot = malloc(sizeof(int) * N), *orow = malloc(sizeof(int) * N), *need = malloc(sizeof(int) * n);
    double *dco = malloc(sizeof(double) * (size_t)8 * (N + 1)), *nf = malloc(sizeof(double) * 2 * n);
    int *oi = malloc(sizeof(int) * n);
    unsigned char *sk = malloc(n);
    if (!ZcT || !slot || !orow || !need || !dco || !nf || !oi || !sk) {
        free(ZcT); free(slot); free(orow); free(need); free(dco); free(nf); free(oi); free(sk);
        return -1;
    }
    /* the candidates' squared distances to the centres that own a frame */
    int no = 0;
    for (int i = 0; i < N; i++) slot[i] = -1;
    for (int f = 0; f < n && owner; f++)
        if (owner[f] >= 0 && slot[owner[f]] < 0) { slot[owner[f]] = no; orow[no++] = owner[f]; }
    /* dots_fma writes row o's products to dco[c (N + 1) + o] */
    if (no > 0) dots_fma(D->Z, zd, orow, 0, no, ZcT, L, N + 1, dco);
    for (int c = 0; c < L; c++) {
        for (int k = 0; k < no; k++) {
            int o = orow[k];
            double v = D->zz[o] + D->zz[g[c]] - 2 * dco[(size_t)c * (N + 1) + o];
            dco[(size_t)c * (N + 1) + o] = v > 0 ? v : 0;
        }
        dco[(size_t)c * (N + 1) + N] = -INFINITY;
    }
    int nn = prune_frames(D, g, L, mind, owner, dco, need, dist, sk, oi, nf, nf + n);
    struct dcols_job j = {D, g, L, NULL, ZcT, dist, need, nn};
    if (t && nn >= REPLIB_TEAM_MINROWS)
        team_run(t, REPLIB_TEAM_CHUNKS, dcols_block, &j);
    else
        dcols_block(&j, -1);
    free(ZcT); free(slot); free(orow); free(need); free(dco); free(nf); free(oi); free(sk);
    return 0;
}

/* Sample a frame with probability proportional to max(wt[f], 0) among
 * frames with skip[f] == 0 (skip may be NULL); -1 if all weights are 0. */
static double d2_total(const double *wt, const unsigned char *skip, int n)
{
    double tot = 0;
    for (int f = 0; f < n; f++) if (!(skip && skip[f]) && wt[f] > 0) tot += wt[f];
    return tot;
}

/* tot: d2_total(wt, skip, n), summed once for the draws of one set of weights */
static int d2_sample(struct rng *r, const double *wt, const unsigned char *skip, int n, double tot)
{
    if (!(tot > 0)) return -1;
    double u = rng_uniform(r) * tot;
    int g = -1;
    for (int f = 0; f < n; f++) {
        if ((skip && skip[f]) || !(wt[f] > 0)) continue;
        g = f;
        if (u < wt[f]) break;
        u -= wt[f];
    }
    return g;
}

/* Greedy k-means++ (Arthur & Vassilvitskii 2007 with the candidate trials of
 * scikit-learn): the first centre (when no piece is fixed) is a uniformly
 * random frame; every further one is the best of 2 + ln d D^2-sampled
 * frames, best meaning the lowest potential sum_f min(mind_f, |z_f - z_c|^2). */
static int seed_greedy(const struct replib_data *D, struct team *t, int d, int prune, struct rng *r, struct lstate *s)
{
    int n = D->n, nfix = D->nfix, L = 2 + (int)log((double)d);
    s->nfree = 0; s->nnz = 0;
    double *mind = malloc(sizeof(double) * n), *kc = malloc(sizeof(double) * n);
    double *dcl = malloc(sizeof(double) * (size_t)n * L), *db = malloc(sizeof(double) * n);
    int *cands = malloc(sizeof(int) * L), *owner = malloc(sizeof(int) * n);
    unsigned char *used = calloc(n, 1);
    if (!mind || !kc || !dcl || !db || !used || !cands || !owner) {
        free(mind); free(kc); free(dcl); free(db); free(used); free(cands); free(owner);
        return cm_seterr("replib: out of memory");
    }
    for (int f = 0; f < n; f++) { mind[f] = INFINITY; owner[f] = -1; }
    for (int a = 0; a < d; a++) {
        int g = -1;
        if (a < nfix) {
            g = n + a;
            dcol(D, g, kc, db);
        } else {
            if (a > 0) {
                /* the L candidates are drawn before any distance is known
                 * (mind does not change meanwhile), then measured by one GEMM */
                double bestpot = INFINITY;
                int nc = 0;
                double tot = d2_total(mind, used, n);
                for (int t = 0; t < L; t++) {
                    int c = d2_sample(r, mind, used, n, tot);
                    if (c < 0) break;
                    cands[nc++] = c;
                }
                if (nc > 0 && (prune ? dcols_pruned(D, t, cands, nc, mind, owner, dcl) : dcols(D, t, cands, nc, dcl)) < 0) {
                    free(mind); free(kc); free(dcl); free(db); free(used); free(cands); free(owner);
                    return cm_seterr("replib: out of memory");
                }
                for (int t = 0; t < nc; t++) {
                    const double *dct = dcl + (size_t)t * n;
                    double pot = 0;
                    for (int f = 0; f < n; f++) pot += dct[f] < mind[f] ? dct[f] : mind[f];
                    if (pot < bestpot) { bestpot = pot; g = cands[t]; memcpy(db, dct, sizeof(double) * n); }
                }
            }
            if (g < 0) {        /* first centre, or every frame already fitted exactly */
                int left = 0;
                for (int f = 0; f < n; f++) left += !used[f];
                int k = rng_int(r, left);
                for (g = 0; g < n; g++) if (!used[g] && k-- == 0) break;
                dcol(D, g, kc, db);
            }
            used[g] = 1;
        }
        s->src[a] = g;
        for (int f = 0; f < n; f++) if (db[f] < mind[f]) { mind[f] = db[f]; owner[f] = g; }
    }
    free(mind); free(kc); free(dcl); free(db); free(used); free(cands); free(owner);
    return 0;
}

/* Hartigan's single-frame moves for lambda = 0 on the costs in w (w->P,
 * w->Q for the piece means of l, w->U = costs): frame f leaves piece a
 * for b when n_b/(n_b+1) |z_f - r_b|^2 < n_a/(n_a-1) |z_f - r_a|^2 (a fixed
 * piece has no factor: it does not move), which lowers the energy by
 * exactly the difference; both means and their cost columns are updated in
 * O(N) (one column of K or one GEMV on Z).  Returns the number of moves. */
static int hartigan(const struct replib_data *D, struct work *w, int *l, double *kc)
{
    int n = D->n, d = w->d, nfix = D->nfix, moves = 0;
    double *P = p_write(w, 1), *U = w->U, *Q = w->Q;
    int *cnt = calloc(d, sizeof(int));
    if (!cnt) return -1;
    for (int f = 0; f < n; f++) cnt[l[f]]++;
    for (int sweep = 0; sweep < 50; sweep++) {
        int sm = 0;
        for (int f = 0; f < n; f++) {
            int a = l[f];
            const double *u = U + (size_t)f * d;
            double rem;
            if (a < nfix) rem = u[a];
            else if (cnt[a] < 2) continue;
            else rem = u[a] * cnt[a] / (cnt[a] - 1);
            int b = -1;
            double add = INFINITY;
            for (int c = 0; c < d; c++) {
                if (c == a) continue;
                double v;
                if (c < nfix) v = u[c];
                else if (cnt[c] < 1) continue;
                else v = u[c] * cnt[c] / (cnt[c] + 1);
                if (v < add) { add = v; b = c; }
            }
            if (b < 0 || !(rem - add > 1e-12 * rem)) continue;
            kcol(D, f, kc);
            double zf = D->zz[f];
            if (a >= nfix) {
                double na = cnt[a], pf = P[(size_t)f * d + a];
                Q[(size_t)a * d + a] = (na * na * Q[(size_t)a * d + a] - 2 * na * pf + zf) / ((na - 1) * (na - 1));
                for (int g = 0; g < n; g++)
                    P[(size_t)g * d + a] = (na * P[(size_t)g * d + a] - kc[g]) / (na - 1);
            }
            if (b >= nfix) {
                double nb = cnt[b], pf = P[(size_t)f * d + b];
                Q[(size_t)b * d + b] = (nb * nb * Q[(size_t)b * d + b] + 2 * nb * pf + zf) / ((nb + 1) * (nb + 1));
                for (int g = 0; g < n; g++)
                    P[(size_t)g * d + b] = (nb * P[(size_t)g * d + b] + kc[g]) / (nb + 1);
            }
            for (int g = 0; g < n; g++) {
                U[(size_t)g * d + a] = D->zz[g] + Q[(size_t)a * d + a] - 2 * P[(size_t)g * d + a];
                U[(size_t)g * d + b] = D->zz[g] + Q[(size_t)b * d + b] - 2 * P[(size_t)g * d + b];
            }
            cnt[a]--; cnt[b]++;
            l[f] = b;
            sm++;
        }
        moves += sm;
        if (!sm) break;
    }
    free(cnt);
    return moves;
}

/* Per-restart scratch arrays. */
struct scratch {
    int *l, *ln, *bl, *cnt;     /* n, n, n, d */
    double *cost, *kc, *dc, *cur, *rc;  /* n, n, n, n, d */
    double *dcl;                /* (2 + ln d) by n: distances to split candidates */
    int *order;                 /* d */
};

static void scratch_free(struct scratch *x)
{
    free(x->l); free(x->ln); free(x->bl); free(x->cnt);
    free(x->cost); free(x->kc); free(x->dc); free(x->cur); free(x->rc); free(x->order); free(x->dcl);
    memset(x, 0, sizeof *x);
}

static int scratch_init(struct scratch *x, int n, int d)
{
    x->l = malloc(sizeof(int) * n); x->ln = malloc(sizeof(int) * n); x->bl = malloc(sizeof(int) * n);
    x->cnt = malloc(sizeof(int) * d); x->order = malloc(sizeof(int) * d);
    x->cost = malloc(sizeof(double) * n); x->kc = malloc(sizeof(double) * n);
    x->dc = malloc(sizeof(double) * n); x->cur = malloc(sizeof(double) * n);
    x->rc = malloc(sizeof(double) * d);
    x->dcl = malloc(sizeof(double) * (size_t)n * (2 + (int)log((double)d)));
    if (!x->dcl || !x->l || !x->ln || !x->bl || !x->cnt || !x->order || !x->cost || !x->kc || !x->dc || !x->cur || !x->rc) {
        scratch_free(x);
        return cm_seterr("replib: out of memory");
    }
    return 0;
}

/* Block coordinate descent from the labels x->l: library step, label step,
 * until no label changes, E stalls (o->tol) or o->iterations.  *E (in: the
 * energy of x->l, INFINITY if unknown; out: the final energy).  On return
 * w holds the costs of the library s that x->l was labelled with. */
static int bcd(const struct replib_data *D, const struct replib_opts *o, struct work *w,
               struct lstate *s, struct scratch *x, double *E, struct restart *out, struct replib_iter *it)
{
    int n = D->n, d = o->d;
    double mu = o->lambda / 2;
    int iters = o->iterations < 1 ? 1 : o->iterations;
    int *l = x->l, *ln = x->ln;
    for (int k = 1; k <= iters; k++) {
        double ti = wall();
        it->iteration++;
        if (library_step(D, d, mu, l, x->cost, s, &it->reseeded) < 0) return -1;
        int ic = it->reseeded ? 1 : costs_incremental(D, s, mu, w, l);
        if (ic < 0) return cm_seterr("replib: out of memory");
        if (ic > 0) {
            if (compute_costs(D, s, mu, w) < 0) return -1;
            if (!D->K) { memcpy(w->lw, l, sizeof(int) * n); w->have = 1; w->ninc = 0; }
        }
        memcpy(ln, l, sizeof(int) * n);
        /* after an incremental update the candidates of the last label step are kept */
        w->cand_reuse = ic == 0 && k > 1;
        double tl = wall();
        double En = label_step(w, o->method, ln, 1);
        out->label_seconds += wall() - tl;
        if (isnan(En)) return cm_seterr("replib: the energy is not a number (squared coordinate differences overflow: scale the input down, e.g. with mesh-normalize)");
        it->changed = 0;
        for (int f = 0; f < n; f++) it->changed += ln[f] != l[f];
        memcpy(l, ln, sizeof(int) * n);
        for (int f = 0; f < n; f++) x->cost[f] = D->zz[f] + w->qd[l[f]] - 2 * w->P[(size_t)f * d + l[f]];
        it->energy = En;
        energy_from_p(w, l, &it->data, &it->velocity);
        it->seconds = wall() - ti;
        out->iterations++;
        keep_log(out, it);
        double Eprev = *E;
        *E = En;
        if (it->changed == 0 || (isfinite(Eprev) && Eprev - En <= o->tol * fabs(Eprev))) break;
    }
    return 0;
}

/* Descent to a local minimum: block coordinate descent and, with lambda = 0
 * and the search on, Hartigan moves until neither changes anything. */
static int descend(const struct replib_data *D, const struct replib_opts *o, struct work *w,
                   struct lstate *s, struct scratch *x, double *E, struct restart *out, struct replib_iter *it)
{
    if (bcd(D, o, w, s, x, E, out, it) < 0) return -1;
    if (o->search <= 0 || o->lambda > 0) return 0;
    for (int round = 0; round < 100; round++) {
        /* costs of the means of l (bcd may have stopped on tol) */
        int rs;
        if (library_step(D, o->d, 0, x->l, x->cost, s, &rs) < 0 || compute_costs(D, s, 0, w) < 0) return -1;
        if (rs) break;          /* an empty piece: leave it to the descent's re-seeding */
        ensure_uh(w);
        *E = chain_energy(&w->ch, x->l, NULL, NULL);
        int mv = hartigan(D, w, x->l, x->kc);
        if (mv < 0) return cm_seterr("replib: out of memory");
        if (mv == 0) break;
        *E = INFINITY;
        if (bcd(D, o, w, s, x, E, out, it) < 0) return -1;
    }
    return 0;
}

/* s2[f] = min over b != l[f] of U[f][b], frames [f0, f1) */
struct second_job {
    const double *U;
    const int *l;
    int n, d;
    double *s2;
};

/* the minimum over two ranges, vectorized (a minimum is exact in any order) */
__attribute__((optimize("tree-vectorize", "finite-math-only", "no-signed-zeros"),
               target_clones("avx512f", "avx2", "default")))
static void second_rows(const struct second_job *j, int f0, int f1)
{
    int d = j->d;
    for (int f = f0; f < f1; f++) {
        const double *u = j->U + (size_t)f * d;
        int lf = j->l[f];
        double m1 = INFINITY, m2 = INFINITY;
        for (int b = 0; b < lf; b++) m1 = u[b] < m1 ? u[b] : m1;
        for (int b = lf + 1; b < d; b++) m2 = u[b] < m2 ? u[b] : m2;
        j->s2[f] = m2 < m1 ? m2 : m1;
    }
}

static void second_job_run(void *ctx, int i)
{
    const struct second_job *j = ctx;
    int f0, f1;
    chunk_rows(j->n, i, &f0, &f1);
    second_rows(j, f0, f1);
}

/* One split/merge proposal on the labels x->l (costs in w): piece a, whose
 * frames are cheapest to hand to their second-best pieces, gives them away
 * and is re-placed at the best of 2 + ln d D^2-sampled badly fitted frames,
 * taking the frames that lie closer to that frame than to their piece.
 * Returns 1 if a proposal was made, 0 if none is possible. */
static int split_merge(const struct replib_data *D, const struct replib_opts *o, struct work *w,
                       struct scratch *x, struct rng *r)
{
    int n = D->n, d = o->d, nfix = D->nfix, L = 2 + (int)log((double)d);
    ensure_u(w);
    const double *U = w->U;
    int *l = x->l, *cnt = x->cnt;
    memset(cnt, 0, sizeof(int) * d);
    for (int f = 0; f < n; f++) cnt[l[f]]++;
    for (int a = 0; a < d; a++) x->rc[a] = 0;
    int sec_ok = 0;
    /* each frame's second-best cost (the cost after the merge for frames
     * of a), by blocks of frames; summed per piece in frame order */
    struct second_job sj = {U, l, n, d, x->dc};
    if (w->team && n >= REPLIB_TEAM_MINROWS) team_run(w->team, REPLIB_TEAM_CHUNKS, second_job_run, &sj);
    else second_rows(&sj, 0, n);
    for (int f = 0; f < n; f++) {
        double s2 = x->dc[f];
        if (isfinite(s2)) { x->rc[l[f]] += s2 - U[(size_t)f * d + l[f]]; sec_ok = 1; }
    }
    if (!sec_ok) return 0;
    int k = 0;
    for (int a = nfix; a < d; a++) if (cnt[a] > 0) x->order[k++] = a;
    if (k < 1) return 0;
    /* the 3 cheapest removals, one picked at random */
    int top = k < 3 ? k : 3;
    for (int i = 0; i < top; i++)
        for (int j = i + 1; j < k; j++)
            if (x->rc[x->order[j]] < x->rc[x->order[i]]) { int t = x->order[i]; x->order[i] = x->order[j]; x->order[j] = t; }
    int a = x->order[rng_int(r, top)];
    for (int f = 0; f < n; f++) {
        const double *u = U + (size_t)f * d;
        if (l[f] != a) { x->cur[f] = u[l[f]]; continue; }
        int b = -1;
        for (int c = 0; c < d; c++) if (c != a && (b < 0 || u[c] < u[b])) b = c;
        x->cur[f] = u[b];
        x->ln[f] = b;
    }
    int g = -1;
    double bestgain = -1;
    int cands[64], nc = 0;
    double tot = d2_total(x->cur, NULL, n);
    for (int t = 0; t < L && t < 64; t++) {
        int c = d2_sample(r, x->cur, NULL, n, tot);
        if (c < 0) break;
        cands[nc++] = c;
    }
    if (nc > 0 && (o->no_prune ? dcols(D, w->team, cands, nc, x->dcl)
                               : dcols_pruned(D, w->team, cands, nc, x->cur, NULL, x->dcl)) < 0) return -1;
    for (int t = 0; t < nc; t++) {
        const double *dct = x->dcl + (size_t)t * n;
        double gain = 0;
        for (int f = 0; f < n; f++) if (dct[f] < x->cur[f]) gain += x->cur[f] - dct[f];
        if (gain > bestgain) { bestgain = gain; g = cands[t]; memcpy(x->cost, dct, sizeof(double) * n); }
    }
    if (g < 0) return 0;
    for (int f = 0; f < n; f++) {
        if (l[f] == a) l[f] = x->ln[f];
        if (x->cost[f] < x->cur[f] || f == g) l[f] = a;
        if (x->cost[f] < x->cur[f]) x->cur[f] = x->cost[f];
    }
    memcpy(x->cost, x->cur, sizeof(double) * n);  /* fit costs, for re-seeding */
    return 1;
}

/* Block coordinate descent from one start, then the local search; the
 * result goes to *out. */
static void run_restart(const struct replib_data *D, const struct replib_opts *o, int rs,
                        struct work *w, struct lstate *s, struct scratch *x, struct restart *out)
{
    int n = D->n, d = o->d;
    double mu = o->lambda / 2;
    int *l = x->l;
    struct rng r;
    rng_seed(&r, o->seed ^ (0x9E3779B97F4A7C15ULL * (uint64_t)(rs + 1)));
    double ti = wall(), E;
    struct replib_iter it = {0};
    it.restart = rs;
    memset(x->cost, 0, sizeof(double) * n);
    if (rs == 0 && o->init_labels) {
        memcpy(l, o->init_labels, sizeof(int) * n);
        E = INFINITY;
    } else {
        int sr = o->start == REPLIB_START_PLUSPLUS ? seed_pieces(D, d, &r, s) : seed_greedy(D, w->team, d, !o->no_prune, &r, s);
        if (sr < 0 || compute_costs(D, s, mu, w) < 0) { out->rc = -1; return; }
        double tl = wall();
        E = label_step(w, o->method, l, 0);
        out->label_seconds += wall() - tl;
        if (isnan(E)) { out->rc = cm_seterr("replib: the energy is not a number (squared coordinate differences overflow: scale the input down, e.g. with mesh-normalize)"); return; }
        it.energy = E;
        chain_energy(&w->ch, l, &it.data, &it.velocity);
        it.changed = n;
        it.seconds = wall() - ti;
        keep_log(out, &it);
        for (int f = 0; f < n; f++) x->cost[f] = w->U[(size_t)f * d + l[f]];
    }
    /* with the search on, the first descent's label steps (after the
     * first) also run on the candidates: the exact descent at the end
     * makes the result a fixed point of the exact label step anyway */
    w->ncand = o->method == REPLIB_DP && mu > 0 && o->search > 0 ? REPLIB_TRIAL_CANDIDATES : 0;
    if (descend(D, o, w, s, x, &E, out, &it) < 0) { out->rc = -1; return; }
    /* w and s hold the library and costs that l was optimised for */
    out->labels = malloc(sizeof(int) * n);
    if (!out->labels || lstate_copy(&out->s, s) < 0) { out->rc = -1; return; }
    memcpy(out->labels, l, sizeof(int) * n);
    out->E = E;
    /* w holds the costs of s = out->s (descend ends on them) */
    if (o->search > 0 && best_costs(D, mu, w, 1) < 0) { out->rc = -1; return; }
    /* trials at lambda > 0 with the DP: label steps on a few candidates
     * per frame, then one exact descent from the best */
    w->ncand = o->method == REPLIB_DP && mu > 0 && o->search > 0 ? REPLIB_TRIAL_CANDIDATES : 0;
    for (int t = 0; t < o->search; t++) {
        memcpy(x->ln, l, sizeof(int) * n);
        int sm = split_merge(D, o, w, x, &r);
        if (sm < 0) { out->rc = cm_seterr("replib: out of memory"); return; }
        if (!sm) break;
        double En = INFINITY;
        if (descend(D, o, w, s, x, &En, out, &it) < 0) { out->rc = -1; return; }
        if (En < out->E - 1e-12 * fabs(out->E)) {
            out->E = En;
            memcpy(out->labels, l, sizeof(int) * n);
            if (lstate_copy(&out->s, s) < 0 || best_costs(D, mu, w, 1) < 0) { out->rc = -1; return; }
            out->accepted++;
        } else {
            memcpy(l, out->labels, sizeof(int) * n);
            if (lstate_copy(s, &out->s) < 0 || best_costs(D, mu, w, 0) < 0) { out->rc = -1; return; }
        }
    }
    if (w->ncand > 0) {
        w->ncand = 0;
        memcpy(l, out->labels, sizeof(int) * n);
        double En = out->E;
        if (lstate_copy(s, &out->s) < 0 || descend(D, o, w, s, x, &En, out, &it) < 0) { out->rc = -1; return; }
        if (En < out->E) {
            out->E = En;
            memcpy(out->labels, l, sizeof(int) * n);
            if (lstate_copy(&out->s, s) < 0 || best_costs(D, mu, w, 1) < 0) { out->rc = -1; return; }
        }
    }
    if (o->search > 0 && best_costs(D, mu, w, 0) < 0) { out->rc = -1; return; }
    ensure_uh(w);
    chain_energy(&w->ch, out->labels, &out->data, &out->velocity);
}

struct worker {
    const struct replib_data *D;
    const struct replib_opts *o;
    struct restart *out;
    int restarts;
    int *next;                  /* shared restart counter */
    pthread_mutex_t *lock;
    struct team *team;          /* shared by the workers (NULL with one) */
    int rc;
    char msg[512];              /* the worker's error (cm_errmsg is per thread) */
};

static void *worker_run(void *arg);

static void *worker_main(void *arg)
{
    struct worker *wk = arg;
    worker_run(arg);
    if (wk->rc) snprintf(wk->msg, sizeof wk->msg, "%s", cm_errmsg());
    return NULL;
}

static void *worker_run(void *arg)
{
    struct worker *wk = arg;
    const struct replib_data *D = wk->D;
    int n = D->n, d = wk->o->d;
    struct work w;
    struct lstate s;
    struct scratch x;
    if (scratch_init(&x, n, d) < 0) { wk->rc = -1; return NULL; }
    if (lstate_init(&s, d) < 0) { scratch_free(&x); wk->rc = -1; return NULL; }
    if (work_init(&w, D, d) < 0) { scratch_free(&x); lstate_free(&s); wk->rc = -1; return NULL; }
    w.team = wk->team;
    for (;;) {
        pthread_mutex_lock(wk->lock);
        int rs = (*wk->next)++;
        pthread_mutex_unlock(wk->lock);
        if (rs >= wk->restarts) break;
        run_restart(D, wk->o, rs, &w, &s, &x, &wk->out[rs]);
        if (wk->out[rs].rc) { wk->rc = -1; break; }
    }
    scratch_free(&x);
    lstate_free(&s);
    work_free(&w);
    return NULL;
}

/* worker_run, then (several workers) help the others until all are done */
static void *worker_team(void *arg)
{
    struct worker *wk = arg;
    worker_main(arg);
    if (wk->team) team_help(wk->team);
    return NULL;
}

/* The restarts on D; the best library goes to res->R, or with keep != NULL
 * its state (rows of D) to *keep and res->R stays NULL. */
static int learn_run(const struct replib_data *D, const struct replib_opts *o, struct replib_result *res,
                     struct lstate *keep)
{
    int n = D->n, d = o->d, m3 = D->m3;
    memset(res, 0, sizeof *res);
    if (d < 1) return cm_seterr("the library needs at least one piece (d = %d)", d);
    if (d < D->nfix) return cm_seterr("d = %d is less than the %d fixed pieces", d, D->nfix);
    if (d - D->nfix > n) return cm_seterr("d = %d pieces but only %d frames", d, n);
    if (!(o->lambda >= 0) || !isfinite(o->lambda)) return cm_seterr("lambda must be >= 0");
    if (D->swap_cost != 0) return cm_seterr("replib_learn: a swap cost is charged by replib_label only");
    if (o->init_labels)
        for (int f = 0; f < n; f++)
            if (o->init_labels[f] < 0 || o->init_labels[f] >= d)
                return cm_seterr("initial label %d of frame %d is not in [0, %d)", o->init_labels[f], f, d);
    double t0 = wall();
    int restarts = o->restarts < 1 ? 1 : o->restarts;
    int nth = o->threads;
    if (nth <= 0) {
        long c = sysconf(_SC_NPROCESSORS_ONLN);
        nth = c > 0 ? (int)c : 1;
    }
    if (nth > restarts) nth = restarts;
    if (nth > 16) nth = 16;
    struct restart *out = calloc(restarts, sizeof *out);
    res->labels = malloc(sizeof(int) * n);
    res->R = keep ? NULL : big_alloc(sizeof(double) * (size_t)d * m3);     /* written whole: no calloc */
    if (!out || !res->labels || (!keep && !res->R)) {
        free(out); replib_result_free(res);
        return cm_seterr("replib: out of memory");
    }
    int next = 0, rc = 0;
    pthread_mutex_t lock = PTHREAD_MUTEX_INITIALIZER;
    struct team team = {PTHREAD_MUTEX_INITIALIZER, PTHREAD_COND_INITIALIZER, PTHREAD_COND_INITIALIZER,
                        0, 0, nth, 0, 0, 0, 0, NULL, NULL};
    struct worker wk[16];
    pthread_t th[16];
    int started = 0;
    /* restarts run in parallel: BLAS single-threaded meanwhile (the per-
     * iteration products are small); results do not depend on the order */
    int blas_threads = openblas_get_num_threads();
    openblas_set_num_threads(1);
    dots_ok();                  /* their lazy answers, before the workers read them */
    kept_sums();
    for (int t = 0; t < nth; t++) {
        wk[t] = (struct worker){D, o, out, restarts, &next, &lock, nth > 1 ? &team : NULL, 0, {0}};
        if (t == nth - 1) {
            worker_team(&wk[t]);     /* the last one runs here, then helps */
        } else if (pthread_create(&th[t], NULL, worker_team, &wk[t]) != 0) {
            worker_main(&wk[t]);     /* a failed spawn: its share runs here, without helping */
            if (wk[t].team) team_leave(wk[t].team);
        } else {
            started |= 1 << t;
        }
    }
    for (int t = 0; t < nth; t++)
        if (started & (1 << t)) pthread_join(th[t], NULL);
    openblas_set_num_threads(blas_threads);
    for (int t = 0; t < nth; t++) if (wk[t].rc) rc = -1;
    int best = -1;
    for (int rs = 0; rs < restarts && !rc; rs++) {
        if (o->log)
            for (int k = 0; k < out[rs].nlog; k++) o->log(o->log_ctx, &out[rs].log[k]);
        res->iterations += out[rs].iterations;
        res->accepted += out[rs].accepted;
        res->label_seconds += out[rs].label_seconds;
        res->restarts++;
        if (best < 0 || out[rs].E < out[best].E) best = rs;
    }
    if (!rc) {
        res->d = d; res->n = n; res->m3 = m3;
        res->best_restart = best;
        res->helped = team.helped;
        res->energy = out[best].E; res->data = out[best].data; res->velocity = out[best].velocity;
        memcpy(res->labels, out[best].labels, sizeof(int) * n);
        if (keep ? lstate_copy(keep, &out[best].s) < 0 : library_out(D, &out[best].s, res->R, o->threads) < 0) rc = -1;
    } else {
        const char *why = "";
        for (int t = 0; t < nth && !*why; t++) if (wk[t].rc) why = wk[t].msg;
        cm_seterr("%s", *why ? why : "replib: out of memory in the block coordinate descent");
    }
    for (int rs = 0; rs < restarts; rs++) {
        free(out[rs].labels); free(out[rs].log);
        lstate_free(&out[rs].s);
    }
    free(out);
    if (rc) { replib_result_free(res); return -1; }
    res->seconds = wall() - t0;
    return 0;
}

/* Sampled learning (o->sample, replib.h): the restarts (start and search)
 * run on nb = sample / B blocks of B consecutive frames spread evenly over
 * the animation (block j starts at frame j n / nb; a block is a clip of
 * its own, the input's cuts inside it kept, so the velocity term sees
 * B - 1 of every B transitions); the best library, solved in the sample's
 * coordinates, labels all n frames (one exact label step: its costs are
 * one DGEMM n x zdim x d), and from those labels one restart on all frames
 * runs the descent and the search (o->search trials).  Direct back end
 * only (the sample's rows of Z are copied).  The iterations of both
 * stages are counted in res; res->sampled = nb B. */
static int learn_sampled(const struct replib_data *D, const struct replib_opts *o, struct replib_result *res)
{
    int n = D->n, d = o->d, nfix = D->nfix, zd = D->zdim, B = REPLIB_SAMPLE_BLOCK;
    int nb = o->sample / B > 0 ? o->sample / B : 1, m = nb * B;
    double t0 = wall(), mu = o->lambda / 2;
    memset(res, 0, sizeof *res);
    struct replib_data S = {0};
    S.n = m; S.nv = D->nv; S.nfix = nfix; S.N = m + nfix; S.m3 = D->m3; S.zdim = zd;
    S.lowrank = D->lowrank; S.step = D->step;
    int *idx = malloc(sizeof(int) * m), *l0 = malloc(sizeof(int) * n);
    S.link = calloc(m, 1);
    S.Z = big_alloc(sizeof(double) * (size_t)S.N * zd);
    S.zz = malloc(sizeof(double) * S.N);
    S.dd = calloc(m, sizeof(double));
    if (!idx || !l0 || !S.link || !S.Z || !S.zz || !S.dd) {
        free(idx); free(l0); replib_data_free(&S);
        return cm_seterr("replib: out of memory (a sample of %d frames)", m);
    }
    for (int j = 0; j < nb; j++) {
        int f0 = (int)((long long)j * n / nb);
        for (int i = 0; i < B; i++) idx[j * B + i] = f0 + i;
    }
    for (int i = 0; i < S.N; i++) {
        int g = i < m ? idx[i] : n + (i - m);
        memcpy(S.Z + (size_t)i * zd, D->Z + (size_t)g * zd, sizeof(double) * zd);
        S.zz[i] = D->zz[g];
    }
    for (int i = 0; i + 1 < m; i++)
        if ((i + 1) % B != 0 && D->link[idx[i]]) { S.link[i] = 1; S.dd[i] = D->dd[idx[i]]; }
    free(idx);
    struct replib_opts os = *o;
    os.sample = 0;
    struct replib_result rs;
    struct lstate ls = {0};
    int rc = learn_run(&S, &os, &rs, &ls);
    if (rc == 0) {
        /* all frames labelled with the sample's library */
        struct work w;
        rc = work_init(&w, D, d);
        if (rc == 0 && (rc = lstate_apply(&ls, S.Z, S.N, NULL, zd, w.Rw)) == 0) {
            direct_products(D, &w);
            derive_costs(D, mu, &w);
            if (isnan(label_step(&w, o->method, l0, 0)))
                rc = cm_seterr("replib: the energy is not a number (squared coordinate differences overflow: scale the input down, e.g. with mesh-normalize)");
        }
        if (w.P) work_free(&w);
    }
    lstate_free(&ls);
    replib_data_free(&S);
    if (rc == 0) {
        struct replib_opts of = *o;
        of.sample = 0; of.init_labels = l0; of.restarts = 1; of.search = o->search;
        rc = learn_run(D, &of, res, NULL);
    }
    free(l0);
    if (rc == 0) {
        res->restarts = rs.restarts;
        res->best_restart = rs.best_restart;
        res->iterations += rs.iterations;
        res->accepted += rs.accepted;
        res->helped += rs.helped;
        res->label_seconds += rs.label_seconds;
        res->sampled = m;
        res->sample_energy = rs.energy;
        res->seconds = wall() - t0;
    }
    replib_result_free(&rs);
    return rc;
}

int replib_learn(const struct replib_data *D, const struct replib_opts *o, struct replib_result *res)
{
    /* sampled when the sample is smaller and its rows are few enough to copy */
    int m = o->sample > 0 ? (o->sample / REPLIB_SAMPLE_BLOCK > 0 ? o->sample / REPLIB_SAMPLE_BLOCK : 1) * REPLIB_SAMPLE_BLOCK : 0;
    if (m > 0 && D->n > m && D->n > o->sample && !D->K && D->Z && !o->init_labels && o->d - D->nfix <= m &&
        (double)(m + D->nfix) * D->zdim * sizeof(double) <= REPLIB_SAMPLE_MAX_BYTES)
        return learn_sampled(D, o, res);
    return learn_run(D, o, res, NULL);
}

void replib_result_free(struct replib_result *res)
{
    free(res->labels); free(res->R);
    res->labels = NULL; res->R = NULL;
}

double replib_label(const struct replib_data *D, double lambda, enum replib_method method,
                    int *l, double *data, double *velocity)
{
    return replib_label_timed(D, lambda, method, l, data, velocity, NULL);
}

double replib_label_timed(const struct replib_data *D, double lambda, enum replib_method method,
                          int *l, double *data, double *velocity, double *label_seconds)
{
    int d = D->nfix;
    if (d < 1) { cm_seterr("replib_label: empty library"); return NAN; }
    struct lstate s;
    struct work w;
    if (lstate_init(&s, d) < 0) return NAN;
    if (work_init(&w, D, d) < 0) { lstate_free(&s); return NAN; }
    for (int a = 0; a < d; a++) s.src[a] = D->n + a;
    double E = NAN;
    if (compute_costs(D, &s, lambda / 2, &w) == 0) {
        double t = wall();
        E = label_step(&w, method, l, 0);
        if (label_seconds) *label_seconds = wall() - t;
        if (!isnan(E)) chain_energy(&w.ch, l, data, velocity);
    }
    lstate_free(&s);
    work_free(&w);
    return E;
}

/* The report's two halves, each summed in frame and vertex order: job 0
 * the data term and errors, job 1 the velocity term (they run on two
 * threads; every sum has one fixed order, so the numbers do not depend
 * on it). */
struct eval_job {
    const double *X, *xbase, *ref, *R, *w;
    const float *Xf;
    const int32_t *Xi;
    const mapped_double *const *Xm;
    int keep;                           /* Xm's pages stay mapped once read */
    double q;
    int n, nv, oom;
    const int *l;
    const unsigned char *cut;
    double *frame_err;
    struct eval_part {                  /* the sums of each half */
        double data, se, me, vel, sv, mv;
        long nvel;
        int worst;
    } part[2];
};

/* frame f of the kept 32-bit frames in double (b + kept q, or b + kept;
 * element-wise, vectorized); xm: the integers read where the frame lies
 * (as kept_axpy) */
__attribute__((optimize("O3"), target_clones("avx512f", "avx2", "default")))
static void kept_frame(const double *restrict b, const int32_t *restrict xi, const mapped_double *restrict xm,
                       const float *restrict xf, double q, size_t m3, double *restrict out)
{
    double iq = q > 0 ? 1 / q : 0;
    if (xi) for (size_t k = 0; k < m3; k++) out[k] = b[k] + xi[k] * q;
    else if (xm) for (size_t k = 0; k < m3; k++) out[k] = b[k] + replib_kept_int(xm[k], b[k], iq) * q;
    else for (size_t k = 0; k < m3; k++) out[k] = b[k] + xf[k];
}

/* Job j of two: the frames [f0, f1) of its half, each read (decoded)
 * once: its data term, and the velocity term of each step f -> f + 1
 * from it (the first frame of the other half is read again for the
 * last step).  The sums of a half run in frame order; the halves are
 * fixed by n, not by the threads. */
static void eval_half(void *ctx, int job)
{
    struct eval_job *j = ctx;
    const double *X = j->X, *xbase = j->xbase, *ref = j->ref, *R = j->R, *w = j->w;
    const float *Xf = j->Xf;
    const int32_t *Xi = j->Xi;
    const mapped_double *const *Xm = j->Xm;
    double q = j->q;
    int n = j->n, nv = j->nv;
    int f0 = job == 0 ? 0 : n / 2, f1 = job == 0 ? n / 2 : n;
    const int *l = j->l;
    const unsigned char *cut = j->cut;
    size_t m3 = 3 * (size_t)nv;
    double data = 0, vel = 0, se = 0, sv = 0, me = 0, mv = 0;
    long nvel = 0;
    int worst = f0;
    double *xb = NULL, *xcur = NULL, *xnext = NULL;   /* frames f and f + 1 in double */
    if (f0 >= f1) { j->part[job] = (struct eval_part){0}; return; }
#define KEPT(f, out) kept_frame(xbase ? xbase + (size_t)((f) / REPLIB_KEEP_CHUNK) * m3 : ref, \
                                Xi ? Xi + (size_t)(f) * m3 : NULL, Xm ? Xm[f] : NULL, \
                                Xi || Xm ? NULL : Xf + (size_t)(f) * m3, q, m3, out)
    /* read where they lie: their pages go, 32 frames at a time (one call,
     * one TLB flush, instead of one per frame) */
    int rel = f0;
#define RELEASE(f) do { if (Xm && !j->keep && ((f) + 1 - rel == 32 || (f) + 1 == f1)) { \
        mapped_release((const void *)Xm[rel], (const void *)(Xm[f] + m3)); rel = (f) + 1; } } while (0)
    if (!X) {
        xb = malloc(sizeof(double) * 2 * m3);
        if (!xb) { j->oom = 1; return; }
        xcur = xb; xnext = xb + m3;
        KEPT(f0, xcur);
    }
    for (int f = f0; f < f1; f++) {
        int step = f + 1 < n && !(cut && cut[f + 1]);
        if (xb && step) KEPT(f + 1, xnext);
        const double *x = xb ? xcur : X + f * m3, *r = R + l[f] * m3;
        double fm = 0;
        for (int i = 0; i < nv; i++) {
            double dx = x[3 * i] - r[3 * i], dy = x[3 * i + 1] - r[3 * i + 1], dz = x[3 * i + 2] - r[3 * i + 2];
            double e2 = dx * dx + dy * dy + dz * dz, e = sqrt(e2);
            data += (w ? w[i] : 1) * e2;
            se += e;
            if (e > fm) fm = e;
        }
        if (j->frame_err) j->frame_err[f] = fm;
        if (fm > me) { me = fm; worst = f; }
        if (step) {
            const double *x1 = xb ? xnext : x + m3, *r1 = R + l[f + 1] * m3;
            for (size_t k = 0; k < m3; k += 3) {
                double e2 = 0;
                for (int c = 0; c < 3; c++) {
                    double v = (x1[k + c] - x[k + c]) - (r1[k + c] - r[k + c]);
                    e2 += v * v;
                }
                double e = sqrt(e2);
                vel += (w ? w[k / 3] : 1) * e2;
                sv += e;
                if (e > mv) mv = e;
            }
            nvel++;
        }
        RELEASE(f);
        if (xb) {
            /* frame f + 1 is in xnext: the two swap roles (a cut: read it now) */
            double *t = xcur; xcur = xnext; xnext = t;
            if (!step && f + 1 < f1) KEPT(f + 1, xcur);
        }
    }
#undef KEPT
#undef RELEASE
    j->part[job] = (struct eval_part){data, se, me, vel, sv, mv, nvel, worst};
    free(xb);
}

static void evaluate(const double *X, const float *Xf, const int32_t *Xi, const mapped_double *const *Xm, int keep, double q,
                     const double *xbase, const double *ref, int n, int nv, const double *R,
                     const int *l, const double *w, const unsigned char *cut, double lambda,
                     struct replib_report *rep, double *frame_err)
{
    struct eval_job j = {0};
    j.X = X; j.xbase = xbase; j.ref = ref; j.R = R; j.w = w; j.Xf = Xf; j.Xi = Xi; j.Xm = Xm; j.keep = keep; j.q = q;
    j.n = n; j.nv = nv; j.l = l; j.cut = cut; j.frame_err = frame_err;
    parallel_run(2, 2, eval_half, &j);
    if (j.oom) { memset(rep, 0, sizeof *rep); rep->energy = NAN; return; }
    const struct eval_part *a = &j.part[0], *b = &j.part[1];
    long nvel = a->nvel + b->nvel;
    rep->data = a->data + b->data;
    rep->velocity = a->vel + b->vel;
    rep->energy = rep->data + lambda / 2 * rep->velocity;
    rep->mean_err = (a->se + b->se) / ((double)n * nv);
    rep->max_err = b->me > a->me ? b->me : a->me;             /* the first worst frame */
    rep->worst_frame = b->me > a->me ? b->worst : a->worst;
    rep->mean_verr = nvel ? (a->sv + b->sv) / ((double)nvel * nv) : 0;
    rep->max_verr = b->mv > a->mv ? b->mv : a->mv;
}

void replib_evaluate(const double *X, int n, int nv, const double *R, int d, const int *l,
                     const double *w, const unsigned char *cut, double lambda,
                     struct replib_report *rep, double *frame_err)
{
    (void)d;
    evaluate(X, NULL, NULL, NULL, 0, 0, NULL, NULL, n, nv, R, l, w, cut, lambda, rep, frame_err);
}

void replib_evaluate_f(const float *Xf, const double *xbase, const double *ref, int n, int nv, const double *R, int d,
                       const int *l, const double *w, const unsigned char *cut, double lambda,
                       struct replib_report *rep, double *frame_err)
{
    (void)d;
    evaluate(NULL, Xf, NULL, NULL, 0, 0, xbase, ref, n, nv, R, l, w, cut, lambda, rep, frame_err);
}

void replib_evaluate_i(const int32_t *Xi, double q, const double *xbase, const double *ref, int n, int nv, const double *R, int d,
                       const int *l, const double *w, const unsigned char *cut, double lambda,
                       struct replib_report *rep, double *frame_err)
{
    (void)d;
    evaluate(NULL, NULL, Xi, NULL, 0, q, xbase, ref, n, nv, R, l, w, cut, lambda, rep, frame_err);
}

void replib_evaluate_m(const mapped_double *const *Xm, int keep, double q, const double *xbase, const double *ref,
                       int n, int nv, const double *R, int d, const int *l, const double *w, const unsigned char *cut,
                       double lambda, struct replib_report *rep, double *frame_err)
{
    (void)d;
    evaluate(NULL, NULL, NULL, Xm, keep, q, xbase, ref, n, nv, R, l, w, cut, lambda, rep, frame_err);
}
