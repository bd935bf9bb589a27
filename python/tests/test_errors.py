# Copyright (c) 2026 The CGAL_ext geodesics developers.
"""Bad input raises GeodesicError (a ValueError) with a message naming the problem; never a crash.

Each case is (what to call, a regular expression the message must match). Inputs that could
crash the interpreter are tried in a child process, so that a crash fails one test instead of
ending the run.
"""

import subprocess
import sys
import textwrap

import numpy as np
import pytest

import cgal_ext_geodesics as geo


@pytest.fixture(scope="module")
def small():
    """A 6 x 6 height field (36 vertices, 50 faces) and its Mesh."""
    n = 6
    x, y = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n), indexing="ij")
    V = np.stack([x, y, 0.1 * np.sin(3 * x) * np.cos(2 * y)], -1).reshape(-1, 3)
    i = (np.arange(n - 1)[:, None] * n + np.arange(n - 1)[None, :]).ravel()
    F = np.concatenate([np.stack([i, i + n, i + 1], 1), np.stack([i + 1, i + n, i + n + 1], 1)])
    return V, F, geo.Mesh(V, F)


def cases(V, F, m):
    """name -> (function, regular expression of the message)."""
    nan_V = V.copy()
    nan_V[7, 1] = np.nan
    P = lambda *a, **k: geo.GeodesicPaths(m, *a, **k)  # noqa: E731
    return {
        # ids
        "vertex id out of range": (lambda: m.distances(36), r"vertex 36 is out of range.*36 vertices"),
        "vertex id out of range in a list": (lambda: m.distances([0, 1, 99]), r"vertex 99 is out of range"),
        "vertex id out of range in an array": (lambda: m.distances(np.array([99])), r"vertex 99 is out of range"),
        "huge vertex id": (lambda: m.distances(2**62), r"out of range"),
        "negative id": (lambda: m.distances(-1), r"-1 is negative"),
        "negative id in a list": (lambda: m.distances([0, -2]), r"-2 is negative"),
        "negative id in an array": (lambda: m.distances(np.array([0, -2], dtype=np.int32)), r"-2 is negative"),
        "face id out of range": (lambda: m.distances((50, (0.2, 0.3, 0.5))), r"face 50 is out of range.*50 faces"),
        "negative face id": (lambda: m.distances((-1, (0.2, 0.3, 0.5))), r"-1 is negative"),
        "face ids out of range as arrays": (lambda: m.distances((np.array([0, 77]), np.full((2, 3), 1 / 3))),
                                            r"face 77 is out of range"),
        "target out of range": (lambda: P(0).path(36), r"target.*vertex 36 is out of range"),
        "target negative": (lambda: P(0).distance(-3), r"target -3 is negative"),
        "matrix target out of range": (lambda: m.distance_matrix([0], targets=[40]), r"target.*40 is out of range"),
        "matrix target face point": (lambda: m.distance_matrix([0], targets=[(0, (0.2, 0.3, 0.5))]),
                                     r"a vertex id is expected"),
        "stop vertex out of range": (lambda: m.distances(0, stop_vertices=[36]), r"stop vertex.*36 is out of range"),
        "first sample out of range": (lambda: m.farthest_point_sampling(3, first=36), r"first sample.*out of range"),
        "pattern center out of range": (lambda: m.detect_patterns(center=36, radius=0.1), r"center.*out of range"),
        # barycentric coordinates
        "barycentric not summing to 1": (lambda: m.distances((3, (0.2, 0.3, 0.6))), r"sum to 1"),
        "barycentric negative": (lambda: m.distances((3, (-0.2, 0.7, 0.5))), r"non-negative"),
        "barycentric NaN": (lambda: m.distances((3, (np.nan, 0.5, 0.5))), r"must be finite numbers"),
        "barycentric infinite": (lambda: m.distances((3, (np.inf, 0.5, 0.5))), r"must be finite numbers"),
        "two barycentric coordinates": (lambda: m.distances((3, (0.5, 0.5))), r"face point \(face, \(b0, b1, b2\)\)"),
        "barycentric as arrays, wrong shape": (lambda: m.distances((np.array([0, 1]), np.ones((3, 3)) / 3)),
                                               r"shape \(2, 3\)"),
        "barycentric as arrays, not summing to 1": (lambda: m.distances((np.array([0, 1]), np.ones((2, 3)) / 2)),
                                                    r"sum to 1"),
        "target barycentric not summing to 1": (lambda: P(0).distance((3, (0.5, 0.5, 0.5))), r"sum to 1"),
        "path source barycentric negative": (lambda: P((3, (1.5, -0.5, 0.0))), r"non-negative"),
        "matrix source barycentric": (lambda: m.distance_matrix([(3, (0.5, 0.5, 0.5))]), r"sum to 1"),
        "voronoi source barycentric": (lambda: m.voronoi([0, (3, (0.5, 0.5, 0.5))]), r"sum to 1"),
        # sources of another kind
        "source a string": (lambda: m.distances("abc"), r"expected a vertex id"),
        "source a float": (lambda: m.distances(1.5), r"expected a vertex id"),
        "source a bool": (lambda: m.distances(True), r"expected a vertex id"),
        "sources a float array": (lambda: m.distances(np.array([1.0, 2.0])), r"integer dtype"),
        "sources a 2-d array": (lambda: m.distances(np.array([[1, 2]])), r"one-dimensional"),
        "sources None": (lambda: m.distances(None), r"expected a vertex id"),
        # vertices
        "vertices of shape (n, 2)": (lambda: geo.Mesh(V[:, :2], F), r"shape \(n, 3\).*\(36, 2\)"),
        "vertices of shape (n, 4)": (lambda: geo.Mesh(np.hstack([V, V[:, :1]]), F), r"shape \(n, 3\)"),
        "vertices flat": (lambda: geo.Mesh(V.ravel(), F), r"shape \(n, 3\)"),
        "vertices of strings": (lambda: geo.Mesh(np.array([["a", "b", "c"]] * 36), F), r"vertices"),
        "vertices None": (lambda: geo.Mesh(None, F), r"vertices"),
        "NaN coordinate": (lambda: geo.Mesh(nan_V, F), r"point 7 has a non-finite coordinate"),
        "infinite coordinate": (lambda: geo.Mesh(np.where(np.arange(36)[:, None] == 4, np.inf, V), F),
                                r"point 4 has a non-finite coordinate"),
        # faces
        "float faces": (lambda: geo.Mesh(V, F.astype(np.float64)), r"integer dtype.*float64"),
        "bool faces": (lambda: geo.Mesh(V, F.astype(bool)), r"integer dtype"),
        "faces of a float in a list": (lambda: geo.Mesh(V, [[0, 1, 2.0]]), r"face 0 .*not an integer"),
        "faces out of range": (lambda: geo.Mesh(V, np.vstack([F, [[0, 1, 36]]])),
                               r"face 50 has vertex id 36, out of range"),
        "faces negative": (lambda: geo.Mesh(V, np.vstack([F, [[0, -1, 2]]])), r"face 50 has vertex id -1"),
        "faces in a list out of range": (lambda: geo.Mesh(V, [[0, 1, 2], [0, 1, 99]]), r"face 1 has vertex id 99"),
        "faces of shape (m, 2)": (lambda: geo.Mesh(V, F[:, :2]), r"shape \(m, 3\)"),
        "faces 3-d": (lambda: geo.Mesh(V, F[None]), r"shape \(m, 3\)"),
        "faces None": (lambda: geo.Mesh(V, None), r"faces"),
        "faces not sequences": (lambda: geo.Mesh(V, [1, 2, 3]), r"face 0 is not a sequence"),
        # empty or degenerate meshes
        "empty mesh": (lambda: geo.Mesh(np.zeros((0, 3)), np.zeros((0, 3), dtype=int)), r"empty|no face"),
        "no faces": (lambda: geo.Mesh(V, np.zeros((0, 3), dtype=int)), r"no polygon|no face"),
        "all points the same": (lambda: geo.Mesh(np.zeros((3, 3)), [[0, 1, 2]]), r"fewer than 3 distinct points"),
        "zero area": (lambda: geo.Mesh(np.array([[0, 0, 0], [1, 0, 0], [2, 0, 0.0]]), [[0, 1, 2]]).distances(0),
                      r"degenerate"),
        # options
        "unknown algorithm": (lambda: m.distances(0, algorithm="dijkstra"), r"unknown algorithm 'dijkstra'"),
        "unknown algorithm for paths": (lambda: P(0, algorithm="exact"), r"unknown algorithm 'exact'"),
        "unknown algorithm for voronoi": (lambda: m.voronoi([0, 1], algorithm="x"), r"unknown algorithm 'x'"),
        "lam with fwp_mmp": (lambda: m.distances(0, algorithm="fwp_mmp", lam=4), r"lam.*'avtp' and 'pavtp' only"),
        "lam with mmp": (lambda: m.distances(0, algorithm="mmp", lam=4), r"lam.*'avtp' and 'pavtp' only"),
        "lam zero": (lambda: m.distances(0, lam=0), r"lam must be a positive"),
        "lam negative for sampling": (lambda: m.farthest_point_sampling(3, lam=-1), r"lam must be a positive"),
        "lam infinite": (lambda: m.distances(0, lam=np.inf), r"lam must be a positive, finite"),
        "threads=0": (lambda: m.distances(0, threads=0), r"threads must be an integer from 1 to.*got 0"),
        "threads=-1": (lambda: m.distances(0, threads=-1), r"threads must be an integer from 1 to.*got -1"),
        "threads=0 for a matrix": (lambda: m.distance_matrix([0], threads=0), r"threads must be an integer from 1 to.*got 0"),
        "threads=0 for paths": (lambda: P(0, threads=0), r"threads must be an integer from 1 to.*got 0"),
        "threads=0 for voronoi": (lambda: m.voronoi([0, 1], threads=0), r"threads must be an integer from 1 to.*got 0"),
        "threads=0 for sampling": (lambda: m.farthest_point_sampling(3, threads=0), r"threads must be an integer from 1 to.*got 0"),
        "threads=0 for patterns": (lambda: m.detect_patterns(center=0, radius=0.2, threads=0),
                                   r"threads must be an integer from 1 to.*got 0"),
        "negative max_distance": (lambda: m.distances(0, max_distance=-1), r"max_distance must be a non-negative"),
        "NaN max_distance": (lambda: m.distances(0, max_distance=np.nan), r"max_distance must be a non-negative"),
        "negative max_distance for a matrix": (lambda: m.distance_matrix([0], max_distance=-1),
                                               r"max_distance must be a non-negative"),
        "negative max_distance for paths": (lambda: P(0, max_distance=-0.5), r"max_distance must be a non-negative"),
        "stop_vertices with mmp": (lambda: m.distances(0, algorithm="mmp", stop_vertices=[5]),
                                   r"stop_vertices works with the VTP family only"),
        "stop_vertices with pmmp": (lambda: m.distances(0, algorithm="pmmp", stop_vertices=[5]),
                                    r"stop_vertices works with the VTP family only"),
        "stop_vertices with fwp_mmp": (lambda: m.distances(0, algorithm="fwp_mmp", stop_vertices=[5]),
                                       r"stop_vertices works with the VTP family only"),
        "stop vertex a face point": (lambda: m.distances(0, stop_vertices=[(0, (0.2, 0.3, 0.5))]),
                                     r"a vertex id is expected"),
        # no sources
        "no sources": (lambda: m.distances([]), r"no source"),
        "no sources, an empty array": (lambda: m.distances(np.array([], dtype=np.int64)), r"no source"),
        "no sources for a matrix": (lambda: m.distance_matrix([]), r"no source"),
        "no sources for paths": (lambda: P([]), r"no source"),
        "no sources for voronoi": (lambda: m.voronoi([]), r"no source"),
        # sampling
        "count=0": (lambda: m.farthest_point_sampling(0), r"at least 1, got 0"),
        "count > n": (lambda: m.farthest_point_sampling(37), r"37 samples.*only 36 vertices"),
        "radius negative": (lambda: m.farthest_point_sampling(3, radius=-1), r"radius must be a positive"),
        "radius NaN": (lambda: m.farthest_point_sampling(3, radius=np.nan), r"radius must be a positive"),
        "first sample twice": (lambda: m.farthest_point_sampling(3, first=[0, 0]), r"sample 0 is given twice"),
        "more first samples than count": (lambda: m.farthest_point_sampling(1, first=[0, 1]), r"more than the 1"),
        # patterns
        "pattern not marked": (lambda: m.detect_patterns(), r"mark the pattern"),
        "pattern marked twice": (lambda: m.detect_patterns(center=0, radius=0.1, vertices=[1, 2]), r"not both"),
        "pattern center without radius": (lambda: m.detect_patterns(center=0), r"radius"),
        "pattern empty scales": (lambda: m.detect_patterns(center=0, radius=0.1, scales=(2, 1)), r"empty scale range"),
        "pattern spacing zero": (lambda: m.detect_patterns(center=14, radius=0.2, sample_spacing=0),
                                 r"sample_spacing must be positive"),
        # progress
        "progress not callable": (lambda: m.distances(0, progress=5), r"progress must be a function"),
        "progress not callable for a matrix": (lambda: m.distance_matrix([0], progress="x"), r"progress must be"),
        "progress not callable for paths": (lambda: P(0, progress=1.0), r"progress must be a function"),
        "progress not callable for voronoi": (lambda: m.voronoi([0, 1], progress=[]), r"progress must be"),
        "progress not callable for sampling": (lambda: m.farthest_point_sampling(2, progress=3), r"progress must"),
        # module-level functions
        "a Mesh and faces": (lambda: geo.distances(m, F, 0), r"not both"),
    }


