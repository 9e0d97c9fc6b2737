"""taa-farm under a real one-node Slurm cluster started on this machine (issue 16's acceptance
test): a 24-frame shot submitted in 4 chunks with `taa-farm submit`, in window mode (every frame
bit-identical to one taatool run: pixels and header, see same_frame) and history mode (within
the README's tolerance); a task killed with SIGKILL mid-frame and requeued with
`scontrol requeue` (the chunk completes with the same frames, no partial file); a task whose
input is missing (fails with exit status 3 and a clear message, the others finish). Skips,
saying why, only where the daemons cannot start.

Interpreter: Debian's /usr/bin/python3 with python3-pytest, python3-numpy, python3-openimageio.
"""
import filecmp
import os
import re
import shutil
import signal
import subprocess
import time

import numpy as np
import OpenImageIO as oiio
import pytest

from slurm_cluster import SlurmCluster, SlurmUnavailable, alive, wait_for

FARM = os.environ["TAA_FARM"]
TAATOOL = os.environ["TAA_TAATOOL"]
SAMPLE = os.environ["TAA_SAMPLE_DIR"]
TMP = os.environ["TAA_TEST_TMPDIR"]
FRAMES = range(1, 25)
CHUNK = 6  # 4 tasks
# README "Render farm": the largest display-value difference (Reinhard x/(1+x)) of history-mode
# chunks with the default pre-roll (128) to one run over the shot, on the slowest scene measured.
HISTORY_MAX_ABS = 0.00221

WRITTEN = re.compile(r"^PROGRESS: \d+% frame (\d+) written: ", re.M)


@pytest.fixture(scope="module")
def cluster():
    try:
        started = SlurmCluster().__enter__()
    except SlurmUnavailable as why:
        pytest.skip(f"Slurm daemons cannot start on this machine: {why}")
    yield started
    started.stop()


def shot_args(folder, sample=SAMPLE):
    return [os.path.join(sample, "beauty.####.exr"),
            "--depth", os.path.join(sample, "depth.####.exr"),
            "--motion", os.path.join(sample, "motion.####.exr"),
            "--frames", "1-24", "-o", os.path.join(folder, "r.####.exr")]


def history_args(folder, sample=SAMPLE):
    """The shot in history mode (the pre-roll and requeue tests are about it)."""
    return [*shot_args(folder, sample), "--mode", "history"]


def frame_path(folder, frame):
    return os.path.join(folder, f"r.{frame:04d}.exr")


@pytest.fixture(scope="module")
def work():
    folder = os.path.join(TMP, "slurm")
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    return folder


@pytest.fixture(scope="module")
def reference(work):
    """taatool's whole-shot output, per mode: what the farm must reproduce."""
    folders = {}
    for mode in ("history", "window"):
        folders[mode] = os.path.join(work, "taatool-" + mode)
        subprocess.run([TAATOOL, *shot_args(folders[mode]), "--mode", mode, "-q"], check=True)
    return folders


def submit(cluster, name, args):
    """`taa-farm submit --chunk 6` in folder `name`; returns (job id, output folder, log folder)."""
    out = os.path.join(TMP, "slurm", name)
    logs = out + "-logs"
    result = subprocess.run([FARM, "submit", "--chunk", str(CHUNK), "--log-dir", logs,
                             "--job-name", name, *args(out)], capture_output=True, text=True,
                            env=cluster.env)
    assert result.returncode == 0, result.stderr
    job = result.stdout.strip()
    assert re.fullmatch(r"\d+", job), result.stdout
    return job, out, logs


def task_states(cluster, job):
    """{task: (state, exit code)} from scontrol (MinJobAge keeps finished tasks listed)."""
    shown = subprocess.run(["scontrol", "-o", "show", "job", job], capture_output=True,
                           text=True, env=cluster.env).stdout
    states = {}
    for line in shown.splitlines():
        fields = dict(f.split("=", 1) for f in line.split() if "=" in f)
        if "ArrayTaskId" in fields and fields["ArrayTaskId"].isdigit():
            states[int(fields["ArrayTaskId"])] = (fields["JobState"], fields["ExitCode"])
    return states


