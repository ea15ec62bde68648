/* distortion.h -- relative area and volume distortion of a deformed mesh
 * against its reference pose (same connectivity), thesis Eq. 3.6:
 *     d_A = A_c / A_0 - 1  per triangle,
 *     d_V = V_c / V_0 - 1  per element,
 * where the element of a triangle is the tetrahedron it spans with the
 * mesh's vertex centroid (translation invariant).  Elements whose reference
 * volume is below 1e-3 of the mean |volume| are skipped (their ratio is
 * meaningless).  Also the largest relative edge length change.
 */
#ifndef CM_DISTORTION_H
#define CM_DISTORTION_H
#ifdef __cplusplus
extern "C" {
#endif

struct distortion {
    double area_mean, area_sigma;   /* of d_A over triangles */
    double area_abs;                /* mean of |d_A| */
    double vol_mean, vol_sigma;     /* of d_V over the kept elements */
    int vol_n;                      /* elements kept */
    double edge_max;                /* max over edges of |l / L - 1| */
    double volume_rel;              /* enclosed volume V / V0 - 1 (closed meshes) */
};

/* V0, V: #V by 3 reference and current positions, F: #F by 3. */
int mesh_distortion(const double *V0, const double *V, const int *F, int nv, int nf,
                    struct distortion *d);

#ifdef __cplusplus
}
#endif
#endif
