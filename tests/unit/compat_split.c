/* compat_split.c -- the compatible triangulation's split search gives the
 * same mesh, bit for bit, on 1, 2 and 3 threads, and with the inside tests
 * over the grid of a piece's edges as with every edge tested: jagged
 * many-lobed outlines, some of whose pieces need stage II's Steiner
 * points, with runs of collinear points (edges exactly on grid lines and
 * through cell corners). */
#include "compat_tri.h"
#include "cm_error.h"
#include "tap.h"
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* a lobed outline of n points, counter-clockwise: lobes twisted by `twist`,
 * radius jittered by `jit`; every fifth run of 4 points put on a line */
static double *outline(int n, int lobes, double twist, double jit, unsigned seed)
{
    double *P = malloc(2 * (size_t)n * sizeof *P);
    for (int k = 0; k < n; k++) {
        double t = 2 * M_PI * k / n;
        seed = seed * 1103515245u + 12345u;
        double r = 1 + 0.45 * sin(lobes * t + twist * sin(2 * t)) + jit * ((seed >> 16 & 1023) / 1023.0 - 0.5);
        P[2 * k] = round(64 * r * cos(t));   /* integer coordinates: collinear runs and grid lines exactly */
        P[2 * k + 1] = round(64 * r * sin(t));
    }
    for (int k = 0; k + 3 < n; k += 20)   /* a straight run: points 1, 2 on the chord 0-3 */
        for (int u = 1; u < 3; u++)
            for (int d = 0; d < 2; d++)
                P[2 * (k + u) + d] = P[2 * k + d] + u * (P[2 * (k + 3) + d] - P[2 * k + d]) / 3;
    return P;
}

/* triangulates the shapes; returns 0 and fills c, or -1 */
static int tri(int N, double *const *P, const int *n, int threads, int exhaustive, struct compat *c)
{
    int corr[4 * 8];
    for (int k = 0; k < 4; k++)
        for (int s = 0; s < N; s++) corr[k * N + s] = k * n[s] / 4;
    if (compat_match(N, P, n, corr, 4, c, NULL) < 0) return -1;
    c->threads = threads;
    c->exhaustive = exhaustive;
    return compat_triangulate(c);
}

static int same(const struct compat *a, const struct compat *b)
{
    if (a->nv != b->nv || a->nf != b->nf || memcmp(a->F, b->F, 3 * (size_t)a->nf * sizeof *a->F)) return 0;
    for (int s = 0; s < a->N; s++)
        if (memcmp(a->X[s], b->X[s], 2 * (size_t)a->nv * sizeof **a->X)) return 0;
    return 1;
}

int main(void)
{
    struct { int N, n, lobes; double jit; } cases[] = {{2, 90, 5, 0.15}, {3, 110, 6, 0.2}};
    for (size_t k = 0; k < sizeof cases / sizeof *cases; k++) {
        int N = cases[k].N, n[8];
        double *P[8];
        for (int s = 0; s < N; s++) {
            n[s] = cases[k].n + 7 * s;
            P[s] = outline(n[s], cases[k].lobes, 0.8 * s, cases[k].jit, 17 + 31 * s + (unsigned)k);
        }
        struct compat ref, c2, c3, ex;
        int r = tri(N, P, n, 1, 0, &ref);
        ok(r == 0, "case %zu (%d shapes, %d+ points): triangulated on one thread%s%s", k, N, cases[k].n,
           r ? ": " : "", r ? cm_errmsg() : "");
        if (r) continue;
        ok(ref.stage_count[1] > 0, "case %zu: stage II used (%d stage I, %d stage II splits, %d overlays)", k, ref.stage_count[0],
           ref.stage_count[1], ref.stage_count[2]);
        ok(tri(N, P, n, 2, 0, &c2) == 0 && same(&ref, &c2), "case %zu: two threads, the same mesh", k);
        ok(tri(N, P, n, 3, 0, &c3) == 0 && same(&ref, &c3), "case %zu: three threads, the same mesh", k);
        ok(tri(N, P, n, 2, 1, &ex) == 0 && same(&ref, &ex), "case %zu: every edge tested, the same mesh", k);
        compat_free(&ref); compat_free(&c2); compat_free(&c3); compat_free(&ex);
        for (int s = 0; s < N; s++) free(P[s]);
    }
    return tap_done();
}