def wait_until_done(cluster, job, timeout=240):
    def finished():
        states = task_states(cluster, job)
        return len(states) == 4 and all(s not in ("PENDING", "RUNNING", "CONFIGURING",
                                                  "COMPLETING", "REQUEUED")
                                        for s, _ in states.values())
    wait_for(finished, timeout, f"job {job}\n" + cluster.log_tail("slurmctld.log"))
    return task_states(cluster, job)


def log_of(logs, job, task):
    path = os.path.join(logs, f"taa-farm-{job}_{task}.log")
    with open(path, errors="replace") as log:
        return log.read()


def written_frames(logs, job):
    """Every frame some run of some task reported written, with repeats. (A run killed between
    a frame's rename and its PROGRESS line wrote a frame it does not report.)"""
    frames = []
    for task in range(4):
        frames += [int(f) for f in WRITTEN.findall(log_of(logs, job, task))]
    return sorted(frames)


def same_frame(a, b):
    """Whether two EXRs hold the same frame: every part's channels, pixel types, windows and
    pixels bit for bit, and every header attribute but DateTime, which OpenImageIO's EXR writer
    sets to the time of writing when the input has none (taa copies the input's when it has
    one; the bundled sample's frames have one, so here the files are byte-identical too)."""
    if filecmp.cmp(a, b, shallow=False):
        return True
    parts = []
    for path in (a, b):
        image = oiio.ImageInput.open(path)
        assert image, oiio.geterror()
        frames = []
        for part in range(image.spec().get_int_attribute("oiio:subimages", 1)):
            image.seek_subimage(part, 0)
            spec = image.spec()
            header = sorted((p.name, str(p.value)) for p in spec.extra_attribs
                            if p.name != "DateTime")
            pixels = image.read_image(part, 0, 0, spec.nchannels, "float")
            frames.append((list(spec.channelnames), [str(f) for f in spec.channelformats],
                           (spec.x, spec.y, spec.width, spec.height, spec.full_x, spec.full_y,
                            spec.full_width, spec.full_height), header, pixels.tobytes()))
        image.close()
        parts.append(frames)
    return parts[0] == parts[1]


def display_difference(a, b):
    """Largest absolute difference of the Reinhard-tonemapped RGB of two EXRs."""
    def tonemapped(path):
        image = oiio.ImageInput.open(path)
        rgb = np.maximum(image.read_image(0, 0, 0, 3, "float"), 0)
        image.close()
        return rgb / (1 + rgb)
    return float(np.abs(tonemapped(a) - tonemapped(b)).max())


def test_window_mode_chunks_are_bit_identical_to_one_taatool_run(cluster, reference):
    job, out, logs = submit(cluster, "window", lambda out: [*shot_args(out), "--mode", "window"])
    states = wait_until_done(cluster, job)
    assert states == {t: ("COMPLETED", "0:0") for t in range(4)}, states
    assert written_frames(logs, job) == list(FRAMES)  # each frame once, by one task
    for frame in FRAMES:
        assert same_frame(frame_path(out, frame), frame_path(reference["window"], frame)), \
            f"frame {frame} differs from taatool's"
    status = subprocess.run([FARM, "status", *shot_args(out), "--mode", "window"],
                            capture_output=True, text=True)
    assert status.returncode == 0, status.stdout
    assert "24 of 24 frames complete" in status.stdout


@pytest.fixture(scope="module")
def history_job(cluster, reference):
    job, out, logs = submit(cluster, "history", history_args)
    states = wait_until_done(cluster, job)
    assert states == {t: ("COMPLETED", "0:0") for t in range(4)}, states
    return out


def test_history_mode_chunks_are_within_the_stated_tolerance(history_job, reference):
    worst = max(display_difference(frame_path(history_job, f),
                                   frame_path(reference["history"], f)) for f in FRAMES)
    assert worst <= HISTORY_MAX_ABS, worst
    # On a shot shorter than the pre-roll every chunk's history starts at the shot's first
    # frame: the frames are taatool's, bit for bit.
    for frame in FRAMES:
        assert same_frame(frame_path(history_job, frame),
                          frame_path(reference["history"], frame)), frame


def find_task_process(job, task):
    """The pid of taa-farm running task `task` of array job `job` (the batch script execs it)."""
    farm = os.path.realpath(FARM)
    for entry in os.listdir("/proc"):
        if not entry.isdigit():
            continue
        try:
            if os.path.realpath(f"/proc/{entry}/exe") != farm:
                continue
            with open(f"/proc/{entry}/environ", "rb") as environ:
                env = dict(v.split(b"=", 1) for v in environ.read().split(b"\0") if b"=" in v)
        except OSError:
            continue
        if (env.get(b"SLURM_ARRAY_JOB_ID") == job.encode()
                and env.get(b"SLURM_ARRAY_TASK_ID") == str(task).encode()):
            return int(entry)
    return None


