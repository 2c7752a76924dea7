"""info, reduce and render from Python: the same document, keys and images as the
command line."""
import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import rotinterp

CLI = os.environ.get("ROTINTERP_CLI", "build/rotinterp")
DATA = Path(os.environ.get("ROTINTERP_SHARED_DATA", "../shared/data"))
SAMPLES = Path(__file__).resolve().parents[2] / "samples"
BVH_CLIPS = sorted((DATA / "bvh").glob("*.bvh"))


def cli(*args):
    return subprocess.run([CLI, *map(str, args)], check=True, capture_output=True, text=True).stdout


@pytest.mark.parametrize("path", [SAMPLES / "walk.bvh", BVH_CLIPS[0], DATA / "fbx" / "digitalrune_Marine_Run.fbx"],
                         ids=lambda p: p.name)
def test_info_is_the_document_info_json_prints(path):
    assert rotinterp.info(path) == json.loads(cli("info", "--json", path))


def test_info_raises_as_read_clip_does(tmp_path):
    with pytest.raises(FileNotFoundError):
        rotinterp.info(tmp_path / "missing.bvh")


@pytest.mark.parametrize("method, args, kwargs", [
    ("slerp", ["--tolerance", "0.5deg"], {"tolerance": "0.5deg"}),
    ("c2", [], {}),  # the default budget: 1 mm at 10 cm
    ("clamped", ["--tolerance", "2mm", "--shell-distance", "5cm", "--tolerance-for", "Head=0.2deg"],
     {"tolerance": ["2mm"], "shell_distance": 0.05, "tolerance_for": {"Head": "0.2deg"}}),
    ("c2", ["--loop", "closed"], {"loop": "closed"}),
])
def test_reduce_keeps_the_keys_the_command_keeps(method, args, kwargs, tmp_path):
    path = SAMPLES / "walk.bvh"
    keys = tmp_path / "keys.json"
    cli("reduce", path, "-o", keys, "--method", method, "--quiet", *args)
    theirs = json.loads(keys.read_text())
    ours = rotinterp.reduce(rotinterp.read_clip(path), method=method, **kwargs)
    assert ours["kept_keys"] == theirs["kept_keys"] < ours["source_keys"] == theirs["source_keys"]
    assert ours["metres_per_unit"] == theirs["metres_per_unit"]
    reduced = ours["clip"]
    for j, joint in enumerate(theirs["joints"]):
        mine = ours["joints"][j]
        assert mine["name"] == joint["name"]
        assert list(mine["rotation_frames"]) == joint["rotation"]["frames"]
        times, quats = reduced.track(j)
        np.testing.assert_array_equal(times, joint["rotation"]["times"])
        np.testing.assert_array_equal(quats, joint["rotation"]["keys"])
        assert mine["max_rotation_error_deg"] == joint["max_rotation_error_deg"]
        if "translation" in joint:
            assert list(mine["translation_frames"]) == joint["translation"]["frames"]
            assert mine["max_translation_error_mm"] == joint["max_translation_error_mm"]
        else:
            assert mine["translation_frames"] is None


def test_reduce_loop_takes_a_cycle_as_the_command_does():
    clip = rotinterp.read_clip(str(DATA / "fbx" / "digitalrune_Marine_Run.fbx"))
    ends = rotinterp.reduce(clip, method="c2")
    cycle = rotinterp.reduce(clip, method="c2", loop=True)
    assert ends["loop"] is None and cycle["loop"] == "closed"
    assert cycle["kept_keys"] < ends["kept_keys"]
    looped = {j["name"]: j["looped"] for j in cycle["joints"]}
    assert not looped["L_Arm"] and sum(looped.values()) == len(looped) - 1  # the source's pop keeps its ends
    with pytest.raises(ValueError, match="expected auto, closed or open"):
        rotinterp.reduce(clip, loop="wrap")


def test_reduce_refuses_budgets_the_command_refuses():
    clip = rotinterp.read_clip(SAMPLES / "walk.bvh")
    with pytest.raises(ValueError, match="'0.5' needs a unit"):
        rotinterp.reduce(clip, tolerance="0.5")
    with pytest.raises(ValueError, match="has no joint 'Tail'"):
        rotinterp.reduce(clip, tolerance="1deg", tolerance_for={"Tail": "1deg"})
    with pytest.raises(ValueError, match="a length budget needs a length tolerance"):
        rotinterp.reduce(clip, tolerance="1deg", tolerance_for={"Head": "1mm"})


def test_render_writes_the_pngs_the_command_writes(tmp_path):
    if not hasattr(rotinterp._rotinterp, "render"):
        pytest.skip("built without the renderer")
    options = ["--method", "slerp,c2", "--keep-every", "6", "--frames", "3:30:9", "--size", "192x108", "--sheet",
               "--trail", "LeftHand", "--view", "side"]
    cli("render", SAMPLES / "walk.bvh", "-o", tmp_path / "cli", "-q", *options)
    files = rotinterp.render(SAMPLES / "walk.bvh", tmp_path / "py", methods=["slerp", "c2"], keep_every=6,
                             frames="3:30:9", size="192x108", sheet=True, trail="LeftHand", view="side")
    names = sorted(p.name for p in (tmp_path / "cli").iterdir())
    assert sorted(Path(f).name for f in files) == names and "sheet.png" in names and len(names) == 5
    for name in names:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name


