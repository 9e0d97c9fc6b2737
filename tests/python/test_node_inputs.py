"""taa.Node on bad and unusual arrays: a clear taa.Error and never a crash of the host process;
layouts the C ABI cannot take as they are (other byte orders, transposed, reversed) copied."""
import re
import subprocess
import sys

import numpy as np
import pytest

import taa

# Calls that once crashed the interpreter (issue 17, defect 1). Each runs in its own process so
# that a crash fails its case instead of the whole session.
BAD_CALLS = {
    "short jitter": ("taa.Node().push(np.zeros((4, 4, 4), np.float32), jitter=[1])",
                     r"jitter needs 2 numbers"),
    "string as color": ("taa.Node().push('hello')", r"color .*numeric.*<U5"),
    "bytes array": ("taa.Node().push(np.full((4, 4, 4), b'ab'))", r"color .*numeric.*S2"),
    "string array": ("taa.Node().push(np.full((4, 4, 3), 'x'))", r"color .*numeric.*<U1"),
    "string depth": ("taa.Node().push(np.zeros((4, 4, 4), np.float32), depth='x')",
                     r"depth .*numeric"),
    "object motion": ("taa.Node().push(np.zeros((4, 4, 4), np.float32), "
                      "motion=np.full((4, 4, 2), None))", r"motion .*numeric.*object"),
    "complex color": ("taa.Node().push(np.zeros((4, 4, 4), np.complex64))",
                      r"color .*numeric.*complex64"),
    "None as color": ("taa.Node().push(None)", r"color .*numeric"),
    "string jitter": ("taa.Node().push(np.zeros((4, 4, 4), np.float32), jitter='ab')",
                      r"jitter must be a numeric array.*<U2"),
    "string matrix": ("taa.Node().push(np.zeros((4, 4, 4), np.float32), "
                      "world_to_camera='x' * 16)", r"world_to_camera must be a numeric array.*<U16"),
}


@pytest.mark.parametrize("name", sorted(BAD_CALLS))
def test_bad_arrays_raise_instead_of_crashing(name):
    call, expected = BAD_CALLS[name]
    code = ("import numpy as np, taa\n"
            f"try:\n    {call}\nexcept taa.Error as error:\n    print('taa.Error:', error)\n")
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert result.returncode == 0, f"{call} ended the process ({result.returncode}): " \
                                   f"{result.stderr[-2000:]}"
    assert result.stdout.startswith("taa.Error:"), result.stdout + result.stderr
    assert re.search(expected, result.stdout), result.stdout


def flat_frame(dtype=np.float32, shape=(6, 10, 4)):
    rng = np.random.default_rng(7)
    return rng.uniform(0.0, 2.0, shape).astype(dtype)


def resolve_alone(color, **kwargs):
    return taa.Node(jitter="none").push(color, frame=1, **kwargs)


@pytest.mark.parametrize("dtype", [">f4", ">f2"])
def test_big_endian_arrays_give_the_native_result(dtype):
    """Defect 4: a big-endian array was read as native bytes (all-zero output)."""
    native = flat_frame(np.dtype(dtype).newbyteorder("="))
    swapped = native.astype(dtype)
    expected = resolve_alone(native)
    assert np.abs(expected).max() > 0.1
    np.testing.assert_array_equal(resolve_alone(swapped), expected)


def test_big_endian_depth_and_motion_are_converted():
    color = flat_frame()
    depth = np.full(color.shape[:2], 5.0, np.float32)
    motion = np.full(color.shape[:2] + (2,), 0.25, np.float32)
    node, swapped_node = taa.Node(jitter="none"), taa.Node(jitter="none")
    for frame in (1, 2):
        expected = node.push(color, depth=depth, motion=motion, frame=frame)
        got = swapped_node.push(color, depth=depth.astype(">f4"),
                                motion=motion.astype(">f4"), frame=frame)
        np.testing.assert_array_equal(got, expected)


@pytest.mark.parametrize("layout", ["transposed", "reversed columns", "channels last strided"])
def test_unusual_strides_are_copied(layout):
    """Item 9: a transposed array failed with the C ABI's stride message instead of a copy."""
    base = flat_frame(shape=(10, 6, 4))
    if layout == "transposed":
        array = base.transpose(1, 0, 2)
    elif layout == "reversed columns":
        array = flat_frame()[:, ::-1]
    else:
        array = flat_frame(shape=(6, 10, 8))[:, :, ::2]
    assert not array.flags.c_contiguous
    np.testing.assert_array_equal(resolve_alone(array),
                                  resolve_alone(np.ascontiguousarray(array)))


def test_integer_and_bool_arrays_are_converted_to_float():
    ints = np.ones((4, 4, 4), np.int32)
    np.testing.assert_array_equal(resolve_alone(ints), resolve_alone(ints.astype(np.float32)))


@pytest.mark.parametrize("jitter", [(float("nan"), 0.0), (0.0, float("inf"))])
def test_non_finite_jitter_is_refused(jitter):
    """Defect 3: a NaN jitter made every pixel +Inf."""
    node = taa.Node()
    with pytest.raises(taa.Error, match=r"jitter .* finite"):
        node.push(flat_frame(), jitter=jitter, frame=1)
    assert np.isfinite(node.push(flat_frame(), jitter=(0.25, -0.25), frame=1)).all()
