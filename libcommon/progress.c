/* progress.c -- see progress.h */
#include "progress.h"
#include <stdio.h>
#include <stdlib.h>
#include <time.h>
#include <unistd.h>

double now_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

void progress_start(struct progress *p, const char *label, long total)
{
    p->label = label;
    p->total = total;
    p->last = 0;
    p->t0 = p->tlast = now_seconds();
    const char *e = getenv("STOPMO_PROGRESS");
    p->on = e ? atoi(e) != 0 : isatty(2);
}

void progress_step(struct progress *p, long done)
{
    if (!p->on) return;
    double t = now_seconds();
    if (t - p->tlast < 0.1 && done != p->total) return;
    p->tlast = t;
    p->last = done;
    if (p->total > 0) {
        int w = 30, k = (int)(w * done / p->total);
        fprintf(stderr, "\r%s [", p->label);
        for (int i = 0; i < w; i++) fputc(i < k ? '#' : '.', stderr);
        fprintf(stderr, "] %ld/%ld %.1fs", done, p->total, t - p->t0);
    } else {
        fprintf(stderr, "\r%s %ld %.1fs", p->label, done, t - p->t0);
    }
    fflush(stderr);
}

void progress_end(struct progress *p)
{
    if (p->on && p->last > 0) fputs("\n", stderr);
    p->on = 0;
}
