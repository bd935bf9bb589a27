// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_ROWS_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_ROWS_H

// The local distance rows of a pattern detection, all from one `Row_solvers` (made at the first
// row, released after the last), and the descent over vertices they serve (the patch's
// centroid, the instances' centres).

#include <CGAL_ext/Geodesics_3/internal/distance_rows/Distance_rows.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_mesh.h>

#include <CGAL/boost/graph/iterator.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// Local distance rows from vertices (by index): each row lists the vertices it reached, by
/// increasing index, with their distances. The detector owns it; its parts ask it for rows.
template <bool parallel, class TriangleMesh, class VertexPointMap, class VertexIndexMap>
class Pattern_rows
{
public:
  typedef Pattern_mesh<parallel, TriangleMesh, VertexPointMap, VertexIndexMap> Mesh;
  typedef std::vector<Row_entry> Row;

  /// `approximation`: lambda of AVTP for the rows; 0: exact.
  Pattern_rows(const Mesh& mesh, double approximation) : m_mesh(mesh), m_approximation(approximation) {}

  // Local distance rows from `sources` (vertex indices), within `radius` and, when `stop` (vertex
  // indices) is not empty, until each of its vertices is settled: `hand_over(i, row)` in order.
  template <class HandOver>
  void for_each_local_row(const std::vector<std::size_t>& sources, double radius, const HandOver& hand_over,
                          const std::vector<std::size_t>& stop = {})
  {
    for_each_local_row_stopping(sources, radius, same_stops_for_every_row(stop), hand_over);
  }

  // The same, the stop vertices of row i (and its stop floor) set by `add_stops(i, solver)`.
  template <class AddStops, class HandOver>
  void for_each_local_row_stopping(const std::vector<std::size_t>& sources, double radius, const AddStops& add_stops,
                                   const HandOver& hand_over)
  {
    if(!m_row_solvers) {
      if(m_approximation > 0)
        m_row_solvers.emplace(m_mesh.tm, m_mesh.solver_parameters().approximation(m_approximation));
      else
        m_row_solvers.emplace(m_mesh.tm, m_mesh.solver_parameters());
    }
    std::vector<Source_point> points;
    for(std::size_t v : sources)
      points.push_back(m_row_solvers->mesh().source_point(m_mesh.vertex[v]));
    m_row_solvers->template for_each_row_stopping<Row>(
      points, radius, add_stops,
      [](const VTP_solver& solver, const auto& mesh, Row& row) { make_sparse_row(solver, mesh, row); }, hand_over);
    m_rows += sources.size();
  }

  // One local distance row from `source`, within `radius`.
  Row local_row(std::size_t source, double radius)
  {
    Row row;
    for_each_local_row({source}, radius, [&](std::size_t, const Row& entries) { row = entries; });
    return row;
  }

  // A descent over vertices for several walkers at once (the patch's centroid, the instances'
  // centres). Walker w starts at start[w]; every step evaluates the vertices tried, one local
  // row each (within `radius`, and until the stop vertices that `add_stops(w, stops)` gives
  // walker w's rows are settled), in one batch:
  // first the starts, then the unvisited neighbours of each moving walker's best vertex that
  // `may_visit(w, vertex)` lets in. `cost(w, vertex, row)` is a vertex's cost; a walker stops
  // when none of its vertices tried costs less than its best, and all stop after `max_steps`.
  // Returns each walker's best vertex and its cost.
  template <class AddStops, class Cost, class MayVisit>
  std::vector<std::pair<std::size_t, double>> descend(const std::vector<std::size_t>& start, double radius,
                                                      const AddStops& add_stops, const Cost& cost,
                                                      const MayVisit& may_visit, int max_steps)
  {
    const std::size_t n = start.size();
    std::vector<std::pair<std::size_t, double>> best(n);
    std::vector<std::vector<std::size_t>> visited(n);
    std::vector<std::pair<std::size_t, std::size_t>> tried; // (walker, vertex)
    for(std::size_t w = 0; w < n; ++w) {
      best[w] = {start[w], std::numeric_limits<double>::infinity()};
      visited[w].push_back(start[w]);
      tried.emplace_back(w, start[w]);
    }
    for(int step = 0; step < max_steps && !tried.empty(); ++step) {
      std::vector<std::size_t> sources;
      for(const auto& t : tried)
        sources.push_back(t.second);
      std::vector<bool> moved(n, false);
      for_each_local_row_stopping(
        sources, radius, [&](std::size_t r, Row_stops& stops) { add_stops(tried[r].first, stops); },
        [&](std::size_t r, const Row& entries) {
          const auto [w, v] = tried[r];
          const double c = cost(w, v, entries);
          if(c < best[w].second) {
            best[w] = {v, c};
            moved[w] = true;
          }
        });
      tried.clear();
      for(std::size_t w = 0; w < n; ++w) {
        if(!moved[w])
          continue;
        for(auto u : CGAL::vertices_around_target(m_mesh.vertex[best[w].first], m_mesh.tm)) {
          const std::size_t ui = m_mesh.index(u);
          if(std::find(visited[w].begin(), visited[w].end(), ui) == visited[w].end()) {
            visited[w].push_back(ui);
            if(may_visit(w, ui))
              tried.emplace_back(w, ui);
          }
        }
      }
    }
    return best;
  }

  /// Releases the solvers (after the run's last row: their solver mesh and solvers go before
  /// the arrangement's) and returns the number of rows solved since they were made.
  std::size_t release()
  {
    m_row_solvers.reset();
    return std::exchange(m_rows, 0);
  }

private:
  const Mesh& m_mesh;
  double m_approximation;
  // the solvers of every local row (made at the first row, released after the last)
  std::optional<Row_solvers<parallel, TriangleMesh, VertexPointMap>> m_row_solvers;
  std::size_t m_rows = 0; // rows solved since the solvers were made
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_ROWS_H