CASE_NAMES = list(cases(np.zeros((36, 3)), np.zeros((50, 3), dtype=int), None))


@pytest.mark.parametrize("name", CASE_NAMES)
def test_bad_input_raises_geodesic_error(small, name):
    V, F, m = small
    function, message = cases(V, F, m)[name]
    with pytest.raises(geo.GeodesicError, match=message) as info:
        function()
    assert isinstance(info.value, ValueError), f"{name}: GeodesicError is not a ValueError"
    assert len(str(info.value)) > 10, f"{name}: the message says nothing: {info.value!r}"


def test_geodesic_error_is_a_value_error():
    assert issubclass(geo.GeodesicError, ValueError)
    assert issubclass(geo.Cancelled, Exception) and not issubclass(geo.Cancelled, ValueError)
    assert geo.GeodesicError.__doc__ and geo.Cancelled.__doc__


def test_reading_a_missing_file(tmp_path):
    # as open() does: an OSError with the errno and the file name
    missing = tmp_path / "no such mesh.off"
    for read in (geo.read_mesh, lambda p: geo.Mesh.read(str(p))):
        with pytest.raises(FileNotFoundError) as info:
            read(missing)
        assert info.value.filename == str(missing), "the error does not name the file"


@pytest.mark.parametrize("content", [
    "",
    "OFF\n3 1 0\n0 0 0\n1 0\n",
    "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
    "OFF\n3 1 0\n0 0 nan\n1 0 0\n0 1 0\n3 0 1 2\n",
    "not a mesh at all\n",
], ids=["empty", "truncated", "index-out-of-range", "nan", "garbage"])
def test_reading_a_bad_file(tmp_path, content):
    path = tmp_path / "bad.off"
    path.write_text(content)
    with pytest.raises(geo.GeodesicError, match="bad.off"):
        geo.read_mesh(path)


