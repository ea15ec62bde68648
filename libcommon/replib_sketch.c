/* replib_sketch.c -- one-pass low-rank sketch of an animation (see replib_sketch.h). */
#include "replib_sketch.h"
#include "big_alloc.h"
#include "cm_error.h"
#include "rng.h"
#include <cblas.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <pthread.h>
#include <immintrin.h>
#include <sys/mman.h>
#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23      /* Linux 5.14 */
#endif

extern void dgeqrf_(const int *m, const int *n, double *a, const int *lda, double *tau, double *work,
                    const int *lwork, int *info);
extern void dorgqr_(const int *m, const int *n, const int *k, double *a, const int *lda, const double *tau,
                    double *work, const int *lwork, int *info);
extern void dsyev_(const char *jobz, const char *uplo, const int *n, double *a, const int *lda, double *w,
                   double *work, const int *lwork, int *info);
extern void dgels_(const char *trans, const int *m, const int *n, const int *nrhs, double *a, const int *lda,
                   double *b, const int *ldb, double *work, const int *lwork, int *info);

#define BATCH 128         /* frames per co-range update (W is read and written once per batch);
                             two batch buffers: one filled while the other is summed */
#define STRIP 256         /* columns of W per cache block */
#define TILE 256          /* coordinates of the batch transposed at a time */

static void keeper_stop(struct replib_sketch *S);
static int flush_wait(struct replib_sketch *S);
static void keeper_start(struct replib_sketch *S);

void replib_sketch_free(struct replib_sketch *S)
{
    keeper_stop(S);
    flush_wait(S);
    free(S->ref); free(S->sw); free(S->om); free(S->Y); free(S->W);
    free(S->cut); free(S->Xk); free(S->xbase); free(S->kb); free(S->zb); free(S->zprev); free(S->V);
    free(S->zt); free(S->yt); free(S->xp);
    memset(S, 0, sizeof *S);
}

/* zeta distinct values in [0, m), each with a random sign: out[i] =
 * 2 index + (sign < 0) */
static void sparse_signs(struct rng *g, int m, int zeta, int *out)
{
    for (int i = 0; i < zeta; i++) {
        int j, dup;
        do {
            j = rng_int(g, m);
            dup = 0;
            for (int t = 0; t < i; t++) dup |= out[t] >> 1 == j;
        } while (dup);
        out[i] = 2 * j + (rng_uniform(g) < 0.5);
    }
}

int replib_sketch_init(struct replib_sketch *S, int nv, int k, const double *w, size_t keep_bytes,
                       uint64_t seed)
{
    memset(S, 0, sizeof *S);
    if (nv < 1 || k < 1) return cm_seterr("replib_sketch: %d vertices, rank %d", nv, k);
    int m3 = S->m3 = 3 * nv;
    S->nv = nv; S->k = k; S->s = 2 * k + 1; S->seed = seed;
    S->zeta = k < REPLIB_SKETCH_ZETA ? k : REPLIB_SKETCH_ZETA;
    S->zpsi = S->s < REPLIB_SKETCH_ZETA ? S->s : REPLIB_SKETCH_ZETA;
    S->keep_bytes = keep_bytes; S->keeping = keep_bytes > 0;
    S->ref = malloc(sizeof(double) * m3);
    S->om = malloc(sizeof(int) * (size_t)m3 * S->zeta);
    S->W = big_calloc(sizeof(double) * (size_t)S->s * m3);
    S->zb = big_alloc(sizeof(double) * 2 * (size_t)BATCH * m3);
    S->zt = malloc(sizeof(double) * (size_t)BATCH * TILE);
    S->yt = malloc(sizeof(double) * (size_t)BATCH * k);
    S->zprev = malloc(sizeof(double) * 3 * (size_t)m3);     /* keep_chunk's scratch */
    if (!S->ref || !S->om || !S->W || !S->zb || !S->zt || !S->yt || !S->zprev) goto oom;
    if (S->keeping && !(S->kb = malloc(sizeof(double) * 2 * (size_t)REPLIB_KEEP_CHUNK * m3))) goto oom;
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
    for (int t = 0; t < m3; t++) sparse_signs(&g, k, S->zeta, S->om + (size_t)t * S->zeta);
    if (S->keeping) keeper_start(S);
    return 0;
oom:
    replib_sketch_free(S);
    return cm_seterr("replib_sketch: out of memory (%d vertices, rank %d)", nv, k);
}

/* column f of Psi: zpsi rows with signs (sparse_signs' encoding) */
static void psi_col(const struct replib_sketch *S, int f, int *p)
{
    struct rng g;
    rng_seed(&g, S->seed * 0x9E3779B97F4A7C15ULL + 0x5107c4ULL + (uint64_t)f);
    sparse_signs(&g, S->s, S->zpsi, p);
}

/* y += sg x (n values, sg = +-1: exact products, so the same roundings
 * as BLAS daxpy; no branch on the sign), vectorized */
#define SKETCH_SIMD __attribute__((optimize("O3"), target_clones("avx512f", "avx2", "default")))
static inline void vadd(double *restrict y, const double *restrict x, int n, double sg)
{
    for (int i = 0; i < n; i++) y[i] += sg * x[i];
}

/* y = (y + s0 x0) + s1 x1, and the same with four: one load and store of
 * y, the roundings of vadd one frame after the other */
static inline void vadd2(double *restrict y, const double *restrict x0, const double *restrict x1, int n,
                         double s0, double s1)
{
    for (int i = 0; i < n; i++) y[i] = (y[i] + s0 * x0[i]) + s1 * x1[i];
}

static inline void vadd4(double *restrict y, const double *restrict x0, const double *restrict x1,
                         const double *restrict x2, const double *restrict x3, int n,
                         double s0, double s1, double s2, double s3)
{
    for (int i = 0; i < n; i++) y[i] = (((y[i] + s0 * x0[i]) + s1 * x1[i]) + s2 * x2[i]) + s3 * x3[i];
}

/* The same three with the frames read where they lie: z = x - r, or
 * sw (x - r) with weights (sw not NULL), formed as center_row forms it, so
 * the same sums as on the stored rows */
#define ZX(x, i) (sw ? sw[i] * ((x)[i] - r[i]) : (x)[i] - r[i])
static inline void vaddx(double *restrict y, const mapped_double *restrict x0, const double *restrict r,
                         const double *restrict sw, int n, double sg)
{
    for (int i = 0; i < n; i++) y[i] += sg * ZX(x0, i);
}

