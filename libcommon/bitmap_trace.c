/* bitmap_trace.c -- see bitmap_trace.h */
#include "bitmap_trace.h"
#include "cm_error.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* directions in y-up corner coordinates: 0 +x, 1 +y, 2 -x, 3 -y */
static const int DX[4] = {1, 0, -1, 0}, DY[4] = {0, 1, 0, -1};

/* the point of P strictly between a and b farthest from the chord a-b
 * (-1 if there is none), its distance in *dist */
static int farthest(const double *P, int a, int b, double *dist)
{
    double ax = P[2 * a], ay = P[2 * a + 1], bx = P[2 * b], by = P[2 * b + 1];
    double L = hypot(bx - ax, by - ay), best = -1;
    int bi = -1;
    for (int i = a + 1; i < b; i++) {
        double d = L > 0 ? fabs((bx - ax) * (P[2 * i + 1] - ay) - (by - ay) * (P[2 * i] - ax)) / L
                         : hypot(P[2 * i] - ax, P[2 * i + 1] - ay);
        if (d > best) { best = d; bi = i; }
    }
    *dist = best;
    return bi;
}

static void dp(const double *P, int a, int b, double tol, unsigned char *keep)
{
    double d;
    int i = farthest(P, a, b, &d);
    if (i >= 0 && d > tol) { keep[i] = 1; dp(P, a, i, tol, keep); dp(P, i, b, tol, keep); }
}

/* Douglas-Peucker simplification of the closed loop P (m points; room for
 * m + 1) to tol, in place; keep: m + 1 scratch flags.  Where the simplified
 * loop would cross or touch itself (two parts of the outline closer than
 * tol, e.g. legs a pixel apart), the farthest dropped point of each of the
 * two edges is put back, until it does not: the loop stays simple because
 * the unsimplified one is.  Returns the number of points kept, -1 if out of
 * memory (cm_errmsg set). */
static int simplify_loop(double *P, int m, double tol, unsigned char *keep)
{
    /* split the closed loop at point 0 and its farthest point */
    int far = 0;
    double fd = -1;
    for (int i = 1; i < m; i++) {
        double dd = hypot(P[2 * i] - P[0], P[2 * i + 1] - P[1]);
        if (dd > fd) { fd = dd; far = i; }
    }
    memset(keep, 0, m + 1);
    keep[0] = keep[far] = keep[m] = 1;
    P[2 * m] = P[0]; P[2 * m + 1] = P[1];
    dp(P, 0, far, tol, keep);
    dp(P, far, m, tol, keep);
    int *idx = malloc(sizeof *idx * (size_t)(m + 1));
    double *Q = malloc(2 * sizeof *Q * (size_t)(m + 1));
    if (!idx || !Q) { free(idx); free(Q); return cm_seterr("out of memory"); }
    int q;
    for (;;) {
        q = 0;
        for (int i = 0; i < m; i++)
            if (keep[i]) { idx[q] = i; Q[2 * q] = P[2 * i]; Q[2 * q + 1] = P[2 * i + 1]; q++; }
        if (q < 3) break;
        int start[2] = {0, q};
        struct rings r = {.nrings = 1, .start = start, .P = Q};
        int e[2], hit = rings_first_crossing(&r, &e[0], &e[1]);
        if (hit < 0) { free(idx); free(Q); return -1; }
        if (!hit) break;
        int added = 0;
        for (int t = 0; t < 2; t++) {
            int a = idx[e[t]], b = e[t] + 1 < q ? idx[e[t] + 1] : m;
            double dd;
            int f = farthest(P, a, b, &dd);
            if (f >= 0) { keep[f] = 1; added = 1; }
        }
        if (!added) break;   /* cannot happen: the full loop is simple */
    }
    for (int i = 0; i < q; i++) { P[2 * i] = Q[2 * i]; P[2 * i + 1] = Q[2 * i + 1]; }
    free(idx); free(Q);
    return q;
}

