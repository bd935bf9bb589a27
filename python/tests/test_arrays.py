# Copyright (c) 2026 The CGAL_ext geodesics developers.
"""The arrays in and out: shapes, dtypes, views, polygon soups and repairs, and the properties
every geodesic distance has (symmetry, the triangle inequality, the same bytes on any number of
threads)."""

import numpy as np
import pytest
import scipy.sparse

import cgal_ext_geodesics as geo


def flat_grid(n, seed=0, jitter=0.3):
    """A flat, jittered n x n grid in z = 0: geodesic distances are the Euclidean ones."""
    rng = np.random.default_rng(seed)
    x, y = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n), indexing="ij")
    h = 1.0 / (n - 1)
    inner = np.zeros_like(x, dtype=bool)
    inner[1:-1, 1:-1] = True
    x = x + inner * rng.uniform(-jitter, jitter, x.shape) * h
    y = y + inner * rng.uniform(-jitter, jitter, y.shape) * h
    V = np.stack([x, y, np.zeros_like(x)], -1).reshape(-1, 3)
    i = (np.arange(n - 1)[:, None] * n + np.arange(n - 1)[None, :]).ravel()
    F = np.concatenate([np.stack([i, i + n, i + 1], 1), np.stack([i + 1, i + n, i + n + 1], 1)])
    quads = np.stack([i, i + n, i + n + 1, i + 1], 1)
    return V, F, quads


@pytest.fixture(scope="module")
def mushroom(data_dir):
    return geo.read_mesh(data_dir / "mushroom.off")


# ----------------------------------------------------------------------------------------------
# shapes and dtypes


def check_array(a, shape, dtype, what):
    assert isinstance(a, np.ndarray), f"{what}: a {type(a).__name__}, not a numpy array"
    assert a.dtype == dtype, f"{what}: dtype {a.dtype}, not {np.dtype(dtype)}"
    assert a.shape == shape, f"{what}: shape {a.shape}, not {shape}"


def test_mesh_properties(mushroom):
    n, m = mushroom.n_vertices, mushroom.n_faces
    assert (n, m) == (2337, 4608)
    check_array(mushroom.vertices, (n, 3), np.float64, "vertices")
    check_array(mushroom.faces, (m, 3), np.int64, "faces")
    r = mushroom.repairs
    assert isinstance(r, dict) and r["changed"] is False and r["summary"] == ""
    for k in ("merged_points", "removed_polygons", "split_polygons", "triangulated_polygons", "reversed_polygons",
              "duplicated_points", "non_manifold_edges", "isolated_points"):
        assert r[k] == 0, f"repairs[{k!r}] of a clean mesh is {r[k]}"
    assert "2337 vertices" in repr(mushroom)


def test_distances_shapes_and_dtypes(mushroom):
    n = mushroom.n_vertices
    check_array(mushroom.distances(0), (n,), np.float64, "distances")
    d, labels = mushroom.distances([0, 9], return_sources=True)
    check_array(d, (n,), np.float64, "distances with labels")
    check_array(labels, (n,), np.int64, "labels")
    for algorithm in ("pvtp", "vtp", "pmmp", "fwp_mmp", "mmp", "fwp-mmp", "VTP", "avtp", "pavtp"):
        check_array(mushroom.distances(0, algorithm=algorithm), (n,), np.float64, f"distances, {algorithm}")
    d = mushroom.distances(0, max_distance=0.1)
    assert np.isinf(d).any() and np.all(d[np.isfinite(d)] <= 0.1)
    d = mushroom.distances(0, max_distance=0.0)
    assert d[0] == 0 and np.isfinite(d).sum() >= 1
    d = mushroom.distances(0, stop_vertices=[5])
    assert np.isfinite(d[5]) and d[5] == mushroom.distances(0)[5]


def test_matrix_shapes_and_dtypes(mushroom):
    n = mushroom.n_vertices
    check_array(mushroom.distance_matrix([0, 1, 2]), (3, n), np.float64, "dense matrix")
    check_array(mushroom.distance_matrix(np.array([4]), targets=[0, 1]), (1, 2), np.float64, "dense, targets")
    check_array(mushroom.distance_matrix(7), (1, n), np.float64, "dense, one source")
    s = mushroom.distance_matrix([0, 1, 2], max_distance=0.2)
    assert isinstance(s, scipy.sparse.csr_matrix) and s.shape == (3, n) and s.dtype == np.float64
    s = mushroom.distance_matrix([0, 1, 2], targets=[5, 6], max_distance=0.2)
    assert isinstance(s, scipy.sparse.csr_matrix) and s.shape == (3, 2)
    # an infinite max_distance is no max distance: the dense matrix
    assert isinstance(mushroom.distance_matrix([0], max_distance=np.inf), np.ndarray)


