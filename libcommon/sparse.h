/* sparse.h -- sparse matrices for libcommon: a growable triplet list that
 * becomes a CHOLMOD compressed-column matrix (duplicates summed), and the
 * shared cholmod_common.
 */
#ifndef CM_SPARSE_H
#define CM_SPARSE_H
#include <cholmod.h>
#ifdef __cplusplus
extern "C" {
#endif

/* The process-wide cholmod_common (started on first use, finished atexit). */
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