int bitmap_trace(const unsigned char *in, int w, int h, double min_area, double tol, struct rings *out)
{
    memset(out, 0, sizeof *out);
    snprintf(out->name, sizeof out->name, "<bitmap>");
    int W = w + 1, H = h + 1;
    /* outgoing boundary edges per corner (at most 2), corners indexed y*W+x
     * in y-up coordinates: corner (x, y) with y = h - row */
    int *outd = malloc((size_t)W * H * 2 * sizeof *outd);
    for (size_t i = 0; i < (size_t)W * H * 2; i++) outd[i] = -1;
#define INSIDE(x, r) ((x) >= 0 && (x) < w && (r) >= 0 && (r) < h && in[(size_t)(r) * w + (x)])
#define ADD(cx, cy, d) do { size_t k_ = ((size_t)(cy) * W + (cx)) * 2; \
        if (outd[k_] < 0) outd[k_] = (d); else outd[k_ + 1] = (d); } while (0)
    long nedges = 0;
    int rc = 0;
    for (int r = 0; r < h; r++)
        for (int x = 0; x < w; x++) {
            if (!INSIDE(x, r)) continue;
            int yb = h - r - 1, yt = h - r;   /* bottom and top corner rows of this pixel (y up) */
            if (!INSIDE(x, r + 1)) { ADD(x, yb, 0); nedges++; }       /* bottom edge, +x */
            if (!INSIDE(x + 1, r)) { ADD(x + 1, yb, 1); nedges++; }   /* right edge, +y */
            if (!INSIDE(x, r - 1)) { ADD(x + 1, yt, 2); nedges++; }   /* top edge, -x */
            if (!INSIDE(x - 1, r)) { ADD(x, yt, 3); nedges++; }       /* left edge, -y */
        }
    /* a corner with two outgoing edges is a saddle (inside pixels touching
     * diagonally): each of the two passes through it is cut by a chamfer
     * of PINCH pixels, so the loop (or the two loops) keep apart there
     * instead of touching at one point; at most one extra point an edge */
    const double PINCH = 0.25;
    double *P = malloc(2 * (size_t)(2 * nedges + 3) * sizeof *P);
    unsigned char *used = calloc((size_t)W * H * 2, 1);
    unsigned char *keep = malloc(2 * nedges + 3);
    for (int cy = 0; cy < H; cy++)
        for (int cx = 0; cx < W; cx++)
            for (int s = 0; s < 2; s++) {
                size_t k0 = ((size_t)cy * W + cx) * 2 + s;
                if (outd[k0] < 0 || used[k0]) continue;
                /* start at an ordinary corner: a loop through a saddle is
                 * found again from one of its other corners */
                if (outd[k0 - s] >= 0 && outd[k0 - s + 1] >= 0) continue;
                /* walk the loop; the start edge stays available so an
                 * ambiguous start corner closes the loop correctly */
                int x = cx, y = cy, d = outd[k0], n = 0, pd = -1;
                for (;;) {
                    if (pd < 0) { P[2 * n] = x; P[2 * n + 1] = y; n++; }
                    else {      /* the saddle's chamfer: back along pd, on along d */
                        P[2 * n] = x - PINCH * DX[pd]; P[2 * n + 1] = y - PINCH * DY[pd]; n++;
                        P[2 * n] = x + PINCH * DX[d]; P[2 * n + 1] = y + PINCH * DY[d]; n++;
                    }
                    x += DX[d]; y += DY[d];
                    size_t kk = ((size_t)y * W + x) * 2;
                    /* prefer a left turn (inside on the left: keeps the
                     * loop tight around inside pixels, 4-connectivity) */
                    int pref[3] = {(d + 1) & 3, d, (d + 3) & 3}, nd = -1;
                    size_t used_k = 0;
                    for (int q = 0; q < 3 && nd < 0; q++)
                        for (int t = 0; t < 2; t++)
                            if (outd[kk + t] == pref[q] && (!used[kk + t] || kk + t == k0)) {
                                nd = pref[q]; used_k = kk + t; break;
                            }
                    if (nd < 0 || used_k == k0) break;
                    used[used_k] = 1;
                    pd = outd[kk] >= 0 && outd[kk + 1] >= 0 ? d : -1;
                    d = nd;
                }
                used[k0] = 1;
                /* merge collinear runs */
                int m = 0;
                for (int i = 0; i < n; i++) {
                    const double *a = P + 2 * ((i + n - 1) % n), *b = P + 2 * i, *c = P + 2 * ((i + 1) % n);
                    if ((b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]) != 0) {
                        P[2 * m] = b[0]; P[2 * m + 1] = b[1]; m++;
                    }
                }
                if (m < 3) continue;
                double area = 0;
                for (int i = 0; i < m; i++) {
                    int j = (i + 1) % m;
                    area += 0.5 * (P[2 * i] * P[2 * j + 1] - P[2 * j] * P[2 * i + 1]);
                }
                if (fabs(area) < min_area) continue;
                if (tol > 0) {
                    int q = simplify_loop(P, m, tol, keep);
                    if (q < 0) { rc = -1; goto out; }
                    if (q < 3) continue;
                    m = q;
                }
                rings_append(out, P, m);
            }
out:
    free(outd); free(P); free(keep); free(used);
    if (rc < 0) { rings_free(out); return -1; }
    if (out->nrings == 0) return cm_seterr("no inside pixels (empty image after thresholding)");
    /* largest counter-clockwise loop first */
    int best = -1;
    double ba = 0;
    for (int k = 0; k < out->nrings; k++) {
        double a = rings_area(out, k);
        if (a > ba) { ba = a; best = k; }
    }
    if (best > 0) {
        struct rings r2;
        memset(&r2, 0, sizeof r2);
        memcpy(r2.name, out->name, sizeof r2.name);
        rings_append(&r2, rings_ring(out, best), rings_count(out, best));
        for (int k = 0; k < out->nrings; k++)
            if (k != best) rings_append(&r2, rings_ring(out, k), rings_count(out, k));
        rings_free(out);
        *out = r2;
    }
    return 0;
}
