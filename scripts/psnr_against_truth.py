"""PSNR of resolved frames against a truth render, as taa-yardstick scores them (x / (1 + x) of
each linear channel, peak 1, MSE over R, G and B), for renders too large for the yardstick
(a 1080p truth rendered for a few frames by samples/blender/render_scene.py --products truth).
Also per horizontal band (thirds of the picture, top first): where a run gains or loses.
Runs with Debian's /usr/bin/python3 (python3-numpy, python3-openimageio).

  /usr/bin/python3 scripts/psnr_against_truth.py TRUTH.####.exr FRAME LABEL=RUN.####.exr...

`####` is the frame number, four digits; a file's colour is its R, G, B or its
<layer>.Combined.R, G, B.
"""
import sys

import numpy as np

from exr_colour import read_rgb, yardstick_tonemap


def tonemapped(path):
    return yardstick_tonemap(read_rgb(path))


def psnr(a, b):
    return 10.0 * np.log10(1.0 / np.mean((a - b) ** 2))


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    frame = int(sys.argv[2])
    name = lambda pattern: pattern.replace("####", "%04d" % frame)
    truth = tonemapped(name(sys.argv[1]))
    thirds = np.array_split(np.arange(truth.shape[0]), 3)
    print("%-16s %8s %8s %8s %8s" % ("frame %d" % frame, "PSNR", "top", "middle", "bottom"))
    for run in sys.argv[3:]:
        label, pattern = run.split("=", 1)
        image = tonemapped(name(pattern))
        bands = [psnr(image[rows], truth[rows]) for rows in thirds]
        print("%-16s %8.2f %8.2f %8.2f %8.2f" % (label, psnr(image, truth), *bands))


if __name__ == "__main__":
    main()