def test_paths_shapes_and_dtypes(mushroom):
    n = mushroom.n_vertices
    p = geo.GeodesicPaths(mushroom, [0, 100])
    assert p.n_sources == 2 and p.mesh is mushroom
    assert isinstance(p.distance(50), float) and isinstance(p.nearest_source(50), int)
    check_array(p.distances(), (n,), np.float64, "paths.distances()")
    check_array(p.nearest_sources(), (n,), np.int64, "paths.nearest_sources()")
    xyz = p.path(2000)
    assert xyz.ndim == 2 and xyz.shape[1] == 3 and xyz.dtype == np.float64 and len(xyz) >= 2
    faces, bary = p.path_locations(2000)
    check_array(faces, (len(xyz),), np.int64, "path_locations faces")
    check_array(bary, (len(xyz), 3), np.float64, "path_locations barycentric")
    # the locations are the points
    F, V = mushroom.faces, mushroom.vertices
    at = np.einsum("kj,kjc->kc", bary, V[F[faces]])
    np.testing.assert_allclose(at, xyz, atol=1e-12, err_msg="path_locations and path")
    np.testing.assert_allclose(bary.sum(axis=1), 1, atol=1e-12)
    # a face point target
    assert p.path((30, (0.2, 0.3, 0.5))).shape[1] == 3
    # a path of a source to itself: one point
    assert geo.GeodesicPaths(mushroom, 7).path(7).shape == (1, 3)


def test_paths_beyond_max_distance(mushroom):
    p = geo.GeodesicPaths(mushroom, 0, max_distance=0.05)
    far = int(np.argmax(mushroom.distances(0)))
    assert p.distance(far) == np.inf and p.nearest_source(far) == -1
    assert p.path(far).shape == (0, 3)
    assert p.nearest_sources()[far] == -1


def test_voronoi_shapes_and_dtypes(mushroom):
    n = mushroom.n_vertices
    v = mushroom.voronoi([0, 100, 1000, 2000])
    assert isinstance(v, geo.VoronoiDiagram)
    check_array(v.cells, (n,), np.int64, "cells")
    check_array(v.distances, (n,), np.float64, "voronoi distances")
    assert v.vertices.dtype == np.float64 and v.vertices.ndim == 2 and v.vertices.shape[1] == 3
    assert len(v.vertex_sources) == len(v.vertices) and all(isinstance(t, tuple) for t in v.vertex_sources)
    assert v.dual_edges.dtype == np.int64 and v.dual_edges.shape[1:] == (2,) and len(v.dual_edges) >= 3
    assert v.dual_triangles.dtype == np.int64 and v.dual_triangles.shape[1:] == (3,)
    assert isinstance(v.unresolved_parts, int)
    for b in v.bisectors:
        assert len(b["sources"]) == 2 and b["points"].dtype == np.float64 and b["points"].shape[1] == 3
    assert set(np.unique(v.cells)) == {0, 1, 2, 3}


def test_sampling_shapes_and_dtypes(mushroom):
    n = mushroom.n_vertices
    s = mushroom.farthest_point_sampling(6)
    assert isinstance(s, geo.Sampling)
    check_array(s.samples, (6,), np.int64, "samples")
    check_array(s.radii, (6,), np.float64, "radii")
    check_array(s.distances, (n,), np.float64, "sampling distances")
    check_array(s.nearest_samples, (n,), np.int64, "nearest samples")
    assert len(set(s.samples.tolist())) == 6
    assert np.all(s.distances[s.samples] == 0)
    assert np.all(s.nearest_samples[s.samples] == np.arange(6))
    # the first sample, by default, is the vertex farthest from vertex 0
    assert s.samples[0] == np.argmax(mushroom.distances(0))
    assert mushroom.farthest_point_sampling(3, first=[1, 2, 3]).samples.tolist() == [1, 2, 3]


