/* numparse.c -- see numparse.h */
#include "numparse.h"
#include "shortest.h"
#include <errno.h>
#include <float.h>
#include <limits.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <math.h>
#include <string.h>

static const uint64_t p10u[18] = {
    1ULL, 10ULL, 100ULL, 1000ULL, 10000ULL, 100000ULL, 1000000ULL, 10000000ULL, 100000000ULL,
    1000000000ULL, 10000000000ULL, 100000000000ULL, 1000000000000ULL, 10000000000000ULL,
    100000000000000ULL, 1000000000000000ULL, 10000000000000000ULL, 100000000000000000ULL};

static const double pow10tab[23] = {
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
    1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

#if LDBL_MANT_DIG == 64
static const long double pow10tabl[28] = {
    1e0L, 1e1L, 1e2L, 1e3L, 1e4L, 1e5L, 1e6L, 1e7L, 1e8L, 1e9L, 1e10L, 1e11L, 1e12L, 1e13L,
    1e14L, 1e15L, 1e16L, 1e17L, 1e18L, 1e19L, 1e20L, 1e21L, 1e22L, 1e23L, 1e24L, 1e25L,
    1e26L, 1e27L};
/* 10^-k rounded to extended precision */
static const long double inv10tabl[28] = {
    1e-0L, 1e-1L, 1e-2L, 1e-3L, 1e-4L, 1e-5L, 1e-6L, 1e-7L, 1e-8L, 1e-9L, 1e-10L, 1e-11L,
    1e-12L, 1e-13L, 1e-14L, 1e-15L, 1e-16L, 1e-17L, 1e-18L, 1e-19L, 1e-20L, 1e-21L, 1e-22L,
    1e-23L, 1e-24L, 1e-25L, 1e-26L, 1e-27L};
#endif

/* Append the decimal digits at *pp to m (m wraps past 19 digits; callers
 * count the digits and give up then).  This loop is most of the cost of
 * reading a plain MESH stream.  With `padded` (the caller guarantees 8
 * readable bytes past any position of the string, its NUL included),
 * eight digits at a time are checked and converted in one 64-bit word
 * (SWAR, as in fast_float); the rest byte by byte. */
static inline uint64_t scan_digits(const char **pp, uint64_t m, int padded)
{
    const char *p = *pp;
#if __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    if (padded) {
        static const uint64_t p10[9] = {1, 10, 100, 1000, 10000, 100000, 1000000,
                                        10000000, 100000000};
        for (;;) {
            uint64_t v;
            memcpy(&v, p, sizeof v);
            /* high bit of every byte that is not a digit ('0' ^ 0x30 = 0,
             * digits 0..9; 0x76 pushes 10..127 over 127, no carries) */
            uint64_t x = v ^ 0x3030303030303030ULL;
            uint64_t nd = (((x & 0x7F7F7F7F7F7F7F7FULL) + 0x7676767676767676ULL) | x) &
                          0x8080808080808080ULL;
            int n = nd ? __builtin_ctzll(nd) >> 3 : 8;
            if (n == 0)
                break;
            /* right-align the n digits behind '0' fill: 8 digits in one word */
            if (n < 8)
                v = (v << (64 - 8 * n)) | (0x3030303030303030ULL >> (8 * n));
            v -= 0x3030303030303030ULL;
            v = v * 10 + (v >> 8);
            v = (((v & 0x000000FF000000FFULL) * 0x000F424000000064ULL) +
                 (((v >> 16) & 0x000000FF000000FFULL) * 0x0000271000000001ULL)) >> 32;
            m = m * p10[n] + (uint32_t)v;
            p += n;
            if (n < 8)
                break;
        }
        *pp = p;
        return m;
    }
#else
    (void)padded;
#endif
    while ((unsigned)(*p - '0') < 10) { m = m * 10 + (uint64_t)(*p - '0'); p++; }
    *pp = p;
    return m;
}

#if LDBL_MANT_DIG == 64 && defined(__SIZEOF_INT128__)
typedef unsigned __int128 u128;

