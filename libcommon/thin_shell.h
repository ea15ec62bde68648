/* thin_shell.h -- the discrete thin shell of Froehlich & Botsch (2011,
 * "Example-driven deformations based on discrete shells") with the
 * E-StopMotion thesis' changes (Sec. 4.4, Eq. 4.60-4.64): per-edge stretch
 * and bend stiffness taken from a local (per-vertex) stiffness map, a
 * per-face tetrahedron volume term and a soft landmark term, minimized by
 * Gauss-Newton with analytic Jacobians and a CHOLMOD factorization of
 * J^T J (pattern analyzed once, refactored every iteration).
 *
 * Every term is a squared residual, E(X) = 1/2 sum r^2, all dimensionless:
 *
 *   stretch, every edge e = (i,j):
 *       r_e = sqrt(ks k_e) (|x_i - x_j| / L_e - 1)
 *   bend, every interior (manifold, consistently oriented) edge:
 *       r_e = sqrt(kb k_e) * L_e / sqrt(A_e / 3) * (theta_e - theta0_e)
 *     (theta: signed dihedral angle, A_e: rest area of the two faces, so
 *      kb k_e L_e^2 / (A_e/3) (theta - theta0)^2 is Froehlich-Botsch's
 *      bending energy; theta - theta0 wrapped to (-pi, pi])
 *   volume, every face f = (a,b,c):
 *       r_f = sqrt(kv kbar) (vol_f(X) - vol_f(V)) / vbar,
 *       vol_f(X) = (x_a - o) . ((x_b - o) x (x_c - o)) / 6
 *     (o: the apex, see below; vbar: mean |vol_f(V)|; for a closed mesh
 *      sum_f vol_f is the enclosed volume, thesis Eq. 4.63; kbar: the mean
 *      vertex stiffness, so the volume keeps its weight against the
 *      stretch and bend terms whatever the scale of the stiffness map)
 *   enclosed volume (one residual, its Jacobian row is dense):
 *       r_V = sqrt(kvg kbar #F) (sum_f vol_f(X) - sum_f vol_f(V)) / |sum_f vol_f(V)|
 *   landmarks, every handle h and coordinate d:
 *       r_hd = sqrt(lambda kbar) (x_{H_h,d} - t_{h,d}) / Lbar
 *     (kbar again: the thesis weights the landmarks "proportional to the
 *      stretch and bend stiffnesses"; so k and c k give the same result)
 *
 * with k_e = (k_i + k_j) / 2 the edge stiffness averaged from the vertex
 * stiffness k (thesis Sec. 4.4.1; see stiffness.h), L_e the rest edge
 * length and Lbar the mean rest edge length.
 *
 * One Gauss-Newton iteration solves (J^T J + mu I) dx = -J^T r (mu =
 * damping * mean diagonal of the first J^T J; when CHOLMOD finds the
 * matrix numerically singular, mu grows 100-fold and the factorization is
 * retried, up to 6 times; mu relaxes by 10 per accepted step) and
 * backtracks alpha = 1, 1/2, ... until E(X + alpha dx) < E(X), so the
 * energy never increases.  The bend Jacobian of a face squashed below a
 * tenth of its rest area uses that tenth instead (the exact one grows
 * like 1/area and swamps J^T J as an obtuse face flattens under
 * compression; seen on the camel scans).
 * The sparse part of J^T J is factored by CHOLMOD (analysis on the first
 * iteration, numeric refactorization after); the dense rank-one part
 * g_V g_V^T of the enclosed-volume residual is added by Sherman-Morrison
 * (one extra right-hand side).  Iterations stop early once the energy
 * decreases by less than 1e-6 relatively.
 *
 * The apex o of the per-face tetrahedra is the rest centroid for the rest
 * volumes; before every Gauss-Newton iteration it moves to the point that
 * fits the current tetrahedra best (a 3 by 3 least-squares problem, as
 * every vol_f is affine in o; alternating minimization, so E still never
 * increases).  A rigid motion of the whole surface then leaves every
 * tetrahedron unchanged; with a fixed apex a translation or a rotation
 * about another point would be resisted.  The per-face term still resists
 * isometric bending a little (the faces on the outside of a bend move away
 * from the apex), so its default weight is small: kv = 0.1 with kvg = 10
 * (measured, see clay-deform(1)).
 */
#ifndef CM_THIN_SHELL_H
#define CM_THIN_SHELL_H
#ifdef __cplusplus
extern "C" {
#endif

struct thin_shell_params {
    double ks;       /* stretch weight, default 1 */
    double kb;       /* bend weight, default 1 */
    double kv;       /* per-face volume weight, default 0.1 (0: no per-face term) */
    double kvg;      /* enclosed-volume weight, default 10 (0: none; closed meshes) */
    double lambda;   /* landmark weight, default 100 */
    double damping;  /* Levenberg damping relative to mean diag(J^T J), default 1e-6 */
};

void thin_shell_defaults(struct thin_shell_params *p);

struct thin_shell;

/* V: #V by 3 rest shape, F: #F by 3 (consistently oriented).
 * k: #V per-vertex stiffness (NULL = all 1), positive.
 * H: nh handle (landmark) vertex indices (copied).  p: weights (NULL =
 * defaults).  Returns NULL (cm_errmsg set) on bad indices or topology. */
struct thin_shell *thin_shell_new(const double *V, const int *F, int nv, int nf,
                                  const double *k, const int *H, int nh,
                                  const struct thin_shell_params *p);
void thin_shell_free(struct thin_shell *s);

/* Number of residuals (stretch, bend, volume, landmark, in that order). */
int thin_shell_nres(const struct thin_shell *s);

/* Residuals at X (#V by 3) for handle targets T (nh by 3), with the
 * per-face apex where the last thin_shell_solve left it (at first: the
 * rest centroid).
 * r: nres (out).  With idx and g non-NULL also the Jacobian: residual q
 * depends on the vertices idx[4q .. 4q+3] (-1 = unused) with gradient
 * g[12q + 3a + d] = d r_q / d X[idx[4q+a]][d].  idx: nres by 4, g: nres by 12.
 * Returns E = 1/2 sum r^2. */
double thin_shell_residuals(const struct thin_shell *s, const double *X, const double *T,
                            double *r, int *idx, double *g);

/* The enclosed-volume residual r_V at X; grad: #V by 3 (out, may be NULL),
 * d r_V / d X (0 when kvg = 0). */
double thin_shell_volume_residual(const struct thin_shell *s, const double *X, double *grad);

/* Energy 1/2 (sum r^2 + r_V^2) at X (apex as for thin_shell_residuals). */
double thin_shell_energy(const struct thin_shell *s, const double *X, const double *T);

/* Run `iters` Gauss-Newton iterations toward handle targets T (nh by 3).
 * X: #V by 3, in: the start, out: the result.  E: iters + 1 energies (out,
 * may be NULL): E[0] at the start, E[i] after iteration i (iterations after
 * convergence repeat the last value).  Returns 0, or -1 (cm_errmsg set)
 * if the factorization fails. */
int thin_shell_solve(struct thin_shell *s, const double *T, int iters, double *X, double *E);

#ifdef __cplusplus
}
#endif
#endif
