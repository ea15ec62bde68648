/* meshcolor.h -- colour a mesh from a column file: integer labels through
 * the categorical palette, scalars through the viridis map (colormap.h).
 *
 * A file with #F rows colours faces, one with #V rows colours vertices
 * (when #F == #V, faces win); any other row count is an error naming both
 * counts.  The result plugs into a render_style (raster.h).
 */
#ifndef CM_MESHCOLOR_H
#define CM_MESHCOLOR_H
#include "raster.h"
#ifdef __cplusplus
extern "C" {
#endif

struct mesh_colors {
    int per_face;              /* 1: one entry per face, 0: per vertex */
    int n;                     /* #F or #V */
    unsigned char *rgb;        /* n by 3 colours (labels, or scalars per face), or NULL */
    float *t;                  /* #V positions in [0, 1] for per-vertex scalars, or NULL */
    unsigned char lut[256 * 3];/* the colour table for t */
    double lo, hi;             /* scalar range used (scalars only) */
    int nlabels;               /* number of distinct labels (labels only) */
};

/* Read one integer label per row (negative = unlabelled, grey).
 *   path  column file (NULL or "-" = stdin)
 *   nv, nf  #V and #F of the mesh the labels belong to
 * Returns -1 (cm_errmsg) on a bad file or a row count that matches neither. */
int mesh_colors_labels(const char *path, int nv, int nf, struct mesh_colors *mc);

/* Read one scalar per row and map [lo, hi] to the colormap.
 *   range  NULL: the data's min and max; else range[0], range[1]
 * Returns -1 (cm_errmsg) as above. */
int mesh_colors_scalars(const char *path, int nv, int nf, const double *range,
                        struct mesh_colors *mc);

/* As mesh_colors_scalars(), from column col (0-based) of a file with any
 * number of columns, e.g. mesh-metrics --per-face.  The file has #F (else
 * #V) rows, or a block of them per frame: then block (a frame index) picks
 * one.  Errors (cm_errmsg): no such column, a row count that is no multiple
 * of #F or #V, no such block. */
int mesh_colors_scalars_column(const char *path, int col, int block, int nv, int nf,
                               const double *range, struct mesh_colors *mc);

/* Point the style's face_rgb / vertex_rgb / vertex_t / lut at mc. */
void mesh_colors_apply(const struct mesh_colors *mc, struct render_style *s);

/* Check mc fits a mesh of nv vertices and nf faces; -1 (cm_errmsg) if not.
 *   what  names the mesh in the message */
int mesh_colors_check(const struct mesh_colors *mc, int nv, int nf, const char *what);

void mesh_colors_free(struct mesh_colors *mc);

#ifdef __cplusplus
}
#endif
#endif
