# Renders eikon's OpenVDB export (export.vdb with up_axis "z") in Blender 3.4 with
# Cycles, headless, as docs/images/blender_export.png was made:
#   eikon run scenes/painted_smoke.json --out DIR --set 'export.vdb={"fields": ["scattering", "fluence"], "up_axis": "z"}'
#   blender --background --factory-startup --python tools/blender/render_eikon_export.py -- DIR/vdb/fields_00000.vdb OUT.png
# The smoke's density is 8 × eikon's σs so that its thin strokes show.
# Blender (Debian's `blender` package) is needed only to remake this asset, not to
# build or test eikon, so tools/debian-packages.txt does not list it.
import math
import sys

import bpy

vdb, out = sys.argv[sys.argv.index("--") + 1:][:2]
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
bpy.ops.object.volume_import(filepath=vdb, align="WORLD", location=(0, 0, 0))
volume = bpy.context.object
material = bpy.data.materials.new("eikon smoke")
material.use_nodes = True
nodes = material.node_tree.nodes
nodes.clear()
shader = nodes.new("ShaderNodeVolumePrincipled")
shader.inputs["Density"].default_value = 8.0  # × eikon's σs (1/m): thin smoke shows
shader.inputs["Density Attribute"].default_value = "scattering"
shader.inputs["Color"].default_value = (0.9, 0.9, 0.95, 1.0)
output = nodes.new("ShaderNodeOutputMaterial")
material.node_tree.links.new(shader.outputs["Volume"], output.inputs["Volume"])
volume.data.materials.append(material)

bpy.ops.mesh.primitive_plane_add(size=3.0, location=(0, 0, 0))
floor = bpy.data.materials.new("floor")
floor.use_nodes = True
floor.node_tree.nodes["Principled BSDF"].inputs["Base Color"].default_value = (0.12, 0.12, 0.12, 1.0)
bpy.context.object.data.materials.append(floor)
bpy.ops.object.light_add(type="SUN", rotation=(math.radians(35), 0, math.radians(30)))
bpy.context.object.data.energy = 4.0
bpy.ops.object.camera_add(location=(0.0, -2.6, 1.3), rotation=(math.radians(72), 0, 0))
scene.camera = bpy.context.object
scene.world = bpy.data.worlds.new("sky")
scene.world.color = (0.004, 0.005, 0.008)
scene.view_settings.view_transform = "Standard"
scene.render.engine = "CYCLES"
scene.cycles.samples = 48
scene.cycles.use_denoising = False
scene.cycles.device = "CPU"
scene.render.resolution_x, scene.render.resolution_y = 480, 360
scene.render.filepath = out
bpy.ops.render.render(write_still=True)
volume.data.grids.load()
print("grids:", [grid.name for grid in volume.data.grids])
