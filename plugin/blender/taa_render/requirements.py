"""What a render needs for taa, checked and set when a taa render starts, put back when it ends.
Each Setting says what it is for; blockers are what the add-on cannot fix."""


class Setting:
    """One scene setting the resolve needs: `owner(scene)` holds the attribute `name`; `wanted`
    is the value taa needs, or a function of the current value (None: leave it, only put it
    back afterwards)."""

    def __init__(self, label, why, owner, name, wanted):
        self.label, self.why, self.owner, self.name, self.wanted = label, why, owner, name, wanted

    def get(self, scene):
        return getattr(self.owner(scene), self.name)

    def set(self, scene, value):
        setattr(self.owner(scene), self.name, value)

    def wanted_value(self, scene, before=None):
        """What taa sets; a function of the value the scene had before the render (`before`,
        else the current one)."""
        if callable(self.wanted):
            return self.wanted(self.get(scene) if before is None else before)
        return self.wanted


def _exr_depth(before):
    # Half colour unless the scene asked for float; Cycles writes Depth and Vector as float
    # either way (measured on Blender 3.4.1). Blender itself picks 32 when a PNG's 8 bits
    # become an EXR's, so the choice is made from the value before the render.
    return before if before in ('16', '32') else '16'


def settings(scene):
    """The settings of `scene` taa needs, in the order they are set (the file format before its
    colour depth, whose choices depend on it)."""
    result = [
        Setting('Motion blur', 'Cycles writes no Vector pass with it on',
                lambda s: s.render, 'use_motion_blur', False),
        Setting('Pixel filter', 'a pixel is its own jittered sample area, nothing of its '
                'neighbours', lambda s: s.cycles, 'pixel_filter_type', 'BOX'),
        Setting('Pixel filter width', 'one pixel wide', lambda s: s.cycles, 'filter_width', 1.0),
        Setting('Denoising', 'a denoiser blurs across pixels; taa filters the jittered samples '
                'itself', lambda s: s.cycles, 'use_denoising', False),
        Setting('File format', 'colour, depth and vectors in one file, as --preset cycles '
                'reads them', lambda s: s.render.image_settings, 'file_format',
                'OPEN_EXR_MULTILAYER'),
        Setting('Colour depth', 'half colour (float kept); depth and vectors are float',
                lambda s: s.render.image_settings, 'color_depth', _exr_depth),
        Setting('Stamp burn-in', 'it would draw the camera note into the pixels',
                lambda s: s.render, 'use_stamp', False),
        Setting('Stamp note', 'the note carries each frame\'s camera into the EXR header',
                lambda s: s.render, 'use_stamp_note', True),
        Setting('Stamp note text', 'set per frame to the camera note',
                lambda s: s.render, 'stamp_note_text', None),
    ]
    for layer in scene.view_layers:
        if not layer.use:
            continue
        owner = (lambda name: lambda s: s.view_layers[name])(layer.name)
        result.append(Setting('Depth pass (%s)' % layer.name,
                              'depth for camera reprojection and visibility',
                              owner, 'use_pass_z', True))
        result.append(Setting('Vector pass (%s)' % layer.name,
                              'each sample\'s motion to the previous frame',
                              owner, 'use_pass_vector', True))
    return result


def _animated(data_block, paths):
    animation = data_block.animation_data
    if animation is None:
        return []
    curves = list(animation.drivers)
    if animation.action is not None:
        curves += list(animation.action.fcurves)
    return sorted({c.data_path for c in curves if c.data_path in paths})


def blockers(scene):
    """Why taa cannot render `scene`, as sentences; empty when it can."""
    problems = []
    if scene.render.engine != 'CYCLES':
        problems.append('the render engine is %s: taa\'s Blender conventions are Cycles\''
                        % scene.render.engine)
    camera = scene.camera
    if camera is None or camera.type != 'CAMERA':
        problems.append('the scene has no camera')
    else:
        if camera.data.type == 'PANO':
            problems.append('the camera is panoramic: its projection is no matrix')
        animated = _animated(camera.data, ('shift_x', 'shift_y'))
        if animated:
            problems.append('the camera\'s lens shift is animated (%s): the jitter is a shift '
                            'set per frame' % ', '.join(animated))
    if scene.render.use_multiview:
        problems.append('stereo/multi-view renders are not supported (one camera per frame)')
    return problems


def describe(value):
    if isinstance(value, bool):
        return 'on' if value else 'off'
    return repr(value)


def apply(scene, log):
    """Sets every setting to what taa needs; returns [(setting, previous value)] for restore.
    Each change is logged with its reason."""
    # Every value is taken before anything is set: setting one may change another (the file
    # format changes the colour depth).
    changes = [(setting, setting.get(scene)) for setting in settings(scene)]
    for setting, before in changes:
        wanted = setting.wanted_value(scene, before)
        if wanted is None or setting.get(scene) == wanted:
            continue
        setting.set(scene, wanted)
        if wanted != before:
            log('%s: %s -> %s (%s)' % (setting.label, describe(before), describe(wanted),
                                        setting.why))
    return changes


def restore(scene, changes, log):
    """Puts back what apply changed, in the same order (the file format before its colour
    depth: PNG's 8 bits are no EXR choice). One setting that cannot be put back does not keep
    the others from it."""
    for setting, previous in changes:
        try:
            if setting.get(scene) != previous:
                setting.set(scene, previous)
        except (TypeError, ValueError, AttributeError, KeyError) as error:
            log('could not put back %s (%s): %s' % (setting.label, describe(previous), error))
