/* textline.h -- one line of a text file, with the limits every stopmo
 * text reader holds (stopmo-columns(5), stopmo-rings(5)):
 *   a line is at most TEXTLINE_MAX bytes ('\n' not counted), so one huge
 *   line (a runaway comment) costs no more than that in memory;
 *   a NUL byte is never text (binary data, or the zero-filled tail of a
 *   write that crashed): it is an error, not the end of the line.
 */
#ifndef CM_TEXTLINE_H
#define CM_TEXTLINE_H
#include <stdio.h>
#ifdef __cplusplus
extern "C" {
#endif

#define TEXTLINE_MAX (1 << 20)

/* Read the next line of f into *buf (grown as needed, capacity *cap),
 * NUL terminated, without its '\n' (a '\r' before it stays).
 *   name    file name for messages
 *   lineno  the number of this line (for messages)
 * Returns its length (>= 0), -1 at the end of the input, -2 on an error
 * (read error, line too long, NUL byte) with the message in cm_errmsg():
 * "cannot read 'NAME': line N: problem". */
long textline_read(FILE *f, char **buf, size_t *cap, const char *name, long lineno);

#ifdef __cplusplus
}
#endif
#endif
