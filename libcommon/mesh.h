/* mesh.h -- the MESH stream: a triangle mesh animation (a static mesh is an
 * animation with one frame).  Format: man 5 stopmo-mesh.
 *
 *   MESH 1              ("MESH 1 raw" for the binary variant)
 *   vertices 2694
 *   faces 5032
 *   frames 335          ("frames ?" when the writer streams)
 *   f 0 1 2             one line per triangle, 0-based (raw: int32 LE block)
 *   frame 0             frame header; "frame 17 cut" starts a new clip
 *   0.125 1.5 -0.25     one line per vertex (raw: 3 float64 LE per vertex)
 *
 * Two interfaces:
 *   whole mesh:      mesh_read() / mesh_write() on struct mesh
 *   frame by frame:  struct mesh_reader / struct mesh_writer, memory
 *                    O(one frame + topology), for the streaming tools.
 * Readers accept both variants.  All functions return < 0 on error with a
 * message in cm_errmsg() naming the file and line.
 */
#ifndef CM_MESH_H
#define CM_MESH_H
#include "mapped_frames.h"
#include <stdio.h>
#ifdef __cplusplus
extern "C" {
#endif

struct mesh {
    int nv;               /* #V vertices per frame */
    int nf;               /* #F triangles */
    int nframes;          /* number of frames (>= 1 for a valid mesh) */
    int *F;               /* #F by 3 vertex indices, row-major */
    double *V;            /* nframes by #V by 3 positions, frame-major */
    unsigned char *cut;   /* nframes flags: 1 = this frame starts a new clip */
};

/* Pointer to the #V by 3 positions of frame k. */
static inline double *mesh_frame(const struct mesh *m, int k)
{
    return m->V + (size_t)k * m->nv * 3;
}

/* Allocate (zeroed) storage for the given sizes. */
int mesh_alloc(struct mesh *m, int nv, int nf, int nframes);
void mesh_free(struct mesh *m);

/* Read a whole stream.  path NULL or "-" reads stdin. */
int mesh_read(const char *path, struct mesh *m);
/* Write a whole stream (raw != 0: binary variant).  A big text stream
 * (2 x 4096 vertex lines or more) is formatted on up to 4 threads (one per
 * core) while this one writes, in order: the bytes are those of
 * mesh_writer_frame, frame by frame. */
int mesh_write(FILE *f, const struct mesh *m, int raw);

/* Number of clips (1 + number of cut marks after frame 0). */
int mesh_nclips(const struct mesh *m);

/* ---- frame-by-frame reading ---- */
struct mesh_reader {
    const char *name;     /* file name used in messages ("<stdin>") */
    int nv, nf;
    int nframes;          /* -1 when the header said "frames ?" */
    int *F;               /* #F by 3, owned by the reader */
    int raw;              /* 1 if the stream is the raw variant */
    int frame;            /* index of the next frame to read */
    /* private */
    FILE *f;
    int own;
    long line;
    char *buf;
    size_t cap, len, pos;
    int eof;
    const unsigned char *map;   /* mesh_reader_map: the whole file, read-only, or NULL */
    size_t map_len, map_pos;    /* its size; the offset the buffer fills from next */
    int map_owned;              /* 1: mesh_reader_close unmaps it */
};

/* Open and read the header and faces.  path NULL or "-" reads stdin.
 * Limits (stopmo-mesh(5)): text lines of at most 1 MiB, no NUL byte in a
 * text line, counts up to 200000000, at least one frame; a regular file
 * whose header announces far more data than it holds (over 16 MiB more)
 * fails at once as truncated. */
int mesh_reader_open(struct mesh_reader *r, const char *path);
/* The same on an open stream f (positioned at the header); `name` is used
 * in messages; own != 0: mesh_reader_close() closes f. */
int mesh_reader_open_stream(struct mesh_reader *r, FILE *f, const char *name, int own);
/* Read the next frame into X (#V by 3); *cut (may be NULL) gets its cut
 * mark.  Returns 1 if a frame was read, 0 at the proper end of the stream,
 * -1 on error (truncated, wrong count, NaN, ...). */
int mesh_reader_next(struct mesh_reader *r, double *X, int *cut);
void mesh_reader_close(struct mesh_reader *r);
/* ---- raw frames left in place (a regular file, mapped) ----
 * mesh_reader_map maps a raw stream's regular file read-only (PROT_READ,
 * MAP_PRIVATE) once the header is read: returns 1, or 0 (nothing changes:
 * a text stream, a pipe, a big-endian host, or mmap refused).  Then
 * mesh_reader_next_ref gives each frame's vertex block where it lies in
 * the mapping: *X points to #V by 3 little-endian doubles at any byte
 * alignment (read them through mapped_double, mapped_frames.h), valid
 * until the mapping is unmapped; the same checks, results and messages as mesh_reader_next,
 * without copying the block.  mesh_reader_next still works on a mapped
 * reader (it copies).  The file must not shrink meanwhile (SIGBUS).
 * mesh_reader_take_map hands the mapping over (*len: its size): the
 * caller munmaps it after its last use of the blocks, and
 * mesh_reader_close leaves it. */
int mesh_reader_map(struct mesh_reader *r);
int mesh_reader_next_ref(struct mesh_reader *r, const mapped_double **X, int *cut);
const void *mesh_reader_take_map(struct mesh_reader *r, size_t *len);

/* ---- frame-by-frame writing ---- */
struct mesh_writer {
    FILE *f;
    int raw, nv, nf;
    int nframes;          /* announced count, -1 for "?" */
    int written;
};

/* Write the header and faces.  nframes < 0 writes "frames ?". */
int mesh_writer_open(struct mesh_writer *w, FILE *f, int nv, int nf,
                     const int *F, int nframes, int raw);
/* Write one frame (#V by 3 positions); cut != 0 marks a new clip. */
int mesh_writer_frame(struct mesh_writer *w, const double *X, int cut);
/* Check the announced frame count was met and flush. */
int mesh_writer_close(struct mesh_writer *w);

#ifdef __cplusplus
}
#endif
#endif
