/* procrustes2: recovers_similarity, weights, never_reflects, errors */
#include "procrustes.h"
#include "rng.h"
#include "tap.h"
#include <math.h>

int main(void)
{
    struct rng r;
    rng_seed(&r, 7);
    double A[2 * 20], B[2 * 20], w[20];
    /* an exact similarity (angle 2.5 rad, scale 1.7, shift (3, -1)) is recovered */
    double an0 = 2.5, s0 = 1.7;
    for (int i = 0; i < 20; i++) {
        A[2 * i] = rng_normal(&r); A[2 * i + 1] = rng_normal(&r);
        B[2 * i] = s0 * (cos(an0) * A[2 * i] - sin(an0) * A[2 * i + 1]) + 3;
        B[2 * i + 1] = s0 * (sin(an0) * A[2 * i] + cos(an0) * A[2 * i + 1]) - 1;
    }
    double an, s, t[2];
    double res = procrustes2(A, B, NULL, 20, &an, &s, t);
    ok(res >= 0 && res < 1e-12 && fabs(an - an0) < 1e-12 && fabs(s - s0) < 1e-12 && fabs(t[0] - 3) < 1e-12 &&
       fabs(t[1] + 1) < 1e-12, "an exact similarity: angle %.15g, scale %.15g, shift (%g, %g), residual %g", an, s, t[0], t[1], res);
    /* weights: two points moved far away and given weight 0 change nothing */
    for (int i = 0; i < 20; i++) w[i] = i < 2 ? 0 : 1;
    B[0] += 50; B[3] -= 40;
    res = procrustes2(A, B, w, 20, &an, &s, t);
    ok(res < 1e-12 && fabs(an - an0) < 1e-12 && fabs(s - s0) < 1e-12, "weight 0 ignores two outliers (residual %g)", res);
    /* a mirror image is fitted by a rotation, never a reflection: the fit of
     * a triangle onto its mirror has a residual */
    double T[6] = {0, 0, 2, 0, 0, 1}, M[6] = {0, 0, -2, 0, 0, 1};
    res = procrustes2(T, M, NULL, 3, &an, &s, t);
    ok(res > 0.1, "a mirror image is not matched exactly (residual %.3f, angle %.3f)", res, an);
    /* errors: all weights 0, coinciding points */
    for (int i = 0; i < 20; i++) w[i] = 0;
    ok(procrustes2(A, B, w, 20, &an, &s, t) < 0, "all weights 0: an error");
    double C[4] = {1, 1, 1, 1};
    ok(procrustes2(C, B, NULL, 2, &an, &s, t) < 0, "the points of A coincide: an error");
    return tap_done();
}
