/* big_alloc: big_calloc is zero-filled at every size, also where the
 * allocator hands back memory that was just written and freed (the pages
 * dropped with MADV_DONTNEED read as zeros); big_alloc's arrays are
 * 2 MB-aligned from 2 MB on; mapped_release leaves a file mapping's data
 * readable */
#include "big_alloc.h"
#include "mapped_frames.h"
#include "tap.h"
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

static int all_zero(const unsigned char *p, size_t n)
{
    for (size_t i = 0; i < n; i++)
        if (p[i]) return 0;
    return 1;
}

int main(void)
{
    size_t sizes[] = {1, 4096, (size_t)1 << 20, ((size_t)2 << 20) + 12345, ((size_t)32 << 20) + 12345, (size_t)64 << 20};
    for (int k = 0; k < 6; k++) {
        size_t n = sizes[k];
        int zero = 1;
        for (int round = 0; round < 3; round++) {
            unsigned char *d = big_alloc(n);        /* dirtied, freed: may come back below */
            if (!d) { zero = 0; break; }
            memset(d, 0xa5, n);
            free(d);
            unsigned char *z = big_calloc(n);
            if (!z) { zero = 0; break; }
            zero &= all_zero(z, n);
            memset(z, 0x5a, n);                     /* dirty it too: the next round may get it */
            free(z);
        }
        ok(zero, "big_calloc(%zu) is zero-filled after dirtied memory was freed (3 rounds)", n);
    }
    void *a = big_alloc((size_t)40 << 20);
    ok(a && ((uintptr_t)a & (((uintptr_t)2 << 20) - 1)) == 0, "big_alloc(40 MB) is 2 MB-aligned");
    free(a);
    a = big_alloc((size_t)3 << 20);
    ok(a && ((uintptr_t)a & (((uintptr_t)2 << 20) - 1)) == 0, "big_alloc(3 MB) is 2 MB-aligned");
    free(a);

    /* mapped_release on a file mapping: the data read again after it */
    char path[4096];
    const char *tmp = getenv("TMPDIR");
    snprintf(path, sizeof path, "%s/big_alloc_unitXXXXXX", tmp && *tmp ? tmp : "/tmp");
    int fd = mkstemp(path);
    size_t fl = 5 * 4096 + 100;
    unsigned char *buf = malloc(fl);
    int rel = fd >= 0 && buf;
    if (rel) {
        for (size_t i = 0; i < fl; i++) buf[i] = (unsigned char)(i * 7 + 3);
        rel = write(fd, buf, fl) == (ssize_t)fl;
    }
    unsigned char *m = rel ? mmap(NULL, fl, PROT_READ, MAP_PRIVATE, fd, 0) : MAP_FAILED;
    if (m != MAP_FAILED) {
        volatile unsigned s = 0;
        for (size_t i = 0; i < fl; i++) s += m[i];
        mapped_release(m + 100, m + fl - 50);       /* whole pages inside only */
        mapped_release(m + 10, m + 20);             /* none */
        rel = memcmp(m, buf, fl) == 0;
        munmap(m, fl);
    } else
        rel = 0;
    ok(rel, "mapped_release: a file mapping reads the same after its pages are released");
    if (fd >= 0) { close(fd); unlink(path); }
    free(buf);
    return tap_done();
}
