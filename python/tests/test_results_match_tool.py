# Copyright (c) 2026 The CGAL_ext geodesics developers.
"""The module computes what the `geodesic` tool computes, for the same input.

The tool writes its text files with round-trip digits and its .npy files in binary, so that the
results are compared exactly; only what the tool prints in its statistics (a path's length) is
compared to 1e-12 relative.
"""

import numpy as np
import pytest
import scipy.io
import scipy.sparse

import cgal_ext_geodesics as geo

FACE_POINT = (10, (0.125, 0.25, 0.625))
FACE_POINTS = (np.array([10, 200, 333]), np.array([[0.125, 0.25, 0.625], [0.5, 0.5, 0.0], [1 / 3, 1 / 3, 1 / 3]]))
SEVERAL = [0, 57, 1200, 2000]


def face_point_text(face, b):
    return "f:%d:%r:%r:%r" % (face, float(b[0]), float(b[1]), float(b[2]))


def load_column(path, dtype=np.float64):
    return np.loadtxt(path, dtype=dtype, ndmin=1)


def assert_exact(got, expected, what):
    got, expected = np.asarray(got), np.asarray(expected)
    assert got.shape == expected.shape, f"{what}: shape {got.shape}, the tool's {expected.shape}"
    bad = ~((got == expected) | (np.isnan(got) & np.isnan(expected)) if got.dtype.kind == "f" else (got == expected))
    assert not bad.any(), (f"{what}: {bad.sum()} of {bad.size} entries differ from the tool's, first at "
                           f"{np.argwhere(bad)[0].tolist()}: {got[bad][:3]} instead of {expected[bad][:3]}")


def assert_close(got, expected, what, rtol=1e-12):
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    assert got.shape == expected.shape, f"{what}: shape {got.shape}, the tool's {expected.shape}"
    np.testing.assert_allclose(got, expected, rtol=rtol, atol=0, err_msg=what)


# ----------------------------------------------------------------------------------------------
# distances

DISTANCE_CASES = {
    # name: (Mesh.distances options, the tool's options)
    "pvtp-default": (dict(), ["--algorithm", "pvtp"]),
    "pvtp-threads1": (dict(threads=1), ["--algorithm", "pvtp", "--threads", "1"]),
    "pvtp-threads2": (dict(threads=2), ["--algorithm", "pvtp", "--threads", "2"]),
    "vtp": (dict(algorithm="vtp"), ["--algorithm", "vtp"]),
    "vtp-threads1": (dict(algorithm="vtp", threads=1), ["--algorithm", "vtp"]),
    "fwp_mmp": (dict(algorithm="fwp_mmp"), ["--algorithm", "fwp-mmp"]),
    "pmmp": (dict(algorithm="pmmp"), ["--algorithm", "pmmp"]),
    "mmp": (dict(algorithm="mmp"), ["--algorithm", "mmp"]),
    "lam4": (dict(lam=4), ["--algorithm", "pavtp", "--lambda", "4"]),
    "avtp-lam4": (dict(algorithm="avtp", lam=4), ["--algorithm", "avtp", "--lambda", "4"]),
    "avtp-default-lam": (dict(algorithm="avtp"), ["--algorithm", "avtp"]),
    "max_distance": (dict(max_distance=0.2), ["--max-distance", repr(0.2)]),
    "max_distance-mmp": (dict(algorithm="mmp", max_distance=0.15),
                         ["--algorithm", "mmp", "--max-distance", repr(0.15)]),
}


@pytest.mark.parametrize("case", list(DISTANCE_CASES))
def test_distances_from_a_vertex(bundled, run_tool, tmp_path, case):
    path, mesh = bundled
    options, tool_options = DISTANCE_CASES[case]
    d = mesh.distances(3, **options)
    run_tool("distances", path, "--source", "3", "--output", tmp_path / "d.txt", *tool_options)
    expected = load_column(tmp_path / "d.txt")
    assert_exact(d, expected, f"{path.name}, {case}: distances from vertex 3")
    if "max_distance" in options:
        assert np.isinf(d).any() and np.isfinite(d).sum() > 10, f"{path.name}, {case}: max_distance cut nothing"
        assert d[np.isfinite(d)].max() <= options["max_distance"]


@pytest.mark.parametrize("algorithm,tool_algorithm",
                         [("pvtp", "pvtp"), ("vtp", "vtp"), ("mmp", "mmp"), ("fwp_mmp", "fwp-mmp"), ("pmmp", "pmmp")])
