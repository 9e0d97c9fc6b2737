"""Side-by-side crops of a yardstick scene for looking at, not scoring (docs/TUNING.md).

Row one: the raw input, each run's output, the truth (tonemapped x/(1+x), gamma 2.2); row two:
each one's absolute error against the truth, times 8. Scaled up 4x, nearest neighbour.
Runs with Debian's /usr/bin/python3 (python3-numpy, python3-openimageio).

  /usr/bin/python3 scripts/crop_compare.py SCENE_CACHE FRAME X Y WIDTH HEIGHT OUT.png RUN...

SCENE_CACHE: the scene's render cache (input.####.exr, truth.####.exr); RUN: a folder of
resolved frames (*.####.exr), e.g. a yardstick's <work>/runs/<scene>/<configuration>.
"""
import glob
import sys

import numpy as np
import OpenImageIO as oiio

from exr_colour import read_rgb


def main():
    if len(sys.argv) < 9:
        sys.exit(__doc__)
    cache, frame = sys.argv[1], int(sys.argv[2])
    x, y, width, height = map(int, sys.argv[3:7])
    out, runs = sys.argv[7], sys.argv[8:]
    images = [read_rgb("%s/input.%04d.exr" % (cache, frame))]
    for run in runs:
        found = sorted(glob.glob("%s/*.%04d.exr" % (run, frame)))
        if not found:
            sys.exit("no frame %d in %s" % (frame, run))
        images.append(read_rgb(found[0]))
    images.append(read_rgb("%s/truth.%04d.exr" % (cache, frame)))

    def display(image):
        return np.clip(image / (1.0 + image), 0.0, 1.0) ** (1.0 / 2.2)

    def crop(image):
        return image[y:y + height, x:x + width]

    truth = display(images[-1])
    top = [crop(display(image)) for image in images]
    errors = [np.repeat(np.clip(np.abs(display(image) - truth).mean(-1) * 8.0, 0.0, 1.0)[..., None],
                        3, -1) for image in images]
    bottom = [crop(error) for error in errors]
    sheet = np.concatenate([np.concatenate(top, 1), np.concatenate(bottom, 1)], 0)
    sheet = np.kron(sheet, np.ones((4, 4, 1)))
    buffer = oiio.ImageBuf(oiio.ImageSpec(sheet.shape[1], sheet.shape[0], 3, "uint8"))
    buffer.set_pixels(oiio.ROI(), sheet.astype(np.float32))
    if not buffer.write(out):
        sys.exit("cannot write %s: %s" % (out, buffer.geterror()))


if __name__ == "__main__":
    main()
