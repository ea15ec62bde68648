/* gltf_write.h -- glTF 2.0 scenes (.glb, .gltf) of triangle meshes whose
 * animation is morph targets with keyed weights, written directly (JSON
 * text and little-endian buffers; no library needed for this subset).
 *
 * What a scene holds:
 *   meshes      one node per mesh (the scene's root nodes, in order); each
 *               mesh has one indexed triangle primitive with POSITION and
 *               NORMAL (area-weighted vertex normals), and any number of
 *               morph targets, each with POSITION and NORMAL deltas to the
 *               base; target names go to mesh.extras.targetNames (read by
 *               Blender as shape-key names, and by three.js)
 *   animations  each a set of channels; a channel drives the morph weights
 *               of one mesh's node with STEP keys whose weights are one-hot
 *               (key k shows exactly target hot[k]), stored as a sparse
 *               accessor (K keys cost O(K) bytes, not O(K x targets));
 *               clips are separate animations
 * A morph target is stored as the float32 difference to the float32 base,
 * so base + delta is the target to float precision.  Buffers stream to a
 * temporary file while targets are added: memory O(one frame + topology +
 * the keys), whatever the number of targets.
 *
 * Vertex normals: the area-weighted sum of the incident triangles' normals,
 * normalized; a vertex with no incident triangle of non-zero area (unused,
 * or only degenerate triangles) gets (0, 0, 1), since glTF requires unit
 * normals.  Morph-target normal deltas are computed from the target's own
 * normals the same way.
 *
 * Accessor min/max (required for POSITION and animation inputs) are the
 * exact float32 extremes, printed so that they parse back to the same
 * float32.  Every function returns < 0 with cm_errmsg() on failure.
 */
#ifndef CM_GLTF_WRITE_H
#define CM_GLTF_WRITE_H
#include <stdio.h>
#ifdef __cplusplus
extern "C" {
#endif

enum gltf_container {
    GLTF_NONE = 0,
    GLTF_JSON,      /* .gltf: JSON text, buffer in a .bin file or a data: URI */
    GLTF_BINARY     /* .glb: one binary file (JSON chunk + BIN chunk) */
};

/* Container from a file name's extension (.gltf, .glb; case-insensitive),
 * or from a format name ("gltf", "glb"); GLTF_NONE if neither. */
int gltf_container_from_name(const char *path);
int gltf_container_parse(const char *name);

struct gltf_writer;     /* opaque */

/* Start an empty scene.  generator: the asset.generator string. */
struct gltf_writer *gltf_writer_new(const char *generator);
void gltf_writer_free(struct gltf_writer *g);

/* Add a mesh (and its node).
 *   name  mesh and node name (copied)
 *   nv    #V vertices, nf #F triangles (both >= 1)
 *   F     #F by 3 vertex indices in [0, #V)
 *   X     #V by 3 base positions (finite)
 * Returns the mesh index (0, 1, ...). */
int gltf_add_mesh(struct gltf_writer *g, const char *name, int nv, int nf, const int *F,
                  const double *X);

/* Add a morph target to mesh mi.
 *   name  target name (copied; may be NULL)
 *   X     #V by 3 target positions (finite)
 * Returns the target index within the mesh. */
int gltf_add_target(struct gltf_writer *g, int mi, const char *name, const double *X);

/* Add an animation (call after all targets are added).  Returns its index. */
int gltf_add_animation(struct gltf_writer *g, const char *name);

/* Add to animation ai a channel driving the weights of mesh mi:
 *   nkeys  keys (>= 1)
 *   t      nkeys key times in seconds, strictly increasing
 *   hot    nkeys target indices in [0, #targets of mi): at key k weight 1
 *          on target hot[k], 0 on all others; STEP interpolation */
int gltf_add_onehot_channel(struct gltf_writer *g, int ai, int mi, int nkeys, const double *t,
                            const int *hot);

/* Write the scene.
 *   container  GLTF_BINARY: one .glb stream to out (bin_out unused);
 *              GLTF_JSON: JSON to out; the buffer goes to bin_out under the
 *              name bin_uri (a relative file name), or, if bin_out is NULL,
 *              into the JSON as a base64 data: URI
 *   name       output name for messages */
int gltf_write(struct gltf_writer *g, int container, FILE *out, const char *name, FILE *bin_out,
               const char *bin_uri);

#ifdef __cplusplus
}
#endif
#endif
