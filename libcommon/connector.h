/* connector.h -- the geometry of connectors between printed replacement
 * pieces (magnet pockets, keyed plugs and their sockets) and of engraved
 * dot-matrix ids, as closed triangle solids for the Booleans of solid.h.
 *
 * A connector sits on the seam strip of a shell solid (shell.h): the strip
 * between a seam vertex x and its offset x + sgn T n.  Its frame:
 *   o     3  centre of the strip at the connector (model units)
 *   u     3  unit tangent of the seam
 *   w     3  unit across the strip (the seam normal n, toward the outside)
 *   a     3  unit axis into the part the seam edge belongs to (a = +-u x w)
 * Cross-sections are convex polygons in (s, r) = coordinates along u and w;
 * a prism spans axis coordinates z0 < z1 along a.
 */
#ifndef CM_CONNECTOR_H
#define CM_CONNECTOR_H
#ifdef __cplusplus
extern "C" {
#endif

struct connector_frame {
    double o[3], u[3], w[3], a[3];
};

/* A growing triangle soup of closed components (several disjoint solids in
 * one mesh).  V #V by 3, F #F by 3, both malloc'd. */
struct trimesh {
    int nv, nf, capv, capf;
    double *V;
    int *F;
};
void trimesh_free(struct trimesh *m);

/* Append the prism over the convex polygon P (n by 2 (s, r), counter-
 * clockwise) between z0 < z1 along the frame's axis, outward oriented. */
void connector_prism(struct trimesh *m, const struct connector_frame *fr, const double *P, int n,
                     double z0, double z1);

/* Polygons (out: n by 2, counter-clockwise in (s, r)):
 *   circle: regular n-gon circumscribing the circle of radius R (the
 *           magnet fits inside; n >= 8)
 *   keyed:  trapezoid W across the strip (r), L along the seam at r = +W/2
 *           (the outer side) and L/2 at r = -W/2, so a piece turned half a
 *           turn about the axis does not fit */
void connector_circle(double R, int n, double *P);
void connector_keyed(double W, double L, double *P);

/* Offset the convex counter-clockwise polygon P (n by 2) outward by d
 * (every edge moved by d along its outer normal; d may be negative). */
void convex_offset(const double *P, int n, double d, double *Q);

/* Append the dot-matrix text s: one box per lit pixel of the 5x7 font
 * (image.h), pixels `pitch` apart, boxes 0.8 pitch wide, so they never
 * touch.  Lit pixel centres are laid out in the plane through c spanned by
 * x (3, unit, reading direction) and y (3, unit, up); `place` (may be NULL)
 * moves each centre onto the surface it engraves (e.g. the closest point).
 * Each box spans [-depth, +above] along the unit normal n (3, pointing out
 * of the material toward the reader).  Returns the number of boxes. */
int connector_text(struct trimesh *m, const char *s, const double c[3], const double x[3],
                   const double y[3], const double n[3], double pitch, double depth, double above,
                   void (*place)(void *ctx, const double p[3], double q[3]), void *ctx);

#ifdef __cplusplus
}
#endif
#endif
