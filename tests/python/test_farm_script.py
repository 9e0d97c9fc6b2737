"""samples/farm/taa_farm_post.py: chunked, resumable, progress lines, output as taatool's."""
import os
import shutil
import signal
import subprocess
import sys

import numpy as np
import OpenImageIO as oiio

import taa

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


def test_a_truncated_output_is_redone(tmp_root):
    """Defect 7: a frame cut short after it was written opened, so it counted as complete."""
    shutil.rmtree(os.path.join(tmp_root, "farm_truncated"), ignore_errors=True)
    out = os.path.join(tmp_root, "farm_truncated", "resolved.####.exr")
    assert run_chunk(out, "3-5", 2).returncode == 0
    victim = out.replace("####", "0004")
    os.truncate(victim, os.path.getsize(victim) // 2)
    assert oiio.ImageInput.open(victim)  # what the script used to check
    assert taa.check_output(victim)[0] is False
    again = run_chunk(out, "3-5", 2)
    assert again.returncode == 0, again.stderr
    assert "wrote 1 frame(s), skipped 2 complete" in again.stdout
    assert taa.check_output(victim) == (True, "")


def dead_pid():
    child = subprocess.Popen(["true"])
    child.wait()
    return child.pid


def test_a_dead_tasks_temporaries_are_removed(tmp_root):
    """Defect 8: scratch folders and temporaries of killed tasks stayed forever."""
    folder = os.path.join(tmp_root, "farm_stale")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    host = taa.farm_scratch_prefix().split("-")[2]
    dead, live = dead_pid(), os.getpid()
    stale_dir = os.path.join(folder, f".taa-farm-{host}-{dead}-x1y2z3")
    os.makedirs(stale_dir)
    open(os.path.join(stale_dir, "resolved.0003.exr"), "w").close()
    stale_file = os.path.join(folder, f".resolved.0004.exr.taa-tmp-{host}-{dead}-0.exr")
    live_dir = os.path.join(folder, f".taa-farm-{host}-{live}-a1b2c3")
    open(stale_file, "w").close()
    os.makedirs(live_dir)
    result = run_chunk(os.path.join(folder, "resolved.####.exr"), "3-4", 1)
    assert result.returncode == 0, result.stderr
    assert not os.path.exists(stale_dir) and not os.path.exists(stale_file)
    assert f"removed a dead task's temporary {stale_dir}" in result.stdout
    assert os.path.isdir(live_dir)  # this process still runs


def test_sigterm_stops_between_frames_and_removes_the_scratch_folder(tmp_root):
    folder = os.path.join(tmp_root, "farm_sigterm")
    shutil.rmtree(folder, ignore_errors=True)
    args = [sys.executable, SCRIPT, os.path.join(SAMPLE_DIR, "beauty.####.exr"),
            "--depth", os.path.join(SAMPLE_DIR, "depth.####.exr"),
            "--motion", os.path.join(SAMPLE_DIR, "motion.####.exr"),
            "-o", os.path.join(folder, "resolved.####.exr"), "--shot", "1-24", "--chunk", "1-24",
            "--option", "threads=0"]
    task = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert task.stdout.readline().startswith("PROGRESS: ")  # resolving: the scratch folder exists
    task.send_signal(signal.SIGTERM)
    _out, err = task.communicate(timeout=120)
    assert task.returncode == 143, err
    assert "interrupted by SIGTERM" in err
    assert not [n for n in os.listdir(folder) if n.startswith(".taa")]
