/* mapped_frames.h -- animation frames read where they lie in a read-only
 * file mapping (mesh_reader_next_ref: raw MESH vertex blocks, little-endian
 * doubles at any byte offset) instead of being copied out of the file.
 *
 * mapped_double is a double at any alignment: code that reads such frames
 * takes `const mapped_double *` (GCC and Clang accept a typedef that lowers
 * the alignment; loads are then unaligned ones, the arithmetic the same).
 *
 * mapped_release drops a range of the mapping from the process's page
 * tables once it has been read (madvise MADV_DONTNEED): the data stay in
 * the page cache and fault in again if read later, so the resident set
 * stays a window of the file instead of growing to all of it.  Only for
 * read-only private FILE mappings: on anonymous memory it would zero the
 * data.
 */
#ifndef CM_MAPPED_FRAMES_H
#define CM_MAPPED_FRAMES_H
#ifdef __cplusplus
extern "C" {
#endif

typedef double mapped_double __attribute__((aligned(1)));

/* Release the whole pages inside [p0, p1) of a read-only private file
 * mapping; nothing when there are none.  Safe while other threads read
 * them (they fault in again). */
void mapped_release(const void *p0, const void *p1);

#ifdef __cplusplus
}
#endif
#endif
