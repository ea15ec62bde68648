/* numparse: parse_double_equals_strtod (random decimal strings of 1..25
 * digits, 17-digit %.17g output, exponents, edge cases), parse_long,
 * format_double_round_trips and is shortest */
#include "numparse.h"
#include "rng.h"
#include "tap.h"
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int same(double a, double b) { return memcmp(&a, &b, sizeof a) == 0; }

/* compare with strtod: value (bit-exact) and end pointer */
static int agrees(const char *s, char *why, size_t n)
{
    double a = 0, b;
    char *end;
    const char *p = parse_double(s, &a);
    b = strtod(s, &end);
    if (end == s) {
        if (p) { snprintf(why, n, "'%s': parsed, strtod did not", s); return 0; }
        return 1;
    }
    if (!p) { snprintf(why, n, "'%s': not parsed", s); return 0; }
    if (p != end) { snprintf(why, n, "'%s': end differs", s); return 0; }
    if (!same(a, b) && !(isnan(a) && isnan(b))) {
        snprintf(why, n, "'%s': %.17g vs strtod %.17g", s, a, b);
        return 0;
    }
    /* the padded variant (8 readable bytes past the NUL) agrees too */
    char pad[160];
    memset(pad, 0, sizeof pad);
    if (strlen(s) < 140) {
        strcpy(pad, s);
        double c = 0;
        const char *q = parse_double_padded(pad, &c);
        if (q - pad != end - s || (!same(c, b) && !(isnan(c) && isnan(b)))) {
            snprintf(why, n, "'%s': padded %.17g vs strtod %.17g", s, c, b);
            return 0;
        }
    }
    return 1;
}

