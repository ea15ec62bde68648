/* meshio.h -- static triangle meshes from and to the common file formats:
 * Wavefront OBJ, OFF, PLY and STL.
 *
 * Reading gives a struct mesh with one frame.  Polygons are triangulated as
 * fans (v0 vi vi+1), which keeps the orientation of every face; vertex order
 * and face order are the file's.  Normals, texture coordinates, colours and
 * materials are ignored (OBJ "f 1/2/3" uses the position index only, so
 * vertices are never split at UV seams by reading).
 *
 * OBJ and OFF are parsed here with the exact decimal parser (numparse.h):
 * OpenMesh 9's OBJ and OFF readers store positions as float (measured:
 * 0.12345678901234567 comes back as 0.12345679104328156, 1.6e-8 relative),
 * which breaks the OBJ -> MESH -> OBJ round trip to 1e-9.  PLY and STL are
 * read through OpenMesh from memory (both are float32 in practice; STL's
 * vertex soup is merged into shared vertices by OpenMesh's STL reader;
 * binary STL is recognized by its size, 84 + 50 n bytes).
 *
 * Writing: OBJ and OFF as text with shortest round-trip decimals; PLY and
 * STL through OpenMesh, binary unless MESHIO_ASCII is given (binary STL is
 * what slicers for 3D printing expect; it stores float32).
 *
 * All functions return < 0 on error with a message in cm_errmsg() naming
 * the file ("cannot read 'x.obj': line 7: face index 12 out of range").
 */
#ifndef CM_MESHIO_H
#define CM_MESHIO_H
#include <stdio.h>
#include "mesh.h"
#ifdef __cplusplus
extern "C" {
#endif

enum meshio_format {
    MESHIO_NONE = 0,
    MESHIO_OBJ,
    MESHIO_OFF,
    MESHIO_PLY,
    MESHIO_STL
};

/* write flags */
#define MESHIO_ASCII 1    /* text PLY / STL instead of binary */

/* Format from the extension of path (case-insensitive: .obj .off .ply .stl);
 * MESHIO_NONE if there is none of these. */
int meshio_format_from_name(const char *path);
/* Format from its name ("obj", "OFF", ...); MESHIO_NONE if unknown. */
int meshio_format_parse(const char *name);
/* "obj", "off", "ply", "stl" (or "none"). */
const char *meshio_format_name(int fmt);

/* Read a static mesh.
 *   path  file name, or "-" for stdin (then fmt must be given)
 *   fmt   MESHIO_OBJ ... or MESHIO_NONE to take it from the extension
 *   m     out: one frame; m->V #V by 3, m->F #F by 3 (triangles)
 * Fails on a missing or unreadable file, an unknown extension, a malformed
 * line, an index out of range, a non-finite coordinate, or a file without
 * any face. */
int meshio_read(const char *path, int fmt, struct mesh *m);

/* Write one frame.
 *   f      open output stream (binary formats write bytes)
 *   name   file name for messages
 *   fmt    MESHIO_OBJ ... MESHIO_STL
 *   flags  0 or MESHIO_ASCII
 *   nv     #V, nf #F
 *   F      #F by 3 vertex indices (0-based)
 *   X      #V by 3 positions */
int meshio_write(FILE *f, const char *name, int fmt, int flags,
                 int nv, int nf, const int *F, const double *X);

#ifdef __cplusplus
}
#endif
#endif
