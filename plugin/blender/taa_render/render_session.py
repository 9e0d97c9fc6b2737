"""A taa render: from render_init to render_complete (or render_cancel) of a scene with taa on.

render_init    checks the scene (blockers refuse it), sets what the resolve needs (each change
               printed with its reason) and remembers what it was;
frame_change_pre   sets the camera's lens shift to the frame's jitter before the frame is
               evaluated (Cycles evaluates each frame's neighbours too, for the Vector pass; the
               frame itself comes last, measured on Blender 3.4.1);
frame_change_post  from the evaluated camera, writes the frame's camera note into the stamp
               note, which Blender writes into the EXR header as "Note";
render_write   adds the frame's entry to the camera sidecar, when asked for;
render_complete / render_cancel   puts every setting and lens shift back.
Nothing happens outside a taa render (timeline scrubbing, other scenes)."""
import bpy
from bpy.app.handlers import persistent

from . import camera_note, halton, lens_shift, requirements, sidecar


def log(text):
    print('taa: ' + text, flush=True)


class Session:
    def __init__(self, scene):
        self.scene_name = scene.name
        self.changes = []
        self.base_shifts = {}  # camera data -> its own (shift_x, shift_y)
        self.entries = {}      # frame -> camera note entry text
        self.sidecar_path = None

    def jitter(self, frame):
        """The frame's jitter as the float32 values the note states."""
        return tuple(camera_note.float32(v) for v in halton.frame_jitter(frame))

    def apply_jitter(self, scene, frame):
        data = scene.camera.data
        if data not in self.base_shifts:
            self.base_shifts[data] = (data.shift_x, data.shift_y)
        data.shift_x, data.shift_y = lens_shift.jittered_shift(
            scene, data, self.base_shifts[data], self.jitter(frame))

    def camera_entry(self, scene, depsgraph, frame):
        camera = scene.camera.evaluated_get(depsgraph)
        # Cycles renders with the camera's transform without scale.
        view = camera.matrix_world.normalized().inverted()
        width, height = lens_shift.render_size(scene)
        projection = camera.calc_matrix_camera(depsgraph, x=width, y=height,
                                               scale_x=scene.render.pixel_aspect_x,
                                               scale_y=scene.render.pixel_aspect_y)
        jitter = self.jitter(frame)
        unjittered = camera_note.unjittered_projection(camera_note.column_major(projection),
                                                       jitter, width, height)
        return camera_note.entry_text(camera_note.column_major(view), unjittered, jitter)

    def end(self, scene):
        for data, (x, y) in self.base_shifts.items():
            data.shift_x, data.shift_y = x, y
        requirements.restore(scene, self.changes, log)


_session = None


def active(scene):
    return _session is not None and scene.name == _session.scene_name


def end_session(scene=None):
    """Puts the scene back (also when the add-on is disabled in the middle of a render)."""
    global _session
    if _session is None:
        return
    session, _session = _session, None
    session.end(scene or bpy.data.scenes[session.scene_name])
    log('settings and lens shift put back')


@persistent
def on_render_init(scene, *_):
    global _session
    if not scene.taa_render.enabled:
        return
    end_session()
    problems = requirements.blockers(scene)
    if problems:
        log('NOT APPLIED to this render (no jitter, no camera note): ' + '; '.join(problems))
        return
    session = Session(scene)
    log('jittering each frame and writing its camera note; settings for the resolve:')
    session.changes = requirements.apply(scene, lambda text: log('  ' + text))
    if scene.taa_render.write_sidecar:
        session.sidecar_path = sidecar.path_for(scene, scene.taa_render)
    _session = session
    session.apply_jitter(scene, scene.frame_current)


@persistent
def on_frame_change_pre(scene, *_):
    if active(scene):
        _session.apply_jitter(scene, scene.frame_current)


@persistent
def on_frame_change_post(scene, depsgraph=None):
    if not active(scene) or depsgraph is None:
        return
    frame = scene.frame_current
    entry = _session.camera_entry(scene, depsgraph, frame)
    _session.entries[frame] = entry
    scene.render.stamp_note_text = camera_note.note_text(entry)


@persistent
def on_render_write(scene, *_):
    if not active(scene) or _session.sidecar_path is None:
        return
    frame = scene.frame_current
    sidecar.write(_session.sidecar_path, {frame: _session.entries[frame]})


@persistent
def on_render_end(scene, *_):
    if active(scene):
        if _session.sidecar_path:
            log('camera sidecar: ' + _session.sidecar_path)
        end_session(scene)


HANDLERS = (
    ('render_init', on_render_init),
    ('frame_change_pre', on_frame_change_pre),
    ('frame_change_post', on_frame_change_post),
    ('render_write', on_render_write),
    ('render_complete', on_render_end),
    ('render_cancel', on_render_end),
)


def register():
    for name, handler in HANDLERS:
        handlers = getattr(bpy.app.handlers, name)
        if handler not in handlers:
            handlers.append(handler)


def unregister():
    end_session()
    for name, handler in HANDLERS:
        handlers = getattr(bpy.app.handlers, name)
        if handler in handlers:
            handlers.remove(handler)