static inline void vadd2x(double *restrict y, const mapped_double *restrict x0, const mapped_double *restrict x1,
                          const double *restrict r, const double *restrict sw, int n, double s0, double s1)
{
    for (int i = 0; i < n; i++) y[i] = (y[i] + s0 * ZX(x0, i)) + s1 * ZX(x1, i);
}

static inline void vadd4x(double *restrict y, const mapped_double *restrict x0, const mapped_double *restrict x1,
                          const mapped_double *restrict x2, const mapped_double *restrict x3,
                          const double *restrict r, const double *restrict sw, int n,
                          double s0, double s1, double s2, double s3)
{
    for (int i = 0; i < n; i++)
        y[i] = (((y[i] + s0 * ZX(x0, i)) + s1 * ZX(x1, i)) + s2 * ZX(x2, i)) + s3 * ZX(x3, i);
}

/* W += Psi_b Z_b for the batch, by strips of columns: each row of W takes
 * its frames of the batch in order (pl: the frames of row i are
 * pl[po[i] .. po[i+1]-1], 2 frame + (sign < 0)), so every value of W sums
 * its frames in frame order whatever the batching, and the row's strip
 * stays in L1 while the batch's strip is in L2 */
struct wjob { struct replib_sketch *S; const double *zb; const mapped_double *const *xs; const int *po, *pl; int nb; };

/* the same, the batch's frames read where they lie (xs: nb pointers) */
SKETCH_SIMD
static void w_update_strips_x(struct wjob *j)
{
    struct replib_sketch *S = j->S;
    int m3 = S->m3, s = S->s;
    const mapped_double *const *xs = j->xs;
    for (int t0 = 0; t0 < m3; t0 += STRIP) {
        int len = m3 - t0 < STRIP ? m3 - t0 : STRIP;
        const double *r = S->ref + t0, *sw = S->sw ? S->sw + t0 : NULL;
        for (int i = 0; i < s; i++) {
            double *w = S->W + (size_t)i * m3 + t0;
            int q = j->po[i], q1 = j->po[i + 1];
            for (; q + 4 <= q1; q += 4) {
                const int *e = j->pl + q;
                vadd4x(w, xs[e[0] >> 1] + t0, xs[e[1] >> 1] + t0, xs[e[2] >> 1] + t0, xs[e[3] >> 1] + t0, r, sw, len,
                       e[0] & 1 ? -1.0 : 1.0, e[1] & 1 ? -1.0 : 1.0, e[2] & 1 ? -1.0 : 1.0, e[3] & 1 ? -1.0 : 1.0);
            }
            for (; q + 2 <= q1; q += 2) {
                const int *e = j->pl + q;
                vadd2x(w, xs[e[0] >> 1] + t0, xs[e[1] >> 1] + t0, r, sw, len, e[0] & 1 ? -1.0 : 1.0, e[1] & 1 ? -1.0 : 1.0);
            }
            for (; q < q1; q++) {
                int e = j->pl[q];
                vaddx(w, xs[e >> 1] + t0, r, sw, len, e & 1 ? -1.0 : 1.0);
            }
        }
    }
}

SKETCH_SIMD
static void w_update_strips(struct wjob *j)
{
    struct replib_sketch *S = j->S;
    int m3 = S->m3, s = S->s;
    if (j->xs) { w_update_strips_x(j); return; }
    for (int t0 = 0; t0 < m3; t0 += STRIP) {
        int len = m3 - t0 < STRIP ? m3 - t0 : STRIP;
        for (int i = 0; i < s; i++) {
            double *w = S->W + (size_t)i * m3 + t0;
            int q = j->po[i], q1 = j->po[i + 1];
            /* four frames per pass over the row's strip: w is loaded and
             * stored once for them, the additions in the same order */
            for (; q + 4 <= q1; q += 4) {
                const int *e = j->pl + q;
                vadd4(w, j->zb + (size_t)(e[0] >> 1) * m3 + t0, j->zb + (size_t)(e[1] >> 1) * m3 + t0,
                      j->zb + (size_t)(e[2] >> 1) * m3 + t0, j->zb + (size_t)(e[3] >> 1) * m3 + t0, len,
                      e[0] & 1 ? -1.0 : 1.0, e[1] & 1 ? -1.0 : 1.0, e[2] & 1 ? -1.0 : 1.0, e[3] & 1 ? -1.0 : 1.0);
            }
            for (; q + 2 <= q1; q += 2) {
                const int *e = j->pl + q;
                vadd2(w, j->zb + (size_t)(e[0] >> 1) * m3 + t0, j->zb + (size_t)(e[1] >> 1) * m3 + t0, len,
                      e[0] & 1 ? -1.0 : 1.0, e[1] & 1 ? -1.0 : 1.0);
            }
            for (; q < q1; q++) {
                int e = j->pl[q];
                vadd(w, j->zb + (size_t)(e >> 1) * m3 + t0, len, e & 1 ? -1.0 : 1.0);
            }
        }
    }
}

static void *w_update(void *arg)
{
    w_update_strips(arg);
    return NULL;
}

/* Y^T for coordinates t0 .. t1-1 of the batch (zt: those coordinates
 * transposed, (t1 - t0) by nb): the nonzeros of Omega in these rows
 * grouped by column j (counting sort, t increasing within j), then row j
 * of yt takes them in t order while it stays in L1 (the same sums in the
 * same order as one nonzero at a time) */
SKETCH_SIMD
static void y_tile(const struct replib_sketch *S, const double *zt, int t0, int t1, int nb, double *yt,
                   int *cnt, int *list)
{
    int k = S->k, zeta = S->zeta;
    memset(cnt, 0, sizeof(int) * (k + 1));
    for (int t = t0; t < t1; t++)
        for (int i = 0; i < zeta; i++) cnt[(S->om[(size_t)t * zeta + i] >> 1) + 1]++;
    for (int j = 0; j < k; j++) cnt[j + 1] += cnt[j];
    for (int t = t0; t < t1; t++)
        for (int i = 0; i < zeta; i++) {
            int o = S->om[(size_t)t * zeta + i];
            list[cnt[o >> 1]++] = 2 * (t - t0) + (o & 1);
        }
    /* cnt[j] is now the end of column j's entries */
    for (int j = 0, q = 0; j < k; j++) {
        double *y = yt + (size_t)j * nb;
        for (; q < cnt[j]; q++) vadd(y, zt + (size_t)(list[q] >> 1) * nb, nb, list[q] & 1 ? -1.0 : 1.0);
    }
}

/* y_lanes where the CPU has AVX-512 and STOPMO_SKETCH_LANES is not 0
 * (0: the transposed tiles, as on other CPUs; the same bytes either way,
 * which t0305 checks) */
