# A tiny Cycles stereo render (Blender's multi-view EXR: one part, a multiView attribute,
# channels like ViewLayer.Combined.left.R; depth, vectors, DiffDir, DiffCol and IndexOB) of the
# factory scene's cube sliding, for the multi-view tests. Usage: blender -b --factory-startup -noaudio -P stereo_scene.py -- OUT
import sys

import bpy

out = sys.argv[sys.argv.index("--") + 1]
scene = bpy.context.scene
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = 1
scene.cycles.use_denoising = False
scene.render.resolution_x = 40
scene.render.resolution_y = 24
scene.render.resolution_percentage = 100
scene.render.use_motion_blur = False  # Cycles writes no vectors with it on
scene.render.filter_size = 0.01       # about a one-pixel box: each pixel its own sample
scene.render.use_multiview = True
scene.render.views_format = "STEREO_3D"
scene.render.image_settings.file_format = "OPEN_EXR_MULTILAYER"
scene.render.image_settings.views_format = "MULTIVIEW"
scene.render.image_settings.color_depth = "16"
layer = scene.view_layers[0]
layer.use_pass_z = True
layer.use_pass_vector = True
# Passes resolved beside each view's colour (issue 21): a light with its factor, an ID.
layer.use_pass_diffuse_direct = True
layer.use_pass_diffuse_color = True
layer.use_pass_object_index = True
cube = bpy.data.objects["Cube"]
cube.location = (0, 0, 0)
cube.keyframe_insert("location", frame=1)
cube.location = (0.6, 0.2, 0)
cube.keyframe_insert("location", frame=5)
scene.frame_start = 1
scene.frame_end = 5
scene.render.filepath = out + "/render_"
bpy.ops.render.render(animation=True)
