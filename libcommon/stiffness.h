/* stiffness.h -- per-vertex stiffness maps from landmarks (E-StopMotion
 * thesis Sec. 4.4.1, Eq. 4.56-4.59, Algorithm 1).
 *
 * 1. Each landmark l gets a stiffness from its strain (Eq. 4.56 with the
 *    material constants folded into kmin): eps_l = |displacement_l| / diag,
 *        k_l = kmin (eps_max / eps_l)^gamma,  clamped to [kmin, kmax],
 *    so the landmark pulled farthest is the softest and one that barely
 *    moves is stiff (gamma = (m - 1)/m of the Ramberg-Osgood exponent m).
 * 2. The landmark values spread over the surface with weights of the
 *    distance d (Euclidean or geodesic, divided by `radius`):
 *        inverse distance (Shepard, Eq. 4.58): w = 1 / d^q,
 *        Gauss (Eq. 4.59):                     w = 1 / exp(d^q).
 *    Global propagation (Eq. 4.57): k_i = sum w_j k_j / sum w_j.
 *    Radial propagation (Algorithm 1): with normalized weights w^_j, a
 *    landmark counts fully when w^_j >= 0.4, not at all (kmax instead) when
 *    w^_j <= 0.1, and blends in between with the factor
 *    ((w^ - 0.1)/0.3)^2, so regions far from every landmark stay stiff.
 *    (The printed Algorithm 1 blends the other way round, which makes the
 *    surroundings of a landmark stiffer than farther regions; corrected.)
 */
#ifndef CM_STIFFNESS_H
#define CM_STIFFNESS_H
#ifdef __cplusplus
extern "C" {
#endif

enum stiffness_weight { STIFF_IDW, STIFF_GAUSS };
enum stiffness_spread { STIFF_GLOBAL, STIFF_RADIAL };

struct stiffness_params {
    double kmin, kmax;          /* default 1, 100 */
    double gamma;               /* Eq. 4.56 exponent (m-1)/m, default 0.5 */
    double q;                   /* weight exponent, default 2 */
    double radius;              /* distance unit, fraction of the diagonal, default 0.1 */
    enum stiffness_weight weight;
    enum stiffness_spread spread;
    int geodesic;               /* 1: geodesic distances (CGAL heat method) */
};

void stiffness_defaults(struct stiffness_params *p);

/* Landmark stiffness (step 1).  V: #V by 3 source, L: nl source vertices,
 * P: nl by 3 their targets, kl: nl (out). */
void landmark_stiffness(const double *V, int nv, const int *L, const double *P, int nl,
                        const struct stiffness_params *p, double *kl);

/* The map (step 2).  F: #F by 3 (for geodesic distances), kl: nl,
 * k: #V (out).  Returns -1 (cm_errmsg) if geodesic distances fail. */
int stiffness_map(const double *V, const int *F, int nv, int nf, const int *L,
                  const double *kl, int nl, const struct stiffness_params *p, double *k);

#ifdef __cplusplus
}
#endif
#endif
