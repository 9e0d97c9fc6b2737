"""Where a yardstick scene's error lies: on depth edges or off them (docs/TUNING.md).

For frames 5-24 of a real scene, each run's squared error against the truth (tonemapped
x/(1+x), RGB mean) is split by the aux render's depth: a pixel whose 3x3 depths differ by more
than 10% is an edge. Prints, per run, the PSNR over all pixels, over edges and off them, and the
edges' share of the error. Runs with Debian's /usr/bin/python3 (python3-numpy,
python3-openimageio).

  /usr/bin/python3 scripts/error_by_edges.py SCENE_CACHE RUN...

SCENE_CACHE: the scene's render cache (aux.####.exr, truth.####.exr, ssaa2.####.exr); RUN: a
folder of resolved frames (resolved.####.exr), e.g. a yardstick's <work>/runs/<scene>/<config>.
SSAA-2 is measured beside them.
"""
import os
import sys

import numpy as np
import OpenImageIO as oiio

from exr_colour import read_rgb, yardstick_tonemap


def depth_edges(path):
    image = oiio.ImageBuf(path)
    names = list(image.spec().channelnames)
    depth = image.get_pixels(oiio.FLOAT)[..., names.index("ViewLayer.Depth.Z")]
    depth = np.minimum(depth, 1e9)
    padded = np.pad(depth, 1, mode="edge")
    h, w = depth.shape
    around = np.stack([padded[1 + dy:1 + dy + h, 1 + dx:1 + dx + w]
                       for dy in (-1, 0, 1) for dx in (-1, 0, 1)])
    return around.max(0) > around.min(0) * 1.1


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    cache, runs = sys.argv[1], sys.argv[2:]
    sums = {}
    for frame in range(5, 25):
        truth = yardstick_tonemap(read_rgb(os.path.join(cache, "truth.%04d.exr" % frame)))
        edge = depth_edges(os.path.join(cache, "aux.%04d.exr" % frame))
        outputs = [("ssaa-2", os.path.join(cache, "ssaa2.%04d.exr" % frame))]
        outputs += [(run, os.path.join(run, "resolved.%04d.exr" % frame)) for run in runs]
        for name, path in outputs:
            error = ((yardstick_tonemap(read_rgb(path)) - truth) ** 2).mean(-1)
            s = sums.setdefault(name, np.zeros(4))
            s += [error[edge].sum(), edge.sum(), error[~edge].sum(), (~edge).sum()]
    psnr = lambda mse: -10.0 * np.log10(mse)
    for name, (on, on_count, off, off_count) in sums.items():
        print("%s: all %.2f dB; edges (%.0f%% of pixels) %.2f dB, %.0f%% of the error; "
              "elsewhere %.2f dB" % (name, psnr((on + off) / (on_count + off_count)),
                                     100.0 * on_count / (on_count + off_count), psnr(on / on_count),
                                     100.0 * on / (on + off), psnr(off / off_count)))


if __name__ == "__main__":
    main()
