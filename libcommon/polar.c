/* polar.c -- see polar.h */
#include "polar.h"
#include <math.h>
#include <string.h>

void dgesvd_(const char *jobu, const char *jobvt, const int *m, const int *n, double *a,
             const int *lda, double *s, double *u, const int *ldu, double *vt, const int *ldvt,
             double *work, const int *lwork, int *info);

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

void polar3(const double A[9], double R[9], double S[9])
{
    /* LAPACK is column-major: pass A^T's storage, i.e. A row-major is A^T
     * column-major.  SVD of A^T = U' s V'^T  =>  A = V' s U'^T. */
    double a[9], s[3], u[9], vt[9], work[64];
    memcpy(a, A, sizeof a);
    int three = 3, lwork = 64, info = 0;
    dgesvd_("A", "A", &three, &three, a, &three, s, u, &three, vt, &three, work, &lwork, &info);
    /* column-major u (3x3) = U' ; column-major vt = V'^T.
     * A = (V') diag(s) (U')^T, so the row-major U of A is V' and V is U'.
     * R = U_A V_A^T = V' U'^T.  In row-major: R[i][j] = sum_k V'[i][k] U'[j][k]
     * with V'[i][k] = vt(k,i) = vt[i*3+k] (column-major: vt(r,c) = vt[c*3+r])
     * and U'[j][k] = u(j,k) = u[k*3+j]. */
    double Ua[9], Va[9];
    for (int i = 0; i < 3; i++)
        for (int k = 0; k < 3; k++) {
            Ua[3 * i + k] = vt[i * 3 + k];   /* V'[i][k] */
            Va[3 * i + k] = u[k * 3 + i];    /* U'[i][k] */
        }
    double Vt[9];
    mat3_transpose(Va, Vt);
    mat3_mul(Ua, Vt, R);
    if (mat3_det(R) < 0) {
        for (int i = 0; i < 3; i++) Ua[3 * i + 2] = -Ua[3 * i + 2];
        mat3_mul(Ua, Vt, R);
    }
    double Rt[9];
    mat3_transpose(R, Rt);
    mat3_mul(Rt, A, S);
    for (int i = 0; i < 3; i++)
        for (int j = i + 1; j < 3; j++) {
            double m = 0.5 * (S[3 * i + j] + S[3 * j + i]);
            S[3 * i + j] = S[3 * j + i] = m;
        }
    (void)info;
}