def test_patterns_shapes_and_dtypes(mushroom):
    V, F = np.array(mushroom.vertices), mushroom.faces
    p = geo.detect_patterns(V, F, center=0, radius=0.1)
    assert isinstance(p, geo.PatternInstances)
    check_array(p.labels, (len(V),), np.int64, "pattern labels")
    assert len(p.instances) >= 1
    assert p.arrangement_edges.dtype == np.int64 and p.arrangement_edges.shape[1:] == (2,)
    assert p.arrangement_triangles.dtype == np.int64 and p.arrangement_triangles.shape[1:] == (3,)
    check_array(p.centers(), (len(p.instances), 3), np.float64, "centers()")
    for i in p.instances:
        check_array(i["center"], (3,), np.float64, "instance center")
        assert i["vertices"].dtype == np.int64 and i["correspondence"].dtype == np.int64
        assert i["correspondence"].shape[1:] == (2,)
        assert isinstance(i["scale"], float) and isinstance(i["energy"], float)
    marked = np.flatnonzero(mushroom.distances(0) < 0.05)
    q = mushroom.detect_patterns(vertices=marked)
    assert isinstance(q, geo.PatternInstances) and len(q.instances) >= 1


# ----------------------------------------------------------------------------------------------
# input dtypes


@pytest.mark.parametrize("vdtype", [np.float64, np.float32, np.int64, np.float16])
@pytest.mark.parametrize("fdtype", [np.int64, np.int32, np.uint16, np.uint32, np.int16])
def test_any_dtype_gives_the_same_result(vdtype, fdtype):
    V, F, _ = flat_grid(20, seed=5)
    V = V * 100 + np.array([0, 0, 1]) * (np.arange(len(V)) % 3)[:, None]  # not flat, integers make sense
    Vt = V.astype(vdtype)
    reference = geo.Mesh(Vt.astype(np.float64), F)
    mesh = geo.Mesh(Vt, F.astype(fdtype))
    what = f"vertices {np.dtype(vdtype)}, faces {np.dtype(fdtype)}"
    assert mesh.vertices.dtype == np.float64 and np.array_equal(mesh.vertices, Vt.astype(np.float64)), what
    assert np.array_equal(mesh.faces, F), what
    assert mesh.distances(3).tobytes() == reference.distances(3).tobytes(), what
    sources = np.array([3, 77], dtype=fdtype)
    assert mesh.distances(sources).tobytes() == reference.distances([3, 77]).tobytes(), what + ", array sources"
    assert mesh.distances(fdtype(3)).tobytes() == reference.distances(3).tobytes(), what + ", numpy scalar source"


def test_non_contiguous_and_fortran_arrays():
    V, F, _ = flat_grid(15, seed=2)
    reference = geo.Mesh(V, F).distances(0)
    W = np.zeros((len(V), 6))
    W[:, ::2] = V
    G = np.zeros((len(F), 3, 2), dtype=np.int64)
    G[:, :, 0] = F
    assert not W[:, ::2].flags.c_contiguous and not G[:, :, 0].flags.c_contiguous
    for Vx, Fx in [(np.asfortranarray(V), np.asfortranarray(F)), (W[:, ::2], G[:, :, 0]),
                   (V.tolist(), F.tolist())]:
        assert geo.Mesh(Vx, Fx).distances(0).tobytes() == reference.tobytes()


def test_sources_in_every_form(mushroom):
    n_ref = mushroom.distances([3, 8])
    for sources in ([3, 8], (3, 8), np.array([3, 8]), np.array([3, 8], dtype=np.uint8), [np.int32(3), np.int64(8)]):
        assert mushroom.distances(sources).tobytes() == n_ref.tobytes(), f"sources {sources!r}"
    fp = (12, (0.2, 0.3, 0.5))
    one = mushroom.distances(fp)
    for sources in ([fp], (12, np.array([0.2, 0.3, 0.5])), (np.array([12]), np.array([[0.2, 0.3, 0.5]])),
                    [(np.int64(12), [0.2, 0.3, 0.5])]):
        assert mushroom.distances(sources).tobytes() == one.tobytes(), f"sources {sources!r}"
    # a face point at a corner is that vertex
    corner = mushroom.faces[12][1]
    assert np.array_equal(mushroom.distances((12, (0.0, 1.0, 0.0))), mushroom.distances(int(corner)))
    # a vertex and a face point together, with labels in the order given
    d, labels = mushroom.distances([3, fp], return_sources=True)
    assert labels[3] == 0 and np.array_equal(d, np.minimum(mushroom.distances(3), one))


# ----------------------------------------------------------------------------------------------
# the vertices view


def test_vertices_is_a_read_only_view(mushroom):
    a, b = mushroom.vertices, mushroom.vertices
    assert np.shares_memory(a, b), "each access to vertices copies the array"
    assert not a.flags.writeable and not a.flags.owndata
    assert a.base is not None
    with pytest.raises(ValueError):
        a[0, 0] = 1.0
    with pytest.raises(ValueError):
        a.setflags(write=True)


