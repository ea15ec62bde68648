/* procrustes.c -- see procrustes.h */
#include "procrustes.h"
#include "cm_error.h"
#include "polar.h"
#include <math.h>

double procrustes(const double *A, const double *B, const double *w, int n, int scale,
                  double R[9], double t[3], double *s)
{
    double W = 0, ca[3] = {0, 0, 0}, cb[3] = {0, 0, 0};
    for (int i = 0; i < n; i++) {
        double wi = w ? w[i] : 1;
        W += wi;
        for (int d = 0; d < 3; d++) { ca[d] += wi * A[3 * i + d]; cb[d] += wi * B[3 * i + d]; }
    }
    if (n < 1 || !(W > 0)) return cm_seterr("procrustes: no points with positive weight");
    for (int d = 0; d < 3; d++) { ca[d] /= W; cb[d] /= W; }
    /* C = sum w (b - cb)(a - ca)^T : R = polar rotation of C */
    double C[9] = {0}, va = 0;
    for (int i = 0; i < n; i++) {
        double wi = w ? w[i] : 1, a[3], b[3];
        for (int d = 0; d < 3; d++) { a[d] = A[3 * i + d] - ca[d]; b[d] = B[3 * i + d] - cb[d]; }
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) C[3 * r + c] += wi * b[r] * a[c];
        va += wi * (a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    }
    double S[9];
    polar3(C, R, S);
    double sc = 1;
    if (scale && va > 0) sc = (S[0] + S[4] + S[8]) / va;
    if (!(sc > 0)) sc = 1;
    for (int r = 0; r < 3; r++)
        t[r] = cb[r] - sc * (R[3 * r] * ca[0] + R[3 * r + 1] * ca[1] + R[3 * r + 2] * ca[2]);
    if (s) *s = sc;
    double res = 0;
    for (int i = 0; i < n; i++) {
        double wi = w ? w[i] : 1, y[3];
        similarity_apply(R, t, sc, A + 3 * i, 1, y);
        for (int d = 0; d < 3; d++) res += wi * (y[d] - B[3 * i + d]) * (y[d] - B[3 * i + d]);
    }
    return sqrt(res / W);
}

void similarity_apply(const double R[9], const double t[3], double s, const double *X,
                      int n, double *Y)
{
    for (int i = 0; i < n; i++) {
        double x[3] = {X[3 * i], X[3 * i + 1], X[3 * i + 2]};
        for (int r = 0; r < 3; r++)
            Y[3 * i + r] = s * (R[3 * r] * x[0] + R[3 * r + 1] * x[1] + R[3 * r + 2] * x[2]) + t[r];
    }
}

double procrustes2(const double *A, const double *B, const double *w, int n, double *a, double *s, double t[2])
{
    double W = 0, ca[2] = {0, 0}, cb[2] = {0, 0};
    for (int i = 0; i < n; i++) {
        double wi = w ? w[i] : 1;
        W += wi;
        for (int d = 0; d < 2; d++) { ca[d] += wi * A[2 * i + d]; cb[d] += wi * B[2 * i + d]; }
    }
    if (!(W > 0)) return cm_seterr("procrustes2: no points with positive weight");
    for (int d = 0; d < 2; d++) { ca[d] /= W; cb[d] /= W; }
    /* with u = a - ca, v = b - cb:  sum w u.v = k cos a,  sum w u x v = k sin a */
    double dot = 0, cross = 0, va = 0;
    for (int i = 0; i < n; i++) {
        double wi = w ? w[i] : 1;
        double ux = A[2 * i] - ca[0], uy = A[2 * i + 1] - ca[1], vx = B[2 * i] - cb[0], vy = B[2 * i + 1] - cb[1];
        dot += wi * (ux * vx + uy * vy);
        cross += wi * (ux * vy - uy * vx);
        va += wi * (ux * ux + uy * uy);
    }
    if (!(va > 0)) return cm_seterr("procrustes2: the points coincide");
    double an = atan2(cross, dot), sc = hypot(dot, cross) / va, c = cos(an), sn = sin(an);
    t[0] = cb[0] - sc * (c * ca[0] - sn * ca[1]);
    t[1] = cb[1] - sc * (sn * ca[0] + c * ca[1]);
    double res = 0;
    for (int i = 0; i < n; i++) {
        double x = sc * (c * A[2 * i] - sn * A[2 * i + 1]) + t[0] - B[2 * i];
        double y = sc * (sn * A[2 * i] + c * A[2 * i + 1]) + t[1] - B[2 * i + 1];
        res += (w ? w[i] : 1) * (x * x + y * y);
    }
    *a = an;
    *s = sc;
    return sqrt(res / W);
}
