/* mesh_prefetch.h -- read a MESH stream's frames ahead on a second thread.
 *
 * A reader thread parses frames (mesh_reader_next) into a ring of `depth`
 * frame buffers while the caller works on the previous ones: parsing the
 * text and the caller's work overlap on two cores.  Frames arrive in
 * order, the results and error messages are those of mesh_reader_next
 * (an error is reported when the caller reaches it, after every frame
 * before it).
 *
 *   struct mesh_prefetch p;
 *   if (mesh_prefetch_start(&p, &r, 8) < 0) ...;
 *   const double *X; int cut, rc;
 *   while ((rc = mesh_prefetch_next(&p, &X, &cut)) == 1) use X (#V by 3);
 *   mesh_prefetch_stop(&p);        then mesh_reader_close(&r)
 */
#ifndef CM_MESH_PREFETCH_H
#define CM_MESH_PREFETCH_H
#include "mesh.h"
#include <pthread.h>

struct mesh_prefetch {
    /* private */
    struct mesh_reader *r;
    int depth;                  /* ring slots */
    double *buf;                /* depth by #V by 3 */
    const mapped_double **ptr;   /* by reference: depth frame pointers (buf unused), else NULL */
    int *cut;                   /* depth */
    int head, count, held;      /* first filled slot, filled slots, caller holds slot head */
    int done, rc, stop;         /* reader finished with rc (0 end, -1 error) */
    char msg[1024];             /* the reader thread's error (cm_errmsg is per thread) */
    pthread_mutex_t lock;
    pthread_cond_t filled, freed;
    pthread_t th;
};

/* Start reading r (opened, header read; nothing read through r until
 * mesh_prefetch_stop) ahead by up to depth (>= 2) frames.  Returns 0, or
 * -1 and cm_seterr (out of memory, no thread). */
int mesh_prefetch_start(struct mesh_prefetch *p, struct mesh_reader *r, int depth);

/* The next frame: *X (#V by 3, valid until the next call or stop) and
 * *cut (may be NULL) as mesh_reader_next gives them.  Returns 1, 0 at the
 * end of the stream, -1 and cm_seterr with mesh_reader_next's message. */
int mesh_prefetch_next(struct mesh_prefetch *p, const double **X, int *cut);

/* The same for a mapped reader (mesh_reader_map): the reader thread runs
 * mesh_reader_next_ref (header, checks, page tables of the block) and
 * hands over where each frame lies; nothing is copied.
 * mesh_prefetch_next_ref gives *X as mesh_reader_next_ref does (valid
 * while the mapping is). */
int mesh_prefetch_start_ref(struct mesh_prefetch *p, struct mesh_reader *r, int depth);
int mesh_prefetch_next_ref(struct mesh_prefetch *p, const mapped_double **X, int *cut);

/* Stop the reader thread (it finishes the frame it is parsing) and free
 * the buffers.  Safe after start failed or twice. */
void mesh_prefetch_stop(struct mesh_prefetch *p);

#endif
