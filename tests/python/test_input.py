"""Input as scipy takes it: any real dtype, non-unit quaternions normalized, scipy
Rotations wherever quaternions are; zero / non-finite keys refused by index."""
import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import rotinterp


def unit64(q):
    """The float64 unit quaternions the given (rounded) values stand for."""
    q = np.asarray(q, dtype=np.float64)
    return q / np.linalg.norm(q, axis=-1, keepdims=True)


def test_float32_keys_give_the_float64_result_to_1e7_rad():
    # The first call: glTF / PyTorch keys, norm off by up to ~1e-7.
    q64 = Rotation.random(1000, random_state=1).as_quat()
    q32 = q64.astype(np.float32)
    t = np.arange(1000) / 30
    new_t = np.linspace(0.0, t[-1], 2999)
    for method in ("slerp", "c2"):
        ours = rotinterp.interpolate(t, q32, new_t, method=method)
        same_values = rotinterp.interpolate(t, unit64(q32), new_t, method=method)
        assert rotinterp.angle(ours, same_values).max() < 1e-12, method
        # Against the float64 keys the float32 ones were rounded from: within the
        # rounding itself (float32 resolves about 6e-8 per component).
        original = rotinterp.interpolate(t, q64, new_t, method="slerp")
        if method == "slerp":
            assert rotinterp.angle(ours, original).max() < 1e-7


def test_keys_printed_to_six_decimals_are_taken_as_the_rotations_they_round():
    # The second call: quaternions as CSVs hold them.
    q = np.round(Rotation.random(10, random_state=2).as_quat(), 6)
    ours = rotinterp.interpolate(np.arange(10.0), q, [0.5])
    expected = rotinterp.interpolate(np.arange(10.0), unit64(q), [0.5])
    assert rotinterp.angle(ours, expected).max() < 1e-12


def test_seven_decimal_keys_of_a_constant_turn_give_that_turn_with_c2():
    # The third call: 0, 45 and 90 degrees about z, printed to 7 decimals.
    f = rotinterp.make_interpolator([0, 1, 2], [[0, 0, 0, 1], [0, 0, 0.3826834, 0.9238795],
                                                [0, 0, 0.7071068, 0.7071068]], method="c2")
    t = np.linspace(0, 2, 41)
    exact = Rotation.from_rotvec(np.outer(t * np.pi / 4, [0, 0, 1])).as_quat()
    assert rotinterp.angle(f(t), exact).max() < 1e-7


@pytest.mark.parametrize("bad, message", [(0.0, "is zero"), (np.nan, "is not finite"), (np.inf, "is not finite")])
def test_zero_and_non_finite_keys_are_refused_by_their_index(bad, message):
    t = np.arange(5.0)
    q = Rotation.random(5, random_state=3).as_quat()
    q[3] = bad if bad == 0.0 else [0, bad, 0, 1]
    with pytest.raises(ValueError, match=r"quats\[3\] " + message):
        rotinterp.interpolate(t, q, [0.5])
    with pytest.raises(ValueError, match=r"quats\[3\] " + message):
        rotinterp.make_interpolator(t, q)
    many = np.stack([Rotation.random(5, random_state=4).as_quat(), q], axis=1)  # (K, J, 4): joint 1 is bad
    with pytest.raises(ValueError, match=r"quats\[3, 1\] " + message):
        rotinterp.interpolate(t, many, [0.5])


def test_any_non_zero_scale_of_a_key_is_the_same_rotation():
    t = np.arange(6.0)
    q = Rotation.random(6, random_state=5).as_quat()
    scales = np.array([1e-300, 3.0, 1e-5, 1e300, -2.0, 0.5])[:, None]  # -q is q too
    new_t = np.linspace(0, 5, 51)
    for method in ("slerp", "c2", "squad"):
        assert rotinterp.angle(rotinterp.interpolate(t, q * scales, new_t, method),
                               rotinterp.interpolate(t, q, new_t, method)).max() < 1e-12, method


def test_times_of_any_real_dtype_give_the_float64_result():
    q = Rotation.random(8, random_state=6).as_quat()
    reference = rotinterp.interpolate(np.arange(8.0), q, np.array([0.5, 3.25, 6.0]))
    for dtype in (np.int32, np.int64, np.float32, np.uint8, np.float16):
        ours = rotinterp.interpolate(np.arange(8).astype(dtype), q, np.array([0.5, 3.25, 6.0]).astype(np.float32))
        assert rotinterp.angle(ours, reference).max() < 1e-12, dtype
    f = rotinterp.make_interpolator(np.arange(8).astype(np.int16), q)
    for number in (3, 3.0, np.float32(3.0), np.int64(3)):  # numbers of any type: one orientation
        assert f(number).shape == (4,) and f.angular_acceleration(number).shape == (3,), type(number)
        np.testing.assert_array_equal(f(number), f(3.0))


def test_a_scipy_rotation_is_accepted_wherever_quaternions_are():
    r = Rotation.random(7, random_state=7)
    t = np.arange(7.0) / 10
    new_t = np.linspace(0, 0.6, 25)
    arrays = r.as_quat()
    np.testing.assert_array_equal(rotinterp.interpolate(t, r, new_t), rotinterp.interpolate(t, arrays, new_t))
    # scalar_first names the layout of the result; the Rotation brings its own.
    np.testing.assert_array_equal(rotinterp.interpolate(t, r, new_t, scalar_first=True),
                                  np.roll(rotinterp.interpolate(t, arrays, new_t), 1, axis=-1))
    np.testing.assert_array_equal(rotinterp.make_interpolator(t, r, "c2")(new_t),
                                  rotinterp.make_interpolator(t, arrays, "c2")(new_t))
    other = Rotation.random(7, random_state=8)
    np.testing.assert_allclose(rotinterp.angle(r, other), (r.inv() * other).magnitude(), atol=1e-12)
    swing, twist = rotinterp.swing_twist(r, [0, 0, 1])
    assert rotinterp.angle(swing, rotinterp.swing_twist(arrays, [0, 0, 1])[0]).max() == 0.0
    # A clip's rotations: a flat Rotation of F·J, frame-major, as (F, J, 4).
    clip = rotinterp.Clip(["root", "child"], [-1, 0], [[0, 0, 0], [0, 1, 0]], np.arange(3) / 30,
                          Rotation.from_quat(r.as_quat()[:6]))
    assert rotinterp.angle(clip.rotations, r.as_quat()[:6].reshape(3, 2, 4)).max() < 1e-15
