"""How much of the chain-link's contrast a cycles_fence resolve keeps (docs/TUNING.md).

Over the band of rows where the fence's wires cross the grass (145-178 of 180 at 320x180), the
resolved frames' error is regressed on the truth's departure from the grass's colour (the
band's median per frame), both tonemapped x/(1+x), gamma 2.2, frames 5-24: a slope of k means
the wires keep 1 - k of their contrast against the grass. Also prints the band's PSNR and the
brick wall's above it (rows 20-89). Runs with Debian's /usr/bin/python3 (python3-numpy,
python3-openimageio).

  /usr/bin/python3 scripts/wire_contrast.py SCENE_CACHE RUN

SCENE_CACHE: cycles_fence's render cache (truth.####.exr); RUN: a folder of resolved frames
(*.####.exr), e.g. a yardstick's <work>/runs/cycles_fence/<configuration>.
"""
import glob
import sys

import numpy as np

from exr_colour import read_rgb, yardstick_tonemap


def tonemapped(path):
    return yardstick_tonemap(read_rgb(path)) ** (1.0 / 2.2)


def psnr(error):
    return 10.0 * np.log10(1.0 / np.mean(error ** 2))


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    cache, run = sys.argv[1], sys.argv[2]
    errors, truths = [], []
    for frame in range(5, 25):
        found = sorted(glob.glob("%s/*.%04d.exr" % (run, frame)))
        if not found:
            sys.exit("no frame %d in %s" % (frame, run))
        truth = tonemapped("%s/truth.%04d.exr" % (cache, frame))
        errors.append(tonemapped(found[0]) - truth)
        truths.append(truth)
    error, truth = np.array(errors), np.array(truths)
    band_error, band_truth = error[:, 145:178, 2:318], truth[:, 145:178, 2:318]
    grass = np.median(band_truth.reshape(len(band_truth), -1, 3), axis=1)[:, None, None, :]
    departure = band_truth - grass
    slope = -(band_error * departure).sum() / (departure * departure).sum()
    print("band %.2f dB, contrast lost %.1f %%, wall %.2f dB"
          % (psnr(band_error), 100.0 * slope, psnr(error[:, 20:90, 2:318])))


if __name__ == "__main__":
    main()
