#!/usr/bin/env python3
"""`rotinterp eval` against the Python a user would write instead, in one run.

The script a user writes: for each clip, each joint and each spacing N in 2, 4, 8,
16, keys at frames 0, N, 2N, ... and the last; scipy's Slerp and RotationSpline
rebuilt from them at every frame; the geodesic angle to the original (degrees) and
its mean, RMS, 95th percentile and max per joint. Clips are read with rotinterp's
reader (the same for both sides). Against `rotinterp eval --methods slerp,c2
--keep-every 2,4,8,16 --metrics angle -j 1 --no-plots` on the same clips: like with
like, the angle alone (eval also reads the clips itself and writes its files).
CPU seconds (user + system; for eval those of the child process and its
importer); the two run in turn, and the ratio is the median of the pairs' ratios.

  PYTHONPATH=build/python /usr/bin/python3 bench/bench_eval_scipy.py [--repeat 3] [--build build] [CLIP...]
  (default clips: cmu_01_01, cmu_01_03 and assimp_Boxing_Toes from ../shared/data)
"""
import argparse
import os
import resource
import subprocess
import tempfile
import time

import numpy as np
from scipy.spatial.transform import Rotation, RotationSpline, Slerp

import rotinterp

SPACINGS = (2, 4, 8, 16)
HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_CLIPS = [os.path.join(HERE, "..", "..", "shared", "data", "bvh", name)
                 for name in ("cmu_01_01.bvh", "cmu_01_03.bvh", "assimp_Boxing_Toes.bvh")]


def scipy_eval(paths):
    """Per clip x method x N x joint: mean, RMS, p95, max of the geodesic angle (degrees)."""
    rows = []
    for path in paths:
        clip = rotinterp.read_clip(path)
        t = clip.times
        q = clip.rotations  # (frames, joints, 4), x y z w
        for n in SPACINGS:
            keys = np.unique(np.append(np.arange(0, t.size, n), t.size - 1))
            for j in range(q.shape[1]):
                ref = Rotation.from_quat(q[:, j])
                key_rot = Rotation.from_quat(q[keys, j])
                for name, curve in (("slerp", Slerp(t[keys], key_rot)), ("c2", RotationSpline(t[keys], key_rot))):
                    angle = np.degrees((ref.inv() * curve(t)).magnitude())
                    rows.append((path, name, n, j, angle.mean(), np.sqrt((angle ** 2).mean()),
                                 np.percentile(angle, 95), angle.max()))
    return rows


def cpu_self():
    u = resource.getrusage(resource.RUSAGE_SELF)
    return u.ru_utime + u.ru_stime


def cpu_children():
    u = resource.getrusage(resource.RUSAGE_CHILDREN)
    return u.ru_utime + u.ru_stime


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--build", default="build")
    ap.add_argument("clips", nargs="*", default=DEFAULT_CLIPS)
    a = ap.parse_args()
    cli = os.path.join(a.build, "rotinterp")
    best_scipy = best_eval = best_scipy_wall = best_eval_wall = float("inf")
    ratios = []
    with tempfile.TemporaryDirectory() as out:
        for _ in range(a.repeat):
            c0, w0 = cpu_self(), time.perf_counter()
            rows = scipy_eval(a.clips)
            scipy_cpu = cpu_self() - c0
            best_scipy = min(best_scipy, scipy_cpu)
            best_scipy_wall = min(best_scipy_wall, time.perf_counter() - w0)
            c0, w0 = cpu_children(), time.perf_counter()
            subprocess.run([cli, "eval", *a.clips, "--methods", "slerp,c2", "--keep-every", "2,4,8,16",
                            "--metrics", "angle", "-j", "1", "--no-plots", "-q", "-o", out], check=True)
            eval_cpu = cpu_children() - c0
            best_eval = min(best_eval, eval_cpu)
            best_eval_wall = min(best_eval_wall, time.perf_counter() - w0)
            ratios.append(scipy_cpu / eval_cpu)
    frames = sum(rotinterp.read_clip(p).frame_count for p in a.clips)
    print(f"{len(a.clips)} clips, {frames} frames; slerp and c2 (scipy Slerp, RotationSpline) x keep-every "
          f"{','.join(map(str, SPACINGS))}; {len(rows)} joint rows; best of {a.repeat}")
    print(f"scipy script          {best_scipy:7.3f} s CPU  {best_scipy_wall:7.3f} s wall")
    print(f"rotinterp eval -j 1 --metrics angle   {best_eval:7.3f} s CPU  {best_eval_wall:7.3f} s wall")
    print(f"rotinterp eval is {float(np.median(ratios)):.1f}x faster (CPU, median of {len(ratios)} pairs; best of "
          f"each {best_scipy / best_eval:.1f}x), {best_scipy_wall / best_eval_wall:.1f}x (wall); goal >= 20x")


if __name__ == "__main__":
    main()
