/* loopcap.h -- a cap over a boundary loop of a triangle mesh (the flat-ish
 * lid that closes a printed piece where it meets its neighbour part).
 *
 * The cap is a fan from a centre point when the loop, projected along the
 * normal a, is star-shaped about the centre (every fan triangle strictly
 * positive by the exact orient2 predicate, predicates2.h); otherwise the
 * constrained Delaunay triangulation of the projected loop (cdt2_polygon,
 * no new points), which is valid for any loop whose projection is simple.
 * Triangles have the fan's orientation (loop[k+1], loop[k], centre), i.e.
 * the loop's order reversed, so the cap closes a mesh whose boundary runs
 * in loop order.
 */
#ifndef CM_LOOPCAP_H
#define CM_LOOPCAP_H
#ifdef __cplusplus
extern "C" {
#endif

/* X        #V by 3 positions
 * loop     n vertex ids into X, in boundary order (n >= 3)
 * c        3 centre (the fan's apex)
 * a        3 projection normal (any length > 0; e.g. loop_area_vector)
 * centre   the vertex id the fan uses for c
 * T        out: #T by 3 triangles (malloc'd): n of them for a fan, n - 2
 *          for the triangulation
 * fan      out (may be NULL): 1 for a fan, 0 for the triangulation
 * Returns #T, or -1 with cm_errmsg (the projected loop is not simple). */
int loop_cap(const double *X, const int *loop, int n, const double c[3], const double a[3], int centre,
             int **T, int *fan);

/* Vector area of the loop (sum over k of x_k x x_{k+1} / 2), the same for
 * any centre: its direction is the loop's mean normal (out, 3). */
void loop_area_vector(const double *X, const int *loop, int n, double a[3]);

#ifdef __cplusplus
}
#endif
#endif
