/* anim_pack.c -- 16-bit quantised, frame-differenced, deflated positions. */
#include "anim_pack.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <zlib.h>

void anim_pack_bbox(const double *X, size_t npoints, double lo[3], double hi[3])
{
    for (int a = 0; a < 3; a++) lo[a] = INFINITY, hi[a] = -INFINITY;
    for (size_t i = 0; i < npoints; i++)
        for (int a = 0; a < 3; a++) {
            if (X[3 * i + a] < lo[a]) lo[a] = X[3 * i + a];
            if (X[3 * i + a] > hi[a]) hi[a] = X[3 * i + a];
        }
    for (int a = 0; a < 3; a++) {
        if (!(lo[a] <= hi[a])) lo[a] = hi[a] = 0;
        if (hi[a] == lo[a]) hi[a] = lo[a] + 1;
    }
}

double anim_pack_bound(const double lo[3], const double hi[3])
{
    double s = 0;
    for (int a = 0; a < 3; a++) s += (hi[a] - lo[a]) * (hi[a] - lo[a]);
    return sqrt(s) / 131070;
}

void anim_pack_positions(const double *X, int nframes, int nv, const double lo[3],
                         const double hi[3], unsigned char *out, double *err)
{
    size_t m = (size_t)nv * 3;
    uint16_t *prev = calloc(m ? m : 1, sizeof *prev);
    double worst = 0;
    for (int k = 0; k < nframes; k++) {
        const double *x = X + (size_t)k * m;
        unsigned char *o = out + (size_t)k * m * 2;
        for (size_t v = 0; v < m / 3; v++) {
            double e2 = 0;
            for (int a = 0; a < 3; a++) {
                size_t i = 3 * v + a;
                double s = (hi[a] - lo[a]) / 65535;
                long q = lround((x[i] - lo[a]) / s);
                if (q < 0) q = 0;
                if (q > 65535) q = 65535;
                e2 += (lo[a] + q * s - x[i]) * (lo[a] + q * s - x[i]);
                uint16_t d = (uint16_t)((uint16_t)q - prev[i]);
                prev[i] = (uint16_t)q;
                o[i] = d & 255;
                o[m + i] = d >> 8;
            }
            if (sqrt(e2) > worst) worst = sqrt(e2);
        }
    }
    free(prev);
    if (err) *err = worst;
}

int anim_pack_deflate(const void *in, size_t n, unsigned char **out, size_t *outn)
{
    uLongf cap = compressBound(n);
    unsigned char *buf = malloc(cap ? cap : 1);
    if (!buf) return cm_seterr("out of memory compressing %zu bytes", n);
    int rc = compress2(buf, &cap, in, n, 6);
    if (rc != Z_OK) {
        free(buf);
        return cm_seterr("zlib compress failed (%d)", rc);
    }
    *out = buf;
    *outn = cap;
    return 0;
}

int anim_pack_inflate(const unsigned char *in, size_t inn, void *out, size_t n)
{
    uLongf len = n;
    int rc = uncompress(out, &len, in, inn);
    if (rc != Z_OK || len != n)
        return cm_seterr("corrupt packed data (zlib %d, %lu of %zu bytes)", rc, (unsigned long)len, n);
    return 0;
}
