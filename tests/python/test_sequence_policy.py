"""taa.resolve_sequence under issue 17's policy: gaps, strict, warnings with counts, Ctrl-C."""
import os
import shutil
import subprocess
import sys
import textwrap
import warnings

import pytest

import taa
from conftest import SAMPLE_DIR


@pytest.fixture()
def gapped(tmp_root, request):
    """Frames 1-6 of the bundled sample with frame 4 missing."""
    folder = os.path.join(tmp_root, "policy_" + request.node.name)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    for frame in (1, 2, 3, 5, 6):
        for stem in ("beauty", "depth", "motion"):
            name = f"{stem}.{frame:04d}.exr"
            os.symlink(os.path.join(SAMPLE_DIR, name), os.path.join(folder, name))
    return folder


def resolve(folder, **kwargs):
    return taa.resolve_sequence(os.path.join(folder, "beauty.####.exr"),
                                depth=os.path.join(folder, "depth.####.exr"),
                                motion=os.path.join(folder, "motion.####.exr"),
                                output=os.path.join(folder, "out", "r.####.exr"), **kwargs)


def test_a_gap_is_an_error_a_warning_with_skip_missing_and_an_error_when_strict(gapped):
    with pytest.raises(taa.Error, match=r"1 frame missing from the sequence 1-6: 4 .*beauty\.0004"):
        resolve(gapped)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        reports = resolve(gapped, skip_missing=True)
    assert [r["frame"] for r in reports] == [1, 2, 3, 5, 6]
    assert [r["history_reset"] for r in reports] == [True, False, False, True, False]
    messages = [str(w.message) for w in caught if issubclass(w.category, RuntimeWarning)]
    # The generated frames have no camera: window mode says what that costs (issue 24).
    assert messages[0] == "skipped 1 missing frame (4): history restarts after each gap"
    assert len(messages) == 2 and messages[1].startswith("no camera matrices (header, camera "
                                                         "note or --camera-sidecar) in 5 frames")
    with pytest.raises(taa.Error, match=r"--strict: not skipped"):
        resolve(gapped, skip_missing=True, strict=True)


def test_ctrl_c_stops_between_frames_leaving_complete_frames_only(tmp_root):
    """KeyboardInterrupt reaches the caller once the frames in flight are written."""
    folder = os.path.join(tmp_root, "ctrl_c")
    shutil.rmtree(folder, ignore_errors=True)
    script = textwrap.dedent(f"""
        import os, signal, taa
        def progress(report):
            if report["frame"] == 2:
                os.kill(os.getpid(), signal.SIGINT)
        try:
            taa.resolve_sequence({os.path.join(SAMPLE_DIR, "beauty.####.exr")!r},
                                 output={os.path.join(folder, "r.####.exr")!r},
                                 progress=progress, threads=2)
        except KeyboardInterrupt:
            names = sorted(os.listdir({folder!r}))
            print("stopped", names)
            for name in names:
                assert taa.check_output(os.path.join({folder!r}, name))[0], name
    """)
    result = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                            timeout=300)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("stopped ['r.0001.exr', 'r.0002.exr'"), result.stdout
    assert ".taa" not in result.stdout
    assert "'r.0024.exr'" not in result.stdout
