# Run by the GLB character tests:
#   blender -b --factory-startup --python blender_fbx_to_glb.py -- OUT.json FBX GLB [FBX GLB]...
# Makes the glTF characters the tests start from as Blender users make them: each
# FBX imported with Blender's own importer, default options, then exported with its
# own glTF exporter as GLB (meshes, skins, materials, every action), over the whole
# of each action rather than the scene's playback range. OUT.json lists the files written.
import json
import sys

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
out_path, files = args[0], args[1:]
written = []
for fbx, glb in zip(files[0::2], files[1::2]):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.import_scene.fbx(filepath=fbx)
    # A texture whose image the data set does not ship is dropped, as a user would:
    # 3.4's exporter fails on an empty image (its specular factor of no pixels).
    for material in bpy.data.materials:
        if material.node_tree:
            for node in list(material.node_tree.nodes):
                if node.type == "TEX_IMAGE" and (node.image is None or node.image.size[0] == 0):
                    material.node_tree.nodes.remove(node)
    bpy.ops.export_scene.gltf(filepath=glb, export_format="GLB", export_frame_range=False)
    written.append(glb)
with open(out_path, "w") as f:
    json.dump(written, f)
