/* mesh_spool.c -- see mesh_spool.h */
#include "mesh_spool.h"
#include "cm_error.h"
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int mesh_spool_begin(struct mesh_spool *s, const char *path, const struct mesh_reader *r)
{
    memset(s, 0, sizeof *s);
    struct stat st;
    if (path && strcmp(path, "-") && stat(path, &st) == 0 && S_ISREG(st.st_mode)) {
        s->path = strdup(path);
        return s->path ? 0 : cm_seterr("out of memory");
    }
    const char *dir = getenv("TMPDIR");
    if (!dir || !*dir) dir = "/tmp";
    size_t n = strlen(dir) + 32;
    s->path = malloc(n);
    if (!s->path) return cm_seterr("out of memory");
    snprintf(s->path, n, "%s/stopmo-spool-XXXXXX", dir);
    int fd = mkstemp(s->path);
    if (fd < 0) {
        cm_seterr("cannot create a temporary file in '%s': %s", dir, strerror(errno));
        free(s->path); s->path = NULL;
        return -1;
    }
    /* unlinked at once: the open descriptor keeps the data, and nothing is
     * left behind however the program ends (a signal, a crash, kill -9) */
    unlink(s->path);
    s->temp = 1;
    s->f = fdopen(fd, "w+b");
    if (!s->f) { close(fd); return cm_seterr("cannot write temporary '%s': %s", s->path, strerror(errno)); }
    /* the header's frame count (the first pass checks it) */
    if (mesh_writer_open(&s->w, s->f, r->nv, r->nf, r->F, r->nframes, 1) < 0) return -1;
    return 0;
}

int mesh_spool_frame(struct mesh_spool *s, const double *X, int cut)
{
    if (!s->f) return 0;
    if (mesh_writer_frame(&s->w, X, cut) < 0)
        return cm_seterr("cannot write temporary '%s': %s", s->path, cm_errmsg());
    return 0;
}

int mesh_spool_rewind(struct mesh_spool *s, struct mesh_reader *r2)
{
    if (!s->temp)
        return mesh_reader_open(r2, s->path);
    if (!s->f)
        return cm_seterr("internal: no temporary to read back");
    if (!s->done) {
        int bad = mesh_writer_close(&s->w) < 0;
        if (fflush(s->f) != 0 || ferror(s->f)) bad = 1;
        if (bad) return cm_seterr("cannot write temporary '%s' (disk full?)", s->path);
        s->done = 1;
    }
    /* a second descriptor on the unlinked file, from its start, for r2
     * (descriptors from dup share the offset: one r2 at a time) */
    int fd = dup(fileno(s->f));
    FILE *f = fd >= 0 && lseek(fd, 0, SEEK_SET) == 0 ? fdopen(fd, "rb") : NULL;
    if (!f) {
        int e = errno;
        if (fd >= 0) close(fd);
        return cm_seterr("cannot read temporary '%s': %s", s->path, strerror(e));
    }
    return mesh_reader_open_stream(r2, f, s->path, 1);
}

void mesh_spool_free(struct mesh_spool *s)
{
    if (s->f) { fclose(s->f); s->f = NULL; }
    free(s->path);
    s->path = NULL;
}
