/* arap_deform2d.h -- as-rigid-as-possible shape manipulation of a 2D mesh
 * with point handles (Igarashi, Moscovich, Hughes 2005), used to make pose
 * variations of one drawing (N-way morphing Sec. 3.2).
 *
 * Step 1 (similarity): every vertex c of a triangle is expressed in the
 * frame of the opposite edge (a, b) of the rest shape,
 *   c - a = x (b - a) + y R90 (b - a),
 * and sum || v_c - v_a - x (v_b - v_a) - y R90 (v_b - v_a) ||^2 over the three
 * corners of every triangle is minimized with the handles fixed (2n unknowns,
 * one SPD system).
 * Step 2 (scale adjustment): each rest triangle is fitted to its step-1 image
 * by a rotation and translation (2D Procrustes; Igarashi fits a similarity
 * and rescales it, which gives nearly the same triangle), then
 * sum over triangle edges || (v_j - v_i) - (f_j - f_i) ||^2 is minimized
 * with the handles fixed (x and y separately).
 * Both matrices depend only on the rest shape and the handle set: they are
 * factored once, and every set of handle positions costs a few solves.
 */
#ifndef CM_ARAP_DEFORM2D_H
#define CM_ARAP_DEFORM2D_H
#ifdef __cplusplus
extern "C" {
#endif

struct arap_deform2d;

/* V: #V by 3 rest positions (x, y used); F: #F by 3; H: nh handle vertex
 * indices (distinct, nh >= 2, at least 2 in every connected component;
 * every vertex in a triangle).  NULL on failure (cm_errmsg names a piece
 * with too few handles). */
struct arap_deform2d *arap_deform2d_new(const double *V, int nv, const int *F, int nf,
                                        const int *H, int nh);
/* P: nh by 2 handle targets; out: #V by 3 (z = 0). */
int arap_deform2d_solve(struct arap_deform2d *D, const double *P, double *out);
void arap_deform2d_free(struct arap_deform2d *D);

#ifdef __cplusplus
}
#endif
#endif
