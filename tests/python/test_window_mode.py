"""Window mode in the Python module (mode="window", window=K) against taatool --mode window on
the bundled sample: resolve_sequence, Node.push / Node.resolve in any order, and the errors."""
import os
import random
import shutil
import subprocess

import numpy as np
import pytest

import taa
from conftest import FRAMES, SAMPLE_DIR, TAATOOL, read_exr, sample_args

K = 3


def sample_path(stem, frame):
    return os.path.join(SAMPLE_DIR, f"{stem}.{frame:04d}.exr")


def load_frame(frame):
    return (read_exr(sample_path("beauty", frame), ["R", "G", "B", "A"]),
            read_exr(sample_path("depth", frame), ["Z"])[:, :, 0],
            read_exr(sample_path("motion", frame), ["X", "Y"]))


def output_frame(folder, frame):
    return read_exr(os.path.join(folder, f"resolved.{frame:04d}.exr"), ["R", "G", "B", "A"])


@pytest.fixture(scope="session")
def taatool_window(tmp_root):
    """Folder of taatool's float window-mode output (K = 3) on the whole bundled sample."""
    out = os.path.join(tmp_root, "taatool_window")
    os.makedirs(out, exist_ok=True)
    subprocess.run([TAATOOL, *sample_args(os.path.join(out, "resolved.####.exr")),
                    "--mode", "window", "--window", str(K), "-q"], check=True)
    return out


@pytest.fixture(scope="session")
def frames():
    return {frame: load_frame(frame) for frame in FRAMES}


def test_resolve_sequence_window_is_identical_to_taatool(taatool_window, tmp_root):
    out = os.path.join(tmp_root, "module_window")
    shutil.rmtree(out, ignore_errors=True)
    reports = taa.resolve_sequence(
        os.path.join(SAMPLE_DIR, "beauty.####.exr"),
        depth=os.path.join(SAMPLE_DIR, "depth.####.exr"),
        motion=os.path.join(SAMPLE_DIR, "motion.####.exr"),
        output=os.path.join(out, "resolved.####.exr"), pixel_type="float",
        mode="window", window=K)
    assert [r["frame"] for r in reports] == list(FRAMES)
    for frame in FRAMES:
        np.testing.assert_array_equal(output_frame(out, frame),
                                      output_frame(taatool_window, frame))
    # The options reached the resolve: the history mode's frames are others.
    history = taa.resolve_sequence(
        os.path.join(SAMPLE_DIR, "beauty.####.exr"),
        depth=os.path.join(SAMPLE_DIR, "depth.####.exr"),
        motion=os.path.join(SAMPLE_DIR, "motion.####.exr"),
        output=os.path.join(out, "history.####.exr"), pixel_type="float", frames="1-12")
    assert len(history) == 12
    difference = np.abs(read_exr(os.path.join(out, "history.0012.exr"), ["R", "G", "B", "A"]) -
                        output_frame(out, 12))
    assert difference.max() > 1e-3


def test_resolve_sequence_window_chunk_matches_the_whole_run(taatool_window, tmp_root):
    """A chunk reads its windows' frames around it: the same frames as the whole run."""
    out = os.path.join(tmp_root, "module_window_chunk")
    shutil.rmtree(out, ignore_errors=True)
    taa.resolve_sequence(
        os.path.join(SAMPLE_DIR, "beauty.####.exr"),
        depth=os.path.join(SAMPLE_DIR, "depth.####.exr"),
        motion=os.path.join(SAMPLE_DIR, "motion.####.exr"),
        output=os.path.join(out, "resolved.####.exr"), pixel_type="float", frames="10-13",
        mode="window", window=K)
    for frame in range(10, 14):
        np.testing.assert_array_equal(output_frame(out, frame),
                                      output_frame(taatool_window, frame))


def push(node, frames, frame, **extra):
    color, depth, motion = frames[frame]
    return node.push(color, depth=depth, motion=motion, frame=frame, **extra)


