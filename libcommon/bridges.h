/* bridges.h -- proximity bridges between the connected components of a
 * triangle mesh: pairs of triangles of different components that touch or
 * nearly touch (an eyeball and its eyelids, teeth and lips, a tongue and
 * its mouth socket).  A production head is many components; a bridge lets
 * distances and labels pass from the skin to the parts that sit in it.
 *
 * Bridges of face f: from f's centroid, the closest point on every other
 * component whose bounding box, grown by r, holds the centroid (a CGAL AABB
 * tree per component); a bridge when that point is within r.  A component
 * that gets no bridge that way (nothing within r) gets one bridge anyway:
 * the closest pair from its centroids to any other component, at whatever
 * distance, so every component is linked to its nearest neighbour.
 */
#ifndef CM_BRIDGES_H
#define CM_BRIDGES_H
#ifdef __cplusplus
extern "C" {
#endif

struct bridge {
    int f, g;        /* faces in two different components */
    double d;        /* distance from f's centroid to the closest point of g */
};

/* Bridges between the components of a mesh.
 *   V     #V by 3 vertex positions
 *   F     #F by 3 vertex indices
 *   comp  #F component of each face (0..nc-1, e.g. connected_components())
 *   r     bridging distance (>= 0, same units as V)
 *   out   (out) malloc'd array of bridges (free()), f's component first
 *         in the order of faces; NULL when there are none
 * Returns the number of bridges, or -1 (cm_errmsg set) on bad input or
 * out of memory.  Deterministic: the same input gives the same list. */
int component_bridges(const double *V, int nv, const int *F, int nf, const int *comp, int nc,
                      double r, struct bridge **out);

#ifdef __cplusplus
}
#endif
#endif