def test_vertices_view_keeps_the_mesh_alive():
    V, F, _ = flat_grid(10)
    v = geo.Mesh(V, F).vertices  # the mesh is gone but for the view
    import gc

    gc.collect()
    assert np.array_equal(v, V)


def test_vertices_are_a_copy_of_the_input():
    V, F, _ = flat_grid(10)
    mesh = geo.Mesh(V, F)
    V[0] = 99.0
    assert not np.shares_memory(mesh.vertices, V) and mesh.vertices[0, 0] == 0.0


# ----------------------------------------------------------------------------------------------
# polygons, soups, non-manifold input


def test_quads_are_triangulated():
    V, F, quads = flat_grid(9, seed=3, jitter=0.0)
    mesh = geo.Mesh(V, quads)
    assert mesh.repairs["triangulated_polygons"] == len(quads), mesh.repairs
    assert mesh.repairs["changed"] and "triangulated" in mesh.repairs["summary"]
    assert mesh.n_faces == len(quads)
    faces = mesh.faces
    assert isinstance(faces, list) and len(faces) == len(quads)
    assert all(f.dtype == np.int64 and f.tolist() == q.tolist() for f, q in zip(faces, quads))
    d = mesh.distances(0)
    np.testing.assert_allclose(d, np.linalg.norm(V - V[0], axis=1), rtol=1e-12, atol=1e-15,
                               err_msg="flat quads: geodesic distances are the Euclidean ones")
    # the path across the quads: the diagonal, its points in no input triangle (-1, NaN)
    p = geo.GeodesicPaths(mesh, 0)
    xyz = p.path(len(V) - 1)
    np.testing.assert_allclose(xyz[:, 0], xyz[:, 1], atol=1e-12, err_msg="the path across flat quads is straight")
    faces, bary = p.path_locations(len(V) - 1)
    assert len(faces) == len(xyz) and np.all(faces == -1) and np.all(np.isnan(bary))
    # a face point in a quad is refused, saying so
    with pytest.raises(geo.GeodesicError, match="not a triangle"):
        mesh.distances((0, (0.2, 0.3, 0.5)))


def test_mixed_polygons_as_lists():
    V, F, quads = flat_grid(6, jitter=0.0)
    polygons = [list(q) for q in quads[:5]] + [[int(a), int(b), int(c)] for q in quads[5:] for a, b, c in
                                               ((q[0], q[1], q[2]), (q[0], q[2], q[3]))]
    mesh = geo.Mesh(V, polygons)
    assert mesh.repairs["triangulated_polygons"] == 5, mesh.repairs
    assert mesh.n_faces == len(polygons)
    np.testing.assert_allclose(mesh.distances(0), np.linalg.norm(V - V[0], axis=1), rtol=1e-12, atol=1e-15)
    # an (m, 4) array of quads and the same as lists
    assert np.array_equal(geo.Mesh(V, quads).distances(0), geo.Mesh(V, quads.tolist()).distances(0))


def test_soup_with_duplicate_points_is_merged(mushroom):
    V, F = np.array(mushroom.vertices), mushroom.faces
    soup_V = V[F].reshape(-1, 3)
    soup_F = np.arange(len(soup_V)).reshape(-1, 3)
    soup = geo.Mesh(soup_V, soup_F)
    assert soup.repairs["merged_points"] == len(soup_V) - len(V), soup.repairs
    assert soup.n_vertices == len(soup_V) and soup.repairs["changed"]
    d = soup.distances(0)  # point 0 of the soup is vertex F[0, 0]
    expected = mushroom.distances(int(F[0, 0]))[F.ravel()]
    np.testing.assert_allclose(d, expected, rtol=1e-12, atol=1e-15, err_msg="the merged soup and the mesh")
    # every copy of a point has the same distance
    assert np.all(d.reshape(-1, 3) == expected.reshape(-1, 3))


def tetrahedron(center, size=1.0):
    return center + size * np.array([[1, 1, 1], [1, -1, -1], [-1, 1, -1], [-1, -1, 1]], dtype=float)


