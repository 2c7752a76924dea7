"""The Python module: the same results as the command line, the same curves as scipy,
and one-line errors. Run by ctest (`pytest`) with PYTHONPATH=build/python and
ROTINTERP_CLI / ROTINTERP_SHARED_DATA set (tests/CMakeLists.txt)."""
import csv
import math
import os
import subprocess
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation, RotationSpline, Slerp

import rotinterp

CLI = os.environ.get("ROTINTERP_CLI", "build/rotinterp")
DATA = Path(os.environ.get("ROTINTERP_SHARED_DATA", "../shared/data"))
BVH_CLIPS = sorted((DATA / "bvh").glob("*.bvh"))
METHODS = [m["name"] for m in rotinterp.methods()]


def cli(*args):
    subprocess.run([CLI, *map(str, args)], check=True, capture_output=True)


def smooth_track(seed, keys, joints, rate=120.0):
    """Smooth random motion: rotation vectors that are sums of sinusoids, per joint."""
    rng = np.random.default_rng(seed)
    t = np.arange(keys) / rate
    amp = rng.uniform(0.2, 1.2, (joints, 3, 3))
    freq = rng.uniform(0.2, 1.5, (joints, 3, 3))
    phase = rng.uniform(0, 2 * np.pi, (joints, 3, 3))
    v = (amp[None] * np.sin(2 * np.pi * freq[None] * t[:, None, None, None] + phase[None])).sum(axis=3)
    q = Rotation.from_rotvec(v.reshape(-1, 3)).as_quat().reshape(keys, joints, 4)
    return t, q


def angle_between(a, b):
    """Rotation angle between quaternion arrays (x, y, z, w), q and -q alike."""
    return rotinterp.angle(a, b)


# ---- the same bytes and numbers as the CLI ------------------------------------------------------

@pytest.mark.parametrize("method", METHODS)
def test_resample_then_write_gives_the_cli_bytes_for_every_method(method, tmp_path):
    assert BVH_CLIPS, f"no BVH clips in {DATA}"
    for clip in BVH_CLIPS:
        ours, theirs = tmp_path / "py.bvh", tmp_path / "cli.bvh"
        rotinterp.write_clip(rotinterp.resample(rotinterp.read_clip(clip), fps=50, method=method), ours)
        cli("resample", clip, "-o", theirs, "--fps", "50", "--method", method, "--quiet")
        assert ours.read_bytes() == theirs.read_bytes(), f"{clip.name} {method}"


def test_sparse_keys_and_fbx_sources_give_the_cli_bytes(tmp_path):
    fbx = DATA / "fbx" / "digitalrune_Marine_Run.fbx"
    for source, args in [(BVH_CLIPS[0], ["--keep-every", "8"]), (fbx, ["--fps", "30000/1001"])]:
        ours, theirs = tmp_path / "py.bvh", tmp_path / "cli.bvh"
        clip = rotinterp.read_clip(source)
        out = (rotinterp.resample(clip, keep_every=8) if args[0] == "--keep-every"
               else rotinterp.resample(clip, fps=Fraction(30000, 1001)))
        rotinterp.write_clip(out, ours)
        cli("resample", source, "-o", theirs, *args, "--quiet")
        assert ours.read_bytes() == theirs.read_bytes(), source.name


