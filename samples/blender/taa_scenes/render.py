"""Rendering the products of a scene: the jittered 1-spp input, the unjittered reference data,
the many-sample truth, SSAA-N references and the camera sidecar (samples/README.md, "Blender
scenes").

Facts of Blender 3.4's Cycles this relies on (checked by tests/blender):
- sample 0 of a pixel sits at the pixel centre, so a 1-spp render is never jittered by the
  sampler; the jitter is applied as a lens shift, shift_x = jx / W, shift_y = -jy / W with W the
  larger image side (jx right, jy down, in pixels);
- the shift is not animated, so the Vector pass (previous and next frame of the objects and
  the camera's transform) carries no jitter;
- Depth is planar, 1e10 where nothing is hit; Vector XY = previous - current in pixels with y
  up, ZW = current - next.
"""
import json
import os
import sys

import bpy
import numpy as np


ADDON_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', '..', 'plugin',
                         'blender')
if ADDON_DIR not in sys.path:
    sys.path.insert(0, ADDON_DIR)
# taa's default jitter, Halton(2, 3) at an index minus 0.5 (pixels, x right, y down): the
# add-on's own, which the input is rendered through.
from taa_render.halton import frame_jitter as halton_jitter  # noqa: E402


def register_addon():
    """taa's Blender add-on (plugin/blender/taa_render), registered from the source tree: the
    input is rendered through it as a user renders (README "Rendering input for taa")."""
    import importlib
    addon = importlib.import_module('taa_render')
    if not hasattr(bpy.types.Scene, 'taa_render'):
        addon.register()
    return addon


