# Run by the client tests: blender -b --factory-startup --python blender_dump.py -- OUT.json FILE...
# Imports each FILE (FBX, glTF/GLB or BVH) into an empty scene with Blender's own
# importer, default options, and dumps what a user sees: the armatures, the
# scene's frame rate, the bones Blender connected, and at each key of the
# armature's action (with its clip time) every bone's world head and the origin of
# every armature and empty object (FBX Nulls that Blender did not make bones);
# every action's name, and where there are several (takes), each one's keys.
# A BVH is imported at global_scale 0.01, centimetres (`FILE@SCALE` sets another).
import json
import os
import sys

import bpy
from mathutils import Matrix, Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import blender_compat  # noqa: E402,F401  (Blender 3.4 on Python 3.11 and numpy 1.24)



def geometric_translations(path):
    """Model name → GeometricTranslation of an FBX file, read with Blender's own parser."""
    from io_scene_fbx import parse_fbx
    root, _ = parse_fbx.parse(path)
    out = {}
    for objects in (e for e in root.elems if e.id == b"Objects"):
        for model in (e for e in objects.elems if e.id == b"Model"):
            name = model.props[1].split(b"\x00")[0].decode("utf-8", "replace")
            for props in (e for e in model.elems if e.id == b"Properties70"):
                for p in props.elems:
                    if p.props[0] == b"GeometricTranslation":
                        out[name] = tuple(p.props[4:7])
    return out


def node_origin(obj, geom):
    """World matrix of the FBX node an object was imported from.

    An FBX GeometricTranslation G moves only the node's own geometry. A Null has
    none, but Blender's importer bakes G into the empty (import_fbx.py,
    blen_read_object_transform_do: matrix = base @ G) and parents its children to
    that, so they move by G as well (Marine_Run's foot controls: 29 to 54 mm).
    This takes G out again, the node's own and its ancestors', from the transforms
    Blender imported: nothing is fitted."""
    g = Matrix.Translation(Vector(geom.get(obj.name, (0.0, 0.0, 0.0)))).inverted()
    if obj.parent is None or obj.parent_type != "OBJECT":  # a root, or hung from a bone
        return obj.matrix_world @ g
    return node_origin(obj.parent, geom) @ obj.matrix_parent_inverse @ obj.matrix_basis @ g


args = sys.argv[sys.argv.index("--") + 1:]
out_path, files = args[0], args[1:]
results = {}
for spec in files:
    path, scale = spec, None
    head, _, tail = spec.rpartition("@")
    if head and tail.replace(".", "", 1).isdigit():
        path, scale = head, float(tail)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    lower = path.lower()
    # Key time of Blender frame f, as each importer places keys:
    #  FBX:  f = t·fps + 1 (anim_offset 1; fps the scene's integer rate, which the
    #        importer sets from the file's TimeMode);
    #  glTF: f = t·fps with the scene's rate left at its 24 (glTF has no rate);
    #  BVH:  f = 1 + frame index, and the scene's rate set from the file's frame time.
    if lower.endswith(".fbx"):
        bpy.ops.import_scene.fbx(filepath=path)
        first_frame = 1.0
    elif lower.endswith(".bvh"):
        bpy.ops.import_anim.bvh(filepath=path, global_scale=0.01 if scale is None else scale, update_scene_fps=True)
        first_frame = 1.0
    else:
        bpy.ops.import_scene.gltf(filepath=path)
        first_frame = 0.0
    fps = scene.render.fps if lower.endswith(".fbx") else scene.render.fps / scene.render.fps_base
    armatures = [o for o in scene.objects if o.type == "ARMATURE"]
    r = {"armatures": len(armatures), "fps": scene.render.fps / scene.render.fps_base,
         "object_types": sorted(o.type for o in scene.objects)}
    if len(armatures) == 1:
        arm = armatures[0]
        r["bones"] = [b.name for b in arm.pose.bones]
        r["connected"] = [b.name for b in arm.data.bones if b.use_connect]
        action = arm.animation_data.action if arm.animation_data else None
        keys = set()
        if action:
            for fc in action.fcurves:
                keys.update(round(k.co[0], 6) for k in fc.keyframe_points)
        # Nodes the importer made objects rather than bones (an FBX Null above the
        # bones becomes the armature object, other Nulls empties): their origins.
        nodes = [o for o in scene.objects if o.type in ("ARMATURE", "EMPTY")]
        for o in nodes:  # hidden objects are not evaluated by frame_set
            o.hide_viewport = False
            o.hide_set(False)
        geom = geometric_translations(path) if lower.endswith(".fbx") else {}
        r["objects"] = [o.name for o in nodes]
        frames, origins = [], []
        for key in sorted(keys):
            whole = int(key // 1)
            scene.frame_set(whole, subframe=key - whole)
            frames.append([list(arm.matrix_world @ b.head) for b in arm.pose.bones])
            origins.append([list(node_origin(o, geom).translation) for o in nodes])
        r["key_frames"] = sorted(keys)
        r["times"] = [(k - first_frame) / fps for k in sorted(keys)]
        r["positions"] = frames
        r["object_positions"] = origins
        # Every action the import made (FBX: one per stack; glTF: one per animation)
        # and, where there are several, the bone heads at each key of each, played
        # on the armature in turn.
        r["actions"] = [a.name for a in bpy.data.actions]
        if len(bpy.data.actions) > 1 and arm.animation_data:
            r["action_keys"] = {}
            for a in bpy.data.actions:
                arm.animation_data.action = a
                keys = sorted({round(k.co[0], 6) for fc in a.fcurves for k in fc.keyframe_points})
                heads, action_origins = [], []
                for key in keys:
                    whole = int(key // 1)
                    scene.frame_set(whole, subframe=key - whole)
                    heads.append([list(arm.matrix_world @ b.head) for b in arm.pose.bones])
                    action_origins.append([list(node_origin(o, geom).translation) for o in nodes])
                r["action_keys"][a.name] = {"times": [(k - first_frame) / fps for k in keys], "positions": heads,
                                            "object_positions": action_origins}
    results[spec] = r
with open(out_path, "w") as f:
    json.dump(results, f)
