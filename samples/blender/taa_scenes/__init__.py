"""The Blender scenes of taa's quality yardstick (docs/QUALITY.md, real-render section) and
of its conventions test. Each module builds its scene into an empty Blender scene with
`build(frames)` and says what it stresses in `DESCRIPTION`. YARDSTICK lists the scenes the
yardstick measures (`render_scene.py --list`); the others serve tests."""
from . import ball, blades, contact, conventions, fence, floor, lit

SCENES = {
    'cycles_fence': fence,
    'cycles_ball': ball,
    'cycles_blades': blades,
    'cycles_floor': floor,
    'cycles_lit': lit,
    'cycles_contact': contact,
    'cycles_conventions': conventions,
}

YARDSTICK = ['cycles_fence', 'cycles_ball', 'cycles_blades', 'cycles_floor', 'cycles_lit',
             'cycles_contact']