static int sketch_lanes(void)
{
    const char *e = getenv("STOPMO_SKETCH_LANES");
    return __builtin_cpu_supports("avx512f") && !(e && !strcmp(e, "0"));
}

/* the 32 lanes z0..z3 (coordinate t of 32 frames) added into Y's 32
 * transposed rows (yt: k by 32) with the signs of row t of Omega (om:
 * zeta nonzeros, 2 column + (sign < 0)) */
__attribute__((target("avx512f")))
static inline void lanes_add(double *yt, const int *om, int zeta, __m512d z0, __m512d z1, __m512d z2,
                             __m512d z3)
{
    const __m512d one = _mm512_set1_pd(1.0), mone = _mm512_set1_pd(-1.0);
    for (int i = 0; i < zeta; i++) {
        double *y = yt + (size_t)(om[i] >> 1) * 32;
        __m512d sg = om[i] & 1 ? mone : one;
        _mm512_storeu_pd(y, _mm512_add_pd(_mm512_loadu_pd(y), _mm512_mul_pd(sg, z0)));
        _mm512_storeu_pd(y + 8, _mm512_add_pd(_mm512_loadu_pd(y + 8), _mm512_mul_pd(sg, z1)));
        _mm512_storeu_pd(y + 16, _mm512_add_pd(_mm512_loadu_pd(y + 16), _mm512_mul_pd(sg, z2)));
        _mm512_storeu_pd(y + 24, _mm512_add_pd(_mm512_loadu_pd(y + 24), _mm512_mul_pd(sg, z3)));
    }
}

/* the transposed rows yt of frames f0 + b0 .. (at most 32, fewer at the
 * batch's end: nb) into Y */
static void lanes_store(struct replib_sketch *S, const double *yt, int nb, int f0, int b0)
{
    int k = S->k;
    for (int c = 0; c < 32 && b0 + c < nb; c++)
        for (int j = 0; j < k; j++) S->Y[(size_t)(f0 + b0 + c) * k + j] = yt[(size_t)j * 32 + c];
}

/* Y_b = Z_b Omega with AVX-512, without transposing the batch: 32 frames
 * in the lanes of four vectors (coordinate t gathered from their 32 rows,
 * each row read once, front to back), and coordinate t's zeta nonzeros of
 * Omega added to their columns of Y in t order: y += sg z, the same
 * operations in the same order as y_tile on the transposed batch, so the
 * same Y.  perf on Monkey (-r 1 -i 1): 222-236 samples against 366-405
 * for the transposition and y_tile (8 frames per pass: 540-636, the
 * per-nonzero overhead not amortized).  yt: 32 k scratch. */
__attribute__((target("avx512f")))
static void y_lanes(struct replib_sketch *S, const double *zb, int nb, int f0, double *yt)
{
    int m3 = S->m3, k = S->k, zeta = S->zeta;
    for (int b0 = 0; b0 < nb; b0 += 32) {
        int idx[32];
        for (int c = 0; c < 32; c++) idx[c] = (b0 + c < nb ? b0 + c : b0) * m3;     /* spare lanes: a copy */
        __m256i v0 = _mm256_loadu_si256((const __m256i *)idx), v1 = _mm256_loadu_si256((const __m256i *)(idx + 8));
        __m256i v2 = _mm256_loadu_si256((const __m256i *)(idx + 16)), v3 = _mm256_loadu_si256((const __m256i *)(idx + 24));
        memset(yt, 0, sizeof(double) * 32 * (size_t)k);
        const int *om = S->om;
        for (int t = 0; t < m3; t++, om += zeta) {
            __m512d z0 = _mm512_i32gather_pd(v0, zb + t, 8), z1 = _mm512_i32gather_pd(v1, zb + t, 8);
            __m512d z2 = _mm512_i32gather_pd(v2, zb + t, 8), z3 = _mm512_i32gather_pd(v3, zb + t, 8);
            lanes_add(yt, om, zeta, z0, z1, z2, z3);
        }
        lanes_store(S, yt, nb, f0, b0);
    }
}

/* y_lanes on frames read where they lie (xs: nb pointers into one mapping,
 * each less than 2^31 bytes past xs[0]): coordinate t of the 32 frames
 * gathered by byte offsets, then z = x - ref (times sw with weights), the
 * operations of center_row, so the same Y. */
__attribute__((target("avx512f")))
static void y_lanes_x(struct replib_sketch *S, const mapped_double *const *xs, int nb, int f0, double *yt)
{
    int m3 = S->m3, k = S->k, zeta = S->zeta;
    const double *ref = S->ref, *sw = S->sw;
    for (int b0 = 0; b0 < nb; b0 += 32) {
        int idx[32];
        const char *x0 = (const char *)(const void *)xs[b0];
        for (int c = 0; c < 32; c++)        /* spare lanes: a copy */
            idx[c] = b0 + c < nb ? (int)((const char *)(const void *)xs[b0 + c] - x0) : 0;
        __m256i v0 = _mm256_loadu_si256((const __m256i *)idx), v1 = _mm256_loadu_si256((const __m256i *)(idx + 8));
        __m256i v2 = _mm256_loadu_si256((const __m256i *)(idx + 16)), v3 = _mm256_loadu_si256((const __m256i *)(idx + 24));
        memset(yt, 0, sizeof(double) * 32 * (size_t)k);
        const int *om = S->om;
        for (int t = 0; t < m3; t++, om += zeta) {
            const char *xt = x0 + 8 * (size_t)t;
            __m512d r = _mm512_set1_pd(ref[t]);
            __m512d z0 = _mm512_sub_pd(_mm512_i32gather_pd(v0, xt, 1), r), z1 = _mm512_sub_pd(_mm512_i32gather_pd(v1, xt, 1), r);
            __m512d z2 = _mm512_sub_pd(_mm512_i32gather_pd(v2, xt, 1), r), z3 = _mm512_sub_pd(_mm512_i32gather_pd(v3, xt, 1), r);
            if (sw) {
                __m512d w = _mm512_set1_pd(sw[t]);
                z0 = _mm512_mul_pd(w, z0); z1 = _mm512_mul_pd(w, z1); z2 = _mm512_mul_pd(w, z2); z3 = _mm512_mul_pd(w, z3);
            }
            lanes_add(yt, om, zeta, z0, z1, z2, z3);
        }
        lanes_store(S, yt, nb, f0, b0);
    }
}

/* The batch zb (nb frames from f0) into the sketches: Y_b = Z_b Omega
 * (on the batch transposed by tiles) here, and W += Psi_b Z_b on a second
 * thread meanwhile (they write disjoint arrays; each is summed in a fixed
 * order: the bytes do not depend on the threads). */
