"""The Python entry points refuse what the command refuses, with its one-line
message (issue 47, class 5), and read no memory an array does not hold."""
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import rotinterp

CLI = os.environ.get("ROTINTERP_CLI", "build/rotinterp")
WALK = Path(__file__).resolve().parents[2] / "samples" / "walk.bvh"


def test_zero_joints_give_an_empty_result_not_memory_the_array_does_not_hold():
    times = np.arange(4.0)
    out = rotinterp.interpolate(times, np.zeros((4, 0, 4)), [0.5, 1.5, 2.5])
    assert out.shape == (3, 0, 4)
    assert rotinterp.interpolate(times, np.zeros((4, 0, 4), dtype=np.float32), 0.5).shape == (0, 4)


T = np.arange(4.0)
Q = np.tile([0.0, 0.0, 0.0, 1.0], (4, 1))
ROT = np.tile([0.0, 0.0, 0.0, 1.0], (4, 2, 1))


def two_joint_clip(**kw):
    return rotinterp.Clip(["a", "b"], kw.pop("parents", [-1, 0]), np.zeros((2, 3)), kw.pop("times", T), ROT, **kw)


@pytest.mark.parametrize("bad", [T.astype(complex) + 1j, np.array(["0", "1", "2", "3"]),
                                 np.arange(4).astype("timedelta64[s]"), np.arange(4).astype("datetime64[s]"),
                                 np.array([0, 1, 2, 3], dtype=object), np.array([0, 1, 1, 1], dtype=bool)])
def test_times_of_a_dtype_that_is_not_a_real_number_are_refused(bad):
    with pytest.raises(TypeError, match=r"^times must be real numbers \(integers or floats\), got dtype " +
                       str(bad.dtype).replace("[", r"\[").replace("]", r"\]") + "$"):
        rotinterp.interpolate(bad, Q, [0.5])


def test_complex_quaternions_and_bool_sample_times_are_refused():
    with pytest.raises(TypeError, match="^quats must be real numbers .*complex128$"):
        rotinterp.interpolate(T, Q.astype(complex), [0.5])
    with pytest.raises(TypeError, match="^new_times must be real numbers .*bool$"):
        rotinterp.interpolate(T, Q, np.array([True]))


def test_a_nan_or_infinite_time_is_refused_by_every_time_argument():
    f = rotinterp.make_interpolator(T, Q)
    for call in (lambda: f(np.nan), lambda: f.angular_velocity(np.inf), lambda: rotinterp.interpolate(T, Q, [np.nan])):
        with pytest.raises(ValueError, match="non-finite value at flat index 0$"):
            call()


@pytest.mark.parametrize("axis", [[0, 0, 0], [0, np.nan, 0], [np.inf, 0, 0]])
def test_swing_twist_refuses_an_axis_with_no_direction(axis):
    with pytest.raises(ValueError, match="^swing_twist: axis must be a finite non-zero vector"):
        rotinterp.swing_twist(Q, axis)


def test_a_tiny_axis_is_still_a_direction():
    swing, twist = rotinterp.swing_twist(np.array([0.0, 0.0, np.sin(0.5), np.cos(0.5)]), [0, 0, 1e-200])
    assert np.allclose(swing, [0, 0, 0, 1]) and np.allclose(twist, [0, 0, np.sin(0.5), np.cos(0.5)])


def test_parents_that_are_not_joint_indices_are_refused():
    with pytest.raises(ValueError, match=r"^parents\[1\] = 4294967296 is neither -1 \(a root\) nor the index of a joint"):
        two_joint_clip(parents=[-1, 2**32])
    with pytest.raises(ValueError, match=r"^parents\[0\] = -5 is neither"):
        two_joint_clip(parents=[-5, 0])
    with pytest.raises(TypeError, match="^parents must be integers, got dtype float64$"):
        two_joint_clip(parents=[-1, 0.7])


@pytest.mark.parametrize("metres", [0, -1, float("nan"), float("inf")])
def test_metres_per_unit_must_be_positive_and_finite_as_unit_is(metres):
    message = r"^metres_per_unit: unit '.*' is not m, cm, mm, in, ft or a positive number of metres per unit$"
    with pytest.raises(ValueError, match=message):
        two_joint_clip(metres_per_unit=metres)
    with pytest.raises(ValueError, match=message):
        rotinterp.reduce(two_joint_clip(frame_time=1.0), metres_per_unit=metres)
    with pytest.raises(ValueError, match=message.replace("metres_per_unit", "unit", 1)):
        rotinterp.read_clip("samples/walk.bvh", unit=metres)


@pytest.mark.parametrize("shell,why", [(float("nan"), "is not a number"), (-1.0, "must be greater than 0")])
def test_evaluate_refuses_the_shell_distance_the_command_refuses(shell, why):
    with pytest.raises(ValueError, match="^shell_distance: length '.*' " + why):
        rotinterp.evaluate(two_joint_clip(frame_time=1.0), methods=["slerp"], keep_every=[2], shell_distance=shell)


