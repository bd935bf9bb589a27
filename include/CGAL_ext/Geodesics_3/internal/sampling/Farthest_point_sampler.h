// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_SAMPLING_FARTHEST_POINT_SAMPLER_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_SAMPLING_FARTHEST_POINT_SAMPLER_H

// Exact farthest-point sampling, incremental: each new sample's propagation starts from the
// distance field of the samples before it, so it sweeps only the region where the new sample
// is nearer (VTP_solver::keep_field_for_next_run).

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Solver_settings.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Source_windows.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/VTP_solver.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Mesh_setup.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh.h>
#include <CGAL_ext/Geodesics_3/internal/support/Parallel_for.h>
#include <CGAL_ext/Geodesics_3/internal/support/Solver_arena.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// The distance field of a growing set of samples (solver-mesh indices, in the solver mesh's unit).
///
/// Parallel, on two threads or more, several samples are run at once: beside the farthest
/// vertex v, the vertices most likely to be the next samples among those that the runs before
/// them cannot change (their straight-line distance to each earlier vertex of the batch is no
/// less than their distance to the samples). All runs start from the same field, each in a
/// solver of its own. A run is kept, in order, when its vertex is the farthest once the runs
/// before it are kept, and it read no distance that they changed: it then computed exactly
/// what it would have computed after them, so the samples, distances and labels are those of
/// one sample at a time, for every number of threads. The first run that fails is undone, with
/// every run after it.
template <bool parallel>
class Farthest_point_sampler
{
public:
  /// One solver serves every sample (more when samples run in batches): each run starts from
  /// the field the last one left, and resets only what that run wrote. `in_batches`: whether
  /// samples may run in batches (when parallel on two threads or more).
  Farthest_point_sampler(const Solver_mesh& mesh, const Solver_settings& settings, bool in_batches = true)
    : m_mesh(mesh)
    , m_settings(settings)
    , m_solver(mesh, settings, parallel)
    , m_arena(settings.number_of_threads)
  {
    if constexpr(parallel) {
      std::size_t threads = 1;
      m_arena.execute([&] { threads = arena_concurrency(); });
      if(in_batches && threads > 1 && !m_mesh.position.empty())
        for(std::size_t i = 1; i < runs_per_thread * threads; ++i) {
          m_twins.push_back(std::make_unique<VTP_solver>(mesh, settings, parallel));
          m_twins.back()->note_reads();
        }
    }
  }

  /// Adds vertex v as the next sample: one propagation from v over the region where it is
  /// nearer than every earlier sample (none for a vertex in no face: it covers itself).
  void add_sample(int v)
  {
    add_samples(v, [](std::size_t, double) { return true; });
  }

  /// The same; then, when samples run in batches, the samples after v as long as
  /// `enough(number of samples, covering radius)` is false and the batch's runs are kept (see
  /// the class).
  template <class Enough>
  void add_samples(int v, const Enough& enough)
  {
    const int index = int(m_samples.size());
    m_samples.push_back(v);
    m_batch.assign(1, v);
    if(!m_twins.empty() && index > 0 && !is_isolated_point(m_mesh, v) &&
       m_solver.reached_vertices().size() <= max_vertices_before_batches)
      add_likely_next_samples();
    if(m_batch.size() == 1) {
      run_samples(std::size_t(index), std::size_t(index) + 1);
      return;
    }
    for(std::size_t i = 0; i < m_batch.size(); ++i)
      start_run(solver(i), m_batch[i], index + int(i));
    m_arena.execute([this] {
      for_each_index(true, m_batch.size(), 1, [this](std::size_t i, std::size_t) {
        VTP_solver& s = solver(i);
#ifdef CGAL_LINKED_WITH_TBB
        tbb::this_task_arena::isolate([&s] { s.run(); }); // no other run inside this one's loops
#else
        s.run();
#endif
      });
    });
    add_statistics(m_solver.statistics());
    update_farthest(m_solver.reached_vertices());
    std::size_t kept = 1;
    for(; kept < m_batch.size(); ++kept) {
      VTP_solver& s = solver(kept);
      if(!(covering_radius() > 0 && m_farthest == m_batch[kept] && !enough(m_samples.size(), covering_radius())))
        break;
      bool undisturbed = true;
      for(std::size_t j = 0; j < kept && undisturbed; ++j)
        undisturbed = std::none_of(solver(j).reached_vertices().begin(), solver(j).reached_vertices().end(),
                                   [&s](int u) { return s.was_read(u); });
      if(!undisturbed)
        break;
      m_samples.push_back(m_batch[kept]);
      add_statistics(s.statistics());
      m_solver.copy_field_from(s, s.reached_vertices());
      update_farthest(s.reached_vertices());
    }
    m_statistics.batched_runs_kept += kept - 1;
    m_statistics.batched_runs_undone += m_batch.size() - kept;
    // every twin back to the field of the kept runs
    for(const auto& twin : m_twins)
      for(std::size_t i = 0; i < m_batch.size(); ++i)
        twin->copy_field_from(m_solver, solver(i).reached_vertices());
  }

