// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_DISTANCE_ROWS_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_DISTANCE_ROWS_H

// The rows of a distance matrix: independent single-source solves on one mesh cache, in
// parallel across sources, handed over in source order from the calling thread.

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>
#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/internal/Geodesic_setup.h>
#include <CGAL_ext/Geodesics_3/internal/Parallel_for.h>
#include <CGAL_ext/Geodesics_3/internal/VTP_solver.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

template <bool parallel, class TriangleMesh, class Sources, class RowFunction, class NamedParameters>
void distance_rows(const TriangleMesh& tm, const Sources& sources, RowFunction& row, const NamedParameters& np)
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
  const std::size_t number_of_vertices = mesh.cache().number_of_mesh_vertices;

  // Each row is one sequential solve, a task of its own. A batch of rows is solved, then handed
  // over in order (from the calling thread, which runs the arena's loop); a few rows per thread
  // keep the threads busy and the memory small.
  run_in_arena<parallel>(settings.number_of_threads, [&] {
    const std::size_t batch = parallel ? 4 * arena_concurrency() : 1;
    std::vector<std::vector<double>> rows(std::min(batch, points.size()));
    for(std::size_t first = 0; first < points.size(); first += batch) {
      const std::size_t n = std::min(batch, points.size() - first);
      for_each_index(parallel, n, 1, [&](std::size_t j, std::size_t) {
        VTP_solver solver(mesh.cache(), settings, false);
        solver.add_source(points[first + j]);
        solver.run();
        const std::vector<double>& d = solver.distances();
        std::vector<double>& r = rows[j];
        r.resize(number_of_vertices);
        for(std::size_t v = 0; v < number_of_vertices; ++v)
          r[v] = mesh.to_mesh_unit(d[v]);
      });
      for(std::size_t j = 0; j < n; ++j)
        row(first + j, static_cast<const std::vector<double>&>(rows[j]));
    }
  });
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_DISTANCE_ROWS_H
