// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_DISTANCE_ROWS_DISTANCE_ROWS_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_DISTANCE_ROWS_DISTANCE_ROWS_H

// The rows of a distance matrix, dense or sparse: independent single-source solves on one
// solver mesh, in parallel across sources, handed over in source order from the calling thread.

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>
#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/VTP_solver.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Mesh_setup.h>
#include <CGAL_ext/Geodesics_3/internal/support/Parallel_for.h>
#include <CGAL_ext/Geodesics_3/internal/support/Progress_reporter.h>
#include <CGAL_ext/Geodesics_3/internal/support/Solver_arena.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// One entry of a sparse row: a vertex index and its distance.
typedef std::pair<std::size_t, double> Row_entry;

/// The memory the rows of a batch may take (`for_each_row`).
constexpr std::size_t row_budget_bytes = std::size_t(64) << 20;
/// The time a batch of rows should take (`for_each_row`): the callback hears of the rows a few
/// times a second.
constexpr double batch_seconds = 0.2;

/// What the `add_stops` of `Row_solvers::for_each_row_stopping` may set on the solver of a row:
/// stop vertices, given by mesh vertex index, and the stop floor.
class Row_stops
{
public:
  Row_stops(VTP_solver& solver, const Solver_mesh& mesh) : m_solver(solver), m_mesh(mesh) {}
  /// (an index out of range is passed on, for the solver's check to name it)
  void add_stop_vertex(std::size_t mesh_vertex)
  {
    m_solver.add_stop_vertex(mesh_vertex < m_mesh.number_of_mesh_vertices ? m_mesh.cache_vertex(int(mesh_vertex))
                                                                          : int(mesh_vertex));
  }
  void set_stop_floor_in_mesh_unit(double floor) { m_solver.set_stop_floor_in_mesh_unit(floor); }

private:
  VTP_solver& m_solver;
  const Solver_mesh& m_mesh;
};

/// The `add_stops` of `Row_solvers::for_each_row_stopping` that gives every row the stop vertices
/// `stop` (mesh vertex indices), kept by reference.
template <class StopVertices>
auto same_stops_for_every_row(const StopVertices& stop)
{
  return [&stop](std::size_t, Row_stops& stops) {
    for(auto v : stop)
      stops.add_stop_vertex(std::size_t(v));
  };
}

/// Single-source VTP solves on one mesh, any number of calls: the solver mesh, the task arena
/// and one solver per thread are made once and kept (a caller that asks for a few rows at a
/// time, again and again, pays for them once, and a row costs what it sweeps). One call at a
/// time: the calls share the solvers.
template <bool parallel, class TriangleMesh, class VertexPointMap>
class Row_solvers
{
public:
  typedef Mesh_setup<TriangleMesh, VertexPointMap> Setup;

  /// Reads the named parameters as `geodesic_distance_rows()` does (VTP only).
  template <class NamedParameters>
  Row_solvers(const TriangleMesh& tm, const NamedParameters& np)
    : m_settings(vtp_settings(np))
    , m_progress(std::exchange(m_settings.callback, {}), "the distance rows")
    , m_own_mesh(std::in_place, tm, np)
    , m_mesh(*m_own_mesh)
    , m_arena(m_settings.number_of_threads)
  {
  }

  /// On a solver mesh the caller made and keeps, read only (several `Row_solvers` may share
  /// it); `settings` as `read_solver_settings()` checks them, VTP's.
  Row_solvers(const Setup& prepared, Solver_settings settings)
    : m_settings(std::move(settings))
    , m_progress(std::exchange(m_settings.callback, {}), "the distance rows")
    , m_mesh(prepared)
    , m_arena(m_settings.number_of_threads)
  {
  }

  const Setup& mesh() const { return m_mesh; }
  /// The max distance of the named parameters (+infinity without), in the mesh's unit.
  double max_distance_asked() const { return m_settings.max_distance; }

  /// Runs one solve from each of `points`, within `max_distance` (in the mesh's unit) and, when
  /// `stop` (a range of mesh vertex indices) is not empty, until each of its vertices is settled; in
  /// parallel across sources. Calls `make_row(solver, mesh, row)` after each run, on the thread
  /// that ran it, then `hand_over(i, row)` in source order from the calling thread. A batch of
  /// rows is solved, then handed over: as many rows as fit `row_budget_bytes` at the size of the
  /// rows made so far, and as the threads solve in `batch_seconds` at the speed so far, between 1
  /// and 64 per thread (the threads wait for the batch's last row: the longer the batch, the less
  /// they wait; the shorter, the sooner the caller's callback hears of it and can cancel).
  template <class Row, class StopVertices, class MakeRow, class HandOver>
  void for_each_row(const std::vector<Source_point>& points, double max_distance, const StopVertices& stop,
                    MakeRow make_row, HandOver hand_over)
  {
    for_each_row_stopping<Row>(points, max_distance, same_stops_for_every_row(stop), make_row, hand_over);
  }

