/* fuzz_mesh.c -- the MESH stream reader, plain and raw (mesh.h).
 * Oracle: a stream that reads is written raw and read back, then written
 * plain and read back; topology and every coordinate must come back
 * bit-exact (the plain-raw round trip of stopmo-mesh(5)). */
#include "fuzz_common.h"
#include "mesh.h"

/* read a whole stream from f (frames kept up to a budget) */
static int read_all(FILE *f, struct mesh *m, size_t budget)
{
    struct mesh_reader r;
    memset(m, 0, sizeof *m);
    if (mesh_reader_open_stream(&r, f, "<fuzz>", 0) < 0) return -1;
    size_t fs = (size_t)r.nv * 3;
    int rc = 0;
    m->nv = r.nv;
    m->nf = r.nf;
    m->F = malloc(((size_t)r.nf * 3 + 1) * sizeof *m->F);
    memcpy(m->F, r.F, (size_t)r.nf * 3 * sizeof *m->F);
    for (;;) {
        if ((size_t)(m->nframes + 1) * (fs + 1) > budget) { rc = -2; break; }
        m->V = realloc(m->V, ((size_t)(m->nframes + 1) * fs + 1) * sizeof *m->V);
        m->cut = realloc(m->cut, (size_t)m->nframes + 1);
        int c = 0;
        int k = mesh_reader_next(&r, m->V + (size_t)m->nframes * fs, &c);
        if (k < 0) { rc = -1; break; }
        if (k == 0) break;
        m->cut[m->nframes++] = (unsigned char)c;
    }
    mesh_reader_close(&r);
    return rc;
}

static void same(const struct mesh *a, const struct mesh *b)
{
    if (a->nv != b->nv || a->nf != b->nf || a->nframes != b->nframes) fuzz_fail("mesh: counts differ");
    if (memcmp(a->F, b->F, (size_t)a->nf * 3 * sizeof *a->F)) fuzz_fail("mesh: faces differ");
    if (memcmp(a->V, b->V, (size_t)a->nframes * a->nv * 3 * sizeof *a->V)) fuzz_fail("mesh: coordinates differ");
    for (int k = 1; k < a->nframes; k++)
        if (!a->cut[k] != !b->cut[k]) fuzz_fail("mesh: cut marks differ");
}

static void round_trip(const struct mesh *m, int raw)
{
    char *buf = NULL;
    size_t len = 0;
    FILE *w = open_memstream(&buf, &len);
    if (!w || mesh_write(w, m, raw) < 0) fuzz_fail("mesh: write");
    fclose(w);
    FILE *f = fmemopen(buf, len, "rb");
    struct mesh back;
    if (!f || read_all(f, &back, (size_t)1 << 26) != 0) fuzz_fail(raw ? "mesh: raw copy does not read" : "mesh: plain copy does not read");
    fclose(f);
    same(m, &back);
    mesh_free(&back);
    free(buf);
}

FUZZ_TARGET(mesh)(const uint8_t *data, size_t size)
{
    FILE *f = fmemopen((void *)data, size, "rb");
    if (!f) return 0;
    struct mesh m;
    int rc = read_all(f, &m, (size_t)1 << 22);
    fclose(f);
    if (rc == 0 && m.nframes > 0) {
        round_trip(&m, 1);
        round_trip(&m, 0);
    }
    mesh_free(&m);
    /* the same bytes from a regular file (the file-size checks) */
    char path[64];
    fuzz_file(data, size, ".mesh", path);
    struct mesh_reader r;
    if (mesh_reader_open(&r, path) == 0) {
        if (r.nv <= (1 << 18)) {
            double *X = malloc(((size_t)r.nv * 3 + 1) * sizeof *X);
            int k = 0;
            while (k++ < 64 && mesh_reader_next(&r, X, NULL) > 0) {}
            free(X);
        }
        mesh_reader_close(&r);
    }
    fuzz_file_done(path);
    return 0;
}
