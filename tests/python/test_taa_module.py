"""The Python module on the bundled sample: identical output to taatool, errors as taa.Error."""
import os
import shutil
import subprocess

import numpy as np
import OpenImageIO as oiio
import pytest

import taa
from conftest import FRAMES, SAMPLE_DIR, TAATOOL, read_exr


def sample_path(stem, frame):
    return os.path.join(SAMPLE_DIR, f"{stem}.{frame:04d}.exr")


def taatool_frame(folder, frame):
    return read_exr(os.path.join(folder, f"resolved.{frame:04d}.exr"), ["R", "G", "B", "A"])


def test_resolve_sequence_is_identical_to_taatool(taatool_output, tmp_root):
    out = os.path.join(tmp_root, "module")
    shutil.rmtree(out, ignore_errors=True)
    seen = []
    reports = taa.resolve_sequence(
        os.path.join(SAMPLE_DIR, "beauty.####.exr"),
        depth=os.path.join(SAMPLE_DIR, "depth.####.exr"),
        motion=os.path.join(SAMPLE_DIR, "motion.####.exr"),
        output=os.path.join(out, "resolved.####.exr"), pixel_type="float",
        progress=lambda report: seen.append(report["frame"]))
    assert [r["frame"] for r in reports] == list(FRAMES)
    assert seen == list(FRAMES)
    for frame in FRAMES:
        ours = read_exr(os.path.join(out, f"resolved.{frame:04d}.exr"), ["R", "G", "B", "A"])
        np.testing.assert_array_equal(ours, taatool_frame(taatool_output, frame))


def test_options_reach_the_resolve(taatool_history_output, tmp_root):
    def resolve(name, frames):
        out = os.path.join(tmp_root, name)
        taa.resolve_sequence(os.path.join(SAMPLE_DIR, "beauty.####.exr"),
                             output=os.path.join(out, "resolved.####.exr"), frames=frames,
                             mode="history", blend=1.0, pixel_type="float")
        return read_exr(os.path.join(out, "resolved.0003.exr"), ["R", "G", "B", "A"])

    # blend 1 keeps no history: frame 3 after frames 1-2 is frame 3 resolved alone (up to the
    # rounding of the shader's mix()).
    with_history = resolve("blend_1_3", [1, 2, 3])
    np.testing.assert_allclose(with_history, resolve("blend_3", "3"), atol=1e-6, rtol=1e-6)
    assert np.abs(with_history - taatool_frame(taatool_history_output, 3)).max() > 1e-3


def load_frame(frame):
    return (read_exr(sample_path("beauty", frame), ["R", "G", "B", "A"]),
            read_exr(sample_path("depth", frame), ["Z"])[:, :, 0],
            read_exr(sample_path("motion", frame), ["X", "Y"]))


def test_node_matches_taatool_frame_by_frame(taatool_history_output):
    node = taa.Node()
    flipped = taa.Node()
    for frame in FRAMES:
        color, depth, motion = load_frame(frame)
        out = node.push(color, depth=depth, motion=motion, frame=frame)
        assert out.shape == color.shape and out.dtype == np.float32
        np.testing.assert_allclose(out, taatool_frame(taatool_history_output, frame), atol=1e-6,
                                   rtol=0)
        # The same frame given bottom row first (as OpenFX and GL lay images out).
        up = flipped.push(color[::-1], depth=depth[::-1], motion=motion[::-1], frame=frame,
                          y_up=True)
        np.testing.assert_array_equal(up[::-1], out)


def test_node_takes_float16(taatool_history_output):
    """Half arrays decode exactly: the same as float32 arrays holding the half-rounded values."""
    half_node, float_node = taa.Node(), taa.Node()
    for frame in FRAMES[:6]:
        halves = [a.astype(np.float16) for a in load_frame(frame)]
        from_half = half_node.push(*halves, frame=frame)
        from_float = float_node.push(*[h.astype(np.float32) for h in halves], frame=frame)
        np.testing.assert_array_equal(from_half, from_float)
    # And stays close to the full-precision result.
    error = np.abs(from_half - taatool_frame(taatool_history_output, FRAMES[5]))
    assert error.mean() < 2e-3


