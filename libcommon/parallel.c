/* parallel.c -- see parallel.h */
#include "parallel.h"
#include <pthread.h>
#include <unistd.h>

#define PARALLEL_MAX 64

struct pool {
    int n, next;
    pthread_mutex_t lock;
    void (*job)(void *ctx, int i);
    void *ctx;
};

static void *worker(void *arg)
{
    struct pool *p = arg;
    for (;;) {
        pthread_mutex_lock(&p->lock);
        int i = p->next < p->n ? p->next++ : -1;
        pthread_mutex_unlock(&p->lock);
        if (i < 0) return NULL;
        p->job(p->ctx, i);
    }
}

int parallel_threads(int nthreads)
{
    if (nthreads > 0) return nthreads;
    long c = sysconf(_SC_NPROCESSORS_ONLN);
    return c > 0 ? (int)c : 1;
}

void parallel_run(int n, int nthreads, void (*job)(void *ctx, int i), void *ctx)
{
    nthreads = parallel_threads(nthreads);
    if (nthreads > n) nthreads = n;
    if (nthreads > PARALLEL_MAX) nthreads = PARALLEL_MAX;
    if (nthreads <= 1) {
        for (int i = 0; i < n; i++) job(ctx, i);
        return;
    }
    struct pool p = {n, 0, PTHREAD_MUTEX_INITIALIZER, job, ctx};
    pthread_t th[PARALLEL_MAX];
    int started = 0;
    for (int t = 0; t < nthreads - 1; t++)
        if (pthread_create(&th[started], NULL, worker, &p) == 0) started++;
    worker(&p);
    for (int t = 0; t < started; t++) pthread_join(th[t], NULL);
    pthread_mutex_destroy(&p.lock);
}
