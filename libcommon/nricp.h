/* nricp.h -- optimal-step non-rigid ICP (Amberg, Romdhani, Vetter 2007),
 * as in the E-StopMotion thesis Sec. 5.2.1 (Eq. 5.1-5.5, Algorithm 2).
 *
 * Every source vertex i gets an affine map X_i (4 by 3, acting on the row
 * [v_i 1]).  For each stiffness alpha of a decreasing schedule, repeat until
 * the maps stop changing:
 *   1. correspondences: the closest POINT u_i on the target surface to each
 *      deformed source vertex (closest_point.h), weight w_i = 1, or 0 when
 *      the normals differ by more than max_angle, when u_i lies on the
 *      target's boundary, or when it is farther than max_dist;
 *      and, if backward > 0, the other way round: the closest point of the
 *      current source surface to each target vertex (so every part of the
 *      target pulls some of the source: coverage), same rejections;
 *   2. solve the normal equations of
 *      E(X) = alpha^2 sum_edges |G (X_i - X_j)|^2 + sum_i w_i^2 |[v_i 1] X_i - u_i|^2
 *           + beta^2 sum_landmarks |[v_l 1] X_l - l|^2 + backward terms,
 *      G = diag(1, 1, 1, gamma), one sparse SPD system of size 4 #V with
 *      three right-hand sides, refactored (CHOLMOD, analysis kept) each time.
 * The landmark weight beta fades linearly from beta to 0 over the schedule.
 * Finally (relax > 0) a few sweeps remove the small fold-overs that closest
 * point correspondences leave in concave creases: each vertex moves half way
 * to its one-ring centroid within its tangent plane, then onto its closest
 * point on the target (if that correspondence passes the same tests).
 * Internally coordinates are centred on the target and divided by its
 * bounding-box diagonal, so the parameters do not depend on the scale.
 */
#ifndef CM_NRICP_H
#define CM_NRICP_H
#ifdef __cplusplus
extern "C" {
#endif

struct nricp_params {
    int steps;             /* stiffness steps (default 12) */
    double alpha_max;      /* first stiffness (default 50) */
    double alpha_min;      /* last stiffness, geometric schedule (default 0.5) */
    double beta;           /* initial landmark weight (default 10) */
    double gamma;          /* weight of the translation column in G (default 1) */
    double max_angle;      /* normal rejection angle, degrees (default 60) */
    double max_dist;       /* rejection distance, fraction of the target diagonal (default 0.1; <= 0 off) */
    double backward;       /* weight of target->source correspondences (default 1; 0 off) */
    double eps;            /* inner loop stops when the RMS change of the deformed vertices,
                              relative to the diagonal, is below eps (default 1e-4) */
    int max_inner;         /* inner iterations per stiffness (default 3) */
    int nearest_vertex;    /* baseline: correspondence = the nearest corner of the closest
                              triangle (~ the closest target vertex) instead of the closest
                              point; default 0 */
    int untangle;          /* untangling rounds after the schedule (default 10; 0 off): while
                              faces are flipped (mesh_distance.h flipped_face_flags), ARAP
                              (rest shape: the source, 100 local/global Gauss-Seidel sweeps)
                              on their vertices and one-rings, the closest target points as
                              soft constraints, then the relax sweeps; the pose with the
                              fewest flipped faces is returned */
    double untangle_weight;/* weight of those constraints against one edge's ARAP term (default 100) */
    int relax;             /* final fold-removal sweeps (default 5; 0: pure Amberg) */
};

void nricp_defaults(struct nricp_params *p);

/* Called after every stiffness step with the current deformed source
 * (#VS by 3), the step index and its stiffness; return nonzero to stop.
 * Steps >= p->steps are untangling rounds (return value ignored): flipped
 * is the number of flipped faces that round starts from (-1 for the
 * schedule's steps). */
typedef int (*nricp_step_fn)(void *ctx, int step, double alpha, double beta, int inner,
                             int rejected, int flipped, const double *X);

/* VS: #VS by 3 source (already rigidly aligned), FS: #FS by 3;
 * VT: #VT by 3 target, FT: #FT by 3.
 * lm_src: nl source vertex indices, lm_dst: nl by 3 target positions.
 * X: #VS by 3 (out) registered source positions.
 * Returns 0, or -1 (cm_errmsg set) on bad indices or a failed solve. */
int nricp_register(const double *VS, const int *FS, int nvs, int nfs,
                   const double *VT, const int *FT, int nvt, int nft,
                   const int *lm_src, const double *lm_dst, int nl,
                   const struct nricp_params *p, double *X, nricp_step_fn cb, void *ctx);

#ifdef __cplusplus
}
#endif
#endif