TEMPORARY_WRITER = re.compile(r"\.taa-tmp-.*-(\d+)-[0-9a-f]+\.exr$")


def writer_alive(name):
    """Whether the process named in a temporary's name (its writer, on this host) still runs."""
    match = TEMPORARY_WRITER.search(name)
    return bool(match) and alive(int(match.group(1)))


def temporaries(folder):
    """Hidden files in `folder`: taa's temporaries (".<frame>.taa-tmp-<host>-<pid>-<random>.exr")."""
    try:
        return [name for name in os.listdir(folder) if name.startswith(".")]
    except FileNotFoundError:
        return []


def kill_task_1_mid_chunk(cluster, name):
    """Submits the history shot and SIGKILLs task 1 (frames 7-12, history from 1) once it has
    written frame 7 and is writing a later one (a temporary of 8-12 is there), else once it has
    written 10. Returns (job, out, logs, its log so far), or None when the task finished first
    (then the job is cancelled)."""
    job, out, logs = submit(cluster, name, history_args)
    log1 = os.path.join(logs, f"taa-farm-{job}_1.log")
    wait_for(lambda: os.path.exists(log1), 120, "task 1 to start", interval=0.01)
    pid = None
    def found():
        nonlocal pid
        pid = find_task_process(job, 1)
        return pid is not None or "frame 12 written" in log_of(logs, job, 1)
    wait_for(found, 60, "task 1's taa-farm process", interval=0.01)
    later = tuple(f".r.{f:04d}.exr" for f in range(8, 13))
    def writing_after_7():
        log = log_of(logs, job, 1)
        return ("frame 10 written" in log or not alive(pid or 0) or
                ("frame 7 written" in log and any(n.startswith(later) for n in temporaries(out))))
    wait_for(writing_after_7, 120, "task 1 to write frames after 7", interval=0.001)
    killed = pid is not None and alive(pid)
    if killed:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:  # it ended between the check and the kill: try again
            killed = False
        else:
            wait_for(lambda: not alive(pid), 10, "the killed task to go")
    killed_log = log_of(logs, job, 1)
    if not killed or "frame 12 written" in killed_log:
        subprocess.run(["scancel", job], env=cluster.env)
        return None
    return job, out, logs, killed_log


def test_a_task_killed_mid_frame_and_requeued_completes_its_chunk(cluster, history_job):
    for attempt in range(3):  # the kill must land inside task 1's writes
        killed = kill_task_1_mid_chunk(cluster, f"killed{attempt}")
        if killed:
            break
    assert killed, "task 1 finished before it could be killed, three times"
    job, out, logs, killed_log = killed
    # The killed task's temporaries: those whose writer is gone (checked after listing, and
    # still there after the check). Another task still running has its own in flight, which
    # it renames into place itself.
    left = [name for name in temporaries(out)
            if not writer_alive(name) and os.path.exists(os.path.join(out, name))]
    print(f"task 1 killed after writing {WRITTEN.findall(killed_log)}, leaving {left}")
    wait_for(lambda: task_states(cluster, job).get(1, ("",))[0] == "FAILED", 30,
             "task 1 to be FAILED")
    # Nothing partial at a final path: every frame there reads whole.
    status = subprocess.run([FARM, "status", *history_args(out)], capture_output=True, text=True)
    assert "incomplete" not in status.stdout, status.stdout

    subprocess.run(["scontrol", "requeue", f"{job}_1"], check=True, env=cluster.env)
    # Slurm holds a requeued job back (its EligibleTime is minutes away): let it start now.
    def released():
        update = subprocess.run(["scontrol", "update", f"JobId={job}_1", "StartTime=now"],
                                capture_output=True, env=cluster.env)
        return update.returncode == 0
    wait_for(released, 30, "the requeued task to accept a start time")
    states = wait_until_done(cluster, job)
    assert states == {t: ("COMPLETED", "0:0") for t in range(4)}, states

    rerun = log_of(logs, job, 1)[len(killed_log):]
    for frame in WRITTEN.findall(killed_log):
        assert f"frame {frame} complete, skipped" in rerun, rerun
    # The killed run's temporaries (writes in flight): removed by the next task that started
    # on this host, their writer's pid being gone.
    all_logs = "".join(log_of(logs, job, task) for task in range(4))
    for name in left:
        assert f"removed a dead run's temporary {os.path.join(out, name)}" in all_logs, all_logs
    written = written_frames(logs, job)
    assert len(written) == len(set(written)), written  # no frame written twice
    assert set(written) >= set(FRAMES) - {7, 8, 9, 10, 11, 12}, written
    assert not temporaries(out), os.listdir(out)
    for frame in FRAMES:  # the same frames as the history job nobody killed
        assert same_frame(frame_path(out, frame), frame_path(history_job, frame)), f"frame {frame}"


