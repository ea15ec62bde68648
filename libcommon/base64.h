/* base64.h -- RFC 4648 base64 (standard alphabet, '=' padding, no line
 * breaks), the text form in which binary arrays go into HTML pages.
 */
#ifndef CM_BASE64_H
#define CM_BASE64_H
#include <stddef.h>
#include <stdio.h>
#ifdef __cplusplus
extern "C" {
#endif

/* Length of the encoding of n bytes: 4 * ceil(n / 3). */
static inline size_t base64_len(size_t n) { return (n + 2) / 3 * 4; }

/* Encode n bytes.
 *   in   n bytes
 *   out  base64_len(n) characters (out; not NUL-terminated) */
void base64_encode(const void *in, size_t n, char *out);

/* Encode n bytes onto f in blocks.  Returns -1 (cm_errmsg) on a write error. */
int base64_write(FILE *f, const void *in, size_t n);

/* Decode len characters (len a multiple of 4, '=' padding at the end only).
 *   out  at most 3 * len / 4 bytes (out)
 * Returns the number of bytes decoded, or -1 (cm_errmsg) on a bad character
 * or length. */
long base64_decode(const char *in, size_t len, unsigned char *out);

#ifdef __cplusplus
}
#endif
#endif