def test_bow_tie_of_two_tetrahedra():
    # tetrahedron A: points 0-3; tetrahedron B: point 3 (shared) and points 4-6
    A = tetrahedron(np.zeros(3))
    shared = A[3]
    B = shared + (shared - A[:3])  # B's other corners, mirrored through the shared point
    V = np.vstack([A, B])
    FA = np.array([[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]])
    FB = np.array([[4, 5, 6], [4, 3, 5], [4, 6, 3], [5, 3, 6]])
    mesh = geo.Mesh(V, np.vstack([FA, FB]))
    d = mesh.distances(0)
    assert np.all(np.isfinite(d)), f"the bow-tie's far tetrahedron is not reached: {d}"
    # on a tetrahedron, the shortest path between two corners is their edge
    for b in (4, 5, 6):
        expected = np.linalg.norm(V[0] - V[3]) + np.linalg.norm(V[3] - V[b])
        assert d[b] == pytest.approx(expected, rel=1e-12), f"vertex {b} across the shared vertex"
    assert mesh.repairs["changed"], mesh.repairs
    p = geo.GeodesicPaths(mesh, 0)
    xyz = p.path(5)
    assert any(np.array_equal(x, V[3]) for x in xyz), "the path does not go through the shared vertex"
    assert np.linalg.norm(np.diff(xyz, axis=0), axis=1).sum() == pytest.approx(d[5], rel=1e-12)


def test_two_triangles_sharing_a_vertex_only():
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [-1, 0, 0], [0, -1, 0]], dtype=float)
    mesh = geo.Mesh(V, [[0, 1, 2], [0, 3, 4]])
    d = mesh.distances(1)
    np.testing.assert_allclose(d, [1, 0, np.sqrt(2), 2, 2], rtol=1e-12)


# ----------------------------------------------------------------------------------------------
# properties of geodesic distances on random meshes


def test_flat_random_grid_distances_are_euclidean():
    for seed in (1, 2, 3):
        V, F, _ = flat_grid(14, seed=seed)
        d = geo.Mesh(V, F).distance_matrix([0, 13, 100])
        e = np.linalg.norm(V[[0, 13, 100]][:, None] - V[None], axis=2)
        np.testing.assert_allclose(d, e, rtol=1e-12, atol=1e-14, err_msg=f"flat jittered grid, seed={seed}")


def test_symmetry_and_triangle_inequality(random_mesh):
    mesh, what = random_mesh.mesh, random_mesh.what
    rng = np.random.default_rng(random_mesh.seed)
    ids = rng.choice(mesh.n_vertices, size=12, replace=False)
    D = mesh.distance_matrix(ids, targets=ids)
    scale = D.max()
    assert np.all(np.isfinite(D)) and scale > 0, what
    assert np.all(np.diag(D) == 0), what
    asym = np.abs(D - D.T).max()
    assert asym <= 1e-12 * scale, f"{what}: d(a, b) and d(b, a) differ by {asym} (ids {ids.tolist()})"
    slack = D[:, None, :] - (D[:, :, None] + D[None, :, :])  # d(i, k) - d(i, j) - d(j, k)
    worst = np.unravel_index(np.argmax(slack), slack.shape)
    assert slack.max() <= 1e-12 * scale, (f"{what}: triangle inequality broken by {slack.max()} for vertices "
                                          f"{[int(ids[i]) for i in worst]}")
    # every algorithm agrees
    for algorithm in ("vtp", "pmmp", "fwp_mmp", "mmp"):
        d = mesh.distances(int(ids[0]), algorithm=algorithm)
        np.testing.assert_allclose(d[ids], D[0], rtol=1e-12, atol=1e-14 * scale, err_msg=f"{what}, {algorithm}")
    # geodesic distances are at least the Euclidean ones
    V = mesh.vertices
    e = np.linalg.norm(V[ids][:, None] - V[ids][None], axis=2)
    assert np.all(D >= e - 1e-12 * scale), what
    # the approximation is never below the exact distance
    a = mesh.distances(int(ids[0]), lam=2)
    exact = mesh.distances(int(ids[0]))
    assert np.all(a >= exact - 1e-12 * scale), f"{what}: AVTP below the exact distance"


def test_path_lengths_are_the_distances(random_mesh):
    mesh, what = random_mesh.mesh, random_mesh.what
    p = geo.GeodesicPaths(mesh, 0)
    d = p.distances()
    rng = np.random.default_rng(random_mesh.seed)
    for t in rng.choice(mesh.n_vertices, size=8, replace=False):
        xyz = p.path(int(t))
        length = np.linalg.norm(np.diff(xyz, axis=0), axis=1).sum()
        assert length == pytest.approx(d[t], rel=1e-9, abs=1e-12), f"{what}: path to {t}"