def test_node_streams_frames_like_taatool(taatool_window, frames):
    """Frames in order, each resolved once its window is in; the ring of 2K+1 evicts the frame
    farthest behind as the sequence goes on."""
    node = taa.Node(mode="window", window=K)
    pending = list(FRAMES)
    for frame in FRAMES:
        assert push(node, frames, frame) is None
        # t's window is in once t + K is, or the last frame.
        while pending and (pending[0] + K <= frame or frame == FRAMES[-1]):
            t = pending.pop(0)
            out = node.resolve(t)
            assert out.shape == frames[t][0].shape and out.dtype == np.float32
            np.testing.assert_array_equal(out, output_frame(taatool_window, t))


def test_node_resolves_in_any_order(taatool_window, frames):
    """The window of 10 pushed shuffled, then, after dropping 7 and pushing 14, frame 11; the
    results do not depend on the order. Rows bottom first give the same frame flipped."""
    rng = random.Random(14)
    window = list(range(10 - K, 10 + K + 1))
    rng.shuffle(window)
    node = taa.Node(mode="window", window=K)
    for frame in window:
        push(node, frames, frame)
    np.testing.assert_array_equal(node.resolve(10), output_frame(taatool_window, 10))
    node.drop(10 - K)
    push(node, frames, 11 + K)
    np.testing.assert_array_equal(node.resolve(11), output_frame(taatool_window, 11))
    np.testing.assert_array_equal(node.resolve(11, y_up=True)[::-1],
                                  output_frame(taatool_window, 11))

    flipped = taa.Node(mode="window", window=K)
    for frame in window:
        color, depth, motion = frames[frame]
        flipped.push(color[::-1], depth=depth[::-1], motion=motion[::-1], frame=frame,
                     y_up=True)
    np.testing.assert_array_equal(flipped.resolve(10, y_up=True)[::-1],
                                  output_frame(taatool_window, 10))


def test_node_window_errors(frames):
    with pytest.raises(taa.Error, match=r'taa_node_resolve_frame needs parameter "mode" = '
                                        r'"window"'):
        taa.Node().resolve(1)
    with pytest.raises(taa.Error, match="option window expects"):
        taa.Node(mode="window", window=25)
    with pytest.raises(taa.Error, match="option mode expects"):
        taa.Node(mode="windows")

    node = taa.Node(mode="window", window=1)
    with pytest.raises(taa.Error, match=r"frame 5 has not been pushed \(the ring holds no "
                                        r"frames\)"):
        node.resolve(5)
    for frame in (1, 2, 3, 4):  # a ring of 3: pushing 4 evicts 1
        push(node, frames, frame)
    with pytest.raises(taa.Error, match=r"frame 1 of frame 2's window \(frames 1-3\) is not in "
                                        r"the ring: it was evicted when frame 4 was pushed"):
        node.resolve(2)
    node.drop(3)
    with pytest.raises(taa.Error, match=r"frame 3 is not in the ring: it was dropped"):
        node.resolve(3)
    # The node still works after errors: frame 4's window is 3-4 once 3 is back.
    push(node, frames, 3)
    assert node.resolve(4).shape == frames[4][0].shape


def test_frame_numbers_anywhere_in_the_int_range(frames):
    """Issue 25, defect 2: pushing and resolving frame 2**31 - 1 grew without bound (13.4 GB
    in 10 minutes). Both ends of the int range and random numbers between resolve from their
    windows, in both modes; numbers beyond the range are an error, not a wrapped frame."""
    rng = random.Random(25)
    starts = [2**31 - 3, -2**31] + [rng.randrange(-2**31, 2**31 - 2) for _ in range(4)]
    for start in starts:
        for mode in ("window", "history"):
            node = taa.Node(mode=mode, window=1)
            for i in range(3):
                color, depth, motion = frames[FRAMES[0] + i]
                node.push(color, depth=depth, motion=motion, frame=start + i)
            if mode == "window":
                for i in range(3):
                    assert np.isfinite(node.resolve(start + i)).all(), (start, i)
    with pytest.raises(TypeError):
        taa.Node(mode="window", window=1).push(frames[FRAMES[0]][0], frame=2**31)
