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
