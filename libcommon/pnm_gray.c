/* pnm_gray.c -- see pnm_gray.h */
#include "pnm_gray.h"
#include "cm_error.h"
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void gray_free(struct gray *g) { free(g->v); memset(g, 0, sizeof *g); }

/* next header integer, skipping blanks and # comments */
static int hdr_int(FILE *f, long *line, int *out)
{
    int c;
    for (;;) {
        c = getc(f);
        if (c == '#') { while ((c = getc(f)) != EOF && c != '\n') ; }
        if (c == '\n') (*line)++;
        if (c == EOF) return -1;
        if (!isspace(c)) break;
    }
    if (!isdigit(c)) return -1;
    long v = 0;
    while (c != EOF && isdigit(c)) { v = v * 10 + (c - '0'); if (v > 1000000000) return -1; c = getc(f); }
    if (c == '\n') (*line)++;
    *out = (int)v;
    return 0;
}

int gray_read(const char *path, struct gray *g)
{
    memset(g, 0, sizeof *g);
    int std = !path || !strcmp(path, "-");
    const char *name = std ? "<stdin>" : path;
    FILE *f = std ? stdin : fopen(path, "rb");
    if (!f) return cm_seterr("cannot read '%s': %s", name, strerror(errno));
    long line = 1;
    int rc = -1;
    int m0 = getc(f), m1 = getc(f);
    if (m0 != 'P' || m1 < '1' || m1 > '6') {
        cm_seterr("cannot read '%s': line 1: not a netpbm image (P1-P6)", name);
        goto out;
    }
    int type = m1 - '0', w, h, maxval = 1;
    if (hdr_int(f, &line, &w) < 0 || hdr_int(f, &line, &h) < 0 ||
        (type != 1 && type != 4 && hdr_int(f, &line, &maxval) < 0)) {
        cm_seterr("cannot read '%s': line %ld: bad header", name, line);
        goto out;
    }
    if (w < 1 || h < 1 || (long)w * h > 400000000L || maxval < 1 || maxval > 65535) {
        cm_seterr("cannot read '%s': line %ld: bad size %dx%d or maxval %d", name, line, w, h, maxval);
        goto out;
    }
    g->w = w; g->h = h; g->maxval = maxval; g->bitmap = type == 1 || type == 4;
    g->v = malloc((size_t)w * h * sizeof *g->v);
    if (!g->v) { cm_seterr("cannot read '%s': out of memory", name); goto out; }
    int ch = type == 3 || type == 6 ? 3 : 1;
    for (long i = 0; i < (long)w * h; i++) {
        int val = 0;
        if (type == 4) {
            int x = (int)(i % w);
            static int byte;
            if (x % 8 == 0) { byte = getc(f); if (byte == EOF) goto trunc; }
            val = (byte >> (7 - x % 8)) & 1;
        } else if (type == 1) {
            int c;
            do { c = getc(f); if (c == '\n') line++; if (c == '#') { while ((c = getc(f)) != EOF && c != '\n') ; line++; } }
            while (c != EOF && isspace(c));
            if (c == EOF) goto trunc;
            if (c != '0' && c != '1') { cm_seterr("cannot read '%s': line %ld: expected 0 or 1", name, line); goto out; }
            val = c - '0';
        } else {
            long acc = 0;
            for (int k = 0; k < ch; k++) {
                int s;
                if (type == 2 || type == 3) {
                    if (hdr_int(f, &line, &s) < 0) goto trunc;
                } else if (maxval < 256) {
                    s = getc(f); if (s == EOF) goto trunc;
                } else {
                    int a = getc(f), b = getc(f); if (b == EOF) goto trunc; s = a * 256 + b;
                }
                if (s > maxval) { cm_seterr("cannot read '%s': line %ld: value %d above maxval %d", name, line, s, maxval); goto out; }
                acc += ch == 3 ? (k == 0 ? 299 : k == 1 ? 587 : 114) * (long)s : s;
            }
            val = ch == 3 ? (int)(acc / 1000) : (int)acc;
        }
        g->v[i] = val;
    }
    rc = 0;
    goto out;
trunc:
    cm_seterr("cannot read '%s': line %ld: truncated pixel data", name, line);
out:
    if (!std) fclose(f);
    if (rc < 0) gray_free(g);
    return rc;
}