def test_render_refuses_options_as_the_command_does(tmp_path):
    if not hasattr(rotinterp._rotinterp, "render"):
        pytest.skip("built without the renderer")
    clip = rotinterp.read_clip(SAMPLES / "walk.bvh")
    with pytest.raises(ValueError, match="give out_dir"):
        rotinterp.render(clip)
    with pytest.raises(ValueError, match="unknown method 'nope'"):
        rotinterp.render(clip, tmp_path, methods=["nope"])


def test_render_draws_the_files_own_curves_as_the_command_does(tmp_path):
    if not hasattr(rotinterp._rotinterp, "render"):
        pytest.skip("built without the renderer")
    run = DATA / "fbx" / "digitalrune_Marine_Run.fbx"
    cli("render", run, "-o", tmp_path / "cli", "-q", "-m", "slerp,source", "--frames", "4:20:8", "--size", "192x108")
    files = rotinterp.render(run, tmp_path / "py", methods=["slerp", "source"], frames="4:20:8", size="192x108")
    names = sorted(p.name for p in (tmp_path / "cli").iterdir())
    assert sorted(Path(f).name for f in files) == names and len(names) == 3
    for name in names:
        assert (tmp_path / "py" / name).read_bytes() == (tmp_path / "cli" / name).read_bytes(), name
    # The source's panel is not slerp's: without it the frames differ.
    rotinterp.render(run, tmp_path / "slerp2", methods=["slerp", "slerp"], frames="4:20:8", size="192x108")
    assert (tmp_path / "slerp2" / names[0]).read_bytes() != (tmp_path / "py" / names[0]).read_bytes()


def test_render_source_needs_a_file_with_motion_of_its_own(tmp_path):
    if not hasattr(rotinterp._rotinterp, "render"):
        pytest.skip("built without the renderer")
    walk = rotinterp.read_clip(SAMPLES / "walk.bvh")
    with pytest.raises(ValueError, match="give the file's path"):
        rotinterp.render(walk, tmp_path, methods=["source"])
    # Collada keeps no curves or samplers that source replays (a BVH's source is its frames).
    rotinterp.write_clip(walk, tmp_path / "walk.dae")
    with pytest.raises(ValueError, match="walk.dae"):
        rotinterp.render(tmp_path / "walk.dae", tmp_path / "out", methods=["slerp", "source"])


def largest_pause_of_another_thread(call):
    """Run call() in a thread while this one keeps stamping the clock; the longest gap
    between stamps: the whole call if it held the GIL, a scheduling slice if not."""
    import threading
    import time
    worker = threading.Thread(target=call)
    stamps = [time.perf_counter()]
    worker.start()
    while worker.is_alive():
        stamps.append(time.perf_counter())
    worker.join()
    stamps.append(time.perf_counter())
    return float(np.diff(stamps).max()), stamps[-1] - stamps[0]


@pytest.mark.parametrize("name", ["reduce", "render"])
def test_commands_release_the_gil(name, tmp_path):
    # (A call that holds the GIL, e.g. rotinterp._rotinterp._eval_world_positions,
    # leaves this thread no stamp at all until it returns.)
    clip = rotinterp.read_clip(BVH_CLIPS[0])
    if name == "render" and not hasattr(rotinterp._rotinterp, "render"):
        pytest.skip("built without the renderer")
    call = {"reduce": lambda: rotinterp.reduce(clip, method="bf", tolerance="0.1mm"),
            "render": lambda: rotinterp.render(clip, tmp_path, methods=["slerp", "c2"], size="320x180",
                                               frames="0:120:2")}[name]
    pause, total = largest_pause_of_another_thread(call)
    assert total > 0.1  # long enough for a held GIL to show
    assert pause < 0.5 * total, (pause, total)


def test_resample_loop_gives_one_period_closing_as_the_input():
    clip = rotinterp.read_clip(str(DATA / "fbx" / "digitalrune_Marine_Run.fbx"))
    looped = rotinterp.resample(clip, fps=25, loop=True)
    assert looped.frame_count == 34  # 33 frames per period (1.333 s at 25 Hz), closed: the last repeats the first
    seam = np.degrees(rotinterp.angle(looped.rotations[0], looped.rotations[-1]))
    names = list(looped.joint_names)
    pop = names.index("L_Arm")  # the source's own 4.4° pop: reported, kept
    assert seam[pop] == pytest.approx(4.39, abs=0.01)
    assert np.delete(seam, pop).max() < 1e-7
    assert rotinterp.resample(clip, fps=25, loop="closed").frame_count == 34
    with pytest.raises(ValueError, match="expected auto, closed or open"):
        rotinterp.resample(clip, fps=25, loop="wrap")
