// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_DISTANCE_ROWS_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_DISTANCE_ROWS_H

// The rows of a distance matrix, dense or sparse: independent single-source solves on one mesh
// cache, in parallel across sources, handed over in source order from the calling thread.

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>
#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/internal/Geodesic_setup.h>
#include <CGAL_ext/Geodesics_3/internal/Parallel_for.h>
#include <CGAL_ext/Geodesics_3/internal/VTP_solver.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// One entry of a sparse row: a vertex index and its distance.
typedef std::pair<std::size_t, double> Row_entry;

/// The memory the rows of a batch may take (`for_each_row`).
constexpr std::size_t row_budget_bytes = std::size_t(64) << 20;

/// Calls `solve(i, solver)` for every source i, each a sequential VTP run on a solver of the
/// calling thread (kept and reset between rows: a row costs what it sweeps), in parallel across
/// sources; then `hand_over(i, solver_result)` in source order, from the calling thread, with
/// what `solve` made of row i. A batch of rows is solved, then handed over: as many rows as fit
/// `row_budget_bytes` at the size of the rows made so far, between 4 and 64 per thread (the
/// threads wait for the batch's last row: the longer the batch, the less they wait).
template <bool parallel, class Row, class TriangleMesh, class Sources, class MakeRow, class HandOver,
          class NamedParameters>
void for_each_row(const TriangleMesh& tm, const Sources& sources, const NamedParameters& np, MakeRow make_row,
                  HandOver hand_over)
{
  typedef Vertex_point_map_of<TriangleMesh, NamedParameters> Vertex_point_map;
  const Solver_settings settings = read_solver_settings(np, VTP);
  if(settings.algorithm != VTP)
    throw Geodesic_error("distance matrices are computed with VTP, got algorithm " +
                         std::to_string(int(settings.algorithm)));
  const Mesh_setup<TriangleMesh, Vertex_point_map> mesh(tm, np);
  const std::vector<Source_point> points = mesh.source_points(sources);
  if(points.empty())
    throw Geodesic_error("no source was given");

  run_in_arena<parallel>(settings.number_of_threads, [&] {
    const std::size_t threads = parallel ? arena_concurrency() : 1;
    std::vector<std::unique_ptr<VTP_solver>> solvers(threads);
    std::size_t batch = parallel ? 4 * threads : 1;
    std::size_t rows_made = 0, bytes_made = 0;
    std::vector<Row> rows;
    for(std::size_t first = 0, n = 0; first < points.size(); first += n) {
      n = std::min(batch, points.size() - first);
      if(rows.size() < n)
        rows.resize(n);
      for_each_index(parallel, n, 1, [&](std::size_t j, std::size_t slot) {
        std::unique_ptr<VTP_solver>& solver = solvers[slot];
        if(!solver)
          solver = std::make_unique<VTP_solver>(mesh.cache(), settings, false);
        solver->reset();
        solver->add_source(points[first + j]);
        solver->run();
        make_row(*solver, mesh, rows[j]);
      });
      for(std::size_t j = 0; j < n; ++j) {
        bytes_made += rows[j].size() * sizeof(typename Row::value_type);
        hand_over(first + j, static_cast<const Row&>(rows[j]));
      }
      rows_made += n;
      if(parallel)
        batch = std::clamp<std::size_t>(row_budget_bytes * rows_made / std::max<std::size_t>(bytes_made, 1),
                                        4 * threads, 64 * threads);
    }
  });
}

/// Dense rows: the distance of every vertex of the mesh, by vertex index.
template <bool parallel, class TriangleMesh, class Sources, class RowFunction, class NamedParameters>
void distance_rows(const TriangleMesh& tm, const Sources& sources, RowFunction& row, const NamedParameters& np)
{
  for_each_row<parallel, std::vector<double>>(
    tm, sources, np,
    [](const VTP_solver& solver, const auto& mesh, std::vector<double>& r) {
      const std::vector<double>& d = solver.distances();
      r.assign(mesh.cache().number_of_mesh_vertices, VTP_solver::infinity());
      for(int v : solver.reached_vertices())
        if(std::size_t(v) < r.size())
          r[std::size_t(v)] = mesh.to_mesh_unit(d[std::size_t(v)]);
    },
    row);
}

/// Sparse rows: the vertices reached (within the max distance), by vertex index, in order.
template <bool parallel, class TriangleMesh, class Sources, class RowFunction, class NamedParameters>
void sparse_distance_rows(const TriangleMesh& tm, const Sources& sources, RowFunction& row,
                          const NamedParameters& np)
{
  for_each_row<parallel, std::vector<Row_entry>>(
    tm, sources, np,
    [](const VTP_solver& solver, const auto& mesh, std::vector<Row_entry>& r) {
      const std::vector<double>& d = solver.distances();
      r.clear();
      for(int v : solver.reached_vertices())
        if(std::size_t(v) < mesh.cache().number_of_mesh_vertices && d[std::size_t(v)] < VTP_solver::infinity())
          r.emplace_back(std::size_t(v), mesh.to_mesh_unit(d[std::size_t(v)]));
      std::sort(r.begin(), r.end());
    },
    row);
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_DISTANCE_ROWS_H
