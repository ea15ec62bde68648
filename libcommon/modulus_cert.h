/* modulus_cert.h -- a computed certificate that given correspondence
 * points forbid a good compatible triangulation: an upper bound on the
 * smallest angle any compatible triangulation of the poses can reach.
 *
 * A compatible triangulation of poses i and j is a piecewise-affine
 * homeomorphism f between them that maps outline to outline and every
 * given correspondence point to its partner.  If every triangle has all
 * its angles >= theta in both poses, the affine map of each triangle has
 * a ratio of singular values (distortion) of at most Kmax(theta)^2
 * (affine_distortion_max), so f is Kmax(theta)^2-quasiconformal, and the
 * conformal modulus (quad_modulus.h) of every quadrilateral "pose i with
 * four of the given points" differs from the one of pose j with the
 * partner points by at most that factor.  Those moduli depend only on the
 * outlines and the points, not on the matching between them; so when
 * their ratio R exceeds Kmax(theta)^2, no compatible triangulation that
 * honours the points has all angles >= theta in both poses: its worst
 * angle is at most theta*(R) (angle_ceiling).  The moduli are bracketed
 * (finite elements on the solution and on the conjugate quadrilateral),
 * and the certificate uses the lower bound of the ratio, so it is
 * rigorous up to floating-point rounding.
 */
#ifndef CM_MODULUS_CERT_H
#define CM_MODULUS_CERT_H
#ifdef __cplusplus
extern "C" {
#endif

/* Kmax(theta): the largest ratio of singular values of the affine map
 * from an equilateral triangle onto a triangle whose angles are all
 * >= theta (radians, in (0, pi/3]).  For a triangle of angles A, B, C:
 * K + 1/K = (2 / sqrt 3) (cot A + cot B + cot C), largest at the
 * boundary of the feasible angles: (theta, theta, pi - 2 theta) or
 * (theta, (pi - theta) / 2, (pi - theta) / 2).  About 4.76 at 20 degrees. */
double affine_distortion_max(double theta);

/* theta*(R): the angle (radians, in (0, pi/3]) with Kmax(theta)^2 = R;
 * pi/3 for R <= 1.  A map that must distort some quadrilateral's modulus
 * R times has a triangle with an angle <= theta*(R) in one of the poses. */
double angle_ceiling(double R);

struct modulus_cert {
    int quads;          /* quadruples of points examined (C(ncorr, 4)) */
    double ratio;       /* lower bound of the largest modulus ratio over every
                           quadruple and pair of poses (0: fewer than 4 points) */
    double ratio_hi;    /* upper bound of that quadruple and pair's ratio */
    int pose[2];        /* the pair: pose[0] has the larger modulus */
    int row[4];         /* the four points: rows of corr, increasing */
    double lo[2], hi[2];/* modulus brackets in pose[0] and pose[1] */
    double ceiling;     /* theta*(ratio), degrees (60 without a certificate) */
    long meshes;        /* quadrilaterals meshed and solved (quads x N) */
    int nv;             /* vertices of the largest mesh used */
};

/* The certificate over every quadruple of the given points and every pair
 * of poses (branch and bound: all brackets to a loose width first, then
 * the quadruples that can still carry the largest ratio to tol; a
 * quadruple whose ratio is below 2 even at its upper bound, a ceiling
 * above 50 degrees, keeps the bracket of the first mesh).
 * N      poses
 * P      N arrays: P[s] is n[s] by 2, a simple counter-clockwise polygon
 * n      N corner counts
 * corr   ncorr by N corner indices (row-major: corr[k*N+s] is point k in
 *        pose s), in increasing cyclic order counter-clockwise in every pose
 * ncorr  rows (fewer than 4: no certificate, c->ratio = 0)
 * tol    relative width of the final brackets (e.g. 0.03)
 * c      out
 * Returns 0, or -1 (cm_errmsg set) on bad input or a failed solve. */
int modulus_certificate(int N, double *const *P, const int *n, const int *corr, int ncorr, double tol,
                        struct modulus_cert *c);

#ifdef __cplusplus
}
#endif
#endif
