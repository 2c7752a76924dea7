"""rotinterp: resample, compare and evaluate keyframed 3-D orientations on numpy arrays.

Quaternion layout, for every function here: arrays whose last axis is 4,
scalar-last ``(x, y, z, w)`` by default (as scipy.spatial.transform.Rotation's
``as_quat()``), scalar-first ``(w, x, y, z)`` with ``scalar_first=True``.

Quaternion input is taken as scipy's ``Rotation.from_quat`` takes it: any real dtype
(float32 included), and every finite non-zero quaternion is normalized, so keys
rounded to float32 or to 6 printed decimals are accepted as the rotations they
stand for. A zero, NaN or infinite quaternion raises ``ValueError`` naming its index
(``quats[3, 1] is zero``). A scipy ``Rotation`` (anything with ``as_quat()``) is
accepted wherever quaternions are, whatever ``scalar_first`` says (it is the layout
of the arrays returned). Times may be any real dtype. Outputs are float64 unit
quaternions.

Times are seconds. Angles are radians, except in ``evaluate``'s columns and
``reduce``'s report (degrees, as in ``errors.csv`` and the keys file). Positions
are metres. Errors raise ``ValueError`` (bad input) or ``OSError`` (files) carrying
the same one-line message as the ``rotinterp`` command.
"""
try:
    from . import _rotinterp
except ImportError as e:
    if (getattr(e, "name", None) or "").startswith("rotinterp._rotinterp") or "_rotinterp" in str(e):
        raise ImportError("rotinterp: the compiled module rotinterp._rotinterp is not built here (" + __path__[0] +
                          "): build it with `cmake --build build --target rotinterp_python` (scripts/demo.sh "
                          "does), then PYTHONPATH=build/python") from e
    raise
from ._rotinterp import Clip, Interpolator

__version__ = _rotinterp.__version__
#: The method ``resample`` and ``interpolate`` use unless told otherwise.
default_method = _rotinterp.default_method

__all__ = ["Clip", "Interpolator", "methods", "interpolate", "make_interpolator", "read_clip", "write_clip",
           "resample", "evaluate", "info", "reduce", "render", "angle", "swing_twist", "default_method"]


def methods():
    """The interpolation methods: a list of dicts with ``name``, ``description``,
    ``continuity`` (0, 1, 2), ``coordinate_invariant``, ``exact_on_constant_velocity``
    and ``preserves_holds`` (a segment between two equal keys stays still)."""
    return _rotinterp.methods()


def interpolate(times, quats, new_times, method=default_method, scalar_first=False, extrapolate="clamp"):
    """Interpolate key orientations at new times.

    times: (K,) strictly increasing seconds. quats: (K, 4) for one track, or
    (K, J, 4) for J joints keyed at the same times (all joints in one call).
    new_times: (N,) seconds, any order, or a number. A NaN or infinite time raises
    ValueError, as everywhere here. method: a name of ``methods()``, any case
    (scipy's ``Slerp`` is "slerp"; its ``RotationSpline`` is "c2", which the message
    for "RotationSpline" names). extrapolate: outside [times[0], times[-1]],
    "clamp" (the default) holds the end keys, "raise" raises ValueError (scipy's Slerp),
    "continue" turns on at the curve's angular velocity at its end key (constant
    beyond it), for the methods of continuity >= 1 (squad, c2, ...; not slerp, nlerp).
    Returns (N, 4) or (N, J, 4); (4,) or (J, 4) for a number. Keys may come in either
    hemisphere (q and -q); every method takes the short way and never returns NaN.
    Releases the GIL.
    """
    return _rotinterp.interpolate(times, quats, new_times, method, scalar_first, extrapolate)


