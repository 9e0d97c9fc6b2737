#!/usr/bin/python3
"""Runs taatool -v and reads its peak RSS (VmHWM) when frame 100, every 100th and the last are
written; deletes each output once the next is written, so a long soak needs no disk. For
scripts/soak.sh.

    soak_monitor.py --frames N --out DIR -- taatool -v ... -o DIR/r.####.exr
"""
import argparse
import os
import subprocess
import sys
import time


def status_kib(pid, field):
    """A 'VmXxx:   123 kB' line of /proc/PID/status, in KiB."""
    with open(f"/proc/{pid}/status") as status:
        for line in status:
            if line.startswith(field + ":"):
                return int(line.split()[1])
    raise RuntimeError(f"no {field} in /proc/{pid}/status")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--frames", type=int, required=True)
    parser.add_argument("--out", required=True)
    parser.add_argument("command", nargs=argparse.REMAINDER)
    args = parser.parse_args()
    command = args.command[1:] if args.command[:1] == ["--"] else args.command
    # Frame 100 and the last are the figures; every 100th between shows whether a difference
    # is a trend (a leak) or where one frame's transient peak happened to fall.
    checkpoints = sorted({min(100, args.frames), args.frames, *range(100, args.frames, 100)})
    start = time.monotonic()
    task = subprocess.Popen(command, stdout=subprocess.PIPE, text=True)
    peaks, written = {}, []
    for line in task.stdout:
        if not line.startswith("frame "):
            continue
        index = int(line.split("(")[1].split("/")[0])  # "frame 1001 (3/1000): ..."
        written.append(line.rsplit(" -> ", 1)[1].split(" [")[0].strip())
        while len(written) > 1:  # the newest stays: it may still be renamed into place
            os.remove(written.pop(0))
        if index in checkpoints:
            peaks[index] = (status_kib(task.pid, "VmHWM"), status_kib(task.pid, "VmRSS"),
                            time.monotonic() - start)
    if task.wait() != 0:
        sys.exit(f"soak: taatool failed with status {task.returncode}")
    for path in written:
        os.remove(path)
    for index in checkpoints:
        hwm, rss, seconds = peaks[index]
        print(f"soak: frame {index}: peak RSS {hwm / 1024:.0f} MiB (now {rss / 1024:.0f} MiB), "
              f"{seconds:.0f} s")
    first, last = peaks[checkpoints[0]][0], peaks[checkpoints[-1]][0]
    print(f"soak: peak RSS from frame {checkpoints[0]} to {checkpoints[-1]}: "
          f"{100.0 * (last - first) / first:+.1f} %")


if __name__ == "__main__":
    main()
