/* winding.h -- generalized winding number of a closed (or nearly closed)
 * triangle mesh at a point (Jacobson et al. 2013): the sum of the signed
 * solid angles of the triangles over 4 pi.  About 1 inside, 0 outside, and
 * robust to self-intersections, small holes and fins, which is what scans
 * have.  O(#F) per query.
 */
#ifndef CM_WINDING_H
#define CM_WINDING_H
#ifdef __cplusplus
extern "C" {
#endif

/* V: #V by 3, F: #F by 3, p: 3. */
double winding_number(const double *V, const int *F, int nf, const double p[3]);

/* Volume of the set {w_A > 1/2} (and, if VB/FB are given, of {w_A > 1/2 and
 * w_B > 1/2}) by an n^3 grid over A's bounding box: *va, *vi (out). */
void winding_volumes(const double *VA, int nva, const int *FA, int nfa,
                     const double *VB, const int *FB, int nfb, int n, double *va, double *vi);

#ifdef __cplusplus
}
#endif
#endif
