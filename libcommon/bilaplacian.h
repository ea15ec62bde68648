/* bilaplacian.h -- the squared-Laplacian (bi-Laplacian) energy matrix of a
 * triangle mesh, mixed FEM discretization (Jacobson et al. 2010), as used by
 * StopShop's part boundary homogenization (Eq. 7-8):
 *
 *   int ||Laplacian(D)||^2 dA  ~  tr(D^T Q D),   Q = L^T M^-1 L
 *
 * with L the symmetric cot Laplacian and M the diagonal mass matrix of the
 * mesh V, F (laplacian.h).  Q is symmetric positive semi-definite; its null
 * space holds the constant functions of each connected component.
 */
#ifndef CM_BILAPLACIAN_H
#define CM_BILAPLACIAN_H
#include "laplacian.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Q: #V by #V, symmetric with only the upper triangle stored (stype 1).
 * V  #V by 3 positions (StopShop: the average mesh), F  #F by 3,
 * type  the mass matrix (MASS_VORONOI is the mixed-FEM choice).
 * Vertices of zero mass (isolated, or only in zero-area triangles) get
 * zero rows and columns.  Returns NULL (cm_errmsg set) on failure. */
cholmod_sparse *bilaplacian(const double *V, const int *F, int nv, int nf,
                            enum mass_type type);

/* tr(D^T Q D) for D  #V by ncols (row-major), Q as returned above (stype 1
 * upper) or with both halves stored (stype 0). */
double quadratic_energy(const cholmod_sparse *Q, const double *D, int ncols);

#ifdef __cplusplus
}
#endif
#endif
