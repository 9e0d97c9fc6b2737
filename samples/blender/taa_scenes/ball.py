"""A fast striped ball (6-12 px/frame) bouncing and rolling across a textured wall it hides and
reveals; the camera stands still, so most of the frame never changes."""
import math

from . import build as b

DESCRIPTION = ('Cycles: a striped ball bouncing and rolling (6-12 px/frame) before a brick and '
               'checker wall, static camera')


def build(frames):
    b.world(zenith=(0.3, 0.45, 0.8, 1), horizon=(0.7, 0.75, 0.8, 1))
    wall = b.emission('wall', b.mix(b.checker((0, 0, 0, 1), (1, 1, 1, 1), scale=6.0),
                                    b.bricks((0.1, 0.1, 0.1, 1), (0.7, 0.3, 0.2, 1),
                                             (0.5, 0.45, 0.4, 1), scale=1.5),
                                    b.flat((0.85, 0.85, 0.8, 1))))
    # Checker squares of 1/12 m on the left half (about 3.5 px), bricks elsewhere.
    b.rectangle('wall', 14, 6, wall, location=(0, 2.0, 3.0), rotation=(math.radians(90), 0, 0))
    floor = b.emission('floor', b.checker((0.2, 0.2, 0.22, 1), (0.6, 0.6, 0.6, 1), scale=2.0))
    b.rectangle('floor', 14, 12, floor, location=(0, -2, 0))

    radius = 0.55
    # Bands about 12 px wide at 320x180: fine enough to alias at the rim, coarse enough that
    # the ball reads as a ball and not as its average colour.
    stripes = b.emission('ball', b.stripes((1.0, 0.85, 0.1, 1), (0.8, 0.05, 0.05, 1), scale=1.0,
                                           axis='Z'), strength=1.3)
    ball = b.sphere('ball', radius, stripes)

    def ball_at(frame):
        t = frame - 1.0
        x = -2.6 + 0.21 * t
        bounce = 0.55 * abs(math.sin(math.pi * t / 9.0))
        # Rolling: rotation about the axis perpendicular to the motion and the floor normal.
        return (x, 0.3, radius + bounce), (0.0, x / radius, 0.0)

    b.animate(ball, frames, ball_at)
    cam = b.camera(lens_mm=35.0)
    b.animate(cam, frames, lambda f: ((0.0, -7.5, 1.6), b.look_rotation(0.0, 1.0)))
