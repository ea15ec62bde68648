/* rings.c -- rings_degenerate and rings_orientation at any scale: the
 * same shapes scaled by 1e-300 ... 1e300 give the same answers (the area
 * test used to square the diagonal, which overflows above 1e154);
 * rings_sharpest_left on either side of a ring. */
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

    /* rings_sharpest_left: the inside of a counter-clockwise ring, the
     * outside of a clockwise one */
    double P[8];
    int start[2] = {0, 4};
    struct rings r = {.nrings = 1, .start = start, .P = P};
    for (int i = 0; i < 8; i++) P[i] = square[i];
    ok(fabs(rings_sharpest_left(&r, 0) - M_PI / 2) < 1e-12, "a counter-clockwise square: 90 degrees");
    for (int i = 0; i < 8; i++) P[i] = cw[i];
    ok(fabs(rings_sharpest_left(&r, 0) - 1.5 * M_PI) < 1e-12, "a clockwise square: 270 degrees (its outside)");
    /* a triangle with a 10 degree tip at (10, 0); the same with a notch */
    double t = tan(5 * M_PI / 180) * 10;
    double tri[] = {0, -t, 10, 0, 0, t};
    start[1] = 3;
    for (int i = 0; i < 6; i++) P[i] = tri[i];
    ok(fabs(rings_sharpest_left(&r, 0) * 180 / M_PI - 10) < 1e-9, "a triangle with a 10 degree tip: 10 degrees");
    /* a notch to (8, 0) (reflex there): the barbs at (0, +-t) are
     * atan(t / 8) - 5 = 1.24 degrees */
    double arrow[] = {0, -t, 10, 0, 0, t, 8, 0};
    start[1] = 4;
    for (int i = 0; i < 8; i++) P[i] = arrow[i];
    double a = rings_sharpest_left(&r, 0) * 180 / M_PI, b = atan(t / 8) * 180 / M_PI - 5;
    ok(fabs(a - b) < 1e-9, "an arrow head: its barbs, %.3f degrees (expected %.3f)", a, b);

    /* rings_collinear: a line encloses nothing; a figure eight (signed
     * area 0) and a sliver of area 5e-15 are not lines */
    double lin[] = {512, 72.3, 512, 72.0, 512, 71.7, 512, 71.7 + 1e-13};
    start[1] = 4;
    for (int i = 0; i < 8; i++) P[i] = lin[i];
    ok(rings_collinear(&r, 0), "17 points on x = 512, here 4: on one line");
    double bow[] = {0, 0, 10, 10, 10, 0, 0, 10};
    for (int i = 0; i < 8; i++) P[i] = bow[i];
    ok(!rings_collinear(&r, 0) && rings_degenerate(&r, 0), "a figure eight: no line (though its signed area is 0)");
    double rep[] = {1, 1, 1, 1, 2, 2, 3, 3.000000000000001};
    for (int i = 0; i < 8; i++) P[i] = rep[i];
    ok(!rings_collinear(&r, 0), "a repeated first point, then a point off the line by 1e-15: no line (exact)");
    start[1] = 3;
    for (int i = 0; i < 6; i++) P[i] = sliver[i];
    ok(!rings_collinear(&r, 0) && rings_degenerate(&r, 0), "a sliver of relative area 1e-15: degenerate but not a line");
    /* polygon_roundness: 1 for a circle, 0.84 for a 2:1 ellipse, pi/4 for
     * a square, low for a C (round hull, little solidity); either orientation */
    {
        double C[2 * 400], E[2 * 400], Q[8] = {0, 0, 1, 0, 1, 1, 0, 1}, K[2 * 400];
        int nk = 0;
        for (int i = 0; i < 400; i++) {
            double t = 2 * M_PI * i / 400;
            C[2 * i] = cos(t); C[2 * i + 1] = sin(t);
            E[2 * i] = 2 * cos(-t); E[2 * i + 1] = sin(-t);   /* clockwise */
        }
        for (int i = 0; i < 200; i++) {   /* a C: the outer arc out, the inner arc back */
            double t = 0.6 + (2 * M_PI - 1.2) * i / 199;
            K[2 * nk] = cos(t); K[2 * nk + 1] = sin(t); nk++;
        }
        for (int i = 199; i >= 0; i--) {
            double t = 0.6 + (2 * M_PI - 1.2) * i / 199;
            K[2 * nk] = 0.6 * cos(t); K[2 * nk + 1] = 0.6 * sin(t); nk++;
        }
        double rc = polygon_roundness(C, 400), re = polygon_roundness(E, 400), rq = polygon_roundness(Q, 4);
        double rk = polygon_roundness(K, nk);
        ok(fabs(rc - 1) < 1e-4, "a circle of 400 points: roundness %.6f", rc);
        ok(fabs(re - 0.8411) < 1e-3, "a 2:1 ellipse, clockwise: roundness %.4f (0.8411)", re);
        ok(fabs(rq - M_PI / 4) < 1e-12, "a square: roundness %.6f (pi/4)", rq);
        ok(rk < 0.6, "a C: roundness %.3f (round hull, little solidity)", rk);
        double L[6] = {0, 0, 1, 1, 2, 2};
        ok(polygon_roundness(L, 3) == 0, "three points on a line: 0");
        /* the fuzzer's square of side 1e200: squared lengths overflow
         * unless it is scaled first */
        double B[8] = {0, 0, 1e200, 0, 1e200, 1e200, 0, 1e200};
        double rb = polygon_roundness(B, 4);
        ok(fabs(rb - M_PI / 4) < 1e-12, "a square of side 1e200: roundness %.6f (pi/4)", rb);
    }
    return tap_done();
}