static int flush_batch(struct replib_sketch *S, const double *zb, const mapped_double *const *xs, int nb, int f0)
{
    int m3 = S->m3, k = S->k, zp = S->zpsi, s = S->s;
    if (nb == 0) return 0;
    int *pc = malloc(sizeof(int) * (size_t)nb * zp), *po = calloc(s + 1, sizeof(int));
    int *pl = malloc(sizeof(int) * (size_t)nb * zp);
    int *cnt = malloc(sizeof(int) * (k + 1)), *list = malloc(sizeof(int) * (size_t)TILE * S->zeta);
    if (!pc || !po || !pl || !cnt || !list) {
        free(pc); free(po); free(pl); free(cnt); free(list);
        return cm_seterr("replib_sketch: out of memory");
    }
    for (int b = 0; b < nb; b++) psi_col(S, f0 + b, pc + (size_t)b * zp);
    /* the batch's frames of each row of W, in frame order */
    for (int q = 0; q < nb * zp; q++) po[(pc[q] >> 1) + 1]++;
    for (int i = 0; i < s; i++) po[i + 1] += po[i];
    for (int b = 0; b < nb; b++)
        for (int i = 0; i < zp; i++) {
            int e = pc[(size_t)b * zp + i];
            pl[po[e >> 1]++] = 2 * b + (e & 1);
        }
    for (int i = s; i > 0; i--) po[i] = po[i - 1];
    po[0] = 0;
    struct wjob job = {S, zb, xs, po, pl, nb};
    pthread_t th;
    int threaded = pthread_create(&th, NULL, w_update, &job) == 0;
    if (!threaded) w_update(&job);
    double *zt = S->zt, *yt = S->yt;
    if (sketch_lanes() && (xs ? (uintptr_t)(const void *)xs[nb - 1] - (uintptr_t)(const void *)xs[0] <= 2147483647u - 8 * (size_t)m3
                              : (size_t)BATCH * m3 <= 2147483647)) {
        if (xs) y_lanes_x(S, xs, nb, f0, yt);
        else y_lanes(S, zb, nb, f0, yt);
        if (threaded) pthread_join(th, NULL);
        free(pc); free(po); free(pl); free(cnt); free(list);
        return 0;
    }
    memset(yt, 0, sizeof(double) * (size_t)k * nb);
    for (int t0 = 0; t0 < m3; t0 += TILE) {
        /* coordinates t0 .. t1-1 of the batch, transposed (TILE by nb) */
        int t1 = t0 + TILE < m3 ? t0 + TILE : m3;
        for (int u0 = t0; u0 < t1; u0 += 16)
            for (int b0 = 0; b0 < nb; b0 += 16) {
                int u1 = u0 + 16 < t1 ? u0 + 16 : t1, b1 = b0 + 16 < nb ? b0 + 16 : nb;
                for (int t = u0; t < u1; t++)
                    for (int b = b0; b < b1; b++) {
                        const double *r = S->ref, *sw = S->sw;
                        zt[(size_t)(t - t0) * nb + b] = xs ? ZX(xs[b], t) : zb[(size_t)b * m3 + t];
                    }
            }
        y_tile(S, zt, t0, t1, nb, yt, cnt, list);
    }
    for (int b = 0; b < nb; b++)
        for (int j = 0; j < k; j++) S->Y[(size_t)(f0 + b) * k + j] = yt[(size_t)j * nb + b];
    if (threaded) pthread_join(th, NULL);
    free(pc); free(po); free(pl); free(cnt); free(list);
    return 0;
}

/* The batches are summed on a helper thread while the caller fills the
 * other half of zb; at most one is pending.  The caller waits for it
 * (flush_wait) before Y moves (grow), at the end, and before the next. */
struct flusher {
    struct replib_sketch *S;
    const double *zb;
    const mapped_double *const *xs;
    int nb, f0, rc;
    char msg[512];
    pthread_t th;
};

static void *flusher_main(void *arg)
{
    struct flusher *F = arg;
    F->rc = flush_batch(F->S, F->zb, F->xs, F->nb, F->f0);
    if (F->rc < 0) snprintf(F->msg, sizeof F->msg, "%s", cm_errmsg());
    return NULL;
}

static int flush_wait(struct replib_sketch *S)
{
    struct flusher *F = S->flusher;
    if (!F) return 0;
    pthread_join(F->th, NULL);
    int rc = F->rc;
    if (rc < 0) cm_seterr("%s", F->msg);
    free(F);
    S->flusher = NULL;
    return rc;
}

/* hand the buffered batch over (summed on the helper, or here if there is
 * none) and start filling the other half of zb */
static int flush(struct replib_sketch *S)
{
    int nb = S->nb, f0 = S->n - nb;
    if (nb == 0) return 0;
    if (flush_wait(S) < 0) return -1;
    const double *zb = S->zb + (size_t)S->zhalf * BATCH * S->m3;
    const mapped_double *const *xs = S->inplace ? S->xp + f0 : NULL;
    S->zhalf ^= 1;
    S->nb = 0;
    struct flusher *F = calloc(1, sizeof *F);
    if (F) {
        F->S = S; F->zb = zb; F->xs = xs; F->nb = nb; F->f0 = f0;
        if (pthread_create(&F->th, NULL, flusher_main, F) == 0) { S->flusher = F; return 0; }
        free(F);
    }
    return flush_batch(S, zb, xs, nb, f0);
}

/* The per-frame arrays, for the frames announced (S->expect) at once, then
 * doubled: first allocated on huge pages (big_alloc), moved by realloc
 * only past the announced count (each 4 KB page faulted in costs 10-12 us
 * on this paravirtualized guest; the Monkey's bases are 10 MB) */
static void *grow_array(void *p, size_t bytes)
{
    return p ? realloc(p, bytes) : big_alloc(bytes);
}

static int grow(struct replib_sketch *S)
{
    int nc = S->cap ? 2 * S->cap : S->expect > 0 ? S->expect : 1024;
    double *Y = grow_array(S->Y, sizeof(double) * (size_t)nc * S->k);
    if (!Y) return -1;
    S->Y = Y;
    double *xo = grow_array(S->xbase, sizeof(double) * (size_t)(nc / REPLIB_KEEP_CHUNK + 1) * S->m3);
    if (!xo) return -1;
    S->xbase = xo;
    unsigned char *c = realloc(S->cut, nc);
    if (!c) return -1;
    S->cut = c;
    if (S->xref) {
        const mapped_double **xp = realloc(S->xp, sizeof *xp * (size_t)nc);
        if (!xp) return -1;
        S->xp = xp;
    }
    S->cap = nc;
    return 0;
}

