/* tap.h -- minimal TAP output for C unit tests.
 *   ok(cond, "name %d", x);  ...  return tap_done();
 * Each unit test file is one program; prove runs it. */
#ifndef STOPMO_TAP_H
#define STOPMO_TAP_H
#include <stdarg.h>
#include <stdio.h>

static int tap_n, tap_fail;

__attribute__((format(printf, 2, 3))) static int ok(int cond, const char *fmt, ...)
{
    va_list ap;
    printf("%s %d - ", cond ? "ok" : "not ok", ++tap_n);
    va_start(ap, fmt);
    vprintf(fmt, ap);
    va_end(ap);
    printf("\n");
    if (!cond) tap_fail++;
    return cond;
}

#define diag(...) (printf("# "), printf(__VA_ARGS__), printf("\n"))

static int tap_done(void)
{
    printf("1..%d\n", tap_n);
    return tap_fail != 0;
}
#endif