  /// Adds `vertices` (distinct points, before any other sample) as the first samples, in order,
  /// by one propagation from all of them at once: the field is then theirs, and the runs of the
  /// samples after them sweep only what each takes over. The covering radius after each of them
  /// is the one after all of them. One vertex is one sample's run, as `add_sample` makes it.
  void add_initial_samples(const std::vector<int>& vertices)
  {
    const std::size_t first = m_samples.size();
    m_samples.insert(m_samples.end(), vertices.begin(), vertices.end());
    // a vertex in no face covers itself; the others run together (a source's number is its
    // place in the run, so each group of consecutive ones in faces is one run)
    for(std::size_t i = first; i < m_samples.size();) {
      std::size_t end = i + 1;
      if(!is_isolated_point(m_mesh, m_samples[i]))
        while(end < m_samples.size() && !is_isolated_point(m_mesh, m_samples[end]))
          ++end;
      run_samples(i, end);
      i = end;
    }
    m_covering_radii.resize(first); // one a run above
    m_covering_radii.resize(m_samples.size(), covering_radius());
  }

  /// The vertex of the caller's mesh farthest from every sample.
  int farthest_vertex() const { return m_farthest; }
  /// The largest distance of a vertex to its nearest sample.
  double covering_radius() const { return m_solver.distances()[std::size_t(m_farthest)]; }
  /// The covering radius after each sample (after all the initial samples, for each of them).
  const std::vector<double>& covering_radii() const { return m_covering_radii; }

  const std::vector<int>& samples() const { return m_samples; }
  const std::vector<double>& distances() const { return m_solver.distances(); }
  const std::vector<int>& nearest_samples() const { return m_solver.nearest_sources(); }
  /// What the propagations did, added up (peaks: the largest).
  const Geodesic_statistics& statistics() const { return m_statistics; }

private:
  // The vertices of the caller's mesh by distance, the largest first and the lowest index first
  // among equals. A run (or an isolated sample) only lowers distances, so it pushes the
  // vertices it reached; an entry whose distance is no longer its vertex's is dropped when it
  // comes to the top. The heap is rebuilt when the stale entries outgrow the mesh, so that a
  // sample costs what its run swept, not a scan of the mesh.
  struct Candidate
  {
    double distance;
    int vertex;      // the solver mesh's index
    int mesh_vertex; // the caller's, which decides ties
    bool operator<(const Candidate& c) const
    {
      return distance < c.distance || (distance == c.distance && mesh_vertex > c.mesh_vertex);
    }
  };
  Candidate candidate(double distance, int v) const { return Candidate{distance, v, m_mesh.mesh_vertex(v)}; }

  static Source_point vertex_source(int v)
  {
    Source_point s;
    s.vertex = v;
    return s;
  }
  static void start_run(VTP_solver& solver, int v, int index)
  {
    solver.keep_field_for_next_run(index);
    solver.add_source(vertex_source(v));
  }

  // The run of samples [first, end) at once (or one isolated sample), the twin solvers brought
  // to the same field.
  void run_samples(std::size_t first, std::size_t end)
  {
    const int v = m_samples[first], index = int(first);
    m_solver.keep_field_for_next_run(index);
    if(is_isolated_point(m_mesh, v)) {
      m_solver.set_isolated_point(v, 0., index);
    } else {
      for(std::size_t i = first; i < end; ++i)
        m_solver.add_source(vertex_source(m_samples[i]));
      m_arena.execute([this] { m_solver.run(); });
      add_statistics(m_solver.statistics());
    }
    for(const auto& twin : m_twins)
      twin->copy_field_from(m_solver, m_solver.reached_vertices());
    update_farthest(m_solver.reached_vertices());
  }

  void add_statistics(const Geodesic_statistics& run) { add_run_statistics(m_statistics, run); }

