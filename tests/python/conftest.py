"""Shared fixtures: the bundled sample, taatool's float output on it, EXR reading."""
import os
import subprocess

import numpy as np
import OpenImageIO as oiio
import pytest

SAMPLE_DIR = os.environ.get("TAA_SAMPLE_DIR", "")
TAATOOL = os.environ.get("TAA_TAATOOL", "")
FRAMES = range(1, 25)


def read_exr(path, channels):
    """The named channels of an EXR as float32 (H, W, C), rows top first."""
    image = oiio.ImageInput.open(path)
    assert image, f"cannot open {path}: {oiio.geterror()}"
    spec = image.spec()
    pixels = image.read_image(0, 0, 0, spec.nchannels, "float")
    image.close()
    indices = [spec.channelnames.index(name) for name in channels]
    return np.ascontiguousarray(pixels[:, :, indices])


def sample_args(out_pattern):
    """taatool's arguments for the bundled sample's separate files."""
    return [os.path.join(SAMPLE_DIR, "beauty.####.exr"),
            "--depth", os.path.join(SAMPLE_DIR, "depth.####.exr"),
            "--motion", os.path.join(SAMPLE_DIR, "motion.####.exr"),
            "-d", "float", "-o", out_pattern]


@pytest.fixture(scope="session")
def tmp_root():
    root = os.environ.get("TAA_TEST_TMPDIR") or "/tmp/taa_python_tests"
    os.makedirs(root, exist_ok=True)
    return root


def run_taatool_on_sample(tmp_root, name, extra):
    if not os.path.exists(os.path.join(SAMPLE_DIR, "beauty.0001.exr")):
        pytest.fail(f"bundled sample missing in {SAMPLE_DIR!r} (build target taa_sample)")
    out = os.path.join(tmp_root, name)
    os.makedirs(out, exist_ok=True)
    subprocess.run([TAATOOL, *sample_args(os.path.join(out, "resolved.####.exr")), "-q", *extra],
                   check=True)
    return out


@pytest.fixture(scope="session")
def taatool_output(tmp_root):
    """Folder of taatool's float output on the whole bundled sample, at its defaults."""
    return run_taatool_on_sample(tmp_root, "taatool", [])


@pytest.fixture(scope="session")
def taatool_history_output(tmp_root):
    """The same in history mode: what a Node (history unless told) gives frame by frame."""
    return run_taatool_on_sample(tmp_root, "taatool-history", ["--mode", "history"])
