/* big_alloc.c -- large arrays on transparent huge pages (see big_alloc.h). */
#include "big_alloc.h"
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

void *big_alloc(size_t bytes)
{
    if (bytes < ((size_t)2 << 20)) return malloc(bytes);
    void *p = NULL;
    size_t align = (size_t)2 << 20;
    if (posix_memalign(&p, align, (bytes + align - 1) / align * align) != 0) return NULL;
#ifdef MADV_HUGEPAGE
    madvise(p, (bytes + align - 1) / align * align, MADV_HUGEPAGE);
#endif
    return p;
}

void *big_calloc(size_t bytes)
{
    if (bytes < ((size_t)2 << 20)) return calloc(1, bytes ? bytes : 1);
    size_t align = (size_t)2 << 20, len = (bytes + align - 1) / align * align;
    void *p = big_alloc(bytes);
    if (p && madvise(p, len, MADV_DONTNEED) != 0) memset(p, 0, bytes);
    return p;
}
