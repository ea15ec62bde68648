/* numparse.h -- fast, exact decimal <-> double conversion for the text streams.
 *
 * parse_double() takes the Clinger fast path (at most 15 significant digits,
 * |exponent| <= 22: one exact multiply or divide by a power of ten, which is
 * correctly rounded) and falls back to strtod() for everything else, so the
 * result is always the correctly rounded double.  About 5-10x strtod.
 *
 * format_double() writes what the first of %.15g, %.16g, %.17g that reads
 * back to the same double prints (so plain -> raw -> plain is bit-exact),
 * from the shortest decimal of x (shortest.h: Dragonbox, via {fmt}) laid
 * out in %g style, without printf.
 */
#ifndef CM_NUMPARSE_H
#define CM_NUMPARSE_H
#ifdef __cplusplus
extern "C" {
#endif

/* Parse one number starting at s (leading blanks skipped).
 * On success stores the value in *out, returns the pointer past the number.
 * Returns NULL if no number starts there.  Non-finite values are returned
 * as parsed (callers reject them). */
const char *parse_double(const char *s, double *out);

/* The same, faster on long digit strings, for callers whose buffer stays
 * readable for at least 8 bytes past the string's terminating NUL (the
 * MESH reader pads its line buffer). */
const char *parse_double_padded(const char *s, double *out);

/* Parse a decimal integer (leading blanks skipped); NULL if none/overflow. */
const char *parse_long(const char *s, long *out);

/* Write x into buf (>= 32 bytes) as the shortest round-trip decimal.
 * Returns the number of characters written. */
int format_double(char *buf, double x);

#ifdef __cplusplus
}
#endif
#endif