/* lo, hi (m3) = the smallest and largest of each coordinate over the nb
 * frames xs[0 .. nb-1] */
SKETCH_SIMD
static void chunk_range(const mapped_double *const *xs, int nb, int m3, double *restrict lo, double *restrict hi)
{
    memcpy(lo, (const void *)xs[0], sizeof(double) * m3);
    memcpy(hi, (const void *)xs[0], sizeof(double) * m3);
    for (int g = 1; g < nb; g++) {
        const mapped_double *restrict x = xs[g];
        for (int t = 0; t < m3; t++) {
            lo[t] = x[t] < lo[t] ? x[t] : lo[t];
            hi[t] = x[t] > hi[t] ? x[t] : hi[t];
        }
    }
}

/* The chunk's frames as integers of the step q (iq = 1 / q) about the
 * bases o, branch-free; returns 0 and raises *e to the largest rounding
 * when every value is on the grid within +-2^31 steps, else 1 (the caller
 * redoes the chunk value by value).  The roundings are >= 0, so their
 * largest is that of their bit patterns as integers: an integer max, which
 * the loop takes 8 coordinates at a time (AVX-512; the double max would
 * not vectorize without -ffinite-math-only; perf: this was 5% of the
 * Monkey-size run's CPU as scalar code).  Same integers, same *e. */
SKETCH_SIMD
static int chunk_ints(struct replib_sketch *S, const mapped_double *const *xs, int f0, int nb, const double *restrict o,
                      double q, double iq, double *e)
{
    int m3 = S->m3, bad = 0, store = !S->decode;
    double tol = 1e-3 * q;
    int64_t em;
    memcpy(&em, e, sizeof em);
    for (int g = 0; g < nb; g++) {
        const mapped_double *restrict x = xs[g];
        int32_t *restrict xi = store ? (int32_t *)S->Xk + (size_t)(f0 + g) * m3 : NULL;
        for (int t = 0; t < m3; t++) {
            double v = x[t] - o[t], u = v * iq;
            double k = replib_kept_int(x[t], o[t], iq), ek = fabs(k * q - v);
            bad |= !(fabs(u) <= 2147483647.0) | (ek > tol);
            double kc = k < -2147483647.0 ? -2147483647.0 : k > 2147483647.0 ? 2147483647.0 : k;
            if (store) xi[t] = (int32_t)kc;     /* decode: only checked */
            int64_t eb;
            memcpy(&eb, &ek, sizeof eb);
            em = eb > em ? eb : em;
        }
    }
    if (bad) return 1;
    memcpy(e, &em, sizeof em);
    return 0;
}

/* Encode the buffered frames of the chunk that ends before frame f1 into
 * the kept 32-bit frames: base = the midrange of each coordinate over the
 * chunk (on the input's grid), then integers of the step while every value
 * is on the grid and within +-2^31 steps, else floats (all kept frames
 * turned to floats once, in place).  kb: the chunk's frames one after the
 * other, or NULL: where they lie (S->xp; then, with S->release, their pages
 * are released once read). */
static void keep_chunk(struct replib_sketch *S, int f1, const double *kb)
{
    int m3 = S->m3, c = (f1 - 1) / REPLIB_KEEP_CHUNK, f0 = c * REPLIB_KEEP_CHUNK, nb = f1 - f0;
    double q = S->xstep, iq = q > 0 ? 1 / q : 0, e = 0, *o = S->xbase + (size_t)c * m3;
    double *lo = S->zprev + m3, *hi = lo + m3;   /* scratch */
    const mapped_double *xb[REPLIB_KEEP_CHUNK];
    const mapped_double *const *xs = xb;
    if (kb) for (int g = 0; g < nb; g++) xb[g] = kb + (size_t)g * m3;
    else xs = S->xp + f0;
    chunk_range(xs, nb, m3, lo, hi);
    for (int t = 0; t < m3; t++)
        o[t] = q > 0 ? nearbyint(0.5 * (lo[t] + hi[t]) / q) * q : 0.5 * (lo[t] + hi[t]);
    if (S->decode) {
        /* frames read where they lie later: only the check (the first
         * value off the grid ends the checks; finish encodes them all) */
        if (!S->offgrid && !(S->fixed && chunk_ints(S, xs, f0, nb, o, q, iq, &e) == 0)) S->offgrid = 1;
        if (e > S->float_err) S->float_err = e;
        if (S->release) mapped_release((const void *)xs[0], (const void *)(xs[nb - 1] + m3));
        return;
    }
    int done = S->fixed && chunk_ints(S, xs, f0, nb, o, q, iq, &e) == 0;    /* every value on the grid */
    for (int g = 0; g < nb && S->fixed && !done; g++) {
        const mapped_double *x = xs[g];
        int32_t *xi = (int32_t *)S->Xk + (size_t)(f0 + g) * m3;
        for (int t = 0; t < m3; t++) {
            /* round to nearest by the 1.5 2^52 trick (|v / q| < 2^31 checked first) */
            double v = x[t] - o[t], u = v * iq;
            if (!(fabs(u) <= 2147483647.0)) { S->fixed = 0; break; }
            double k = (u + 6755399441055744.0) - 6755399441055744.0, ek = fabs(k * q - v);
            if (ek > 1e-3 * q) { S->fixed = 0; break; }
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
            const mapped_double *x = xs[g];
            float *xf = (float *)S->Xk + (size_t)(f0 + g) * m3;
            for (int t = 0; t < m3; t++) {
                double v = x[t] - o[t];
                xf[t] = (float)v;
                if (fabs((double)xf[t] - v) > e) e = fabs((double)xf[t] - v);
            }
        }
    }
    if (e > S->float_err) S->float_err = e;
    /* the frames' pages: read again only by later passes */
    if (!kb && S->release) mapped_release((const void *)xs[0], (const void *)(xs[nb - 1] + m3));
}

/* The kept frames of the chunk starting at frame f0 (within the kept
 * capacity) faulted in, so that keep_chunk finds them mapped: the pages
 * are zeroed by the kernel either way (contents are not touched; an older
 * kernel refuses and they fault as before).  On the helper thread right
 * after it encodes the chunk before (that zeroing, 0.3-0.5 s at the Monkey
 * size when the memory is cold, was on the reading thread, the read's
 * critical path), else on the caller's. */
