# Run by the client tests: blender -b --factory-startup --python blender_nla_rig.py -- OUT_STEM
# Builds a three-bone armature with two actions of different lengths and start frames
# ("Walk" frames 1-21, "Wave" frames 10-45, each on an NLA track, 30 fps) and exports
# it as Blender users do: OUT_STEM.fbx with every action baked as a take
# (bake_anim_use_all_actions) and OUT_STEM.glb with an animation per NLA track.
import math, sys
import bpy
out = sys.argv[sys.argv.index("--") + 1]
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

make_action("Walk", 1, 21, 0.6)
make_action("Wave", 10, 45, 1.2)
bpy.ops.object.mode_set(mode="OBJECT")
bpy.ops.export_scene.fbx(filepath=out + ".fbx", bake_anim=True, bake_anim_use_all_actions=True,
                         bake_anim_use_nla_strips=False, add_leaf_bones=False)
bpy.ops.export_scene.gltf(filepath=out + ".glb", export_format="GLB", export_nla_strips=True)
