# Type stub for the rotinterp package (signatures; the docstrings are in __init__.py).
# Quaternions: arrays with last axis 4, (x, y, z, w) unless scalar_first=True, any real
# dtype, normalized on input; or a scipy Rotation (QuatLike).
from fractions import Fraction
from os import PathLike
from typing import Any, Literal, Mapping, Sequence, TypedDict

import numpy as np
import numpy.typing as npt

__version__: str
default_method: str

ArrayLike = npt.ArrayLike
Path = str | PathLike[str]
QuatLike = ArrayLike  # or any object with as_quat(), e.g. scipy.spatial.transform.Rotation
Frame = Literal["fixed", "body"]  # "fixed" by default; scipy's RotationSpline(t, 1) is frame="body"
Extrapolate = Literal["clamp", "raise", "continue"]  # "continue": methods of continuity >= 1

class MethodInfo(TypedDict):
    name: str
    description: str
    continuity: int
    coordinate_invariant: bool
    exact_on_constant_velocity: bool
    preserves_holds: bool

class ClipUnit:
    metres_per_unit: float
    origin: Literal["declared", "given", "inferred", "assumed"]
    reason: str
    name: str                                     # "cm", "in", … or "0.0652 m"

class Clip:
    def __init__(self, names: Sequence[str], parents: ArrayLike, offsets: ArrayLike, times: ArrayLike,
                 rotations: QuatLike, translations: Mapping[str, ArrayLike] | None = None,
                 frame_time: float | None = None, metres_per_unit: float = 1.0, scalar_first: bool = False,
                 name: str = "clip") -> None: ...
    @property
    def name(self) -> str: ...
    @property
    def names(self) -> list[str]: ...
    @property
    def parents(self) -> np.ndarray: ...          # (J,) int, -1 for a root
    @property
    def offsets(self) -> np.ndarray: ...          # (J, 3) rest offsets, clip units
    @property
    def times(self) -> np.ndarray: ...            # (F,) seconds
    @property
    def rotations(self) -> np.ndarray: ...        # (F, J, 4) local rotations, (x, y, z, w)
    def rotations_as(self, scalar_first: bool) -> np.ndarray: ...
    @property
    def translations(self) -> dict[str, np.ndarray]: ...  # joint -> (F, 3), where present
    def track(self, joint: int | str, scalar_first: bool = False) -> tuple[np.ndarray, np.ndarray]: ...
    @property
    def frame_time(self) -> float: ...            # seconds per frame, 0 when none
    @property
    def rate(self) -> float | None: ...           # Hz, exact rate as a float
    @property
    def rate_text(self) -> str | None: ...        # "30", "30000/1001"
    @property
    def unit(self) -> ClipUnit: ...
    @property
    def metres_per_unit(self) -> float: ...       # = unit.metres_per_unit: what positions() and reduce() use
    @property
    def joint_names(self) -> list[str]: ...       # = names
    def positions(self, frames: int | ArrayLike | None = None) -> np.ndarray: ...  # (F, J, 3) world, metres
    @property
    def euler_orders(self) -> list[str]: ...      # each joint's order in its file ("ZXY"), first axis outermost
    @property
    def local_rotations(self) -> np.ndarray: ...  # (F, J, 3) radians, each joint in its file's order
    def to_euler(self, order: str | None = None, degrees: bool = False) -> np.ndarray: ...  # (F, J, 3)
    @property
    def source_format(self) -> str: ...
    @property
    def frame_count(self) -> int: ...

class Interpolator:
    def __call__(self, t: float | ArrayLike) -> np.ndarray: ...
    def angular_velocity(self, t: float | ArrayLike, frame: Frame = "fixed") -> np.ndarray: ...      # rad/s
    def angular_acceleration(self, t: float | ArrayLike, frame: Frame = "fixed") -> np.ndarray: ...  # rad/s²
    @property
    def method(self) -> str: ...
    @property
    def times(self) -> np.ndarray: ...

def methods() -> list[MethodInfo]: ...
def interpolate(times: ArrayLike, quats: QuatLike, new_times: float | ArrayLike, method: str = ...,
                scalar_first: bool = False, extrapolate: Extrapolate = "clamp") -> np.ndarray: ...
def make_interpolator(times: ArrayLike, quats: QuatLike, method: str = ...,
                      scalar_first: bool = False, extrapolate: Extrapolate = "clamp") -> Interpolator: ...
def read_clip(path: Path, anim: str | int | None = None, unit: str | float | None = None, *,
              allow_external_files: bool = False) -> Clip: ...
def write_clip(clip: Clip, path: Path, bvh_order: str = "ZXY") -> None: ...
def resample(clip: Clip, fps: float | str | Fraction | None = None, keep_every: int | None = None,
             method: str = ..., method_for: Mapping[str, str] | None = None, translation: str = "cubic",
             range: tuple[float | None, float | None] | None = None,
             loop: bool | str | None = None) -> Clip: ...
def evaluate(inputs: Path | Clip | Sequence[Path | Clip], methods: Sequence[str] | None = None,
             keep_every: Sequence[int] = (2, 4, 8, 16), subframe: int = 0,
             shell_distance: str | float = 0.03,
             metrics: str | Sequence[str] | None = None) -> dict[str, np.ndarray]: ...
def info(path: Path, anim: str | int | None = None, unit: str | float | None = None, *,
         allow_external_files: bool = False) -> dict[str, Any]: ...
def reduce(clip: Clip, method: str = "slerp", tolerance: str | Sequence[str] | None = None,
           shell_distance: str | float | None = None, tolerance_for: Mapping[str, str | Sequence[str]] | None = None,
           translation: str = "cubic", metres_per_unit: float | None = None) -> dict[str, Any]: ...
def render(input: Path | Clip, out_dir: Path | None = None, methods: Sequence[str] | None = None, keep_every: int = 10,
           frames: str | None = None, size: str = "960x540", trail: str = "", trail_window: float = 1.0,
           sheet: bool = False, view: str = "overlay", colour: str | None = None, camera: str | None = None,
           focus: str = "",
           strip: bool = True, video: Path | None = None, video_fps: float = 0.0,
           backend: str | None = None) -> list[str]: ...
def angle(a: QuatLike, b: QuatLike, scalar_first: bool = False) -> np.ndarray: ...
def swing_twist(q: QuatLike, axis: ArrayLike, scalar_first: bool = False) -> tuple[np.ndarray, np.ndarray]: ...
