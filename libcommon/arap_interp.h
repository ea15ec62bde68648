/* arap_interp.h -- as-rigid-as-possible interpolation between two poses of
 * one triangle mesh (thesis Sec. 3.2.7, corrected as in Alexa et al. 2000 /
 * Baxter et al. 2008 / Liu et al. 2011).
 *
 * Every triangle becomes a tetrahedron by a fourth vertex above its centroid
 * (thesis Eq. 3.1, with the norm that the equation's typo drops):
 *     v4 = (v1 + v2 + v3)/3 + n / sqrt(|n|),  n = (v2 - v1) x (v3 - v2).
 * The affine map of each tetrahedron from source to target, M (3 by 3,
 * column vectors), is split by the polar decomposition M = R S.  At time t
 * the expected map is
 *     M(t) = exp(t log R) ((1 - t) I + t S),
 * with the rotation vector log R chosen, by a breadth-first walk over the
 * faces, on the 2 pi branch closest to the neighbour it was reached from
 * (so a limb that turns by 190 degrees does not snap the other way).
 * The pose minimizes the area-weighted energy (thesis Eq. 3.2)
 *     E(t) = sum_T a_T || V*_T X_T - M_T(t)^T ||_F^2,
 * V*_T = (D V_T)^-1 D, over the #V + #F unknown positions (original vertices
 * and fourth vertices).  Its normal matrix H (Eq. 3.3) does not depend on t
 * and is factored once (CHOLMOD); each t is one solve with three columns.
 * The free translation is fixed by the interpolated centroid:
 * mean(X(t)) = (1 - t) mean(V0) + t mean(V1).  t = 0 and t = 1 reproduce the
 * two poses up to rounding.
 */
#ifndef CM_ARAP_INTERP_H
#define CM_ARAP_INTERP_H
#ifdef __cplusplus
extern "C" {
#endif

struct arap_interp;

/* V0, V1: #V by 3 source and target positions; F: #F by 3 shared faces.
 * Returns NULL (cm_errmsg set) on a degenerate triangle or a failed
 * factorization. */
struct arap_interp *arap_interp_new(const double *V0, const double *V1, const int *F,
                                    int nv, int nf);
/* X: #V by 3 (out) the pose at time t (any real t; 0 and 1 are the keys). */
int arap_interp_pose(struct arap_interp *a, double t, double *X);
/* Largest |rotation angle| over the elements after branch selection (radians). */
double arap_interp_max_angle(const struct arap_interp *a);
void arap_interp_free(struct arap_interp *a);

/* The fourth vertex of a triangle (Eq. 3.1).  a, b, c, out: 3. */
void tet_fourth_vertex(const double *a, const double *b, const double *c, double *out);

#ifdef __cplusplus
}
#endif
#endif
