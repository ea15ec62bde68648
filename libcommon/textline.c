/* textline.c -- see textline.h */
#include "textline.h"
#include "cm_error.h"
#include <errno.h>
#include <stdlib.h>
#include <string.h>

long textline_read(FILE *f, char **buf, size_t *cap, const char *name, long lineno)
{
    size_t n = 0;
    int c = EOF;
    flockfile(f);
    while ((c = getc_unlocked(f)) != EOF && c != '\n') {
        if (c == 0) {
            funlockfile(f);
            return cm_seterr("cannot read '%s': line %ld: NUL byte in a text line", name, lineno) - 1;
        }
        if (n >= TEXTLINE_MAX) {
            funlockfile(f);
            return cm_seterr("cannot read '%s': line %ld: line longer than %d bytes", name, lineno,
                             TEXTLINE_MAX) - 1;
        }
        if (n + 1 >= *cap) {
            size_t nc = *cap ? 2 * *cap : 256;
            char *nb = realloc(*buf, nc);
            if (!nb) {
                funlockfile(f);
                return cm_seterr("cannot read '%s': line %ld: out of memory", name, lineno) - 1;
            }
            *buf = nb;
            *cap = nc;
        }
        (*buf)[n++] = (char)c;
    }
    funlockfile(f);
    if (c == EOF) {
        if (ferror(f))
            return cm_seterr("cannot read '%s': %s", name, strerror(errno)) - 1;
        if (n == 0)
            return -1;
    }
    if (!*buf) {
        if (!(*buf = malloc(1)))
            return cm_seterr("cannot read '%s': out of memory", name) - 1;
        *cap = 1;
    }
    (*buf)[n] = 0;
    return (long)n;
}
