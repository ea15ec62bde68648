/* laplacian.h -- cotangent Laplacian and mass matrices of a triangle mesh.
 *
 * Convention (as libigl's cotmatrix): L is symmetric negative semi-definite,
 *   L_ij = (cot a_ij + cot b_ij) / 2 for an edge ij with opposite angles a, b,
 *   L_ii = -sum_j L_ij, so every row sums to zero.
 * The mass matrix is diagonal and returned as a vector.
 */
#ifndef CM_LAPLACIAN_H
#define CM_LAPLACIAN_H
#include "sparse.h"
#ifdef __cplusplus
extern "C" {
#endif

/* Add the cot Laplacian's entries to T (#V by #V, all entries, both
 * halves), scaled by `scale`.  V: #V by 3, F: #F by 3. */
void cot_laplacian_triplets(const double *V, const int *F, int nf, double scale,
                            struct triplets *T);

/* L: #V by #V cot Laplacian, unsymmetric storage (stype 0). */
cholmod_sparse *cot_laplacian(const double *V, const int *F, int nv, int nf);

/* W: #E per-edge cotangent weights (out), W[e] = (cot a_e + cot b_e) / 2 for
 * edge e = (E[2e], E[2e+1]) of the topology t built from F (a boundary
 * edge has one term): the cot Laplacian's off-diagonal entries per edge,
 * for methods that work on edges (ARAP, shells). */
struct topology;
void cot_edge_weights(const double *V, const int *F, int nf, const struct topology *t, double *W);

/* Umbrella (uniform Laplacian) smoothing, explicit: in each of `sweeps`
 * sweeps every vertex i with mask[i] != 0 (mask NULL: all) moves by
 * lambda times the way to the mean of its neighbours at the start of the
 * sweep, p_i <- (1 - lambda) p_i + lambda mean_j p_j.  V: #V by 3 (in/out),
 * t: its topology; vertices without neighbours stay.  Returns 0, or -1
 * (cm_errmsg set) when out of memory. */
int umbrella_smooth(const struct topology *t, const unsigned char *mask, double lambda, int sweeps,
                    double *V);

enum mass_type { MASS_BARYCENTRIC, MASS_VORONOI };

/* M: #V diagonal mass entries (out).  Barycentric: a third of the incident
 * areas.  Voronoi: mixed Voronoi areas (Meyer et al. 2003), obtuse
 * triangles split barycentrically.  Isolated vertices get 0. */
void mass_diag(const double *V, const int *F, int nv, int nf, enum mass_type type, double *M);

#ifdef __cplusplus
}
#endif
#endif
