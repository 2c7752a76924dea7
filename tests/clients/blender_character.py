# Run by the character tests:
#   blender -b --factory-startup --python blender_character.py -- OUT.json STEP SOURCE OURS [SOURCE OURS]...
# Imports each FBX or GLB file into an empty scene with Blender's own importer for
# it, default options, and dumps the character as a user sees it: every mesh (vertex and face
# counts, vertex-group names, material count), every action, and per take the
# DEFORMED meshes (every vertex as the armature poses it playing that take's
# action, world space, metres): their bounding box and centroid at three times, a
# SOURCE take's first and last key and the time nearest its middle on a grid of
# STEP seconds from its first key (a key of both files compared); OURS (the file
# after it) at the same times of its take of the same name. A take is its action's
# name without the object's ("OBJECT|TAKE", Blender's importer; "|LAYER" after it
# where the take has several layers); its action is the one that moves bones.
import json
import sys

import bpy
import numpy
from mathutils import Vector

# Debian's Blender 3.4 glTF importer still calls numpy.bool, which Debian 12's numpy
# (1.24) removed: every glTF mesh import fails without the alias (bool, as it was).
if not hasattr(numpy, "bool"):
    numpy.bool = bool


def take_of(action_name):
    return action_name.split("|", 1)[-1]


def moves_bones(action):
    return any(c.data_path.startswith("pose.bones") for c in action.fcurves)


def deformed_box(scene, meshes, t, fps):
    # The FBX importer puts FBX time 0 at frame 1 (its anim_offset); a source and ours
    # go through the same importer, so the glTF one's offset cancels too.
    frame = 1 + t * fps
    scene.frame_set(int(frame // 1), subframe=frame % 1)
    graph = bpy.context.evaluated_depsgraph_get()
    points = []
    for o in meshes:
        evaluated = o.evaluated_get(graph)
        mesh = evaluated.to_mesh()
        points += [evaluated.matrix_world @ v.co for v in mesh.vertices]
        evaluated.to_mesh_clear()
    low = Vector(tuple(min(p[i] for p in points) for i in range(3)))
    high = Vector(tuple(max(p[i] for p in points) for i in range(3)))
    centroid = sum(points, Vector()) / len(points)
    return {"time": t, "min": list(low), "max": list(high), "centroid": list(centroid)}


args = sys.argv[sys.argv.index("--") + 1:]
out_path, step, files = args[0], float(args[1]), args[2:]
results = {}
times = {}  # take → the source's three times
for index, path in enumerate(files):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if path.lower().endswith((".glb", ".gltf")):
        bpy.ops.import_scene.gltf(filepath=path)
    else:
        bpy.ops.import_scene.fbx(filepath=path)
    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    meshes = sorted((o for o in scene.objects if o.type == "MESH"), key=lambda o: o.name)
    armature = next((o for o in scene.objects if o.type == "ARMATURE"), None)
    r = {
        "fps": fps,
        "takes": sorted({take_of(a.name) for a in bpy.data.actions}),
        "actions": len(bpy.data.actions),
        "meshes": [{"name": o.data.name, "vertices": len(o.data.vertices), "faces": len(o.data.polygons),
                    "groups": [g.name for g in o.vertex_groups], "materials": len(o.data.materials)} for o in meshes],
        "poses": {},
    }
    if index % 2 == 0:
        times = {}
    if armature and armature.animation_data and meshes:
        for action in sorted((a for a in bpy.data.actions if moves_bones(a)), key=lambda a: a.name):
            take = take_of(action.name)
            armature.animation_data.action = action
            if index % 2 == 0:  # a source: its times
                first, last = ((f - 1) / fps for f in action.frame_range)
                times[take] = [first, first + round((last - first) / 2 / step) * step, last]
            r["poses"][take] = [deformed_box(scene, meshes, t, fps) for t in times.get(take, [])]
    results[path] = r
with open(out_path, "w") as f:
    json.dump(results, f)