@pytest.mark.parametrize("metrics", [None, "angle", ["fk", "smoothness"]])
def test_evaluate_equals_errors_csv_to_the_last_digit(tmp_path, metrics):
    paths = [str(BVH_CLIPS[0]), str(DATA / "bvh" / "assimp_Boxing_Toes.bvh")]
    methods, spacings = ["slerp", "clamped", "bf"], [2, 8]
    cols = rotinterp.evaluate(paths, methods=methods, keep_every=spacings, metrics=metrics)
    chosen = "all" if metrics is None else metrics if isinstance(metrics, str) else ",".join(metrics)
    cli("eval", *paths, "--methods", ",".join(methods), "--keep-every", "2,8", "--metrics", chosen, "-j", "1",
        "--no-plots", "-q", "-o", tmp_path / "e")
    with open(tmp_path / "e" / "errors.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    assert len(rows) == len(cols["clip"]) > 0
    assert list(cols) == list(rows[0])  # the file's columns, in its order
    for i, row in enumerate(rows):
        for name, text in row.items():
            ours = cols[name][i]
            if isinstance(ours, str) or name in ("clip", "method", "joint", "kind"):
                assert str(ours) == text, (i, name)
            elif text == "":
                assert math.isnan(ours), (i, name)
            else:
                assert float(ours) == float(text), (i, name, ours, text)


def test_a_clip_built_from_arrays_round_trips_its_arrays():
    src = rotinterp.read_clip(BVH_CLIPS[0])
    built = rotinterp.Clip(src.names, src.parents, src.offsets, src.times, src.rotations_as(scalar_first=True),
                           translations=src.translations, scalar_first=True, name="built")
    assert built.names == src.names
    assert built.rate_text == src.rate_text == "30"  # NC_bandai…, the first BVH by name
    np.testing.assert_array_equal(built.parents, src.parents)
    assert angle_between(built.rotations, src.rotations).max() < 1e-12
    same = rotinterp.resample(built, method="slerp")  # the same rate: the keys back
    assert angle_between(same.rotations, src.rotations).max() < 1e-9
    np.testing.assert_allclose(same.translations["Hips"], src.translations["Hips"], atol=1e-12)


# ---- the same curves as scipy --------------------------------------------------------------------

@pytest.mark.parametrize("scalar_first", [False, True])
def test_slerp_equals_scipy_slerp(scalar_first):
    t, q = smooth_track(1, 200, 5, rate=30.0)
    new_t = np.linspace(t[0], t[-1], 1111)
    ours = rotinterp.interpolate(t, np.roll(q, 1, axis=-1) if scalar_first else q, new_t, "slerp",
                                 scalar_first=scalar_first)
    if scalar_first:
        ours = np.roll(ours, -1, axis=-1)
    for j in range(q.shape[1]):
        ref = Slerp(t, Rotation.from_quat(q[:, j]))(new_t).as_quat()
        assert angle_between(ours[:, j], ref).max() < 1e-9


@pytest.mark.parametrize("scalar_first", [False, True])
def test_c2_equals_scipy_rotation_spline(scalar_first, monkeypatch):
    # scipy stops its iteration at 10 steps or 1e-9; raised so that both are converged.
    monkeypatch.setattr(RotationSpline, "MAX_ITER", 200)
    monkeypatch.setattr(RotationSpline, "TOL", 1e-15)
    t, q = smooth_track(2, 120, 4, rate=10.0)
    t = t + np.random.default_rng(3).uniform(0, 0.02, t.size)  # non-uniform
    new_t = np.linspace(t[0], t[-1], 997)
    for j in range(q.shape[1]):
        keys = np.roll(q[:, j], 1, axis=-1) if scalar_first else q[:, j]
        f = rotinterp.make_interpolator(t, keys, "c2", scalar_first=scalar_first)
        ours = f(new_t)
        if scalar_first:
            ours = np.roll(ours, -1, axis=-1)
        spline = RotationSpline(t, Rotation.from_quat(q[:, j]))
        assert angle_between(ours, spline(new_t).as_quat()).max() < 1e-9
        # scipy's rate is in the body frame, ours in the fixed frame.
        body = Rotation.from_quat(ours).inv().apply(f.angular_velocity(new_t))
        np.testing.assert_allclose(body, spline(new_t, 1), atol=1e-7)


def test_interpolator_takes_numbers_and_arrays():
    t, q = smooth_track(4, 10, 1)
    f = rotinterp.make_interpolator(t, q[:, 0], "clamped")
    assert f(t[3]).shape == (4,)
    assert f(t).shape == (10, 4)
    assert f.angular_velocity(0.01).shape == (3,)
    assert angle_between(f(t), q[:, 0]).max() < 1e-9
    assert f.method == "clamped"


def test_metrics_on_arrays():
    a = Rotation.from_rotvec([[0, 0, 0.3], [1, 0, 0]]).as_quat()
    b = Rotation.from_rotvec([[0, 0, -0.2], [0, 0, 0]]).as_quat()
    np.testing.assert_allclose(rotinterp.angle(a, -b), [0.5, 1.0], atol=1e-15)
    swing, twist = rotinterp.swing_twist(Rotation.from_rotvec([[0.3, 0, 0.4]]).as_quat(), [0, 0, 1])
    np.testing.assert_allclose(Rotation.from_quat(twist).as_rotvec()[0, :2], 0, atol=1e-15)
    composed = Rotation.from_quat(swing) * Rotation.from_quat(twist)
    assert angle_between(composed.as_quat(), Rotation.from_rotvec([[0.3, 0, 0.4]]).as_quat()).max() < 1e-15


# ---- bad input raises with the message --------------------------------------------------------------

def test_method_names_are_taken_in_any_case_and_a_near_miss_gets_did_you_mean():
    t, q = smooth_track(5, 6, 2)
    assert np.array_equal(rotinterp.interpolate(t, q, t, "SLERP"), rotinterp.interpolate(t, q, t, "slerp"))
    with pytest.raises(ValueError, match="did you mean squad"):
        rotinterp.interpolate(t, q, t, "sqaud")


def test_bad_input_raises_value_error_with_the_message():
    t, q = smooth_track(5, 6, 2)
    with pytest.raises(ValueError, match=r"quats must be quaternions: .* got shape \(6, 2, 3\)"):
        rotinterp.interpolate(t, q[..., :3], t)
    with pytest.raises(ValueError, match=r"shape \(K, 4\) or \(K, J, 4\)"):
        rotinterp.interpolate(t, q[None], t)
    with pytest.raises(ValueError, match=r"quats\[2, 1\] is not finite"):
        bad = q.copy()
        bad[2, 1, 0] = np.nan
        rotinterp.interpolate(t, bad, t)
    with pytest.raises(ValueError, match="increasing"):
        rotinterp.interpolate(t[::-1], q, t)
    with pytest.raises(ValueError, match="unknown method 'nope' .valid: slerp"):
        rotinterp.interpolate(t, q, t, "nope")
    with pytest.raises(ValueError, match="has 6 keys but times has 5"):
        rotinterp.interpolate(t[:5], q, t)
    with pytest.raises(ValueError, match="keep_every"):
        rotinterp.resample(rotinterp.read_clip(BVH_CLIPS[0]), keep_every=0)


def test_files_raise_os_errors(tmp_path):
    with pytest.raises(FileNotFoundError, match="no such file"):
        rotinterp.read_clip(tmp_path / "missing.bvh")
    with pytest.raises(IsADirectoryError):
        rotinterp.read_clip(tmp_path)
    broken = tmp_path / "broken.bvh"
    broken.write_text("HIERARCHY\nROOT x\n{\n")
    with pytest.raises(ValueError, match="broken.bvh"):
        rotinterp.read_clip(broken)
    clip = rotinterp.read_clip(BVH_CLIPS[0])
    rotinterp.write_clip(clip, tmp_path / "new" / "dir" / "out.bvh")  # missing folders are made, as the CLI makes them
    assert (tmp_path / "new" / "dir" / "out.bvh").is_file()
    (tmp_path / "afile").write_text("in the way")
    with pytest.raises(OSError, match="afile: cannot create the output folder: a file of that name is in the way"):
        rotinterp.write_clip(clip, tmp_path / "afile" / "out.bvh")
    with pytest.raises(ValueError, match="unknown format"):
        rotinterp.write_clip(clip, tmp_path / "out.xyz")
