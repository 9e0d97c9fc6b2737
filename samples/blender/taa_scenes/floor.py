"""A fine checker and striped floor seen at a grazing angle under a forward dolly, rows of thin
posts on both sides, sky above without geometry (zero vectors, as Cycles writes)."""
import math

from . import build as b

DESCRIPTION = ('Cycles: fine checker floor at a grazing angle, forward dolly (1-22 px/frame), '
               'thin posts, sky without geometry')


def build(frames):
    b.world(zenith=(0.2, 0.35, 0.8, 1), horizon=(0.9, 0.9, 0.95, 1))
    tiles = b.emission('floor', b.mix(b.stripes((0, 0, 0, 1), (1, 1, 1, 1), scale=0.6,
                                                axis='Y'),
                                      b.checker((0.08, 0.08, 0.1, 1), (0.85, 0.85, 0.8, 1),
                                                scale=8.0),
                                      b.flat((0.7, 0.2, 0.15, 1))))
    b.rectangle('floor', 60, 400, tiles, location=(0, 190, 0))
    post = b.emission('post', b.flat((0.95, 0.9, 0.3, 1)))
    posts = []
    for k in range(40):
        for x in (-2.5, 2.5):
            posts.append(((x, 3.0 + 4.0 * k, 0.0), (x, 3.0 + 4.0 * k, 1.6)))
    b.tubes('posts', posts, 0.03, post, sides=8)
    cam = b.camera(lens_mm=30.0, clip=(0.05, 1000.0))
    b.animate(cam, frames, lambda f: ((0.0, 0.15 * (f - 1), 0.45),
                                      b.look_rotation(0.5 * math.sin(0.2 * f), -6.0)))
