/* buried.h -- a scan's buried skin: the faces whose front lies inside the
 * scan's own volume.
 *
 * Where two parts of a scanned character pass through each other (a thigh
 * pushed into the flank, two legs crossing), each part's skin runs on
 * inside the other: those faces are in the file but are not the outside of
 * any solid, and no registration of a clean source can both lie on them
 * and keep its own faces turned the right way.  A face is buried when the
 * generalized winding number of the whole mesh (winding.h) at the point
 * `offset` in front of its centroid, along its normal, is above 1/2.  On a
 * closed scan without self-intersections no face is buried; a face whose
 * orientation is reversed is buried too (its front is the inside).
 * O(#F^2): every test sums the solid angles of all faces (about 2.5 s CPU
 * for 10k faces), on nthreads threads (parallel.h; the flags do not depend
 * on the number of threads).
 */
#ifndef CM_BURIED_H
#define CM_BURIED_H
#ifdef __cplusplus
extern "C" {
#endif

/* V: #V by 3 positions, F: #F by 3 faces (nv, nf);
 * offset: distance in front of each centroid where the winding number is
 *   taken (> 0; e.g. 1e-4 of the bounding-box diagonal: far below an edge);
 * rings: the flags then grow by this many rings of faces sharing a vertex
 *   with a flagged face (0: the buried faces alone);
 * nthreads: threads (<= 0: one per processor);
 * zone: #F (out) 1 for the buried faces and the rings around them.
 * Returns the number of buried faces (before growing), or -1 (cm_errmsg). */
/* The tools' offset: this fraction of the bounding-box diagonal (about a
 * hundredth of an edge on a 10k-face scan). */
#define BURIED_OFFSET 1e-4

int buried_faces(const double *V, int nv, const int *F, int nf, double offset, int rings,
                 int nthreads, unsigned char *zone);

#ifdef __cplusplus
}
#endif
#endif
