/* rings.c -- see rings.h */
#include "rings.h"
#include "predicates2.h"
#include "cm_error.h"
#include "numparse.h"
#include "textline.h"
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

void rings_free(struct rings *r)
{
    free(r->start);
    free(r->P);
    free(r->line);
    memset(r, 0, sizeof *r);
}

static int grow(struct rings *r, int npts)
{
    int total = r->start ? r->start[r->nrings] : 0;
    int *s = realloc(r->start, (r->nrings + 2) * sizeof *s);
    double *P = realloc(r->P, 2 * (size_t)(total + npts + 1) * sizeof *P);
    long *L = realloc(r->line, (size_t)(total + npts + 1) * sizeof *L);
    if (!s || !P || !L) {
        if (s) r->start = s;
        if (P) r->P = P;
        if (L) r->line = L;
        return cm_seterr("out of memory");
    }
    r->start = s; r->P = P; r->line = L;
    if (r->nrings == 0) r->start[0] = 0;
    return 0;
}

int rings_append(struct rings *r, const double *P, int n)
{
    if (grow(r, n) < 0) return -1;
    int t = r->start[r->nrings];
    memcpy(r->P + 2 * (size_t)t, P, 2 * (size_t)n * sizeof *P);
    for (int i = 0; i < n; i++) r->line[t + i] = 0;
    r->start[++r->nrings] = t + n;
    return 0;
}

int rings_from_points(struct rings *r, const double *P, int n)
{
    memset(r, 0, sizeof *r);
    strcpy(r->name, "<points>");
    return rings_append(r, P, n);
}

static char *skip(char *s) { while (*s == ' ' || *s == '\t' || *s == '\r') s++; return s; }

