/* big_alloc.h -- large arrays on transparent huge pages.
 *
 * First-touch page faults of 4 KB pages cost seconds of system time per
 * gigabyte here (measured: 4.6 s sys for the Bunny-size dict-learn
 * benchmark); with the kernel's THP mode "madvise" (Debian's default) a
 * 2 MB-aligned block advised MADV_HUGEPAGE faults once per 2 MB.  On a
 * paravirtualized guest with shadow page tables (this machine) a 4 KB fault
 * costs 10-12 us even on memory the process used before (128 MB: 0.4 s of
 * CPU), a 2 MB one about 0.1 ms on memory the guest has backed (0.01 s per
 * 128 MB; 0.19 s on memory it has not touched since boot), so arrays of a
 * few MB (a restart's n by d costs, a label step's tables) are worth it
 * too.
 */
#ifndef CM_BIG_ALLOC_H
#define CM_BIG_ALLOC_H
#include <stddef.h>

/* bytes: the size.  Returns memory to release with free() (and that
 * realloc() accepts, though a moved block is not on huge pages), 2
 * MB-aligned, rounded up to 2 MB and advised for huge pages when bytes >=
 * 2 MB, else plain malloc(); NULL when out of memory. */
void *big_alloc(size_t bytes);

/* The same, zero-filled (calloc's contract).  From 2 MB on, the pages are
 * dropped (MADV_DONTNEED: a private anonymous range then reads as zeros)
 * rather than written, so they are zeroed once, by the kernel, when first
 * touched, on huge pages: one fault per 2 MB instead of two per 4 KB (a
 * read, then a write, of a calloc'd array that is summed into). */
void *big_calloc(size_t bytes);

#endif
