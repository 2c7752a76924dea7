"""rotinterp: resample, compare and evaluate keyframed 3-D orientations on numpy arrays.

Quaternion layout, for every function here: float64 arrays whose last axis is 4,
scalar-last ``(x, y, z, w)`` by default (as scipy.spatial.transform.Rotation's
``as_quat()``), scalar-first ``(w, x, y, z)`` with ``scalar_first=True``. Times are
seconds. Angles are radians, except in ``evaluate``'s columns (degrees, as in
``errors.csv``). Errors raise ``ValueError`` (bad input) or ``OSError`` (files)
carrying the same one-line message as the ``rotinterp`` command.
"""
from . import _rotinterp
from ._rotinterp import Clip, Interpolator

__version__ = _rotinterp.__version__
#: The method ``resample`` and ``interpolate`` use unless told otherwise.
default_method = _rotinterp.default_method

__all__ = ["Clip", "Interpolator", "methods", "interpolate", "make_interpolator", "read_clip", "write_clip",
           "resample", "evaluate", "angle", "swing_twist", "default_method"]


def methods():
    """The interpolation methods: a list of dicts with ``name``, ``description``,
    ``continuity`` (0, 1, 2), ``coordinate_invariant``, ``exact_on_constant_velocity``
    and ``preserves_holds`` (a segment between two equal keys stays still)."""
    return _rotinterp.methods()


def interpolate(times, quats, new_times, method=default_method, scalar_first=False):
    """Interpolate key orientations at new times.

    times: (K,) strictly increasing seconds. quats: (K, 4) for one track, or
    (K, J, 4) for J joints keyed at the same times (all joints in one call).
    new_times: (N,) seconds, any order; outside [times[0], times[-1]] the ends hold.
    Returns (N, 4) or (N, J, 4). Keys may come in either hemisphere (q and -q);
    every method takes the short way and never returns NaN. Releases the GIL.
    """
    return _rotinterp.interpolate(times, quats, new_times, method, scalar_first)


def make_interpolator(times, quats, method=default_method, scalar_first=False):
    """Build one track's interpolator: ``f(t)`` gives (4,) for a number or (N, 4) for an
    array of times, ``f.angular_velocity(t)`` the fixed-frame (world) angular velocity in
    rad/s ((3,) or (N, 3)), in closed form. scipy's ``RotationSpline(t, 1)`` gives the
    body-frame rate: ``Rotation.from_quat(f(t)).inv().apply(f.angular_velocity(t))``."""
    return _rotinterp.make_interpolator(times, quats, method, scalar_first)


def read_clip(path, anim=None):
    """Read a clip (BVH, FBX, glTF/GLB, Collada, ...). ``anim``: an animation's name or
    index (default: the first). Raises FileNotFoundError/IsADirectoryError for a path
    that is not a file, ValueError for a file that is not a clip."""
    return _rotinterp.read_clip(str(path), anim)


def write_clip(clip, path, bvh_order="ZXY"):
    """Write a clip; the format follows the extension (.bvh, .fbx, .glb, .gltf, .dae),
    atomically, the same bytes as the ``rotinterp`` command writes. ``bvh_order``: the
    Euler order of joints without a BVH layout. Raises OSError when it cannot write."""
    _rotinterp.write_clip(clip, str(path), bvh_order)


def resample(clip, fps=None, keep_every=None, method=default_method, method_for=None, translation="cubic",
             range=None):
    """Resample a clip, as ``rotinterp resample`` does.

    fps: output rate in Hz (a number, a string such as "30000/1001", or a
    fractions.Fraction), exact. keep_every: keep every Nth frame (and the last) as keys
    and rebuild every frame from them. Neither: the same rate. method_for: {joint:
    method}. translation: "cubic" (Steffen, no overshoot) or "linear". range:
    (start, end) seconds from the first frame, either may be None.
    """
    return _rotinterp.resample(clip, fps, keep_every, method, method_for or {}, translation, range)


def evaluate(inputs, methods=None, keep_every=(2, 4, 8, 16), subframe=0, shell_distance=0.03):
    """Evaluate interpolators on clips as ``rotinterp eval`` does, and return the rows of
    ``errors.csv`` as columns: a dict of numpy arrays that ``pandas.DataFrame`` takes as
    it is. inputs: a path, a Clip, or a list of them (a path's text is its clip id, as in
    the CSV; a Clip's id is its name). methods: names (default all). End Site rows have
    NaN in the rotation-only columns (empty cells in the CSV), rows of joints that are not
    feet NaN in the foot-contact columns; spacings N a clip has fewer than 2N + 1 frames for
    give no rows. Releases the GIL."""
    return _rotinterp.evaluate(inputs, None if methods is None else list(methods), list(keep_every), subframe,
                               shell_distance)


def angle(a, b, scalar_first=False):
    """The rotation angle (radians, in [0, pi]) between quaternion arrays of one shape
    (..., 4): the geodesic distance, q and -q alike. Returns shape (...)."""
    return _rotinterp.angle(a, b, scalar_first)


def swing_twist(q, axis, scalar_first=False):
    """Split q = swing * twist about ``axis`` (3,) in the moving frame, for (..., 4)
    arrays: twist is a rotation about the axis, swing about an axis perpendicular to it.
    Returns (swing, twist)."""
    return _rotinterp.swing_twist(q, axis, scalar_first)
