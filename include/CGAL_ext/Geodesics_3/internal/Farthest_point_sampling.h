// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_FARTHEST_POINT_SAMPLING_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_FARTHEST_POINT_SAMPLING_H

// Exact farthest-point sampling, incremental: each new sample's propagation starts from the
// distance field of the samples before it, so it sweeps only the region where the new sample
// is nearer (VTP_solver::keep_field_for_next_run).

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/internal/Geodesic_setup.h>
#include <CGAL_ext/Geodesics_3/internal/Mesh_cache.h>
#include <CGAL_ext/Geodesics_3/internal/Solver_settings.h>
#include <CGAL_ext/Geodesics_3/internal/Sources.h>
#include <CGAL_ext/Geodesics_3/internal/VTP_solver.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// The distance field of a growing set of samples (cache indices, in the cache's unit).
template <bool parallel>
class Farthest_point_sampler
{
public:
  /// One solver serves every sample: each run starts from the field the last one left, and
  /// resets only what that run wrote.
  Farthest_point_sampler(const Mesh_cache& mesh, const Solver_settings& settings)
    : m_mesh(mesh)
    , m_settings(settings)
    , m_solver(mesh, settings, parallel)
    , m_arena(settings.number_of_threads)
  {
  }

  /// Adds vertex v as the next sample: one propagation from v over the region where it is
  /// nearer than every earlier sample (none for a vertex in no face: it covers itself).
  void add_sample(int v)
  {
    const int index = int(m_samples.size());
    m_samples.push_back(v);
    m_solver.keep_field_for_next_run(index);
    if(is_isolated_point(m_mesh, v)) {
      m_solver.set_isolated_point(v, 0., index);
    } else {
      Source_point s;
      s.vertex = v;
      m_solver.add_source(s);
      m_arena.execute([this] { m_solver.run(); });
      const Geodesic_statistics& run = m_solver.statistics();
      m_statistics.windows_created += run.windows_created;
      m_statistics.peak_windows = std::max(m_statistics.peak_windows, run.peak_windows);
      m_statistics.peak_window_bytes = std::max(m_statistics.peak_window_bytes, run.peak_window_bytes);
      m_statistics.vertices_popped += run.vertices_popped;
      m_statistics.lists_propagated += run.lists_propagated;
      m_statistics.wavefront_resets += run.wavefront_resets;
      m_statistics.seconds_solve += run.seconds_solve;
      m_statistics.seconds_selection += run.seconds_selection;
      m_statistics.seconds_propagation += run.seconds_propagation;
      m_statistics.seconds_merge += run.seconds_merge;
    }
    update_farthest();
  }

  /// The vertex of the caller's mesh farthest from every sample.
  int farthest_vertex() const { return m_farthest; }
  /// The largest distance of a vertex to its nearest sample.
  double covering_radius() const { return m_solver.distances()[std::size_t(m_farthest)]; }

  const std::vector<int>& samples() const { return m_samples; }
  const std::vector<double>& distances() const { return m_solver.distances(); }
  const std::vector<int>& nearest_samples() const { return m_solver.nearest_sources(); }
  /// What the propagations did, added up (peaks: the largest).
  const Geodesic_statistics& statistics() const { return m_statistics; }

private:
  // The vertices of the caller's mesh by distance, the largest first and the lowest index first
  // among equals. A run (or an isolated sample) only lowers distances, so it pushes the
  // vertices it reached; an entry
  // whose distance is no longer its vertex's is dropped when it comes to the top. The heap is
  // rebuilt when the stale entries outgrow the mesh, so that a sample costs what its run swept,
  // not a scan of the mesh.
  struct Candidate
  {
    double distance;
    int vertex;
    bool operator<(const Candidate& c) const
    {
      return distance < c.distance || (distance == c.distance && vertex > c.vertex);
    }
  };

  void update_farthest()
  {
    const std::vector<double>& d = m_solver.distances();
    const std::size_t n = m_mesh.number_of_mesh_vertices;
    const auto push = [&](int u) {
      if(std::size_t(u) < n) {
        m_heap.push_back(Candidate{d[std::size_t(u)], u});
        std::push_heap(m_heap.begin(), m_heap.end());
      }
    };
    if(m_samples.size() == 1 || m_heap.size() > 4 * n) {
      m_heap.clear();
      for(std::size_t u = 0; u < n; ++u)
        m_heap.push_back(Candidate{d[u], int(u)});
      std::make_heap(m_heap.begin(), m_heap.end());
    } else {
      for(int u : m_solver.reached_vertices())
        push(u);
    }
    while(m_heap.front().distance != d[std::size_t(m_heap.front().vertex)]) {
      std::pop_heap(m_heap.begin(), m_heap.end());
      m_heap.pop_back();
    }
    m_farthest = m_heap.front().vertex;
  }

  const Mesh_cache& m_mesh;
  const Solver_settings m_settings;
  VTP_solver m_solver;
  Solver_arena<parallel> m_arena;
  std::vector<int> m_samples;
  int m_farthest = 0;
  std::vector<Candidate> m_heap;
  Geodesic_statistics m_statistics;
};

/// The default first sample: the vertex farthest from the first vertex in a face (vertex 0 on
/// a mesh without isolated vertices).
template <bool parallel>
int default_first_sample(const Mesh_cache& mesh, const Solver_settings& settings)
{
  int start = 0;
  while(std::size_t(start) < mesh.number_of_mesh_vertices && is_isolated_point(mesh, start))
    ++start;
  if(std::size_t(start) == mesh.number_of_mesh_vertices)
    throw Geodesic_error("every vertex is in no face: there is no surface to sample");
  Farthest_point_sampler<parallel> from_start(mesh, settings);
  from_start.add_sample(start);
  return from_start.farthest_vertex();
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_FARTHEST_POINT_SAMPLING_H