def test_distances_from_a_face_point(bundled, run_tool, tmp_path, algorithm, tool_algorithm):
    path, mesh = bundled
    d = mesh.distances(FACE_POINT, algorithm=algorithm, threads=1)
    run_tool("distances", path, "--source", face_point_text(*FACE_POINT), "--algorithm", tool_algorithm,
             "--output", tmp_path / "d.txt")
    assert_exact(d, load_column(tmp_path / "d.txt"), f"{path.name}: distances from {FACE_POINT}, {algorithm}")


def test_distances_from_face_points_as_two_arrays(bundled, run_tool, tmp_path):
    path, mesh = bundled
    faces, bary = FACE_POINTS
    d, labels = mesh.distances((faces, bary), return_sources=True)
    as_list = mesh.distances([(int(f), tuple(b)) for f, b in zip(faces, bary)])
    assert_exact(as_list, d, f"{path.name}: face points as a list and as two arrays")
    sources = ",".join(face_point_text(f, b) for f, b in zip(faces, bary))
    run_tool("distances", path, "--source", sources, "--output", tmp_path / "d.txt", "--labels", tmp_path / "l.txt")
    assert_exact(d, load_column(tmp_path / "d.txt"), f"{path.name}: distances from 3 face points")
    assert_exact(labels, load_column(tmp_path / "l.txt", np.int64), f"{path.name}: nearest face point")


@pytest.mark.parametrize("algorithm,tool_algorithm", [("pvtp", "pvtp"), ("mmp", "mmp"), ("pmmp", "pmmp")])
def test_distances_from_several_sources_with_labels(bundled, run_tool, tmp_path, algorithm, tool_algorithm):
    path, mesh = bundled
    sources = SEVERAL + [FACE_POINT]
    d, labels = mesh.distances(sources, algorithm=algorithm, return_sources=True)
    assert d.dtype == np.float64 and labels.dtype == np.int64
    text = ",".join([str(s) for s in SEVERAL] + [face_point_text(*FACE_POINT)])
    run_tool("distances", path, "--source", text, "--algorithm", tool_algorithm, "--output", tmp_path / "d.txt",
             "--labels", tmp_path / "l.txt")
    what = f"{path.name}: distances from {sources}, {algorithm}"
    assert_exact(d, load_column(tmp_path / "d.txt"), what)
    assert_exact(labels, load_column(tmp_path / "l.txt", np.int64), what + ", nearest sources")
    assert set(np.unique(labels)) == set(range(len(sources))), what


def test_module_level_distances_match_the_mesh_method(bundled):
    path, mesh = bundled
    V, F = np.array(mesh.vertices), mesh.faces
    assert_exact(geo.distances(V, F, [0, 9], threads=1), mesh.distances([0, 9], threads=1),
                 f"{path.name}: geo.distances and Mesh.distances")
    assert_exact(geo.distances(mesh, None, 5), mesh.distances(5), f"{path.name}: geo.distances(mesh, None, ...)")


# ----------------------------------------------------------------------------------------------
# distance matrices


@pytest.mark.parametrize("threads", [1, None])
def test_dense_matrix(bundled, run_tool, tmp_path, threads):
    path, mesh = bundled
    sources = [0, 5, 77, FACE_POINT]
    m = mesh.distance_matrix(sources, threads=threads)
    assert isinstance(m, np.ndarray) and m.shape == (4, mesh.n_vertices) and m.dtype == np.float64
    text = "0,5,77," + face_point_text(*FACE_POINT)
    extra = [] if threads is None else ["--threads", str(threads)]
    run_tool("matrix", path, "--source", text, "--output", tmp_path / "m.npy", *extra)
    assert_exact(m, np.load(tmp_path / "m.npy"), f"{path.name}: dense matrix from {sources}")
    # each row alone is the distances from its source alone
    assert_exact(m[1], mesh.distances(5), f"{path.name}: row 1 and the distances from vertex 5")


