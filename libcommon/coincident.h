/* coincident.h -- vertices at identical positions, frame by frame (UV-seam and normal-seam
 * duplicates of exported meshes).  Meshes exported from DCC tools and glTF
 * often split the surface along texture seams: the two sides share
 * positions but not vertex indices, so the topology falls apart into
 * components (facecap: 17 components, the face and the back of the head
 * among them).  Geometry processing that must cross those seams (geodesic
 * distances, smoothing) works on the joined faces instead, while the
 * tool keeps the input's vertices and faces for its output.
 * (weld.h's mesh_weld() removes the duplicates from a whole in-memory
 * animation; this file finds them frame by frame, for streaming tools.)
 *
 * rep: #V representative of each vertex: the smallest index of the
 * vertices at the bit-identical position (rep[v] == v for unique ones).
 */
#ifndef CM_COINCIDENT_H
#define CM_COINCIDENT_H
#ifdef __cplusplus
extern "C" {
#endif

/* V: #V by 3.  rep: #V (out).  Returns the number of vertices welded
 * away (#V minus the number of distinct positions), -1 on allocation
 * failure. */
int coincident_find(const double *V, int nv, int *rep);

/* Un-weld vertices that no longer sit exactly on their representative in
 * the frame V (#V by 3), so a weld holds in every frame it has been
 * refined with.  rep: #V in/out.  Returns the number of vertices un-welded. */
int coincident_refine(const double *V, int nv, int *rep);

/* Fw: #F by 3 (out, may alias F): F with every index replaced by its
 * representative. */
void coincident_faces(const int *F, int nf, const int *rep, int *Fw);

#ifdef __cplusplus
}
#endif
#endif