/* sign of X - Y * 2^s, exactly */
static int cmp_shift(u128 X, u128 Y, int s)
{
    if (s < 0)
        return -cmp_shift(Y, X, -s);
    u128 q = s >= 128 ? 0 : X >> s;
    u128 rem = s >= 128 ? X : X & (((u128)1 << s) - 1);
    if (q != Y)
        return q > Y ? 1 : -1;
    return rem != 0;
}

/* sign of m * 10^e - D * 2^Q (|e| <= 27, D < 2^54): which side of the
 * midpoint D 2^Q the decimal m 10^e lies on */
static int tie_side(uint64_t m, int e, uint64_t D, int Q)
{
    static const uint64_t pow5[28] = {
        1ULL, 5ULL, 25ULL, 125ULL, 625ULL, 3125ULL, 15625ULL, 78125ULL, 390625ULL,
        1953125ULL, 9765625ULL, 48828125ULL, 244140625ULL, 1220703125ULL, 6103515625ULL,
        30517578125ULL, 152587890625ULL, 762939453125ULL, 3814697265625ULL,
        19073486328125ULL, 95367431640625ULL, 476837158203125ULL, 2384185791015625ULL,
        11920928955078125ULL, 59604644775390625ULL, 298023223876953125ULL,
        1490116119384765625ULL, 7450580596923828125ULL};
    if (e < 0)   /* m / (5^k 2^k) vs D 2^Q  <=>  m vs D 5^k 2^(Q+k) */
        return cmp_shift(m, (u128)D * pow5[-e], Q - e);
    /* m 5^e 2^e vs D 2^Q  <=>  m 5^e vs D 2^(Q-e) */
    return cmp_shift((u128)m * pow5[e], D, Q - e);
}
#endif

/* m * 10^exp10 (m has `digits` significant digits, at most 19), negated
 * if neg, correctly rounded into *out: returns 1, or 0 when the value
 * needs strtod (more digits or exponent than the fast paths take, or a
 * near-tie they cannot decide). */
static inline __attribute__((always_inline)) int
decimal_to_double(uint64_t m, int digits, int exp10, int neg, double *out)
{
    if (digits <= 15 && exp10 >= -22 && exp10 <= 22) {
        /* Clinger's fast path: m and 10^|e| are exact doubles, one
         * correctly rounded multiply or divide */
        double v = (double)m;
        if (exp10 < 0) v /= pow10tab[-exp10];
        else if (exp10 > 0) v *= pow10tab[exp10];
        *out = neg ? -v : v;
        return 1;
    }
    {
#if LDBL_MANT_DIG == 64
        /* 16..19 digits (what %.17g prints for computed coordinates): m is
         * exact in x87 extended precision, so is 10^k for k <= 27, and one
         * multiply or divide rounds once to 64 bits.  Rounding that to
         * double gives the correctly rounded result unless the extended
         * value is exactly a midpoint between two doubles (the only
         * 64-bit number that can separate the true value from its
         * 64-bit rounding); those rare ties go to strtod. */
        if (exp10 < 0 && exp10 >= -27 && digits <= 19) {
            /* the common case of coordinates: multiply by the rounded
             * reciprocal instead of dividing (x87 fdiv is slow); two
             * roundings leave r within 2 units of its last place of the
             * exact value, which rounds correctly to double unless r is
             * that close to a midpoint; those take the exact division */
            long double r = (long double)m * inv10tabl[-exp10];
            uint64_t sig;
            memcpy(&sig, &r, sizeof sig);
            unsigned low = (unsigned)(sig & 0x7ff);
            if (low < 0x3fe || low > 0x402) {
                double d = (double)r;
                *out = neg ? -d : d;
                return 1;
            }
        }
        if (digits <= 19 && exp10 >= -27 && exp10 <= 27) {
            long double r = (long double)m;
            if (exp10 < 0) r /= pow10tabl[-exp10];
            else if (exp10 > 0) r *= pow10tabl[exp10];
            /* x87 layout: the 64-bit significand (explicit leading 1)
             * first; r lies in the normal double range, so it is a
             * midpoint iff its low 11 bits are 100 0000 0000 */
            uint64_t sig;
            memcpy(&sig, &r, sizeof sig);
            double d = (double)r;
            if ((sig & 0x7ff) == 0x400) {
#ifdef __SIZEOF_INT128__
                /* r is a midpoint: (double)r rounded to even; decide
                 * exactly on which side of r the decimal lies */
                uint16_t ex;
                memcpy(&ex, (const char *)&r + 8, sizeof ex);
                int c = tie_side(m, exp10, sig >> 10, (int)(ex & 0x7fff) - 16383 - 63 + 10);
                if (c != 0 && (c > 0) != ((long double)d > r))
                    d = nextafter(d, c > 0 ? INFINITY : -INFINITY);
#else
                return 0;
#endif
            }
            *out = neg ? -d : d;
            return 1;
        }
        if (digits <= 19 && exp10 >= -54 && exp10 <= 54) {
            /* tiny roundoff values like 1.5e-19 and huge ones: two exact
             * powers, two roundings, so r may be up to 2 units of its last
             * place from the exact value; it rounds correctly unless it is
             * that close to a midpoint (then strtod) */
            long double r = (long double)m;
            if (exp10 < 0) r = r / pow10tabl[27] / pow10tabl[-exp10 - 27];
            else r = r * pow10tabl[27] * pow10tabl[exp10 - 27];
            uint64_t sig;
            memcpy(&sig, &r, sizeof sig);
            unsigned low = (unsigned)(sig & 0x7ff);
            if (low >= 0x3fe && low <= 0x402)
                return 0;
            double d = (double)r;
            *out = neg ? -d : d;
            return 1;
        }
#endif
        return 0;
    }
}

