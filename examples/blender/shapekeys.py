# shapekeys.py -- a shape-key animation made in Blender, exported as glTF and
# FBX, plus Blender's own evaluated frames as a MESH stream for comparison.
#
#   blender -b --factory-startup -P shapekeys.py -- OUTDIR [FRAMES [cube]]
#
# Scene: Suzanne (or with "cube": a cube, the small test files of
# tests/data) with one level of subdivision (applied), two shape keys
# ("smile": the right half lifted, "squash": flattened along z), their
# values keyed on every frame 1..FRAMES (default 48) at 24 fps.  Writes
#   OUTDIR/suzanne.glb            File > Export > glTF 2.0 (.glb), with
#                                 Shape Keys and Animation on (the defaults)
#   OUTDIR/suzanne.fbx            File > Export > FBX, Shape Keys and
#                                 Baked Animation on (the defaults)
#   OUTDIR/suzanne-actions.fbx    the same with All Actions and NLA Strips
#                                 off (bake_anim_use_all_actions=False,
#                                 bake_anim_use_nla_strips=False): only then
#                                 does Blender 3.4 write the shape-key curves
#   OUTDIR/suzanne-blender.mesh   the evaluated positions of every frame in
#                                 Blender's vertex order and axes (object
#                                 coordinates, +Z up), triangles from
#                                 Blender's own triangulation (loop_triangles)
#   OUTDIR/suzanne.blend          the scene
import math
import os
import sys

import bpy

argv = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
if not argv:
    sys.exit("usage: blender -b -P shapekeys.py -- OUTDIR [FRAMES]")
out = os.path.abspath(argv[0])
nframes = int(argv[1]) if len(argv) > 1 else 48
cube = len(argv) > 2 and argv[2] == "cube"
name = "cube" if cube else "suzanne"
os.makedirs(out, exist_ok=True)

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.fps = 24
scene.frame_start = 1
scene.frame_end = nframes

if cube:
    bpy.ops.mesh.primitive_cube_add(size=2)
else:
    bpy.ops.mesh.primitive_monkey_add(size=2)
ob = bpy.context.active_object
mod = ob.modifiers.new("subsurf", "SUBSURF")
mod.levels = 1
mod.render_levels = 1
bpy.ops.object.modifier_apply(modifier=mod.name)

ob.shape_key_add(name="Basis")
smile = ob.shape_key_add(name="smile", from_mix=False)
for v in smile.data:
    if v.co.x > 0:
        v.co.z += 0.3 * v.co.x
squash = ob.shape_key_add(name="squash", from_mix=False)
for v in squash.data:
    v.co.z *= 0.6
    v.co.x *= 1.2

for f in range(1, nframes + 1):
    t = (f - 1) / max(nframes - 1, 1)
    smile.value = 0.5 - 0.5 * math.cos(2 * math.pi * t)
    squash.value = 0.5 + 0.5 * math.sin(3 * math.pi * t)
    smile.keyframe_insert("value", frame=f)
    squash.keyframe_insert("value", frame=f)

bpy.ops.export_scene.gltf(filepath=os.path.join(out, name + ".glb"), export_format="GLB",
                          export_animations=True, export_morph=True, export_apply=False)
bpy.ops.export_scene.fbx(filepath=os.path.join(out, name + ".fbx"), use_selection=False,
                         bake_anim=True, object_types={"MESH"})
bpy.ops.export_scene.fbx(filepath=os.path.join(out, name + "-actions.fbx"), use_selection=False,
                         bake_anim=True, bake_anim_use_all_actions=False, bake_anim_use_nla_strips=False,
                         object_types={"MESH"})

# Blender's own frames, as a MESH stream (object coordinates)
me = ob.data
me.calc_loop_triangles()
tris = [tuple(t.vertices) for t in me.loop_triangles]
with open(os.path.join(out, name + "-blender.mesh"), "w") as fh:
    fh.write("MESH 1\nvertices %d\nfaces %d\nframes %d\n" % (len(me.vertices), len(tris), nframes))
    for t in tris:
        fh.write("f %d %d %d\n" % t)
    dg = bpy.context.evaluated_depsgraph_get()
    for f in range(1, nframes + 1):
        scene.frame_set(f)
        ev = ob.evaluated_get(dg).to_mesh()
        fh.write("frame %d\n" % (f - 1))
        for v in ev.vertices:
            fh.write("%.9g %.9g %.9g\n" % (v.co.x, v.co.y, v.co.z))
        ob.evaluated_get(dg).to_mesh_clear()
bpy.ops.wm.save_as_mainfile(filepath=os.path.join(out, name + ".blend"))
print("shapekeys.py: wrote %s (%d vertices, %d frames)" % (out, len(me.vertices), nframes))
