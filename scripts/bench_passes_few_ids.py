"""Rewrites bench-passes' frames with a handful of Cryptomatte IDs, as a render has (a few
objects a pixel), instead of the depth's value in every pixel: rank layer 00 holds one ID per
depth band (log2 of depth, halves) with coverage 1, the other pairs and layers are empty.
Usage (Debian's /usr/bin/python3, python3-openimageio):
  /usr/bin/python3 scripts/bench_passes_few_ids.py IN_FOLDER OUT_FOLDER FIRST LAST
IN_FOLDER is scripts/bench-passes.sh's cache (cycles_fence-1920x1080-passes-typed)."""
import os
import shutil
import sys

import numpy as np
import OpenImageIO as oiio


def rewrite(source, target):
    image = oiio.ImageInput.open(source)
    spec = image.spec()
    pixels = image.read_image(0, 0, 0, spec.nchannels, "float")
    image.close()
    names = list(spec.channelnames)
    depth = pixels[:, :, names.index("ViewLayer.Depth.Z")]
    band = np.clip(np.floor(np.log2(np.maximum(depth, 1e-3)) * 2), -8, 8)
    ids = (1.0 + 0.37 * band).astype(np.float32)
    for layer in ("00", "01", "02"):
        for component in "rgba":
            index = names.index(f"ViewLayer.CryptoObject{layer}.{component}")
            first_pair = layer == "00" and component in "rg"
            pixels[:, :, index] = (ids if component == "r" else 1.0) if first_pair else 0.0
    out = oiio.ImageOutput.create(target)
    if not out.open(target, spec) or not out.write_image(pixels):
        sys.exit(f"cannot write {target}: {oiio.geterror()}")
    out.close()


def main():
    source, target, first, last = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    os.makedirs(target, exist_ok=True)
    for frame in range(first, last + 1):
        name = f"input.{frame:04d}.exr"
        rewrite(os.path.join(source, name), os.path.join(target, name))
    camera = os.path.join(source, "camera.json")
    if os.path.exists(camera):
        shutil.copy(camera, target)


if __name__ == "__main__":
    main()
