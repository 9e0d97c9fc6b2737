#!/usr/bin/python3
"""Measures the every-pass resolve of issue 21 on a real render (Debian's /usr/bin/python3 with
python3-openimageio and python3-numpy): per pass, PSNR of the raw input and of taatool's
default resolve against the many-sample truth; the comp identity mismatch
|Combined - sum over Diff, Gloss, Trans of (Dir + Ind) x Col - Emit - Env| for the truth, the raw
input, the resolve and the raw passes beside the resolved beauty (--passthrough); Cryptomatte
matte error for each object of the manifest. scripts/measure-passes.sh renders the shot and
calls this.

    measure_passes.py SHOT_DIR RESOLVED_DIR FIRST LAST
"""
import json
import sys

import numpy as np
import OpenImageIO as oiio

L = 'ViewLayer.'
LIGHT = ['Combined', 'DiffDir', 'DiffInd', 'GlossDir', 'GlossInd', 'TransDir', 'TransInd', 'Emit',
         'Env', 'AO', 'Shadow']
FACTOR = ['DiffCol', 'GlossCol', 'TransCol']
RGB = ['R', 'G', 'B']


def load(path):
    image = oiio.ImageInput.open(path)
    if image is None:
        raise SystemExit('cannot read %s: %s' % (path, oiio.geterror()))
    spec = image.spec()
    pixels = image.read_image('float')
    image.close()
    channels = {name: pixels[:, :, i] for i, name in enumerate(spec.channelnames)}
    attributes = {a.name: a.value for a in spec.extra_attribs}
    return channels, attributes


def rgb(image, name):
    return np.stack([image[L + name + '.' + c] for c in RGB], axis=-1)


def psnr(a, b):
    """On x / (1 + x) of each value: light passes are unbounded, their errors judged as seen."""
    ta, tb = a / (1 + np.abs(a)), b / (1 + np.abs(b))
    mse = float(np.mean((ta - tb) ** 2))
    return float('inf') if mse == 0 else 10 * np.log10(1.0 / mse)


def identity(beauty, passes):
    rebuilt = rgb(passes, 'Emit') + rgb(passes, 'Env')
    for kind in ('Diff', 'Gloss', 'Trans'):
        rebuilt = rebuilt + (rgb(passes, kind + 'Dir') + rgb(passes, kind + 'Ind')) * rgb(
            passes, kind + 'Col')
    difference = np.abs(rgb(beauty, 'Combined') - rebuilt)
    relative = 100.0 * difference.sum() / np.abs(rgb(beauty, 'Combined')).sum()
    return relative, float(np.percentile(difference, 99))


def matte(image, id_float):
    coverage = np.zeros_like(image[L + 'Depth.Z'])
    for layer in ('00', '01', '02'):
        prefix = L + 'CryptoObject' + layer + '.'
        for id_channel, coverage_channel in (('r', 'g'), ('b', 'a')):
            ids = image[prefix + id_channel]
            coverage += np.where(ids == id_float, image[prefix + coverage_channel], 0.0)
    return coverage


def placement(coverage, reference):
    """A matte's centroid offset from the reference's (px, x and y) and its area over the
    reference's: a matte that lags a moving object or trails a ghost shows in both."""
    ys, xs = np.mgrid[0:coverage.shape[0], 0:coverage.shape[1]]
    area, truth_area = coverage.sum(), reference.sum()
    if area <= 0 or truth_area <= 0:
        return float('nan'), float('nan'), float('nan')
    return (float((coverage * xs).sum() / area - (reference * xs).sum() / truth_area),
            float((coverage * ys).sum() / area - (reference * ys).sum() / truth_area),
            float(area / truth_area))


def main():
    shot, resolved, first, last = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
    scores = {}
    identities = {'truth': [], 'raw input': [], 'resolved': [], 'raw passes, resolved beauty': []}
    mattes = {}
    for frame in range(first, last + 1):
        truth, attributes = load('%s/truth.%04d.exr' % (shot, frame))
        raw, _ = load('%s/input.%04d.exr' % (shot, frame))
        out, _ = load('%s/r.%04d.exr' % (resolved, frame))
        for name in LIGHT + FACTOR:
            scores.setdefault(name, []).append((psnr(rgb(raw, name), rgb(truth, name)),
                                                psnr(rgb(out, name), rgb(truth, name))))
        identities['truth'].append(identity(truth, truth))
        identities['raw input'].append(identity(raw, raw))
        identities['resolved'].append(identity(out, out))
        identities['raw passes, resolved beauty'].append(identity(out, raw))
        manifest_key = [k for k in attributes if k.endswith('/manifest')][0]
        manifest = json.loads(attributes[manifest_key])
        for name, hex_id in manifest.items():
            id_float = np.frombuffer(bytes.fromhex(hex_id)[::-1], dtype=np.float32)[0]
            reference = matte(truth, id_float)
            resolved_matte = matte(out, id_float)
            mattes.setdefault(name, []).append(
                (float(np.mean(np.abs(matte(raw, id_float) - reference))),
                 float(np.mean(np.abs(resolved_matte - reference)))) +
                placement(resolved_matte, reference))
    print('frames %d-%d\n' % (first, last))
    print('| pass | raw PSNR (dB) | resolved PSNR (dB) | gain |')
    print('|---|---|---|---|')
    for name, values in scores.items():
        raw_db = np.mean([v[0] for v in values])
        out_db = np.mean([v[1] for v in values])
        if np.isinf(raw_db) and np.isinf(out_db):
            print('| %s | (empty in the shot) | | |' % name)
            continue
        print('| %s | %.2f | %.2f | %+.2f |' % (name, raw_db, out_db, out_db - raw_db))
    print('\n| comp identity | mismatch, relative L1 | 99th percentile of the difference |')
    print('|---|---|---|')
    for name, values in identities.items():
        print('| %s | %.3f %% | %.5f |' % (name, np.mean([v[0] for v in values]),
                                         np.mean([v[1] for v in values])))
    print('\n| Cryptomatte object | raw matte error | resolved matte error | resolved centroid - '
          'truth\'s, x y (px, worst frame) | resolved area / truth\'s (range) |')
    print('|---|---|---|---|---|')
    for name, values in mattes.items():
        dx = max((v[2] for v in values), key=abs)
        dy = max((v[3] for v in values), key=abs)
        areas = [v[4] for v in values]
        print('| %s | %.4f | %.4f | %+.2f %+.2f | %.3f-%.3f |' % (
            name, np.mean([v[0] for v in values]), np.mean([v[1] for v in values]), dx, dy,
            min(areas), max(areas)))


main()
