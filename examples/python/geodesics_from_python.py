#!/usr/bin/env python3
"""Exact geodesics from Python with cgal_ext_geodesics: distances from a vertex and from a point
inside a face, the nearest of two sources, a shortest path, a local sparse distance matrix,
farthest-point samples and a geodesic Voronoi diagram.

Usage: geodesics_from_python.py [MESH]   (OFF, OBJ, PLY or STL; default: data/elephant.off)
From a build tree: PYTHONPATH=BUILD/python /usr/bin/python3 examples/python/geodesics_from_python.py
"""

import sys
from pathlib import Path

import numpy as np

import cgal_ext_geodesics as geo

DEFAULT_MESH = Path(__file__).resolve().parent.parent.parent / "data" / "elephant.off"


def a_triangle(mesh):
    """A face of the input that is a triangle, near the middle of the face list."""
    faces = mesh.faces
    if isinstance(faces, np.ndarray):  # every face is a triangle
        return mesh.n_faces // 2
    # Face points are barycentric coordinates of an input triangle: polygons cannot hold one.
    triangles = [f for f, polygon in enumerate(faces) if len(polygon) == 3]
    if not triangles:
        sys.exit("this mesh has no triangle to put a face point in")
    return triangles[len(triangles) // 2]


def main():
    path = sys.argv[1] if len(sys.argv) > 1 else DEFAULT_MESH
    try:
        mesh = geo.read_mesh(path)
    except geo.GeodesicError as e:
        sys.exit(f"error: {e}")
    print(mesh)
    if mesh.repairs["changed"]:
        print("  repaired:", mesh.repairs["summary"])

    # One Mesh for every call below: the solver mesh is prepared at the first solve and reused.
    d = mesh.distances(0)
    reached = np.isfinite(d)  # other connected components are at inf
    farthest = int(np.argmax(np.where(reached, d, -1.0)))
    print(f"from vertex 0: the farthest vertex is {farthest}, at {d[farthest]:.6g}"
          f" ({np.count_nonzero(~reached)} vertices unreached)")

    face = a_triangle(mesh)
    bary = (0.2, 0.3, 0.5)
    face_point = (face, bary)
    # The coordinates follow the order of the face's vertices in mesh.faces.
    xyz = np.asarray(bary) @ mesh.vertices[mesh.faces[face]]
    d_face = mesh.distances(face_point)
    print(f"from a point of face {face} at {np.round(xyz, 4)}: vertex 0 is at {d_face[0]:.6g}")

    # Both sources in one propagation: each vertex gets the nearer one, its Voronoi cell.
    d_both, nearest = mesh.distances([0, face_point], return_sources=True)
    cells = np.bincount(nearest[nearest >= 0], minlength=2)
    print(f"nearest source: {cells[0]} vertices nearer to vertex 0, {cells[1]} to the face point")

    # GeodesicPaths keeps the windows of its propagation: each later target is a query only.
    paths = geo.GeodesicPaths(mesh, [0, face_point])
    target = mesh.n_vertices // 2
    polyline = paths.path(target)
    if len(polyline) == 0:
        print(f"path to vertex {target}: no source reaches it")
    else:
        length = np.linalg.norm(np.diff(polyline, axis=0), axis=1).sum()
        print(f"path to vertex {target}: {len(polyline)} points from source {paths.nearest_source(target)},"
              f" length {length:.6g} (distance {paths.distance(target):.6g})")

    try:
        import scipy.sparse  # noqa: F401  (only the sparse matrix needs it)
    except ImportError:
        print("local distance matrix: skipped, SciPy is not installed (python3-scipy)")
    else:
        # A radius relative to the mesh's size, so that any mesh gives a few neighbours per row.
        radius = 0.05 * d[farthest]
        local = mesh.distance_matrix(np.arange(mesh.n_vertices), max_distance=radius)
        print(f"local distance matrix within {radius:.3g}: {local.shape[0]} x {local.shape[1]},"
              f" {local.nnz} entries, {local.nnz / local.shape[0]:.1f} per row")

    count = min(10, mesh.n_vertices)
    sampling = mesh.farthest_point_sampling(count)
    print(f"{count} farthest-point samples: {sampling.samples.tolist()},"
          f" covering radius {sampling.radii[-1]:.6g}")

    # The samples' nearest_samples are the cells at the vertices; the diagram also gives the
    # bisectors across faces and the dual graph.
    voronoi = mesh.voronoi(sampling.samples)
    print(f"Voronoi diagram of the samples: cells of {np.bincount(voronoi.cells[voronoi.cells >= 0]).tolist()}"
          f" vertices, {len(voronoi.bisectors)} bisectors, {len(voronoi.vertices)} Voronoi vertices,"
          f" {len(voronoi.dual_edges)} dual edges, {len(voronoi.dual_triangles)} dual triangles")


if __name__ == "__main__":
    main()