# ----------------------------------------------------------------------------------------------
# the same bytes on any number of threads


def results_on_threads(mesh, threads, algorithm="pvtp"):
    """Every result of the module on this many threads, as bytes, named."""
    sources = [0, 5, (3, (0.2, 0.3, 0.5))]
    out = {}
    d, labels = mesh.distances(sources, threads=threads, algorithm=algorithm, return_sources=True)
    out["distances"], out["labels"] = d, labels
    out["max_distance"] = mesh.distances(sources, threads=threads, algorithm=algorithm, max_distance=0.3)
    v = mesh.voronoi(sources, threads=threads, algorithm=algorithm)
    out.update({"voronoi cells": v.cells, "voronoi distances": v.distances, "voronoi vertices": v.vertices})
    out.update({f"bisector {i}": b["points"] for i, b in enumerate(v.bisectors)})
    p = geo.GeodesicPaths(mesh, sources, threads=threads, algorithm=algorithm)
    out.update({"paths distances": p.distances(), "paths sources": p.nearest_sources(),
                "path": p.path(mesh.n_vertices - 1)})
    if algorithm == "pvtp":
        out["lam"] = mesh.distances(sources, threads=threads, lam=2.0)
        out["stop_vertices"] = mesh.distances(sources, threads=threads, stop_vertices=[10, 20])
        out["matrix"] = mesh.distance_matrix(sources, threads=threads)
        out["sparse matrix"] = mesh.distance_matrix(sources, threads=threads, max_distance=0.3).toarray()
        s = mesh.farthest_point_sampling(5, threads=threads)
        out.update({"samples": s.samples, "radii": s.radii, "sample distances": s.distances,
                    "nearest samples": s.nearest_samples})
        s = mesh.farthest_point_sampling(5, threads=threads, lam=2.0)
        out.update({"samples, lam": s.samples, "radii, lam": s.radii})
    return {k: np.ascontiguousarray(a).tobytes() for k, a in out.items()}


def assert_same_bytes(a, b, what):
    assert a.keys() == b.keys(), what
    different = [k for k in a if a[k] != b[k]]
    assert not different, f"{what}: {', '.join(different)} differ"


@pytest.mark.parametrize("algorithm", ["pvtp", "pmmp"])
def test_threads_give_identical_bytes(random_mesh, algorithm):
    mesh, what = random_mesh.mesh, random_mesh.what
    one = results_on_threads(mesh, 1, algorithm)
    for threads in (2, 4, None):
        assert_same_bytes(one, results_on_threads(mesh, threads, algorithm),
                          f"{what}, {algorithm}: threads=1 and threads={threads}")


@pytest.mark.parametrize("sequential,parallel", [("vtp", "pvtp"), ("fwp_mmp", "pmmp"), ("mmp", "pvtp")])
def test_sequential_and_parallel_agree_to_round_off(random_mesh, sequential, parallel):
    mesh, what = random_mesh.mesh, random_mesh.what
    sources = [0, 5, (3, (0.2, 0.3, 0.5))]
    a, cells_a = mesh.distances(sources, algorithm=sequential, return_sources=True)
    b, cells_b = mesh.distances(sources, algorithm=parallel, return_sources=True)
    scale = np.ptp(mesh.vertices, axis=0).max()
    assert np.array_equal(np.isfinite(a), np.isfinite(b)), what
    finite = np.isfinite(a)
    assert np.abs(a[finite] - b[finite]).max(initial=0) <= 1e-12 * scale, f"{what}: {sequential} against {parallel}"
    va = mesh.voronoi(sources, algorithm=sequential)
    vb = mesh.voronoi(sources, algorithm=parallel)
    # a vertex equidistant from two sites may fall on either side
    tied = np.abs(va.distances - vb.distances) > 0
    assert np.mean(va.cells == vb.cells) > 0.99, f"{what}: Voronoi cells of {sequential} and {parallel}"
    assert not np.any(tied & (np.abs(va.distances - vb.distances) > 1e-12 * scale)), what


def test_threads_identical_on_a_bundled_mesh(elephant):
    ref = elephant.distances([0, 1000], threads=1)
    for threads in (2, 4):
        assert elephant.distances([0, 1000], threads=threads).tobytes() == ref.tobytes()
    ref = elephant.distance_matrix([0, 7, 1000], threads=1)
    for threads in (2, 4):
        assert elephant.distance_matrix([0, 7, 1000], threads=threads).tobytes() == ref.tobytes()
