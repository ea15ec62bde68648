/* fuzz_columns.c -- column files, labels and landmarks (columns.h,
 * landmarks.h).  Oracle: columns that read are written and read back
 * bit-exact. */
#include "fuzz_common.h"
#include "columns.h"
#include "landmarks.h"

FUZZ_TARGET(columns)(const uint8_t *data, size_t size)
{
    char path[64];
    fuzz_file(data, size, ".txt", path);
    struct columns c;
    if (columns_read(path, 0, -1, NULL, &c) == 0) {
        char *buf = NULL;
        size_t len = 0;
        FILE *w = open_memstream(&buf, &len);
        if (!w || columns_write(w, c.x, c.rows, c.cols) < 0) fuzz_fail("columns: write");
        fclose(w);
        char p2[64];
        fuzz_file((const uint8_t *)buf, len, ".txt", p2);
        struct columns b;
        if (columns_read(p2, c.cols, c.rows, NULL, &b) < 0) fuzz_fail("columns: copy does not read");
        if (memcmp(b.x, c.x, (size_t)c.rows * c.cols * sizeof *c.x)) fuzz_fail("columns: round trip differs");
        columns_free(&b);
        fuzz_file_done(p2);
        free(buf);
        columns_free(&c);
    }
    int *L = NULL, n = 0;
    if (labels_read(path, -1, "faces", 0, -1, &L, &n) == 0) free(L);
    static const double VT[30] = {0};
    struct landmarks lm;
    if (landmarks_read(path, 10, VT, 10, &lm) == 0) landmarks_free(&lm);
    fuzz_file_done(path);
    return 0;
}