def test_reading_a_folder(tmp_path):
    with pytest.raises(IsADirectoryError) as info:
        geo.read_mesh(tmp_path)
    assert info.value.filename == str(tmp_path)


def test_source_in_no_face(small):
    V, F, _ = small
    m = geo.Mesh(np.vstack([V, [[5.0, 5.0, 5.0]]]), F)  # point 36 is in no face
    assert m.repairs["isolated_points"] == 1
    with pytest.raises(geo.GeodesicError, match="vertex 36 is in no face"):
        m.distances(36)
    with pytest.raises(geo.GeodesicError, match="vertex 36 is in no face"):
        geo.GeodesicPaths(m, 36)
    d = m.distances([36, 0])  # with another source: the isolated point is at 0, the others reached
    assert d[36] == 0 and np.all(np.isfinite(d))


def test_face_point_in_a_polygon():
    V = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [2, 0, 0]], dtype=float)
    m = geo.Mesh(V, [[0, 1, 2, 3], [1, 4, 2]])
    with pytest.raises(geo.GeodesicError, match="face 0 of the file is not a triangle.*4 vertices"):
        m.distances((0, (0.2, 0.3, 0.5)))
    assert m.distances((1, (0.2, 0.3, 0.5)))[0] > 0


def test_the_mesh_works_after_errors(small):
    V, F, m = small
    reference = geo.Mesh(V, F).distances([0, 7])
    for bad in ((3, (0.5, 0.5, 0.5)), [0, 99], [(3, (0.2, 0.3, 0.5)), (3, (1, 1, 1))]):
        with pytest.raises(geo.GeodesicError):
            m.distances(bad)
        assert m.distances([0, 7]).tobytes() == reference.tobytes()


