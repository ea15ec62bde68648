/* big_alloc.h -- large arrays on transparent huge pages.
 *
 * First-touch page faults of 4 KB pages cost seconds of system time per
 * gigabyte here (measured: 4.6 s sys for the Bunny-size dict-learn
 * benchmark); with the kernel's THP mode "madvise" (Debian's default) a
 * 2 MB-aligned block advised MADV_HUGEPAGE faults once per 2 MB.
 */
#ifndef CM_BIG_ALLOC_H
#define CM_BIG_ALLOC_H
#include <stddef.h>

/* bytes: the size.  Returns memory to release with free() (and that
 * realloc() accepts), 2 MB-aligned and advised for huge pages when bytes
 * >= 32 MB, else plain malloc(); NULL when out of memory. */
void *big_alloc(size_t bytes);

#endif
