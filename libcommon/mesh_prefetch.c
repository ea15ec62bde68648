/* mesh_prefetch.c -- see mesh_prefetch.h */
#include "mesh_prefetch.h"
#include "cm_error.h"
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static void *reader_main(void *arg)
{
    struct mesh_prefetch *p = arg;
    size_t fl = 3 * (size_t)p->r->nv;
    for (;;) {
        pthread_mutex_lock(&p->lock);
        while (p->count == p->depth && !p->stop) pthread_cond_wait(&p->freed, &p->lock);
        int slot = (p->head + p->count) % p->depth, stop = p->stop;
        pthread_mutex_unlock(&p->lock);
        if (stop) break;
        int cut = 0, rc;
        if (p->ptr) rc = mesh_reader_next_ref(p->r, &p->ptr[slot], &cut);
        else rc = mesh_reader_next(p->r, p->buf + (size_t)slot * fl, &cut);
        pthread_mutex_lock(&p->lock);
        if (rc == 1) {
            p->cut[slot] = cut;
            p->count++;
        } else {
            p->done = 1;
            p->rc = rc < 0 ? -1 : 0;
            if (rc < 0) snprintf(p->msg, sizeof p->msg, "%s", cm_errmsg());
        }
        pthread_cond_signal(&p->filled);
        pthread_mutex_unlock(&p->lock);
        if (rc != 1) break;
    }
    return NULL;
}

static int start(struct mesh_prefetch *p, struct mesh_reader *r, int depth, int ref)
{
    memset(p, 0, sizeof *p);
    p->r = r;
    p->depth = depth < 2 ? 2 : depth;
    size_t fl = 3 * (size_t)(r->nv > 0 ? r->nv : 1);
    /* by reference: only the pointers (buf stays a 1-double placeholder) */
    p->buf = malloc(ref ? sizeof(double) : sizeof(double) * fl * p->depth);
    p->cut = calloc(p->depth, sizeof(int));
    if (ref) p->ptr = calloc(p->depth, sizeof *p->ptr);
    if (!p->buf || !p->cut || (ref && !p->ptr)) {
        free(p->buf); free(p->cut); free(p->ptr); p->buf = NULL; p->cut = NULL; p->ptr = NULL;
        return cm_seterr("out of memory (%d frame buffers of %d vertices)", p->depth, r->nv);
    }
    pthread_mutex_init(&p->lock, NULL);
    pthread_cond_init(&p->filled, NULL);
    pthread_cond_init(&p->freed, NULL);
    if (pthread_create(&p->th, NULL, reader_main, p) != 0) {
        pthread_mutex_destroy(&p->lock);
        pthread_cond_destroy(&p->filled);
        pthread_cond_destroy(&p->freed);
        free(p->buf); free(p->cut); free(p->ptr); p->buf = NULL; p->cut = NULL; p->ptr = NULL;
        return cm_seterr("cannot start the reader thread");
    }
    return 0;
}

int mesh_prefetch_start(struct mesh_prefetch *p, struct mesh_reader *r, int depth)
{
    return start(p, r, depth, 0);
}

int mesh_prefetch_start_ref(struct mesh_prefetch *p, struct mesh_reader *r, int depth)
{
    return start(p, r, depth, 1);
}

/* the next frame as a copy (*X) or by reference (*Xr) */
static int next(struct mesh_prefetch *p, const double **X, const mapped_double **Xr, int *cut)
{
    size_t fl = 3 * (size_t)p->r->nv;
    pthread_mutex_lock(&p->lock);
    if (p->held) {      /* the caller is done with the previous frame */
        p->head = (p->head + 1) % p->depth;
        p->count--;
        p->held = 0;
        pthread_cond_signal(&p->freed);
    }
    while (p->count == 0 && !p->done) pthread_cond_wait(&p->filled, &p->lock);
    int rc;
    if (p->count > 0) {
        if (Xr) *Xr = p->ptr[p->head];
        else *X = p->buf + (size_t)p->head * fl;
        if (cut) *cut = p->cut[p->head];
        p->held = 1;
        rc = 1;
    } else {
        rc = p->rc;
        if (rc < 0) cm_seterr("%s", p->msg);
    }
    pthread_mutex_unlock(&p->lock);
    return rc;
}

int mesh_prefetch_next(struct mesh_prefetch *p, const double **X, int *cut)
{
    if (p->ptr) return cm_seterr("mesh_prefetch_next: started by reference");
    return next(p, X, NULL, cut);
}

int mesh_prefetch_next_ref(struct mesh_prefetch *p, const mapped_double **X, int *cut)
{
    if (!p->ptr) return cm_seterr("mesh_prefetch_next_ref: not started by reference");
    return next(p, NULL, X, cut);
}

void mesh_prefetch_stop(struct mesh_prefetch *p)
{
    if (!p->buf) return;
    pthread_mutex_lock(&p->lock);
    p->stop = 1;
    pthread_cond_signal(&p->freed);
    pthread_mutex_unlock(&p->lock);
    pthread_join(p->th, NULL);
    pthread_mutex_destroy(&p->lock);
    pthread_cond_destroy(&p->filled);
    pthread_cond_destroy(&p->freed);
    free(p->buf); free(p->cut); free(p->ptr);
    p->buf = NULL; p->cut = NULL; p->ptr = NULL;
}
