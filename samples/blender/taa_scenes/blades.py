"""Thin fan blades spinning in front of a wall and a textured cube tumbling beside them:
rotation, whose per-frame vectors chained over several frames drift off the true circles."""
import math

from . import build as b

DESCRIPTION = ('Cycles: five 2 px fan blades spinning at 9 deg/frame (tips ~10 px/frame) and '
               'a tumbling checker cube, slow camera drift')


def build(frames):
    b.world(zenith=(0.25, 0.3, 0.5, 1), horizon=(0.5, 0.5, 0.55, 1))
    wall = b.emission('wall', b.stripes((0.15, 0.18, 0.2, 1), (0.75, 0.78, 0.7, 1), scale=1.5,
                                        axis='Y'))
    b.rectangle('wall', 16, 8, wall, location=(0, 3.0, 2.0), rotation=(math.radians(90), 0, 0))
    floor = b.emission('floor', b.checker((0.3, 0.25, 0.2, 1), (0.5, 0.45, 0.35, 1), scale=2.5))
    b.rectangle('floor', 16, 14, floor, location=(0, -1, -0.6))

    blade = b.emission('blade', b.stripes((0.95, 0.95, 0.9, 1), (0.9, 0.2, 0.1, 1), scale=6.0,
                                          axis='X'), strength=1.2)
    hub = b.emission('hub', b.flat((0.2, 0.2, 0.2, 1)))
    fan = b.box('hub', (0.18, 0.1, 0.18), hub, location=(-1.2, 0.0, 1.5))
    for k in range(5):
        angle = 2.0 * math.pi * k / 5
        piece = b.box('blade%d' % k, (1.5, 0.012, 0.045), blade,
                      location=(0.8 * math.cos(angle), 0.0, 0.8 * math.sin(angle)),
                      rotation=(0.0, -angle, 0.0))
        piece.parent = fan
    b.animate(fan, frames, lambda f: ((-1.2, 0.0, 1.5), (0.0, math.radians(9.0 * f), 0.0)))

    cube_material = b.emission('cube', b.checker((0.05, 0.3, 0.1, 1), (0.9, 0.95, 0.8, 1),
                                                 scale=6.0))
    cube = b.box('cube', (0.9, 0.9, 0.9), cube_material)
    b.animate(cube, frames, lambda f: ((1.5, 0.2, 1.2), (math.radians(7.0 * f),
                                                           math.radians(11.0 * f), 0.3)))

    cam = b.camera(lens_mm=35.0)
    b.animate(cam, frames, lambda f: ((0.02 * f, -6.0, 1.4), b.look_rotation(0.0, 0.5)))