static void populate_chunk(const struct replib_sketch *S, int f0)
{
    size_t m3 = (size_t)S->m3, a = (size_t)f0 * m3 * 4, e = (size_t)(f0 + REPLIB_KEEP_CHUNK) * m3 * 4;
    if (e > (size_t)S->xcap * m3 * 4) e = (size_t)S->xcap * m3 * 4;
    uintptr_t p0 = ((uintptr_t)S->Xk + a) & ~(uintptr_t)4095, p1 = ((uintptr_t)S->Xk + e) & ~(uintptr_t)4095;
    if (S->Xk && p1 > p0) madvise((void *)p0, p1 - p0, MADV_POPULATE_WRITE);
}

/* The kept frames are encoded on a helper thread, one chunk at a time,
 * while the caller buffers the next chunk (S->kb holds two): the chunk's
 * arithmetic is that of keep_chunk on the caller's thread.  The caller
 * waits for it (keeper_wait) before it touches what keep_chunk writes or
 * reads: the kept frames, the bases, the chunk buffer it hands over next. */
struct keeper {
    struct replib_sketch *S;
    int f1;                     /* chunk ending before frame f1 to encode, 0 = none */
    const double *kb;
    int stop;
    pthread_mutex_t lock;
    pthread_cond_t cond;
    pthread_t th;
};

static void *keeper_main(void *arg)
{
    struct keeper *K = arg;
    pthread_mutex_lock(&K->lock);
    for (;;) {
        while (!K->f1 && !K->stop) pthread_cond_wait(&K->cond, &K->lock);
        if (!K->f1) break;
        int f1 = K->f1;
        const double *kb = K->kb;
        pthread_mutex_unlock(&K->lock);
        keep_chunk(K->S, f1, kb);
        populate_chunk(K->S, f1);   /* before K->f1 = 0: the caller may move Xk after that */
        pthread_mutex_lock(&K->lock);
        K->f1 = 0;
        pthread_cond_broadcast(&K->cond);
    }
    pthread_mutex_unlock(&K->lock);
    return NULL;
}

static void keeper_wait(struct replib_sketch *S)
{
    struct keeper *K = S->keeper;
    if (!K) return;
    pthread_mutex_lock(&K->lock);
    while (K->f1) pthread_cond_wait(&K->cond, &K->lock);
    pthread_mutex_unlock(&K->lock);
}

/* encode the chunk ending before f1 from kb, on the helper if there is one */
static void keeper_post(struct replib_sketch *S, int f1, const double *kb)
{
    struct keeper *K = S->keeper;
    if (!K) { keep_chunk(S, f1, kb); return; }
    pthread_mutex_lock(&K->lock);
    while (K->f1) pthread_cond_wait(&K->cond, &K->lock);
    K->f1 = f1;
    K->kb = kb;
    pthread_cond_broadcast(&K->cond);
    pthread_mutex_unlock(&K->lock);
}

static void keeper_stop(struct replib_sketch *S)
{
    struct keeper *K = S->keeper;
    if (!K) return;
    pthread_mutex_lock(&K->lock);
    K->stop = 1;
    pthread_cond_broadcast(&K->cond);
    pthread_mutex_unlock(&K->lock);
    pthread_join(K->th, NULL);
    pthread_mutex_destroy(&K->lock);
    pthread_cond_destroy(&K->cond);
    free(K);
    S->keeper = NULL;
}

static void keeper_start(struct replib_sketch *S)
{
    struct keeper *K = calloc(1, sizeof *K);
    if (!K) return;                 /* no helper: the chunks are encoded here */
    K->S = S;
    pthread_mutex_init(&K->lock, NULL);
    pthread_cond_init(&K->cond, NULL);
    if (pthread_create(&K->th, NULL, keeper_main, K) != 0) {
        pthread_mutex_destroy(&K->lock);
        pthread_cond_destroy(&K->cond);
        free(K);
        return;
    }
    S->keeper = K;
}

/* z (m) = sw (x - ref) (sw may be NULL: 1); returns |z|^2 (eight partial
 * sums: vectorized), not finite if a value of x is not */
SKETCH_SIMD
static double center_norm(const mapped_double *restrict x, const mapped_double *restrict ref,
                          const double *restrict sw, int m);

SKETCH_SIMD
static double center_row(const mapped_double *restrict x, const mapped_double *restrict ref,
                         const double *restrict sw, int m, double *restrict z)
{
    if (!z) return center_norm(x, ref, sw, m);
    double acc[8] = {0};
    int t = 0;
    if (sw) for (int i = 0; i < m; i++) z[i] = sw[i] * (x[i] - ref[i]);
    else for (int i = 0; i < m; i++) z[i] = x[i] - ref[i];
    for (; t + 8 <= m; t += 8)
        for (int j = 0; j < 8; j++) acc[j] += z[t + j] * z[t + j];
    double s = 0;
    for (; t < m; t++) s += z[t] * z[t];
    for (int j = 0; j < 8; j++) s += acc[j];
    return s;
}

/* center_row's |z|^2 without storing z (the same z, the same sums) */
SKETCH_SIMD
static double center_norm(const mapped_double *restrict x, const mapped_double *restrict ref,
                          const double *restrict sw, int m)
{
    double acc[8] = {0};
    int t = 0;
    for (; t + 8 <= m; t += 8)
        for (int j = 0; j < 8; j++) {
            double z = sw ? sw[t + j] * (x[t + j] - ref[t + j]) : x[t + j] - ref[t + j];
            acc[j] += z * z;
        }
    double s = 0;
    for (; t < m; t++) {
        double z = sw ? sw[t] * (x[t] - ref[t]) : x[t] - ref[t];
        s += z * z;
    }
    for (int j = 0; j < 8; j++) s += acc[j];
    return s;
}

