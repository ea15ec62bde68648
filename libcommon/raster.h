/* raster.h -- a small z-buffer triangle rasterizer for looking at meshes.
 *
 * Camera: orbit angles around the fitted points.  World up is one axis
 * (y by default, as in OBJ and glTF; z for Z-up data; or a negative axis).  With up = y the
 * view direction for azimuth a and elevation e (degrees) points from the
 * object towards the camera along
 *     d = (cos e sin a, sin e, cos e cos a),
 * so a = 0, e = 0 looks at the front (from +z), a = 90 from +x (right),
 * e = 90 from above (top).  Orthographic by default; optional perspective
 * with a vertical field of view.  The projection is fitted to the view-space
 * bounding box of every point given to camera_fit() (all frames that will
 * be drawn, so a film strip keeps one fixed camera).
 *
 * Shading: Lambert with a headlight (a light fixed to the camera, slightly
 * above and left of the view direction) plus ambient:
 *     c = base * (ambient + (1 - ambient) * max(0, n . l))
 * Two-sided: back faces use -n and are dimmed by back_dim so holes and
 * flipped faces stand out.  Smooth (interpolated per-vertex intensity from
 * area-weighted vertex normals) or flat (face normals).
 * Colours: one uniform colour, per-face colours, per-vertex colours
 * (interpolated, or "nearest corner" for categorical data) or per-vertex
 * values t in [0, 1] interpolated and looked up in a 256-entry table.
 * Optional wireframe overlay on the visible faces (edges found from the
 * barycentric distance to the triangle's sides, so hidden edges stay
 * hidden).  Supersampling ss x ss per pixel, box-filtered.
 */
#ifndef CM_RASTER_H
#define CM_RASTER_H
#include "image.h"
#ifdef __cplusplus
extern "C" {
#endif

struct camera {
    double azimuth, elevation;  /* degrees */
    int up;                     /* world up axis: 0, 1, 2 = +x, +y, +z; 3, 4, 5 = -x, -y, -z */
    int perspective;            /* 0: orthographic */
    double fov;                 /* perspective vertical field of view, degrees */
    double margin;              /* free border, fraction of the image side */
    /* set by camera_init / camera_fit */
    double R[9];                /* 3 by 3 world -> view rotation, row-major; rows:
                                   right, up, towards the viewer */
    double lo[3], hi[3];        /* view-space bounds of the fitted points */
    int fitted;                 /* number of points fitted so far */
};

/* Azimuth and elevation (degrees) of a named view: front, back, left,
 * right, top, bottom, iso.  Returns -1 for an unknown name. */
int camera_named_view(const char *name, double *azimuth, double *elevation);

/* Set up an orthographic camera with no fitted points yet.
 *   up  world up axis: 0, 1, 2 = +x, +y, +z; 3, 4, 5 = -x, -y, -z */
void camera_init(struct camera *c, double azimuth, double elevation, int up);

/* Extend the fit by points.
 *   V   #V by 3 positions */
void camera_fit(struct camera *c, const double *V, int nv);

/* Forget the fitted points (keep the angles). */
void camera_reset(struct camera *c);

/* Extend the fit by a view-space box, e.g. the lo/hi of another camera
 * with the same angles fitted to one frame (streaming tools keep these
 * per frame instead of the frames).
 *   lo, hi  3 each */
void camera_fit_box(struct camera *c, const double lo[3], const double hi[3]);

struct render_style {
    unsigned char color[3];          /* uniform base colour */
    unsigned char background[3];
    const unsigned char *face_rgb;   /* #F by 3 face colours, or NULL */
    const unsigned char *vertex_rgb; /* #V by 3 vertex colours, or NULL */
    int vertex_nearest;              /* vertex_rgb: 1 = colour of the nearest corner */
    const float *vertex_t;           /* #V values in [0, 1] looked up in lut, or NULL */
    const unsigned char *lut;        /* 256 by 3 table for vertex_t */
    int flat;                        /* 1: flat shading */
    double ambient;                  /* 0..1 */
    double back_dim;                 /* brightness factor of back faces, 0..1 */
    int wireframe;                   /* 1: draw edges of visible faces */
    unsigned char wire_rgb[3];
    double wire_width;               /* in output pixels */
    int ss;                          /* supersampling per axis, 1..8 */
};

/* Defaults: clay colour, white background, smooth shading, ambient 0.25,
 * back faces at 0.55, 2 x 2 supersampling, 1-pixel dark wireframe off. */
void render_style_default(struct render_style *s);

/* Render one frame into a new w by h image (out is allocated).
 *   V    #V by 3 positions
 *   F    #F by 3 vertex indices (validated by the caller)
 *   cam  a fitted camera (with no fitted points, e.g. an empty mesh, the
 *        image is just the background)
 * Returns -1 (cm_errmsg) on a bad size or out of memory. */
int raster_render(const double *V, const int *F, int nv, int nf, const struct camera *cam,
                  const struct render_style *s, int w, int h, struct image *out);

/* Where points land in a w by h render with camera cam (pixels, x right,
 * y down; the same projection as raster_render).
 *   P   n by 3 positions,  XY  n by 2 (out) */
void raster_project_points(const struct camera *cam, int w, int h, const double *P, int n,
                           double *XY);

#ifdef __cplusplus
}
#endif
#endif
