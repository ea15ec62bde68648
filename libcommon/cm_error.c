/* cm_error.c -- see cm_error.h */
#include "cm_error.h"
#include <stdarg.h>
#include <stdio.h>

static _Thread_local char msg[1024];

int cm_seterr(const char *fmt, ...)
{
    char tmp[1024];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(tmp, sizeof tmp, fmt, ap);   /* fmt may mention cm_errmsg() */
    va_end(ap);
    snprintf(msg, sizeof msg, "%s", tmp);
    return -1;
}

const char *cm_errmsg(void) { return msg; }
