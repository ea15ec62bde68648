/* polar.h -- polar decomposition A = R S of small matrices (row-major),
 * R a rotation (det +1), S symmetric.  When det A < 0 the closest rotation
 * is returned and S absorbs the reflection (S then has a negative
 * eigenvalue), as needed by ARAP-style methods.
 */
#ifndef CM_POLAR_H
#define CM_POLAR_H
#ifdef __cplusplus
extern "C" {
#endif

/* A, R, S: 2 by 2. */
void polar2(const double A[4], double R[4], double S[4]);
/* A, R, S: 3 by 3.  Via the SVD A = U diag(s) V^T (LAPACK dgesvd):
 * R = U D V^T with D = diag(1, 1, det(U V^T)), S = R^T A. */
void polar3(const double A[9], double R[9], double S[9]);
/* Rotation angle of a 2x2 rotation matrix, in (-pi, pi]. */
double rot2_angle(const double R[4]);

/* 3x3 helpers, row-major */
void mat3_mul(const double A[9], const double B[9], double C[9]);
void mat3_transpose(const double A[9], double T[9]);
double mat3_det(const double A[9]);
int mat3_inverse(const double A[9], double I[9]);   /* -1 if singular */

#ifdef __cplusplus
}
#endif
#endif
