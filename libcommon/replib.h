/* replib.h -- replacement library and per-frame labels (StopShop Sec. 3.3,
 * Eq. 10-16): given one part's animation X (n frames of #V vertices), find
 * d pieces R and labels l minimizing
 *
 *   E(R, l) = sum_f |x_f - r_{l_f}|_W^2
 *           + lambda/2 sum_{f, f+1 in one clip} |(x_{f+1} - x_f) - (r_{l_{f+1}} - r_{l_f})|_W^2
 *
 * by block coordinate descent with restarts:
 *   library step: with mu = lambda/2, S the d by n assignment matrix and G
 *     the n by (n-1) in-clip forward difference (Eq. 12), solve the d by d
 *     SPD system  A R^T = B,  A = S S^T + mu S G G^T S^T,
 *     B = (S + mu S G G^T) X^T  (Eq. 13 with the paper's lambda read as
 *     lambda/2, so that it is the exact normal equation of Eq. 10, and with
 *     A d by d, not n by n).  A piece no frame uses is re-seeded with the
 *     worst-fit frame; fixed pieces (--fixed) stay as given.
 *   label step: exact chain DP (chainlabel.h), or alpha-expansion / swap.
 * With lambda = 0 this is Lloyd's k-means.
 *
 * Costs come from dense products: |z|^2 + |r|^2 - 2 z.r.  Internally every
 * piece is r_a = sum_g C_ag z_g over the frames (and fixed pieces) z_g, so
 * two back ends give the same numbers:
 *   Gram:   K = Z Z^T once (one DSYRK, N^2 3#V flops, or 6 N 3#V r when Z
 *           has rank <= r to rounding, as blend-shape faces do); per iteration
 *           P = K C^T, Q = C P: independent of #V, restarts nearly free.
 *   direct: per iteration R = A^-1 B (sparse B), P = Z R^T (one DGEMM,
 *           serving both the data and the velocity term since
 *           dz_f . r_a = P_{f+1,a} - P_{f,a}) and Q = R R^T (DSYRK).
 * Z is X centered on the mean frame and scaled by sqrt(w) per vertex (the
 * energy is translation invariant and the library step does not depend on
 * W, Sec. 3.3).
 */