def test_a_progress_function_that_raises_propagates_its_exception(elephant, elephant_path, big_grid):
    class Boom(Exception):
        pass

    def progress(done):
        raise Boom("from the progress function")

    with pytest.raises(Boom):
        elephant.distance_matrix(np.arange(300), threads=1, progress=progress)
    big = big_grid[2]
    with pytest.raises(Boom):
        big.distances(0, threads=1, progress=progress)
    assert elephant.distances(0).tobytes() == geo.read_mesh(elephant_path).distances(0).tobytes()
    assert big.distances(0, max_distance=0.1).tobytes() == geo.Mesh(*big_grid[:2]).distances(
        0, max_distance=0.1).tobytes()


# ----------------------------------------------------------------------------------------------
# Exact only, and argument names


@pytest.mark.parametrize("call", ["paths", "voronoi"])
def test_lam_is_no_argument_of_the_exact_applications(small, call):
    # an unknown keyword is Python's own TypeError, naming the argument
    with pytest.raises(TypeError, match="lam|incompatible"):
        if call == "paths":
            geo.GeodesicPaths(small[2], 0, lam=4)
        else:
            small[2].voronoi([0, 1], lam=4)


@pytest.mark.parametrize("algorithm", ["avtp", "pavtp"])
def test_approximate_algorithms_refused_by_paths_and_voronoi(small, algorithm):
    with pytest.raises(geo.GeodesicError, match=f"'{algorithm}' is approximate; paths and Voronoi diagrams are exact"):
        geo.GeodesicPaths(small[2], 0, algorithm=algorithm)
    with pytest.raises(geo.GeodesicError, match=f"'{algorithm}' is approximate"):
        small[2].voronoi([0, 1], algorithm=algorithm)


