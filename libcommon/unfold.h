/* unfold.h -- repair fold-overs of a scanned mesh: a face whose normal
 * points against at least two of its three neighbours (dot products of unit
 * normals below min_cos, e.g. -0.5: creases sharper than 120 degrees on two
 * sides) is a triangle turned over in place, a remeshing artefact,
 * not a shape: a registration or a deformation keeps it turned over.  Its
 * corners move to the centroids of their one-rings (Laplacian smoothing of
 * those vertices only), sweep after sweep, until no such face is left.
 * Connectivity and all other vertices are kept.
 */
#ifndef CM_UNFOLD_H
#define CM_UNFOLD_H
#ifdef __cplusplus
extern "C" {
#endif

/* V: #V by 3 (in/out); F: #F by 3; min_cos: the crease threshold (cosine);
 * max_sweeps: smoothing sweeps at most.
 * *found (out, may be NULL): fold-overs before the first sweep.
 * Returns the number of fold-overs left (0 when all were repaired), or -1
 * (cm_errmsg set). */
int unfold_faces(double *V, const int *F, int nv, int nf, double min_cos, int max_sweeps,
                 int *found);

#ifdef __cplusplus
}
#endif
#endif
