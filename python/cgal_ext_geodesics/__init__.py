# Copyright (c) 2026 The CGAL_ext geodesics developers.
"""Exact discrete geodesics on triangle meshes, on NumPy arrays.

Distances from vertices or points inside faces (VTP, MMP, approximate AVTP),
shortest paths, geodesic Voronoi diagrams, farthest-point sampling, dense and
sparse distance matrices, and repetitive pattern detection, from the CGAL_ext
geodesics package. The computations run in C++ without the GIL, on every core
unless told otherwise, and give the same results for every number of threads.

Start with a mesh::

    import numpy as np
    import cgal_ext_geodesics as geo

    mesh = geo.Mesh(V, F)               # or geo.read_mesh("bunny.off")
    d = mesh.distances(0)               # exact distances from vertex 0, (n,)
    d = geo.distances(V, F, [0, 17])    # the same without keeping the mesh
    paths = geo.GeodesicPaths(mesh, 0)
    xyz = paths.path(123)               # (k, 3), from the source to vertex 123

Sources and targets are vertex ids or face points ``(face, (b0, b1, b2))``.
Bad input raises ``GeodesicError`` (a ValueError) naming what is wrong and
where; a ``progress`` function returning False raises ``Cancelled``; Ctrl-C
interrupts any computation within a fraction of a second.
"""

from dataclasses import dataclass
from typing import List, Optional, Tuple

import numpy as np

from ._geodesics import Cancelled, GeodesicError, GeodesicPaths, Mesh
from ._geodesics import _detect_patterns, _farthest_point_sampling, _voronoi

__all__ = [
    "Mesh", "GeodesicPaths", "GeodesicError", "Cancelled", "read_mesh",
    "distances", "distance_matrix", "voronoi", "farthest_point_sampling", "detect_patterns",
    "VoronoiDiagram", "Sampling", "PatternInstances",
]


def read_mesh(path):
    """Reads a mesh file (.off, .obj, .ply or .stl, ASCII or binary) into a :class:`Mesh`.

    Polygon soups are repaired as :class:`Mesh` does; ``mesh.repairs`` says what was done.
    Raises FileNotFoundError (IsADirectoryError) when there is no such file, as open() does, and
    GeodesicError when the file cannot be read or made into a mesh.
    """
    return Mesh.read(path)


def _as_mesh(vertices, faces):
    if isinstance(vertices, Mesh):
        if faces is not None:
            raise GeodesicError("give a Mesh, or vertices and faces, not both")
        return vertices
    return Mesh(vertices, faces)


@dataclass
class VoronoiDiagram:
    """A geodesic Voronoi diagram, in the mesh's vertex ids.

    cells: (n,) int64, the source (index in the order given) of each vertex's cell, -1 if none reaches it.
    distances: (n,) float64, the distance of each vertex to its nearest source.
    bisectors: one dict per curve between two cells: 'sources' (i, j) and 'points' (k, 3).
    vertices: (p, 3) float64, the points where three or more cells meet.
    vertex_sources: the sources of the cells meeting at each vertex.
    dual_edges: (e, 2) int64, pairs of sources whose cells share a bisector.
    dual_triangles: (t, 3) int64, triples of sources whose cells meet at a vertex.
    unresolved_parts: parts of faces where more cells meet than could be told apart (0 almost always).
    """
    cells: np.ndarray
    distances: np.ndarray
    bisectors: List[dict]
    vertices: np.ndarray
    vertex_sources: List[Tuple[int, ...]]
    dual_edges: np.ndarray
    dual_triangles: np.ndarray
    unresolved_parts: int


@dataclass
class Sampling:
    """Farthest-point samples.

    samples: (k,) int64, vertex ids, in the order they were chosen.
    radii: (k,) float64, the covering radius after each sample (the largest distance of a vertex to the samples so far).
    distances: (n,) float64, each vertex's distance to its nearest sample.
    nearest_samples: (n,) int64, the index (in `samples`) of each vertex's nearest sample.
    """
    samples: np.ndarray
    radii: np.ndarray
    distances: np.ndarray
    nearest_samples: np.ndarray


@dataclass
class PatternInstances:
    """Instances of a repetitive pattern.

    instances: one dict per instance: 'center' (3,), 'center_vertex', 'scale' (relative to the
        marked instance), 'energy' (how well it matches: lower is better), 'vertices' (int64 ids)
        and 'correspondence' (c, 2): pairs (vertex of the marked instance, vertex of this one).
    labels: (n,) int64, the instance of each vertex, -1 for none.
    arrangement_edges: (e, 2) int64, neighbouring instances.
    arrangement_triangles: (t, 3) int64, triangles of neighbouring instances.
    """
    instances: List[dict]
    labels: np.ndarray
    arrangement_edges: np.ndarray
    arrangement_triangles: np.ndarray

    def centers(self):
        """The centres of the instances, (k, 3) float64."""
        return np.array([i["center"] for i in self.instances], dtype=np.float64).reshape(-1, 3)