def test_missing_file_raises_with_the_library_message(tmp_root):
    missing = os.path.join(tmp_root, "nowhere", "beauty.####.exr")
    with pytest.raises(taa.Error) as error:
        taa.resolve_sequence(missing, output=os.path.join(tmp_root, "x.####.exr"),
                             frames="1-3")
    message = str(error.value)
    assert "missing input frame" in message
    assert os.path.join(tmp_root, "nowhere", "beauty.0001.exr") in message
    assert isinstance(error.value, RuntimeError)


def test_bad_option_raises_taatool_message(tmp_root):
    output = os.path.join(tmp_root, "y.exr")
    with pytest.raises(taa.Error) as error:
        taa.resolve_sequence(sample_path("beauty", 1), output=output, blend=2)
    cli = subprocess.run([TAATOOL, sample_path("beauty", 1), "-o", output, "--blend", "2"],
                         capture_output=True, text=True)
    assert cli.returncode == 1
    assert cli.stderr.strip() == f"taatool ERROR: {error.value}"
    assert "blend" in str(error.value)


def test_progress_exceptions_propagate(tmp_root):
    def fail(report):
        raise ValueError(f"stop at {report['frame']}")

    with pytest.raises(ValueError, match="stop at 1"):
        taa.resolve_sequence(os.path.join(SAMPLE_DIR, "beauty.####.exr"), frames="1-2",
                             output=os.path.join(tmp_root, "p.####.exr"), progress=fail)


def test_node_errors_carry_the_library_message():
    node = taa.Node()
    with pytest.raises(taa.Error, match='unknown parameter "blendd"'):
        node.set("blendd", 0.5)
    with pytest.raises(taa.Error, match=r'option blend expects .*, got "0"'):
        taa.Node(blend=0)
    color = np.zeros((8, 8, 4), np.float32)
    with pytest.raises(taa.Error, match="depth is 4x4 but color is 8x8"):
        node.push(color, depth=np.zeros((4, 4), np.float32))
    with pytest.raises(taa.Error, match="color must have 3 to 4 channels, has 2"):
        node.push(np.zeros((8, 8, 2), np.float32))
    # The node still works after errors.
    assert node.push(color + 0.25)[0, 0, 0] == pytest.approx(0.25)


ACES_CONFIG = os.path.join(os.environ.get("TAA_SOURCE_DIR", ""), "tests", "color",
                           "aces_style.ocio")


def test_studio_ocio_follows_the_one_rule(tmp_root, monkeypatch):
    """Any studio $OCIO works in every face (issue 24): the bracket is taa's maths, the config
    (ocio_config, else $OCIO, else taa's) serves the input and output colorspaces."""
    color, depth, motion = load_frame(1)
    monkeypatch.delenv("OCIO", raising=False)
    reference = taa.Node().push(color, depth=depth, motion=motion, frame=1)
    monkeypatch.setenv("OCIO", ACES_CONFIG)
    for parameters in ({}, {"ocio_config": "$OCIO"}, {"colorspace_in": "ACEScg"},
                       {"ocio_config": ACES_CONFIG, "colorspace_in": "scene_linear"}):
        np.testing.assert_array_equal(
            reference, taa.Node(**parameters).push(color, depth=depth, motion=motion, frame=1),
            err_msg=str(parameters))
    # The config converts: ACES2065-1 input written as ACEScg differs from the input's space.
    converted = taa.Node(colorspace_in="ACES2065-1", colorspace_out="ACEScg").push(
        color, depth=depth, motion=motion, frame=1)
    assert np.abs(converted - reference).max() > 1e-3

    out = os.path.join(tmp_root, "studio_ocio", "r.####.exr")
    taa.resolve_sequence(os.path.join(SAMPLE_DIR, "beauty.####.exr"), frames="1-2",
                         colorspace_in="ACEScg", output=out)
    spec = oiio.ImageInput.open(out.replace("####", "0002")).spec()
    assert spec.get_string_attribute("taa:colorspace") == "ACEScg"
    assert spec.get_string_attribute("taa:ocioConfig") == f"$OCIO ({ACES_CONFIG})"
    with pytest.raises(taa.Error, match=r'unknown input colorspace or role "acescg_typo"'):
        taa.Node(colorspace_in="acescg_typo").push(color, frame=1)