/* byref: x stays where it is (replib_sketch_add_ref) */
static int sketch_add(struct replib_sketch *S, const mapped_double *x, int cut, int byref)
{
    int m3 = S->m3, f = S->n;
    if (f == 0) S->xref = byref;
    else if (S->xref != byref)
        return cm_seterr("replib_sketch: frame %d added %s reference, the earlier ones %s", f,
                         byref ? "by" : "not by", byref ? "not" : "by");
    /* frames that stay mapped until finish are summed where they lie (no
     * copy into zb: 61 MB fewer to fault in at the Monkey size) */
    if (f == 0) S->inplace = byref && !S->release;
    double zz = center_row(x, f ? S->ref : x, S->sw, m3,
                           S->inplace ? NULL : S->zb + ((size_t)S->zhalf * BATCH + S->nb) * m3);
    if (!(zz <= 1.7976931348623157e308))     /* a coordinate is not finite (or the squares overflow) */
        for (int t = 0; t < m3; t++)
            if (!isfinite(x[t])) return cm_seterr("frame %d: vertex %d: coordinate is not finite", f, t / 3);
    if (f == S->cap) {
        keeper_wait(S);             /* grow moves the bases and Y */
        if (flush_wait(S) < 0) return -1;
        if (grow(S) < 0) return cm_seterr("replib_sketch: out of memory at frame %d", f);
    }
    if (byref) S->xp[f] = x;        /* before the chunk or batch it ends is handed over */
    if (f == 0) {
        memcpy(S->ref, (const void *)x, sizeof(double) * m3);
        S->xstep = replib_input_step(S->ref, m3);
        S->fixed = S->xstep > 0;
        if (!S->fixed || !byref) S->decode = 0;     /* no grid to read the integers on */
    }
    if (S->keeping) {
        size_t need = (size_t)(f + 1) * m3 * 4;
        if (need > S->keep_bytes) {
            keeper_wait(S);
            free(S->Xk); S->Xk = NULL; S->keeping = 0;      /* too long: sketch only */
            S->dropped = 1; S->dropped_bytes = need;
        } else {
            /* grow the kept frames geometrically, within the budget */
            void *nx = S->Xk;
            if (S->decode) nx = S;          /* none to grow: read where they lie */
            else if (f == S->xcap) {
                size_t nc = S->xcap ? 2 * (size_t)S->xcap : 256, lim = S->keep_bytes / ((size_t)m3 * 4);
                if (!S->xcap && S->expect > 0) nc = (size_t)S->expect;
                if (nc > lim) nc = lim;
                keeper_wait(S);
                nx = S->xcap ? realloc(S->Xk, nc * m3 * 4) : big_alloc(nc * m3 * 4);
                if (nx) { S->xcap = (int)nc; S->Xk = nx; }     /* the helper is idle */
            }
            if (!nx) {
                keeper_wait(S); free(S->Xk); S->Xk = NULL; S->keeping = 0;
                S->dropped = 2; S->dropped_bytes = (size_t)(f + 1) * m3 * 4;
            }
            else {
                /* chunk c is buffered in half c % 2 of kb while the
                 * helper encodes chunk c - 1 from the other half; by
                 * reference, the helper reads the frames where they are */
                double *kb = NULL;
                if (!byref) {
                    kb = S->kb + (size_t)(f / REPLIB_KEEP_CHUNK % 2) * REPLIB_KEEP_CHUNK * m3;
                    memcpy(kb + (size_t)(f % REPLIB_KEEP_CHUNK) * m3, (const void *)x, sizeof(double) * m3);
                }
                if (f % REPLIB_KEEP_CHUNK == REPLIB_KEEP_CHUNK - 1) {
                    keeper_post(S, f + 1, kb);
                    if (!S->keeper) populate_chunk(S, f + 1);
                }
            }
        }
    }
    else if (byref && S->release && f > 0)
        mapped_release((const void *)x, (const void *)(x + m3));   /* read once: not kept */
    S->cut[f] = f > 0 && cut;
    S->zn += zz;
    S->n++;
    S->nb++;
    if (S->nb == BATCH) return flush(S);
    return 0;
}

int replib_sketch_add(struct replib_sketch *S, const double *x, int cut)
{
    return sketch_add(S, x, cut, 0);
}

int replib_sketch_add_ref(struct replib_sketch *S, const mapped_double *x, int cut)
{
    return sketch_add(S, x, cut, 1);
}

