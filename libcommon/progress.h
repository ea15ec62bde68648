/* progress.h -- a progress bar on stderr, shown only when stderr is a
 * terminal (tools only: like tool.h, this is program harness, not library).
 *
 *   struct progress p; progress_start(&p, "seam-homog", nframes);
 *   for (...) progress_step(&p, k + 1);
 *   progress_end(&p);
 * total <= 0 means unknown: the bar shows a count.
 */
#ifndef CM_PROGRESS_H
#define CM_PROGRESS_H
#ifdef __cplusplus
extern "C" {
#endif

struct progress {
    const char *label;
    long total, last;
    double t0, tlast;
    int on;
};

void progress_start(struct progress *p, const char *label, long total);
void progress_step(struct progress *p, long done);
void progress_end(struct progress *p);

/* wall-clock seconds (monotonic) */
double now_seconds(void);

#ifdef __cplusplus
}
#endif
#endif