class Renderer:
    def __init__(self, width, height, out_dir, log=print, max_bounces=0, moving=None):
        self.scene = bpy.context.scene
        self.width, self.height = width, height
        self.out_dir = out_dir
        self.log = log
        s = self.scene
        s.render.engine = 'CYCLES'
        s.cycles.device = 'CPU'
        s.cycles.use_adaptive_sampling = False
        s.cycles.use_denoising = False  # Debian's Blender has no OpenImageDenoise anyway
        # Direct light only unless the scene asks for bounces: no noise, aliasing is then the
        # only error. With bounces each frame gets its own noise (an animated seed), as
        # renders for temporal accumulation are made.
        s.cycles.max_bounces = max_bounces
        s.cycles.use_animated_seed = max_bounces > 0
        s.cycles.caustics_reflective = s.cycles.caustics_refractive = False
        s.cycles.pixel_filter_type = 'BOX'
        s.cycles.filter_width = 1.0
        s.cycles.seed = 0
        s.render.use_motion_blur = False  # the Vector pass needs it off
        s.render.resolution_x, s.render.resolution_y = width, height
        s.render.resolution_percentage = 100
        s.render.film_transparent = False
        s.render.use_persistent_data = True  # keeps the BVH between the many 1-spp renders
        s.view_settings.view_transform = 'Standard'
        s.view_settings.look = 'None'
        settings = s.render.image_settings
        settings.exr_codec = 'ZIP'
        self.camera = s.camera
        # The object the yardstick measures apart (its mask: the aux render's object index).
        self.moving = bpy.data.objects.get(moving) if moving else None
        self.base_shift = (self.camera.data.shift_x, self.camera.data.shift_y)

    def _jitter_shift(self, jx, jy):
        side = float(max(self.width, self.height))
        self.camera.data.shift_x = self.base_shift[0] + jx / side
        self.camera.data.shift_y = self.base_shift[1] - jy / side

    def _render(self, path, frame, samples, jitter, multilayer, half, seed=0):
        s = self.scene
        s.frame_set(frame)
        self._jitter_shift(*jitter)
        s.cycles.samples = samples
        s.cycles.seed = seed
        layer = s.view_layers[0]
        layer.use_pass_z = layer.use_pass_vector = multilayer
        layer.use_pass_object_index = multilayer and self.moving is not None
        settings = s.render.image_settings
        settings.file_format = 'OPEN_EXR_MULTILAYER' if multilayer else 'OPEN_EXR'
        settings.color_mode = 'RGBA'
        settings.color_depth = '16' if half else '32'
        s.render.filepath = path
        bpy.ops.render.render(write_still=True)
        self._jitter_shift(0.0, 0.0)

    def path(self, stem, frame):
        return os.path.join(self.out_dir, '%s.%04d.exr' % (stem, frame))

    def input(self, frames, half=True):
        """The renderer's own output through taa's add-on, one animation render: 1 spp at the
        frame's Halton jitter (a lens shift), its camera in the header's Note, Combined, Depth
        and Vector in one multilayer EXR (half colour, float depth and vectors)."""
        register_addon()
        s = self.scene
        s.cycles.samples = 1
        s.cycles.seed = 0
        layer = s.view_layers[0]
        layer.use_pass_object_index = False
        settings = s.render.image_settings
        settings.file_format = 'OPEN_EXR_MULTILAYER'
        settings.color_depth = '16' if half else '32'
        s.frame_start, s.frame_end = frames[0], frames[-1]
        s.render.filepath = os.path.join(self.out_dir, 'input.####')
        try:
            if bpy.ops.taa.render(animation=True) != {'FINISHED'}:
                raise RuntimeError('the taa add-on refused to render the input (see above)')
        finally:
            s.taa_render.enabled = False  # the operator leaves it on: later renders are ours
        self.log('input %d-%d (through the add-on)' % (frames[0], frames[-1]))

    def aux(self, frames):
        """1 spp without jitter: depth and vectors exactly at the pixel centres, for the
        yardstick's flow and disocclusion masks."""
        for f in frames:
            self._render(self.path('aux', f), f, 1, (0.0, 0.0), True, False)
            self.log('aux %d' % f)

    def truth(self, frames, samples):
        """The box-filtered pixel average: many samples, no jitter."""
        for f in frames:
            self._render(self.path('truth', f), f, samples, (0.0, 0.0), False, False)
            self.log('truth %d (%d samples)' % (f, samples))

    def ssaa(self, frames, counts):
        """SSAA-N: the linear mean of N 1-spp renders at the Halton offsets 1..N, written for
        each N in `counts`."""
        scratch = os.path.join(self.out_dir, 'ssaa-scratch.exr')
        for f in frames:
            total = None
            for n in range(1, max(counts) + 1):
                # Each render its own noise (with bounces): N renders are N samples.
                self._render(scratch, f, 1, halton_jitter(n), False, False, seed=n)
                pixels = _load_pixels(scratch)
                total = pixels if total is None else total + pixels
                if n in counts:
                    _save_pixels(self.path('ssaa%d' % n, f), total / n, self.width, self.height)
            self.log('ssaa %d (%d renders)' % (f, max(counts)))
        os.remove(scratch)

    def without_moving(self, frames, samples):
        """The truth without the moving object (hidden for camera and light): where the truth
        is darker, the object shades the scene (its contact shadow)."""
        self.moving.hide_render = True
        try:
            for f in frames:
                self._render(self.path('nomoving', f), f, samples, (0.0, 0.0), False, False)
                self.log('nomoving %d (%d samples)' % (f, samples))
        finally:
            self.moving.hide_render = False

    def camera_sidecar(self, frames, path):
        """taatool's camera sidecar: OpenGL view and projection (without jitter), jitter."""
        entries = {}
        depsgraph = bpy.context.evaluated_depsgraph_get()
        for f in frames:
            self.scene.frame_set(f)
            self._jitter_shift(0.0, 0.0)
            depsgraph.update()
            cam = self.camera.evaluated_get(depsgraph)
            view = cam.matrix_world.inverted()
            projection = cam.calc_matrix_camera(depsgraph, x=self.width, y=self.height)
            entries[str(f)] = {
                'view': _column_major(view),
                'projection': _column_major(projection),
                'jitter': list(halton_jitter(f)),
            }
        with open(path, 'w') as out:
            json.dump({'frames': entries}, out, indent=1)


def _column_major(matrix):
    return [matrix[row][col] for col in range(4) for row in range(4)]


def _load_pixels(path):
    image = bpy.data.images.load(path)
    pixels = np.empty(len(image.pixels), dtype=np.float32)
    image.pixels.foreach_get(pixels)
    bpy.data.images.remove(image)
    return pixels.astype(np.float64)


def _save_pixels(path, pixels, width, height):
    image = bpy.data.images.new('ssaa', width, height, alpha=True, float_buffer=True)
    # Data, not colour: a generated image saved as 'Linear' comes out sRGB-encoded.
    image.colorspace_settings.name = 'Non-Color'
    image.pixels.foreach_set(pixels.astype(np.float32))
    image.filepath_raw = path
    image.file_format = 'OPEN_EXR'
    image.use_half_precision = False
    image.save()
    bpy.data.images.remove(image)
