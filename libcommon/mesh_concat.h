/* mesh_concat.h -- read several MESH streams that must share one
 * connectivity (same #V, #F and face list) into one animation: their frames
 * one after another.  Used by the tools that take key poses as separate
 * files (arap-interp SOURCE TARGET).
 */
#ifndef CM_MESH_CONCAT_H
#define CM_MESH_CONCAT_H
#include "mesh.h"
#ifdef __cplusplus
extern "C" {
#endif

/* paths: n file names (NULL or "-" = stdin, at most once).  m (out): the
 * frames of all files in order.  Different connectivity is an error naming
 * the file and what differs. */
int mesh_read_concat(const char *const *paths, int n, struct mesh *m);

#ifdef __cplusplus
}
#endif
#endif