def _distance_matrix(self, sources, targets=None, max_distance=None, threads=None, progress=None):
    """The geodesic distances from each source alone to the targets, one row per source.

    sources: vertex ids or face points, one row each (as for `distances`).
    targets: vertex ids, one column each; None for every vertex.
    max_distance: None for a dense (sources, targets) float64 numpy.ndarray; a number for the
        local matrix of the entries within that distance, as a scipy.sparse.csr_matrix (the
        entries beyond are absent, not inf). Without SciPy, raises ImportError naming it.
    threads: None for every core; the rows are the same for every number of threads.
    progress: a function called with the fraction of rows done; returning False cancels.

    The rows are solved in parallel and written into the result as they come, so that a
    dense matrix takes its own size in memory and a sparse one the size of its entries.
    """
    if max_distance is not None and max_distance == float("inf"):
        max_distance = None  # (NaN goes on, to be refused with the other bad values)
    if max_distance is not None:
        try:
            import scipy.sparse
        except ImportError as e:
            raise ImportError("a distance matrix with max_distance is a scipy.sparse.csr_matrix: "
                              "install SciPy (python3-scipy), or leave max_distance=None for a dense array") from e
    raw = self._distance_matrix(sources, targets, max_distance, threads, progress)
    if max_distance is None:
        return raw
    data, indices, indptr, shape = raw
    return scipy.sparse.csr_matrix((data, indices, indptr), shape=shape)


def _mesh_voronoi(self, sources, algorithm=None, threads=None, progress=None):
    """The geodesic Voronoi diagram of the sources (vertex ids or face points), exact.

    algorithm: 'pvtp' (the default), 'vtp', 'pmmp', 'fwp_mmp' or 'mmp', as for `distances`;
    threads: None for every core (the parallel algorithms give the same diagram for every
    number). Returns a :class:`VoronoiDiagram`.
    """
    return VoronoiDiagram(**_voronoi(self, sources, algorithm, threads, progress))


def _mesh_farthest_point_sampling(self, count=None, radius=None, first=None, threads=None, lam=None,
                                  progress=None):
    """Farthest-point sampling with exact geodesic distances (or AVTP's with `lam`).

    count: at most this many samples (at least 1, at most the number of vertices); None with a
        radius: as many as the radius needs.
    radius: stop once every vertex is within this distance of a sample.
    first: the first sample (a vertex id) or the initial samples (ids); None: the vertex farthest
        from vertex 0. Returns a :class:`Sampling`.
    """
    if count is None:
        if radius is None:
            raise GeodesicError("farthest_point_sampling: give a count, a radius, or both")
        count = self.n_vertices
    return Sampling(**_farthest_point_sampling(self, count, radius, first, threads, lam, progress))


def _mesh_detect_patterns(self, center=None, radius=None, vertices=None, scales=None, stroke=None,
                          sample_spacing=1.0 / 3, match_tolerance=0.35, consistency_cutoff=0.7,
                          lam=None, threads=None, progress=None):
    """The instances of a repetitive pattern, from one marked instance (thesis chapter 5).

    Mark the instance with ``center`` (a vertex id) and ``radius`` (its geodesic radius), or
    with ``vertices`` (its vertex ids). scales: (a, b), the sizes sought relative to the marked
    one (default (1, 1)); stroke: vertex ids across instances of changing size. sample_spacing,
    match_tolerance and consistency_cutoff are the detector's knobs (see the manual);
    lam: approximate local distances. Returns :class:`PatternInstances`.
    """
    return PatternInstances(**_detect_patterns(self, center, radius, vertices, scales, stroke, sample_spacing,
                                               match_tolerance, consistency_cutoff, lam, threads, progress))


Mesh.distance_matrix = _distance_matrix
Mesh.voronoi = _mesh_voronoi
Mesh.farthest_point_sampling = _mesh_farthest_point_sampling
Mesh.detect_patterns = _mesh_detect_patterns


def distances(vertices, faces, sources, **options):
    """Geodesic distances from the nearest source to every vertex of the mesh (vertices, faces).

    The same as ``Mesh(vertices, faces).distances(sources, **options)``; keep a :class:`Mesh`
    to solve again on the same mesh without preparing it again.
    """
    return _as_mesh(vertices, faces).distances(sources, **options)


def distance_matrix(vertices, faces, sources, targets=None, max_distance=None, **options):
    """The distance matrix from each source to the targets; see :meth:`Mesh.distance_matrix`."""
    return _as_mesh(vertices, faces).distance_matrix(sources, targets, max_distance, **options)


def voronoi(vertices, faces, sources, **options):
    """The geodesic Voronoi diagram of the sources; see :meth:`Mesh.voronoi`."""
    return _as_mesh(vertices, faces).voronoi(sources, **options)


def farthest_point_sampling(vertices, faces, count=None, **options):
    """Farthest-point samples of the mesh; see :meth:`Mesh.farthest_point_sampling`."""
    return _as_mesh(vertices, faces).farthest_point_sampling(count, **options)


def detect_patterns(vertices, faces, **options):
    """The instances of a repetitive pattern from one marked instance; see :meth:`Mesh.detect_patterns`."""
    return _as_mesh(vertices, faces).detect_patterns(**options)