int rings_read(const char *path, struct rings *r)
{
    memset(r, 0, sizeof *r);
    int std = !path || !strcmp(path, "-");
    snprintf(r->name, sizeof r->name, "%s", std ? "<stdin>" : path);
    FILE *f = std ? stdin : fopen(path, "r");
    if (!f)
        return cm_seterr("cannot read '%s': %s", r->name, strerror(errno));
    char *buf = NULL;
    size_t cap = 0;
    long lineno = 0;
    int want = 0, got = 0;   /* points announced / read in the current ring */
    int total = 0, ok = 0;
    long hdrline = 0;
    size_t pcap = 0;         /* points P and line have room for */
    for (;;) {
        long n = textline_read(f, &buf, &cap, r->name, lineno + 1);
        if (n == -2) goto out;
        if (n < 0) break;
        lineno++;
        char *s = skip(buf);
        if (*s == '#' || *s == '\n' || *s == 0) continue;
        if (!strncmp(s, "ring", 4) && (s[4] == ' ' || s[4] == '\t')) {
            if (got < want) {
                cm_seterr("cannot read '%s': line %ld: ring of line %ld has %d points, header says %d",
                          r->name, lineno, hdrline, got, want);
                goto out;
            }
            long k;
            const char *q = parse_long(s + 4, &k);
            if (!q || (*skip((char *)q) != '\n' && *skip((char *)q) != 0)) {
                cm_seterr("cannot read '%s': line %ld: expected 'ring N'", r->name, lineno);
                goto out;
            }
            if (k < 3 || k > 100000000) {
                cm_seterr("cannot read '%s': line %ld: a ring needs at least 3 points, not %ld",
                          r->name, lineno, k);
                goto out;
            }
            if (r->nrings) r->start[r->nrings] = total;
            /* room for the ring's header only: its points are reserved as
             * they arrive, not from the announced count */
            int *st = realloc(r->start, (size_t)(r->nrings + 2) * sizeof *st);
            if (!st) { cm_seterr("cannot read '%s': out of memory", r->name); goto out; }
            r->start = st;
            if (r->nrings == 0) r->start[0] = 0;
            r->start[r->nrings + 1] = total;  /* placeholder, fixed as points arrive */
            r->nrings++;
            want = (int)k; got = 0; hdrline = lineno;
            continue;
        }
        if (r->nrings == 0) {
            cm_seterr("cannot read '%s': line %ld: expected 'ring N' before the points", r->name, lineno);
            goto out;
        }
        if (got == want) {
            cm_seterr("cannot read '%s': line %ld: more points than the %d announced on line %ld",
                      r->name, lineno, want, hdrline);
            goto out;
        }
        double x, y;
        const char *q = parse_double(s, &x);
        const char *q2 = q ? parse_double(q, &y) : NULL;
        if (!q || !q2 || (*skip((char *)q2) != '\n' && *skip((char *)q2) != 0 && *skip((char *)q2) != '#')) {
            cm_seterr("cannot read '%s': line %ld: expected 2 numbers \"x y\"", r->name, lineno);
            goto out;
        }
        if (!isfinite(x) || !isfinite(y)) {
            cm_seterr("cannot read '%s': line %ld: non-finite number", r->name, lineno);
            goto out;
        }
        if (got > 0 && r->P[2 * (total - 1)] == x && r->P[2 * (total - 1) + 1] == y) {
            cm_seterr("cannot read '%s': line %ld: repeated point (zero-length edge)", r->name, lineno);
            goto out;
        }
        if ((size_t)total + 1 >= pcap) {
            size_t nc = 2 * pcap + 16;
            double *P = realloc(r->P, 2 * nc * sizeof *P);
            if (P) r->P = P;
            long *L = P ? realloc(r->line, nc * sizeof *L) : NULL;
            if (!P || !L) { cm_seterr("cannot read '%s': out of memory", r->name); goto out; }
            r->line = L;
            pcap = nc;
        }
        r->P[2 * total] = x;
        r->P[2 * total + 1] = y;
        r->line[total] = lineno;
        total++; got++;
        r->start[r->nrings] = total;
    }
    if (r->nrings == 0) {
        cm_seterr("cannot read '%s': line %ld: no rings", r->name, lineno);
        goto out;
    }
    if (got < want) {
        cm_seterr("cannot read '%s': line %ld: truncated: ring of line %ld has %d points, header says %d",
                  r->name, lineno, hdrline, got, want);
        goto out;
    }
    for (int k = 0; k < r->nrings; k++) {
        int a = r->start[k], b = r->start[k + 1] - 1;
        if (r->P[2 * a] == r->P[2 * b] && r->P[2 * a + 1] == r->P[2 * b + 1]) {
            cm_seterr("cannot read '%s': line %ld: last point repeats the first (rings close themselves)",
                      r->name, r->line[b]);
            goto out;
        }
    }
    ok = 1;
out:
    free(buf);
    if (!std) fclose(f);
    if (!ok) {
        char keep[256];
        memcpy(keep, r->name, sizeof keep);
        rings_free(r);
        memcpy(r->name, keep, sizeof keep);
        return -1;
    }
    return 0;
}

int rings_write(FILE *f, const struct rings *r)
{
    char bx[32], by[32];
    for (int k = 0; k < r->nrings; k++) {
        fprintf(f, "ring %d\n", rings_count(r, k));
        const double *P = rings_ring(r, k);
        for (int i = 0; i < rings_count(r, k); i++) {
            format_double(bx, P[2 * i]);
            format_double(by, P[2 * i + 1]);
            fprintf(f, "%s %s\n", bx, by);
        }
    }
    return ferror(f) ? cm_seterr("write error") : 0;
}

double rings_area(const struct rings *r, int k)
{
    const double *P = rings_ring(r, k);
    int n = rings_count(r, k);
    double a = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        a += P[2 * i] * P[2 * j + 1] - P[2 * j] * P[2 * i + 1];
    }
    return 0.5 * a;
}

int rings_orientation(const struct rings *r, int k)
{
    const double *P = rings_ring(r, k);
    int n = rings_count(r, k), v = 0;
    for (int i = 1; i < n; i++)
        if (P[2 * i] < P[2 * v] || (P[2 * i] == P[2 * v] && P[2 * i + 1] < P[2 * v + 1])) v = i;
    return orient2_sign(P + 2 * ((v + n - 1) % n), P + 2 * v, P + 2 * ((v + 1) % n));
}

