"""Type hints of the curvebench package (docs/python.md)."""
import os
import pathlib
from typing import Any, Callable, Iterator, Literal, Mapping, NamedTuple, Optional, Sequence, Union, overload

import numpy as np
import numpy.typing as npt

__version__: str

# An (n, 2) array-like of real coordinates; an (n, 2) float64 C-contiguous array is read in place.
PointsLike = npt.ArrayLike
# An (m, 2) array-like of integer indices.
EdgesLike = npt.ArrayLike
Points = npt.NDArray[np.float64]  # (n, 2)
Edges = npt.NDArray[np.int64]     # (m, 2)

# f(points, **parameters) -> edges, or -> (edges, points) for one that moves points.
AlgorithmFunction = Callable[..., Union[EdgesLike, tuple[EdgesLike, PointsLike]]]
AlgorithmLike = Union[str, "Algorithm", AlgorithmFunction]
Path = Union[str, os.PathLike[str]]

class UnknownNameError(ValueError, KeyError):
    """A name that names nothing curvebench knows: an algorithm, a suite, a graph kind."""

class InvalidOutput(ValueError):
    """A Python algorithm returned something that is not edges between its points."""

class Reconstruction:
    """The result of reconstruct(); unpacks as (edges, points)."""
    @property
    def edges(self) -> Edges: ...
    @property
    def points(self) -> Points: ...
    @property
    def runtime(self) -> float: ...
    @property
    def moved(self) -> bool: ...
    @property
    def algorithm(self) -> str: ...
    def __iter__(self) -> Iterator[np.ndarray]: ...

class Algorithm:
    """A Python function as a curvebench algorithm."""
    function: AlgorithmFunction
    name: str
    def __call__(self, *args: Any, **kwargs: Any) -> Any: ...

class Sample:
    """A sampling of a curve with its ground truth."""
    curve: str
    points: Points
    edges: Edges
    lfs: npt.NDArray[np.float64]
    labels: npt.NDArray[np.str_]
    outlier: npt.NDArray[np.bool_]
    component: npt.NDArray[np.int64]
    parameter: npt.NDArray[np.float64]
    minimum_lfs: float
    floored: npt.NDArray[np.int64]
    def __len__(self) -> int: ...

class RunResult(NamedTuple):
    """What run() gives."""
    results: Any  # pandas.DataFrame
    summary: Any  # pandas.DataFrame, or None where the report's code cannot run
    counts: dict[str, int]
    directory: Optional[pathlib.Path]

# Parameters: {name: default}, {name: (default, minimum, maximum)} or
# {name: {"default": ..., "minimum": ..., "maximum": ..., "type": "real" | "integer", "meaning": ...}}.
ParameterSpec = Mapping[str, Union[float, tuple[float, float, float], Mapping[str, Any]]]

@overload
def algorithm(function: AlgorithmFunction, *, name: Optional[str] = ..., title: Optional[str] = ...,
              parameters: Optional[ParameterSpec] = ..., epsilon_below: Optional[float] = ...,
              rho_below: Optional[float] = ..., uniformity_below: Optional[float] = ...,
              covers_open_curves: bool = ..., condition: Optional[str] = ...,
              capabilities: Optional[Mapping[str, Union[str, bool]]] = ...) -> Algorithm: ...
@overload
def algorithm(function: None = ..., *, name: Optional[str] = ..., title: Optional[str] = ...,
              parameters: Optional[ParameterSpec] = ..., epsilon_below: Optional[float] = ...,
              rho_below: Optional[float] = ..., uniformity_below: Optional[float] = ...,
              covers_open_curves: bool = ..., condition: Optional[str] = ...,
              capabilities: Optional[Mapping[str, Union[str, bool]]] = ...) -> Callable[[AlgorithmFunction], Algorithm]: ...

def algorithms() -> list[dict[str, Any]]: ...
def reconstruct(points: PointsLike, algorithm: AlgorithmLike = ..., **parameters: float) -> Reconstruction: ...
def graph(points: PointsLike, kind: str, *, beta: float = ..., k: int = ..., alpha: Optional[float] = ...) -> Edges: ...
def graph_kinds() -> list[tuple[str, str]]: ...
def suites() -> list[tuple[str, str]]: ...
def load_algorithm_file(path: Path) -> list[str]: ...
def sample(curve: str, epsilon: Optional[float] = ..., rho: Optional[float] = ..., uniform: Optional[int] = ...,
           random: Optional[int] = ..., *, safe: bool = ..., crossing_samples: bool = ...,
           minimum_lfs: Optional[float] = ..., uniform_noise: Optional[float] = ..., lfs_noise: Optional[float] = ...,
           outliers: Optional[float] = ..., seed: int = ...) -> Sample: ...
def measure(curve: str, points: PointsLike, edges: Optional[EdgesLike] = ..., *,
            minimum_lfs: Optional[float] = ...) -> dict[str, Any]: ...
def evaluate(points: PointsLike, edges: EdgesLike, truth: EdgesLike, curve: Optional[str] = ...) -> dict[str, Any]: ...
def run(suite: str, algorithms: Union[None, AlgorithmLike, Sequence[AlgorithmLike]] = ..., out: Optional[Path] = ...,
        *, jobs: int = ..., timeout: float = ..., pictures: Optional[Literal["some", "all", "failures", "none"]] = ...,
        resume: bool = ..., shard: Optional[str] = ..., report: bool = ..., progress: bool = ...) -> RunResult: ...
def certify(algorithm: AlgorithmLike, *, curves: str = ..., count: int = ..., rho: bool = ...,
            epsilon: Optional[float] = ..., below_bound: Optional[float] = ..., seed: int = ..., out: Optional[Path] = ...,
            jobs: int = ..., timeout: float = ..., resume: bool = ..., shard: Optional[str] = ...,
            progress: bool = ...) -> dict[str, Any]: ...
@overload
def tightness(algorithms: AlgorithmLike, *, rho: bool = ..., seconds: float = ..., curves: int = ..., moves: int = ...,
              seed: int = ..., out: Optional[Path] = ...) -> dict[str, Any]: ...
@overload
def tightness(algorithms: Sequence[AlgorithmLike], *, rho: bool = ..., seconds: float = ..., curves: int = ...,
              moves: int = ..., seed: int = ..., out: Optional[Path] = ...) -> list[dict[str, Any]]: ...
def hunt(algorithm: AlgorithmLike, *, seconds: float = ..., seed: int = ..., out: Optional[Path] = ...,
         timeout: float = ..., max_findings: int = ..., stop_after: int = ...) -> dict[str, Any]: ...
def plot(points: PointsLike, edges: EdgesLike, truth: Optional[EdgesLike] = ..., ax: Any = ..., *,
         title: Optional[str] = ..., point_size: float = ...) -> Any: ...
