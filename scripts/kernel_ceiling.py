# The error a reconstruction kernel leaves however many samples it gets: a render at S times the
# yardstick's size (Cycles' one sample per pixel sits at the pixel centre: point samples on an
# S x S grid per pixel) filtered by each kernel at the small pixels' centres, against the truth
# (box-filtered, 1024 spp). PSNR on v / (1 + v), as the yardstick's. Debian's /usr/bin/python3:
#   blender -b --factory-startup -P samples/blender/render_scene.py -- --scene cycles_fence \
#       --out /tmp/hires --size 2560x1440 --frames 17-17 --products aux
#   /usr/bin/python3 scripts/kernel_ceiling.py /tmp/hires/aux.0017.exr \
#       ~/.cache/taa/blender/cycles_fence-320x180-1-24/truth.0017.exr 8
import sys

import numpy as np
import OpenImageIO as oiio


def load(path, names):
    image = oiio.ImageInput.open(path)
    spec = image.spec()
    pixels = image.read_image(0, 0, 0, spec.nchannels, 'float')
    image.close()
    missing = [n for n in names if n not in spec.channelnames]
    if missing:
        raise SystemExit('%s: no channel %s' % (path, missing[0]))
    return pixels[:, :, [spec.channelnames.index(n) for n in names]]


def tonemap(v):
    v = np.maximum(v, 0.0)
    return v / (1.0 + v)


def psnr(a, b):
    return 10.0 * np.log10(1.0 / np.mean((tonemap(a) - tonemap(b)) ** 2))


def filtered(fine, shape, scale, kernel, radius):
    """`fine` filtered by kernel(dx, dy) (offsets in small pixels from a small pixel's centre,
    out to `radius`), sampled at the small pixels' centres."""
    height, width = shape
    reach = int(np.ceil(radius)) * scale
    padded = np.pad(fine, ((reach, reach), (reach, reach), (0, 0)), mode='edge')
    total = np.zeros((height, width, fine.shape[2]))
    weights = 0.0
    for py in range(-reach, reach + scale):
        for px in range(-reach, reach + scale):
            weight = kernel((px + 0.5) / scale - 0.5, (py + 0.5) / scale - 0.5)
            if weight <= 1e-6:
                continue
            total += weight * padded[reach + py::scale, reach + px::scale][:height, :width]
            weights += weight
    return total / weights


def main():
    fine_path, truth_path, scale = sys.argv[1], sys.argv[2], int(sys.argv[3])
    rgb = ['ViewLayer.Combined.' + c for c in 'RGB']
    fine = load(fine_path, rgb)
    truth = load(truth_path, ['R', 'G', 'B'])
    shape = truth.shape[:2]
    box = filtered(fine, shape, scale, lambda dx, dy: float(abs(dx) < 0.5 and abs(dy) < 0.5), 0.5)
    print('box (%dx%d points a pixel): %.2f dB' % (scale, scale, psnr(box, truth)))
    for sigma in (0.25, 0.30, 0.35, 0.40):
        gaussian = filtered(fine, shape, scale,
                            lambda dx, dy: np.exp(-(dx * dx + dy * dy) / (2 * sigma * sigma)),
                            4 * sigma)
        print('Gaussian, sigma %.2f: %.2f dB' % (sigma, psnr(gaussian, truth)))


if __name__ == '__main__':
    main()
