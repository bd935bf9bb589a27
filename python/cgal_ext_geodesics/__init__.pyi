# Copyright (c) 2026 The CGAL_ext geodesics developers.
# Type stubs of cgal_ext_geodesics, for editors and type checkers.

from dataclasses import dataclass
from os import PathLike
from typing import Any, Callable, List, Literal, Optional, Sequence, Tuple, Union, overload

import numpy as np
import numpy.typing as npt

ExactAlgorithm = Literal["pvtp", "vtp", "pmmp", "fwp_mmp", "fwp-mmp", "mmp"]
Algorithm = Union[ExactAlgorithm, Literal["pavtp", "avtp"]]
FacePoint = Tuple[int, Tuple[float, float, float]]
Point = Union[int, np.integer, FacePoint]
Sources = Union[Point, Sequence[Point], npt.NDArray[np.integer], Tuple[npt.ArrayLike, npt.ArrayLike]]
Progress = Optional[Callable[[float], Optional[bool]]]
Vertices = npt.ArrayLike
Faces = Union[npt.ArrayLike, Sequence[Sequence[int]]]

class GeodesicError(ValueError): ...
class Cancelled(Exception): ...

class Mesh:
    def __init__(self, vertices: Vertices, faces: Faces) -> None: ...
    @staticmethod
    def read(path: Union[str, bytes, PathLike]) -> Mesh: ...
    @property
    def vertices(self) -> npt.NDArray[np.float64]: ...
    @property
    def faces(self) -> Union[npt.NDArray[np.int64], List[npt.NDArray[np.int64]]]: ...
    @property
    def n_vertices(self) -> int: ...
    @property
    def n_faces(self) -> int: ...
    @property
    def repairs(self) -> dict: ...
    @overload
    def distances(self, sources: Sources, algorithm: Optional[Algorithm] = ..., threads: Optional[int] = ...,
                  max_distance: Optional[float] = ..., stop_vertices: Optional[Sources] = ...,
                  lam: Optional[float] = ..., return_sources: Literal[False] = ...,
                  progress: Progress = ...) -> npt.NDArray[np.float64]: ...
    @overload
    def distances(self, sources: Sources, algorithm: Optional[Algorithm] = ..., threads: Optional[int] = ...,
                  max_distance: Optional[float] = ..., stop_vertices: Optional[Sources] = ...,
                  lam: Optional[float] = ..., *, return_sources: Literal[True],
                  progress: Progress = ...) -> Tuple[npt.NDArray[np.float64], npt.NDArray[np.int64]]: ...
    def distance_matrix(self, sources: Sources, targets: Optional[Sources] = ..., max_distance: Optional[float] = ...,
                        threads: Optional[int] = ..., progress: Progress = ...) -> Any: ...
    def voronoi(self, sources: Sources, algorithm: Optional[ExactAlgorithm] = ..., threads: Optional[int] = ...,
                progress: Progress = ...) -> VoronoiDiagram: ...
    def farthest_point_sampling(self, count: Optional[int] = ..., radius: Optional[float] = ..., first: Optional[Sources] = ...,
                                threads: Optional[int] = ..., lam: Optional[float] = ...,
                                progress: Progress = ...) -> Sampling: ...
    def detect_patterns(self, center: Optional[int] = ..., radius: Optional[float] = ...,
                        vertices: Optional[Sequence[int]] = ..., scales: Optional[Tuple[float, float]] = ...,
                        stroke: Optional[Sequence[int]] = ..., sample_spacing: float = ...,
                        match_tolerance: float = ..., consistency_cutoff: float = ..., lam: Optional[float] = ...,
                        threads: Optional[int] = ..., progress: Progress = ...) -> PatternInstances: ...

class GeodesicPaths:
    def __init__(self, mesh: Mesh, sources: Sources, algorithm: Optional[ExactAlgorithm] = ..., threads: Optional[int] = ...,
                 max_distance: Optional[float] = ..., progress: Progress = ...) -> None: ...
    @property
    def n_sources(self) -> int: ...
    @property
    def mesh(self) -> Mesh: ...
    def distance(self, target: Point) -> float: ...
    def nearest_source(self, target: Point) -> int: ...
    def distances(self) -> npt.NDArray[np.float64]: ...
    def nearest_sources(self) -> npt.NDArray[np.int64]: ...
    def path(self, target: Point) -> npt.NDArray[np.float64]: ...
    def path_locations(self, target: Point) -> Tuple[npt.NDArray[np.int64], npt.NDArray[np.float64]]: ...

@dataclass
class VoronoiDiagram:
    cells: npt.NDArray[np.int64]
    distances: npt.NDArray[np.float64]
    bisectors: List[dict]
    vertices: npt.NDArray[np.float64]
    vertex_sources: List[Tuple[int, ...]]
    dual_edges: npt.NDArray[np.int64]
    dual_triangles: npt.NDArray[np.int64]
    unresolved_parts: int

@dataclass
class Sampling:
    samples: npt.NDArray[np.int64]
    radii: npt.NDArray[np.float64]
    distances: npt.NDArray[np.float64]
    nearest_samples: npt.NDArray[np.int64]

@dataclass
class PatternInstances:
    instances: List[dict]
    labels: npt.NDArray[np.int64]
    arrangement_edges: npt.NDArray[np.int64]
    arrangement_triangles: npt.NDArray[np.int64]
    def centers(self) -> npt.NDArray[np.float64]: ...

def read_mesh(path: Union[str, bytes, PathLike]) -> Mesh: ...
def distances(vertices: Union[Vertices, Mesh], faces: Optional[Faces], sources: Sources,
              **options: Any) -> Any: ...
def distance_matrix(vertices: Union[Vertices, Mesh], faces: Optional[Faces], sources: Sources,
                    targets: Optional[Sources] = ..., max_distance: Optional[float] = ..., **options: Any) -> Any: ...
def voronoi(vertices: Union[Vertices, Mesh], faces: Optional[Faces], sources: Sources,
            **options: Any) -> VoronoiDiagram: ...
def farthest_point_sampling(vertices: Union[Vertices, Mesh], faces: Optional[Faces], count: Optional[int] = ...,
                            **options: Any) -> Sampling: ...
def detect_patterns(vertices: Union[Vertices, Mesh], faces: Optional[Faces], **options: Any) -> PatternInstances: ...
