/* spd.h -- sparse symmetric positive definite solves with CHOLMOD:
 * analyze and factor once, solve many right-hand sides.
 *
 *   struct spd_solver *S = spd_factor(A);         A: n by n SPD
 *   spd_solve(S, B, X, ncols);                    B, X: n by ncols, row-major
 *   spd_free(S);
 *
 * And the workhorse of geometry processing, "minimize a quadratic with
 * fixed values":
 *
 *   minimize  1/2 x^T Q x - x^T b   subject to  x_i = y_i for fixed i
 *
 * solved by eliminating the fixed rows: Q_uu x_u = b_u - Q_uk y_k, with Q_uu
 * factored once (quad_solver_new) and any number of (b, y) pairs solved
 * afterwards (quad_solver_solve).  Each column of a multi-column x is an
 * independent problem (e.g. x, y, z coordinates).
 *
 * A matrix that is not positive definite is reported (cm_errmsg names the
 * failing column), never silently solved: a negative or zero pivot (also in
 * CHOLMOD's simplicial LDL' factorization, which would accept indefinite
 * matrices), or a numerically singular matrix (CHOLMOD's rcond estimate
 * below n * DBL_EPSILON, e.g. a Laplacian with nothing fixed).
 */
#ifndef CM_SPD_H
#define CM_SPD_H
#include "sparse.h"
#ifdef __cplusplus
extern "C" {
#endif

struct spd_solver;

/* Factor A (n by n, symmetric; stype 0 with both halves, or stype 1 upper).
 * Returns NULL (cm_errmsg set) if A is not SPD. */
struct spd_solver *spd_factor(const cholmod_sparse *A);
/* Refactor with new values of the same pattern (keeps the analysis). */
int spd_refactor(struct spd_solver *S, const cholmod_sparse *A);
/* X = A^-1 B.  B, X: n by ncols row-major (may alias). */
int spd_solve(struct spd_solver *S, const double *B, double *X, int ncols);
int spd_size(const struct spd_solver *S);
void spd_free(struct spd_solver *S);

struct quad_solver;

/* Q: n by n symmetric positive semi-definite whose free block is SPD.
 * fixed: n flags (nonzero = fixed), copied. */
struct quad_solver *quad_solver_new(const cholmod_sparse *Q, const unsigned char *fixed);
/* b: n by ncols linear term (NULL = 0); y: n by ncols values of which only
 * the fixed rows are read (NULL = 0); x: n by ncols result (fixed rows = y). */
int quad_solver_solve(struct quad_solver *S, const double *b, const double *y, double *x,
                      int ncols);
void quad_solver_free(struct quad_solver *S);

#ifdef __cplusplus
}
#endif
#endif