static inline __attribute__((always_inline)) const char *
parse_double_impl(const char *s, double *out, int padded)
{
    while (*s == ' ' || *s == '\t' || *s == '\r')
        s++;
    const char *start = s, *p = s;
    int neg = 0;
    if (*p == '-' || *p == '+')
        neg = (*p++ == '-');
    /* Scan the digits with as little work per digit as possible (this loop
     * is most of the cost of reading a plain MESH stream): m may wrap when
     * there are more than 19 significant digits, but those go to strtod. */
    uint64_t m = 0;
    int digits, exp10 = 0, any;
    if (padded && (unsigned)(p[0] - '0') < 10 && p[1] == '.') {
        /* fast lane for the usual shape of a coordinate, "d.ddd" with up
         * to 18 decimals and no exponent: fewer unpredictable branches
         * (fraction zeros are not skipped, they count as digits) */
        const char *f0 = p + 2, *q = f0;
        m = scan_digits(&q, (uint64_t)(p[0] - '0'), 1);
        int nf = (int)(q - f0);
        if (nf >= 1 && nf <= 18 && (*q | 0x20) != 'e') {
            p = q;
            digits = nf + 1;
            exp10 = -nf;
            goto convert;
        }
        m = 0;
    }
    const char *d0 = p;
    while (*p == '0') p++;                          /* leading zeros do not count */
    const char *i0 = p;
    m = scan_digits(&p, 0, padded);
    digits = (int)(p - i0);
    any = p > d0;
    if (*p == '.') {
        p++;
        const char *f0 = p;
        if (digits == 0)
            while (*p == '0') p++;                  /* 0.000ddd: zeros only scale */
        const char *f1 = p;
        m = scan_digits(&p, m, padded);
        digits += (int)(p - f1);
        exp10 = -(int)(p - f0);
        any |= p > f0;
    }
    if (digits > 19)
        goto slow;
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
convert:
    if (decimal_to_double(m, digits, exp10, neg, out))
        return p;
slow:;
    char *end;
    double v2 = strtod(start, &end);
    if (end == start)
        return NULL;
    *out = v2;
    return end;
}

const char *parse_double(const char *s, double *out)
{
    return parse_double_impl(s, out, 0);
}