def test_keep_every_must_be_a_whole_number():
    clip = two_joint_clip(frame_time=1.0)
    with pytest.raises(TypeError, match="^keep_every must be a whole number, got 2.5$"):
        rotinterp.resample(clip, keep_every=2.5)
    with pytest.raises(ValueError, match="^keep_every must be a whole number >= 1, got 1180591620717411303424$"):
        rotinterp.resample(clip, keep_every=2**70)


def test_requests_past_the_key_limit_are_refused_before_allocating():
    with pytest.raises(ValueError, match=r"^frame_time=1e-09 s over 1.5 s of keys would give 1500000001 frames × 2 "
                                         r"joints, more than 100000000 keys$"):
        two_joint_clip(times=np.array([0.0, 0.5, 1.0, 1.5]), frame_time=1e-9)
    with pytest.raises(ValueError, match="^new_times would give 400000000 frames × 1 joint, more than 100000000 keys$"):
        rotinterp.interpolate(T, Q, np.broadcast_to(0.0, (400_000_000,)))
    huge = 400_000_000
    with pytest.raises(ValueError, match="^times would give 400000000 frames"):
        rotinterp.make_interpolator(np.broadcast_to(0.0, (huge,)), np.broadcast_to(Q[0], (huge, 4)))


def test_evaluate_refuses_an_unknown_metric_listing_the_valid_ones():
    with pytest.raises(ValueError, match="unknown metric 'speed'; valid: all, angle, swing-twist"):
        rotinterp.evaluate(two_joint_clip(frame_time=1.0), methods=["slerp"], keep_every=[2], metrics=["angle", "speed"])


def test_a_gltf_buffer_outside_the_folder_is_read_only_with_allow_external_files(tmp_path):
    (tmp_path / "sub").mkdir()
    rotinterp.write_clip(two_joint_clip(frame_time=1.0), str(tmp_path / "clip.gltf"))
    doc = json.loads((tmp_path / "clip.gltf").read_text())
    doc["buffers"][0]["uri"] = "../" + doc["buffers"][0]["uri"]
    outside = tmp_path / "sub" / "outside.gltf"
    outside.write_text(json.dumps(doc))
    for read in (rotinterp.read_clip, rotinterp.info):
        with pytest.raises(ValueError, match=r"leads out of the file's folder \(refused unless --allow-external-files, "
                                             r"in Python allow_external_files=True\)$"):
            read(str(outside))
    assert rotinterp.read_clip(str(outside), allow_external_files=True).names == ["a", "b"]
    assert len(rotinterp.info(str(outside), allow_external_files=True)["joints"]) == 2


# The same request as resample's keywords and as the command's options: the two must
# both refuse it or both take it.
RESAMPLE_REQUESTS = [
    ({"fps": "1e3"}, ["--fps", "1e3"]),
    ({"fps": 1e20}, ["--fps", "1e20"]),
    ({"fps": -30}, ["--fps", "-30"]),
    ({"fps": float("nan")}, ["--fps", "nan"]),
    ({"fps": 0}, ["--fps", "0"]),
    ({"fps": True}, ["--fps", "True"]),
    ({"fps": 30, "keep_every": 2}, ["--fps", "30", "--keep-every", "2"]),
    ({"keep_every": 0}, ["--keep-every", "0"]),
    ({"keep_every": 3}, ["--keep-every", "3"]),
    ({"keep_every": 10**9}, ["--keep-every", "1000000000"]),
    ({"keep_every": 10**12}, ["--keep-every", "1000000000000"]),
    ({"fps": 30, "range": (2.0, 1.0)}, ["--fps", "30", "--range", "2:1"]),
    ({"fps": 30, "range": (-1.0, None)}, ["--fps", "30", "--range=-1:"]),
    ({"fps": 30, "range": (0.5, 1.5)}, ["--fps", "30", "--range", "0.5:1.5"]),
    ({"fps": 30, "translation": "foo"}, ["--fps", "30", "--translation", "foo"]),
    ({"fps": 30, "method": "nope"}, ["--fps", "30", "--method", "nope"]),
    ({"fps": 30, "loop": "maybe"}, ["--fps", "30", "--loop", "maybe"]),
    ({"fps": 30, "loop": "closed"}, ["--fps", "30", "--loop", "closed"]),
]


@pytest.mark.parametrize("kwargs,options", RESAMPLE_REQUESTS, ids=[" ".join(o) for _, o in RESAMPLE_REQUESTS])
def test_resample_refuses_and_takes_what_the_command_does(kwargs, options, tmp_path):
    command = subprocess.run([CLI, "resample", str(WALK), "-o", str(tmp_path / "out.bvh"), "-q", *options],
                             capture_output=True, text=True)
    try:
        rotinterp.resample(rotinterp.read_clip(WALK), **kwargs)
        refused = ""
    except (TypeError, ValueError) as e:
        refused = str(e)
    assert (refused != "") == (command.returncode != 0), (refused, command.stderr)


def test_loop_of_another_type_is_a_type_error_not_a_cast_failure():
    with pytest.raises(TypeError, match=r"^loop must be None, a bool, 'auto', 'closed' or 'open', got 1$"):
        rotinterp.resample(two_joint_clip(frame_time=1.0), loop=1)
