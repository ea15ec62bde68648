/* polar.c -- see polar.h */
#include "polar.h"
#include "geometry.h"
#include <math.h>
#include <string.h>


void polar2(const double A[4], double R[4], double S[4])
{
    /* closest rotation: angle of (a + d, c - b) */
    double th = atan2(A[2] - A[1], A[0] + A[3]);
    double c = cos(th), s = sin(th);
    R[0] = c; R[1] = -s; R[2] = s; R[3] = c;
    /* S = R^T A */
    S[0] = c * A[0] + s * A[2];
    S[1] = c * A[1] + s * A[3];
    S[2] = -s * A[0] + c * A[2];
    S[3] = -s * A[1] + c * A[3];
    double off = 0.5 * (S[1] + S[2]);   /* symmetric up to rounding */
    S[1] = S[2] = off;
}

double rot2_angle(const double R[4]) { return atan2(R[2], R[0]); }

void mat3_mul(const double A[9], const double B[9], double C[9])
{
    double T[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            T[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
    memcpy(C, T, sizeof T);
}

void mat3_transpose(const double A[9], double T[9])
{
    double X[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) X[3 * j + i] = A[3 * i + j];
    memcpy(T, X, sizeof X);
}

double mat3_det(const double A[9])
{
    return A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
           A[2] * (A[3] * A[7] - A[4] * A[6]);
}

int mat3_inverse(const double A[9], double I[9])
{
    double d = mat3_det(A);
    if (d == 0 || !isfinite(d)) return -1;
    double X[9] = {
        A[4] * A[8] - A[5] * A[7], A[2] * A[7] - A[1] * A[8], A[1] * A[5] - A[2] * A[4],
        A[5] * A[6] - A[3] * A[8], A[0] * A[8] - A[2] * A[6], A[2] * A[3] - A[0] * A[5],
        A[3] * A[7] - A[4] * A[6], A[1] * A[6] - A[0] * A[7], A[0] * A[4] - A[1] * A[3]};
    for (int k = 0; k < 9; k++) I[k] = X[k] / d;
    return 0;
}

/* eigen-decomposition of a symmetric 3x3 M (row-major) by cyclic Jacobi
 * rotations: M = V diag(w) V^T, V's columns the eigenvectors */
static void sym3_eigen(const double M[9], double w[3], double V[9])
{
    double a[3][3];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) a[i][j] = M[3 * i + j];
    for (int i = 0; i < 9; i++) V[i] = i % 4 == 0;
    for (int sweep = 0; sweep < 30; sweep++) {
        double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
        double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
        if (!(off > 1e-30 * diag) || off == 0) break;
        for (int p = 0; p < 2; p++)
            for (int q = p + 1; q < 3; q++) {
                if (a[p][q] == 0) continue;
                /* the rotation in the (p, q) plane that zeroes a[p][q] */
                double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
                double t = (theta >= 0 ? 1 : -1) / (fabs(theta) + sqrt(theta * theta + 1));
                double c = 1 / sqrt(t * t + 1), sn = t * c;
                for (int k = 0; k < 3; k++) {        /* a = J^T a J */
                    double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - sn * akq;
                    a[k][q] = sn * akp + c * akq;
                }
                for (int k = 0; k < 3; k++) {
                    double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - sn * aqk;
                    a[q][k] = sn * apk + c * aqk;
                }
                for (int k = 0; k < 3; k++) {        /* V = V J */
                    double vkp = V[3 * k + p], vkq = V[3 * k + q];
                    V[3 * k + p] = c * vkp - sn * vkq;
                    V[3 * k + q] = sn * vkp + c * vkq;
                }
            }
    }
    for (int i = 0; i < 3; i++) w[i] = a[i][i];
}

static void normalize3(double *v)
{
    double l = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    if (l > 0) { v[0] /= l; v[1] /= l; v[2] /= l; }
}

void polar3(const double A[9], double R[9], double S[9])
{
    /* the right singular vectors: eigenvectors of A^T A, sorted by
     * decreasing singular value, det V = +1 */
    double AtA[9], w[3], E[9];
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            AtA[3 * i + j] = A[i] * A[j] + A[3 + i] * A[3 + j] + A[6 + i] * A[6 + j];
    sym3_eigen(AtA, w, E);
    int o[3] = {0, 1, 2};
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++)
            if (w[o[j]] > w[o[i]]) { int t = o[i]; o[i] = o[j]; o[j] = t; }
    double v[3][3];                                   /* v[k]: k-th column */
    for (int k = 0; k < 3; k++)
        for (int d = 0; d < 3; d++) v[k][d] = E[3 * d + o[k]];
    double c[3];
    cross3(v[0], v[1], c);
    if (c[0] * v[2][0] + c[1] * v[2][1] + c[2] * v[2][2] < 0)
        for (int d = 0; d < 3; d++) v[2][d] = -v[2][d];
    /* left singular vectors u_k = A v_k / s_k for the two largest, the third
     * u_0 x u_1; then R = U V^T is the closest rotation (the reflection, if
     * det A < 0, goes to the smallest singular value as in polar.h) */
    double u[3][3];
    for (int k = 0; k < 2; k++)
        for (int d = 0; d < 3; d++)
            u[k][d] = A[3 * d] * v[k][0] + A[3 * d + 1] * v[k][1] + A[3 * d + 2] * v[k][2];
    double n0 = sqrt(u[0][0] * u[0][0] + u[0][1] * u[0][1] + u[0][2] * u[0][2]);
    if (!(n0 > 0)) {                                  /* A = 0 */
        for (int i = 0; i < 9; i++) { R[i] = i % 4 == 0; S[i] = 0; }
        return;
    }
    normalize3(u[0]);
    double p = u[1][0] * u[0][0] + u[1][1] * u[0][1] + u[1][2] * u[0][2];
    for (int d = 0; d < 3; d++) u[1][d] -= p * u[0][d];
    double n1 = sqrt(u[1][0] * u[1][0] + u[1][1] * u[1][1] + u[1][2] * u[1][2]);
    if (!(n1 > 1e-12 * n0)) {                         /* rank 1: any perpendicular */
        double e[3] = {0, 0, 0};
        int m = fabs(u[0][0]) < fabs(u[0][1]) ? (fabs(u[0][0]) < fabs(u[0][2]) ? 0 : 2)
                                               : (fabs(u[0][1]) < fabs(u[0][2]) ? 1 : 2);
        e[m] = 1;
        cross3(u[0], e, u[1]);
    }
    normalize3(u[1]);
    cross3(u[0], u[1], u[2]);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) R[3 * i + j] = u[0][i] * v[0][j] + u[1][i] * v[1][j] + u[2][i] * v[2][j];
    double Rt[9];
    mat3_transpose(R, Rt);
    mat3_mul(Rt, A, S);
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++) {
            double m = 0.5 * (S[3 * i + j] + S[3 * j + i]);
            S[3 * i + j] = S[3 * j + i] = m;
        }
}