def test_dense_matrix_with_targets(bundled, run_tool, tmp_path):
    path, mesh = bundled
    targets = [3, 9, 1000, 3, 2]
    m = geo.distance_matrix(np.array(mesh.vertices), mesh.faces, [1, 2, 7], targets=targets)
    assert m.shape == (3, 5)
    run_tool("matrix", path, "--source", "1,2,7", "--target", ",".join(map(str, targets)), "--output",
             tmp_path / "m.npy")
    assert_exact(m, np.load(tmp_path / "m.npy"), f"{path.name}: dense matrix with targets {targets}")
    run_tool("matrix", path, "--source", "1,2,7", "--target", ",".join(map(str, targets)), "--output",
             tmp_path / "m.txt")
    assert_exact(m, np.loadtxt(tmp_path / "m.txt", ndmin=2), f"{path.name}: the tool's .txt matrix")


def test_sparse_matrix_with_max_distance(bundled, run_tool, tmp_path):
    path, mesh = bundled
    sources, r = [0, 11, 400, FACE_POINT], 0.15
    m = mesh.distance_matrix(sources, max_distance=r)
    assert isinstance(m, scipy.sparse.csr_matrix) and m.shape == (4, mesh.n_vertices) and m.dtype == np.float64
    text = "0,11,400," + face_point_text(*FACE_POINT)
    run_tool("matrix", path, "--source", text, "--max-distance", repr(r), "--output", tmp_path / "m.mtx")
    expected = scipy.sparse.csr_matrix(scipy.io.mmread(str(tmp_path / "m.mtx")))
    expected.sort_indices()
    what = f"{path.name}: sparse matrix from {sources} within {r}"
    assert m.has_sorted_indices, what + ": the column indices of each row are not sorted"
    assert_exact(m.indptr, expected.indptr, what + ", indptr (entries by row)")
    assert_exact(m.indices, expected.indices, what + ", indices")
    assert_exact(m.data, expected.data, what + ", data")
    assert np.all(m.data <= r), what
    # the same entries as the dense matrix's finite ones within r, and as the tool's .txt
    dense = mesh.distance_matrix(sources)
    assert_exact(m.toarray()[m.toarray() > 0], dense[(dense <= r) & (dense > 0)], what + " and the dense matrix")
    run_tool("matrix", path, "--source", text, "--max-distance", repr(r), "--output", tmp_path / "m.txt")
    txt = np.loadtxt(tmp_path / "m.txt", ndmin=2)
    full = np.full(m.shape, np.inf)
    rows = np.repeat(np.arange(m.shape[0]), np.diff(m.indptr))
    full[rows, m.indices] = m.data
    assert_exact(full, txt, what + " and the tool's .txt (inf beyond)")


def test_sparse_matrix_with_targets(bundled, run_tool, tmp_path):
    path, mesh = bundled
    targets = list(range(0, mesh.n_vertices, 7))
    m = mesh.distance_matrix([0, 11], targets=targets, max_distance=0.3)
    assert m.shape == (2, len(targets))
    run_tool("matrix", path, "--source", "0,11", "--target", ",".join(map(str, targets)), "--max-distance",
             repr(0.3), "--output", tmp_path / "m.mtx")
    expected = scipy.sparse.csr_matrix(scipy.io.mmread(str(tmp_path / "m.mtx")))
    expected.sort_indices()
    assert_exact(m.toarray(), expected.toarray(), f"{path.name}: sparse matrix with targets")
    assert_exact(m.indptr, expected.indptr, f"{path.name}: sparse matrix with targets, indptr")


# ----------------------------------------------------------------------------------------------
# Voronoi diagrams


def read_bisectors(path):
    """The tool's bisectors .txt: polylines of 'x y z a b' lines, a blank line between them."""
    curves, current = [], []
    for line in open(path):
        if not line.strip():
            if current:
                curves.append(current)
            current = []
        else:
            current.append([float(x) for x in line.split()])
    if current:
        curves.append(current)
    return [np.array(c) for c in curves]


def read_dual(path):
    edges, triangles = [], []
    for line in open(path):
        w = line.split()
        if w and w[0] == "l":
            edges.append([int(x) - 1 for x in w[1:]])
        elif w and w[0] == "f":
            triangles.append([int(x) - 1 for x in w[1:]])
    return np.array(edges, dtype=np.int64).reshape(-1, 2), np.array(triangles, dtype=np.int64).reshape(-1, 3)


