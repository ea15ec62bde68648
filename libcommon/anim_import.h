/* anim_import.h -- morph-target (blend shape) animations from glTF 2.0
 * (.gltf, .glb) and FBX files, through assimp, as a MESH animation.
 *
 * One mesh of the file is chosen (by default the one with morph targets,
 * the largest if several; else the largest mesh) and its positions are
 * evaluated at every sample time t:
 *
 *     X(t) = B + sum_i w_i(t) (T_i - B)
 *
 * with B the base positions, T_i the morph targets, and w_i(t) the weights
 * of the morph animation, interpolated linearly between keys (STEP keys
 * hold).  Samples are the keyframe times of the animation by default, or
 * t = k / fps for k = 0, 1, ... up to the last key.  Every animation that
 * drives the mesh's morph weights is a clip (mesh-export writes one glTF
 * animation per clip): they follow one another in file order and the first
 * frame of every clip after the first is marked as a cut; `animation`
 * picks a single one.
 *
 * Vertices are kept exactly as the file indexes them: no joining of
 * identical vertices and no splitting (glTF meshes are indexed, so a vertex
 * that lies on a UV seam is already stored twice in the file and stays so;
 * mesh_weld() merges such copies).  Positions are in the mesh's own
 * coordinates (what a baked per-frame OBJ export of the mesh holds) unless
 * `world` is set, in which case the node's global rest-pose transform is
 * applied.  Node (rigid) animations are not applied: assimp 5.2 misreads
 * quantized rotation keys just like the weights below, and the rigid head
 * motion is not part of a deformation anyway.
 *
 * assimp 5.2 reads normalized-integer morph weights (glTF
 * KHR_mesh_quantization, e.g. the uint8 weights that glTF-Transform writes)
 * as raw bytes into floats, leaving tiny denormal garbage.  For glTF files
 * whose weight accessor is not FLOAT, the weights are therefore decoded
 * here from the file's accessor (byte / 255, short / 65535, ...).
 *
 * assimp 5.2 leaves an FBX blend-shape channel without an animation curve
 * out of its morph keys (weight 0 instead of its static DeformPercent);
 * for binary FBX the weights are therefore read from the file itself
 * (fbx_weights.h): every stack that animates the channels is a clip, and
 * every channel has its curve or its static value.
 *
 * With `merge`, every other mesh instance of the scene (a node that
 * references a triangle mesh, depth-first in node order) is appended after
 * the chosen mesh: the chosen mesh keeps vertex and face numbers 0..n-1,
 * the others follow, each placed by its rest-pose transform relative to
 * the chosen mesh's node (inverse(global(chosen)) * global(node); with
 * `world`, global(node)), so the merged head is where the viewer shows it
 * and the chosen mesh is where it is without merging.  Appended meshes
 * are static: their base positions repeated in every frame (their node
 * animations, e.g. eye rotations, are not applied, as above; a morph
 * animation of their own is not applied either: info->merged_morph counts
 * those so the caller can say so).
 *
 * Returns < 0 with cm_errmsg() naming the file on any failure.
 */
#ifndef CM_ANIM_IMPORT_H
#define CM_ANIM_IMPORT_H
#include "mesh.h"
#ifdef __cplusplus
extern "C" {
#endif

enum anim_format {
    ANIM_NONE = 0,
    ANIM_GLTF,     /* .gltf: JSON with external or embedded buffers */
    ANIM_GLB,      /* .glb: binary glTF */
    ANIM_FBX       /* .fbx */
};

/* Format from a file name's extension (case-insensitive), ANIM_NONE if none. */
int anim_format_from_name(const char *path);
/* Format from its name ("gltf", "glb", "fbx"), ANIM_NONE if unknown. */
int anim_format_parse(const char *name);

struct anim_import_opts {
    int format;              /* ANIM_GLTF ... or ANIM_NONE: from the extension */
    const char *mesh;        /* NULL: automatic; else a mesh index ("2"), a
                                mesh name, or a node name (first mesh below it) */
    const char *animation;   /* NULL: every animation driving the mesh's morph
                                weights, one clip each; else an index or a name */
    double fps;              /* <= 0: sample at the keyframes */
    int world;               /* apply the node's global rest-pose transform */
    int merge;               /* also append every other triangle mesh instance
                                of the scene (eyes, teeth, ...), see below */
};

struct anim_import_info {
    int mesh_index;          /* index of the chosen mesh in the file */
    char mesh_name[128];     /* its mesh (or node) name */
    int ntargets;            /* morph targets of the mesh */
    int morph_meshes;        /* meshes with morph targets in the file (counted
                                only when the mesh was chosen automatically) */
    int anim_index;          /* chosen (first) animation, -1 if none */
    char anim_name[128];
    int nclips;              /* animations read (0: static mesh) */
    int nkeys;               /* keys of the morph channels (0: static mesh) */
    double duration;         /* seconds from 0 to the last key, summed over clips */
    int decoded_weights;     /* 1 if weights were decoded from the glTF accessor */
    int fbx_weights;         /* 1 if weights were read from the FBX file itself */
    int merged;              /* merge: mesh instances appended */
    int merged_nv;           /* merge: vertices they added */
    int merged_morph;        /* merge: appended meshes that have morph targets
                                of their own (taken at their base shape) */
};

/* Read the animation of one mesh.
 *   path  file name
 *   o     options (NULL: all defaults)
 *   m     out: #V, #F, frames (1 if the mesh has no morph animation)
 *   info  out (may be NULL): what was chosen */
int anim_import(const char *path, const struct anim_import_opts *o,
                struct mesh *m, struct anim_import_info *info);

#ifdef __cplusplus
}
#endif
#endif