  /// The same, the stop vertices of row i given by `add_stops(i, solver)` (which may also set
  /// the solver's stop floor).
  template <class Row, class AddStops, class MakeRow, class HandOver>
  void for_each_row_stopping(const std::vector<Source_point>& points, double max_distance, const AddStops& add_stops,
                             MakeRow make_row, HandOver hand_over)
  {
    if(points.empty())
      throw Geodesic_error("no source was given");
    m_progress.start();
    m_arena.execute([&] {
      const std::size_t threads = parallel ? arena_concurrency() : 1;
      if(m_solvers.size() < threads) {
        m_solvers.resize(threads);
        m_run_statistics.resize(threads);
      }
      std::size_t batch = threads;
      std::size_t rows_made = 0, bytes_made = 0;
      const auto start = std::chrono::steady_clock::now();
      std::vector<Row> rows;
      for(std::size_t first = 0, n = 0; first < points.size(); first += n) {
        m_progress.report([&] { return double(first) / double(points.size()); });
        n = std::min(batch, points.size() - first);
        if(rows.size() < n)
          rows.resize(n);
        for_each_index(parallel, n, 1, [&](std::size_t j, std::size_t slot) {
          std::unique_ptr<VTP_solver>& solver = m_solvers[slot];
          if(!solver)
            solver = std::make_unique<VTP_solver>(m_mesh.cache(), m_settings, false);
          try {
            solver->reset();
            solver->set_max_distance_in_mesh_unit(max_distance);
            solver->add_source(points[first + j]);
            Row_stops stops(*solver, m_mesh.cache());
            add_stops(first + j, stops);
            solver->run();
            add_run_statistics(m_run_statistics[slot], solver->statistics());
            make_row(*solver, m_mesh, rows[j]);
          } catch(...) {
            solver = nullptr; // a run cut short leaves windows that `reset()` does not clear
            throw;
          }
        });
        for(std::size_t j = 0; j < n; ++j) {
          bytes_made += rows[j].size() * sizeof(typename Row::value_type);
          hand_over(first + j, static_cast<const Row&>(rows[j]));
        }
        rows_made += n;
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        const double by_time = seconds > 0 ? batch_seconds * double(rows_made) / seconds : double(64 * threads);
        const double by_memory = double(row_budget_bytes) * double(rows_made) / double(std::max<std::size_t>(bytes_made, 1));
        batch = std::size_t(std::clamp(std::min(by_time, by_memory), double(threads), double(64 * threads)));
      }
    });
  }

  /// What the runs of every call so far did, summed over the threads (seconds of solve are the
  /// threads' together), with the set-up's seconds; given to the caller who asked with `statistics`.
  Geodesic_statistics report_statistics() const
  {
    Geodesic_statistics total;
    for(const Geodesic_statistics& s : m_run_statistics)
      add_run_statistics(total, s);
    total.vertices = m_mesh.cache().number_of_mesh_vertices;
    total.faces = m_mesh.cache().number_of_faces;
    return internal::report_statistics(m_settings, total, m_mesh.seconds());
  }

private:
  template <class NamedParameters>
  static Solver_settings vtp_settings(const NamedParameters& np)
  {
    const Solver_settings settings = read_solver_settings(np, VTP);
    if(settings.algorithm != VTP)
      throw Geodesic_error("distance matrices are computed with VTP, got algorithm " +
                           std::to_string(int(settings.algorithm)));
    return settings;
  }

  Solver_settings m_settings; // without the callback: the rows' solvers run on any thread
  Progress_reporter m_progress; // the caller's callback: rows handed over, from the calling thread
  std::optional<Setup> m_own_mesh; // unless the caller's is used
  const Setup& m_mesh;
  Solver_arena<parallel> m_arena;
  std::vector<std::unique_ptr<VTP_solver>> m_solvers; // by thread slot
  std::vector<Geodesic_statistics> m_run_statistics;   // by thread slot: its runs, summed
};

/// Calls `make_row(solver, mesh, row)` after a sequential VTP run from each source (see
/// `Row_solvers::for_each_row`), then `hand_over(i, row)` in source order.
template <bool parallel, class Row, class TriangleMesh, class Sources, class MakeRow, class HandOver,
          class NamedParameters>
void for_each_row(const TriangleMesh& tm, const Sources& sources, const NamedParameters& np, MakeRow make_row,
                  HandOver hand_over)
{
  Row_solvers<parallel, TriangleMesh, Vertex_point_map_of<TriangleMesh, NamedParameters>> solvers(tm, np);
  solvers.template for_each_row<Row>(solvers.mesh().source_points(sources), solvers.max_distance_asked(),
                                     std::vector<int>(), make_row, hand_over);
  solvers.report_statistics();
}

/// A sparse row: the vertices the last run of `solver` reached (within its limit), by vertex
/// index, in order, with their distances in the mesh's unit.
template <class Setup>
void make_sparse_row(const VTP_solver& solver, const Setup& mesh, std::vector<Row_entry>& row)
{
  const std::vector<double>& d = solver.distances();
  row.clear();
  const Solver_mesh& cache = mesh.cache();
  for(int v : solver.reached_vertices())
    if(std::size_t(v) < cache.number_of_mesh_vertices && d[std::size_t(v)] < VTP_solver::infinity())
      row.emplace_back(std::size_t(cache.mesh_vertex(v)), mesh.to_mesh_unit(d[std::size_t(v)]));
  std::sort(row.begin(), row.end());
}

/// Dense rows: the distance of every vertex of the mesh, by vertex index.
template <bool parallel, class TriangleMesh, class Sources, class RowFunction, class NamedParameters>
void distance_rows(const TriangleMesh& tm, const Sources& sources, RowFunction& row, const NamedParameters& np)
{
  for_each_row<parallel, std::vector<double>>(
    tm, sources, np,
    [](const VTP_solver& solver, const auto& mesh, std::vector<double>& r) {
      const std::vector<double>& d = solver.distances();
      const Solver_mesh& cache = mesh.cache();
      r.assign(cache.number_of_mesh_vertices, VTP_solver::infinity());
      for(int v : solver.reached_vertices())
        if(std::size_t(v) < r.size())
          r[std::size_t(cache.mesh_vertex(v))] = mesh.to_mesh_unit(d[std::size_t(v)]);
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
    [](const VTP_solver& solver, const auto& mesh, std::vector<Row_entry>& r) { make_sparse_row(solver, mesh, r); },
    row);
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_DISTANCE_ROWS_DISTANCE_ROWS_H
