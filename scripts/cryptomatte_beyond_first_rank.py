"""How much of a render's Cryptomatte coverage lies beyond each pixel's first two IDs (its first
rank layer, the IDs taa's window resolve weighs; docs/PASSES.md, "Not yet"). Prints, per file,
the share of all coverage in rank layers 01 and later, the share of pixels holding more than
0.001 there, and the most one pixel holds there.
Usage (Debian's /usr/bin/python3, python3-numpy, python3-openimageio):
  /usr/bin/python3 scripts/cryptomatte_beyond_first_rank.py FILE.exr...
"""
import sys

import numpy as np
import OpenImageIO as oiio


def main():
    for path in sys.argv[1:]:
        image = oiio.ImageInput.open(path)
        if image is None:
            sys.exit("cannot read %s: %s" % (path, oiio.geterror()))
        names = list(image.spec().channelnames)
        pixels = image.read_image(0, 0, 0, len(names), "float")
        image.close()
        layers = sorted({n.rsplit(".", 1)[0] for n in names if "Crypto" in n})
        if not layers:
            sys.exit("%s: no Cryptomatte rank layer" % path)
        # Each rank layer holds two (id, coverage) pairs: coverage in g and a.
        coverage = np.stack([pixels[..., names.index(layer + "." + c)]
                             for layer in layers for c in "ga"], -1)
        beyond = coverage[..., 2:].sum(-1)
        print("%s: %d rank layers; beyond the first: %.4f %% of the coverage, %.2f %% of the "
              "pixels hold more than 0.001, at most %.3f" %
              (path, len(layers), 100 * beyond.sum() / coverage.sum(),
               100 * (beyond > 1e-3).mean(), beyond.max()))


if __name__ == "__main__":
    main()
