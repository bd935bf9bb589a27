#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL_ext geodesics developers.
"""What the Python module costs over the C++ it calls, side by side, in alternating runs.

1. One exact solve (sequential VTP from vertex 0): the tool's `seconds_solve` and
   `seconds_setup` (from --stats) against the module's first call on a fresh Mesh (set-up and
   solve) and a second call on the same Mesh (prepared: the solve only).
2. Local rows (every vertex within R mean edge lengths of each of K sources, one thread):
   bench_matrix (the C++ API, one geodesic_sparse_distance_rows call, its set-up included)
   against Mesh.distance_matrix with max_distance (a SciPy CSR matrix) on a new Mesh (set-up
   included) and again on the same Mesh, and against K calls of Mesh.distances(algorithm="vtp")
   with max_distance on that Mesh (each a dense (n,) array).

Prints one line per run and the medians. Run it with Debian's interpreter and the module on
the path, with nothing else running:
  PYTHONPATH=build/python /usr/bin/python3 bench/python_overhead.py --mesh armadillo_loop1.off \
      --tool build/src/geodesic --bench-matrix build/bench/bench_matrix
"""

import argparse
import os
import statistics
import subprocess
import tempfile
import time

import numpy as np

import cgal_ext_geodesics as geo


def tool_solve(tool, mesh):
    with tempfile.TemporaryDirectory() as work:
        out = subprocess.run([tool, "distances", mesh, "--source", "0", "--algorithm", "vtp", "--stats",
                              "--output", os.path.join(work, "d.txt")], capture_output=True, text=True,
                             check=True).stderr
    stats = dict(line.split("=", 1) for line in out.splitlines() if "=" in line)
    return float(stats["seconds_setup"]), float(stats["seconds_solve"])


def python_solves(mesh_path):
    mesh = geo.read_mesh(mesh_path)
    t = time.perf_counter()
    first = mesh.distances(0, algorithm="vtp")
    first_seconds = time.perf_counter() - t
    t = time.perf_counter()
    second = mesh.distances(0, algorithm="vtp")
    second_seconds = time.perf_counter() - t
    assert np.array_equal(first, second)
    return first_seconds, second_seconds


def mean_edge_length(mesh):
    v, f = mesh.vertices, mesh.faces
    e = np.concatenate([v[f[:, 1]] - v[f[:, 0]], v[f[:, 2]] - v[f[:, 1]], v[f[:, 0]] - v[f[:, 2]]])
    return float(np.linalg.norm(e, axis=1).mean())


def cpp_rows(bench_matrix, mesh_path, rows, radius_edges):
    out = subprocess.run([bench_matrix, "--mesh", mesh_path, "--rows", str(rows), "--radius", str(radius_edges),
                          "--threads", "1", "--sparse", "1"], capture_output=True, text=True, check=True).stdout
    stats = dict(item.split("=", 1) for item in out.split())
    return float(stats["seconds_per_row"]), float(stats["entries_per_row"])


def python_rows(mesh_path, rows, radius_edges):
    """Per row: distance_matrix on a new Mesh (its set-up included, as in the C++ call), again on
    the same Mesh (reused), and `rows` calls of distances on a reused Mesh."""
    mesh = geo.read_mesh(mesh_path)
    n = mesh.n_vertices
    # the sources bench_matrix takes: vertex i * n / rows
    sources = [i * n // rows for i in range(rows)]
    radius = radius_edges * mean_edge_length(mesh)
    t = time.perf_counter()
    matrix = mesh.distance_matrix(sources, max_distance=radius, threads=1)
    first_call = (time.perf_counter() - t) / rows
    t = time.perf_counter()
    again = mesh.distance_matrix(sources, max_distance=radius, threads=1)
    reused_call = (time.perf_counter() - t) / rows
    assert (matrix != again).nnz == 0
    t = time.perf_counter()
    for s in sources:
        d = mesh.distances(s, algorithm="vtp", max_distance=radius)
    per_call = (time.perf_counter() - t) / rows
    reached = np.isfinite(d).sum()
    return first_call, reused_call, per_call, matrix.nnz / rows, reached


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--mesh", required=True)
    parser.add_argument("--tool", required=True)
    parser.add_argument("--bench-matrix", required=True)
    parser.add_argument("--rows", type=int, default=1000)
    parser.add_argument("--radius", type=float, default=5, help="in mean edge lengths")
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args()

    solve = {"tool setup": [], "tool solve": [], "tool setup+solve": [], "python first call": [],
             "python prepared call": []}
    rows = {"C++ rows, per row": [], "Mesh.distance_matrix, per row": [],
            "Mesh.distance_matrix reused, per row": [], "Mesh.distances calls, per row": []}
    for r in range(args.repeats):
        setup, seconds = tool_solve(args.tool, args.mesh)
        first, second = python_solves(args.mesh)
        solve["tool setup"].append(setup)
        solve["tool solve"].append(seconds)
        solve["tool setup+solve"].append(setup + seconds)
        solve["python first call"].append(first)
        solve["python prepared call"].append(second)
        print(f"run {r}: tool setup {setup:.4f} s solve {seconds:.4f} s | python first {first:.4f} s "
              f"prepared {second:.4f} s", flush=True)
        cpp, cpp_entries = cpp_rows(args.bench_matrix, args.mesh, args.rows, args.radius)
        first_call, reused_call, per_call, entries, reached = python_rows(args.mesh, args.rows, args.radius)
        rows["C++ rows, per row"].append(cpp)
        rows["Mesh.distance_matrix, per row"].append(first_call)
        rows["Mesh.distance_matrix reused, per row"].append(reused_call)
        rows["Mesh.distances calls, per row"].append(per_call)
        print(f"run {r}: rows C++ {1e3 * cpp:.3f} ms ({cpp_entries:.1f} entries) | distance_matrix "
              f"{1e3 * first_call:.3f} ms ({entries:.1f}), reused {1e3 * reused_call:.3f} ms | distances calls "
              f"{1e3 * per_call:.3f} ms (last: {reached})", flush=True)
    print("medians:")
    for name, values in list(solve.items()) + list(rows.items()):
        print(f"  {name}: {statistics.median(values):.5f} s")
    m = {k: statistics.median(v) for k, v in solve.items()}
    print(f"  python prepared call / tool solve: {m['python prepared call'] / m['tool solve']:.3f}")
    print(f"  python first call / tool setup+solve: {m['python first call'] / m['tool setup+solve']:.3f}")
    r = {k: statistics.median(v) for k, v in rows.items()}
    print(f"  distance_matrix / C++ rows: {r['Mesh.distance_matrix, per row'] / r['C++ rows, per row']:.3f}")
    print(f"  distance_matrix reused / C++ rows: "
          f"{r['Mesh.distance_matrix reused, per row'] / r['C++ rows, per row']:.3f}")
    print(f"  distances calls / C++ rows: {r['Mesh.distances calls, per row'] / r['C++ rows, per row']:.3f}")


if __name__ == "__main__":
    main()
