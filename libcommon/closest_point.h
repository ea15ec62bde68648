/* closest_point.h -- closest points on a triangle mesh surface: a bounding
 * box tree of the triangles, built once and queried many times.
 *
 *   struct closest_point_tree *T = closest_point_tree_new(V, nv, F, nf);
 *   closest_point_query(T, p, c, &face, bary);     one point
 *   closest_points(T, P, n, C, I, B, D);           many points
 *   closest_point_tree_free(T);
 *
 * The tree copies the triangles, so V and F may be freed after building.
 */
#ifndef CM_CLOSEST_POINT_H
#define CM_CLOSEST_POINT_H
#ifdef __cplusplus
extern "C" {
#endif

struct closest_point_tree;

/* V: #V by 3 positions, F: #F by 3 indices (checked: 0 <= index < nv).
 * Returns NULL (cm_errmsg set) on bad indices or an empty mesh. */
struct closest_point_tree *closest_point_tree_new(const double *V, int nv, const int *F, int nf);
void closest_point_tree_free(struct closest_point_tree *T);

/* p: 3 query point.  c: 3 (out) closest point on the surface; *face (out,
 * may be NULL) the triangle it lies on; bary: 3 (out, may be NULL) its
 * barycentric coordinates in that triangle (c = sum bary_k V[F[face][k]]).
 * Returns the distance |p - c|. */
double closest_point_query(const struct closest_point_tree *T, const double p[3], double c[3],
                           int *face, double bary[3]);

/* P: n by 3 queries.  Outputs (each may be NULL): C n by 3 closest points,
 * I n face ids, B n by 3 barycentrics, D n distances.  Runs on up to two
 * threads.  Of faces exactly equally near (a query on an edge or a
 * vertex) every query function here names the one with the smallest id,
 * whatever the tree and the hints. */
void closest_points(const struct closest_point_tree *T, const double *P, int n, double *C,
                    int *I, double *B, double *D);

/* The faces within distance r of p (r >= 0): their ids go to out (at most
 * max of them, in no particular order); returns how many there are (which
 * may exceed max). */
int closest_point_faces_within(const struct closest_point_tree *T, const double p[3], double r,
                               int *out, int max);

/* Calls visit(f, ctx) for the faces f within distance r of p (r >= 0), in
 * no particular order, until a call returns nonzero; returns that value,
 * or 0 when every call returned 0 (or no face is that near). */
int closest_point_faces_within_visit(const struct closest_point_tree *T, const double p[3],
                                     double r, int (*visit)(int f, void *ctx), void *ctx);

/* The closest point to p on face f only: c (3, out, may be NULL), its
 * barycentrics (3, out, may be NULL); returns the distance. */
double closest_point_on_face(const struct closest_point_tree *T, int f, const double p[3],
                             double c[3], double bary[3]);

/* As closest_points(), but with a hint per query: a face id H[i] near the
 * answer (e.g. the previous answer of an iterative method; -1 = none).  A
 * good hint prunes the tree search; the answer is the same.  I may be H
 * (each hint is read before its answer is written). */
void closest_points_hinted(const struct closest_point_tree *T, const double *P, int n,
                           const int *H, double *C, int *I, double *B, double *D);

/* As closest_points_hinted() (H may be NULL), faster for many queries
 * (the samples of a surface): a walk of the tree with four children a
 * node, their boxes tested together; a query without a hint starts from
 * the answer of the query before it.  O (n, may be NULL): the order in
 * which to answer the queries, a permutation of 0..n-1 with near queries
 * one after another (closest_points_order(); the order of an earlier call
 * on points that have moved a little is as good); NULL: computed here.
 * The answers are those of closest_points().  I may be H. */
void closest_points_batch(const struct closest_point_tree *T, const double *P, int n,
                          const int *H, const int *O, double *C, int *I, double *B, double *D);

/* P: n by 3 points; O (n, out): them in Morton order (a permutation of
 * 0..n-1), for closest_points_batch(). */
void closest_points_order(const double *P, int n, int *O);

#ifdef __cplusplus
}
#endif
#endif
