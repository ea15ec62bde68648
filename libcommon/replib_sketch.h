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
 * 32 bits (n 3#V words) while they fit a byte budget: then the pieces and
 * the report are computed from those frames instead.  The 32-bit words
 * are integers k = (x_f - b) / q (b: per chunk of 64 frames, the midrange
 * of each coordinate, in double) when the input is printed with a decimal
 * step q (replib_input_step of the first frame: OBJ 1e-6) and every
 * coordinate seen is on that grid within +-2^31 steps: exact (b + k q to
 * double rounding); otherwise single-precision floats of x_f - b, whose
 * rounding (up to 2^-24 |x_f - b|) is reported.  The bases cost 1/32 of
 * the kept frames' memory.  A frame off the grid
 * turns the frames kept so far to floats (in place) and says so.  The norm |Z|_F^2 is accumulated
 * on the way, so the sketch's captured fraction of |Z|_F^2 is known.
 */
#define REPLIB_SKETCH_ZETA 8     /* nonzeros per row of Omega and per column of Psi */

#ifndef CM_REPLIB_SKETCH_H
#define CM_REPLIB_SKETCH_H
#include "replib.h"
#include "mapped_frames.h"
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
    int dropped;                /* the kept frames were dropped on the way: 1 over keep_bytes,
                                   2 out of memory (the pieces then come from the sketch) */
    size_t dropped_bytes;       /* the size that did not fit */
    double *ref;                /* 3#V first frame */
    double *sw;                 /* 3#V sqrt(w), or NULL */
    int zeta, zpsi;             /* nonzeros per row of Omega, per column of Psi */
    int *om;                    /* 3#V by zeta: the nonzeros of row t of Omega, 2 column + (sign < 0) */
    double *zt, *yt;            /* batch scratch: the frames transposed, Y_b transposed */
    double *Y;                  /* cap by k */
    double *W;                  /* s by 3#V */
    unsigned char *cut;         /* cap */
    void *Xk;                   /* cap by 3#V kept frames: int32_t (x_f - x_0) / xstep if fixed,
                                   else float x_f - x_0; or NULL */
    double *xbase;              /* per chunk of REPLIB_KEEP_CHUNK frames, 3#V bases b (the midrange
                                   of each coordinate over the chunk): kept frame = x_f - b */
    double *kb;                 /* 2 by REPLIB_KEEP_CHUNK by 3#V: the frames of the chunk being read
                                   and of the one being encoded (on a helper thread) */
    void *keeper;               /* private: that helper thread, or NULL */
    int fixed;                  /* 1: Xk holds integers of the input's step */
    int floated;                /* 1: Xk holds floats */
    double xstep;               /* the first frame's decimal step q (0: none) */
    double *zb;                 /* 2 by 128 by 3#V: the batch being filled (half zhalf) and the one
                                   being summed into Y and W (on a helper thread) */
    int zhalf;
    void *flusher;              /* private: that helper thread, or NULL */
    double *zprev;              /* 3 by 3#V scratch (keep_chunk) */
    int nb, cap, xcap;
    int expect;                 /* frames announced (0: unknown; set before the first add): the
                                   kept frames are then allocated once, on huge pages */
    const mapped_double **xp;   /* replib_sketch_add_ref: cap frame pointers (valid until finish) */
    int xref;                   /* 1: frames were added by reference */
    int release;                /* 1 (set by the caller): the referenced frames lie in a read-only
                                   private file mapping; their pages are released once read
                                   (mapped_release) and fault in again when a pass needs them;
                                   0: they stay mapped, in this pass and (replib_data.Xm_keep)
                                   in the pieces' and the report's */
    int decode;                 /* 1 (set by the caller, with replib_sketch_add_ref):
                                   the referenced frames stay mapped until the pieces are built, so
                                   they are not copied into Xk: the helper only computes the bases
                                   and checks that every value is on the grid, and finish points
                                   D->Xm at the frames (the same numbers as Xi; no page of Xk to
                                   zero and fill).  A value off the grid: finish keeps the frames
                                   in Xk after all, encoded from where they lie (the same result) */
    int offgrid;                /* decode: a value was found off the grid or out of range */
    int inplace;                /* 1: frames added by reference and not released (S->release = 0)
                                   are summed into Y and W where they lie, not copied into zb */
    uint64_t seed;
    double zn;                  /* |Z|_F^2 */
    double float_err;           /* max |kept(x - x_0) - (x - x_0)| over kept frames (model units) */
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
/* The same for a frame that stays where it is, x (3#V doubles at any
 * alignment, e.g. a raw block in a file mapping: mesh_reader_next_ref)
 * valid until replib_sketch_finish returns: the frame is not copied; the
 * helper that encodes the kept frames reads each chunk where it lies (the
 * same bytes of every result as replib_sketch_add).  All frames of a
 * sketch are added one way or the other, not both. */
int replib_sketch_add_ref(struct replib_sketch *S, const mapped_double *x, int cut);
/* Finish the sketch and fill D (D->n, nv, and everything replib_prepare
 * derives; D->X = NULL, D->Xi or D->Xf / D->ref / D->V point into S, which must
 * outlive D).  No fixed pieces.  Returns 0 or -1. */
int replib_sketch_finish(struct replib_sketch *S, struct replib_data *D);
void replib_sketch_free(struct replib_sketch *S);

#ifdef __cplusplus
}
#endif
#endif
