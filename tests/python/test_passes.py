"""Every pass of the render through the Python module (issue 21): resolve_sequence resolves
the colour file's other channels as taatool does, and a list repeats an option (aov=[...] is
two --aov rules). Run by Debian's /usr/bin/python3 (tests/python/CMakeLists.txt)."""
import os
import subprocess

import numpy as np
import OpenImageIO as oiio
import pytest

import taa
from conftest import SAMPLE_DIR, TAATOOL, read_exr

FRAMES = range(1, 7)


@pytest.fixture(scope="module")
def sample_with_passes(tmp_root):
    """The bundled sample's first frames with an emission pass (half) and a data pass (float)
    in the colour file, as a render writes them."""
    folder = os.path.join(tmp_root, "passes_input")
    os.makedirs(folder, exist_ok=True)
    for frame in FRAMES:
        beauty = read_exr(os.path.join(SAMPLE_DIR, f"beauty.{frame:04d}.exr"),
                          ["R", "G", "B", "A"])
        height, width = beauty.shape[:2]
        emit = 0.25 * beauty[:, :, :3]
        position = np.full((height, width, 1), 1000.0 + frame, dtype=np.float32)
        pixels = np.concatenate([beauty, emit, position], axis=2)
        spec = oiio.ImageSpec(width, height, 8, "half")
        spec.channelnames = ("R", "G", "B", "A", "Emit.R", "Emit.G", "Emit.B", "Position.X")
        spec.channelformats = ("half",) * 7 + ("float",)
        out = oiio.ImageOutput.create("exr")
        path = os.path.join(folder, f"beauty.{frame:04d}.exr")
        assert out.open(path, spec), oiio.geterror()
        assert out.write_image(pixels)
        out.close()
    return folder


def args_for(folder, out):
    return dict(depth=os.path.join(SAMPLE_DIR, "depth.####.exr"),
                motion=os.path.join(SAMPLE_DIR, "motion.####.exr"),
                frames="1-6", mode="window", output=os.path.join(out, "r.####.exr"))


def channel_names(path):
    image = oiio.ImageInput.open(path)
    names = list(image.spec().channelnames)
    image.close()
    return names


def test_passes_are_resolved_as_taatool_resolves_them(sample_with_passes, tmp_root):
    color = os.path.join(sample_with_passes, "beauty.####.exr")
    out = os.path.join(tmp_root, "passes_module")
    taa.resolve_sequence(color, **args_for(sample_with_passes, out))
    tool = os.path.join(tmp_root, "passes_taatool")
    subprocess.run([TAATOOL, color, "--depth", os.path.join(SAMPLE_DIR, "depth.####.exr"),
                    "--motion", os.path.join(SAMPLE_DIR, "motion.####.exr"), "--frames", "1-6",
                    "--mode", "window", "-o", os.path.join(tool, "r.####.exr"), "-q"],
                   check=True)
    names = ["R", "G", "B", "A", "Emit.R", "Emit.G", "Emit.B", "Position.X"]
    path = os.path.join(out, "r.0003.exr")
    assert sorted(channel_names(path)) == sorted(names)
    np.testing.assert_array_equal(read_exr(path, names),
                                  read_exr(os.path.join(tool, "r.0003.exr"), names))
    # The emission pass was resolved with the colour's weights: a quarter of the colour, but
    # where the colour's own limits (overshoot at edges) act, which passes do not take.
    resolved = read_exr(path, names)
    difference = np.abs(resolved[:, :, 4:7] - 0.25 * resolved[:, :, :3])
    assert difference.mean() < 1e-4
    assert np.percentile(difference, 99.5) < 2e-3


def test_a_list_repeats_an_option(sample_with_passes, tmp_root):
    out = os.path.join(tmp_root, "passes_rules")
    taa.resolve_sequence(os.path.join(sample_with_passes, "beauty.####.exr"),
                         aov=["Emit.*=copy", "*=drop"], **args_for(sample_with_passes, out))
    path = os.path.join(out, "r.0003.exr")
    assert sorted(channel_names(path)) == sorted(["R", "G", "B", "A", "Emit.R", "Emit.G",
                                                  "Emit.B"])
    # Copied untouched from frame 3's own file.
    np.testing.assert_array_equal(
        read_exr(path, ["Emit.G"]),
        read_exr(os.path.join(sample_with_passes, "beauty.0003.exr"), ["Emit.G"]))
    with pytest.raises(taa.Error, match="unknown kind 'albedo'"):
        taa.resolve_sequence(os.path.join(sample_with_passes, "beauty.####.exr"),
                             aov=["Emit.*=albedo"], **args_for(sample_with_passes, out))


def test_node_resolves_passes_as_taatool_does(sample_with_passes, tmp_root):
    """Node.push(passes={...}) in window mode, then Node.passes(): taatool's channels bit for
    bit, float16 channels read back as float16."""
    color = os.path.join(sample_with_passes, "beauty.####.exr")
    tool = os.path.join(tmp_root, "passes_taatool_for_node")
    subprocess.run([TAATOOL, color, "--depth", os.path.join(SAMPLE_DIR, "depth.####.exr"),
                    "--motion", os.path.join(SAMPLE_DIR, "motion.####.exr"), "--frames", "1-6",
                    "--mode", "window", "--window", "2", "-o", os.path.join(tool, "r.####.exr"),
                    "-q"], check=True)
    node = taa.Node(mode="window", window=2)
    names = ["Emit.R", "Emit.G", "Emit.B", "Position.X"]
    for frame in range(1, 6):  # frame 3's window: a ring of 2K + 1 = 5
        path = os.path.join(sample_with_passes, f"beauty.{frame:04d}.exr")
        beauty = read_exr(path, ["R", "G", "B", "A"])
        values = read_exr(path, names)
        passes = {name: values[:, :, i].astype(np.float16 if name.startswith("Emit") else
                                               np.float32) for i, name in enumerate(names)}
        node.push(beauty, depth=read_exr(os.path.join(SAMPLE_DIR, f"depth.{frame:04d}.exr"),
                                         ["Z"])[:, :, 0],
                  motion=read_exr(os.path.join(SAMPLE_DIR, f"motion.{frame:04d}.exr"),
                                  ["X", "Y"]),
                  frame=frame, passes=passes)
    node.resolve(3)
    resolved = node.passes()
    assert sorted(resolved) == sorted(names)
    assert resolved["Emit.G"].dtype == np.float16 and resolved["Position.X"].dtype == np.float32
    expected = read_exr(os.path.join(tool, "r.0003.exr"), names)
    for i, name in enumerate(names):
        np.testing.assert_array_equal(resolved[name].astype(np.float32), expected[:, :, i])
    assert list(node.passes(["Emit.B"])) == ["Emit.B"]
    with pytest.raises(taa.Error, match='no pass "Shadow.R"'):
        node.passes(["Shadow.R"])
    history = taa.Node()
    with pytest.raises(taa.Error, match='"mode" = "window"'):
        history.push(beauty, passes={"Emit.R": passes["Emit.R"]})
