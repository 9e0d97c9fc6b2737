"""Renders one of taa's Blender scenes with Cycles on the CPU (Blender's own Python):

    blender -b --factory-startup -P samples/blender/render_scene.py -- \
        --scene cycles_fence --out DIR [--size 320x180] [--frames 1-24] \
        [--products input,aux,truth,ssaa,camera,nomoving] [--truth-samples 1024] [--ssaa 2,4,8,16]

Writes into DIR (samples/README.md, "Blender scenes"): input.####.exr (1 spp at the frame's
Halton jitter, multilayer ViewLayer.Combined/Depth/Vector as Cycles writes it, half colour),
aux.####.exr (1 spp unjittered, float: depth and vectors at the pixel centres), truth.####.exr
(--truth-samples spp, unjittered), ssaaN.####.exr (mean of N 1-spp renders at the Halton
offsets 1..N), camera.json (taatool's camera sidecar); for a scene with a MOVING object,
nomoving.####.exr (the truth without it, a quarter of the samples) and its object index in
aux. `--list` prints the scenes.

Each product is cached: PRODUCT.stamp records what made it (scene sources, size, frames, its
parameters, Blender's version); a product whose stamp matches is not rendered again, so the
yardstick can run this for every scene every time and only pays for what changed.
"""
import argparse
import glob
import hashlib
import json
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import bpy  # noqa: E402

from taa_scenes import SCENES, YARDSTICK  # noqa: E402
from taa_scenes.render import Renderer  # noqa: E402

PRODUCTS = ('camera', 'input', 'aux', 'ssaa', 'truth', 'nomoving')


def frame_range(text):
    first, _, last = text.partition('-')
    first, last = int(first), int(last or first)
    if last < first:
        raise argparse.ArgumentTypeError('expected FIRST-LAST, got %r' % text)
    return first, last


def size(text):
    width, _, height = text.partition('x')
    return int(width), int(height)


def parse(argv):
    parser = argparse.ArgumentParser(prog='render_scene.py')
    parser.add_argument('--scene')
    parser.add_argument('--out')
    parser.add_argument('--size', type=size, default=(320, 180))
    parser.add_argument('--frames', type=frame_range, default=(1, 24))
    parser.add_argument('--products', default=','.join(PRODUCTS))
    parser.add_argument('--truth-samples', type=int, default=1024)
    parser.add_argument('--ssaa', default='2,4,8,16')
    parser.add_argument('--input-depth', choices=('half', 'float'), default='half')
    parser.add_argument('--list', action='store_true')
    args = parser.parse_args(argv)
    if args.list:
        return args
    if args.scene not in SCENES:
        parser.error('unknown scene %r (known: %s)' % (args.scene, ', '.join(SCENES)))
    if not args.out:
        parser.error('--out is required')
    args.products = [p for p in args.products.split(',') if p]
    for product in args.products:
        if product not in PRODUCTS:
            parser.error('unknown product %r (known: %s)' % (product, ', '.join(PRODUCTS)))
    args.ssaa = sorted({int(n) for n in args.ssaa.split(',') if n})
    return args


def stamp_of(args, product):
    """What a product depends on, as text: equal stamps mean the files on disk are current."""
    module = SCENES[args.scene]
    here = os.path.dirname(os.path.abspath(__file__))
    # The scene and the code that builds and renders it; not this driver, whose changes
    # (arguments, listing) do not change what is rendered.
    sources = [module.__file__, os.path.join(here, 'taa_scenes', 'build.py'),
               os.path.join(here, 'taa_scenes', 'render.py')]
    if product == 'input':  # rendered through the add-on
        addon = os.path.join(here, '..', '..', 'plugin', 'blender', 'taa_render')
        sources += sorted(glob.glob(os.path.join(addon, '*.py')))
    params = {'truth': {'samples': args.truth_samples}, 'ssaa': {'counts': args.ssaa},
              'input': {'depth': args.input_depth},
              'nomoving': {'samples': args.truth_samples // 4}}.get(product, {})
    stamp = {
        'product': product, 'scene': args.scene, 'size': list(args.size),
        'frames': list(args.frames), 'params': params, 'blender': bpy.app.version_string,
        'sources': {os.path.relpath(path, here): hashlib.sha256(open(path, 'rb').read()).hexdigest()
                    for path in sources},
    }
    return json.dumps(stamp, indent=1, sort_keys=True) + '\n'


def product_files(out, product):
    if product == 'camera':
        return [os.path.join(out, 'camera.json')]
    stem = 'ssaa[0-9]*' if product == 'ssaa' else product
    return glob.glob(os.path.join(out, stem + '.[0-9]*.exr'))


def is_current(out, product, stamp):
    path = os.path.join(out, product + '.stamp')
    return os.path.exists(path) and open(path).read() == stamp


def main():
    argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
    args = parse(argv)
    if args.list:
        for name in YARDSTICK:
            print('%s\t%s' % (name, SCENES[name].DESCRIPTION))
        return
    os.makedirs(args.out, exist_ok=True)
    bpy.ops.wm.read_factory_settings(use_empty=True)
    first, last = args.frames
    frames = range(first, last + 1)
    # Keys one frame beyond each end: the Vector pass looks at the previous and next frame.
    SCENES[args.scene].build(range(first - 1, last + 2))
    scene = bpy.context.scene
    scene.frame_start, scene.frame_end = first, last
    start = time.time()
    module = SCENES[args.scene]
    moving = getattr(module, 'MOVING', None)
    renderer = Renderer(args.size[0], args.size[1], args.out,
                        log=lambda text: print('render_scene: %s: %s (%.0f s)' % (
                            args.scene, text, time.time() - start), flush=True),
                        max_bounces=getattr(module, 'MAX_BOUNCES', 0), moving=moving)
    render = {
        'camera': lambda: renderer.camera_sidecar(frames, os.path.join(args.out, 'camera.json')),
        'input': lambda: renderer.input(frames, half=args.input_depth == 'half'),
        'aux': lambda: renderer.aux(frames),
        'ssaa': lambda: renderer.ssaa(frames, args.ssaa),
        'truth': lambda: renderer.truth(frames, args.truth_samples),
        'nomoving': lambda: renderer.without_moving(frames, args.truth_samples // 4),
    }
    for product in PRODUCTS:
        if product not in args.products or (product == 'nomoving' and not moving):
            continue
        stamp = stamp_of(args, product)
        if is_current(args.out, product, stamp):
            print('render_scene: %s: %s cached' % (args.scene, product), flush=True)
            continue
        stamp_path = os.path.join(args.out, product + '.stamp')
        for path in product_files(args.out, product) + [stamp_path]:
            if os.path.exists(path):
                os.remove(path)
        render[product]()
        with open(stamp_path, 'w') as out:
            out.write(stamp)
        print('render_scene: %s: %s rendered' % (args.scene, product), flush=True)


try:
    main()
except SystemExit as exit_request:
    # Blender keeps running after a script's SystemExit; leave with its code instead.
    os._exit(exit_request.code if isinstance(exit_request.code, int) else 2)
except Exception:  # noqa: BLE001 - any failure must fail the blender process
    import traceback
    traceback.print_exc()
    os._exit(1)
