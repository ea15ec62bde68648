/* boundary_match.h -- optimized boundary mapping between closed outlines
 * (Baxter, Barla, Anjyo, "Compatible embedding for 2D shape animation",
 * TVCG 2009, Sec. 4, as used for N-way morphing Sec. 3.1: every shape is
 * matched to shape 0, the common parameter domain).
 *
 * The mapping f from outline A (shape 0) to outline B is the elastic curve
 * alignment of Sebastian, Klein and Kimia ("On aligning curves", PAMI 2003),
 * which Baxter et al. guide with automatic correspondences: both outlines
 * are resampled uniformly by arc length (M samples per perimeter), and a
 * dynamic program finds the monotone sample path of least cost
 *
 *   sum over steps (i,j) -> (i+di, j+dj)   |dsA - dsB| + R |dthA - dthB|
 *
 * where ds is the step's arc length as a fraction of its outline's
 * perimeter (stretch) and dth the change of the tangent angle over the step
 * (bending; tangents are chords of +-0.5% of the perimeter, so pixel
 * staircases of traced outlines do not count as corners).  Steps are
 * (di, dj) in {0..3}^2 with gcd 1, so the local stretch is free between 1/3
 * and 3 and a step of one side alone costs its whole length.
 *
 * Given correspondences split both outlines into segments matched one by
 * one (a single given pair: one closed segment from that pair round to
 * itself).  With no given pair, the start on B is found by trying every
 * cyclic shift on a coarse sampling (M/4) and refining the three best
 * shifts on the fine sampling, +-1 coarse sample around each.
 *
 * Outlines are counter-clockwise polygons (rings_orient), vertex indices
 * 0-based in that order.  Arc positions are lengths from vertex 0.
 */
#ifndef CM_BOUNDARY_MATCH_H
#define CM_BOUNDARY_MATCH_H
#ifdef __cplusplus
extern "C" {
#endif

enum {
    BMATCH_ELASTIC = 0,   /* the dynamic program above (Sebastian et al.'s cost, as Baxter et al.) */
    BMATCH_ARCLENGTH = 1, /* baseline: normalized arc length between given pairs (needs one) */
    BMATCH_MULTISCALE = 2 /* default: the same program with a multi-scale feature term (below) */
};

/* Multi-scale mode: every sample carries the turning of the outline at
 * BMATCH_SCALES scales h = 1, 2, 4, 8% of the perimeter (the signed angle
 * between the chords p(s - h) -> p(s) and p(s) -> p(s + h), over pi), and
 * every step adds  F * (dsA + dsB) / 2 * mean_k |turnA_k - turnB_k|  at
 * the step's end: a leg tip, an ear or a notch is matched to the same kind
 * of feature even where the local stretch is large (articulated poses: a
 * leg swung forward moves its tip by 10% of the perimeter and more), and
 * pixel staircases, shorter than 1% of the perimeter, do not count. */
#define BMATCH_SCALES 4

struct bmatch_params {
    int mode;         /* BMATCH_MULTISCALE, BMATCH_ELASTIC or BMATCH_ARCLENGTH */
    int samples;      /* M: fine samples per perimeter (default 256; 16..4096) */
    double bend;      /* R: weight of the bending term, per radian (default 0.03) */
    double start_bend; /* R used to choose the start when no pair is given
                        (default 0.3: the shift is decided by the corners; with
                        0.03 a three-lobed test shape took the wrong lobe) */
    double feature;   /* F: weight of the multi-scale feature term (default 10) */
    double spread;    /* S: weight of the spread term (default 0: none): each step
                         adds  S (dsA + dsB) / 2 |log(a / b) - log(mA / mB)|,
                         a and b its sample counts on A and B (0 counted as
                         1/4), mA and mB the segment's: a step whose stretch
                         ratio differs from the segment's mean ratio pays for
                         it, so the stretch is spread along the segment (the
                         |dsA - dsB| term is the same for every monotone path
                         of one sign); dimensionless, like F */
    int threads;      /* threads for the start search and for bmatch_corr's maps
                         (default 1; <= 0: one per processor); the result does
                         not depend on it */
};

/* Default parameters. */
void bmatch_defaults(struct bmatch_params *prm);

/* Map outline A onto outline B.
 * A       na by 2 counter-clockwise polygon (shape 0)
 * B       nb by 2 counter-clockwise polygon
 * pairs   npairs by 2 vertex indices (row-major: A vertex, B vertex) of given
 *         correspondences, increasing cyclically along both outlines
 *         (checked); npairs = 0: the start on B is searched
 * tB      out: na arc positions on B (0 <= tB[i] < perimeter of B) of A's
 *         vertices; cyclically non-decreasing from any given pair
 * cost    out (may be NULL): the path cost (stretch + R bending)
 * Returns -1 (cm_errmsg) on bad pairs or BMATCH_ARCLENGTH without a pair. */
int bmatch_map(const double *A, int na, const double *B, int nb, const int *pairs, int npairs,
               const struct bmatch_params *prm, double *tB, double *cost);

/* Correspondence points for compat_match from few or no given ones.
 * N       number of shapes
 * P       N arrays, P[s] is n[s] by 2, counter-clockwise
 * n       N vertex counts
 * given   ngiven by N vertex indices (row-major, as compat_match's corr), in
 *         one cyclic order along every outline; ngiven >= 0
 * want    nwant vertices of shape 0 to be placed in the other shapes (points
 *         the user picked on shape 0 only); may be NULL when nwant = 0
 * K       number of points wanted (>= 3; at least ngiven + nwant are placed):
 *         the given ones, the wanted ones, then the
 *         most salient corners of shape 0 (largest turning of the +-3%
 *         chords), at least half a K-th of the perimeter apart, each mapped
 *         into every shape by bmatch_map and snapped to the nearest vertex by
 *         arc length; points that would repeat a vertex or break the cyclic
 *         order in some shape are dropped (never a given one)
 * corr    out: *ncorr by N indices, malloc'd; rows in cyclic order from the
 *         first given point (or from shape 0's first chosen point)
 * ncorr   out: number of rows (<= K)
 * cost    out (may be NULL): N path costs (cost[0] = 0)
 * Returns -1 (cm_errmsg) on bad given points, or if fewer than 3 points
 * remain. */
int bmatch_corr(int N, double *const *P, const int *n, const int *given, int ngiven, const int *want,
                int nwant, int K, const struct bmatch_params *prm, int **corr, int *ncorr, double *cost);

#ifdef __cplusplus
}
#endif
#endif
