"""Path names through the Python face (issue 25): folders and files named with spaces, quotes,
$(...), backticks, line breaks and bytes that are not UTF-8, given as str (surrogate-escaped, as
os.listdir returns them), bytes or pathlib.Path, are read and written under exactly those names;
reports give them back as os.fsdecode would; an error naming such a file is a taa.Error."""
import os
import pathlib
import random
import shutil

import pytest

import taa
from conftest import SAMPLE_DIR

NASTY = " '\"\\$`;&|<>(){}*?~!\t\n\r-"


def random_name(rng):
    parts = [rng.choice(NASTY) if rng.random() < 0.5 else chr(rng.randrange(33, 127))
             for _ in range(rng.randrange(1, 10))]
    name = "n" + "".join(parts).replace("/", "_").replace("#", "_").replace("@", "_")
    return os.fsdecode(name.replace("%", "_").encode() + bytes([0xff, 0xc3]))  # not UTF-8


def copy_sample(folder, frames=range(1, 4)):
    os.makedirs(folder)
    for stem in ("beauty", "depth", "motion"):
        for frame in frames:
            shutil.copy(os.path.join(SAMPLE_DIR, f"{stem}.{frame:04d}.exr"),
                        os.path.join(folder, f"{stem}.{frame:04d}.exr"))


@pytest.mark.parametrize("kind", ["str", "bytes", "path"])
def test_any_name_is_read_and_written_as_it_is(tmp_root, kind):
    rng = random.Random(kind)
    root = os.path.join(tmp_root, "path_names_" + kind)
    shutil.rmtree(os.fsencode(root), ignore_errors=True)
    folder = os.path.join(root, random_name(rng))
    copy_sample(folder)
    out = os.path.join(root, random_name(rng), random_name(rng) + ".####.exr")
    as_kind = {"str": str, "bytes": os.fsencode, "path": pathlib.Path}[kind]
    reports = taa.resolve_sequence(as_kind(os.path.join(folder, "beauty.####.exr")),
                                   depth=as_kind(os.path.join(folder, "depth.####.exr")),
                                   motion=as_kind(os.path.join(folder, "motion.####.exr")),
                                   output=as_kind(out), frames="1-3")
    written = [out.replace("####", f"{frame:04d}") for frame in range(1, 4)]
    assert [r["output"] for r in reports] == written
    for path in written:
        assert os.path.isfile(path), repr(path)


def test_an_error_naming_such_a_file_is_a_taa_error(tmp_root):
    folder = os.path.join(tmp_root, "path_names_missing", random_name(random.Random(3)))
    shutil.rmtree(os.fsencode(os.path.dirname(folder)), ignore_errors=True)
    copy_sample(folder, frames=(1, 3))
    with pytest.raises(taa.Error, match=r"\\xff\\xc3"):
        taa.resolve_sequence(os.path.join(folder, "beauty.####.exr"),
                             depth=os.path.join(folder, "depth.####.exr"),
                             motion=os.path.join(folder, "motion.####.exr"),
                             output=os.path.join(folder, "out.####.exr"), frames="1-3")
