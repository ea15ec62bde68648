/* sparse.c -- see sparse.h */
#include "sparse.h"
#include <pthread.h>
#include <stdlib.h>
#include <string.h>

/* One cholmod_common per thread: its workspace (Iwork, Flag, Head, ...) is
 * written by every factorization and solve, and compat-tri refines two
 * candidates on two threads, each with its own ARAP transfers (one shared
 * common corrupted the heap there).  Freed when the thread ends, and the
 * main thread's at exit. */
static pthread_key_t key;
static pthread_once_t once = PTHREAD_ONCE_INIT;

static void destroy(void *p)
{
    if (!p) return;
    cholmod_finish(p);
    free(p);
}

static void finish_main(void)
{
    destroy(pthread_getspecific(key));
    pthread_setspecific(key, NULL);
}

static void make_key(void)
{
    pthread_key_create(&key, destroy);
    atexit(finish_main);
}

cholmod_common *cm_cholmod(void)
{
    pthread_once(&once, make_key);
    cholmod_common *c = pthread_getspecific(key);
    if (!c) {
        c = malloc(sizeof *c);
        if (!c) return NULL;
        cholmod_start(c);
        c->print = 0;            /* libcommon never prints */
        c->error_handler = NULL;
        if (pthread_setspecific(key, c) != 0) { cholmod_finish(c); free(c); return NULL; }
    }
    return c;
}

void triplets_init(struct triplets *t, int nrow, int ncol)
{
    memset(t, 0, sizeof *t);
    t->nrow = nrow;
    t->ncol = ncol;
}

void triplets_add(struct triplets *t, int i, int j, double x)
{
    if (t->nnz == t->cap) {
        t->cap = t->cap ? 2 * t->cap : 1024;
        t->i = realloc(t->i, t->cap * sizeof *t->i);
        t->j = realloc(t->j, t->cap * sizeof *t->j);
        t->x = realloc(t->x, t->cap * sizeof *t->x);
    }
    t->i[t->nnz] = i;
    t->j[t->nnz] = j;
    t->x[t->nnz] = x;
    t->nnz++;
}

void triplets_free(struct triplets *t)
{
    free(t->i);
    free(t->j);
    free(t->x);
    memset(t, 0, sizeof *t);
}

cholmod_sparse *triplets_to_sparse(const struct triplets *t, int stype)
{
    cholmod_common *c = cm_cholmod();
    size_t n = 0;
    for (size_t k = 0; k < t->nnz; k++)
        n += !(stype && t->i[k] > t->j[k]);
    cholmod_triplet *T = cholmod_allocate_triplet(t->nrow, t->ncol, n + 1, stype, CHOLMOD_REAL, c);
    if (!T) return NULL;
    int *ti = T->i, *tj = T->j;
    double *tx = T->x;
    size_t m = 0;
    for (size_t k = 0; k < t->nnz; k++) {
        if (stype && t->i[k] > t->j[k]) continue;
        ti[m] = t->i[k];
        tj[m] = t->j[k];
        tx[m] = t->x[k];
        m++;
    }
    T->nnz = m;
    cholmod_sparse *A = cholmod_triplet_to_sparse(T, m + 1, c);
    cholmod_free_triplet(&T, c);
    return A;
}

void sparse_mul(const cholmod_sparse *A, const double *x, double *y)
{
    const int *p = A->p, *ii = A->i;
    const double *ax = A->x;
    memset(y, 0, A->nrow * sizeof *y);
    for (size_t j = 0; j < A->ncol; j++)
        for (int k = p[j]; k < p[j + 1]; k++) {
            int i = ii[k];
            if (A->stype > 0 && i > (int)j) continue;
            y[i] += ax[k] * x[j];
            if (A->stype != 0 && i != (int)j) y[j] += ax[k] * x[i];
        }
}

void sparse_free(cholmod_sparse **A)
{
    if (*A) cholmod_free_sparse(A, cm_cholmod());
}