def test_a_task_missing_an_input_fails_alone(cluster, work):
    sample = os.path.join(work, "missing-input")
    os.makedirs(sample)
    for name in os.listdir(SAMPLE):
        os.symlink(os.path.join(SAMPLE, name), os.path.join(sample, name))
    os.remove(os.path.join(sample, "motion.0022.exr"))
    job, out, logs = submit(cluster, "missing", lambda out: history_args(out, sample))
    states = wait_until_done(cluster, job)
    assert states[3] == ("FAILED", "3:0"), states
    assert all(states[t] == ("COMPLETED", "0:0") for t in range(3)), states
    assert ("taa-farm ERROR: input frame not ready (missing), needed by task 3 : "
            f"{sample}/motion.0022.exr (frame 22, channel motion)") in log_of(logs, job, 3)
    assert sorted(os.listdir(out)) == [f"r.{f:04d}.exr" for f in range(1, 19)]


def test_submitting_from_a_folder_with_a_space_or_a_line_break(cluster, reference):
    """Issue 25, defects 1 and 5: the working folder went raw into "#SBATCH --chdir=": a line
    break followed by a command put that command into the batch script (every task ran it), a
    space made sbatch refuse the job. Submitted from such folders, with a job name sbatch's
    own parser would split or cut ('#', quotes, "hetjob"), the job runs nothing else, keeps
    its name and gives taatool's frames."""
    marker = os.path.join(TMP, "slurm", "INJECTED")
    env = dict(cluster.env, TAA_TEST_INJECTED=marker)
    for folder_name in ("My Show", 'evil\ntouch "$TAA_TEST_INJECTED"\n'):
        folder = os.path.join(TMP, "slurm", folder_name)
        shutil.rmtree(folder, ignore_errors=True)
        os.makedirs(folder)
        out = os.path.join(folder, "out")
        name = 'it\'s "my" #1 hetjob'
        # The script as written: bash finds no syntax error, sbatch's own parser takes it.
        dry = subprocess.run([FARM, "submit", "--chunk", str(CHUNK), "--job-name", name,
                              "--dry-run", *shot_args(out), "--mode", "window"],
                             capture_output=True, text=True, env=env, cwd=folder)
        assert dry.returncode == 0, dry.stderr
        assert subprocess.run(["bash", "-n"], input=dry.stdout, text=True).returncode == 0
        test_only = subprocess.run(["sbatch", "--test-only"], input=dry.stdout, text=True,
                                   capture_output=True, env=env, cwd=folder)
        assert test_only.returncode == 0, test_only.stderr
        result = subprocess.run([FARM, "submit", "--chunk", str(CHUNK), "--job-name", name,
                                 *shot_args(out), "--mode", "window"],
                                capture_output=True, text=True, env=env, cwd=folder)
        assert result.returncode == 0, result.stderr
        job = result.stdout.strip()
        shown = subprocess.run(["scontrol", "show", "job", job], capture_output=True,
                               text=True, env=cluster.env).stdout
        assert f"JobName={name}\n" in shown, shown
        states = wait_until_done(cluster, job)
        assert states == {t: ("COMPLETED", "0:0") for t in range(4)}, (folder_name, states)
        for frame in FRAMES:
            assert same_frame(frame_path(out, frame), frame_path(reference["window"], frame))
        # The logs' default place is the folder submit ran in.
        assert os.path.exists(os.path.join(folder, f"taa-farm-{job}_0.log")), os.listdir(folder)
        assert not os.path.exists(marker), f"the folder's name ran a command ({folder_name!r})"
