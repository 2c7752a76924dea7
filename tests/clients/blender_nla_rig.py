# Run by the client tests: blender -b --factory-startup --python blender_nla_rig.py -- OUT_STEM [skinned]
# Builds a three-bone armature with two actions of different lengths and start frames
# ("Walk" frames 1-21, "Wave" frames 10-45, each on an NLA track, 30 fps) and exports
# it as Blender users do: OUT_STEM.fbx with every action baked as a take
# (bake_anim_use_all_actions) and OUT_STEM.glb with an animation per NLA track.
# `skinned`: a character, the armature deforming a mesh of its own (a tube around the
# bones, a vertex group per bone, weights blended along it, one material whose base
# colour is a PNG texture, embedded in the FBX).
import math, sys
import bpy
args = sys.argv[sys.argv.index("--") + 1:]
out, skinned = args[0], "skinned" in args[1:]
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.fps = 30
arm = bpy.data.armatures.new("Rig")
obj = bpy.data.objects.new("Rig", arm)
scene.collection.objects.link(obj)
bpy.context.view_layer.objects.active = obj
bpy.ops.object.mode_set(mode="EDIT")
parent = None
for i, name in enumerate(["Hips", "Spine", "Arm"]):
    b = arm.edit_bones.new(name)
    b.head = (0.0, 0.0, 0.5 * i)
    b.tail = (0.0, 0.0, 0.5 * (i + 1))
    if parent:
        b.parent = parent
        b.use_connect = True
    parent = b
bpy.ops.object.mode_set(mode="POSE")
obj.animation_data_create()

def make_action(name, first, last, amp):
    act = bpy.data.actions.new(name)
    obj.animation_data.action = act
    for f in range(first, last + 1, 5):
        u = (f - first) / (last - first)
        for k, pb in enumerate(obj.pose.bones):
            pb.rotation_mode = "XYZ"
            pb.rotation_euler = (amp * math.sin(2 * math.pi * u + k), 0.3 * k * u, amp * u)
            pb.keyframe_insert("rotation_euler", frame=f)
        obj.pose.bones["Hips"].location = (u, 0.0, 0.0)
        obj.pose.bones["Hips"].keyframe_insert("location", frame=f)
    act.use_fake_user = True
    track = obj.animation_data.nla_tracks.new()
    track.name = name
    track.strips.new(name, first, act)
    obj.animation_data.action = None
    return act



def textured_material(png):
    """A material whose base colour is a 16×16 checker PNG saved at `png`."""
    image = bpy.data.images.new("Checker", 16, 16)
    image.pixels = [c for i in range(256) for c in ((1.0, 0.8, 0.2, 1.0) if (i // 16 + i) % 2 else (0.1, 0.3, 0.9, 1.0))]
    image.filepath_raw = png
    image.file_format = "PNG"
    image.save()
    material = bpy.data.materials.new("Skin")
    material.use_nodes = True
    texture = material.node_tree.nodes.new("ShaderNodeTexImage")
    texture.image = image
    bsdf = material.node_tree.nodes["Principled BSDF"]
    material.node_tree.links.new(texture.outputs["Color"], bsdf.inputs["Base Color"])
    return material


def add_skinned_tube(bone_names, rings=13, sides=8, radius=0.15, length=1.5):
    """A tube along the bones (Z), each vertex weighted to the bones nearest it."""
    verts = [(radius * math.cos(2 * math.pi * s / sides), radius * math.sin(2 * math.pi * s / sides),
              length * r / (rings - 1)) for r in range(rings) for s in range(sides)]
    faces = [(r * sides + s, r * sides + (s + 1) % sides, (r + 1) * sides + (s + 1) % sides, (r + 1) * sides + s)
             for r in range(rings - 1) for s in range(sides)]
    mesh = bpy.data.meshes.new("Body")
    mesh.from_pydata(verts, [], faces)
    uv = mesh.uv_layers.new(name="UVMap")
    for loop in mesh.loops:
        x, y, z = verts[loop.vertex_index]
        uv.data[loop.index].uv = (0.5 + math.atan2(y, x) / (2 * math.pi), z / length)
    mesh.materials.append(textured_material(out + "_skin.png"))
    body = bpy.data.objects.new("Body", mesh)
    scene.collection.objects.link(body)
    body.parent = obj
    body.modifiers.new("Armature", "ARMATURE").object = obj
    span = length / len(bone_names)
    groups = [body.vertex_groups.new(name=n) for n in bone_names]
    for i, (_, _, z) in enumerate(verts):
        weights = [max(0.0, 1.0 - abs(z - span * (b + 0.5)) / span) for b in range(len(bone_names))]
        total = sum(weights)
        for group, w in zip(groups, weights):
            if w > 0.0:
                group.add([i], w / total, "REPLACE")


if skinned:
    add_skinned_tube(["Hips", "Spine", "Arm"])
make_action("Walk", 1, 21, 0.6)
make_action("Wave", 10, 45, 1.2)
bpy.ops.object.mode_set(mode="OBJECT")
bpy.ops.export_scene.fbx(filepath=out + ".fbx", bake_anim=True, bake_anim_use_all_actions=True,
                         bake_anim_use_nla_strips=False, add_leaf_bones=False, path_mode="COPY", embed_textures=True)
bpy.ops.export_scene.gltf(filepath=out + ".glb", export_format="GLB", export_nla_strips=True)