@pytest.mark.parametrize("algorithm", ["vtp", "avtp", "fwp_mmp", "mmp"])
def test_sequential_algorithms_refuse_more_threads(small, algorithm):
    with pytest.raises(geo.GeodesicError, match=f"'{algorithm}' runs on one thread: for threads=2"):
        small[2].distances(0, algorithm=algorithm, threads=2)
    small[2].distances(0, algorithm=algorithm, threads=1)  # one thread is what it runs on


def test_lam_with_an_exact_algorithm(small):
    with pytest.raises(geo.GeodesicError, match="lam .* applies to algorithm 'avtp' and 'pavtp' only, not 'pvtp'"):
        small[2].distances(0, algorithm="pvtp", lam=4)


@pytest.mark.parametrize("max_distance", [-np.inf, np.nan], ids=["-inf", "nan"])
def test_non_finite_max_distance_for_a_matrix(small, max_distance):
    with pytest.raises(geo.GeodesicError, match="max_distance"):
        small[2].distance_matrix([0], max_distance=max_distance)


def test_barycentric_coordinates_not_numbers(small):
    with pytest.raises(geo.GeodesicError, match="barycentric"):
        small[2].distances((3, ("a", "b", "c")))


def test_bad_barycentric_message_gives_the_coordinates_as_given(small):
    with pytest.raises(geo.GeodesicError) as info:
        small[2].distances((3, (0.25, 0.5, 0.375)))
    assert "(0.25, 0.5, 0.375)" in str(info.value), str(info.value)
    assert "sum to 1.125, not 1" in str(info.value), str(info.value)


