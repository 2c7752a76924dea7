# Run by the character tests:
#   blender -b --factory-startup --python blender_character.py -- OUT.json STEP SOURCE OURS [SOURCE OURS]...
# Imports each FBX or GLB file into an empty scene with Blender's own importer for
# it, default options, and dumps the character as a user sees it: every mesh (vertex
# and face counts, vertex-group names, material count), every action, the images
# with pixels, and per take the DEFORMED meshes (every vertex as the armature poses
# it playing that take's action, world space, metres): their bounding box and
# centroid at three times, a SOURCE take's first and last key and the time nearest
# its middle on a grid of STEP seconds from its first key (a key of both files
# compared); OURS (the file after it) at the same times of its take of the same
# name. A take is its action's name without the object's (FBX "OBJECT|TAKE", with
# "|LAYER" after it where Blender names the layer; glTF "TAKE_OBJECT"; an FBX source's
# "TAKE|LAYER" is the take TAKE of a GLB of ours); its action is the one that moves bones.
import json
import os
import sys

import bpy
from mathutils import Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_compat  # noqa: E402,F401  (Blender 3.4 on Python 3.11 and numpy 1.24)


def take_of(action_name, gltf, objects):
    # FBX: "OBJECT|TAKE" or "OBJECT|TAKE|LAYER"; glTF: "TAKE_OBJECT".
    if gltf:
        for o in objects:
            if action_name.endswith("_" + o.name):
                return action_name[:-len(o.name) - 1]
        return action_name
    return action_name.split("|", 1)[-1]


def rename_source_takes(source, ours_takes, times):
    # An FBX source's take "TAKE|LAYER" (or "TAKE" where Blender names no layer) is
    # the take TAKE of a GLB of ours: renamed so, in the source's results and times.
    for take in ours_takes:
        found = next((t for t in times if t == take or t.startswith(take + "|")), None)
        if found is None or found == take:
            continue
        times[take] = times.pop(found)
        source["poses"][take] = source["poses"].pop(found)
        source["takes"] = sorted((take if t == found else t) for t in source["takes"])


def moves_bones(action):
    return any(c.data_path.startswith("pose.bones") for c in action.fcurves)


def deformed_box(scene, meshes, t, fps, gltf, cross):
    # The FBX importer puts FBX time 0 at frame 1 (its anim_offset); the glTF one
    # puts glTF time 0 at frame 0.
    frame = t * fps + (0 if gltf else 1)
    scene.frame_set(int(frame // 1), subframe=frame % 1)
    graph = bpy.context.evaluated_depsgraph_get()
    points = []
    for o in meshes:
        evaluated = o.evaluated_get(graph)
        mesh = evaluated.to_mesh()
        points += [evaluated.matrix_world @ v.co for v in mesh.vertices]
        evaluated.to_mesh_clear()
    if cross:  # one point per position: a glTF mesh has a vertex per seam side (positions_and_triangles)
        points = list({tuple(round(c * 1e6) for c in p): p for p in points}.values())
    low = Vector(tuple(min(p[i] for p in points) for i in range(3)))
    high = Vector(tuple(max(p[i] for p in points) for i in range(3)))
    centroid = sum(points, Vector()) / len(points)
    return {"time": t, "min": list(low), "max": list(high), "centroid": list(centroid)}


args = sys.argv[sys.argv.index("--") + 1:]
out_path, step, files = args[0], float(args[1]), args[2:]
results = {}
times = {}  # take → the source's three times
def is_gltf(path):
    return path.lower().endswith((".glb", ".gltf"))


def mesh_facts(o, cross):
    # Across formats vertices split differently (a glTF vertex per UV seam, an FBX
    # importer's per control point) and polygons are triangulated or not: the distinct
    # positions (to 1 µm, world space) and the triangles they make compare instead, and
    # the object's name and its vertex groups in name order (an importer's own order).
    if not cross:
        return {"name": o.data.name, "vertices": len(o.data.vertices), "faces": len(o.data.polygons),
                "groups": [g.name for g in o.vertex_groups], "materials": len(o.data.materials)}
    seen = {tuple(round(c * 1e6) for c in o.matrix_world @ v.co) for v in o.data.vertices}
    return {"name": o.name, "vertices": len(seen), "faces": sum(len(p.vertices) - 2 for p in o.data.polygons),
            "groups": sorted(g.name for g in o.vertex_groups), "materials": len(o.data.materials)}


for index, path in enumerate(files):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    pair = files[index - index % 2: index - index % 2 + 2]
    cross = len(pair) == 2 and is_gltf(pair[0]) != is_gltf(pair[1])
    if is_gltf(path):
        bpy.ops.import_scene.gltf(filepath=path)
    else:
        bpy.ops.import_scene.fbx(filepath=path)
    scene = bpy.context.scene
    fps = scene.render.fps / scene.render.fps_base
    meshes = sorted((o for o in scene.objects if o.type == "MESH"), key=lambda o: o.name)
    armature = next((o for o in scene.objects if o.type == "ARMATURE"), None)
    r = {
        "fps": fps,
        "takes": sorted({take_of(a.name, is_gltf(path), scene.objects) for a in bpy.data.actions}),
        "actions": len(bpy.data.actions),
        "images": sum(1 for i in bpy.data.images if i.size[0] > 0),  # with pixels: found, or embedded
        "meshes": [mesh_facts(o, cross) for o in meshes],
        "poses": {},
    }
    if index % 2 == 0:
        times = {}
    elif cross:
        rename_source_takes(results[pair[0]], r["takes"], times)
    if armature and armature.animation_data and meshes:
        for action in sorted((a for a in bpy.data.actions if moves_bones(a)), key=lambda a: a.name):
            take = take_of(action.name, is_gltf(path), scene.objects)
            armature.animation_data.action = action
            if index % 2 == 0:  # a source: its times
                first, last = ((f - (0 if is_gltf(path) else 1)) / fps for f in action.frame_range)
                times[take] = [first, first + round((last - first) / 2 / step) * step, last]
            r["poses"][take] = [deformed_box(scene, meshes, t, fps, is_gltf(path), cross) for t in times.get(take, [])]
    results[path] = r
with open(out_path, "w") as f:
    json.dump(results, f)
