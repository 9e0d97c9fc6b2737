"""Python and the C ABI at parity with taatool (issue 24): every option by the registry's name,
presets and the camera sidecar on a Node, docstrings that name exactly what the code takes."""
import json
import os
import re
import subprocess

import numpy as np
import OpenImageIO as oiio
import pytest

import taa
from conftest import SAMPLE_DIR, TAATOOL, read_exr

FRAMES = range(1, 7)


def registry():
    """taatool --list-options: (name, default) of every resolve option."""
    table = subprocess.run([TAATOOL, "--list-options"], check=True, capture_output=True,
                           text=True).stdout
    rows = re.findall(r"^\| `--([a-z-]+)` \| [^|]*(?:\\\|[^|]*)* \| ([^|]*) \|", table, re.M)
    assert len(rows) > 30, table
    return [(name, "" if default == "(empty)" else default) for name, default in rows]


def documented(doc):
    """The keywords a docstring lists, as "  keyword=..." lines."""
    return re.findall(r"^  ([a-z_]+)=", doc, re.M)


def test_docstrings_name_every_registry_option():
    for name, _ in registry():
        keyword = name.replace("-", "_")
        assert keyword in documented(taa.Node.__doc__), name
        assert keyword in documented(taa.resolve_sequence.__doc__), name


def test_every_keyword_the_node_documents_is_taken():
    for line in re.findall(r"^  ([a-z_]+=.*\(default [^)]*\))", taa.Node.__doc__, re.M):
        keyword, default = re.match(r"([a-z_]+)=.*\(default ([^)]*)\)", line).groups()
        value = "" if default == '""' else default
        if keyword == "depth_fov":
            continue  # no default value to set: taken below with one
        if re.fullmatch(r"-?[0-9.]+(e[-+]?[0-9]+)?", value):  # a number: the typed setters
            value = float(value) if re.search(r"[.e]", value) else int(value)
        taa.Node(**{keyword: value})
    taa.Node(depth_fov=40.0, preset="", camera_sidecar="")
    with pytest.raises(taa.Error, match=r'unknown parameter "clip"'):
        taa.Node(clip=False)


def test_every_keyword_resolve_sequence_documents_is_taken(tmp_root):
    """Parsed as taatool's options: an unknown one would fail before the missing input."""
    missing = os.path.join(tmp_root, "parity-missing", "x.####.exr")
    samples = {"True": True, "RANGE": "1-2", "PATTERN": missing, "FILE": missing,
               "LIST": "1", "N": 1, "V": 1.0, "S": 1.0, "M": 1.0, "F": 1.0, "DEGREES": 40.0}
    for keyword, value in re.findall(r"^  ([a-z_]+)=(\S+?):? ", taa.resolve_sequence.__doc__,
                                     re.M):
        if keyword == "output":
            continue  # given to every call
        given = samples.get(value, value.split("|")[0])
        with pytest.raises(taa.Error) as raised:
            taa.resolve_sequence(missing, output=missing + ".out", **{keyword: given})
        assert "unknown option" not in str(raised.value), (keyword, str(raised.value))
    # What the old docstring promised and taatool never had: an error naming the keyword.
    for old in ("clip", "dilate"):
        with pytest.raises(taa.Error, match=f"unknown option --{old}"):
            taa.resolve_sequence(missing, output=missing + ".out", **{old: False})


def write_cycles_frames(folder):
    """The bundled sample as Blender writes a frame: one multilayer file, Cycles' channel names,
    vectors y up pointing to the previous frame (internal (x, y) -> Vector (x, -y))."""
    os.makedirs(folder, exist_ok=True)
    names = ["ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B",
             "ViewLayer.Combined.A", "ViewLayer.Depth.Z", "ViewLayer.Vector.X",
             "ViewLayer.Vector.Y"]
    frames = {}
    for frame in FRAMES:
        color = read_exr(os.path.join(SAMPLE_DIR, f"beauty.{frame:04d}.exr"), ["R", "G", "B", "A"])
        depth = read_exr(os.path.join(SAMPLE_DIR, f"depth.{frame:04d}.exr"), ["Z"])
        motion = read_exr(os.path.join(SAMPLE_DIR, f"motion.{frame:04d}.exr"), ["X", "Y"])
        vector = np.stack([motion[:, :, 0], -motion[:, :, 1]], axis=2)
        pixels = np.concatenate([color, depth, vector], axis=2).astype(np.float32)
        spec = oiio.ImageSpec(pixels.shape[1], pixels.shape[0], len(names), "float")
        spec.channelnames = names
        spec.attribute("BlenderMultiChannel", "Blender V2.55.1 and newer")
        path = os.path.join(folder, f"render.{frame:04d}.exr")
        out = oiio.ImageOutput.create(path)
        assert out.open(path, spec), oiio.geterror()
        assert out.write_image(pixels)
        out.close()
        frames[frame] = (color, depth[:, :, 0], vector)
    return frames


def write_sidecar(path, height, width):
    """Each frame: a camera turning a little about y, and a jitter of its own (not Halton's)."""
    entries = {}
    for frame in FRAMES:
        angle = 0.01 * frame
        c, s = np.cos(angle), np.sin(angle)
        view = np.array([[c, 0, s, 0], [0, 1, 0, 0], [-s, 0, c, -10], [0, 0, 0, 1]])
        aspect, f, near, far = width / height, 1.8, 0.1, 100.0
        projection = np.array([[f / aspect, 0, 0, 0], [0, f, 0, 0],
                               [0, 0, (far + near) / (near - far), 2 * far * near / (near - far)],
                               [0, 0, -1, 0]])
        entries[str(frame)] = {"view": view.T.ravel().tolist(),
                               "projection": projection.T.ravel().tolist(),
                               "jitter": [0.3 - 0.1 * frame, 0.05 * frame - 0.2]}
    with open(path, "w") as out:
        json.dump({"frames": entries}, out)


@pytest.mark.parametrize("with_sidecar", [False, True])
def test_node_with_preset_and_sidecar_matches_taatool(tmp_root, with_sidecar):
    folder = os.path.join(tmp_root, f"parity-cycles-{with_sidecar}")
    frames = write_cycles_frames(folder)
    height, width = frames[1][0].shape[:2]
    extra, parameters = [], {"preset": "cycles"}
    if with_sidecar:
        sidecar = os.path.join(folder, "camera.json")
        write_sidecar(sidecar, height, width)
        extra = ["--camera-sidecar", sidecar]
        parameters["camera_sidecar"] = sidecar
    out = os.path.join(folder, "taatool")
    subprocess.run([TAATOOL, "--preset", "cycles", os.path.join(folder, "render.####.exr"),
                    "--mode", "history", "-d", "float", "-q", *extra,
                    "-o", os.path.join(out, "r.####.exr")], check=True)
    node = taa.Node(**parameters)
    plain = taa.Node()  # taa's own conventions: the preset's must make a difference
    names = ["ViewLayer.Combined.R", "ViewLayer.Combined.G", "ViewLayer.Combined.B",
             "ViewLayer.Combined.A"]
    differs = False
    for frame in FRAMES:
        color, depth, vector = frames[frame]
        resolved = node.push(color, depth=depth, motion=vector, frame=frame)
        expected = read_exr(os.path.join(out, f"r.{frame:04d}.exr"), names)
        np.testing.assert_allclose(resolved, expected, atol=1e-6, rtol=0, err_msg=str(frame))
        other = plain.push(color, depth=depth, motion=vector, frame=frame)
        differs = differs or np.abs(other - expected).max() > 1e-3
    assert differs
