/* rotation.h -- 3D rotations as rotation vectors (axis times angle):
 * the matrix logarithm and exponential of SO(3), and the choice of the
 * rotation "branch" (angle + 2 pi k) closest to a reference, which is what
 * makes interpolation by angle consistent between neighbouring elements.
 * Matrices are 3 by 3 row-major, acting on column vectors.
 */
#ifndef CM_ROTATION_H
#define CM_ROTATION_H
#ifdef __cplusplus
extern "C" {
#endif

/* r: 3 (out) rotation vector of R, |r| in [0, pi].  Robust near 0 and pi. */
void rot_log(const double R[9], double r[3]);
/* R: 3 by 3 (out) = exp([r]x) (Rodrigues). */
void rot_exp(const double r[3], double R[9]);
/* Among r + 2 pi k r/|r| for k in {-2..2}, return in out (3) the one
 * closest to ref (3): the same rotation, on the branch of its neighbour.
 * r with |r| below 1e-12 is copied unchanged. */
void rot_branch_closest(const double r[3], const double ref[3], double out[3]);

#ifdef __cplusplus
}
#endif
#endif