def make_interpolator(times, quats, method=default_method, scalar_first=False, extrapolate="clamp"):
    """Build one track's interpolator: ``f(t)`` gives (4,) for a number or (N, 4) for an
    array of times. Times and ``method`` as ``interpolate`` takes them; ``extrapolate``
    as there, for ``f(t)`` and both derivatives alike. ``f(t, 1)`` (scipy's derivative
    order) raises TypeError: the derivatives have their own names.

    ``f.angular_velocity(t, frame="fixed")`` is the angular velocity in rad/s and
    ``f.angular_acceleration(t, frame="fixed")`` its time derivative in rad/s², each (3,)
    or (N, 3). frame="fixed": in the world frame; frame="body": in the moving frame,
    q(t)^-1 applied to the fixed-frame vector, which is what scipy's
    ``RotationSpline(t, 1)`` and ``(t, 2)`` return (for "c2", the same curve as
    RotationSpline, they agree). The velocity is in closed form for every method; the
    acceleration in closed form for "c2", "clamped" and "slerp" (zero inside segments),
    for the others the difference quotient of the closed-form velocity inside the
    segment (relative error about 1e-10). At a key both belong to the segment starting
    there, at the last key the last segment's (its limit from inside); outside the key
    range both are zero with extrapolate="clamp" (the curve holds its end keys), raise
    with "raise", and with "continue" the velocity is the end key's, constant (so zero
    acceleration), the curve exp((t - t_end) * w_end) * q_end.

    The default frame is "fixed", unlike scipy: ``RotationSpline(t, 1)`` is
    ``f.angular_velocity(t, frame="body")`` here, ``RotationSpline(t, 2)``
    ``f.angular_acceleration(t, frame="body")``."""
    return _rotinterp.make_interpolator(times, quats, method, scalar_first, extrapolate)


def read_clip(path, anim=None, unit=None, *, allow_external_files=False):
    """Read a clip (BVH, FBX, glTF/GLB, Collada, ...). ``anim``: an animation's name or
    index (default: the first). ``unit``: what one clip unit is, as ``--unit`` takes it
    ("m", "cm", "mm", "in", "ft") or metres per unit as a number; default the file's,
    else inferred from the figure's size (``clip.unit`` says which and why).
    ``allow_external_files``: a glTF may read buffer files outside its folder, as
    ``--allow-external-files`` (refused by default). Raises FileNotFoundError/
    IsADirectoryError for a path that is not a file, ValueError for a file that is not a
    clip."""
    return _rotinterp.read_clip(str(path), anim, unit, allow_external_files=allow_external_files)


def write_clip(clip, path, bvh_order="ZXY"):
    """Write a clip; the format follows the extension (.bvh, .fbx, .glb, .gltf, .dae),
    atomically, the same bytes as the ``rotinterp`` command writes. ``bvh_order``: the
    Euler order of joints without a BVH layout. Missing folders of ``path`` are created.
    Raises OSError when it cannot write."""
    _rotinterp.write_clip(clip, str(path), bvh_order)


def info(path, anim=None, unit=None, *, allow_external_files=False):
    """What a clip file holds, as a dict: the document ``rotinterp info --json PATH``
    prints (format, animations, frames, rate, duration, unit, joints with their channels
    and key counts, oddities, warnings). ``allow_external_files`` and errors as
    ``read_clip``'s."""
    return _rotinterp.info(str(path), anim, unit, allow_external_files=allow_external_files)


def reduce(clip, method="slerp", tolerance=None, shell_distance=None, tolerance_for=None, translation="cubic",
           metres_per_unit=None, loop=None):
    """Keep the fewest keys per joint that rebuild ``clip`` with ``method`` within a
    budget, as ``rotinterp reduce`` does (the same keys), with its options in its forms:
    ``tolerance`` items with their units, an angle ("0.5deg", "0.01rad") on each joint's
    local rotation and/or a length ("1mm", "0.1cm") on the shell of virtual vertices in
    object space and the translation tracks, as "0.5deg,1mm" or a list (default 1mm);
    ``shell_distance`` a length ("10cm", the default) or a number of metres;
    ``tolerance_for`` ``{joint: items}``. ``metres_per_unit``: ``clip.unit``'s unless given.
    ``loop``: the clip is a cycle (``--loop``): True or "auto" detects its form, "closed" or
    "open" forces it; keys are chosen on the periodic curves and each looped track of the
    reduced clip ends with its closing key.

    Returns a dict: ``clip`` (the reduced Clip: each track holding only its kept keys),
    ``joints`` (per joint: ``name``, ``rotation_frames`` and ``translation_frames``, the
    kept frame indices, ``looped``, and the largest errors over every frame in degrees and
    mm), ``frames``, ``source_keys``, ``kept_keys``, ``metres_per_unit``, ``loop`` (the
    cycle's form, or None) and the largest errors over all joints. Releases the GIL."""
    return _rotinterp.reduce(clip, method, tolerance, shell_distance, tolerance_for, translation, metres_per_unit, loop)