int replib_sketch_finish(struct replib_sketch *S, struct replib_data *D)
{
    if (flush(S) < 0 || flush_wait(S) < 0) return -1;
    keeper_stop(S);                 /* the chunks handed over are encoded */
    if (S->keeping && S->n % REPLIB_KEEP_CHUNK)
        keep_chunk(S, S->n, S->xref ? NULL : S->kb + (size_t)((S->n - 1) / REPLIB_KEEP_CHUNK % 2) * REPLIB_KEEP_CHUNK * S->m3);
    if (S->keeping && S->decode && S->offgrid) {
        /* a value off the grid: keep the frames after all, every chunk
         * encoded in order from where it lies, as it would have been on
         * the way (the same floats and rounding report) */
        S->decode = 0;
        S->Xk = big_alloc((size_t)S->n * S->m3 * 4);
        if (!S->Xk)     /* refused, not pieces from the sketch without a word */
            return cm_seterr("replib_sketch: out of memory keeping %d frames in 32 bits (%.0f MB; a value "
                             "is off the input's decimal grid, so they cannot be read where they lie)",
                             S->n, (double)S->n * S->m3 * 4 / 1048576);
        else {
            S->xcap = S->n;
            S->fixed = S->xstep > 0; S->floated = 0; S->float_err = 0;
            for (int f1 = REPLIB_KEEP_CHUNK; f1 - REPLIB_KEEP_CHUNK < S->n; f1 += REPLIB_KEEP_CHUNK)
                keep_chunk(S, f1 < S->n ? f1 : S->n, NULL);
        }
    }
    int n = S->n, k = S->k, s = S->s, m3 = S->m3, info = 0;
    if (n < 1) return cm_seterr("replib_sketch: no frames");
    if (!S->keeping && S->sw)
        for (int t = 0; t < m3; t++)
            if (S->sw[t] == 0)
                return cm_seterr("vertex %d has weight 0: its pieces cannot be recovered from the sketch "
                                 "(keep the frames: a larger memory budget)", t / 3);
    int r = k < n ? k : n;          /* rank of the result */
    free(S->om); S->om = NULL;      /* no more frames */
    free(S->zt); S->zt = NULL; free(S->yt); S->yt = NULL; free(S->zb); S->zb = NULL;
    /* Q = orth(Y): column-major n by k is Y^T row-major... transpose in */
    double *Qc = malloc(sizeof(double) * (size_t)n * k), *tau = malloc(sizeof(double) * k);
    if (!Qc || !tau) { free(Qc); free(tau); return cm_seterr("replib_sketch: out of memory"); }
    for (int i = 0; i < n; i++)
        for (int j = 0; j < k; j++) Qc[(size_t)j * n + i] = S->Y[(size_t)i * k + j];
    int lwork = -1;
    double q;
    dgeqrf_(&n, &r, Qc, &n, tau, &q, &lwork, &info);
    lwork = (int)q > k * 64 ? (int)q : k * 64;
    double *work = malloc(sizeof(double) * lwork);
    if (!work) { free(Qc); free(tau); return cm_seterr("replib_sketch: out of memory"); }
    dgeqrf_(&n, &r, Qc, &n, tau, work, &lwork, &info);
    if (info == 0) dorgqr_(&n, &r, &r, Qc, &n, tau, work, &lwork, &info);
    free(work);
    if (info != 0) { free(Qc); free(tau); return cm_seterr("replib_sketch: QR failed (%d)", info); }
    /* M = Psi Q (s by r, column-major): row i of Psi has the frames that
     * were added to row i of W */
    double *M = calloc((size_t)s * r, sizeof(double));
    int *pc = malloc(sizeof(int) * S->zpsi);
    if (!M || !pc) { free(Qc); free(tau); free(M); free(pc); return cm_seterr("replib_sketch: out of memory"); }
    for (int f = 0; f < n; f++) {
        psi_col(S, f, pc);
        for (int i = 0; i < S->zpsi; i++) {
            int row = pc[i] >> 1;
            double sg = pc[i] & 1 ? -1 : 1;
            for (int j = 0; j < r; j++) M[row + (size_t)j * s] += sg * Qc[f + (size_t)j * n];
        }
    }
    free(pc);
    double *Zr = NULL;
    if (S->keeping) {
        /* the frames are kept, so the basis V is not needed: any Zr with
         * Zr Zr^T = Q B B^T Q^T will do.  B = M^+ W = R_M^-1 Q_M^T W
         * (M = Q_M R_M), so B B^T = R_M^-1 Q_M^T (W W^T) Q_M R_M^-T: one
         * DSYRK of W (s^2 3#V flops) and small matrices; with
         * B B^T = U L U^T, Zr = Q U L^1/2. */
        double *G = malloc(sizeof(double) * (size_t)s * s), *T1 = malloc(sizeof(double) * (size_t)s * r);
        double *H = malloc(sizeof(double) * (size_t)r * r), *ev = malloc(sizeof(double) * r);
        Zr = malloc(sizeof(double) * (size_t)n * r);
        lwork = -1;
        dgeqrf_(&s, &r, M, &s, tau, &q, &lwork, &info);
        int lw2 = 3 * r;
        lwork = (int)q > lw2 ? (int)q : lw2;
        lwork = lwork > r * 64 ? lwork : r * 64;
        work = malloc(sizeof(double) * lwork);
        if (!G || !T1 || !H || !ev || !Zr || !work) {
            free(G); free(T1); free(H); free(ev); free(Zr); free(work); free(Qc); free(tau); free(M);
            return cm_seterr("replib_sketch: out of memory");
        }
        cblas_dsyrk(CblasColMajor, CblasUpper, CblasTrans, s, m3, 1.0, S->W, m3, 0.0, G, s);
        free(S->W); S->W = NULL;
        for (int i = 0; i < s; i++)
            for (int j = 0; j < i; j++) G[i + (size_t)j * s] = G[j + (size_t)i * s];
        dgeqrf_(&s, &r, M, &s, tau, work, &lwork, &info);
        for (int j = 0; j < r; j++)          /* R_M (upper) into H's storage */
            for (int i = 0; i < r; i++) H[i + (size_t)j * r] = i <= j ? M[i + (size_t)j * s] : 0;
        if (info == 0) dorgqr_(&s, &r, &r, M, &s, tau, work, &lwork, &info);
        if (info != 0) {
            free(G); free(T1); free(H); free(ev); free(Zr); free(work); free(Qc); free(tau); free(M);
            return cm_seterr("replib_sketch: QR failed (%d)", info);
        }
        double *Rm = malloc(sizeof(double) * (size_t)r * r);
        if (!Rm) { free(G); free(T1); free(H); free(ev); free(Zr); free(work); free(Qc); free(tau); free(M); return cm_seterr("replib_sketch: out of memory"); }
        memcpy(Rm, H, sizeof(double) * (size_t)r * r);
        /* H = Q_M^T G Q_M */
        cblas_dgemm(CblasColMajor, CblasNoTrans, CblasNoTrans, s, r, s, 1.0, G, s, M, s, 0.0, T1, s);
        cblas_dgemm(CblasColMajor, CblasTrans, CblasNoTrans, r, r, s, 1.0, M, s, T1, s, 0.0, H, r);
        free(G); free(T1); free(M);
        /* H <- R_M^-1 H R_M^-T */
        cblas_dtrsm(CblasColMajor, CblasLeft, CblasUpper, CblasNoTrans, CblasNonUnit, r, r, 1.0, Rm, r, H, r);
        cblas_dtrsm(CblasColMajor, CblasRight, CblasUpper, CblasTrans, CblasNonUnit, r, r, 1.0, Rm, r, H, r);
        free(Rm);
        for (int i = 0; i < r; i++)
            for (int j = 0; j < i; j++) H[i + (size_t)j * r] = H[j + (size_t)i * r] = 0.5 * (H[i + (size_t)j * r] + H[j + (size_t)i * r]);
        dsyev_("V", "U", &r, H, &r, ev, work, &lwork, &info);
        free(work); free(tau);
        if (info != 0) { free(H); free(ev); free(Zr); free(Qc); return cm_seterr("replib_sketch: eigenvalues failed (%d)", info); }
        cblas_dgemm(CblasRowMajor, CblasTrans, CblasTrans, n, r, r, 1.0, Qc, n, H, r, 0.0, Zr, r);
        for (int j = 0; j < r; j++) ev[j] = ev[j] > 0 ? sqrt(ev[j]) : 0;
        for (int f = 0; f < n; f++)
            for (int j = 0; j < r; j++) Zr[(size_t)f * r + j] *= ev[j];
        free(H); free(ev); free(Qc);
    } else {
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
        if (!S->V) { free(Rt); free(Qc); free(Bt); return cm_seterr("replib_sketch: out of memory"); }
        for (int t = 0; t < m3; t++)
            for (int j = 0; j < r; j++) S->V[(size_t)t * r + j] = Bt[(size_t)j * m3 + t];
        free(Bt);
        /* Zr = Q R^T: Q column-major n x r = row-major Q^T (r x n) */
        Zr = malloc(sizeof(double) * (size_t)n * r);
        if (!Zr) { free(Rt); free(Qc); return cm_seterr("replib_sketch: out of memory"); }
        cblas_dgemm(CblasRowMajor, CblasTrans, CblasNoTrans, n, r, r, 1.0, Qc, n, Rt, r, 0.0, Zr, r);
        free(Qc); free(Rt);
    }
    /* fill D as replib_prepare would */
    memset(D, 0, sizeof *D);
    D->n = D->N = n; D->nv = S->nv; D->m3 = m3; D->X = NULL;
    D->Xm = S->keeping && S->decode ? S->xp : NULL;
    D->Xm_keep = !S->release;
    D->Xf = S->keeping && !S->decode && !S->fixed ? (const float *)S->Xk : NULL;
    D->Xi = S->keeping && !S->decode && S->fixed ? (const int32_t *)S->Xk : NULL;
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
