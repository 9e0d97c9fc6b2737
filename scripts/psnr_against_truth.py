"""PSNR of resolved frames against a truth render, as taa-yardstick scores them (x / (1 + x) of
each linear channel, peak 1, MSE over R, G and B), for renders too large for the yardstick
(a 1080p truth rendered for a few frames by samples/blender/render_scene.py --products truth).
Also per horizontal band (thirds of the picture, top first): where a run gains or loses.
Runs with Debian's /usr/bin/python3 (python3-numpy, python3-openimageio).

  /usr/bin/python3 scripts/psnr_against_truth.py TRUTH.####.exr FRAME LABEL=RUN.####.exr...

`####` is the frame number, four digits; a file's colour is its R, G, B or its
<layer>.Combined.R, G, B. Where the truth's folder also holds render_scene.py's aux.####.exr
and nomoving.####.exr (a scene with a moving object), two more columns score inside the moving
object and inside its shadow, masked as taa-yardstick masks them (tools/yardstick/
blender_scenes.cpp: the object where aux's object index says so; its shadow where, off the
object, the truth's luma is under 70 % of the render without it, on surfaces lit without it).
"""
import os
import sys

import numpy as np
import OpenImageIO as oiio

from exr_colour import read_rgb, yardstick_tonemap


def tonemapped(path):
    return yardstick_tonemap(read_rgb(path))


def psnr(a, b):
    return 10.0 * np.log10(1.0 / np.mean((a - b) ** 2))


def luma(linear):
    return linear @ np.array([0.2126, 0.7152, 0.0722])


def moving_regions(truth_path):
    """(object mask, shadow mask) for the truth at `truth_path`, or None without aux/nomoving."""
    folder, base = os.path.split(truth_path)
    aux = os.path.join(folder, base.replace("truth.", "aux.", 1))
    without = os.path.join(folder, base.replace("truth.", "nomoving.", 1))
    if not (os.path.exists(aux) and os.path.exists(without)):
        return None
    buffer = oiio.ImageBuf(aux)
    index = buffer.get_pixels(oiio.FLOAT)[..., list(buffer.spec().channelnames).index(
        "ViewLayer.IndexOB.X")]
    moving = index > 0.5
    lit, shaded = luma(read_rgb(without)), luma(read_rgb(truth_path))
    return moving, ~moving & (lit > 0.02) & (shaded < 0.7 * lit)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    frame = int(sys.argv[2])
    name = lambda pattern: pattern.replace("####", "%04d" % frame)
    truth = tonemapped(name(sys.argv[1]))
    thirds = np.array_split(np.arange(truth.shape[0]), 3)
    regions = moving_regions(name(sys.argv[1]))
    extra = " %8s %8s" % ("object", "shadow") if regions else ""
    print("%-16s %8s %8s %8s %8s%s" % ("frame %d" % frame, "PSNR", "top", "middle", "bottom",
                                        extra))
    for run in sys.argv[3:]:
        label, pattern = run.split("=", 1)
        image = tonemapped(name(pattern))
        bands = [psnr(image[rows], truth[rows]) for rows in thirds]
        extra = "".join(" %8.2f" % psnr(image[mask], truth[mask]) for mask in regions or ())
        print("%-16s %8.2f %8.2f %8.2f %8.2f%s" % (label, psnr(image, truth), *bands, extra))


if __name__ == "__main__":
    main()
