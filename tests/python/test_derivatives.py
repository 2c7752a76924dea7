"""Angular velocity and acceleration, fixed and body frame: against finite differences
of our own curves (every method) and against scipy's RotationSpline for c2, which
builds the same curve (test_rotinterp.py: test_c2_equals_scipy_rotation_spline)."""
import numpy as np
import pytest
from scipy.spatial.transform import Rotation, RotationSpline

import rotinterp

METHODS = [m["name"] for m in rotinterp.methods()]


def track(seed, keys=12):
    rng = np.random.default_rng(seed)
    t = np.cumsum(rng.uniform(0.05, 0.2, keys))  # non-uniform spacing
    rotvec = np.cumsum(rng.normal(0, 0.35, (keys, 3)), axis=0)
    return t, Rotation.from_rotvec(rotvec).as_quat()


def inside_segments(t, fractions=(0.13, 0.5, 0.77)):
    return np.array([a + u * (b - a) for a, b in zip(t[:-1], t[1:]) for u in fractions])


@pytest.mark.parametrize("method", METHODS)
def test_body_angular_velocity_matches_finite_differences_of_the_curve(method):
    t, q = track(1)
    f = rotinterp.make_interpolator(t, q, method)
    x = inside_segments(t)
    h = 1e-6
    # q(x−h)⁻¹·q(x+h) = exp(2h·ω_body) + O(h³).
    fd = (Rotation.from_quat(f(x - h)).inv() * Rotation.from_quat(f(x + h))).as_rotvec() / (2 * h)
    w = f.angular_velocity(x, frame="body")
    assert np.abs(w - fd).max() < 1e-6 * (1 + np.abs(w).max())
    # Fixed frame: the same vector carried by q(x).
    np.testing.assert_allclose(f.angular_velocity(x), Rotation.from_quat(f(x)).apply(w), atol=1e-12)


@pytest.mark.parametrize("frame", ["fixed", "body"])
@pytest.mark.parametrize("method", METHODS)
def test_angular_acceleration_matches_finite_differences_of_angular_velocity(method, frame):
    t, q = track(2)
    f = rotinterp.make_interpolator(t, q, method)
    x = inside_segments(t)
    h = 1e-6 * np.diff(t).min()
    fd = (f.angular_velocity(x + h, frame=frame) - f.angular_velocity(x - h, frame=frame)) / (2 * h)
    a = f.angular_acceleration(x, frame=frame)
    assert np.abs(a).max() > 0 or method == "slerp"
    assert np.abs(a - fd).max() < 1e-5 * (1 + np.abs(a).max()), np.abs(a - fd).max()


def test_c2_derivatives_equal_rotation_spline_in_the_body_frame(monkeypatch):
    # scipy stops its iteration at 10 steps or 1e-9; raised so that both are converged.
    monkeypatch.setattr(RotationSpline, "MAX_ITER", 200)
    monkeypatch.setattr(RotationSpline, "TOL", 1e-15)
    for seed in (3, 4, 5):
        t, q = track(seed, keys=30)
        f = rotinterp.make_interpolator(t, q, "c2")
        spline = RotationSpline(t, Rotation.from_quat(q))
        x = np.linspace(t[0], t[-1], 1001)[1:-1]  # scipy's ends differ: it extrapolates, we hold
        assert rotinterp.angle(f(x), spline(x).as_quat()).max() < 1e-9  # the same curve first
        w, a = spline(x, 1), spline(x, 2)
        assert np.abs(f.angular_velocity(x, frame="body") - w).max() < 1e-8 * (1 + np.abs(w).max())
        assert np.abs(f.angular_acceleration(x, frame="body") - a).max() < 1e-7 * (1 + np.abs(a).max())


def test_derivatives_take_numbers_and_arrays_and_only_the_two_frames():
    t, q = track(6)
    f = rotinterp.make_interpolator(t, q, "c2")
    assert f.angular_acceleration(float(t[3])).shape == (3,)
    assert f.angular_acceleration(t[:5], frame="body").shape == (5, 3)
    np.testing.assert_array_equal(f.angular_acceleration(t[-1] + 1.0), 0.0)  # held after the last key
    with pytest.raises(ValueError, match='frame must be "fixed" or "body"'):
        f.angular_velocity(t[2], frame="world")
