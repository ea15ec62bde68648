/* fuzz_gltf.c -- glTF morph animations (anim_import.h): assimp's reader
 * and our own accessor decoding of the weights. */
#include "fuzz_common.h"
#include "anim_import.h"
#include "mesh.h"

FUZZ_TARGET(gltf)(const uint8_t *data, size_t size)
{
    char path[64];
    fuzz_file(data, size, ".gltf", path);
    struct anim_import_opts o;
    memset(&o, 0, sizeof o);
    o.format = ANIM_GLTF;
    struct anim_import_info inf;
    struct mesh m;
    memset(&m, 0, sizeof m);
    if (anim_import(path, &o, &m, &inf) == 0)
        mesh_free(&m);
    fuzz_file_done(path);
    return 0;
}
