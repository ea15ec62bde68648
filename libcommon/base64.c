/* base64.c -- RFC 4648 base64 encoding and decoding. */
#include "base64.h"
#include "cm_error.h"

static const char alphabet[] =
    "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";

void base64_encode(const void *in, size_t n, char *out)
{
    const unsigned char *p = in;
    size_t i = 0;
    for (; i + 3 <= n; i += 3, out += 4) {
        unsigned v = (unsigned)p[i] << 16 | (unsigned)p[i + 1] << 8 | p[i + 2];
        out[0] = alphabet[v >> 18];
        out[1] = alphabet[v >> 12 & 63];
        out[2] = alphabet[v >> 6 & 63];
        out[3] = alphabet[v & 63];
    }
    if (i < n) {
        unsigned v = (unsigned)p[i] << 16 | (i + 1 < n ? (unsigned)p[i + 1] << 8 : 0);
        out[0] = alphabet[v >> 18];
        out[1] = alphabet[v >> 12 & 63];
        out[2] = i + 1 < n ? alphabet[v >> 6 & 63] : '=';
        out[3] = '=';
    }
}

int base64_write(FILE *f, const void *in, size_t n)
{
    enum { BLOCK = 3 * 4096 };
    char buf[BLOCK / 3 * 4];
    const unsigned char *p = in;
    for (size_t i = 0; i < n; i += BLOCK) {
        size_t k = n - i < BLOCK ? n - i : BLOCK;
        base64_encode(p + i, k, buf);
        if (fwrite(buf, 1, base64_len(k), f) != base64_len(k))
            return cm_seterr("cannot write base64 data");
    }
    return 0;
}

static int value(char c)
{
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+') return 62;
    if (c == '/') return 63;
    return -1;
}

long base64_decode(const char *in, size_t len, unsigned char *out)
{
    if (len % 4)
        return cm_seterr("base64: length %zu is not a multiple of 4", len);
    long n = 0;
    for (size_t i = 0; i < len; i += 4) {
        int pad = 0, v[4];
        for (int j = 0; j < 4; j++) {
            if (in[i + j] == '=' && i + 4 == len && j >= 2) { v[j] = 0; pad++; continue; }
            if (pad || (v[j] = value(in[i + j])) < 0)
                return cm_seterr("base64: bad character at offset %zu", i + j);
        }
        unsigned w = (unsigned)v[0] << 18 | (unsigned)v[1] << 12 | (unsigned)v[2] << 6 | (unsigned)v[3];
        out[n++] = w >> 16;
        if (pad < 2) out[n++] = w >> 8 & 255;
        if (pad < 1) out[n++] = w & 255;
    }
    return n;
}