int main(void)
{
    struct rng r;
    rng_seed(&r, 42);
    char buf[128], why[256] = "";
    int bad = 0;
    long tried = 0;

    /* random decimal strings: sign, 1..25 digits, a point anywhere, exponent */
    for (int it = 0; it < 150000; it++) {
        int nd = 1 + rng_int(&r, 25), k = 0;
        if (rng_int(&r, 3) == 0) buf[k++] = rng_int(&r, 2) ? '-' : '+';
        int point = rng_int(&r, nd + 2) - 1;        /* -1: no point */
        if (point == 0 && rng_int(&r, 2)) buf[k++] = '0';
        for (int d = 0; d < nd; d++) {
            if (d == point) buf[k++] = '.';
            int z = rng_int(&r, 4) == 0;           /* runs of zeros are common */
            buf[k++] = (char)('0' + (z ? 0 : rng_int(&r, 10)));
        }
        if (point == nd) buf[k++] = '.';
        if (rng_int(&r, 3) == 0)
            k += sprintf(buf + k, "%c%d", rng_int(&r, 2) ? 'e' : 'E',
                         rng_int(&r, 2) ? rng_int(&r, 40) - 20 : rng_int(&r, 700) - 350);
        buf[k] = 0;
        tried++;
        if (!agrees(buf, why, sizeof why) && bad++ < 5) diag("%s", why);
    }
    ok(bad == 0, "parse_double: equals strtod on %ld random decimal strings (%d differ)", tried, bad);

    /* %.17g, %.16g, %.15g of random doubles (17 significant digits: the
     * fast path's hard case) */
    bad = 0;
    tried = 0;
    for (int it = 0; it < 60000; it++) {
        double x;
        switch (it % 3) {
        case 0: x = rng_normal(&r) * pow(10, rng_int(&r, 20) - 10); break;
        case 1: x = rng_uniform(&r); break;
        default: { uint64_t u = rng_u64(&r); memcpy(&x, &u, sizeof x); if (!isfinite(x)) x = 1; }
        }
        for (int prec = 15; prec <= 17; prec++) {
            snprintf(buf, sizeof buf, "%.*g", prec, x);
            tried++;
            if (!agrees(buf, why, sizeof why) && bad++ < 5) diag("%s", why);
        }
    }
    ok(bad == 0, "parse_double: equals strtod on %ld printed doubles (%d differ)", tried, bad);

    /* 16..19 significant digits with exponents from -60 to 60: the x87
     * paths, their tie breaking and their fallbacks */
    bad = 0;
    tried = 0;
    for (int it = 0; it < 100000; it++) {
        int nd = 16 + rng_int(&r, 4), k = 0;
        if (rng_int(&r, 2)) buf[k++] = '-';
        buf[k++] = (char)('1' + rng_int(&r, 9));
        buf[k++] = '.';
        for (int d = 1; d < nd; d++) buf[k++] = (char)('0' + rng_int(&r, 10));
        k += sprintf(buf + k, "e%d", rng_int(&r, 121) - 60);
        tried++;
        if (!agrees(buf, why, sizeof why) && bad++ < 5) diag("%s", why);
    }
    ok(bad == 0, "parse_double: equals strtod on %ld long mantissas, wide exponents (%d differ)",
       tried, bad);
    /* exact midpoints between doubles and their neighbours: 17+ digit
     * decimals of (d1 + d2) / 2, the tie breaking's hard cases */
    bad = 0;
    tried = 0;
    for (int it = 0; it < 20000; it++) {
        double x = rng_uniform(&r) * pow(10, rng_int(&r, 20) - 10);
        double y = nextafter(x, INFINITY);
        long double mid = ((long double)x + y) / 2;
        for (int prec = 17; prec <= 19; prec++) {
            snprintf(buf, sizeof buf, "%.*Le", prec - 1, mid);
            tried++;
            if (!agrees(buf, why, sizeof why) && bad++ < 5) diag("%s", why);
        }
    }
    ok(bad == 0, "parse_double: equals strtod near midpoints (%ld strings, %d differ)", tried, bad);

    /* hand-picked hard and edge cases */
    static const char *edge[] = {
        "0", "-0", "+0", "0.0", "-0.0", ".5", "-.5", "5.", "1e0", "1E+2", "1e-2",
        "9007199254740993", "9007199254740992", "9007199254740991",
        "0.1", "0.2", "0.3", "1.7976931348623157e308", "2.2250738585072014e-308",
        "4.9406564584124654e-324", "2.4703282292062327e-324", "1e-400", "1e400",
        "123456789012345678901234567890", "0.000000000000000000000000000001",
        "3.14159265358979323846264338327950288", "1.00000000000000011102230246251565404",
        "1.00000000000000011102230246251565405", "8.98846567431158e307",
        "1e22", "1e23", "1e-22", "1e-23", "123456789012345e-22", "999999999999999e22",
        "0.99999999999999994", "0.99999999999999995", "inf", "-inf", "nan", "infinity",
        "1e", "1e+", "-", "+", ".", "e5", "", "  7", "\t-3.5", "1.5x", "0x1p3",
        "00000000000000000000000000001.5", "1.5e0000000000000000000001",
        NULL};
    bad = 0;
    for (int i = 0; edge[i]; i++)
        if (!agrees(edge[i], why, sizeof why) && strcmp(edge[i], "0x1p3")) {
            bad++;
            diag("%s", why);
        }
    ok(bad == 0, "parse_double: equals strtod on edge cases (%d differ)", bad);
    double h;
    const char *e = parse_double("0x1p3", &h);
    ok(e && *e == 'x' && h == 0, "parse_double: hexadecimal is not a MESH number (stops at 'x')");

    /* parse_long */
    long v;
    ok(parse_long(" 42 ", &v) && v == 42, "parse_long: 42");
    ok(parse_long("-7x", &v) && v == -7, "parse_long: -7 stops at x");
    ok(!parse_long("x", &v) && !parse_long("", &v) && !parse_long("-", &v), "parse_long: no digits");
    ok(!parse_long("99999999999999999999999", &v), "parse_long: overflow is rejected");
    ok(parse_long("9223372036854775800", &v) && v == 9223372036854775800L, "parse_long: large");

    /* format_double: round trip, shortest */
    bad = 0;
    int notshort = 0;
    for (int it = 0; it < 100000; it++) {
        double x, y;
        if (it % 2) { uint64_t u = rng_u64(&r); memcpy(&x, &u, sizeof x); if (!isfinite(x)) continue; }
        else x = rng_normal(&r) * pow(10, rng_int(&r, 30) - 15);
        if (it % 7 == 0) x = (double)rng_int(&r, 2000) / 8;     /* short ones */
        int n = format_double(buf, x);
        if (n != (int)strlen(buf) || !parse_double(buf, &y) || !same(x, y)) {
            if (bad++ < 5) diag("format_double(%.17g) = '%s'", x, buf);
            continue;
        }
        /* no %.Ng with fewer digits reads back */
        char b2[64];
        for (int p = 1; p < 15; p++) {
            snprintf(b2, sizeof b2, "%.*g", p, x);
            if (strtod(b2, NULL) == x && strlen(b2) < strlen(buf)) { notshort++; break; }
        }
    }
    ok(bad == 0, "format_double: round_trips bit-exactly (%d failures)", bad);
    ok(notshort == 0, "format_double: shortest (%d longer than needed)", notshort);

    /* format_double: the very text of the first %.Pg (P = 15, 16, 17; from
     * P = 1 for subnormals) that reads back, on random bit patterns, wide
     * ranges, 6-decimal data and subnormals.  The 16- and 17-digit cases
     * are where a candidate rounded from a longer one can read back while
     * not being printf's nearest decimal (the formatter before Dragonbox
     * printed such a neighbour for about 1 value in 200). */
    bad = 0;
    int checked = 0, long16 = 0;
    for (int it = 0; it < 250000; it++) {
        double x;
        uint64_t u = rng_u64(&r);
        switch (it % 5) {
        case 4:     /* few digits at every place: integers with zeros, 0.0005, 1e+16 */
            x = (double)(rng_int(&r, 200001) - 100000) * pow(10, rng_int(&r, 30) - 12); break;
        case 0: memcpy(&x, &u, sizeof x); if (!isfinite(x)) continue; break;
        case 1: x = rng_normal(&r) * pow(10, rng_int(&r, 40) - 20); break;
        case 2: x = (double)(rng_int(&r, 2000001) - 1000000) * 1e-6 + rng_int(&r, 300); break;
        default: x = ldexp((double)(u & 0xfffff), -1074 + (int)(u >> 60)); break;
        }
        char ref[64];
        int p = fabs(x) < DBL_MIN ? 1 : 15;
        for (; p < 17; p++) {
            snprintf(ref, sizeof ref, "%.*g", p, x);
            if (strtod(ref, NULL) == x) break;
        }
        if (p == 17) snprintf(ref, sizeof ref, "%.17g", x);
        if (x == 0) strcpy(ref, signbit(x) ? "-0" : "0");
        long16 += p >= 16;
        format_double(buf, x);
        checked++;
        if (strcmp(buf, ref) && bad++ < 5) diag("format_double(%.17g) = '%s', printf '%s'", x, buf, ref);
    }
    ok(bad == 0, "format_double: the text of the first %%.Pg that reads back (%d of %d differ; %d need 16-17 digits)",
       bad, checked, long16);
    static const double special[] = {0.0, -0.0, 1.0, -1.0, 0.1, 1e-300, 4.9406564584124654e-324,
                                     1.7976931348623157e308, 2.2250738585072014e-308, 123456.0};
    bad = 0;
    for (size_t i = 0; i < sizeof special / sizeof *special; i++) {
        double y;
        format_double(buf, special[i]);
        if (!parse_double(buf, &y) || !same(y, special[i])) { bad++; diag("'%s'", buf); }
    }
    ok(bad == 0, "format_double: special values incl. -0 and subnormals round trip");
    format_double(buf, 0.1);
    ok(!strcmp(buf, "0.1"), "format_double: 0.1 prints as 0.1 (%s)", buf);
    format_double(buf, -0.0);
    ok(!strcmp(buf, "-0"), "format_double: -0 prints as -0 (%s)", buf);
    return tap_done();
}
