/* mesh_spool.h -- read a MESH stream twice with memory O(one frame).
 *
 * Tools whose math needs a whole-animation quantity before they can process
 * the frames (the average mesh, the average triangle areas) read the
 * stream once to accumulate, then once more.  A regular file is simply
 * reopened; anything else (a pipe, stdin) is copied frame by frame to a
 * temporary raw MESH file ($TMPDIR or /tmp, bit-exact doubles) during the
 * first pass and read back from there.  The temporary is unlinked as soon
 * as it is created (only the open descriptor holds it), so nothing stays
 * behind however the program ends.
 *
 *   mesh_reader_open(&r, path);
 *   mesh_spool_begin(&sp, path, &r);
 *   while (mesh_reader_next(&r, X, &cut) == 1) { mesh_spool_frame(&sp, X, cut); ... }
 *   mesh_spool_rewind(&sp, &r2);          r2: a reader at frame 0 again
 *   ...
 *   mesh_reader_close(&r2); mesh_spool_free(&sp);
 */
#ifndef CM_MESH_SPOOL_H
#define CM_MESH_SPOOL_H
#include "mesh.h"
#ifdef __cplusplus
extern "C" {
#endif

struct mesh_spool {
    char *path;            /* file read in the second pass (the temporary's
                              former name, for messages) */
    int temp;              /* 1 if path is our temporary copy */
    FILE *f;               /* the (unlinked) temporary, NULL for a regular file */
    int done;              /* 1 once the first pass was finished */
    struct mesh_writer w;
};

/* Start after mesh_reader_open(r, path) (path NULL or "-" = stdin). */
int mesh_spool_begin(struct mesh_spool *s, const char *path, const struct mesh_reader *r);
/* Record one frame read in the first pass (no-op for a regular file). */
int mesh_spool_frame(struct mesh_spool *s, const double *X, int cut);
/* Finish the first pass and open a new reader r2 at the first frame.
 * The data were validated in the first pass, so r2 normally cannot fail
 * except on I/O errors.  It may be called again (after closing the
 * previous r2) to start over; one r2 at a time. */
int mesh_spool_rewind(struct mesh_spool *s, struct mesh_reader *r2);
/* Free (and release the temporary if the second pass never began). */
void mesh_spool_free(struct mesh_spool *s);

#ifdef __cplusplus
}
#endif
#endif
