"""taa.check_output and taa.remove_stale_temporaries: the checks a Python step resuming a job
uses (taa-farm does the same in C++)."""
import os
import shutil
import subprocess

import OpenImageIO as oiio

import taa

from conftest import SAMPLE_DIR, TAATOOL, sample_args


def test_a_truncated_output_is_not_complete(tmp_root):
    folder = os.path.join(tmp_root, "check_output")
    shutil.rmtree(folder, ignore_errors=True)
    subprocess.run([TAATOOL, *sample_args(os.path.join(folder, "r.####.exr")), "--frames",
                    "3-4", "-q"], check=True)
    victim = os.path.join(folder, "r.0004.exr")
    assert taa.check_output(victim) == (True, "")
    os.truncate(victim, os.path.getsize(victim) // 2)
    assert oiio.ImageInput.open(victim)  # the header still opens
    complete, reason = taa.check_output(victim)
    assert not complete and "truncated or corrupt" in reason
    assert taa.check_output(os.path.join(folder, "r.0005.exr")) == (False, "missing")
    assert taa.check_output(os.path.join(SAMPLE_DIR, "beauty.0001.exr"))[0] is False  # not taa's


def dead_pid():
    child = subprocess.Popen(["true"])
    child.wait()
    return child.pid


def test_only_dead_writers_temporaries_are_removed(tmp_root):
    folder = os.path.join(tmp_root, "stale")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    host = taa.farm_scratch_prefix().split("-")[2]
    dead, live = dead_pid(), os.getpid()
    stale_dir = os.path.join(folder, f".taa-farm-{host}-{dead}-x1y2z3")
    os.makedirs(stale_dir)
    stale_file = os.path.join(folder, f".r.0004.exr.taa-tmp-{host}-{dead}-0.exr")
    live_file = os.path.join(folder, f".r.0005.exr.taa-tmp-{host}-{live}-0.exr")
    other_host = os.path.join(folder, f".r.0006.exr.taa-tmp-elsewhere-{dead}-0.exr")
    for path in (stale_file, live_file, other_host):
        open(path, "w").close()
    removed, failed = taa.remove_stale_temporaries(os.path.join(folder, "r.####.exr"))
    assert sorted(removed) == sorted([stale_dir, stale_file]) and failed == []
    assert os.path.exists(live_file) and os.path.exists(other_host)
