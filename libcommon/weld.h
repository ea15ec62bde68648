/* weld.h -- merge coincident vertices of a mesh animation.
 *
 * Exporters split a vertex wherever an attribute other than position
 * changes (UV seams, hard normals): the copies sit at the same place in
 * every frame but are not connected, so the surface falls apart into
 * patches for topology-based tools.  mesh_weld() merges two vertices when
 * they are within eps of each other in EVERY frame (eps = 0: bit-identical
 * positions), keeps the first of each group (surviving vertices keep their
 * order), re-indexes the faces, and drops faces that became degenerate
 * (two corners merged).
 */
#ifndef CM_WELD_H
#define CM_WELD_H
#include "mesh.h"
#ifdef __cplusplus
extern "C" {
#endif

/* m    in/out: mesh animation (#V, V and F are replaced; frames, cuts kept)
 * eps  distance below which two positions count as coincident (>= 0)
 * nmerged, ndropped  out (may be NULL): vertices removed, faces dropped
 * Returns 0, or -1 (out of memory) with cm_errmsg(). */
int mesh_weld(struct mesh *m, double eps, int *nmerged, int *ndropped);

#ifdef __cplusplus
}
#endif
#endif