@pytest.mark.parametrize("algorithm,tool_algorithm", [("pvtp", "pvtp"), ("vtp", "vtp"), ("mmp", "mmp")])
def test_voronoi(bundled, run_tool, tmp_path, algorithm, tool_algorithm):
    path, mesh = bundled
    sources = [0, 100, 1000, 2000, FACE_POINT]
    v = mesh.voronoi(sources, algorithm=algorithm)
    text = "0,100,1000,2000," + face_point_text(*FACE_POINT)
    run_tool("voronoi", path, "--source", text, "--algorithm", tool_algorithm, "--output", tmp_path / "c.txt",
             "--bisectors", tmp_path / "b.txt", "--dual", tmp_path / "d.obj")
    what = f"{path.name}: Voronoi diagram of {sources}, {algorithm}"
    assert_exact(v.cells, load_column(tmp_path / "c.txt", np.int64), what + ", cells")
    d, labels = mesh.distances(sources, algorithm=algorithm, return_sources=True)
    assert_exact(v.cells, labels, what + ": cells and the nearest sources of distances()")
    assert_close(v.distances, d, what + ": distances and those of distances()")
    curves = read_bisectors(tmp_path / "b.txt")
    assert len(v.bisectors) == len(curves), what + ", number of bisectors"
    for i, (b, c) in enumerate(zip(v.bisectors, curves)):
        assert tuple(b["sources"]) == (int(c[0, 3]), int(c[0, 4])), f"{what}, bisector {i}: its sources"
        assert_exact(b["points"], c[:, :3], f"{what}, bisector {i}: its points")
    edges, triangles = read_dual(tmp_path / "d.obj")
    assert_exact(v.dual_edges, edges, what + ", dual edges")
    assert_exact(v.dual_triangles, triangles, what + ", dual triangles")
    assert v.unresolved_parts == 0, what


# ----------------------------------------------------------------------------------------------
# farthest-point sampling

SAMPLING_CASES = {
    "count": (dict(count=8), ["--count", "8"]),
    "first": (dict(count=6, first=5), ["--count", "6", "--first", "5"]),
    "firsts": (dict(count=7, first=[5, 17, 900]), ["--count", "7", "--first", "5,17,900"]),
    "radius": (dict(count=500, radius=0.5), ["--count", "500", "--radius", repr(0.5)]),
    "lam": (dict(count=8, lam=4.0), ["--count", "8", "--algorithm", "pavtp", "--lambda", "4"]),
    "threads1": (dict(count=8, threads=1), ["--count", "8", "--threads", "1"]),
}


@pytest.mark.parametrize("case", list(SAMPLING_CASES))
def test_farthest_point_sampling(bundled, run_tool, tmp_path, case):
    path, mesh = bundled
    options, tool_options = SAMPLING_CASES[case]
    s = mesh.farthest_point_sampling(**options)
    run_tool("sample", path, *tool_options, "--output", tmp_path / "s.txt", "--labels", tmp_path / "l.txt")
    expected = np.loadtxt(tmp_path / "s.txt", ndmin=2)
    what = f"{path.name}: farthest-point sampling, {options}"
    assert_exact(s.samples, expected[:, 0].astype(np.int64), what + ", samples")
    assert_exact(s.radii, expected[:, 1], what + ", radii")
    assert_exact(s.nearest_samples, load_column(tmp_path / "l.txt", np.int64), what + ", nearest samples")
    assert np.all(np.diff(s.radii) <= 0), what + ": the covering radius grows"
    if case == "radius":
        assert len(s.samples) < 500 and s.radii[-1] <= 0.5 < s.radii[-2], what
    # the distances are those from the samples
    assert_close(s.distances, mesh.distances(s.samples, lam=options.get("lam")), what + ", distances")


def test_module_level_sampling_and_voronoi(bundled):
    path, mesh = bundled
    V, F = np.array(mesh.vertices), mesh.faces
    a, b = geo.farthest_point_sampling(V, F, 5), mesh.farthest_point_sampling(5)
    assert_exact(a.samples, b.samples, f"{path.name}: geo.farthest_point_sampling")
    assert_exact(geo.voronoi(V, F, [0, 9]).cells, mesh.voronoi([0, 9]).cells, f"{path.name}: geo.voronoi")


# ----------------------------------------------------------------------------------------------
# paths


def tool_stats(stderr):
    stats = {}
    for line in stderr.splitlines():
        if "=" in line:
            k, v = line.split("=", 1)
            stats[k.strip()] = v.strip()
    return stats