def render(input, out_dir=None, methods=None, keep_every=10, frames=None, size="960x540", trail="", trail_window=1.0,
           sheet=False, view="overlay", colour=None, camera=None, focus="", strip=True, video=None, video_fps=0.0,
           backend=None):
    """Draw comparison frames offscreen, as ``rotinterp render`` does (the same PNGs for
    the same options): the clip (a Clip or a path) rebuilt by each method from every
    ``keep_every``-th frame, over the truth in one panel (``view`` "overlay") or side by
    side ("side"). Options as the command's, in its forms: ``frames`` "START:END:STEP",
    ``size`` "WxH", ``colour`` (side only) "error" or "method", ``camera``
    "fixed" or "follow", ``backend`` "osmesa" or "egl". ``methods`` may name "source" when
    ``input`` is the path of a file with motion of its own (FBX curves, glTF samplers, BVH
    frames): a panel of the file's own motion, as
    ``render -m source`` draws it. Returns the paths written (frames,
    then the sheet, then the video). Raises RuntimeError where the module was built
    without the renderer. Releases the GIL."""
    if not hasattr(_rotinterp, "render"):
        raise RuntimeError("rotinterp was built without the renderer (ROTINTERP_BUILD_RENDER=OFF)")
    return _rotinterp.render(input if isinstance(input, Clip) else str(input),
                             None if out_dir is None else str(out_dir), None if methods is None else list(methods),
                             keep_every, frames, size, trail, trail_window, sheet, view, colour, camera, focus, strip,
                             None if video is None else str(video), video_fps, backend)


def resample(clip, fps=None, keep_every=None, method=default_method, method_for=None, translation="cubic",
             range=None, loop=None):
    """Resample a clip, as ``rotinterp resample`` does.

    fps: output rate in Hz (a number, a string such as "30000/1001", or a
    fractions.Fraction), exact. keep_every: keep every Nth frame (and the last) as keys
    and rebuild every frame from them. Neither: the same rate. method_for: {joint:
    method}. translation: "cubic" (Steffen, no overshoot) or "linear". range:
    (start, end) seconds from the first frame, either may be None. loop: the clip is a
    cycle (``--loop``): True or "auto" detects its form, "closed" or "open" forces it;
    the result is one period at the new rate, closing the same way (docs/resample.md).
    """
    return _rotinterp.resample(clip, fps, keep_every, method, method_for or {}, translation, range, loop)


def evaluate(inputs, methods=None, keep_every=(2, 4, 8, 16), subframe=0, shell_distance=0.03, metrics=None):
    """Evaluate interpolators on clips as ``rotinterp eval`` does, and return the rows of
    ``errors.csv`` as columns: a dict of numpy arrays that ``pandas.DataFrame`` takes as
    it is. inputs: a path, a Clip, or a list of them (a path's text is its clip id, as in
    the CSV; a Clip's id is its name). methods: names (default all). End Site rows have
    NaN in the rotation-only columns (empty cells in the CSV), rows of joints that are not
    feet NaN in the foot-contact columns; spacings N a clip has fewer than 2N + 1 frames for
    give no rows. metrics: as eval --metrics, names ("angle", "fk", …) or one comma list
    (default all); only those are computed, and only their columns returned (no End Site
    rows without "fk"). Releases the GIL."""
    return _rotinterp.evaluate(inputs, None if methods is None else list(methods), list(keep_every), subframe,
                               shell_distance, metrics)


def angle(a, b, scalar_first=False):
    """The rotation angle (radians, in [0, pi]) between quaternion arrays of one shape
    (..., 4): the geodesic distance, q and -q alike. Returns shape (...)."""
    return _rotinterp.angle(a, b, scalar_first)


def swing_twist(q, axis, scalar_first=False):
    """Split q = swing * twist about ``axis`` (3,) in the moving frame, for (..., 4)
    arrays: twist is a rotation about the axis, swing about an axis perpendicular to it.
    Returns (swing, twist)."""
    return _rotinterp.swing_twist(q, axis, scalar_first)
