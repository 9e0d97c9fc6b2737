"""Renders the every-pass shot of issue 21 (taa_scenes/passes.py) with every pass a comp uses:
the input through taa's add-on (1 spp, jittered, half colour) and the truth (unjittered, many
samples, float), both multilayer EXR with the same passes. scripts/measure-passes.sh runs it
and measures the resolve against the truth.

    blender -b --factory-startup -P samples/blender/render_passes_shot.py -- \\
        --out DIR [--size 320x180] [--frames 1-12] [--truth-samples 512] [--products input,truth]
"""
import argparse
import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from taa_scenes import passes  # noqa: E402
from taa_scenes.render import Renderer, register_addon  # noqa: E402


def every_pass(layer):
    """The passes of issue 21, as Blender 3.4.1 names them in a multilayer EXR."""
    for name in ('use_pass_combined', 'use_pass_z', 'use_pass_mist', 'use_pass_normal',
                 'use_pass_position', 'use_pass_uv', 'use_pass_object_index',
                 'use_pass_vector', 'use_pass_diffuse_direct', 'use_pass_diffuse_indirect',
                 'use_pass_diffuse_color', 'use_pass_glossy_direct', 'use_pass_glossy_indirect',
                 'use_pass_glossy_color', 'use_pass_transmission_direct',
                 'use_pass_transmission_indirect', 'use_pass_transmission_color',
                 'use_pass_emit', 'use_pass_environment', 'use_pass_ambient_occlusion',
                 'use_pass_shadow', 'use_pass_cryptomatte_object'):
        if hasattr(layer, name):
            setattr(layer, name, True)
        elif hasattr(layer.cycles, name):
            setattr(layer.cycles, name, True)
    layer.pass_cryptomatte_depth = 6  # three rank layers


def main():
    argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
    parser = argparse.ArgumentParser(prog='render_passes_shot.py')
    parser.add_argument('--out', required=True)
    parser.add_argument('--size', default='320x180')
    parser.add_argument('--frames', default='1-12')
    parser.add_argument('--truth-samples', type=int, default=512)
    parser.add_argument('--products', default='input,truth')
    args = parser.parse_args(argv)
    width, height = (int(v) for v in args.size.split('x'))
    first, last = (int(v) for v in args.frames.split('-'))
    frames = list(range(first, last + 1))
    os.makedirs(args.out, exist_ok=True)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    passes.build(range(first - 1, last + 2))
    renderer = Renderer(width, height, args.out, max_bounces=passes.MAX_BOUNCES)
    scene = bpy.context.scene
    layer = scene.view_layers[0]
    for index, obj in enumerate(sorted(scene.objects, key=lambda o: o.name)):
        obj.pass_index = index + 1
    products = args.products.split(',')
    if 'input' in products:
        register_addon()
        every_pass(layer)
        scene.cycles.samples = 1
        scene.render.image_settings.file_format = 'OPEN_EXR_MULTILAYER'
        scene.render.image_settings.color_depth = '16'
        scene.frame_start, scene.frame_end = first, last
        scene.render.filepath = os.path.join(args.out, 'input.####')
        try:
            if bpy.ops.taa.render(animation=True) != {'FINISHED'}:
                raise RuntimeError('the taa add-on refused to render the input')
        finally:
            scene.taa_render.enabled = False
    if 'truth' in products:
        every_pass(layer)
        settings = scene.render.image_settings
        settings.file_format = 'OPEN_EXR_MULTILAYER'
        settings.color_depth = '32'
        scene.cycles.samples = args.truth_samples
        for f in frames:
            scene.frame_set(f)
            scene.render.filepath = os.path.join(args.out, 'truth.%04d.exr' % f)
            bpy.ops.render.render(write_still=True)
            print('truth %d (%d samples)' % (f, args.truth_samples), flush=True)


main()
