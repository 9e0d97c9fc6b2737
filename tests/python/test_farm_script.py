"""samples/farm/taa_farm_post.py: chunked, resumable, progress lines, output as taatool's."""
import os
import shutil
import subprocess
import sys

import numpy as np

from conftest import SAMPLE_DIR, read_exr

SCRIPT = os.path.join(os.path.dirname(__file__), "..", "..", "samples", "farm",
                      "taa_farm_post.py")


def run_chunk(out_pattern, chunk, preroll):
    args = [sys.executable, SCRIPT, os.path.join(SAMPLE_DIR, "beauty.####.exr"),
            "--depth", os.path.join(SAMPLE_DIR, "depth.####.exr"),
            "--motion", os.path.join(SAMPLE_DIR, "motion.####.exr"),
            "-o", out_pattern, "--shot", "1-24", "--chunk", chunk, "--preroll", str(preroll),
            "--option", "pixel_type=float"]
    return subprocess.run(args, capture_output=True, text=True, env=os.environ.copy())


def test_chunks_with_full_preroll_equal_one_taatool_run(taatool_output, tmp_root):
    shutil.rmtree(os.path.join(tmp_root, "farm"), ignore_errors=True)
    out = os.path.join(tmp_root, "farm", "resolved.####.exr")
    first = run_chunk(out, "1-12", 24)
    second = run_chunk(out, "13-24", 24)
    assert first.returncode == 0 and second.returncode == 0, first.stderr + second.stderr
    progress = [line for line in second.stdout.splitlines() if line.startswith("PROGRESS: ")]
    assert len(progress) == 24 and progress[-1] == "PROGRESS: 100%"
    for frame in (1, 12, 13, 24):
        name = f"resolved.{frame:04d}.exr"
        ours = read_exr(os.path.join(tmp_root, "farm", name), ["R", "G", "B", "A"])
        theirs = read_exr(os.path.join(taatool_output, name), ["R", "G", "B", "A"])
        np.testing.assert_array_equal(ours, theirs)
    assert not [n for n in os.listdir(os.path.join(tmp_root, "farm")) if n.startswith(".taa")]


def test_complete_frames_are_skipped(tmp_root):
    shutil.rmtree(os.path.join(tmp_root, "farm_resume"), ignore_errors=True)
    out = os.path.join(tmp_root, "farm_resume", "resolved.####.exr")
    assert run_chunk(out, "3-5", 2).returncode == 0
    os.remove(out.replace("####", "0004"))
    before = os.path.getmtime(out.replace("####", "0005"))
    again = run_chunk(out, "3-5", 2)
    assert again.returncode == 0, again.stderr
    assert "wrote 1 frame(s), skipped 2 complete, pre-roll from 2" in again.stdout
    assert os.path.exists(out.replace("####", "0004"))
    assert os.path.getmtime(out.replace("####", "0005")) == before
    done = run_chunk(out, "3-5", 2)
    assert "already complete" in done.stdout and "PROGRESS: 100%" in done.stdout


def test_failure_exits_1_with_the_library_message(tmp_root):
    result = run_chunk(os.path.join(tmp_root, "farm_bad", "r.####.exr"), "20-24", 0)
    assert result.returncode == 0
    bad = subprocess.run([sys.executable, SCRIPT, "/nonexistent/b.####.exr", "-o",
                          os.path.join(tmp_root, "farm_bad", "x.####.exr"), "--shot", "1-3",
                          "--chunk", "1-3"], capture_output=True, text=True)
    assert bad.returncode == 1
    assert "missing input frame : /nonexistent/b.0001.exr" in bad.stderr
