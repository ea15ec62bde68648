/* nway_blend.h -- N-way as-rigid-as-possible blending of compatible 2D
 * meshes (Baxter, Barla, Anjyo, N-way morphing Sec. 4.2; Alexa et al. 2000).
 *
 * For every triangle t and shape i, A_ti = R(alpha_ti) S_ti maps the base
 * triangle onto shape i (polar2).  Angles are unwrapped consistently: a
 * breadth-first walk over the triangle adjacency adds multiples of 2 pi so
 * neighbouring triangles differ by less than pi.  For weights w:
 *
 *   alpha_t(w) = sum_i w_i alpha_ti      (always the raw weights)
 *   S_t(w)     = sum_i w'_i S_ti         (w' = shear-limited weights, or w)
 *   A_t(w)     = R(alpha_t(w)) S_t(w)
 *
 * and the vertices minimize sum_t area_t || J_t(V) - A_t(w) ||_F^2 with one
 * vertex fixed per connected component (its translation; the component's
 * lowest vertex index, at sum_i w_i of its positions) and every vertex in
 * no triangle fixed the same way, J_t(V) the gradient of the map from the
 * base triangle: a Laplacian system factored once (quad_solver), solved per
 * frame for x and y.
 */
#ifndef CM_NWAY_BLEND_H
#define CM_NWAY_BLEND_H
#ifdef __cplusplus
extern "C" {
#endif

struct nway_blend;

/* X: N arrays of #V by 3 positions (only x, y are used); F: #F by 3;
 * base: the base pose index.  Fails on a degenerate base triangle. */
struct nway_blend *nway_blend_new(double *const *X, int N, int nv, const int *F, int nf, int base);
/* Blend with weights w (N, summing to 1); ws: weights for the stretch part
 * (NULL = w); the fixed vertices (one per connected component) go to
 * sum_i w_i of their positions; out: #V by 3 (z = 0). */
int nway_blend_eval(struct nway_blend *B, const double *w, const double *ws, double *out);
void nway_blend_free(struct nway_blend *B);

/* Hermite smoothstep phi(t, a, b): 0 below a, 1 above b, 3u^2 - 2u^3 between. */
double hermite_step(double t, double a, double b);
/* Soft clamp to [0, 1]: t on [0, 1]; below, d tanh(t / d) (in (-d, 0));
 * above, 1 + d tanh((t - 1) / d).  C2 at 0 and 1. */
double soft_clamp(double t, double d);

/* Shear limiting: w'_i = phi(w_i) / sum_j phi(w_j) (uniform if the sum is
 * not positive).  mode SHEAR_SOFT (default): phi = soft_clamp(., SHEAR_MARGIN),
 * the identity on [0, 1], so weights inside the pose simplex (all in
 * [0, 1], summing to 1) are unchanged and the morph there is plain ARAP;
 * only extrapolated weights are bent back (to at most SHEAR_MARGIN beyond).
 * mode SHEAR_HERMITE: the paper's phi = hermite_step(., 0, 1), which also
 * remaps weights inside [0, 1] (3t^2 - 2t^3). */
enum { SHEAR_SOFT = 0, SHEAR_HERMITE = 1 };
#define SHEAR_MARGIN 0.1
void shear_limit_weights(const double *w, int N, int mode, double *wl);
/* Texture weights: w*_i = sigma phi(w'_i, sigma/2, 1 - sigma/2) + (1 - sigma) w'_i,
 * normalized; w' = the Hermite-limited weights (SHEAR_HERMITE) or the weights
 * clamped to [0, 1] and normalized (SHEAR_SOFT): colours never extrapolate. */
void texture_weights(const double *w, int N, int mode, double sigma, double *wt);

#ifdef __cplusplus
}
#endif
#endif