@pytest.mark.parametrize("algorithm,tool_algorithm", [("pvtp", "pvtp"), ("pmmp", "pmmp"), ("mmp", "mmp")])
@pytest.mark.parametrize("target", [1500, (77, (0.2, 0.3, 0.5))], ids=["vertex", "face-point"])
def test_path(bundled, run_tool, tmp_path, algorithm, tool_algorithm, target):
    path, mesh = bundled
    sources = [0, 600]
    paths = geo.GeodesicPaths(mesh, sources, algorithm=algorithm)
    assert paths.n_sources == 2
    assert paths.mesh is mesh
    xyz = paths.path(target)
    target_text = str(target) if isinstance(target, int) else face_point_text(*target)
    stats = tool_stats(run_tool("path", path, "--source", "0,600", "--target", target_text, "--algorithm",
                                tool_algorithm, "--output", tmp_path / "p.txt", "--stats"))
    expected = np.loadtxt(tmp_path / "p.txt", ndmin=2)
    what = f"{path.name}: path from {sources} to {target}, {algorithm}"
    assert_exact(xyz, expected, what + ", points")
    assert len(xyz) == int(stats["points"]), what
    length = np.linalg.norm(np.diff(xyz, axis=0), axis=1).sum()
    assert_close(length, float(stats["length"]), what + ", length")
    assert_close(paths.distance(target), float(stats["distance"]), what + ", distance")
    assert paths.nearest_source(target) == int(stats["nearest_source"]), what
    # the path starts at its source
    s = sources[paths.nearest_source(target)]
    assert_exact(xyz[0], mesh.vertices[s], what + ": the first point is the source")
    if isinstance(target, int):
        assert_exact(xyz[-1], mesh.vertices[target], what + ": the last point is the target")
    # the distances of the paths object are those of the solvers
    assert_close(paths.distances(), mesh.distances(sources, algorithm=algorithm), what + ", every distance")


# ----------------------------------------------------------------------------------------------
# pattern detection


def bump_grid(n=90):
    """A 3 x 3 grid of bumps on a height field, (V, F, the vertex nearest the middle bump)."""
    x, y = np.meshgrid(np.linspace(0, 3, n), np.linspace(0, 3, n))
    z = sum(0.15 * np.exp(-((x - a) ** 2 + (y - b) ** 2) / 0.03) for a in (0.5, 1.5, 2.5) for b in (0.5, 1.5, 2.5))
    V = np.c_[x.ravel(), y.ravel(), z.ravel()]
    i = (np.arange(n - 1)[:, None] * n + np.arange(n - 1)).ravel()
    F = np.vstack([np.c_[i, i + 1, i + n + 1], np.c_[i, i + n + 1, i + n]])
    return V, F, int(np.argmin(np.hypot(V[:, 0] - 1.5, V[:, 1] - 1.5)))


def write_off(path, V, F):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(V)} {len(F)} 0\n")
        f.writelines("%r %r %r\n" % tuple(map(float, v)) for v in V)
        f.writelines("3 %d %d %d\n" % tuple(t) for t in F)


@pytest.mark.parametrize("threads", [1, 2])
def test_detect_patterns(run_tool, tmp_path, threads):
    import json
    V, F, middle = bump_grid()
    write_off(tmp_path / "bumps.off", V, F)
    found = geo.Mesh(V, F).detect_patterns(center=middle, radius=0.4, threads=threads)
    run_tool("patterns", tmp_path / "bumps.off", "--patch-center", middle, "--patch-radius", "0.4",
             "--threads", threads, "--output", tmp_path / "p.json", "--labels", tmp_path / "l.txt")
    with open(tmp_path / "p.json") as f:
        expected = json.load(f)["instances"]
    what = f"bumps, threads={threads}"
    assert len(found.instances) == len(expected) == 9, f"{what}: {len(found.instances)} and {len(expected)} instances"
    for k, (a, b) in enumerate(zip(found.instances, expected)):
        assert a["center_vertex"] == b["center_vertex"], f"{what}, instance {k}"
        assert_close(a["center"], b["center"], f"{what}, instance {k}: centre")
        assert_close([a["scale"], a["energy"]], [b["scale"], b["energy"]], f"{what}, instance {k}: scale and energy")
        assert_exact(a["vertices"], np.array(b["vertices"], dtype=np.int64), f"{what}, instance {k}: vertices")
    assert_exact(found.labels, load_column(tmp_path / "l.txt", np.int64), what + ", labels")
