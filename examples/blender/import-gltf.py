# import-gltf.py -- open a glTF (.glb/.gltf) in Blender and write what
# Blender plays, frame by frame, as a MESH stream.
#
#   blender -b --factory-startup --python-exit-code 1 -P import-gltf.py -- FILE.glb OUT.mesh [OBJECT]
#
# File > Import > glTF 2.0 with the default settings; the scene is played
# over the frame range of the imported shape-key action(s), every mesh
# object's evaluated positions are converted back to glTF axes (Blender's
# (x, y, z) is glTF's (x, z, -y)) in object coordinates, and the objects are
# written one after the other (one MESH vertex list, the faces of each
# object offset), in the order of their names; OBJECT: only the object of
# that name.  Prints the shape keys and frames found.
#
# Debian 12's Blender 3.4 glTF importer uses numpy.bool, which Debian's
# numpy 1.24 no longer has ("module 'numpy' has no attribute 'bool'" on
# every import of a mesh); the alias is put back here first.  In the
# Blender UI, type `import numpy; numpy.bool = bool` in the Python console
# once before File > Import > glTF 2.0.
import os
import sys

import bpy
import numpy

if not hasattr(numpy, "bool"):
    numpy.bool = bool

argv = sys.argv[sys.argv.index("--") + 1:]
src, dst = argv[0], argv[1]
bpy.ops.wm.read_factory_settings(use_empty=True)
bpy.ops.import_scene.gltf(filepath=os.path.abspath(src))
scene = bpy.context.scene
obs = sorted((o for o in scene.objects if o.type == "MESH"), key=lambda o: o.name)
if len(argv) > 2:
    obs = [o for o in obs if o.name == argv[2]]
    if not obs:
        sys.exit("import-gltf.py: no mesh object named '%s' in %s" % (argv[2], src))
lo, hi = None, None
for o in obs:
    keys = o.data.shape_keys
    act = keys.animation_data.action if keys and keys.animation_data else None
    if act:
        a, b = act.frame_range
        lo = a if lo is None else min(lo, a)
        hi = b if hi is None else max(hi, b)
lo, hi = (int(round(lo)), int(round(hi))) if lo is not None else (scene.frame_current, scene.frame_current)
tris, nv = [], 0
for o in obs:
    o.data.calc_loop_triangles()
    tris += [tuple(v + nv for v in t.vertices) for t in o.data.loop_triangles]
    nv += len(o.data.vertices)
dg = bpy.context.evaluated_depsgraph_get()
with open(dst, "w") as fh:
    fh.write("MESH 1\nvertices %d\nfaces %d\nframes %d\n" % (nv, len(tris), hi - lo + 1))
    for t in tris:
        fh.write("f %d %d %d\n" % t)
    for f in range(lo, hi + 1):
        scene.frame_set(f)
        fh.write("frame %d\n" % (f - lo))
        for o in obs:
            ev = o.evaluated_get(dg)
            me = ev.to_mesh()
            for v in me.vertices:
                fh.write("%.9g %.9g %.9g\n" % (v.co.x, v.co.z, -v.co.y))
            ev.to_mesh_clear()
print("import-gltf.py: %s: %d mesh objects, %s shape keys, frames %d..%d" %
      (src, len(obs), "+".join(str(len(o.data.shape_keys.key_blocks) - 1 if o.data.shape_keys else 0) for o in obs), lo, hi))
