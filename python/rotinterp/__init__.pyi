# Type stub for the rotinterp package (signatures; the docstrings are in __init__.py).
# Quaternions: float64 arrays with last axis 4, (x, y, z, w) unless scalar_first=True.
from fractions import Fraction
from os import PathLike
from typing import Mapping, Sequence, TypedDict

import numpy as np
import numpy.typing as npt

__version__: str
default_method: str

ArrayLike = npt.ArrayLike
Path = str | PathLike[str]

class MethodInfo(TypedDict):
    name: str
    description: str
    continuity: int
    coordinate_invariant: bool
    exact_on_constant_velocity: bool
    preserves_holds: bool

class Clip:
    def __init__(self, names: Sequence[str], parents: ArrayLike, offsets: ArrayLike, times: ArrayLike,
                 rotations: ArrayLike, translations: Mapping[str, ArrayLike] | None = None,
                 frame_time: float | None = None, unit_scale: float = 1.0, scalar_first: bool = False,
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
    def unit_scale(self) -> float: ...            # metres per clip unit
    @property
    def source_format(self) -> str: ...
    @property
    def frame_count(self) -> int: ...

class Interpolator:
    def __call__(self, t: float | ArrayLike) -> np.ndarray: ...
    def angular_velocity(self, t: float | ArrayLike) -> np.ndarray: ...
    @property
    def method(self) -> str: ...
    @property
    def times(self) -> np.ndarray: ...

def methods() -> list[MethodInfo]: ...
def interpolate(times: ArrayLike, quats: ArrayLike, new_times: ArrayLike, method: str = ...,
                scalar_first: bool = False) -> np.ndarray: ...
def make_interpolator(times: ArrayLike, quats: ArrayLike, method: str = ...,
                      scalar_first: bool = False) -> Interpolator: ...
def read_clip(path: Path, anim: str | int | None = None) -> Clip: ...
def write_clip(clip: Clip, path: Path, bvh_order: str = "ZXY") -> None: ...
def resample(clip: Clip, fps: float | str | Fraction | None = None, keep_every: int | None = None,
             method: str = ..., method_for: Mapping[str, str] | None = None, translation: str = "cubic",
             range: tuple[float | None, float | None] | None = None) -> Clip: ...
def evaluate(inputs: Path | Clip | Sequence[Path | Clip], methods: Sequence[str] | None = None,
             keep_every: Sequence[int] = (2, 4, 8, 16), subframe: int = 0,
             shell_distance: float = 0.03) -> dict[str, np.ndarray]: ...
def angle(a: ArrayLike, b: ArrayLike, scalar_first: bool = False) -> np.ndarray: ...
def swing_twist(q: ArrayLike, axis: ArrayLike, scalar_first: bool = False) -> tuple[np.ndarray, np.ndarray]: ...
