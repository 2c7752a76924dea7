#!/usr/bin/env python3
"""The Python module against scipy and against the C++ library, in one run.

31 joints x 10 000 keys of smooth random motion at 120 Hz, evaluated at 240 Hz, one
thread: rotinterp.interpolate(..., "slerp") against scipy's Slerp (one object per
joint, as users write it) and "c2" against RotationSpline (build + evaluate); the C++
rate is bench_interp's BM_Build + BM_Method for the same method on data of the same
shape, run here. CPU seconds of this process (one thread), best of --repeat runs.

  PYTHONPATH=build/python /usr/bin/python3 bench/bench_python.py [--repeat 3] [--build build]
"""
import argparse
import json
import os
import subprocess
import time

import numpy as np
from scipy.spatial.transform import Rotation, RotationSpline, Slerp

import rotinterp

JOINTS, KEYS, KEY_RATE, SAMPLE_RATE = 31, 10_000, 120.0, 240.0


def motion(seed=1):
    """Smooth random motion: each joint's rotation vector a sum of sinusoids."""
    rng = np.random.default_rng(seed)
    t = np.arange(KEYS) / KEY_RATE
    amp = rng.uniform(0.2, 1.2, (JOINTS, 3, 3))
    freq = rng.uniform(0.2, 1.5, (JOINTS, 3, 3))
    phase = rng.uniform(0, 2 * np.pi, (JOINTS, 3, 3))
    v = (amp[None] * np.sin(2 * np.pi * freq[None] * t[:, None, None, None] + phase[None])).sum(axis=3)
    q = Rotation.from_rotvec(v.reshape(-1, 3)).as_quat().reshape(KEYS, JOINTS, 4)
    new_t = np.arange(int((t[-1] - t[0]) * SAMPLE_RATE) + 1) / SAMPLE_RATE
    return t, q, new_t


def best(repeat, fn):
    times = []
    for _ in range(repeat):
        start = time.process_time()
        fn()
        times.append(time.process_time() - start)
    return min(times)


def cpp_seconds(build_dir, method):
    """Seconds per call (build + evaluate every joint) of the C++ library, from bench_interp."""
    out = subprocess.run([os.path.join(build_dir, "bench", "bench_interp"),
                          f"--benchmark_filter=^BM_(Build|Method)/{method}$", "--benchmark_format=json",
                          "--benchmark_min_time=0.5"], check=True, capture_output=True, text=True).stdout
    total = 0.0
    for b in json.loads(out)["benchmarks"]:
        scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[b["time_unit"]]
        total += b["cpu_time"] * scale
    return total


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--build", default="build")
    a = ap.parse_args()
    t, q, new_t = motion()
    samples = new_t.size * JOINTS
    print(f"{JOINTS} joints x {KEYS} keys at {KEY_RATE:g} Hz, evaluated at {SAMPLE_RATE:g} Hz: "
          f"{samples / 1e6:.2f} M samples per call; best of {a.repeat}")

    def scipy_slerp():
        for j in range(JOINTS):
            Slerp(t, Rotation.from_quat(q[:, j]))(new_t).as_quat()

    def scipy_spline():
        for j in range(JOINTS):
            RotationSpline(t, Rotation.from_quat(q[:, j]))(new_t).as_quat()

    rows = []
    for method, scipy_name, scipy_fn, goal in [("slerp", "Slerp", scipy_slerp, 30), ("c2", "RotationSpline",
                                                                                    scipy_spline, 50)]:
        ours = best(a.repeat, lambda: rotinterp.interpolate(t, q, new_t, method))
        theirs = best(a.repeat, scipy_fn)
        cpp = cpp_seconds(a.build, method)
        rows.append((method, scipy_name, samples / ours, samples / theirs, samples / cpp, theirs / ours, ours / cpp,
                     goal))
    print(f"{'method':7} {'rotinterp M/s':>14} {'scipy M/s':>10} {'C++ M/s':>9} {'vs scipy':>9} {'vs C++':>7}")
    for method, scipy_name, r, s, c, speedup, overhead, goal in rows:
        print(f"{method:7} {r / 1e6:14.2f} {s / 1e6:10.3f} {c / 1e6:9.2f} {speedup:8.1f}x {overhead:6.2f}x"
              f"   (scipy {scipy_name}; goals: >= {goal}x scipy, <= 1.1x C++)")


if __name__ == "__main__":
    main()
