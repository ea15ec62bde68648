/* fuzz_meshio.c -- OBJ, OFF, PLY and STL readers (meshio.h).  The first
 * byte picks the format.  Oracle for OBJ and OFF (exact decimal parsers):
 * a mesh that reads is written in the same format and must read back
 * bit-exact. */
#include "fuzz_common.h"
#include "meshio.h"

FUZZ_TARGET(meshio)(const uint8_t *data, size_t size)
{
    if (size < 1) return 0;
    static const int fmts[4] = {MESHIO_OBJ, MESHIO_OFF, MESHIO_PLY, MESHIO_STL};
    int fmt = fmts[data[0] & 3];
    char path[64];
    fuzz_file(data + 1, size - 1, "", path);
    struct mesh m;
    if (meshio_read(path, fmt, &m) == 0 && (fmt == MESHIO_OBJ || fmt == MESHIO_OFF)) {
        char *buf = NULL;
        size_t len = 0;
        FILE *w = open_memstream(&buf, &len);
        if (!w || meshio_write(w, "<fuzz>", fmt, 0, m.nv, m.nf, m.F, m.V) < 0) fuzz_fail("meshio: write");
        fclose(w);
        char p2[64];
        fuzz_file((const uint8_t *)buf, len, "", p2);
        struct mesh b;
        if (meshio_read(p2, fmt, &b) < 0) fuzz_fail("meshio: written copy does not read");
        if (b.nv != m.nv || b.nf != m.nf || memcmp(b.F, m.F, (size_t)m.nf * 3 * sizeof *m.F) ||
            memcmp(b.V, m.V, (size_t)m.nv * 3 * sizeof *m.V))
            fuzz_fail("meshio: round trip differs");
        mesh_free(&b);
        fuzz_file_done(p2);
        free(buf);
    }
    mesh_free(&m);
    fuzz_file_done(path);
    return 0;
}
