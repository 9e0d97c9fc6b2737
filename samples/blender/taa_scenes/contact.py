"""A box sliding across a lit floor with bounces: its contact shadow moves with it, its lower
edge meets the floor it hides and reveals, a thin railing stands before a brick wall. Diffuse
and glossy bounces make every 1-spp sample noisy (the others are noise-free): the moving
object must stay opaque (no floor sample may show through it) and its contact shadow must
survive the resolve. The yardstick measures the error inside the box and inside its shadow
(MOVING names the object; render.py renders its masks)."""
import math

from . import build as b

DESCRIPTION = ('Cycles: a box sliding on a lit floor (4-5 px/frame) with its contact shadow, a '
               '0.3 px railing before a brick wall, 3 bounces (noisy at 1 spp), slow pan')

MOVING = 'walker'  # the object whose pixels and shadow the yardstick measures apart
MAX_BOUNCES = 3


def build(frames):
    b.world(zenith=(0.02, 0.02, 0.03, 1), horizon=(0.05, 0.05, 0.06, 1))
    floor = b.lit('floor', b.checker((0.3, 0.3, 0.28, 1), (0.65, 0.62, 0.58, 1), scale=2.5),
                  roughness=0.7)
    b.rectangle('floor', 20, 20, floor, location=(0, 3, 0))
    wall = b.lit('wall', b.bricks((0.15, 0.15, 0.15, 1), (0.6, 0.3, 0.22, 1),
                                  (0.55, 0.5, 0.45, 1), scale=1.5), roughness=0.9)
    b.rectangle('wall', 20, 8, wall, location=(0, 5.5, 4.0), rotation=(math.radians(90), 0, 0))
    glossy = b.lit('glossy', b.flat((0.15, 0.3, 0.8, 1)), roughness=0.2, specular=0.8)
    b.sphere('sphere', 0.45, glossy, location=(2.0, 4.2, 0.45))
    # A railing: posts and rails 8 mm thick, about 0.3 px at 320x180 from 5 m.
    dark = b.lit('rail', b.flat((0.05, 0.05, 0.06, 1)), roughness=0.4)
    rails = [((-3.5, 4.5, h), (3.5, 4.5, h)) for h in (0.45, 0.9)]
    posts = [((x, 4.5, 0.0), (x, 4.5, 0.9)) for x in [-3.5 + 0.7 * k for k in range(11)]]
    b.tubes('railing', rails + posts, 0.004, dark, sides=6)

    crate = b.lit('crate', b.stripes((0.75, 0.55, 0.2, 1), (0.5, 0.3, 0.1, 1), scale=6.0,
                                     axis='Z'), roughness=0.6)
    walker = b.box(MOVING, (0.7, 0.7, 0.9), crate)
    walker.pass_index = 1  # its mask in the aux render's object index pass

    def walker_at(frame):
        t = frame - 1.0
        return (-1.8 + 0.14 * t, 3.2, 0.45), (0.0, 0.0, 0.3 + 0.02 * t)

    b.animate(walker, frames, walker_at)
    light = b.point_light('lamp', energy=1200.0, color=(1.0, 0.95, 0.88))
    b.animate(light, frames, lambda f: ((-1.0, 1.5, 4.5), (0, 0, 0)))
    cam = b.camera(lens_mm=30.0)
    b.animate(cam, frames, lambda f: ((0.2, -3.8, 2.0), b.look_rotation(0.8 - 0.06 * f, -14.0)))
