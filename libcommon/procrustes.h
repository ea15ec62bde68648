/* procrustes.h -- the rigid or similarity transform that best maps one
 * point set onto another in the least-squares sense (Kabsch / Umeyama):
 *     minimize  sum_i w_i | s R a_i + t - b_i |^2,  R a rotation (det +1).
 * R is the closest rotation to the weighted cross-covariance (polar.h),
 * s = tr(R^T C) / sum w_i |a_i - abar|^2 when scaling is allowed.
 */
#ifndef CM_PROCRUSTES_H
#define CM_PROCRUSTES_H
#ifdef __cplusplus
extern "C" {
#endif

/* A, B: n by 3 corresponding points; w: n weights (NULL = all 1);
 * scale: 0 rigid (s = 1), 1 similarity.  R: 3 by 3 row-major (out),
 * t: 3 (out), s: (out, may be NULL).  Needs n >= 3 points with positive
 * weight not all on a line for a unique rotation; returns -1 (cm_errmsg
 * set) when n < 1 or the weights sum to 0.  Returns the RMS residual. */
double procrustes(const double *A, const double *B, const double *w, int n, int scale,
                  double R[9], double t[3], double *s);

/* The plane's version: the rotation angle a (radians, counter-clockwise),
 * scale s and translation t (2) of the similarity x -> s R(a) x + t that
 * best maps A onto B (n by 2 each) with weights w (n; NULL = all 1).  No
 * reflection is ever chosen.  Returns the weighted RMS residual, or -1
 * (cm_errmsg set) when the weights do not sum to a positive number or the
 * weighted points of A coincide. */
double procrustes2(const double *A, const double *B, const double *w, int n, double *a, double *s, double t[2]);

/* Apply x -> s R x + t to n points (in place allowed). */
void similarity_apply(const double R[9], const double t[3], double s, const double *X,
                      int n, double *Y);

#ifdef __cplusplus
}
#endif
#endif
