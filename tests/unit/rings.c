/* rings.c -- rings_degenerate and rings_orientation at any scale: the
 * same shapes scaled by 1e-300 ... 1e300 give the same answers (the area
 * test used to square the diagonal, which overflows above 1e154). */
#include "rings.h"
#include "tap.h"
#include <math.h>

/* ring pts (n points) scaled by s: rings_degenerate (what 0) or
 * rings_orientation (what 1) of it */
static int scaled(int what, const double *pts, int n, double s)
{
    double P[64];
    int start[2] = {0, n};
    for (int i = 0; i < 2 * n; i++) P[i] = pts[i] * s;
    struct rings r = {.nrings = 1, .start = start, .P = P};
    return what ? rings_orientation(&r, 0) : rings_degenerate(&r, 0);
}
#define test_degenerate(p, n, s) scaled(0, p, n, s)
#define test_orientation(p, n, s) scaled(1, p, n, s)

int main(void)
{
    static const double square[] = {0, 0, 1, 0, 1, 1, 0, 1};
    static const double line[] = {0, 0, 1, 1, 2, 2, 3, 3};
    static const double sliver[] = {0, 0, 1, 0, 2, 1e-14};  /* area 5e-15 < 1e-12 * 5 */
    static const double thin[] = {0, 0, 1, 0, 2, 1e-6};     /* area 5e-7: a real ring */
    static const double scales[] = {1e-300, 1e-160, 1e-20, 1, 1e20, 1e160, 1e300};
    for (int i = 0; i < 7; i++) {
        double s = scales[i];
        ok(!test_degenerate(square, 4, s), "a square scaled by %g is not degenerate", s);
        ok(test_degenerate(line, 4, s), "collinear points scaled by %g are degenerate", s);
        ok(test_degenerate(sliver, 3, s), "a sliver of relative area 1e-15 scaled by %g is degenerate", s);
        ok(!test_degenerate(thin, 3, s), "a thin triangle of relative area 1e-7 scaled by %g is not", s);
        ok(test_orientation(square, 4, s) > 0, "a counter-clockwise square scaled by %g is counter-clockwise", s);
    }
    static const double cw[] = {0, 0, 0, 1, 1, 1, 1, 0};
    ok(test_orientation(cw, 4, 1e300) < 0, "a clockwise square at 1e300 is clockwise");
    return tap_done();
}