double rings_sharpest_left(const struct rings *r, int k)
{
    const double *P = rings_ring(r, k);
    int n = rings_count(r, k);
    double mn = 2 * M_PI;
    for (int i = 0; i < n; i++) {
        const double *v = P + 2 * i, *a = P + 2 * ((i + 1) % n), *b = P + 2 * ((i + n - 1) % n);
        /* counter-clockwise from the edge to the next point to the edge
         * to the previous one */
        double ax = a[0] - v[0], ay = a[1] - v[1], bx = b[0] - v[0], by = b[1] - v[1];
        double an = atan2(ax * by - ay * bx, ax * bx + ay * by);
        if (an < 0) an += 2 * M_PI;
        if (an < mn) mn = an;
    }
    return mn;
}

void rings_reverse(struct rings *r, int k)
{
    double *P = rings_ring(r, k);
    long *L = r->line + r->start[k];
    int n = rings_count(r, k);
    for (int i = 0, j = n - 1; i < j; i++, j--) {
        double t0 = P[2 * i], t1 = P[2 * i + 1];
        P[2 * i] = P[2 * j]; P[2 * i + 1] = P[2 * j + 1];
        P[2 * j] = t0; P[2 * j + 1] = t1;
        long tl = L[i]; L[i] = L[j]; L[j] = tl;
    }
}

int rings_orient(struct rings *r)
{
    int flipped = 0;
    for (int k = 0; k < r->nrings; k++) {
        int o = rings_orientation(r, k);
        if ((k == 0 && o < 0) || (k > 0 && o > 0)) {
            rings_reverse(r, k);
            flipped++;
        }
    }
    return flipped;
}

static int on_segment(const double *a, const double *b, const double *p)
{
    return fmin(a[0], b[0]) <= p[0] && p[0] <= fmax(a[0], b[0]) &&
           fmin(a[1], b[1]) <= p[1] && p[1] <= fmax(a[1], b[1]);
}

int rings_degenerate(const struct rings *r, int k)
{
    const double *P = rings_ring(r, k);
    int n = rings_count(r, k);
    /* the area test runs on the points scaled by a power of two (exact)
     * so that |coordinates| in [0.5, 1): no overflow of the squares at an
     * extent of 1e154 and more, no underflow at 1e-160 and less */
    double big = 0;
    for (int i = 0; i < 2 * n; i++) big = fmax(big, fabs(P[i]));
    int e = 0;
    if (big > 0 && isfinite(big)) frexp(big, &e);
    double lo[2] = {HUGE_VAL, HUGE_VAL}, hi[2] = {-HUGE_VAL, -HUGE_VAL}, a = 0;
    for (int i = 0; i < n; i++) {
        int j = (i + 1) % n;
        double x = ldexp(P[2 * i], -e), y = ldexp(P[2 * i + 1], -e);
        a += x * ldexp(P[2 * j + 1], -e) - ldexp(P[2 * j], -e) * y;
        lo[0] = fmin(lo[0], x); hi[0] = fmax(hi[0], x);
        lo[1] = fmin(lo[1], y); hi[1] = fmax(hi[1], y);
    }
    double dg = hypot(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(fabs(0.5 * a) > 1e-12 * dg * dg)) return 1;
    for (int i = 2; i < n; i++)
        if (orient2_sign(P, P + 2, P + 2 * i) != 0) return 0;
    return 1;
}

int rings_collinear(const struct rings *r, int k)
{
    const double *P = rings_ring(r, k);
    int n = rings_count(r, k), b = 1;
    while (b < n && P[2 * b] == P[0] && P[2 * b + 1] == P[1]) b++;   /* a second, distinct point */
    for (int i = b + 1; i < n; i++)
        if (orient2_sign(P, P + 2 * b, P + 2 * i) != 0) return 0;
    return 1;
}