# ----------------------------------------------------------------------------------------------
# Never a crash: inputs tried in a child process


def run_child(code):
    """Runs `code` (after a small mesh is made as m) in a child interpreter; returns (rc, out, err)."""
    prelude = textwrap.dedent("""
        import numpy as np
        import cgal_ext_geodesics as geo
        V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [5, 5, 5]], dtype=float)
        F = np.array([[0, 1, 2], [1, 3, 2]])
        m = geo.Mesh(V, F)
        def outcome(f):
            try:
                f()
                return "ok"
            except geo.GeodesicError as e:
                return "GeodesicError: " + str(e)
            except Exception as e:
                return type(e).__name__ + ": " + str(e)
    """)
    r = subprocess.run([sys.executable, "-c", prelude + textwrap.dedent(code)], capture_output=True, text=True,
                       timeout=120)
    return r.returncode, r.stdout, r.stderr


def test_odd_inputs_never_crash():
    rc, out, err = run_child("""
        tries = [
            lambda: geo.Mesh(V, [[0, 0, 1], [1, 3, 2]]).distances(1),
            lambda: geo.Mesh(V * 1e300, F).distances(0),
            lambda: geo.Mesh(V * 1e-300, F).distances(0),
            lambda: geo.Mesh(V, [[0, 1], [1, 3, 2]]),
            lambda: geo.Mesh(V, [[], [1, 3, 2]]),
            lambda: geo.Mesh(V, np.array([[0, 1, 2], [1, 3]], dtype=object)),
            lambda: geo.Mesh(V, np.array([[0, 1, 2**64 - 1]], dtype=np.uint64)),
            lambda: m.distances(np.array([2**64 - 1], dtype=np.uint64)),
            lambda: m.distances(2**63 - 1),
            lambda: m.distances(2**70),
            lambda: m.distances([4]),
            lambda: m.voronoi([0, 0]),
            lambda: m.distance_matrix([0], targets=[]),
            lambda: m.distance_matrix([0], targets=[], max_distance=1.0),
            lambda: m.farthest_point_sampling(5),
            lambda: m.farthest_point_sampling(1, first=[]),
            lambda: geo.GeodesicPaths(m, 0).path(4),
            lambda: geo.GeodesicPaths(m, 0).path_locations(4),
            lambda: m.distances(0, threads=64),
            lambda: m.distances((0, [0.2, 0.3])),
            lambda: m.distances(((0, 1), (0.2, 0.3, 0.5))),
            lambda: m.distances([[0], [1]]),
            lambda: m.distances({0: 1}),
            lambda: m.distances(0, stop_vertices=[]),
            lambda: m.detect_patterns(vertices=[]),
        ]
        for i, f in enumerate(tries):
            print(i, outcome(f), flush=True)
    """)
    assert rc == 0, f"the child process ended with {rc} (a crash) after:\n{out}\n{err[-2000:]}"


