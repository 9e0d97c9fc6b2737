"""The Blender add-on test's scene and checks, in Blender's own Python (tests/blender/addon_test):

    blender -b --factory-startup -P addon_scene.py -- --build DIR
        the conventions scene (surfaces emit their world position, the camera moves and turns)
        with every setting taa needs set otherwise (motion blur on, a Gaussian filter,
        denoising on, single-layer EXR, no Depth or Vector pass, stamp burn-in on, a note of
        the user's), a lens shift of the user's, frames 1-5 at 64x36, 1 sample. Writes
        DIR/scene.blend, DIR/reference.json (each frame's camera as a taatool sidecar, computed
        here without the add-on, with the Halton jitter computed here too) and DIR/before.json
        (the settings the add-on may touch).
    blender -b DIR/scene.blend ... -P addon_scene.py -- --snapshot FILE
        writes those settings as they are now (after the add-on's render) to FILE.
    blender -b DIR/scene.blend ... -P addon_scene.py -- --png-still DIR
        the scene set to write 8-bit PNGs, frame 3 rendered as a still through the add-on's
        operator into DIR/still/frame.exr; the settings before and after into DIR/still/.
"""
import json
import os
import sys

import bpy

FIRST, LAST = 1, 5
WIDTH, HEIGHT = 64, 36
USER_SHIFT = (0.03, -0.02)
USER_NOTE = 'the user\'s own note'


def snapshot(scene):
    """Every setting the add-on changes during a render, and the camera's lens shift."""
    layer = scene.view_layers[0]
    settings = scene.render.image_settings
    camera = scene.camera.data
    return {
        'use_motion_blur': scene.render.use_motion_blur,
        'pixel_filter_type': scene.cycles.pixel_filter_type,
        'filter_width': scene.cycles.filter_width,
        'use_denoising': scene.cycles.use_denoising,
        'file_format': settings.file_format,
        'color_depth': settings.color_depth,
        'use_stamp': scene.render.use_stamp,
        'use_stamp_note': scene.render.use_stamp_note,
        'stamp_note_text': scene.render.stamp_note_text,
        'use_pass_z': layer.use_pass_z,
        'use_pass_vector': layer.use_pass_vector,
        'shift': [camera.shift_x, camera.shift_y],
    }


def write_json(path, value):
    with open(path, 'w') as out:
        json.dump(value, out, indent=1, sort_keys=True)


def halton(index, base):
    result, weight = 0.0, 1.0 / base
    while index > 0:
        result += (index % base) * weight
        index //= base
        weight /= base
    return result


def reference_cameras(scene):
    """Each frame's camera as the scene states it, unjittered: OpenGL view and projection."""
    def column_major(m):
        return [m[row][col] for col in range(4) for row in range(4)]
    entries = {}
    depsgraph = bpy.context.evaluated_depsgraph_get()
    for frame in range(FIRST, LAST + 1):
        scene.frame_set(frame)
        camera = scene.camera.evaluated_get(depsgraph)
        entries[str(frame)] = {
            'view': column_major(camera.matrix_world.inverted()),
            'projection': column_major(camera.calc_matrix_camera(depsgraph, x=WIDTH, y=HEIGHT)),
            'jitter': [halton(frame, 2) - 0.5, halton(frame, 3) - 0.5],
        }
    return {'frames': entries}


def build(folder):
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)),
                                    '..', '..', 'samples', 'blender'))
    from taa_scenes import conventions
    bpy.ops.wm.read_factory_settings(use_empty=True)
    conventions.build(range(FIRST - 1, LAST + 2))
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = FIRST, LAST
    scene.render.engine = 'CYCLES'
    scene.cycles.device = 'CPU'
    scene.cycles.samples = 1
    scene.cycles.use_adaptive_sampling = False
    scene.cycles.max_bounces = 0
    scene.render.resolution_x, scene.render.resolution_y = WIDTH, HEIGHT
    scene.render.resolution_percentage = 100
    scene.view_settings.view_transform = 'Standard'
    scene.camera.data.shift_x, scene.camera.data.shift_y = USER_SHIFT
    # All that taa needs, set otherwise: the add-on must fix each and put it back.
    scene.render.use_motion_blur = True
    scene.cycles.pixel_filter_type = 'GAUSSIAN'
    scene.cycles.filter_width = 1.5
    scene.cycles.use_denoising = True  # Debian's Blender has no denoiser: the render would fail
    scene.render.image_settings.file_format = 'OPEN_EXR'
    scene.render.image_settings.color_depth = '32'  # float colour: positions to 1e-7
    scene.render.use_stamp = True
    scene.render.use_stamp_note = False
    scene.render.stamp_note_text = USER_NOTE
    layer = scene.view_layers[0]
    layer.use_pass_z = layer.use_pass_vector = False
    scene.render.filepath = os.path.join(folder, 'frames', 'input_')
    write_json(os.path.join(folder, 'before.json'), snapshot(scene))
    write_json(os.path.join(folder, 'reference.json'), reference_cameras(scene))
    scene.frame_set(FIRST)
    bpy.ops.wm.save_as_mainfile(filepath=os.path.join(folder, 'scene.blend'))


def png_still(folder):
    scene = bpy.context.scene
    scene.render.image_settings.file_format = 'PNG'
    scene.render.image_settings.color_depth = '8'
    scene.render.filepath = os.path.join(folder, 'still', 'frame')
    scene.frame_set(3)
    write_json(os.path.join(folder, 'still', 'before.json'), snapshot(scene))
    bpy.ops.taa.render(animation=False)
    write_json(os.path.join(folder, 'still', 'after.json'), snapshot(scene))


def main():
    args = sys.argv[sys.argv.index('--') + 1:]
    if args[0] == '--build':
        build(args[1])
    elif args[0] == '--png-still':
        os.makedirs(os.path.join(args[1], 'still'), exist_ok=True)
        png_still(args[1])
    elif args[0] == '--snapshot':
        write_json(args[1], snapshot(bpy.context.scene))
    else:
        raise SystemExit('unknown request %r' % args)


try:
    main()
except Exception:  # noqa: BLE001 - any failure must fail the blender process
    import traceback
    traceback.print_exc()
    os._exit(1)
