/* fuzz_holes.c -- compat-tri's rings with holes (compat_holes.h) in two
 * shapes: the nesting, the ring-by-ring matching and the cuts, straight or
 * bent, that join every hole to its piece.  The input is two rings files
 * separated by a line "--"; each must read, be simple (rings_check_simple)
 * and have no degenerate ring, at most 6 rings of at most 48 points, and
 * both the same rings nested the same way (compat_nest).  No row is given,
 * so every hole starts at its first vertex and may be turned against its
 * piece: the cuts often have to bend.  Oracle: a triangulation that
 * succeeds is positively oriented in both shapes by the exact predicate,
 * every boundary vertex is used, and its area is the rings' area (pieces
 * minus holes) to 1e-9 in each shape. */
#include "fuzz_shapes.h"
#include "compat_holes.h"
#include <math.h>

/* simple rings, at most 6 of at most 48 points, none degenerate */
static int holes_keep(const struct rings *r)
{
    if (r->nrings > 6 || rings_check_simple(r) != 0) return 0;
    for (int k = 0; k < r->nrings; k++)
        if (rings_count(r, k) > 48 || rings_degenerate(r, k)) return 0;
    return 1;
}

/* the mesh's area in shape s against the area of the boundary cycles
 * (pieces counter-clockwise, holes clockwise: their signed sum) */
static int holes_area_ok(const struct compat *c, int s)
{
    const double *X = c->X[s];
    double a = 0, b = 0, scale = 0;
    for (int t = 0; t < c->nf; t++) {
        const double *p = X + 2 * c->F[3 * t], *q = X + 2 * c->F[3 * t + 1], *r = X + 2 * c->F[3 * t + 2];
        a += (q[0] - p[0]) * (r[1] - p[1]) - (q[1] - p[1]) * (r[0] - p[0]);
    }
    for (int k = 0; k < c->nrings; k++)
        for (int i = c->ring_start[k]; i < c->ring_start[k + 1]; i++) {
            int j = i + 1 < c->ring_start[k + 1] ? i + 1 : c->ring_start[k];
            b += X[2 * i] * X[2 * j + 1] - X[2 * j] * X[2 * i + 1];
            scale += fabs(X[2 * i] * X[2 * j + 1]) + fabs(X[2 * j] * X[2 * i + 1]);
        }
    return fabs(a - b) <= 1e-9 * scale + 1e-300;
}

FUZZ_TARGET(holes)(const uint8_t *data, size_t size)
{
    struct rings R[2];
    int ok = fuzz_two_shapes(data, size, R, holes_keep);
    int nr = ok ? R[0].nrings : 0;
    int parent[6];
    unsigned char flipped[12];
    if (ok && R[1].nrings == nr && compat_nest(2, R, parent, flipped) == 0) {
        struct compat c;
        double st[4];
        if (compat_multi(2, R, parent, flipped, NULL, 0, NULL, 0, 0.01, &c, st) == 0) {
            if (compat_multi_triangulate(&c) == 0) {
                if (!fuzz_all_positive(&c)) fuzz_fail("holes: inverted triangle after compat_multi_triangulate");
                unsigned char *used = calloc(c.nb + 1, 1);
                for (int t = 0; t < 3 * c.nf; t++)
                    if (c.F[t] < c.nb) used[c.F[t]] = 1;
                for (int v = 0; v < c.nb; v++)
                    if (!used[v]) fuzz_fail("holes: a boundary vertex in no triangle");
                free(used);
                for (int s = 0; s < 2; s++)
                    if (!holes_area_ok(&c, s)) fuzz_fail("holes: the triangles' area is not the rings' area");
            }
        }
        compat_free(&c);   /* compat_multi cleared it first */
    }
    rings_free(&R[0]);
    rings_free(&R[1]);
    return 0;
}
