/* nricp.h -- optimal-step non-rigid ICP (Amberg, Romdhani, Vetter 2007),
 * as in the E-StopMotion thesis Sec. 5.2.1 (Eq. 5.1-5.5, Algorithm 2).
 *
 * Every source vertex i gets an affine map X_i (4 by 3, acting on the row
 * [v_i 1]).  For each stiffness alpha of a decreasing schedule, repeat until
 * the maps stop changing:
 *   1. correspondences: the closest POINT u_i on the target surface to each
 *      deformed source vertex (closest_point.h), weight w_i = 1, or 0 when
 *      the normals differ by more than max_angle (unless an agreeing point
 *      lies within search farther: then that one), when u_i lies on the
 *      target's boundary, or when it is farther than max_dist;
 *      and, if backward > 0, the other way round: the closest point of the
 *      current source surface to each target vertex (so every part of the
 *      target pulls some of the source: coverage), same rejections;
 *   2. solve the normal equations of
 *      E(X) = alpha^2 sum_edges |G (X_i - X_j)|^2 + sum_i w_i^2 |[v_i 1] X_i - u_i|^2
 *           + beta^2 sum_landmarks |[v_l 1] X_l - l|^2 + backward terms,
 *           + kappa sum_edges |(p_i - p_j) - (Q_i + Q_j)/2 (r_i - r_j)|^2,
 *      G = diag(1, 1, 1, gamma), p_i = [v_i 1] X_i, r the rest shape and
 *      Q_i the rotation closest to the one-ring's map r -> p (polar.h):
 *      an as-rigid-as-possible term (Sorkine & Alexa 2007) beside the
 *      affine one, kappa = rigid alpha / alpha_max, which keeps the local
 *      maps of the stages near rotations (off by default: neutral on the
 *      camel scans, see nricp(1));
 *      one sparse SPD system of size 4 #V with three right-hand sides,
 *      refactored (CHOLMOD, analysis kept) each time; the rotations and the
 *      solve alternate rigid_iters times on one factorization.
 * The landmark weight beta fades linearly from beta to 0 over the schedule.
 * Coarse to fine (coarse > 0): the first steps (the stiff ones) run on the
 * source remeshed coarser, landmarks and correspondences alike; each fine
 * vertex then takes the blend of the coarse affine maps at its closest
 * point of the coarse mesh, and the last fine_steps steps run on the source.
 * At low stiffness the per-vertex affine maps may mirror a few triangles
 * where vertices crowd into a crease or onto a tip.  So finally (fit > 0)
 * the pose is refined by arap_fit (arap_fit.h): the same correspondences
 * with an as-rigid-as-possible regularizer relative to the source, whose
 * rotations cannot mirror, point-to-plane data terms that let the mesh slide
 * along the target, and folded faces released from the data terms.
 * Where the target's skin folds, the fit may still lay the source's
 * surplus on the target in a pleat (faces on the target, turned over);
 * with untangle > 0 nricp_untangle.h smooths them out on the target, and
 * with unflip > 0 patch_unflip.h lays what is left flat by a foldover-free
 * solve on each flipped patch.
 * Internally coordinates are centred on the target and divided by its
 * bounding-box diagonal, so the parameters do not depend on the scale.
 */
