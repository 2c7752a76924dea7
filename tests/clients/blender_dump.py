# Run by the client tests: blender -b --factory-startup --python blender_dump.py -- OUT.json FILE...
# Imports each FILE (FBX or glTF/GLB) into an empty scene with Blender's own
# importer and dumps what a user would see: the armatures, the scene's frame rate,
# and every bone's world head position at each key of the armature's action.
import json
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
out_path, files = args[0], args[1:]
results = {}
for path in files:
    bpy.ops.wm.read_factory_settings(use_empty=True)
    if path.lower().endswith(".fbx"):
        bpy.ops.import_scene.fbx(filepath=path)
    else:
        bpy.ops.import_scene.gltf(filepath=path)
    scene = bpy.context.scene
    armatures = [o for o in scene.objects if o.type == "ARMATURE"]
    r = {"armatures": len(armatures), "fps": scene.render.fps / scene.render.fps_base,
         "objects": sorted(o.type for o in scene.objects)}
    if len(armatures) == 1:
        arm = armatures[0]
        r["bones"] = [b.name for b in arm.pose.bones]
        action = arm.animation_data.action if arm.animation_data else None
        keys = set()
        if action:
            for fc in action.fcurves:
                keys.update(round(k.co[0], 6) for k in fc.keyframe_points)
        frames = []
        for key in sorted(keys):
            whole = int(key // 1)
            scene.frame_set(whole, subframe=key - whole)
            frames.append([list(arm.matrix_world @ b.head) for b in arm.pose.bones])
        r["key_frames"] = sorted(keys)
        r["positions"] = frames
    results[path] = r
with open(out_path, "w") as f:
    json.dump(results, f)
