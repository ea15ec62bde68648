/* replib_sketch.h -- one-pass low-rank sketch of an animation for the
 * replacement library (replib.h), for animations too long to hold: frames
 * arrive one at a time (a pipe) and are never read twice.
 *
 * With z_f = sqrt(w) (x_f - x_0) (x_0 the first frame: the energy is
 * translation invariant), the stream keeps (Tropp, Yurtsever, Udell,
 * Cevher 2017, "Practical sketching algorithms for low-rank matrix
 * approximation", Alg. 7 with a Gaussian test pair):
 *   range sketch     Y = Z Omega       n by k    (Omega: 3#V by k Gaussian)
 *   co-range sketch  W = Psi Z         s by 3#V  (Psi: s by n Gaussian,
 *                                                 column f drawn from (seed, f))
 * batched 64 frames per GEMM, s = 2k + 1.  At the end Q = orth(Y),
 * B = (Psi Q)^+ W (least squares), Z ~ Q B; with B^T = V R (QR),
 * Zr = Q R^T (n by k) are the reduced coordinates handed to replib_learn
 * (Zr Zr^T ~ Z Z^T), and pieces come back as x_0 + (C Zr) V^T / sqrt(w).
 * Memory: n k + s 3#V + 3#V k doubles, plus (optionally) the frames in
 * single precision (n 3#V floats) while they fit a byte budget: then the
 * pieces and the report are computed from those frames instead (exact up
 * to float rounding of x - x_0, which is checked against the input's
 * precision).  Exact norms |z_f|^2 and |z_{f+1} - z_f|^2 are accumulated
 * on the way, so the sketch's captured fraction of |Z|_F^2 is known.
 */
#ifndef CM_REPLIB_SKETCH_H
#define CM_REPLIB_SKETCH_H
#include "replib.h"
#include <stddef.h>
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif

struct replib_sketch {
    int nv, m3;                 /* #V, 3#V */
    int k, s;                   /* range and co-range sketch sizes */
    int n;                      /* frames added so far */
    size_t keep_bytes;          /* budget for the single-precision frames (0: none) */
    int keeping;                /* 1 while the frames are kept */
    double *ref;                /* 3#V first frame */
    double *sw;                 /* 3#V sqrt(w), or NULL */
    double *Om;                 /* 3#V by k */
    double *Y;                  /* cap by k */
    double *W;                  /* s by 3#V */
    double *zz, *dd;            /* cap: exact |z_f|^2, |z_{f+1} - z_f|^2 (0 across cuts) */
    unsigned char *cut;         /* cap */
    float *Xf;                  /* cap by 3#V: x_f - x_0 in single precision, or NULL */
    double *zb;                 /* 64 by 3#V batch */
    double *zprev;              /* 3#V previous z */
    int nb, cap, xcap;
    uint64_t seed;
    double zn;                  /* |Z|_F^2 */
    double float_err;           /* max |float(x - x_0) - (x - x_0)| over kept frames */
    /* after replib_sketch_finish */
    double *V;                  /* 3#V by k basis (orthonormal) */
    double captured;            /* |Zr|_F^2 / |Z|_F^2 */
};

/* k: range sketch size (e.g. 128); w: #V weights or NULL (kept by
 * pointer); keep_bytes: keep frames in float while n 3#V 4 <= keep_bytes.
 * Returns 0 or -1 (cm_errmsg). */
int replib_sketch_init(struct replib_sketch *S, int nv, int k, const double *w, size_t keep_bytes,
                       uint64_t seed);
/* Add one frame x (#V by 3); cut = 1 if it starts a clip. */
int replib_sketch_add(struct replib_sketch *S, const double *x, int cut);
/* Finish the sketch and fill D (D->n, nv, and everything replib_prepare
 * derives; D->X = NULL, D->Xf / D->ref / D->V point into S, which must
 * outlive D).  No fixed pieces.  Returns 0 or -1. */
int replib_sketch_finish(struct replib_sketch *S, struct replib_data *D);
void replib_sketch_free(struct replib_sketch *S);

#ifdef __cplusplus
}
#endif
#endif
