/* nricp_untangle.h -- the last stage of nricp: iron out the pleats a
 * registration leaves where the target's skin folds.
 *
 * Where the target folds (an armpit, a groin), the source has more surface
 * than the target shows, and closest points lay the excess on the target
 * in a pleat: three layers on the surface, the middle one turned over.  Its
 * faces lie on the target (distance ~0) but point against it: the flipped
 * faces of mesh-metrics.  The ARAP fit does not see them, since a rotation
 * by a half turn about a tangent axis maps the rest ring onto the turned
 * layer.  Here the pleat is smoothed out on the target itself: every
 * vertex of a flipped face and of `rings` rings around it moves to the
 * umbrella mean of its neighbours, projected back to the closest point of
 * the target (tangential Laplacian smoothing, which spreads the excess
 * over the region), the rest of the mesh fixed; the flipped faces are
 * recounted every `check` sweeps and the region regrown, until none is
 * left or `iters` sweeps are done.
 */
#ifndef CM_NRICP_UNTANGLE_H
#define CM_NRICP_UNTANGLE_H
#include "closest_point.h"
#ifdef __cplusplus
extern "C" {
#endif

struct nricp_untangle_params {
    int rings;     /* rings around the flipped faces' vertices that move too (default 1) */
    int iters;     /* at most this many smoothing sweeps (default 60) */
    int check;     /* sweeps between recounts of the flipped faces (default 5) */
    double max_move;  /* no vertex moves farther than this many mean edge lengths from
                         where it started (default 1; <= 0: no limit) */
    double tol;    /* thin-part allowance of the flip test (flipped_face_flags), in
                      the points' units (default 0: set it, e.g. FLIP_THIN_TOL diagonals) */
};

void nricp_untangle_defaults(struct nricp_untangle_params *p);

/* P: #V by 3 (in: the registered pose, out: untangled), F: #F by 3 faces;
 * VT: #VT by 3 target, FT: #FT by 3, TT: its tree (closest_point.h).
 * flipped (out, may be NULL): the flipped faces before and after.
 * Returns 0, or -1 (cm_errmsg set). */
int nricp_untangle(double *P, const int *F, int nv, int nf,
                   const double *VT, const int *FT, int nvt, int nft,
                   const struct closest_point_tree *TT, const struct nricp_untangle_params *p,
                   int flipped[2]);

#ifdef __cplusplus
}
#endif
#endif
