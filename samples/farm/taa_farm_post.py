#!/usr/bin/python3
"""Farm post-step: resolve one chunk of a shot with taa, resumably.

    taa_farm_post.py beauty.####.exr --depth depth.####.exr --motion motion.####.exr \\
        -o resolved.####.exr --shot 1001-1100 --chunk 1041-1060 [--preroll 16] \\
        [--option blend=0.1 --option preset=cycles ...]

- Frames of the chunk whose output is complete are skipped, so a re-queued task only does what
  is missing. Complete means the whole file reads, every pixel, and carries taa's metadata
  (taa.check_output): a file cut short after it was written still opens.
- History needs earlier frames: up to --preroll frames before the first missing one (never
  before the shot's first frame) are resolved as read-only pre-roll; their results are thrown
  away. With a pre-roll reaching the shot start, output is identical to one run over the shot;
  otherwise it converges to it within a few frames (history mode).
- Outputs are resolved into a scratch folder beside the output (".taa-farm-HOST-PID-*") and
  renamed into place, so a killed task never leaves a partial frame. SIGTERM and SIGINT stop it
  between frames and remove the scratch folder; after SIGKILL, the next task over the same
  output removes what is left (taa.remove_stale_temporaries).
- One line per resolved frame on stdout: "PROGRESS: NN%" (of the frames this task resolves,
  pre-roll included).
- Exit status: 0 done, 1 taa failed (its message on stderr), 2 bad arguments, 128 + N when
  signal N (SIGINT, SIGTERM) stopped it.
"""
import argparse
import os
import re
import shutil
import signal
import sys
import tempfile

import taa


class Stop(BaseException):
    """Raised by the SIGTERM/SIGINT handler: unwinds through `finally`, unlike the default."""

    def __init__(self, signum):
        super().__init__(signum)
        self.signum = signum


def stop_on(signum, _frame):
    raise Stop(signum)


def frame_range(text):
    match = re.fullmatch(r"\s*(-?\d+)\s*-\s*(-?\d+)\s*", text)
    if not match or int(match.group(1)) > int(match.group(2)):
        raise argparse.ArgumentTypeError(f"expected FIRST-LAST, got {text!r}")
    return int(match.group(1)), int(match.group(2))


def expand(pattern, frame):
    """The file name of `frame` for taatool's placeholders (#, ####, @@@@, %04d)."""
    pattern = re.sub(r"%0?(\d*)d", lambda m: str(frame).zfill(int(m.group(1) or 1)), pattern)
    pattern = re.sub(r"#+|@+", lambda m: str(frame).zfill(4 if m.group(0) == "#"
                                                          else len(m.group(0))), pattern)
    return pattern


def is_complete(path):
    """Reads the whole file: a frame cut short after its rename still opens."""
    complete, _reason = taa.check_output(path)
    return complete


def parse_options(items):
    options = {}
    for item in items:
        key, sep, value = item.partition("=")
        if not sep:
            raise argparse.ArgumentTypeError(f"--option expects KEY=VALUE, got {item!r}")
        options[key.replace("-", "_")] = value
    return options


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("color")
    parser.add_argument("-o", "--output", required=True)
    parser.add_argument("--depth")
    parser.add_argument("--motion")
    parser.add_argument("--shot", type=frame_range, required=True, help="FIRST-LAST of the shot")
    parser.add_argument("--chunk", type=frame_range, required=True, help="this task's frames")
    parser.add_argument("--preroll", type=int, default=16)
    parser.add_argument("--option", action="append", default=[],
                        help="any taatool option as KEY=VALUE (blend=0.1, preset=cycles, ...)")
    try:
        args = parser.parse_args(argv)
        options = parse_options(args.option)
    except argparse.ArgumentTypeError as error:
        print(f"taa_farm_post: {error}", file=sys.stderr)
        return 2
    (shot_first, shot_last), (first, last) = args.shot, args.chunk
    if first < shot_first or last > shot_last or args.preroll < 0:
        print("taa_farm_post: --chunk must lie inside --shot and --preroll be >= 0",
              file=sys.stderr)
        return 2

    signal.signal(signal.SIGTERM, stop_on)
    signal.signal(signal.SIGINT, stop_on)
    out_dir = os.path.dirname(os.path.abspath(args.output))
    removed, failed = taa.remove_stale_temporaries(os.path.abspath(args.output))
    for path in removed:
        print(f"taa_farm_post: removed a dead task's temporary {path}")
    for reason in failed:
        print(f"taa_farm_post: cannot remove a dead task's temporary {reason}", file=sys.stderr)
    missing = [f for f in range(first, last + 1) if not is_complete(expand(args.output, f))]
    if not missing:
        print(f"taa_farm_post: frames {first}-{last} already complete")
        print("PROGRESS: 100%", flush=True)
        return 0
    start = max(shot_first, missing[0] - args.preroll)
    frames = list(range(start, last + 1))
    os.makedirs(out_dir, exist_ok=True)
    scratch = tempfile.mkdtemp(prefix=taa.farm_scratch_prefix(), dir=out_dir)
    scratch_pattern = os.path.join(scratch, os.path.basename(args.output))

    def progress(report):
        percent = 100 * (report["index"] + 1) // report["count"]
        print(f"PROGRESS: {percent}%", flush=True)

    try:
        taa.resolve_sequence(args.color, output=scratch_pattern, frames=frames, depth=args.depth,
                             motion=args.motion, progress=progress, **options)
        for frame in missing:
            os.replace(expand(scratch_pattern, frame), expand(args.output, frame))
    except taa.Error as error:
        print(f"taa_farm_post ERROR: {error}", file=sys.stderr)
        return 1
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    skipped = (last - first + 1) - len(missing)
    print(f"taa_farm_post: wrote {len(missing)} frame(s), skipped {skipped} complete, "
          f"pre-roll from {start}")
    return 0


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except Stop as stop:
        print(f"taa_farm_post ERROR: interrupted by {signal.Signals(stop.signum).name}; frames "
              "moved into place are complete", file=sys.stderr)
        sys.exit(128 + stop.signum)