@pytest.mark.parametrize("call", ["m.distances(0, threads={t})", "geo.GeodesicPaths(m, 0, threads={t})",
                                  "m.voronoi([0, 3], threads={t})", "m.farthest_point_sampling(2, threads={t})"],
                         ids=["distances", "paths", "voronoi", "sampling"])
def test_huge_thread_counts_never_crash(call):
    rc, out, err = run_child(f"""
        r = outcome(lambda: {call.format(t=100000)})
        print(r)
        assert r == "ok" or "threads" in r, r
    """)
    assert rc == 0, f"{call.format(t=100000)}: the child process ended with {rc}:\n{out}\n{err[-1000:]}"


# ----------------------------------------------------------------------------------------------
# Inputs the review found mishandled


def test_faces_of_uint64_beyond_int64(small):
    V, F, m = small
    bad = np.array([[0, 1, 2 ** 64 - 1]], dtype=np.uint64)
    with pytest.raises(geo.GeodesicError, match=f"vertex id {2 ** 64 - 1} is out of range"):
        geo.Mesh(V, bad)
    assert geo.Mesh(V, F.astype(np.uint64)).n_faces == len(F)


def test_read_mesh_takes_str_bytes_and_paths_and_says_when_the_file_is_missing(elephant_path, tmp_path):
    for path in (str(elephant_path), elephant_path, bytes(elephant_path)):
        assert geo.read_mesh(path).n_vertices == 2775
    with pytest.raises(FileNotFoundError) as info:
        geo.read_mesh(tmp_path / "nowhere.off")
    assert info.value.filename == str(tmp_path / "nowhere.off")


def test_face_points_as_two_arrays_of_integer_coordinates(small):
    m = small[2]
    as_ints = m.distances((np.array([3]), np.array([[1, 0, 0]])))
    as_floats = m.distances((np.array([3]), np.array([[1.0, 0.0, 0.0]])))
    assert as_ints.tobytes() == as_floats.tobytes()


def test_a_sequential_algorithm_names_the_parallel_ones(small):
    with pytest.raises(geo.GeodesicError) as info:
        small[2].distances(0, algorithm="vtp", threads=2)
    message = str(info.value)
    assert "'pvtp'" in message and "'pmmp'" in message
    assert "'mmp'" not in message and "'vtp'," not in message, message


def test_face_point_message_gives_the_coordinates_to_the_last_digit(small):
    with pytest.raises(geo.GeodesicError) as info:
        small[2].distances((3, (1 / 3, 1 / 3, 0.5)))
    assert f"({1 / 3!r}, {1 / 3!r}, 0.5)" in str(info.value), str(info.value)


def test_matrix_rows_of_an_isolated_vertex():
    # vertex 4 is in no face: its row is 0 at itself, inf (dense) or absent (sparse) elsewhere
    V = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 0], [5, 5, 5]], dtype=float)
    m = geo.Mesh(V, [[0, 1, 2], [1, 3, 2]])
    sources = [4, 0, 4, 3]
    dense = m.distance_matrix(sources)
    assert dense.shape == (4, 5)
    for r in (0, 2):
        assert dense[r, 4] == 0 and np.all(np.isinf(dense[r, :4])), dense[r]
    for r, s in ((1, 0), (3, 3)):
        assert np.array_equal(dense[r], m.distances(s)), r
    sparse = m.distance_matrix(sources, max_distance=10)
    assert sparse.shape == (4, 5)
    for r in (0, 2):
        assert sparse[r].indices.tolist() == [4] and sparse[r].data.tolist() == [0.0]
    assert np.array_equal(sparse.toarray()[1, :4], dense[1, :4])
    assert np.array_equal(m.distance_matrix([4], targets=[0, 4]), [[np.inf, 0.0]])
