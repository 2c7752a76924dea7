"""Whatever names a clip holds, a written file reads back, and fast (issue 47,
class 4; docs/limits.md "Names")."""
import itertools
import time

import numpy as np

import rotinterp


def test_twenty_thousand_names_that_are_one_bvh_token_are_written_and_read_back_in_seconds(tmp_path):
    # "j" and 15 spaces or tabs: distinct names, each "j_______________" as a BVH token.
    names = ["j" + "".join(gaps) for gaps in itertools.islice(itertools.product(" \t", repeat=15), 20000)]
    n = len(names)
    clip = rotinterp.Clip(names, [-1] + [0] * (n - 1), np.zeros((n, 3)), np.array([0.0, 1 / 30]),
                          np.tile([0.0, 0.0, 0.0, 1.0], (2, n, 1)))
    start = time.monotonic()
    rotinterp.write_clip(clip, str(tmp_path / "many.bvh"))
    back = rotinterp.read_clip(str(tmp_path / "many.bvh"))
    assert time.monotonic() - start < 10
    assert len(set(back.names)) == n
    assert back.names[:3] == ["j_______________", "j_______________#", "j_______________#2"]


def test_control_characters_in_names_are_written_as_underscores(tmp_path):
    clip = rotinterp.Clip(["root\x00", "a\tb\nc"], [-1, 0], np.zeros((2, 3)), np.array([0.0, 1 / 30]),
                          np.tile([0.0, 0.0, 0.0, 1.0], (2, 2, 1)))
    for ext in ("bvh", "fbx", "glb"):
        rotinterp.write_clip(clip, str(tmp_path / f"ctl.{ext}"))
        assert rotinterp.read_clip(str(tmp_path / f"ctl.{ext}")).names == ["root_", "a_b_c"], ext
