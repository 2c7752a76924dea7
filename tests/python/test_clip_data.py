"""Clips as data: joint names and parents, world positions in metres, local rotations
as Euler angles in the files' orders."""
import os
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

import rotinterp

DATA = Path(os.environ.get("ROTINTERP_SHARED_DATA", "../shared/data"))
SAMPLES = Path(__file__).resolve().parents[2] / "samples"
BVH_CLIPS = sorted((DATA / "bvh").glob("*.bvh"))
FBX = DATA / "fbx" / "digitalrune_Marine_Run.fbx"


def test_joint_names_and_parents_describe_the_tree():
    clip = rotinterp.read_clip(SAMPLES / "walk.bvh")
    assert clip.joint_names == clip.names and len(clip.joint_names) == 31
    parents = clip.parents
    assert parents[0] == -1 and all(0 <= p < j for j, p in enumerate(parents) if j > 0)
    assert clip.joint_names[parents[clip.joint_names.index("LeftFoot")]] == "LeftLeg"


@pytest.mark.parametrize("path", BVH_CLIPS + [FBX], ids=lambda p: p.name)
def test_positions_are_evals_world_positions_in_metres(path):
    clip = rotinterp.read_clip(path)
    ours = clip.positions()
    theirs = rotinterp._rotinterp._eval_world_positions(clip) * clip.metres_per_unit
    assert ours.shape == theirs.shape == (clip.frame_count, len(clip.names), 3)
    assert np.abs(ours - theirs).max() <= 1e-12 * np.abs(theirs).max()


def numpy_forward_kinematics(clip):
    """World positions from the clip's arrays, written out independently of the library."""
    rot, off, parents = clip.rotations, clip.offsets, clip.parents
    local = np.broadcast_to(off, rot.shape[:2] + (3,)).copy()
    for name, track in clip.translations.items():
        local[:, clip.names.index(name)] = track
    world_r = [None] * len(parents)
    world_p = np.zeros(local.shape)
    for j, p in enumerate(parents):
        r = Rotation.from_quat(rot[:, j])
        if p < 0:
            world_r[j], world_p[:, j] = r, local[:, j]
        else:
            world_r[j] = world_r[p] * r
            world_p[:, j] = world_p[:, p] + world_r[p].apply(local[:, j])
    return world_p * clip.metres_per_unit


@pytest.mark.parametrize("path", [SAMPLES / "walk.bvh"] + BVH_CLIPS[:2], ids=lambda p: p.name)
def test_positions_equal_forward_kinematics_of_the_clip_arrays(path):
    clip = rotinterp.read_clip(path)
    expected = numpy_forward_kinematics(clip)
    assert np.abs(clip.positions() - expected).max() < 1e-12 * max(1.0, np.abs(expected).max())


def test_positions_of_chosen_frames_are_those_frames():
    clip = rotinterp.read_clip(SAMPLES / "walk.bvh")
    every = clip.positions()
    np.testing.assert_array_equal(clip.positions([0, 7, -1]), every[[0, 7, -1]])
    np.testing.assert_array_equal(clip.positions(5), every[[5]])
    with pytest.raises(ValueError, match="frame 121 outside the clip's 121 frames"):
        clip.positions([121])


def test_positions_are_in_metres_through_the_clips_unit_inferred_or_given():
    # The walk's legs: 42-unit shin bones; a figure 167 units tall is inferred as cm.
    leg, foot = (rotinterp.read_clip(SAMPLES / "walk.bvh").names.index(n) for n in ("LeftLeg", "LeftFoot"))
    for unit, metres in [(None, 0.01), ("cm", 0.01), ("m", 1.0), ("in", 0.0254), (0.02, 0.02)]:
        clip = rotinterp.read_clip(SAMPLES / "walk.bvh", unit=unit)
        assert clip.unit.metres_per_unit == clip.metres_per_unit == metres, unit
        assert clip.unit.origin == ("inferred" if unit is None else "given"), unit
        p = clip.positions(0)[0]
        assert np.linalg.norm(p[foot] - p[leg]) == pytest.approx(42 * metres, rel=1e-12), unit
    with pytest.raises(ValueError, match="furlong"):
        rotinterp.read_clip(SAMPLES / "walk.bvh", unit="furlong")