#ifndef CM_NRICP_H
#define CM_NRICP_H
#ifdef __cplusplus
extern "C" {
#endif

struct nricp_params {
    int steps;             /* stiffness steps (default 6) */
    double alpha_max;      /* first stiffness (default 50) */
    double alpha_min;      /* last stiffness, geometric schedule (default 0.5) */
    double beta;           /* initial landmark weight (default 10) */
    double gamma;          /* weight of the translation column in G (default 1) */
    double max_angle;      /* normal rejection angle, degrees (default 60) */
    double max_dist;       /* rejection distance, fraction of the target diagonal (default 0.1; <= 0 off) */
    double search;         /* a closest point whose normal disagrees gives way to the nearest
                              agreeing point within its distance + search diagonals: the
                              other side of a thin part (correspond.h; default 0.01; 0 off) */
    double backward;       /* weight of target->source correspondences (default 1; 0 off) */
    double eps;            /* inner loop stops when the RMS change of the deformed vertices,
                              relative to the diagonal, is below eps (default 1e-4) */
    int max_inner;         /* inner iterations per stiffness (default 1) */
    int nearest_vertex;    /* baseline: correspondence = the nearest corner of the closest
                              triangle (~ the closest target vertex) instead of the closest
                              point; default 0 */
    int fit;               /* ARAP fit iterations after the schedule (arap_fit.h; default 30;
                              0: pure Amberg) */
    double fit_weight;     /* its final data weight, mu_max of arap_fit (default 30) */
    int fit_smooth;        /* smoothing sweeps of its rest shape (arap_fit rest_smooth; default 1) */
    double rigid;          /* weight of the as-rigid-as-possible term inside the stiffness
                              steps: rigid x alpha / alpha_max per edge against a data weight
                              of 1 per vertex (default 0: Amberg's affine term alone; 10
                              measured neutral on the camel, see nricp(1)) */
    int untangle;          /* > 0: after the fit, the pleats where the target folds (faces
                              flipped against it, mesh-metrics' test) are smoothed out on the
                              target, with this many rings around them (nricp_untangle.h;
                              default 1; 0: off) */
    int unflip;            /* > 0: last, the patches still flipped against the target (the
                              vertices of those faces and this many rings around them) are
                              laid flat on the target by an injectivity-restoring solve,
                              each kept only where it flips fewer faces and uncovers nothing
                              (patch_unflip.h; default 2; 0: off) */
    int fit_release;       /* the ARAP fit's released vertices (folded faces and a ring
                              around them): 0 keep their place as goal (default), 1 the
                              mean of their neighbours (arap_fit_params.release_mean) */
    int rigid_iters;       /* local/global iterations of that term per correspondence
                              update (rotations refitted, same factorization; default 4) */
    double coarse;         /* > 0: coarse to fine: the schedule's stiff steps run on the
                              source remeshed isotropically to this edge length (in target
                              diagonals; mesh_clean.h), the last fine_steps on the source
                              itself, started from the coarse affine maps blended at each
                              vertex's closest point of the coarse mesh (default 0: off) */
    int rigid_const;       /* 1: the rigid term's weight stays rigid at every step instead of
                              fading with alpha / alpha_max (default 0) */
    int fine_steps;        /* steps of the schedule on the source with coarse > 0 (default 2;
                              0: every step coarse, the ARAP fit refines on the source) */
    int parts;             /* a source with parts (open boundaries or several components:
                              a face's mask, eyes, teeth; correspond_parts): -1 decide from
                              the source (default), 0 as a closed surface, 1 with parts.
                              With parts the backward pairs over source that already fits
                              are dropped (overlay) and the ARAP fit's rest smoothing keeps
                              rims and the size of small parts (arap_fit rest_keep) */
    double overlay;        /* with parts: a target point t pulls its closest source point c
                              only unless the source's own distance to the target at c is
                              below overlay |t - c| with |t - c| more than OVERLAY_TAU
                              times the RMS distance of the source's pairs (correspond.h;
                              a cap that mesh-clean laid across a hole, over the skin;
                              default 0.5; 0 off) */
    double small_parts;    /* with parts: every component whose bounding-box diagonal is at
                              most this fraction of the source's, or that has at most this
                              fraction of its vertices, is small (a tooth, an eye); small
                              components whose bounding boxes come within SMALL_PARTS_GAP
                              source diagonals of each other form a group (a row of
                              teeth), and each group ends as the rigid motion of
                              its rest that best fits its registration (procrustes.h): the
                              closest points of a part smaller than the target's faces
                              only squash it (default 0.1; 0 off) */
};

/* the gap that joins small parts into one rigid group, in source diagonals */
#define SMALL_PARTS_GAP 0.01

/* the tau of the overlay test, in RMS distances of the source's pairs */
#define OVERLAY_TAU 3

void nricp_defaults(struct nricp_params *p);

/* Called after every stiffness step with the current deformed source
 * (#VS by 3), the step index and its stiffness; return nonzero to stop.
 * Steps >= p->steps are the ARAP fit's iterations (return value ignored):
 * alpha is then its data weight and folded the number of folded faces
 * (-1 for the schedule's steps).  After the untangling (untangle > 0) it
 * is called once more with folded -2, inner and rejected the faces flipped
 * against the target before and after (X the untangled pose).  With
 * coarse > 0 it is called first with folded -3, inner and rejected the
 * coarse level's vertex and face counts (X NULL); after the unflipping
 * (unflip > 0) with folded -4, inner and rejected the flipped faces before
 * and after; the coarse steps report
 * the fine vertices moved by the coarse maps. */
typedef int (*nricp_step_fn)(void *ctx, int step, double alpha, double beta, int inner,
                             int rejected, int folded, const double *X);

/* VS: #VS by 3 source (already rigidly aligned), FS: #FS by 3;
 * RS: #VS by 3 rest shape of the ARAP fit, or NULL for VS: when VS is a
 * warm start (the previous key's registration in a chain), RS is the first
 * key itself, so the fit keeps its shape and distortion cannot build up;
 * VT: #VT by 3 target, FT: #FT by 3.
 * lm_src: nl source vertex indices, lm_dst: nl by 3 target positions.
 * X: #VS by 3 (out) registered source positions.
 * Returns 0, or -1 (cm_errmsg set) on bad indices or a failed solve. */
int nricp_register(const double *VS, const double *RS, const int *FS, int nvs, int nfs,
                   const double *VT, const int *FT, int nvt, int nft,
                   const int *lm_src, const double *lm_dst, int nl,
                   const struct nricp_params *p, double *X, nricp_step_fn cb, void *ctx);

/* The small parts (nricp_params.small_parts, frac): P (#V by 3, in: a
 * registration of the rest R with faces F, out) takes, for every group of
 * small components, the rigid motion of R's group that best fits it
 * (procrustes.h).  nricp_register does it last; a refinement after it
 * (nricp --refine) calls it again.  Returns the number of groups, -1 on
 * error (cm_errmsg set). */
int nricp_small_parts(const double *R, const int *F, int nv, int nf, double frac, double *P);

/* How much a registration X stretched its rest shape R (both #V by 3, faces
 * F #F by 3): the mean over the faces' edges of |l_X / l_R - 1|
 * (dimensionless; edges of zero rest length skipped).  A registration that
 * slid along the target, the wrong correspondence under a right-looking
 * surface, stretches one side and squeezes the other: nricp --start auto
 * weighs it against the distance to the target. */
double nricp_stretch(const double *R, const double *X, const int *F, int nf);

#ifdef __cplusplus
}
#endif
#endif
