/* mapped_frames.c -- see mapped_frames.h */
#include "mapped_frames.h"
#include <stdint.h>
#include <sys/mman.h>

void mapped_release(const void *p0, const void *p1)
{
    uintptr_t a = ((uintptr_t)p0 + 4095) & ~(uintptr_t)4095, e = (uintptr_t)p1 & ~(uintptr_t)4095;
    if (e > a) madvise((void *)a, e - a, MADV_DONTNEED);
}
