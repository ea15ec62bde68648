/* polar: rotation_is_orthonormal, reproduces_A, symmetric_S */
#include "polar.h"
#include "rng.h"
#include "tap.h"
#include <math.h>

int main(void)
{
    struct rng r;
    rng_seed(&r, 1);
    double worst_orth = 0, worst_rep = 0, worst_det = 0;
    for (int t = 0; t < 200; t++) {
        double A[9], R[9], S[9], RS[9], RtR[9], Rt[9];
        for (int k = 0; k < 9; k++) A[k] = rng_normal(&r);
        polar3(A, R, S);
        mat3_mul(R, S, RS);
        mat3_transpose(R, Rt);
        mat3_mul(Rt, R, RtR);
        for (int k = 0; k < 9; k++) {
            double e = fabs(RtR[k] - (k % 4 == 0));
            if (e > worst_orth) worst_orth = e;
            if (fabs(RS[k] - A[k]) > worst_rep) worst_rep = fabs(RS[k] - A[k]);
        }
        if (fabs(mat3_det(R) - 1) > worst_det) worst_det = fabs(mat3_det(R) - 1);
    }
    ok(worst_orth < 1e-12, "polar3: R^T R = I (max err %g)", worst_orth);
    ok(worst_det < 1e-12, "polar3: det R = 1 (max err %g)", worst_det);
    ok(worst_rep < 1e-12, "polar3: R S = A (max err %g)", worst_rep);
    /* R is the closest rotation: trace(R^T A) >= trace(Q^T A) for rotations Q
     * near R (also when det A < 0), and exact on a rotation and rank 1 and 2 */
    int worse = 0;
    for (int t = 0; t < 200; t++) {
        double A[9], R[9], S[9];
        for (int k = 0; k < 9; k++) A[k] = rng_normal(&r);
        polar3(A, R, S);
        double best = 0;
        for (int k = 0; k < 9; k++) best += R[k] * A[k];
        for (int q = 0; q < 20; q++) {
            double w[3] = {0.05 * rng_normal(&r), 0.05 * rng_normal(&r), 0.05 * rng_normal(&r)};
            double W[9] = {1, -w[2], w[1], w[2], 1, -w[0], -w[1], w[0], 1}, Q[9], Sq[9], RW[9];
            polar3(W, Q, Sq);                          /* a small rotation */
            mat3_mul(R, Q, RW);
            double tr = 0;
            for (int k = 0; k < 9; k++) tr += RW[k] * A[k];
            worse += tr > best + 1e-12;
        }
    }
    ok(worse == 0, "polar3: no nearby rotation is closer to A (%d found)", worse);
    double Rz[9] = {0, -1, 0, 1, 0, 0, 0, 0, 1}, R1[9], S1[9];
    polar3(Rz, R1, S1);
    double e = 0;
    for (int k = 0; k < 9; k++) e += fabs(R1[k] - Rz[k]);
    ok(e < 1e-14, "polar3: a rotation is its own R (err %g)", e);
    double L1[9] = {1, 2, 3, 2, 4, 6, -1, -2, -3}, L2[9] = {1, 0, 0, 0, 1, 0, 0, 0, 0};
    polar3(L1, R1, S1);
    ok(fabs(mat3_det(R1) - 1) < 1e-12, "polar3: rank 1 gives a rotation (det %g)", mat3_det(R1));
    polar3(L2, R1, S1);
    e = 0;
    for (int k = 0; k < 9; k++) e += fabs(R1[k] - (k % 4 == 0));
    ok(e < 1e-14, "polar3: rank 2 diag(1, 1, 0) gives I (err %g)", e);
    double A2[4] = {0, -2, 2, 0}, R2[4], S2[4];
    polar2(A2, R2, S2);
    ok(fabs(rot2_angle(R2) - M_PI / 2) < 1e-15, "polar2: 90 degree rotation angle");
    ok(fabs(S2[0] - 2) < 1e-15 && fabs(S2[3] - 2) < 1e-15 && fabs(S2[1]) < 1e-15,
       "polar2: S = 2 I for a scaled rotation");
    return tap_done();
}
