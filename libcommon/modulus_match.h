/* modulus_match.h -- move the points a boundary matching placed along the
 * outlines so that they force as little stretch as the given points allow.
 *
 * Every four correspondence points a, b, c, d (counter-clockwise) cut each
 * pose's outline into a quadrilateral whose conformal modulus M is fixed
 * by the outline (quad_modulus.h).  Any compatible map through the points
 * changes it by at most its dilatation K, so the largest ratio of M between
 * two poses, over every quadruple, is a stretch every compatible
 * triangulation through the points must have (modulus_cert.h), and it
 * bounds the worst angle.  A matching that places points where the
 * outlines' shapes differ can force far more than the given points do
 * (the flamingo's poses 4 and 5 of issue 10: 23.4x against 7.28x for the
 * five given rows alone).
 *
 * modulus_match_polish lowers that ratio by coordinate descent on the
 * rows that are not pinned: the worst quadruple's free corners step along
 * their pose's outline (input vertices; a row stays strictly between its
 * neighbours), and a step is kept if the largest log-ratio over every
 * quadruple falls.  The moduli are the first mesh's brackets of
 * quad_modulus (the geometric mean of lo and hi; each pose meshed once),
 * so a search step costs one pair of sparse solves per quadruple that
 * contains the moved row.  Deterministic. */
#ifndef CM_MODULUS_MATCH_H
#define CM_MODULUS_MATCH_H
#ifdef __cplusplus
extern "C" {
#endif

/* N       poses
 * P       N arrays: P[s] is n[s] by 2, a simple counter-clockwise polygon
 * n       N corner counts
 * corr    ncorr by N vertex indices (row-major: corr[k*N+s]), in increasing
 *         cyclic order along every outline; changed in place
 * ncorr   rows (>= 4 for anything to happen)
 * pinned  ncorr flags: rows that stay (the given points); NULL: none
 * steps   at most this many kept moves (e.g. 64)
 * shift   a move takes a row at most this many input vertices (e.g. 3)
 * before, after (may be NULL): the largest modulus ratio over every
 *         quadruple and pair of poses (first-mesh estimates; 1 if ncorr < 4)
 * Returns the number of moves kept, -1 on error (cm_errmsg set; corr as
 * it was). */
int modulus_match_polish(int N, double *const *P, const int *n, int *corr, int ncorr,
                         const unsigned char *pinned, int steps, int shift, double *before, double *after);

#ifdef __cplusplus
}
#endif
#endif