  // Adds to the batch the farthest vertices (the heap's top) whose straight-line distance to
  // every vertex already in the batch is at least their distance to the samples: no path from
  // those can shorten theirs. Looks at a few of the farthest only.
  void add_likely_next_samples()
  {
    const std::vector<double>& d = m_solver.distances();
    const std::size_t batch_size = m_twins.size() + 1;
    m_looked_at.clear();
    while(!m_heap.empty() && m_looked_at.size() < max_candidates_looked_at && m_batch.size() < batch_size) {
      const Candidate top = pop_candidate();
      if(top.distance != d[std::size_t(top.vertex)])
        continue; // stale
      m_looked_at.push_back(top);
      if(is_isolated_point(m_mesh, top.vertex))
        continue;
      const std::array<double, 3>& q = m_mesh.position[std::size_t(top.vertex)];
      const double r2 = top.distance * top.distance;
      if(std::all_of(m_batch.begin(), m_batch.end(), [&](int u) {
           const std::array<double, 3>& p = m_mesh.position[std::size_t(u)];
           const double dx = q[0] - p[0], dy = q[1] - p[1], dz = q[2] - p[2];
           return dx * dx + dy * dy + dz * dz >= r2;
         }))
        m_batch.push_back(top.vertex);
    }
    for(const Candidate& c : m_looked_at)
      push_candidate(c);
  }
  static constexpr std::size_t max_candidates_looked_at = 64;
  // Samples run in batches only once a run reaches at most this many vertices: a larger run
  // keeps every thread busy by itself, and a run beside it would take one of them for the
  // whole run, in vain if it is undone.
  static constexpr std::size_t max_vertices_before_batches = 8192;
  static constexpr std::size_t runs_per_thread = 1;

  void push_candidate(const Candidate& c)
  {
    m_heap.push_back(c);
    std::push_heap(m_heap.begin(), m_heap.end());
  }
  Candidate pop_candidate()
  {
    std::pop_heap(m_heap.begin(), m_heap.end());
    const Candidate top = m_heap.back();
    m_heap.pop_back();
    return top;
  }

  VTP_solver& solver(std::size_t i) { return i == 0 ? m_solver : *m_twins[i - 1]; }

  // Pushes the vertices a run lowered and finds the farthest vertex; records the covering radius.
  void update_farthest(const std::vector<int>& lowered)
  {
    const std::vector<double>& d = m_solver.distances();
    const std::size_t n = m_mesh.number_of_mesh_vertices;
    if(m_covering_radii.empty() || m_heap.size() > 4 * n) {
      m_heap.clear();
      for(std::size_t u = 0; u < n; ++u)
        m_heap.push_back(candidate(d[u], int(u)));
      std::make_heap(m_heap.begin(), m_heap.end());
    } else {
      for(int u : lowered)
        if(std::size_t(u) < n)
          push_candidate(candidate(d[std::size_t(u)], u));
    }
    while(m_heap.front().distance != d[std::size_t(m_heap.front().vertex)])
      pop_candidate();
    m_farthest = m_heap.front().vertex;
    m_covering_radii.push_back(covering_radius());
  }

  const Solver_mesh& m_mesh;
  const Solver_settings m_settings;
  VTP_solver m_solver;
  std::vector<std::unique_ptr<VTP_solver>> m_twins; // the other runs' solvers of a batch
  std::vector<int> m_batch;                          // the vertices run at once
  Solver_arena<parallel> m_arena;
  std::vector<int> m_samples;
  std::vector<double> m_covering_radii;
  int m_farthest = 0;
  std::vector<Candidate> m_heap;
  std::vector<Candidate> m_looked_at;
  Geodesic_statistics m_statistics;
};

/// The default first sample: the vertex farthest from the caller's first vertex in a face
/// (vertex 0 on a mesh without isolated vertices).
template <bool parallel>
int default_first_sample(const Solver_mesh& mesh, const Solver_settings& settings)
{
  int first = 0;
  while(std::size_t(first) < mesh.number_of_mesh_vertices && is_isolated_point(mesh, mesh.cache_vertex(first)))
    ++first;
  if(std::size_t(first) == mesh.number_of_mesh_vertices)
    throw Geodesic_error("every vertex is in no face: there is no surface to sample");
  Farthest_point_sampler<parallel> from_start(mesh, settings, false);
  from_start.add_sample(mesh.cache_vertex(first));
  return from_start.farthest_vertex();
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_SAMPLING_FARTHEST_POINT_SAMPLER_H
