# Bakes the fire of scenes/campfire.json with Blender's Mantaflow (Blender
# 3.4, headless):
#   blender --background --factory-startup --python tools/blender/bake_campfire.py -- OUT_DIR
# writes OUT_DIR/data/fluid_data_####.vdb (density, flame, temperature, shadow,
# velocity, ...; half float). Frame 30 is scenes/volumes/campfire.vdb. The
# domain is the one scenes/campfire.json names in volume.blender_domain:
# location (0, 0, 0.5) m, no rotation, dimensions 0.5 × 0.5 × 1 m.
#
# Blender 3.4 cannot run the bake operator without a window (the fluid
# modifier's data pointer is missing), so the cache is "Replay" and stepping
# the frames bakes it.
# Blender (Debian's `blender` package) is needed only to remake this asset, not to
# build or test eikon, so tools/debian-packages.txt does not list it.
import sys

import bpy

out = sys.argv[sys.argv.index("--") + 1]
bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.frame_start, scene.frame_end = 1, 30

bpy.ops.mesh.primitive_cube_add(size=1.0, location=(0.0, 0.0, 0.5))
domain = bpy.context.object
domain.name = "Domain"
domain.scale = (0.5, 0.5, 1.0)
fluid = domain.modifiers.new("Fluid", "FLUID")
fluid.fluid_type = "DOMAIN"
settings = fluid.domain_settings
settings.domain_type = "GAS"
settings.resolution_max = 48
settings.use_adaptive_domain = False
settings.cache_type = "REPLAY"
settings.cache_data_format = "OPENVDB"
settings.openvdb_data_depth = "16"
settings.cache_directory = out
settings.cache_frame_start, settings.cache_frame_end = 1, 30
settings.flame_vorticity = 0.5
settings.burning_rate = 0.75
settings.flame_smoke = 0.4

bpy.ops.mesh.primitive_uv_sphere_add(radius=0.07, location=(0.0, 0.0, 0.06))
source = bpy.context.object
source.name = "Fuel"
flow = source.modifiers.new("Fluid", "FLUID")
flow.fluid_type = "FLOW"
flow.flow_settings.flow_type = "BOTH"
flow.flow_settings.flow_behavior = "INFLOW"
flow.flow_settings.fuel_amount = 1.2

for frame in range(1, 31):
    scene.frame_set(frame)
print("baked", out)
