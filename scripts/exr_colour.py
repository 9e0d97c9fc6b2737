"""The colour of a render's or a resolved file, for the measuring scripts in scripts/ (shared so
that each reads a file and tonemaps it the same way). Debian's /usr/bin/python3 (python3-numpy,
python3-openimageio).
"""
import sys

import numpy as np
import OpenImageIO as oiio


def read_rgb(path):
    """A file's linear R, G, B (height x width x 3): its R, G, B channels, or a Blender render's
    <layer>.Combined.R, G, B. Exits naming the file when it cannot be read."""
    image = oiio.ImageInput.open(path)
    if image is None:
        sys.exit("cannot read %s: %s" % (path, oiio.geterror()))
    pixels = image.read_image("float")
    names = list(image.spec().channelnames)
    image.close()
    rgb = [i for i, n in enumerate(names)
           if n.endswith(("Combined.R", "Combined.G", "Combined.B")) or n in ("R", "G", "B")][:3]
    if len(rgb) != 3:
        sys.exit("%s has no R, G, B or Combined.R, G, B channels (it has %s)"
                 % (path, ", ".join(names)))
    return pixels[..., rgb]


def yardstick_tonemap(linear):
    """x / (1 + x) of each channel, negatives clipped: the space taa-yardstick scores in, peak 1."""
    linear = np.maximum(linear, 0.0)
    return linear / (1.0 + linear)
