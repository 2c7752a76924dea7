"""The Python entry points refuse what the command refuses, with its one-line
message (issue 47, class 5), and read no memory an array does not hold."""
import numpy as np
import pytest

import rotinterp


def test_zero_joints_give_an_empty_result_not_memory_the_array_does_not_hold():
    times = np.arange(4.0)
    out = rotinterp.interpolate(times, np.zeros((4, 0, 4)), [0.5, 1.5, 2.5])
    assert out.shape == (3, 0, 4)
    assert rotinterp.interpolate(times, np.zeros((4, 0, 4), dtype=np.float32), 0.5).shape == (0, 4)
