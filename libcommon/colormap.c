/* colormap.c -- see colormap.h */
#include "colormap.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const unsigned char palette[][3] = {
    {0x1f, 0x77, 0xb4}, {0xff, 0x7f, 0x0e}, {0x2c, 0xa0, 0x2c}, {0xd6, 0x27, 0x28},
    {0x94, 0x67, 0xbd}, {0x8c, 0x56, 0x4b}, {0xe3, 0x77, 0xc2}, {0xbc, 0xbd, 0x22},
    {0x17, 0xbe, 0xcf}, {0xae, 0xc7, 0xe8}, {0xff, 0xbb, 0x78}, {0x98, 0xdf, 0x8a},
    {0xff, 0x98, 0x96}, {0xc5, 0xb0, 0xd5}, {0xc4, 0x9c, 0x94}, {0xf7, 0xb6, 0xd2},
    {0xdb, 0xdb, 0x8d},
};
#define NPAL ((int)(sizeof palette / sizeof palette[0]))

static unsigned char to_byte(double x)
{
    x = x < 0 ? 0 : x > 1 ? 1 : x;
    return (unsigned char)(255 * x + 0.5);
}

static void hsv(double h, double s, double v, unsigned char rgb[3])
{
    h = 6 * (h - floor(h));
    int i = (int)h;
    double f = h - i, p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    double r, g, b;
    switch (i % 6) {
    case 0: r = v; g = t; b = p; break;
    case 1: r = q; g = v; b = p; break;
    case 2: r = p; g = v; b = t; break;
    case 3: r = p; g = q; b = v; break;
    case 4: r = t; g = p; b = v; break;
    default: r = v; g = p; b = q; break;
    }
    rgb[0] = to_byte(r);
    rgb[1] = to_byte(g);
    rgb[2] = to_byte(b);
}

/* R3 low-discrepancy sequence (Roberts 2018) in hue, saturation, value */
static void r3_colour(int k, unsigned char rgb[3])
{
    const double g = 1.2207440846057594;   /* plastic number: x^4 = x + 1 */
    double h = 0.5 + k / g, sat = 0.5 + k / (g * g), val = 0.5 + k / (g * g * g);
    hsv(h, 0.4 + 0.55 * (sat - floor(sat)), 0.55 + 0.43 * (val - floor(val)), rgb);
}

/* Labels NPAL..NEXT-1: greedy farthest-point picks among R3 candidates
 * (each new colour maximizes its distance to all earlier ones), computed
 * once on first use. */
enum { NEXT = 256, NCAND = 4096 };
static unsigned char extended[NEXT][3];
static int extended_ready;

static double cdist(const unsigned char *a, const unsigned char *b)
{
    /* weighted RGB distance: green differences are seen best */
    double dr = a[0] - b[0], dg = a[1] - b[1], db = a[2] - b[2];
    return 2 * dr * dr + 4 * dg * dg + 3 * db * db;
}

static void build_extended(void)
{
    static unsigned char cand[NCAND][3];
    static double best[NCAND];
    for (int i = 0; i < NCAND; i++) {
        r3_colour(i, cand[i]);
        best[i] = 1e300;
        for (int j = 0; j < NPAL; j++) best[i] = fmin(best[i], cdist(cand[i], palette[j]));
        unsigned char grey[3] = {150, 150, 150}, white[3] = {255, 255, 255};
        best[i] = fmin(best[i], cdist(cand[i], grey));
        best[i] = fmin(best[i], cdist(cand[i], white));
    }
    for (int k = 0; k < NPAL; k++) memcpy(extended[k], palette[k], 3);
    for (int k = NPAL; k < NEXT; k++) {
        int pick = 0;
        for (int i = 1; i < NCAND; i++)
            if (best[i] > best[pick]) pick = i;
        memcpy(extended[k], cand[pick], 3);
        for (int i = 0; i < NCAND; i++) best[i] = fmin(best[i], cdist(cand[i], cand[pick]));
    }
    extended_ready = 1;
}

void colormap_label(int label, unsigned char rgb[3])
{
    if (label < 0) {
        rgb[0] = rgb[1] = rgb[2] = 150;
        return;
    }
    if (label < NPAL) {
        memcpy(rgb, palette[label], 3);
        return;
    }
    if (label < NEXT) {
        if (!extended_ready)
            build_extended();
        memcpy(rgb, extended[label], 3);
        return;
    }
    r3_colour(label, rgb);
}

void colormap_viridis(double t, unsigned char rgb[3])
{
    static const double c[7][3] = {
        {0.2777273272234177, 0.005407344544966578, 0.3340998053353061},
        {0.1050930431085774, 1.404613529898575, 1.384590162594685},
        {-0.3308618287255563, 0.214847559468213, 0.09509516302823659},
        {-4.634230498983486, -5.799100973351585, -19.33244095627987},
        {6.228269936347081, 14.17993336680509, 56.69055260068105},
        {4.776384997670288, -13.74514537774601, -65.35303263337234},
        {-5.435455855934631, 4.645852612178535, 26.3124352495832},
    };
    if (isnan(t)) {
        rgb[0] = rgb[1] = rgb[2] = 150;
        return;
    }
    t = t < 0 ? 0 : t > 1 ? 1 : t;
    for (int d = 0; d < 3; d++) {
        double v = c[6][d];
        for (int k = 5; k >= 0; k--) v = v * t + c[k][d];
        rgb[d] = to_byte(v);
    }
}

void colormap_viridis_table(unsigned char lut[256 * 3])
{
    for (int i = 0; i < 256; i++) colormap_viridis(i / 255.0, lut + 3 * i);
}

double colormap_t(double x, double lo, double hi)
{
    if (!(hi > lo))
        return 0.5;
    double t = (x - lo) / (hi - lo);
    return t < 0 ? 0 : t > 1 ? 1 : t;
}

void scalar_range(const double *x, int n, double *lo, double *hi)
{
    double a = x[0], b = x[0];
    for (int i = 1; i < n; i++) {
        if (x[i] < a) a = x[i];
        if (x[i] > b) b = x[i];
    }
    *lo = a;
    *hi = b;
}

int color_parse(const char *s, unsigned char rgb[3])
{
    static const struct { const char *name; unsigned char rgb[3]; } names[] = {
        {"white", {255, 255, 255}}, {"black", {0, 0, 0}}, {"grey", {128, 128, 128}},
        {"gray", {128, 128, 128}}, {"red", {220, 40, 40}}, {"green", {40, 170, 60}},
        {"blue", {40, 80, 220}},
    };
    for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(s, names[i].name)) {
            memcpy(rgb, names[i].rgb, 3);
            return 0;
        }
    if (s[0] == '#') {
        if (strlen(s) != 7 || strspn(s + 1, "0123456789abcdefABCDEF") != 6)
            return -1;
        unsigned long v = strtoul(s + 1, NULL, 16);
        rgb[0] = (unsigned char)(v >> 16);
        rgb[1] = (unsigned char)(v >> 8);
        rgb[2] = (unsigned char)v;
        return 0;
    }
    const char *p = s;
    for (int k = 0; k < 3; k++) {
        char *end;
        if (*p < '0' || *p > '9')
            return -1;
        long v = strtol(p, &end, 10);
        if (v < 0 || v > 255 || end == p || (k < 2 && *end != ',') || (k == 2 && *end))
            return -1;
        rgb[k] = (unsigned char)v;
        p = end + 1;
    }
    return 0;
}
