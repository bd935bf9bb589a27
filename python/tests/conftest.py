# Copyright (c) 2026 The CGAL_ext geodesics developers.
"""Fixtures of the Python tests of cgal_ext_geodesics.

The environment (CTest sets it, see python/CMakeLists.txt):
  PYTHONPATH               the build tree's python/ folder, where the package is
  CGAL_EXT_GEODESIC_TOOL   the `geodesic` command-line tool; unset: `geodesic` in PATH, and
                           without either the comparisons with the tool are skipped (and say so)
  CGAL_EXT_DATA_DIR        the folder of the bundled meshes (elephant.off, mushroom.off);
                           unset: the repository's data/ folder next to python/
"""

import os
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import cgal_ext_geodesics as geo

_HERE = Path(__file__).resolve().parent


# ----------------------------------------------------------------------------------------------
# The environment


def _data_dir():
    env = os.environ.get("CGAL_EXT_DATA_DIR")
    return Path(env) if env else _HERE.parent.parent / "data"


def _tool_path():
    env = os.environ.get("CGAL_EXT_GEODESIC_TOOL")
    if env:
        return env
    return shutil.which("geodesic")


@pytest.fixture(scope="session")
def data_dir():
    d = _data_dir()
    assert d.is_dir(), f"the data folder {d} (CGAL_EXT_DATA_DIR) does not exist"
    return d


@pytest.fixture(scope="session")
def tool():
    """The path of the `geodesic` tool; skips (saying why) the test when there is none."""
    path = _tool_path()
    if not path:
        pytest.skip("no geodesic tool: CGAL_EXT_GEODESIC_TOOL is unset and `geodesic` is not in PATH, "
                    "so the comparisons with the tool are skipped")
    assert os.path.isfile(path) and os.access(path, os.X_OK), \
        f"CGAL_EXT_GEODESIC_TOOL={path} is not an executable file"
    return path


@pytest.fixture(scope="session")
def run_tool(tool):
    """run_tool(*args) runs the tool, fails the test with its output when it fails, returns stderr."""

    def run(*args, expect_failure=False):
        args = [str(a) for a in args]
        r = subprocess.run([tool, *args], capture_output=True, text=True, timeout=120)
        if expect_failure:
            assert r.returncode != 0, f"`geodesic {' '.join(args)}` succeeded, a failure was expected"
        else:
            assert r.returncode == 0, (f"`geodesic {' '.join(args)}` failed with {r.returncode}:\n"
                                       f"{r.stdout}\n{r.stderr}")
        return r.stderr

    return run


@pytest.fixture(scope="session", params=["elephant.off", "mushroom.off"])
def bundled(request, data_dir):
    """(path, Mesh) of each bundled mesh."""
    path = data_dir / request.param
    assert path.is_file(), f"missing bundled mesh {path}"
    return path, geo.read_mesh(path)


@pytest.fixture(scope="session")
def elephant(data_dir):
    path = data_dir / "elephant.off"
    assert path.is_file(), f"missing bundled mesh {path}"
    return geo.read_mesh(path)


@pytest.fixture(scope="session")
def elephant_path(data_dir):
    return data_dir / "elephant.off"


# ----------------------------------------------------------------------------------------------
# Meshes made in NumPy


def grid_mesh(n, seed=0, noise=0.002, jitter=0.0):
    """An n x n height field over [0, 1]^2, two triangles per cell, (V float64, F int64)."""
    rng = np.random.default_rng(seed)
    x, y = np.meshgrid(np.linspace(0, 1, n), np.linspace(0, 1, n), indexing="ij")
    if jitter:
        h = 1.0 / (n - 1)
        inner = np.zeros_like(x, dtype=bool)
        inner[1:-1, 1:-1] = True
        x = x + inner * rng.uniform(-jitter, jitter, x.shape) * h
        y = y + inner * rng.uniform(-jitter, jitter, y.shape) * h
    z = 0.05 * np.sin(6 * x + seed) * np.cos(5 * y) + noise * rng.standard_normal(x.shape)
    V = np.stack([x, y, z], -1).reshape(-1, 3)
    i = (np.arange(n - 1)[:, None] * n + np.arange(n - 1)[None, :]).ravel()
    F = np.concatenate([np.stack([i, i + n, i + 1], 1), np.stack([i + 1, i + n, i + n + 1], 1)])
    return V, F.astype(np.int64)


def sphere_mesh(points, seed=0, noise=0.05):
    """A closed, star-shaped mesh: the convex hull of random directions, each pushed out by a
    random radius (the faces' orientation as the hull gives it: the Mesh repairs it)."""
    from scipy.spatial import ConvexHull

    rng = np.random.default_rng(seed)
    d = rng.standard_normal((points, 3))
    d /= np.linalg.norm(d, axis=1)[:, None]
    F = ConvexHull(d).simplices.astype(np.int64)
    V = d * (1 + noise * rng.uniform(-1, 1, (points, 1))) * np.array([1.0, 0.8, 0.6])
    return V, F


class RandomMesh:
    """A random mesh from a seed; `what` names it (and its seed) in assertion messages."""

    def __init__(self, seed, kind):
        self.seed, self.kind = seed, kind
        rng = np.random.default_rng(seed)
        if kind == "grid":
            n = int(rng.integers(12, 24))
            self.V, self.F = grid_mesh(n, seed=seed, noise=0.01, jitter=0.3)
        else:
            self.V, self.F = sphere_mesh(int(rng.integers(150, 400)), seed=seed)
        self.what = f"random {kind} mesh, seed={seed} ({len(self.V)} vertices)"
        self.mesh = geo.Mesh(self.V, self.F)


RANDOM_SEEDS = [(s, k) for s in (1, 2, 3) for k in ("grid", "sphere")]


@pytest.fixture(scope="session")
def make_random_mesh():
    """make_random_mesh(seed, kind='grid'|'sphere') -> RandomMesh (V, F, mesh, what)."""
    return RandomMesh


@pytest.fixture(scope="session", params=RANDOM_SEEDS, ids=[f"{k}-seed{s}" for s, k in RANDOM_SEEDS])
def random_mesh(request):
    seed, kind = request.param
    return RandomMesh(seed, kind)


@pytest.fixture(scope="session")
def big_grid():
    """A 400 x 400 height field (160,000 vertices), prepared (its first solve done)."""
    V, F = grid_mesh(400, seed=7)
    mesh = geo.Mesh(V, F)
    mesh.distances(0, threads=1, max_distance=0.01)
    return V, F, mesh


def pytest_report_header(config):
    tool = _tool_path()
    return [f"cgal_ext_geodesics: {geo.__file__}",
            f"geodesic tool: {tool or 'none: the comparisons with the tool are skipped'}",
            f"data: {_data_dir()}"]
