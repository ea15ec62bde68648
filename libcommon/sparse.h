/* sparse.h -- sparse matrices for libcommon: a growable triplet list that
 * becomes a CHOLMOD compressed-column matrix (duplicates summed), and the
 * calling thread's cholmod_common.
 */
#ifndef CM_SPARSE_H
#define CM_SPARSE_H
#include <cholmod.h>
#ifdef __cplusplus
extern "C" {
#endif

/* The calling thread's cholmod_common (started on its first use, finished
 * when the thread ends or, for the main thread, at exit): CHOLMOD writes
 * its workspace there, so two threads must not share one.  A matrix or
 * factor belongs to no common: it may be made on one thread and freed on
 * another.  NULL only if out of memory. */
cholmod_common *cm_cholmod(void);

struct triplets {
    int nrow, ncol;
    size_t nnz, cap;
    int *i, *j;
    double *x;
};

void triplets_init(struct triplets *t, int nrow, int ncol);
/* Append entry (i, j, x); entries with the same (i, j) are summed later. */
void triplets_add(struct triplets *t, int i, int j, double x);
void triplets_free(struct triplets *t);

/* Compressed-column matrix from the triplets.  stype 0: unsymmetric
 * (all entries stored); stype 1: symmetric, keep only the upper triangle
 * (entries with i <= j; the caller adds both halves or only the upper). */
cholmod_sparse *triplets_to_sparse(const struct triplets *t, int stype);

/* y = A x for a (possibly stype=1 symmetric) matrix; x, y: #cols, #rows. */
void sparse_mul(const cholmod_sparse *A, const double *x, double *y);

void sparse_free(cholmod_sparse **A);

#ifdef __cplusplus
}
#endif
#endif
