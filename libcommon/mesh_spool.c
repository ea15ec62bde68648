/* mesh_spool.c -- see mesh_spool.h */
#include "mesh_spool.h"
#include "cm_error.h"
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#define MAX_TEMPS 8
static char *temps[MAX_TEMPS];
static int registered;

static void remove_temps(void)
{
    for (int i = 0; i < MAX_TEMPS; i++)
        if (temps[i]) { unlink(temps[i]); temps[i] = NULL; }
}

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
    s->temp = 1;
    if (!registered) { atexit(remove_temps); registered = 1; }
    for (int i = 0; i < MAX_TEMPS; i++)
        if (!temps[i]) { temps[i] = s->path; break; }
    s->f = fdopen(fd, "wb");
    if (!s->f) { close(fd); return cm_seterr("cannot write temporary '%s': %s", s->path, strerror(errno)); }
    if (mesh_writer_open(&s->w, s->f, r->nv, r->nf, r->F, -1, 1) < 0) return -1;
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
    if (s->f) {
        int bad = mesh_writer_close(&s->w) < 0;
        if (fclose(s->f) != 0) bad = 1;
        s->f = NULL;
        if (bad) return cm_seterr("cannot write temporary '%s' (disk full?)", s->path);
    }
    return mesh_reader_open(r2, s->path);
}

void mesh_spool_free(struct mesh_spool *s)
{
    if (s->f) { fclose(s->f); s->f = NULL; }
    if (s->temp && s->path) {
        unlink(s->path);
        for (int i = 0; i < MAX_TEMPS; i++)
            if (temps[i] == s->path) temps[i] = NULL;
    }
    free(s->path);
    s->path = NULL;
}
