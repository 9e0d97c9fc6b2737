"""The conventions check's scene (tests/blender): static geometry whose emission is its own
world position, seen by a camera that moves and turns. Each 1-spp sample's colour tells where
it landed in the world, so the check can find the sample's position in the image (the jitter)
and the position the same point had in the previous frame (the vectors)."""
import math

from . import build as b

DESCRIPTION = 'Cycles: emission = world position, moving camera (the conventions test)'


def build(frames):
    b.world(zenith=(0.0, 0.0, 0.0, 1), horizon=(0.0, 0.0, 0.0, 1))
    position = b.emission('position', b.world_position())
    # World positions stay positive (emission colours are positions).
    b.rectangle('back', 12, 8, position, location=(5, 9, 4), rotation=(math.radians(80), 0, 0.2))
    b.box('near', (0.8, 0.8, 1.4), position, location=(4.2, 5.0, 2.0), rotation=(0.2, 0.1, 0.7))
    b.box('mid', (1.2, 0.6, 0.6), position, location=(6.0, 6.5, 3.0), rotation=(0.0, 0.4, 0.3))
    cam = b.camera(lens_mm=30.0)
    b.animate(cam, frames, lambda f: ((4.6 + 0.15 * f, 0.5 + 0.1 * f, 2.6 + 0.03 * f),
                                      b.look_rotation(3.0 - 1.5 * f, -2.0 + 0.5 * f, 1.0 * f)))
