/* fuzz_rings.c -- 2D outline files (rings.h).  Oracle: rings that read
 * are written and read back bit-exact; simple rings have an exact
 * orientation (rings_orientation), and after rings_orient the outer ring is
 * counter-clockwise and every other clockwise; every ring's roundness
 * (polygon_roundness, any polygon) is in [0, 1]. */
#include "fuzz_common.h"
#include "rings.h"

FUZZ_TARGET(rings)(const uint8_t *data, size_t size)
{
    char path[64];
    fuzz_file(data, size, ".rings", path);
    struct rings r;
    if (rings_read(path, &r) == 0) {
        char *buf = NULL;
        size_t len = 0;
        FILE *w = open_memstream(&buf, &len);
        if (!w || rings_write(w, &r) < 0) fuzz_fail("rings: write");
        fclose(w);
        char p2[64];
        fuzz_file((const uint8_t *)buf, len, ".rings", p2);
        struct rings b;
        if (rings_read(p2, &b) < 0) fuzz_fail("rings: copy does not read");
        if (b.nrings != r.nrings || memcmp(b.start, r.start, (size_t)(r.nrings + 1) * sizeof *r.start) ||
            memcmp(b.P, r.P, 2 * (size_t)r.start[r.nrings] * sizeof *r.P))
            fuzz_fail("rings: round trip differs");
        rings_free(&b);
        fuzz_file_done(p2);
        free(buf);
        for (int k = 0; k < r.nrings && r.start[r.nrings] <= 4096; k++) {
            double x = polygon_roundness(rings_ring(&r, k), rings_count(&r, k));
            if (!(x >= 0 && x <= 1)) fuzz_fail("rings: roundness outside [0, 1]");
        }
        if (r.start[r.nrings] <= 4096 && rings_check_simple(&r) == 0) {
            /* simple rings: the exact orientation is never 0, the outer
             * ring comes out counter-clockwise and the holes clockwise */
            for (int k = 0; k < r.nrings; k++)
                if (rings_orientation(&r, k) == 0) fuzz_fail("rings: a simple ring without orientation");
            rings_orient(&r);
            if (rings_orientation(&r, 0) != 1) fuzz_fail("rings: outer ring clockwise after rings_orient");
            for (int k = 1; k < r.nrings; k++)
                if (rings_orientation(&r, k) != -1) fuzz_fail("rings: a hole counter-clockwise after rings_orient");
        }
        rings_free(&r);
    }
    fuzz_file_done(path);
    return 0;
}
