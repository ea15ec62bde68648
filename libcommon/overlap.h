/* overlap.h -- volume overlap of two closed surfaces (thesis Sec. 2.2):
 * vol(A intersect B) / vol(A), with the intersection computed by CGAL's
 * corefinement (PMP::corefine_and_compute_intersection) and the volumes by
 * PMP::volume.  The thesis' deformation scale: 0.8-1 small, 0.4-0.8
 * intermediate, 0-0.4 large.
 */
#ifndef CM_OVERLAP_H
#define CM_OVERLAP_H
#ifdef __cplusplus
extern "C" {
#endif

/* VA, FA: source (#VA by 3, #FA by 3); VB, FB: target.  Both must be closed,
 * oriented 2-manifolds without self-intersections (checked).
 * *ratio (out): vol(A n B) / vol(A); *va, *vb, *vi (out, may be NULL): the
 * volumes.  Returns -1 (cm_errmsg names the problem) otherwise. */
int volume_overlap(const double *VA, int nva, const int *FA, int nfa,
                   const double *VB, int nvb, const int *FB, int nfb,
                   double *ratio, double *va, double *vb, double *vi);

/* "small", "intermediate" or "large" deformation for an overlap ratio. */
const char *overlap_scale(double ratio);

#ifdef __cplusplus
}
#endif
#endif