const char *parse_double_padded(const char *s, double *out)
{
    return parse_double_impl(s, out, 1);
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

/* Lay out the decimal s * 10^(e - k + 1) (s has exactly k digits, the
 * last one nonzero) the way printf's %.Pg does (P >= k): scientific
 * notation when e < -4 or e >= P, else positional; printf drops the
 * trailing zeros of its P digits, which leaves the k of s.  Returns the
 * length. */
static int layout_g(char *buf, int neg, uint64_t s, int k, int P, int e)
{
    static const char dig2[201] =
        "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
        "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
        "8081828384858687888990919293949596979899";
    /* the k digits of s into t[24 - k .. 23]: two 8-digit halves in 32
     * bits, two digits per step */
    char t[24];
    char *end = t + 24, *d = end;
    uint32_t lo = (uint32_t)(s % 100000000), hi32;
    uint64_t hi = s / 100000000;
    if (hi) {
        for (int i = 0; i < 4; i++) { d -= 2; memcpy(d, dig2 + 2 * (lo % 100), 2); lo /= 100; }
        uint32_t mid = (uint32_t)(hi % 100000000);
        hi32 = (uint32_t)(hi / 100000000);          /* < 10 for k <= 17 */
        if (hi32) {
            for (int i = 0; i < 4; i++) { d -= 2; memcpy(d, dig2 + 2 * (mid % 100), 2); mid /= 100; }
            *--d = (char)('0' + hi32);
        } else {
            while (mid >= 100) { d -= 2; memcpy(d, dig2 + 2 * (mid % 100), 2); mid /= 100; }
            if (mid >= 10) { d -= 2; memcpy(d, dig2 + 2 * mid, 2); } else *--d = (char)('0' + mid);
        }
    } else {
        while (lo >= 100) { d -= 2; memcpy(d, dig2 + 2 * (lo % 100), 2); lo /= 100; }
        if (lo >= 10) { d -= 2; memcpy(d, dig2 + 2 * lo, 2); } else *--d = (char)('0' + lo);
    }
    char *o = buf;
    *o = '-';
    o += neg;
    if (e < -4 || e >= P) {
        *o++ = d[0];
        if (k > 1) { *o++ = '.'; memcpy(o, d + 1, (size_t)k - 1); o += k - 1; }
        *o++ = 'e';
        *o++ = e < 0 ? '-' : '+';
        int ae = e < 0 ? -e : e;
        if (ae >= 100) *o++ = (char)('0' + ae / 100);
        memcpy(o, dig2 + 2 * (ae % 100), 2);
        o += 2;
    } else if (e >= 0) {
        if (k <= e + 1) {
            memcpy(o, d, (size_t)k); o += k;
            for (int i = k; i <= e; i++) *o++ = '0';
        } else {
            memcpy(o, d, (size_t)e + 1); o += e + 1;
            *o++ = '.';
            memcpy(o, d + e + 1, (size_t)(k - e - 1)); o += k - e - 1;
        }
    } else {
        memcpy(o, "0.0000", (size_t)(1 - e));       /* "0." and -e - 1 zeros */
        o += 1 - e;
        memcpy(o, d, (size_t)k); o += k;
    }
    *o = 0;
    return (int)(o - buf);
}

/* The shortest decimal that reads back to x (shortest_decimal: Dragonbox),
 * laid out as %.Pg with P = max(15, its digits).  For a normal double
 * that is what the shortest of %.15g, %.16g, %.17g that reads back
 * prints: a decimal of 15 or fewer digits that reads back is within half
 * an ulp (< 1.2e-16 relative) of x, nearer than half the 15-digit spacing
 * (>= 5e-16 relative), so %.15g prints it; with 16 or 17 digits both are
 * the nearest decimal of that length.  Subnormals print in the same %e
 * form as %.Pg with their own (shorter) P.  Infinities and NaNs as printf
 * prints them. */
int format_double(char *buf, double x)
{
    if (x == 0) {                      /* keep the sign of -0 bit-exact */
        buf[0] = '0'; buf[1] = 0;
        if (signbit(x)) { buf[0] = '-'; buf[1] = '0'; buf[2] = 0; return 2; }
        return 1;
    }
    if (!isfinite(x))
        return snprintf(buf, 32, "%g", x);
    uint64_t s;
    int E;
    shortest_decimal(x, &s, &E);
    /* its digits: floor(log10 s) + 1, from the bit length (s < 10^17) */
    int t = ((64 - __builtin_clzll(s)) * 1233) >> 12;
    int k = t + (s >= p10u[t]);
    return layout_g(buf, x < 0, s, k, k < 15 ? 15 : k, E + k - 1);
}
