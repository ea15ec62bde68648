/* cm_error.h -- the error channel of libcommon.
 *
 * libcommon never prints and never exits.  A function that fails returns a
 * negative value (or NULL) and leaves a one-line message here; the tool that
 * called it decides what to do (usually die("%s", cm_errmsg())).
 * Messages name the file and line where that makes sense:
 *   "cannot read 'x.mesh': line 12: expected 3 numbers"
 */
#ifndef CM_ERROR_H
#define CM_ERROR_H
#ifdef __cplusplus
extern "C" {
#endif

/* Set the message (printf format).  Returns -1 so callers can write
 * `return cm_seterr(...)`. */
int cm_seterr(const char *fmt, ...) __attribute__((format(printf, 1, 2)));

/* The last message set ("" if none).  Valid until the next cm_seterr(). */
const char *cm_errmsg(void);

#ifdef __cplusplus
}
#endif
#endif
