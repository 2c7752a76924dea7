"""interpolate on (K, J, 4) arrays: every joint bit for bit the library's own curve of
that joint (make_interpolator), whatever the keys' signs, norms and dtype; the input
left as it was; and no copy of it made on the way (the output is the one array)."""
import tracemalloc

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import rotinterp

METHODS = [m["name"] for m in rotinterp.methods()]
K, J = 200, 5


def clip_keys(seed=3):
    """(K,) times, (K, J, 4) unit keys of smooth motion, and sample times past both ends,
    at the keys, and out of order; more than one block of samples."""
    rng = np.random.default_rng(seed)
    t = np.cumsum(rng.uniform(0.5, 1.5, K)) / 30
    rotvec = np.cumsum(rng.normal(0, 0.08, (K, J, 3)), axis=0)
    q = Rotation.from_rotvec(rotvec.reshape(-1, 3)).as_quat().reshape(K, J, 4)
    new_t = np.concatenate([[t[0] - 1.0], np.linspace(t[0], t[-1], 301), t[::17], rng.uniform(t[0], t[-1], 40)])
    return t, q, new_t


def per_joint(t, q, new_t, method, scalar_first=False):
    """The (N, J, 4) result built one joint at a time through make_interpolator."""
    return np.stack([rotinterp.make_interpolator(t, q[:, j], method, scalar_first)(new_t)
                     for j in range(q.shape[1])], axis=1)


@pytest.mark.parametrize("method", METHODS)
@pytest.mark.parametrize("scalar_first", [False, True])
def test_every_joint_is_its_own_interpolator_bit_for_bit_with_flipped_unnormalized_keys(method, scalar_first):
    t, q, new_t = clip_keys()
    rng = np.random.default_rng(4)
    flips = np.where(rng.random((K, J, 1)) < 0.3, -1.0, 1.0)
    raw = q * flips * rng.uniform(0.2, 5.0, (K, J, 1))
    ours = rotinterp.interpolate(t, raw, new_t, method, scalar_first=scalar_first)
    assert ours.tobytes() == per_joint(t, raw, new_t, method, scalar_first).tobytes()


@pytest.mark.parametrize("method", ["slerp", "nlerp", "c2"])
def test_float32_keys_are_the_joints_own_interpolators_bit_for_bit(method):
    t, q, new_t = clip_keys(5)
    q32 = (q * 1.7).astype(np.float32)
    ours = rotinterp.interpolate(t, q32, new_t, method)
    assert ours.tobytes() == per_joint(t, q32, new_t, method).tobytes()
    assert ours.tobytes() == rotinterp.interpolate(t, q32.astype(np.float64), new_t, method).tobytes()


def strided(a):
    """The same values as a non-contiguous view: every other element of a twice-as-wide last axis."""
    wide = np.zeros(a.shape[:-1] + (2 * a.shape[-1],), dtype=a.dtype)
    wide[..., ::2] = a
    return wide[..., ::2]


@pytest.mark.parametrize("method", ["slerp", "c2"])
def test_non_contiguous_and_float32_inputs_give_the_contiguous_float64_result_bit_for_bit(method):
    t, q, new_t = clip_keys(9)
    q = (q * 1.3).astype(np.float32).astype(np.float64)  # exactly float32 values, unnormalized
    expected = rotinterp.interpolate(t, q, new_t, method).tobytes()
    for keys in (strided(q), np.asfortranarray(q), q.astype(np.float32), strided(q.astype(np.float32)),
                 np.asfortranarray(q.astype(np.float32))):
        assert not keys.flags.c_contiguous or keys.dtype == np.float32
        assert rotinterp.interpolate(strided(t), keys, strided(new_t), method).tobytes() == expected
    one = rotinterp.interpolate(t, q[:, 1].copy(), new_t, method).tobytes()  # q[:, 1] is itself a strided view
    assert rotinterp.interpolate(t, q[:, 1], new_t, method).tobytes() == one
    assert rotinterp.interpolate(t, q.astype(np.float32)[:, 1], new_t, method).tobytes() == one


@pytest.mark.parametrize("method", ["slerp", "c2"])
def test_a_scipy_rotation_gives_the_result_of_its_quaternions_bit_for_bit(method):
    t, q, new_t = clip_keys(6)
    r = Rotation.from_quat(q[:, 2])
    ours = rotinterp.interpolate(t, r, new_t, method, scalar_first=True)  # a Rotation is scalar-last
    expected = rotinterp.make_interpolator(t, r.as_quat(), method)(new_t)[:, [3, 0, 1, 2]]
    assert ours.tobytes() == expected.tobytes()


def test_the_input_arrays_are_left_as_they_were():
    t, q, new_t = clip_keys(7)
    raw = q * np.where(np.arange(K) % 3 == 0, -2.0, 0.5)[:, None, None]
    before = (t.copy(), raw.copy(), new_t.copy())
    for method in ("slerp", "c2"):
        rotinterp.interpolate(t, raw, new_t, method)
        rotinterp.interpolate(t, raw[:, 1], new_t, method)
    for a, b in zip((t, raw, new_t), before):
        assert a.tobytes() == b.tobytes()


@pytest.mark.parametrize("method", ["slerp", "c2"])
@pytest.mark.parametrize("dtype", [np.float64, np.float32])
def test_a_call_allocates_no_array_but_its_output(method, dtype):
    # numpy reports the arrays it allocates to tracemalloc: a normalized (or float64)
    # copy of the (K, J, 4) input would show as a second array at the peak.
    rng = np.random.default_rng(8)
    t = np.arange(4000) / 120
    q = rng.normal(size=(4000, J, 4)).astype(dtype)
    new_t = np.linspace(0, t[-1], 500)
    out_bytes = new_t.size * J * 4 * 8
    rotinterp.interpolate(t, q, new_t, method)  # warm up: first-call allocations
    tracemalloc.start()
    try:
        rotinterp.interpolate(t, q, new_t, method)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < out_bytes + q.nbytes // 4, (peak, out_bytes, q.nbytes)
