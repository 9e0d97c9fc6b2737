"""taatool's camera sidecar (--camera-sidecar, plugin/src/io/camera_sidecar.h) beside the
frames, for pipelines that strip EXR metadata. Each entry is the very text of the frame's
camera note, so `taatool --camera-sidecar F --jitter sidecar` reads the numbers the header
holds. Entries already in the file are kept (a render of frames 1-10 then 11-20 gives one file);
renders writing the same file at once (farm chunks) would lose entries: use the header there."""
import json
import os

from . import camera_note

FILE_NAME = 'taa_camera.json'


def path_for(scene, settings):
    """The sidecar's path: the add-on's setting, else taa_camera.json in the frames' folder."""
    import bpy
    if settings.sidecar_path:
        return os.path.abspath(bpy.path.abspath(settings.sidecar_path))
    frame_path = scene.render.frame_path(frame=scene.frame_current)
    return os.path.join(os.path.dirname(os.path.abspath(frame_path)), FILE_NAME)


def _entry_of(fields):
    return camera_note.entry_text(fields['view'], fields['projection'], fields['jitter'])


def write(path, entries):
    """Adds `entries` ({frame: entry text}) to the sidecar at `path`, written atomically."""
    merged = {}
    if os.path.exists(path):
        with open(path) as existing:
            frames = json.load(existing).get('frames', {})
        # Written by this module, so re-formatting gives the same text back.
        merged = {int(frame): _entry_of(fields) for frame, fields in frames.items()}
    merged.update(entries)
    lines = ['"%d": %s' % (frame, merged[frame]) for frame in sorted(merged)]
    text = '{"frames": {\n' + ',\n'.join(lines) + '\n}}\n'
    os.makedirs(os.path.dirname(path) or '.', exist_ok=True)
    temporary = '%s.tmp-%d' % (path, os.getpid())
    with open(temporary, 'w') as out:
        out.write(text)
    os.replace(temporary, path)
