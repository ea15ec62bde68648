/* blas_tune.h -- pick a fast OpenBLAS kernel (tools only: program harness,
 * like tool.h).
 *
 * Debian's OpenBLAS 0.3.21 does not recognise recent Intel CPUs (Sapphire
 * Rapids) and falls back to its generic "Prescott" SSE3 kernels; the
 * AVX-512 kernels are 1.4-4x faster there (measured on dict-learn's Gram
 * matrix).  OpenBLAS reads OPENBLAS_CORETYPE only when it is loaded, so the
 * fix has to happen before main(): blas_tune() re-executes the program once
 * (/proc/self/exe, same argv and environment) with OPENBLAS_CORETYPE set to
 * SkylakeX (AVX-512F) or Haswell (AVX2).  It does nothing when the user set
 * OPENBLAS_CORETYPE, when STOPMO_BLAS_TUNE=0, when OpenBLAS already chose a
 * specific kernel, or when re-execution fails.  Call it first in main(),
 * before reading any input.
 */
#ifndef CM_BLAS_TUNE_H
#define CM_BLAS_TUNE_H
#ifdef __cplusplus
extern "C" {
#endif

void blas_tune(char **argv);

/* One BLAS thread (unless the user set OPENBLAS_NUM_THREADS or
 * OMP_NUM_THREADS).  For sparse factorizations of meshes of a few thousand
 * vertices (CHOLMOD's supernodes are small) OpenBLAS's worker threads
 * mostly spin in sched_yield: one thread costs no wall time and saves a
 * third to a half of the CPU time (clay-deform on a 3520-face tube: 4.4-4.9
 * s CPU -> 2.7 s, 2.2-2.5 s wall either way).  The worker threads OpenBLAS
 * started when it loaded are stopped (its pthread build's
 * blas_thread_shutdown_; nothing elsewhere): idle, they spin in sched_yield
 * for 2^28 cycles before they sleep. */
void blas_single_thread(void);

/* The kernel OpenBLAS uses ("SkylakeX", "Prescott", ...). */
const char *blas_corename(void);

#ifdef __cplusplus
}
#endif
#endif
