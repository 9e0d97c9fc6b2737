"""taa's default jitter: the Halton(2, 3) sequence indexed by frame number (DESIGN.md section 3,
plugin/src/resolve/jitter.cpp). The add-on jitters each frame by what taatool assumes when a
frame carries no camera note, so a render stripped of its metadata still resolves."""


def radical_inverse(index, base):
    """The Halton value of `index` in `base`: 1 -> 1/2, 2 -> 1/4, 3 -> 3/4 for base 2."""
    result, weight = 0.0, 1.0 / base
    while index > 0:
        result += (index % base) * weight
        index //= base
        weight /= base
    return result


def frame_jitter(frame):
    """(jx, jy): the frame's sample offset from the pixel centre in pixels, x right, y down, each
    in [-0.5, 0.5). Negative frames use |frame| as taatool does."""
    index = abs(int(frame))
    return radical_inverse(index, 2) - 0.5, radical_inverse(index, 3) - 0.5
