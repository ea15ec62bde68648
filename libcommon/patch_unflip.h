/* patch_unflip.h -- restore injectivity on the patches of a registration
 * whose faces point against the target (mesh-metrics' flipped faces), by a
 * foldover-free solve on each patch, the rest of the mesh fixed.
 *
 * A pleat (three layers on the target, the middle one turned over) cannot
 * be smoothed out by small moves that stay on the target (nricp_untangle.h):
 * the turned layer has to pass through a degenerate state.  Here, for each
 * connected patch (the vertices of the flipped faces and `rings` rings
 * around them; its faces, those touching them):
 *   - every patch face f gets the tangent plane of the target under it (the
 *     normal of the target face closest to its centroid); J_f is the 2 by 2
 *     map from the rest triangle (R, in its own plane) to the face projected
 *     on that plane, so det J_f < 0 exactly where the face is flipped;
 *   - the patch's free vertices minimise (L-BFGS) the untangling energy of
 *     Garanzha, Kaporin, Kudryavtseva, Protais, Ray and Sokolov ("Foldover-
 *     free maps in 50 lines of code", 2021),
 *        sum_f A_f (|J_f|^2 + lambda (det J_f^2 + 1)) / chi(det J_f, eps),
 *        chi(D, eps) = (D + sqrt(eps^2 + D^2)) / 2,
 *     finite for folded faces while eps > 0 and a barrier once eps has
 *     shrunk (their rule for eps), plus the data terms: each free vertex and
 *     each face centroid pulled onto the tangent plane of its closest target
 *     point (wdata, wface), and the target vertices that the patch covered at
 *     the start (their closest point of the pose lay on a patch face) pulling
 *     their closest point of the patch (wback), so that ironing the pleat out
 *     does not uncover the target's crease; tangent planes and closest
 *     points are updated every outer iteration;
 *   - the free vertices are projected onto the target, except where that
 *     move would turn a face over that the solve left unflipped (closest
 *     points fold a thin, creased part such as a fetlock): the vertices of
 *     such a face move half as far, up to 6 times, then stay off it.
 * Three strengths of the backward pull are tried (wback times 1, 0.1, 10);
 * kept is the one with the fewest flipped faces, and only where that is
 * fewer than the patch had and no target vertex near the patch, and no
 * sample (centroid, edge midpoints) of a patch face, lies farther from the
 * other surface than the symmetric Hausdorff distance before (or than
 * `allow`, where that is larger): by default the Hausdorff distance cannot
 * grow.
 */
#ifndef CM_PATCH_UNFLIP_H
#define CM_PATCH_UNFLIP_H
#include "closest_point.h"
#ifdef __cplusplus
extern "C" {
#endif

struct patch_unflip_params {
    int rings;       /* rings around the flipped faces' vertices that move (default 2) */
    int rounds;      /* rounds over the faces still flipped, each with one ring more
                        (default 1; 2 brought camel 01 -> 03 to 0.96% and 01 -> 04 to
                        1.08%, but the camel chain's last keys to 0.95% and 1.09%
                        from 0.55% and 0.75%) */
    int iters;       /* outer iterations (eps updates) per patch (default 30) */
    double wdata;    /* weight of the distance to the target (default 10) */
    double wface;    /* weight of the face centroids' distance to the target (default 100) */
    double wback;    /* weight of the target vertices the patch covered, pulling the
                        closest point of the patch (default 100) */
    double lambda;   /* weight of the area term against the conformal one (default 1) */
    int max_verts;   /* patches with more free vertices are left alone (default 2000) */
    double max_flipped; /* a pose with more than this fraction of its faces flipped is
                        left alone: a start that went wrong, not a pleat (default 0.03:
                        on camel 01 -> 04 the starts above it ended at 139-413 flipped
                        faces after the solve, at up to 16 s each) */
    double tol;      /* thin-part allowance of the flip test (flipped_face_flags), in
                        the points' units (e.g. FLIP_THIN_TOL diagonals) */
    double allow;    /* a kept patch's samples may lie up to this far from the other
                        surface where that is farther than the symmetric Hausdorff
                        distance before, in the points' units (default 0: no farther
                        than before; nricp's last unflip allows its acceptance
                        distance, 1% of the diagonal: a pleat at a camel fetlock laid
                        flat bridges the crease it had folded into) */
};

void patch_unflip_defaults(struct patch_unflip_params *p);

/* P: #V by 3 (in: the registered pose, out: repaired), R: #V by 3 the rest
 * shape (the distortion is measured from it), F: #F by 3 faces;
 * VT: #VT by 3 target, FT: #FT by 3, TT: its tree (closest_point.h).
 * stats (out, may be NULL): flipped faces before, after, patches tried,
 * patches kept.  Returns 0, or -1 (cm_errmsg set). */
int patch_unflip(double *P, const double *R, const int *F, int nv, int nf,
                 const double *VT, const int *FT, int nvt, int nft,
                 const struct closest_point_tree *TT, const struct patch_unflip_params *p,
                 int stats[4]);

/* The same solve on the patches around the faces seed (#F) flags, not the
 * flipped ones: a patch is kept where no face of it is flipped that was
 * not and the largest distance of its samples and of the target vertices
 * near it (the test above) is lower than the symmetric Hausdorff distance
 * before, so the distance there drops and nowhere grows.  For the samples
 * that stay farthest because moving them would fold a face (an edge
 * standing across a crease the target folds into, at a camel fetlock: the
 * refinement's foldover guard holds it), since the solve lays the patch
 * down on the target with no face folded.  p->rounds: 1 is the one
 * meaningful value (the seed does not change).  Returns as patch_unflip;
 * stats[3]: patches kept. */
int patch_refit(double *P, const double *R, const int *F, int nv, int nf,
                const double *VT, const int *FT, int nvt, int nft,
                const struct closest_point_tree *TT, const struct patch_unflip_params *p,
                const unsigned char *seed, int stats[4]);

#ifdef __cplusplus
}
#endif
#endif
