/* parallel.h -- run n independent jobs on a few threads (POSIX threads).
 *
 * For loops whose iterations share no mutable state, e.g. one pose of a
 * compatible mesh each (compat_refine's smoothing moves the vertices of
 * one pose at a time): the results do not depend on the number of threads
 * or on which thread runs which job, so output stays byte-identical.
 */
#ifndef CM_PARALLEL_H
#define CM_PARALLEL_H
#ifdef __cplusplus
extern "C" {
#endif

/* job(ctx, i) for i = 0..n-1 on up to nthreads threads (the calling
 * thread is one of them); jobs are handed out in order as threads become
 * free.  nthreads <= 0: one per online processor.  A thread that cannot be
 * started leaves its share to the others.  Returns when every job is done. */
void parallel_run(int n, int nthreads, void (*job)(void *ctx, int i), void *ctx);

/* the threads parallel_run takes for nthreads (<= 0: the online processors) */
int parallel_threads(int nthreads);

#ifdef __cplusplus
}
#endif
#endif
