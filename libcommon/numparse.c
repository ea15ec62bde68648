/* numparse.c -- see numparse.h */
#include "numparse.h"
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <math.h>

static const double pow10tab[23] = {
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

const char *parse_double(const char *s, double *out)
{
    while (*s == ' ' || *s == '\t' || *s == '\r')
        s++;
    const char *start = s, *p = s;
    int neg = 0;
    if (*p == '-' || *p == '+')
        neg = (*p++ == '-');
    uint64_t m = 0;
    int digits = 0, exp10 = 0, any = 0;
    while (*p == '0') { p++; any = 1; }           /* leading zeros do not count */
    while (*p >= '0' && *p <= '9') {
        if (digits < 19) m = m * 10 + (uint64_t)(*p - '0');
        else exp10++;
        digits++; any = 1; p++;
    }
    if (*p == '.') {
        p++;
        if (digits == 0)
            while (*p == '0') { p++; exp10--; any = 1; }
        while (*p >= '0' && *p <= '9') {
            if (digits < 19) { m = m * 10 + (uint64_t)(*p - '0'); exp10--; }
            digits++; any = 1; p++;
        }
    }
    if (!any)
        goto slow;                                 /* inf, nan, junk */
    if (*p == 'e' || *p == 'E') {
        const char *q = p + 1;
        int eneg = 0, e = 0, edig = 0;
        if (*q == '-' || *q == '+')
            eneg = (*q++ == '-');
        while (*q >= '0' && *q <= '9') {
            if (e < 10000) e = e * 10 + (*q - '0');
            q++; edig++;
        }
        if (!edig)
            goto slow;
        exp10 += eneg ? -e : e;
        p = q;
    }
    if (digits > 15 || m > (1ULL << 53))
        goto slow;
    double v = (double)m;
    if (exp10 < 0) {
        if (exp10 < -22) goto slow;
        v /= pow10tab[-exp10];
    } else if (exp10 > 0) {
        if (exp10 > 22) goto slow;
        v *= pow10tab[exp10];
    }
    *out = neg ? -v : v;
    return p;
slow:;
    char *end;
    double v2 = strtod(start, &end);
    if (end == start)
        return NULL;
    *out = v2;
    return end;
}

const char *parse_long(const char *s, long *out)
{
    while (*s == ' ' || *s == '\t' || *s == '\r')
        s++;
    const char *p = s;
    int neg = 0;
    if (*p == '-' || *p == '+')
        neg = (*p++ == '-');
    if (*p < '0' || *p > '9')
        return NULL;
    long v = 0;
    while (*p >= '0' && *p <= '9') {
        int d = *p++ - '0';
        if (v > (LONG_MAX - d) / 10)
            return NULL;
        v = v * 10 + d;
    }
    *out = neg ? -v : v;
    return p;
}

int format_double(char *buf, double x)
{
    if (x == 0) {                      /* keep the sign of -0 bit-exact */
        buf[0] = '0'; buf[1] = 0;
        if (signbit(x)) { buf[0] = '-'; buf[1] = '0'; buf[2] = 0; return 2; }
        return 1;
    }
    /* for normal doubles a shorter round-trip decimal is also what %.15g
     * prints (it is the nearest 15-digit decimal); subnormals have fewer
     * significant bits, so search them from 1 digit */
    int first = fabs(x) < DBL_MIN ? 1 : 15;
    for (int prec = first; prec <= 17; prec++) {
        int n = snprintf(buf, 32, "%.*g", prec, x);
        double y;
        if (prec == 17 || (parse_double(buf, &y) && y == x))
            return n;
    }
    return 0;
}
