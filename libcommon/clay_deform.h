/* clay_deform.h -- clay-like deformation of a closed surface toward
 * landmark positions: an as-rigid-as-possible shell (Sorkine & Alexa 2007,
 * cotangent weights) whose per-edge stiffness comes from a per-vertex
 * stiffness map (thesis Sec. 4.4.1: soft where the artist pushed, stiff
 * elsewhere), a soft landmark term, and the enclosed volume restored after
 * every iteration (thesis Eq. 4.63 as a constraint).
 *
 * This is clay-deform --model arap (nricp --init-deform uses it too): the
 * same ingredients as the Froehlich-Botsch thin shell of thesis Eq.
 * 4.60-4.64 (local stiffness weighting the metric term, landmark term,
 * volume), but the local-global ARAP iteration instead of Gauss-Newton on
 * dihedral angles: one CHOLMOD factorization for the whole run, every
 * iteration is one back-substitution.  The thin shell itself, clay-deform's
 * default model, is in thin_shell.h.
 *
 *   E(X) = sum_edges k_ij w_ij |(x_i - x_j) - R_i (v_i - v_j)|^2
 *        + lambda sum_l |x_l - t_l|^2,
 *   k_ij = (k_i + k_j) / 2,  w_ij = max(cot, 0) weights of the rest shape,
 * then each vertex moves by delta along its normal with delta =
 * (V0 - V(X)) / area (closed meshes), so the volume is kept.
 */
#ifndef CM_CLAY_DEFORM_H
#define CM_CLAY_DEFORM_H
#ifdef __cplusplus
extern "C" {
#endif

struct clay_deform;

/* V: #V by 3 rest shape, F: #F by 3.  k: #V per-vertex stiffness (NULL =
 * all 1).  H: nh handle (landmark) vertex indices, lambda: their weight
 * relative to the shell (e.g. 100).  Factors the system once.
 * Returns NULL (cm_errmsg set) on bad indices or a failed factorization. */
struct clay_deform *clay_deform_new(const double *V, const int *F, int nv, int nf,
                                    const double *k, const int *H, int nh, double lambda);

/* Deform toward handle positions T (nh by 3).  X: #V by 3, in: the start
 * (e.g. the previous step), out: the result after `iters` local-global
 * iterations.  keep_volume != 0 restores the rest volume each iteration
 * (meaningful for closed meshes only). */
int clay_deform_solve(struct clay_deform *c, const double *T, int iters, int keep_volume,
                      double *X);
void clay_deform_free(struct clay_deform *c);

#ifdef __cplusplus
}
#endif
#endif