int segments_intersect(const double *a, const double *b, const double *c, const double *d)
{
    /* exact signs (predicates2.h) */
    int o1 = orient2_sign(a, b, c), o2 = orient2_sign(a, b, d);
    int o3 = orient2_sign(c, d, a), o4 = orient2_sign(c, d, b);
    if (((o1 > 0 && o2 < 0) || (o1 < 0 && o2 > 0)) && ((o3 > 0 && o4 < 0) || (o3 < 0 && o4 > 0)))
        return 1;
    if (o1 == 0 && on_segment(a, b, c)) return 1;
    if (o2 == 0 && on_segment(a, b, d)) return 1;
    if (o3 == 0 && on_segment(c, d, a)) return 1;
    if (o4 == 0 && on_segment(c, d, b)) return 1;
    return 0;
}

int point_in_ring(const double *P, int n, const double *q)
{
    int in = 0;
    for (int i = 0, j = n - 1; i < n; j = i++) {
        const double *a = P + 2 * j, *b = P + 2 * i;
        if ((a[1] > q[1]) != (b[1] > q[1])) {
            double x = a[0] + (q[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
            if (q[0] < x) in = !in;
        }
    }
    return in;
}

struct seg { double xmin, xmax; int a, b, ring; };

static int cmp_seg(const void *x, const void *y)
{
    const struct seg *s = x, *t = y;
    return (s->xmin > t->xmin) - (s->xmin < t->xmin);
}

/* rings_first_crossing; within: only edges of the same ring */
static int first_crossing(const struct rings *r, int within, int *e1, int *e2)
{
    int total = r->start[r->nrings];
    struct seg *S = malloc((size_t)total * sizeof *S + 1);
    if (!S) return cm_seterr("out of memory");
    int m = 0;
    for (int k = 0; k < r->nrings; k++)
        for (int i = r->start[k]; i < r->start[k + 1]; i++) {
            int j = i + 1 == r->start[k + 1] ? r->start[k] : i + 1;
            S[m].a = i; S[m].b = j; S[m].ring = k;
            S[m].xmin = fmin(r->P[2 * i], r->P[2 * j]);
            S[m].xmax = fmax(r->P[2 * i], r->P[2 * j]);
            m++;
        }
    qsort(S, m, sizeof *S, cmp_seg);
    int bad = 0;
    for (int s = 0; s < m && !bad; s++)
        for (int t = s + 1; t < m && S[t].xmin <= S[s].xmax; t++) {
            if (within && S[t].ring != S[s].ring) continue;
            const double *a = r->P + 2 * S[s].a, *b = r->P + 2 * S[s].b;
            const double *c = r->P + 2 * S[t].a, *d = r->P + 2 * S[t].b;
            int shared = -1;   /* which endpoints coincide by index */
            if (S[s].b == S[t].a) shared = 0;      /* ab, bd: b shared */
            else if (S[t].b == S[s].a) shared = 1; /* cd, da: a shared */
            int hit;
            if (shared == 0)      /* fold-back: d on ab or a on bd */
                hit = orient2(a, b, d) == 0 && ((d[0] - b[0]) * (a[0] - b[0]) + (d[1] - b[1]) * (a[1] - b[1]) > 0);
            else if (shared == 1)
                hit = orient2(c, d, b) == 0 && ((b[0] - a[0]) * (c[0] - a[0]) + (b[1] - a[1]) * (c[1] - a[1]) > 0);
            else
                hit = segments_intersect(a, b, c, d);
            if (hit) {
                *e1 = S[s].a < S[t].a ? S[s].a : S[t].a;
                *e2 = S[s].a < S[t].a ? S[t].a : S[s].a;
                bad = 1;
                break;
            }
        }
    free(S);
    return bad;
}

int rings_first_crossing(const struct rings *r, int *e1, int *e2)
{
    return first_crossing(r, 0, e1, e2);
}

/* the ring holding vertex v */
static int ring_of(const struct rings *r, int v)
{
    int k = 0;
    while (k + 1 < r->nrings && r->start[k + 1] <= v) k++;
    return k;
}

int rings_check_simple(const struct rings *r)
{
    int e1, e2, rc = rings_first_crossing(r, &e1, &e2);
    if (rc < 0) return -1;
    if (rc)
        return cm_seterr("cannot read '%s': line %ld: outline intersects itself (edge from line %ld crosses edge from line %ld)",
                         r->name, r->line[e2], r->line[e1], r->line[e2]);
    return 0;
}

int rings_check_each_simple(const struct rings *r)
{
    int e1, e2, rc = first_crossing(r, 1, &e1, &e2);
    if (rc < 0) return -1;
    if (rc)
        return cm_seterr("cannot read '%s': line %ld: ring %d intersects itself (edge from line %ld crosses edge from "
                         "line %ld)", r->name, r->line[e2], ring_of(r, e2) + 1, r->line[e1], r->line[e2]);
    return 0;
}

static int cmp_xy(const void *x, const void *y)
{
    const double *a = x, *b = y;
    if (a[0] != b[0]) return a[0] < b[0] ? -1 : 1;
    return (a[1] > b[1]) - (a[1] < b[1]);
}

double polygon_diagonal(const double *P, int n)
{
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < n; i++)
        for (int d = 0; d < 2; d++) { lo[d] = fmin(lo[d], P[2 * i + d]); hi[d] = fmax(hi[d], P[2 * i + d]); }
    return hypot(hi[0] - lo[0], hi[1] - lo[1]);
}

double polygon_roundness(const double *P, int n)
{
    double *S = malloc((size_t)n * 2 * sizeof *S), *H = malloc(((size_t)n + 1) * 2 * sizeof *H);
    if (!S || !H) { free(S); free(H); return -1; }
    /* taken to the unit box first: the measure does not depend on the
     * scale, and squared lengths of coordinates near 1e200 would overflow */
    double lo[2] = {P[0], P[1]}, hi[2] = {P[0], P[1]};
    for (int k = 1; k < n; k++)
        for (int d = 0; d < 2; d++) { lo[d] = fmin(lo[d], P[2 * k + d]); hi[d] = fmax(hi[d], P[2 * k + d]); }
    double ext = fmax(hi[0] - lo[0], hi[1] - lo[1]);
    if (!(ext > 0) || !isfinite(ext)) { free(S); free(H); return 0; }
    for (int k = 0; k < n; k++)
        for (int d = 0; d < 2; d++) S[2 * k + d] = (P[2 * k + d] - lo[d]) / ext;
    double a = 0;   /* the polygon's own area, from the scaled copy before it is sorted */
    for (int k = 0; k < n; k++) {
        const double *u = S + 2 * k, *v = S + 2 * ((k + 1) % n);
        a += u[0] * v[1] - u[1] * v[0];
    }
    qsort(S, n, 2 * sizeof *S, cmp_xy);
    /* Andrew's monotone chain: lower hull, then upper, counter-clockwise */
    int h = 0;
    for (int pass = 0; pass < 2; pass++) {
        int base = h;
        for (int k = 0; k < n; k++) {
            const double *q = S + 2 * (pass ? n - 1 - k : k);
            while (h >= base + 2 && orient2_sign(H + 2 * (h - 2), H + 2 * (h - 1), q) <= 0) h--;
            H[2 * h] = q[0]; H[2 * h + 1] = q[1]; h++;
        }
        h--;   /* the last point starts the other chain */
    }
    double ah = 0, lh = 0;
    for (int k = 0; k < h; k++) {
        const double *u = H + 2 * k, *v = H + 2 * ((k + 1) % h);
        ah += u[0] * v[1] - u[1] * v[0];
        lh += hypot(v[0] - u[0], v[1] - u[1]);
    }
    free(S); free(H);
    ah *= 0.5;
    a = 0.5 * fabs(a);
    if (!(ah > 0) || !(lh > 0)) return 0;
    double r = 4 * M_PI * ah / (lh * lh) * (a / ah);
    return r > 1 ? 1 : r >= 0 ? r : 0;
}
