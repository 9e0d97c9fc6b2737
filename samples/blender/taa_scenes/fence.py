"""Wires and a chain-link fence in front of a distant backdrop, under a camera dolly and pan
whose speed grows: parallax of about 3 px/frame on the backdrop to 20 on the nearest wires."""
import math

from . import build as b

DESCRIPTION = ('Cycles: 0.3-0.5 px chain-link fence, power lines and posts before a brick '
               'backdrop with bright lamps; camera dolly and pan speeding up (3-20 px/frame)')


def _diamond_mesh(x0, x1, z0, z1, y, pitch):
    """Two families of diagonal wires in the plane y: a chain-link fence's diamonds."""
    segments = []
    height = z1 - z0
    start = x0 - height
    while start < x1:
        for direction in (1.0, -1.0):
            a = (start, y, z0) if direction > 0 else (start + height, y, z0)
            e = (start + height, y, z1) if direction > 0 else (start, y, z1)
            segments.append((a, e))
        start += pitch
    return segments


def build(frames):
    b.world(zenith=(0.35, 0.5, 0.9, 1), horizon=(0.8, 0.85, 0.9, 1))
    wall = b.emission('backdrop', b.bricks((0.15, 0.15, 0.15, 1), (0.75, 0.35, 0.2, 1),
                                           (0.55, 0.5, 0.45, 1), scale=0.7))
    b.rectangle('backdrop', 120, 40, wall, location=(0, 32, 14), rotation=(math.radians(90), 0, 0))
    grass = b.emission('ground', b.checker((0.12, 0.3, 0.1, 1), (0.2, 0.42, 0.12, 1), scale=3.0))
    b.rectangle('ground', 120, 80, grass, location=(0, 20, 0))
    lamp = b.emission('lamp', b.flat((1, 0.9, 0.7, 1)), strength=25.0)
    for k in range(9):
        b.box('lamp%d' % k, (0.25, 0.05, 0.25), lamp, location=(-16 + 4 * k, 31.9, 3.0 + (k % 3)))

    steel = b.emission('fence', b.flat((0.92, 0.94, 0.96, 1)), strength=1.0)
    b.tubes('fence', _diamond_mesh(-14, 14, 0.0, 2.1, 7.0, 0.11), 0.004, steel)
    posts = [((x, 7.0, 0.0), (x, 7.0, 2.2)) for x in range(-14, 15, 3)]
    b.tubes('posts', posts + [((-14, 7.0, 2.1), (14, 7.0, 2.1))], 0.035, b.emission(
        'post', b.flat((0.3, 0.3, 0.32, 1))), sides=10)
    cable = b.emission('cable', b.flat((0.04, 0.04, 0.05, 1)))
    lines = [((-40, 12.0, 5.2), (40, 12.0, 5.2)), ((-40, 12.0, 5.6), (40, 12.0, 5.6)),
             ((-40, 19.0, 7.5), (40, 19.0, 7.0)), ((-40, 4.0, 3.9), (40, 4.0, 4.1))]
    b.tubes('power_lines', lines, 0.006, cable)

    cam = b.camera(lens_mm=35.0)

    def camera_at(frame):
        t = frame - 1.0
        # Lateral speed grows from 0.07 to 0.17 m/frame (fence parallax ~3 to ~8 px) and the
        # pan speeds up alike (~2 to ~9 px/frame everywhere).
        x = -3.2 + 0.07 * t + 0.0022 * t * t
        y = -1.0 + 0.05 * t
        yaw = 8.0 - 0.3 * t - 0.02 * t * t
        return (x, y, 1.55), b.look_rotation(yaw, 7.0)

    b.animate(cam, frames, camera_at)
