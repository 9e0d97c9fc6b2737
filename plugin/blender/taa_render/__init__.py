"""taa for Blender: renders each frame jittered by the Halton(2,3) sequence taatool assumes, with
the frame's camera (view and unjittered projection) and jitter in the EXR header's "Note", so
`taatool --preset cycles` resolves the frames with exact camera reprojection and no flags.
README "Rendering input for taa" has the steps; docs/ARCHITECTURE.md the note's format."""

bl_info = {
    'name': 'taa: jittered renders for temporal anti-aliasing',
    'author': 'taa',
    'version': (0, 1, 0),
    'blender': (3, 4, 0),
    'location': 'Properties > Output > taa Temporal Anti-Aliasing',
    'description': 'Per-frame sub-pixel jitter and the camera in each EXR header, for taatool',
    'category': 'Render',
}

from . import render_session, ui


def register():
    ui.register()
    render_session.register()


def unregister():
    render_session.unregister()
    ui.unregister()