#ifndef CM_REPLIB_H
#define CM_REPLIB_H
#include "mapped_frames.h"
#include <stddef.h>
#include <stdint.h>
#ifdef __cplusplus
extern "C" {
#endif

#define REPLIB_KEEP_CHUNK 64      /* frames per base of the kept 32-bit frames */

/* The kept integer of coordinate x about its base b on the input's grid
 * (iq = 1 / step): (x - b) / step rounded to nearest, ties to even, by the
 * 1.5 2^52 trick (|(x - b) iq| < 2^31 is checked first).  The one formula
 * of the kept frames (replib_sketch.c) and of the frames read where they
 * lie (replib_data.Xm), so the two give the same numbers. */
static inline double replib_kept_int(double x, double b, double iq)
{
    return ((x - b) * iq + 6755399441055744.0) - 6755399441055744.0;
}
#define REPLIB_SAMPLE_BLOCK 64    /* consecutive frames per block of a sample (replib_opts.sample) */

enum replib_method { REPLIB_DP = 0, REPLIB_EXPANSION = 1, REPLIB_SWAP = 2 };

/* How a restart picks its first pieces (frames, or fixed pieces, as centres):
 *   REPLIB_START_PLUSPLUS  k-means++ (one D^2-sampled frame per centre; the
 *                          method before the local search existed)
 *   REPLIB_START_GREEDY    greedy k-means++: 2 + ln d D^2-sampled candidates
 *                          per centre, the one that lowers sum_f min_a |z_f - r_a|^2
 *                          most is kept (as scikit-learn's KMeans does) */
enum replib_start { REPLIB_START_GREEDY = 0, REPLIB_START_PLUSPLUS = 1 };

/* The animation and everything precomputed from it (reused across d). */
struct replib_data {
    /* inputs, set by the caller before replib_prepare() */
    int n;                      /* frames */
    int nv;                     /* #V vertices per frame */
    const double *X;            /* n by 3#V positions (a MESH's V array) */
    int nfix;                   /* fixed pieces (may be 0) */
    const double *Rfix;         /* nfix by 3#V fixed piece positions, or NULL */
    const double *w;            /* #V saliency weights >= 0, or NULL (all 1) */
    const unsigned char *cut;   /* n flags, 1 = frame starts a clip, or NULL */
    int gram;                   /* -1 auto, 0 direct, 1 Gram, 2 Gram in single precision */
    int no_lowrank;             /* 1: never use the exact low-rank Gram matrix */
    double swap_cost;           /* >= 0, energy units (as the data term): each change of piece
                                   between consecutive frames of one clip costs this much
                                   (chainlabel.h's swap term).  Charged by replib_label only;
                                   replib_learn refuses a nonzero value (relabel its library) */
    /* frames held elsewhere (replib_sketch.h): then X is NULL, Z holds
     * reduced coordinates, and the pieces come from */
    const int32_t *Xi;          /* n by 3#V: (x_f - ref) / xstep, integers (exact), or NULL: */
    double xstep;               /* the step of Xi */
    const double *xbase;        /* ceil(n / REPLIB_KEEP_CHUNK) by 3#V: frame f of Xi or Xf is
                                   x_f = xbase[f / REPLIB_KEEP_CHUNK] + kept (NULL: ref + kept) */
    const mapped_double *const *Xm;   /* n frames where they lie in a file mapping, read as the
                                   integers Xi would hold: x_f = b + round((x - b) / xstep) xstep
                                   (every value checked on that grid), or NULL: */
    int Xm_keep;                /* 1: Xm's pages stay mapped once read (the file is small enough
                                   to stay mapped whole between the passes); 0: each frame's
                                   pages are released after its last read (mapped_release) */
    const float *Xf;            /* n by 3#V: x_f - ref in single precision, or NULL: */
    const double *V;            /* 3#V by zdim orthonormal basis, z ~ Zr V^T */
    const double *ref;          /* 3#V reference frame */
    const double *sw;           /* 3#V square roots of the weights (V side), or NULL */
    /* derived by replib_prepare() */
    int N;                      /* n + nfix */
    int m3;                     /* 3#V */
    unsigned char *link;        /* n: link[f] = 1 if f, f+1 are in one clip */
    double *mean;               /* 3#V mean frame */
    double *Z;                  /* N by zdim centered weighted rows (direct back end only) */
    int zdim;                   /* 3#V, or the rank r of the exact low-rank coordinates */
    double *K;                  /* N by N Gram matrix (Gram back end only) */
    double *zz;                 /* N squared norms |z_g|^2 */
    double *dd;                 /* n: |z_{f+1} - z_f|^2 (0 where not linked) */
    int lowrank;                /* rank r if Z holds exact low-rank coordinates (Z Z^T = K), else 0 */
    double step;                /* the input's decimal step q (OBJ: 1e-6), 0 if none (binary) */
    double lowrank_resid;       /* RMS residual per coordinate of the last low-rank try (0: none);
                                   accepted when <= q/2 (what the input can represent) or 1e-12 relative */
    double prep_seconds;        /* time spent in replib_prepare */
};

/* The input's decimal step: the smallest q = 10^-k (k = 0..9) such that
 * every sampled coordinate of X (count values, up to 65,536 sampled) is a
 * multiple of q to double rounding (text exports print a fixed number of
 * decimals: OBJ 6), or 0 if none. */
double replib_input_step(const double *X, size_t count);

/* Validate (weights finite and >= 0 with a positive sum, X finite) and
 * precompute.  Returns 0, or -1 with cm_errmsg(). */
int replib_prepare(struct replib_data *D);
void replib_data_free(struct replib_data *D);

/* One iteration, for logging. */
struct replib_iter {
    int restart, iteration;     /* iteration 0 = after initialisation */
    double energy;              /* E after the label step */
    double data, velocity;      /* its data term and lambda/2 * velocity term */
    int changed;                /* labels changed in this label step */
    int reseeded;               /* pieces re-seeded in this library step */
    double seconds;             /* wall time of this iteration */
};

struct replib_opts {
    int d;                      /* pieces, nfix <= d <= n + nfix */
    double lambda;              /* velocity weight (>= 0) */
    int restarts;               /* >= 1 */
    int iterations;             /* max iterations per restart (>= 1) */
    uint64_t seed;
    enum replib_method method;  /* label step */
    const int *init_labels;     /* n labels in [0, d) for restart 0, or NULL (k-means++ start) */
    double tol;                 /* stop when E decreases by less than tol * E (e.g. 1e-9) */
    enum replib_start start;    /* first pieces of restarts without init_labels */
    int search;                 /* local search after the descent converges, per restart:
                                   0 = none (plain block coordinate descent, the paper's
                                   method); N > 0 = single-frame moves (lambda = 0: exact
                                   Hartigan moves between piece means) and N split/merge
                                   trials: the piece whose frames are cheapest to hand to
                                   their second-best pieces is moved onto a D^2-sampled
                                   badly fitted frame, the descent rerun, and the result
                                   kept only if its energy is lower.  With lambda > 0 and
                                   the DP, the trials' label steps (and the first descent's
                                   after its first) consider only the 8 cheapest pieces of
                                   each frame (by data cost) and its current label, in
                                   O(n (d + 9^2)) instead of O(n d^2); one exact descent
                                   from the best result follows, so the output is a fixed
                                   point of the exact label step.  On reduced coordinates
                                   (direct back end) a step that changes few labels updates
                                   the library and P incrementally (replib.c) */
    int sample;                 /* > 0: when the frames exceed this many (direct back end: reduced
                                   coordinates, e.g. the sketch, or rows that copy within 512 MB),
                                   the restarts and the search run on a sample of about this many
                                   frames, blocks of REPLIB_SAMPLE_BLOCK consecutive frames spread
                                   evenly over the animation, each block its own clip; the best
                                   library labels all frames (exact label step) and one restart
                                   on all frames from those labels (descent and search) follows,
                                   instead of o->restarts on all frames.  0: off */
    int threads;                /* restarts run in parallel on this many threads (0: one per core),
                                   and the library is built from kept 32-bit frames on as many;
                                   once no restart is left to start, a thread that finished
                                   takes blocks of frames of the row-wise products (costs,
                                   distances, second-best scans) of those still running; the
                                   result does not depend on it */
    int no_prune;               /* 1: the greedy start and the split/merge proposals measure every
                                   frame's distance to their candidates (the method before the
                                   bounds of replib.c's dcols_pruned, which skip frames that
                                   provably cannot change the result: the same bytes; for tests) */
    void (*log)(void *ctx, const struct replib_iter *it);   /* or NULL */
    void *log_ctx;
};

struct replib_result {
    int d, n, m3;
    int *labels;                /* n labels of the best restart */
    double *R;                  /* d by 3#V library (pieces 0..nfix-1 are the fixed ones) */
    double energy, data, velocity;  /* model energy of the best (data + lambda/2 vel) */
    int best_restart;
    int restarts, iterations;   /* restarts run, iterations over all restarts */
    int accepted;               /* split/merge trials kept, over all restarts */
    int helped;                 /* chunks of the restarts' row-wise products run by workers
                                   that had no restart left (timing-dependent; the result is not) */
    double seconds;             /* wall time of replib_learn (excl. prepare) */
    double label_seconds;       /* of which in label steps */
    int sampled;                /* frames of the sample (o->sample), 0 if all frames were searched */
    double sample_energy;       /* the sample's best energy (on its frames), if sampled */
};

/* Block coordinate descent with restarts, run on o->threads threads (BLAS
 * is set to one thread meanwhile: openblas_set_num_threads is global, so
 * do not call this from several threads at once).  Returns 0 or -1
 * (cm_errmsg). */
int replib_learn(const struct replib_data *D, const struct replib_opts *o,
                 struct replib_result *res);
void replib_result_free(struct replib_result *res);

/* Labels for a fixed library: D prepared with nfix = d pieces (Rfix = the
 * library).  l (out): n labels.  Returns the energy (*data, *velocity may
 * be NULL; D->swap_cost times the swaps is in the returned energy and in
 * *velocity), NAN on failure. */
double replib_label(const struct replib_data *D, double lambda, enum replib_method method,
                    int *l, double *data, double *velocity);

/* The same; *label_seconds (may be NULL) gets the time of the label step
 * alone (without the cost products). */
double replib_label_timed(const struct replib_data *D, double lambda, enum replib_method method,
                          int *l, double *data, double *velocity, double *label_seconds);

/* Direct evaluation of a labeling (no Gram tricks), in model units.  The
 * data and the velocity terms are summed on two threads, each in frame
 * and vertex order (the same numbers as one thread). */
struct replib_report {
    double energy;              /* data + lambda/2 * velocity */
    double data;                /* sum_f |x_f - r_l|_W^2 */
    double velocity;            /* sum_linked |dx - dr|_W^2 (without lambda/2) */
    double mean_err, max_err;   /* per-vertex distance |x_fi - r_{l_f} i| over all f, i */
    double mean_verr, max_verr; /* per-vertex velocity error over linked pairs */
    int worst_frame;            /* frame holding max_err */
};

/* X: n by 3#V, R: d by 3#V, l: n labels in [0, d), w: #V or NULL,
 * cut: n or NULL.  frame_err (out, may be NULL): n per-frame max vertex
 * distance. */
void replib_evaluate(const double *X, int n, int nv, const double *R, int d, const int *l,
                     const double *w, const unsigned char *cut, double lambda,
                     struct replib_report *rep, double *frame_err);
/* The same with the frames as b_f + Xi q (Xi: n by 3#V integers, q their
 * step, xbase: the bases b as in struct replib_data, ref: 3#V). */
void replib_evaluate_i(const int32_t *Xi, double q, const double *xbase, const double *ref, int n, int nv, const double *R, int d,
                       const int *l, const double *w, const unsigned char *cut, double lambda,
                       struct replib_report *rep, double *frame_err);
/* The same with the frames as b_f + Xf (Xf: n by 3#V floats, xbase: the
 * bases or NULL for ref, ref: 3#V). */
void replib_evaluate_f(const float *Xf, const double *xbase, const double *ref, int n, int nv, const double *R, int d,
                       const int *l, const double *w, const unsigned char *cut, double lambda,
                       struct replib_report *rep, double *frame_err);
/* The same with the frames where they lie (Xm: n frame pointers), read as
 * replib_data.Xm says (q: their step, xbase: the bases, ref: 3#V); keep:
 * as replib_data.Xm_keep (0: each frame's pages are released once read). */
void replib_evaluate_m(const mapped_double *const *Xm, int keep, double q, const double *xbase, const double *ref,
                       int n, int nv, const double *R, int d, const int *l, const double *w, const unsigned char *cut,
                       double lambda, struct replib_report *rep, double *frame_err);

#ifdef __cplusplus
}
#endif
#endif