def bvh_channel_values(path):
    """The rotation channel values (degrees) of every joint with three of them, as
    written in the MOTION section: {joint: (order, (F, 3))}."""
    lines = Path(path).read_text().split("\n")
    joints, column = [], 0
    for line in lines:
        words = line.split()
        if words[:1] in (["ROOT"], ["JOINT"]):
            joints.append([words[1], None, None])
        elif words[:1] == ["CHANNELS"]:
            names = words[2:]
            rot = [i for i, n in enumerate(names) if n.endswith("rotation")]
            joints[-1][1] = "".join(names[i][0] for i in rot)
            joints[-1][2] = [column + i for i in rot]
            column += len(names)
        elif words[:1] == ["MOTION"]:
            break
    start = next(i for i, l in enumerate(lines) if l.startswith("Frame Time")) + 1
    motion = np.array([[float(v) for v in l.split()] for l in lines[start:] if l.strip()])
    return {name: (order, motion[:, cols]) for name, order, cols in joints if len(cols) == 3}


# Files whose channel curves are continuous (CMU's and bvhio's switch Euler solution
# between frames, e.g. cmu_01_01 LeftForeArm from (0, 0, 0) to (154, -37, -111) deg,
# where ours take the equal rotation nearest the frame before: test_to_euler_…).
CONTINUOUS_BVH = [SAMPLES / "walk.bvh"] + [p for p in BVH_CLIPS if p.name.startswith("NC_bandai")]


@pytest.mark.parametrize("path", CONTINUOUS_BVH, ids=lambda p: p.name)
def test_local_rotations_are_the_files_channel_values(path):
    clip = rotinterp.read_clip(path)
    file = bvh_channel_values(path)
    ours = clip.to_euler(degrees=True)
    np.testing.assert_allclose(np.degrees(clip.local_rotations), ours, atol=1e-9)
    worst = 0.0
    for name, (order, values) in file.items():
        j = clip.names.index(name)
        assert clip.euler_orders[j] == order
        # The same rotations, and angle for angle up to whole turns (the file may wrap
        # where ours stay continuous).
        diff = (ours[:, j] - values + 180.0) % 360.0 - 180.0
        worst = max(worst, np.abs(diff).max())
    assert worst < 1e-4  # the files' decimals, through a quaternion and back


@pytest.mark.parametrize("order", ["XYZ", "ZXY", "ZYZ", "yxz"])
def test_to_euler_rebuilds_the_rotations_without_wraps(order):
    clip = rotinterp.read_clip(BVH_CLIPS[0])
    angles = clip.to_euler(order)
    rebuilt = Rotation.from_euler(order.upper(), angles.reshape(-1, 3)).as_quat().reshape(clip.rotations.shape)
    assert rotinterp.angle(rebuilt, clip.rotations).max() < 1e-9
    # Continuous curves: no frame-to-frame step of a whole turn (scipy's as_euler wraps).
    assert np.abs(np.diff(angles, axis=0)).max() < np.pi


def test_to_euler_refuses_an_order_that_is_not_three_axes():
    clip = rotinterp.read_clip(SAMPLES / "walk.bvh")
    with pytest.raises(ValueError, match="Euler order 'XXY'"):
        clip.to_euler("XXY")


def test_positions_are_blenders_bone_heads_of_the_clip_written_as_glb(tmp_path):
    # Blender imports the GLB as a user would; its bone heads, in metres and Z-up
    # (its glTF importer maps (x, y, z) to (x, -z, y)), at each key (t·24: glTF has no
    # frame rate, Blender keeps 24 fps). Nothing is fitted.
    import json
    import shutil
    import subprocess
    if shutil.which("blender") is None:
        pytest.skip("Blender is not installed (scripts/install-deps.sh adds it)")
    clip = rotinterp.resample(rotinterp.read_clip(FBX), fps=24, range=(0.0, 0.5))
    glb, dump = tmp_path / "clip.glb", tmp_path / "blender.json"
    rotinterp.write_clip(clip, glb)
    script = Path(__file__).resolve().parents[1] / "clients" / "blender_dump.py"
    subprocess.run(["blender", "-b", "--factory-startup", "--python", str(script), "--", str(dump), str(glb)],
                   check=True, capture_output=True, timeout=300)
    seen = json.loads(dump.read_text())[str(glb)]
    assert seen["armatures"] == 1
    frames = np.rint(np.array(seen["key_frames"])).astype(int)  # t·24 on the 24 fps grid
    np.testing.assert_allclose(seen["key_frames"], frames, atol=1e-4)
    ours = clip.positions(frames)
    theirs = np.array(seen["positions"])
    bone = {name: i for i, name in enumerate(seen["bones"])}
    joints = [j for j, name in enumerate(clip.names) if name in bone]
    assert len(joints) == len(clip.names)
    ours_z_up = np.stack([ours[..., 0], -ours[..., 2], ours[..., 1]], axis=-1)[:, joints]
    blender = theirs[:, [bone[clip.names[j]] for j in joints]]
    height = np.ptp(ours[0], axis=0).max()
    assert np.abs(ours_z_up - blender).max() < 1e-4 * height, np.abs(ours_z_up - blender).max()
