"""Static diffuse and glossy geometry under a point light circling above: hard shadows and
highlights sweep across surfaces that do not move (the camera pans slowly). Shading changes
while geometry stands still: history and multi-frame resolves must not smear it."""
import math

from . import build as b

DESCRIPTION = ('Cycles: lit diffuse and glossy objects, a point light circling (hard shadows '
               'of a pole and slats sweep ~5 px/frame), slow pan')


def build(frames):
    b.world(zenith=(0.02, 0.02, 0.03, 1), horizon=(0.05, 0.05, 0.06, 1))
    floor = b.lit('floor', b.checker((0.35, 0.35, 0.33, 1), (0.6, 0.58, 0.55, 1), scale=1.0),
                  roughness=0.6)
    b.rectangle('floor', 20, 20, floor, location=(0, 3, 0))
    wall = b.lit('wall', b.stripes((0.5, 0.45, 0.4, 1), (0.62, 0.58, 0.52, 1), scale=2.0),
                 roughness=0.8)
    b.rectangle('wall', 20, 8, wall, location=(0, 6.0, 4.0), rotation=(math.radians(90), 0, 0))
    glossy = b.lit('glossy', b.flat((0.8, 0.15, 0.1, 1)), roughness=0.25, specular=0.8)
    b.sphere('sphere', 0.7, glossy, location=(-1.6, 3.0, 0.7))
    metal = b.lit('metal', b.flat((0.8, 0.8, 0.85, 1)), roughness=0.3, metallic=1.0)
    b.box('box', (1.0, 1.0, 1.4), metal, location=(1.4, 3.6, 0.7), rotation=(0, 0, 0.5))
    dark = b.lit('dark', b.flat((0.1, 0.1, 0.12, 1)), roughness=0.5)
    b.tubes('pole', [((0.0, 2.2, 0.0), (0.0, 2.2, 2.4))], 0.02, dark, sides=8)
    slats = [((x, 4.6, 0.0), (x, 4.6, 1.8)) for x in [-0.6 + 0.12 * k for k in range(11)]]
    b.tubes('slats', slats, 0.015, dark, sides=6)

    light = b.point_light('sun', energy=900.0, color=(1.0, 0.95, 0.85))
    b.animate(light, frames, lambda f: ((3.0 * math.cos(0.11 * f), 1.5 + 3.0 * math.sin(0.11 * f),
                                         4.0), (0, 0, 0)))
    cam = b.camera(lens_mm=32.0)
    b.animate(cam, frames, lambda f: ((0.0, -4.5, 2.2), b.look_rotation(2.0 - 0.25 * f, -12.0)))
