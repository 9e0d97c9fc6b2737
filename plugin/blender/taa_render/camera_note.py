"""The camera note: a frame's camera and jitter as text, for the EXR header's "Note" and for
taatool's camera sidecar (docs/ARCHITECTURE.md, "Camera note"; plugin/src/io/camera_note.h):

    taa-camera/1 {"view":[16 numbers],"projection":[16 numbers],"jitter":[jx,jy]}

view and projection are OpenGL matrices listed column by column, the projection without the
jitter's lens shift, jitter in pixels (x right, y down). Blender's matrices are float32: each
number is the shortest text that reads back as the same float32, so the note fits Blender's
stamp (511 bytes, measured) with room to spare and the sidecar holds the same text.
"""
import math
import struct

VERSION = 'taa-camera/1'
# Blender 3.4 keeps a stamp note in a 512-byte buffer: the header gets at most 511 bytes.
MAX_NOTE_BYTES = 511


def float32(value):
    """`value` rounded to the nearest float32 (as a Python float)."""
    return struct.unpack('<f', struct.pack('<f', value))[0]


def number_text(value):
    """The shortest decimal text that reads back as float32(value); JSON's number syntax."""
    rounded = float32(value)
    if not math.isfinite(rounded):
        raise ValueError('taa: a camera value is not finite: %r' % value)
    if rounded == 0.0:
        return '0'  # also -0: JSON readers differ on it, and the sign means nothing here
    for digits in range(1, 10):  # 9 significant digits always round-trip a float32
        text = '%.*g' % (digits, rounded)
        if float32(float(text)) == rounded:
            return text
    raise AssertionError('unreachable: 9 digits round-trip every float32')


def column_major(matrix):
    """A 4x4 mathutils.Matrix (indexed [row][column]) as 16 floats, column by column."""
    return [matrix[row][col] for col in range(4) for row in range(4)]


def entry_text(view, projection, jitter):
    """One camera sidecar entry as compact JSON; `view` and `projection` column-major lists."""
    def numbers(values):
        return ','.join(number_text(v) for v in values)
    return '{"view":[%s],"projection":[%s],"jitter":[%s]}' % (
        numbers(view), numbers(projection), numbers(jitter))


def note_text(entry):
    note = VERSION + ' ' + entry
    if len(note.encode('utf-8')) > MAX_NOTE_BYTES:
        raise ValueError('taa: the camera note is %d bytes, Blender keeps %d' %
                         (len(note.encode('utf-8')), MAX_NOTE_BYTES))
    return note


def unjittered_projection(projection, jitter, width, height):
    """Blender's projection of the jittered camera (column-major) with the jitter's lens shift
    taken out. The shift moves the image by (jx, jy) pixels, that is NDC by (2 jx / width,
    -2 jy / height) (NDC y up); the clip-space translation T(tx, ty) undoes it exactly for
    perspective and orthographic projections alike: rows x and y gain t times row w."""
    tx, ty = 2.0 * jitter[0] / width, -2.0 * jitter[1] / height
    result = list(projection)
    for col in range(4):
        w = projection[4 * col + 3]
        result[4 * col + 0] += tx * w
        result[4 * col + 1] += ty * w
    return result
