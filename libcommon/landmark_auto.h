/* landmark_auto.h -- corresponding landmarks between two scans of one
 * character in different poses, without hand work.
 *
 * 1. Extremities of each mesh (tips of limbs, head, tail, ears): the
 *    vertices that are local maxima, within a geodesic radius, of the
 *    geodesic distance from both ends of an approximate diameter (the
 *    feature points of Tierny et al.).
 *    Geodesics: the heat method (geodesic.h).
 * 2. Matching: an injective partial map from A's extremities to B's that
 *    keeps the geodesic distances between matched extremities (isometry),
 *    found by beam search; every unmatched extremity costs a penalty, and
 *    every matched pair the difference of the areas of their geodesic
 *    discs (disc_weight): a foot and a snout can lie at the same distances
 *    from the other tips, but a disc on a thin leg gathers half the area.
 * 3. Left and right: a bilateral character's intrinsic distances cannot
 *    tell its left legs from its right ones (the mirrored map costs the
 *    same).  Among the maps within a small margin of the best cost, the one
 *    whose matched extremities keep their orientation wins: the signs of
 *    the triple products (x_i - c) . ((x_j - c) x (x_k - c)) over all
 *    triples, c the area centroid, weighted by the smaller volume.
 *    That sign test is extrinsic: a limb swung across the body (a leg
 *    lifted forward, a trunk swung aside) turns some triples over, and a
 *    wrong map (the trunk taken for an ear) can agree better than the
 *    right one.  With verify on, the orientation is not trusted alone:
 *    the near-best maps chosen with weights 1, 1/2, 1/4 and 0
 *    on the orientation are each tested by deformation -- A's matched tips
 *    aligned rigidly (no reflection) onto B's, A deformed as rigidly as
 *    possible until they sit there (clay_deform.h), then the mean
 *    closest-point distance both ways -- and the map that fits B best
 *    wins.  A mirrored map cannot be aligned without a reflection and fits
 *    badly; a swapped limb leaves a limb where B has none.  Off by
 *    default: on a narrow body (the camel) the deformation crosses the
 *    legs about as cheaply as not (landmark-auto(1) has the figures).
 *    Pairs that disagree with the rest on average are dropped; then the
 *    leftovers get a second chance (second_ratio): a limb stretched far in
 *    one pose is not isometric to the other, but its tip is still the
 *    clear best partner of the other pose's leftover tip.
 * 4. More landmarks on the limbs: for each matched extremity, on the ring
 *    at geodesic distance t x (its distance to the nearest other matched
 *    extremity) the vertex with the smallest sum of distances to the other
 *    matched extremities (the limb's inner side); optionally the cores
 *    (the smallest sum of distances to all of them: ill-defined on a round
 *    body, off by default).
 */
#ifndef CM_LANDMARK_AUTO_H
#define CM_LANDMARK_AUTO_H
#ifdef __cplusplus
extern "C" {
#endif

struct landmark_auto_params {
    double radius;      /* local-maximum radius, fraction of sqrt(area) (default 0.1) */
    double penalty;     /* cost of an unmatched extremity, fraction of sqrt(area) (default 0.25) */
    double margin;      /* maps within (1 + margin) x the best cost compete on orientation (default 0.5) */
    int beam;           /* beam width of the matching search (default 400) */
    int max_extremities;/* keep at most this many per mesh, farthest first (default 12) */
    double limb_t[4];   /* fractions t for limb landmarks (see 4.) */
    int nlimb;          /* how many of limb_t (default 1: 0.35) */
    int core;           /* 1: also pair the cores (default 0) */
    double disc_weight; /* a matched pair costs disc_weight x penalty x sum over radii
                           r = 0.05, 0.1, 0.2 sqrt(area) of |log(a_A(r) / a_B(r))|, a(r)
                           the area within geodesic distance r of the extremity over the
                           whole area: a hoof is not a snout (default 1; 0: off) */
    int verify;         /* 1: the near-best maps are tested by deformation (see 3.);
                           0: the map with the best score + orientation (default) */
    double second_ratio;/* leftover extremities (a limb stretched far in one pose, not
                           isometric to the other): pair a leftover of A with one of B
                           whose mean mismatch to the matched ones is below penalty and
                           at least this many times smaller than any rival's, both ways,
                           none of the distances off by more than 2 penalty, both tips
                           on average as far from the matched tips as these are from
                           each other (a limb, not a bump on the body) (default 1.5; 0: off) */
};
void landmark_auto_defaults(struct landmark_auto_params *p);

/* Extremities of one mesh.
 *   V #V by 3, F #F by 3 (an oriented manifold, one component)
 *   E (out, malloc'd) their vertex indices, farthest from the rest first
 * Returns their number, -1 on error (cm_errmsg). */
int mesh_extremities(const double *V, const int *F, int nv, int nf,
                     const struct landmark_auto_params *p, int **E);

struct landmark_pairs {
    int n;
    int *a, *b;         /* n vertex indices of A and of B */
    int *kind;          /* n: 0 extremity, 1 limb point, 2 core */
    int na, nb;         /* extremities found on A and B */
    int matched;        /* extremity pairs */
    int second;         /* of them paired in the second chance (second_ratio) */
    double cost;        /* mean |dA - dB| over matched extremity pairs, over sqrt(area of A) */
    double orient;      /* orientation agreement of the chosen map, -1..1 */
    double orient_mirror;/* that of the best mirrored competitor (-2: none) */
    int verified;       /* maps tested by deformation (0: one candidate, or verify off;
                           -1: the test could not run, e.g. a part without a tip for the
                           deformation to hold: the map of score + orientation is kept,
                           why says why) */
    char why[160];
    double fit, fit_next;/* the chosen map's deformation fit and the next best's, over
                           sqrt(area of B) (when verified >= 2) */
    int changed;        /* 1: the fit chose another map than score + orientation would */
};

/* Corresponding landmarks of A (VA, FA) and B (VB, FB).  Returns 0 or -1
 * (cm_errmsg: a mesh the heat method refuses, fewer than 3 matched
 * extremities). */
int landmark_auto(const double *VA, const int *FA, int nva, int nfa,
                  const double *VB, const int *FB, int nvb, int nfb,
                  const struct landmark_auto_params *p, struct landmark_pairs *out);
void landmark_pairs_free(struct landmark_pairs *L);

#ifdef __cplusplus
}
#endif
#endif
