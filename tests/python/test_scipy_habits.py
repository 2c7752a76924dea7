"""What a scipy user types gets a right answer or a clear error, never a quiet wrong one:
NaN times raise from every entry point, the ends of the key range are a choice
(extrapolate=), scipy's call forms and names are pointed to ours."""
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import rotinterp

T = np.arange(6) / 5.0
Q = Rotation.random(6, random_state=3).as_quat()


def entry_points(extrapolate="clamp", method="c2"):
    """Every way to ask the curve at times t, as name -> f(t)."""
    f = rotinterp.make_interpolator(T, Q, method=method, extrapolate=extrapolate)
    return {
        "call": f,
        "angular_velocity": f.angular_velocity,
        "angular_velocity body": lambda t: f.angular_velocity(t, frame="body"),
        "angular_acceleration": f.angular_acceleration,
        "interpolate": lambda t: rotinterp.interpolate(T, Q, t, method=method, extrapolate=extrapolate),
        "interpolate joints": lambda t: rotinterp.interpolate(T, Q[:, None, :], t, method=method,
                                                              extrapolate=extrapolate),
    }


@pytest.mark.parametrize("t", [np.nan, [0.1, np.nan], np.inf, -np.inf])
def test_a_non_finite_time_raises_from_every_entry_point(t):
    for name, f in entry_points().items():
        with pytest.raises(ValueError, match="non-finite"):
            f(t)
            pytest.fail(f"{name} answered for t = {t}")


def test_a_non_finite_resample_range_raises():
    clip = rotinterp.read_clip(Path(__file__).resolve().parents[2] / "samples" / "walk.bvh")
    with pytest.raises(ValueError, match="non-finite"):
        rotinterp.resample(clip, fps=60, range=(np.nan, None))


def test_clamp_is_the_default_and_holds_the_end_keys():
    for name, f in entry_points().items():
        assert np.array_equal(f(T[-1] + 1.0), f(T[-1])) or name.startswith("angular"), name
    f = rotinterp.make_interpolator(T, Q, method="c2")
    assert rotinterp.angle(f(-3.0), Q[0]) < 1e-15
    # The derivatives at the last key are the last segment's, its limit from inside; zero beyond.
    for derivative in (f.angular_velocity, f.angular_acceleration):
        inside, at_end, beyond = derivative([T[-1] - 1e-9, T[-1], T[-1] + 1e-9])
        assert np.allclose(at_end, inside, atol=1e-5) and np.linalg.norm(at_end) > 1.0
        assert np.all(beyond == 0.0)


def test_extrapolate_raise_refuses_times_outside_the_keys_and_answers_inside():
    for name, f in entry_points(extrapolate="raise").items():
        f(np.array([T[0], 0.5, T[-1]]))  # the ends themselves are inside
        for outside in (T[0] - 1e-9, [0.5, T[-1] + 1e-9]):
            with pytest.raises(ValueError, match=r"outside the key range \[0.0, 1.0\]"):
                f(outside)
                pytest.fail(f"{name} answered outside the keys")
    with pytest.raises(ValueError, match="extrapolate must be"):
        rotinterp.interpolate(T, Q, 0.5, extrapolate="extend")


CONTINUED = [m["name"] for m in rotinterp.methods() if m["continuity"] >= 1]


@pytest.mark.parametrize("method", CONTINUED)
def test_extrapolate_continue_turns_on_at_the_end_velocity(method):
    f = rotinterp.make_interpolator(T, Q, method=method, extrapolate="continue")
    clamped = rotinterp.make_interpolator(T, Q, method=method)
    inside = np.linspace(T[0], T[-1], 41)
    assert np.array_equal(f(inside), clamped(inside))  # the keys' range is untouched
    for end, out in ((T[-1], 1.0), (T[0], -1.0)):
        w = clamped.angular_velocity(end)
        assert np.linalg.norm(w) > 0.5
        # exp(dt·w)·q_end, built here by scipy: the curve beyond rotates at the end velocity.
        for dt in (1e-3, 0.3, 2.0):
            want = (Rotation.from_rotvec(out * dt * w) * Rotation.from_quat(clamped(end))).as_quat()
            assert rotinterp.angle(f(end + out * dt), want) < 1e-12, (end, dt)
            assert np.allclose(f.angular_velocity(end + out * dt), w, rtol=0, atol=1e-12)
            assert np.all(f.angular_acceleration(end + out * dt) == 0.0)
        # C¹ across the end key: the one-sided slopes agree (a clamped curve's stop to zero).
        h = 1e-5
        q_in, q_end, q_out = Rotation.from_quat(f([end - out * h, end, end + out * h]))
        slope_in = (q_end * q_in.inv()).as_rotvec() / h * out
        slope_out = (q_out * q_end.inv()).as_rotvec() / h * out
        assert np.allclose(slope_in, slope_out, atol=1e-3 * np.linalg.norm(w)), (end, slope_in, slope_out)
    # Beyond the end the body-frame velocity is constant, as a free spin's.
    body = f.angular_velocity([T[-1] + 0.1, T[-1] + 1.7], frame="body")
    assert np.allclose(body[0], body[1], atol=1e-12)
    # interpolate gives the same curve, for one track and for joints.
    beyond = np.array([-1.0, -0.01, 0.5, 1.01, 3.0])
    assert np.array_equal(rotinterp.interpolate(T, Q, beyond, method=method, extrapolate="continue"), f(beyond))
    joints = rotinterp.interpolate(T, np.stack([Q, Q], axis=1), beyond, method=method, extrapolate="continue")
    assert np.array_equal(joints[:, 1], f(beyond))


