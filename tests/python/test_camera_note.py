"""taa.resolve_sequence reads a frame's camera note (the colour header's "Note", as the Blender
add-on writes it) with no option, as taatool does: the same pixels as the camera sidecar holding
the same numbers, other pixels than without the note."""
import json
import os
import shutil

import numpy as np
import OpenImageIO as oiio
import pytest

import taa
from conftest import SAMPLE_DIR, read_exr

FRAMES = range(1, 7)
CHANNELS = ["R", "G", "B", "A"]


def jitter_of(frame):
    """Jitters other than the Halton default the sample was rendered with, so that using them
    shows in the result."""
    return [0.125 * ((frame % 3) - 1), -0.0625 * ((frame % 4) - 1.5)]


@pytest.fixture(scope="module")
def noted(tmp_root):
    """Frames 1-6 of the bundled sample, the beauty with a jitter-only camera note in its
    header, and a sidecar with the same entries."""
    folder = os.path.join(tmp_root, "camera_note")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    entries = {}
    for frame in FRAMES:
        entry = '{"jitter":[%r,%r]}' % tuple(jitter_of(frame))
        entries[str(frame)] = json.loads(entry)
        beauty = oiio.ImageBuf(os.path.join(SAMPLE_DIR, f"beauty.{frame:04d}.exr"))
        beauty.specmod().attribute("Note", "taa-camera/1 " + entry)
        assert beauty.write(os.path.join(folder, f"beauty.{frame:04d}.exr")), beauty.geterror()
        for stem in ("depth", "motion"):
            name = f"{stem}.{frame:04d}.exr"
            os.symlink(os.path.join(SAMPLE_DIR, name), os.path.join(folder, name))
    with open(os.path.join(folder, "camera.json"), "w") as out:
        json.dump({"frames": entries}, out)
    return folder


def resolve(folder, beauty_folder, out, **kwargs):
    taa.resolve_sequence(os.path.join(beauty_folder, "beauty.####.exr"),
                         depth=os.path.join(folder, "depth.####.exr"),
                         motion=os.path.join(folder, "motion.####.exr"), frames="1-6",
                         pixel_type="float",
                         output=os.path.join(folder, out, "r.####.exr"), **kwargs)
    return [read_exr(os.path.join(folder, out, f"r.{f:04d}.exr"), CHANNELS) for f in FRAMES]


def test_the_note_is_read_with_no_option_and_equals_the_sidecar(noted):
    from_note = resolve(noted, noted, "note")
    from_sidecar = resolve(noted, noted, "sidecar",
                           camera_sidecar=os.path.join(noted, "camera.json"), jitter="sidecar")
    halton = resolve(noted, SAMPLE_DIR, "halton")
    for frame, a, b, c in zip(FRAMES, from_note, from_sidecar, halton):
        assert np.array_equal(a, b), f"frame {frame}"
        assert not np.array_equal(a, c), f"frame {frame}: the note's jitter made no difference"


def test_an_explicit_jitter_wins_over_the_note(noted):
    explicit = resolve(noted, noted, "explicit", jitter="halton")
    halton = resolve(noted, SAMPLE_DIR, "halton_again")
    for frame, a, b in zip(FRAMES, explicit, halton):
        assert np.array_equal(a, b), f"frame {frame}"


def test_a_bad_note_is_an_error_naming_the_frame_and_note(noted, tmp_root):
    folder = os.path.join(tmp_root, "camera_note_bad")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    for frame in FRAMES:
        beauty = oiio.ImageBuf(os.path.join(noted, f"beauty.{frame:04d}.exr"))
        if frame == 3:
            beauty.specmod().attribute("Note", 'taa-camera/1 {"jitter":[0.5]}')
        assert beauty.write(os.path.join(folder, f"beauty.{frame:04d}.exr")), beauty.geterror()
    with pytest.raises(taa.Error, match=r"\"jitter\" must be \[jx, jy\].*beauty\.0003\.exr "
                                        r"\(frame 3, channel Note\)"):
        resolve(noted, folder, "bad_out")