def test_extrapolate_continue_agrees_with_scipys_rotationspline_at_the_end_key():
    from scipy.spatial.transform import RotationSpline
    spline = RotationSpline(T, Rotation.from_quat(Q))
    f = rotinterp.make_interpolator(T, Q, method="c2", extrapolate="continue")
    # scipy continues its end cubic: the same velocity at the end key, so near it the
    # two part only at second order in the distance.
    assert np.allclose(f.angular_velocity(T[-1], frame="body"), spline(T[-1], 1), atol=1e-9)
    for dt in (1e-3, 1e-2):
        gap = rotinterp.angle(f(T[-1] + dt), spline(T[-1] + dt).as_quat())
        assert gap < 2 * np.linalg.norm(spline(T[-1], 2)) * dt**2, dt


@pytest.mark.parametrize("method", ["slerp", "nlerp"])
def test_extrapolate_continue_is_refused_where_the_end_velocity_is_only_a_chord(method):
    for call in (lambda: rotinterp.make_interpolator(T, Q, method=method, extrapolate="continue"),
                 lambda: rotinterp.interpolate(T, Q, [2.0], method=method, extrapolate="continue")):
        with pytest.raises(ValueError, match=rf"{method}'s is only its last chord's: use one of squad, expmap"):
            call()


def test_scipys_derivative_order_argument_points_to_the_named_derivatives():
    f = rotinterp.make_interpolator(T, Q, method="c2")
    with pytest.raises(TypeError, match=r"angular_velocity\(t, frame=\"body\"\)") as e:
        f(0.3, 1)
    assert "angular_acceleration" in str(e.value)


def test_scipys_class_names_find_their_methods():
    assert rotinterp.make_interpolator(T, Q, method="Slerp").method == "slerp"
    for name in ("rotationspline", "RotationSpline"):
        with pytest.raises(ValueError, match=r'RotationSpline is method="c2"'):
            rotinterp.interpolate(T, Q, [0.5], method=name)
        with pytest.raises(ValueError, match=r'RotationSpline is method="c2"'):
            rotinterp.make_interpolator(T, Q, method=name)
    # The clip commands alike, where a method is named.
    clip = rotinterp.read_clip(Path(__file__).resolve().parents[2] / "samples" / "walk.bvh")
    for call in (lambda: rotinterp.resample(clip, fps=60, method="RotationSpline"),
                 lambda: rotinterp.resample(clip, fps=60, method_for={"Hips": "RotationSpline"}),
                 lambda: rotinterp.evaluate([clip], methods=["RotationSpline"], keep_every=[4]),
                 lambda: rotinterp.reduce(clip, method="RotationSpline")):
        with pytest.raises(ValueError, match=r'RotationSpline is method="c2"'):
            call()


def test_a_scalar_time_gives_one_sample_in_interpolate_as_in_the_callable():
    f = rotinterp.make_interpolator(T, Q, method="c2")
    one = rotinterp.interpolate(T, Q, 0.55, method="c2")
    assert one.shape == (4,) and np.array_equal(one, f(0.55))
    joints = rotinterp.interpolate(T, np.stack([Q, Q], axis=1), np.float32(0.55), method="c2")
    assert joints.shape == (2, 4) and np.array_equal(joints[1], rotinterp.interpolate(T, Q, np.float32(0.55),
                                                                                       method="c2"))


def test_an_empty_track_names_its_arguments():
    for call in (lambda: rotinterp.interpolate([], np.zeros((0, 4)), [0.0]),
                 lambda: rotinterp.make_interpolator([], np.zeros((0, 4)))):
        with pytest.raises(ValueError, match=r"times and quats are empty \(quats of shape \(0, 4\)\)"):
            call()


def test_importing_without_the_compiled_module_says_how_to_build_it(tmp_path):
    package = tmp_path / "rotinterp"
    package.mkdir()
    source = Path(rotinterp.__file__).resolve()
    (package / "__init__.py").write_text(source.read_text())
    done = subprocess.run([sys.executable, "-c", "import rotinterp"], cwd=tmp_path, capture_output=True, text=True,
                          env={"PYTHONPATH": str(tmp_path)})
    assert done.returncode != 0
    last = done.stderr.strip().splitlines()[-1]
    assert last.startswith("ImportError") and "--target rotinterp_python" in last, last
    assert "circular" not in last
