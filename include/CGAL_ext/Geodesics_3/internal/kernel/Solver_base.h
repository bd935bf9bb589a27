// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_SOLVER_BASE_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_SOLVER_BASE_H

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>
#include <CGAL_ext/Geodesics_3/Tolerances.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Solver_settings.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Source_windows.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Window.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh.h>
#include <CGAL_ext/Geodesics_3/internal/support/Progress_reporter.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// What the VTP and MMP solvers share: the mesh, the sources, the vertex distances and
/// nearest sources with the arrivals of the paths that gave them (and so the saddles' cones),
/// the settings, the trimming of a window by its edge's end vertices, and the statistics.
class Solver_base
{
public:
  static double infinity() { return std::numeric_limits<double>::infinity(); }

  /// Adds a source (checked; a face point on a corner becomes that vertex); its index is the
  /// number of sources added before it.
  void add_source(const Source_point& s) { m_sources.push_back(normalized_source(m_mesh, s)); }
  /// The same for a source that `normalized_source` gave (the solver mesh's positions, which it may
  /// read, may have been freed since).
  void add_normalized_source(const Source_point& s) { m_sources.push_back(s); }

  const Solver_mesh& mesh() const { return m_mesh; }
  const std::vector<Source_point>& sources() const { return m_sources; }
  /// The distance of every vertex (+infinity where no source reaches), in the solver mesh's unit.
  const std::vector<double>& distances() const { return m_distance; }
  /// The index of the nearest source of every vertex (the source whose path set its distance),
  /// -1 where no source reaches.
  const std::vector<int>& nearest_sources() const { return m_nearest_source; }
  /// In the solver mesh's unit.
  double max_distance() const { return m_max_distance; }
  const Geodesic_statistics& statistics() const { return m_statistics; }
  /// The caller's callback of the runs from now on (`Solver_settings::callback`); between runs only.
  void set_callback(std::function<bool(double)> callback) { m_progress = Progress_reporter(std::move(callback)); }

protected:
  typedef std::chrono::steady_clock Clock;

  /// `settings` were checked by `read_solver_settings()`; `parallel` runs the loops on the
  /// threads of the caller's task arena.
  Solver_base(const Solver_mesh& mesh, const Solver_settings& settings, bool parallel)
    : m_mesh(mesh)
    , m_distance(mesh.number_of_vertices, infinity())
    , m_nearest_source(mesh.number_of_vertices, -1)
    , m_emitted(mesh.number_of_vertices, infinity())
    , m_max_distance(settings.max_distance / mesh.unit)
    , m_window_limit(settings.max_distance / mesh.unit)
    , m_min_window_length(min_window_length_ratio * mesh.mean_edge_length)
    , m_batch_size(settings.batch_size)
    , m_parallel(parallel)
    , m_progress(settings.callback)
  {
#ifndef CGAL_LINKED_WITH_TBB
    if(parallel)
      throw Geodesic_error("parallel propagation needs TBB (CGAL_LINKED_WITH_TBB is not defined)");
#endif
  }

  Solver_base(const Solver_base&) = delete;
  Solver_base& operator=(const Solver_base&) = delete;

  static double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

  /// Trims a window (in the frame of h) by the distances `d_from` and `d_to` of the source and
  /// target of h, and drops it when its smallest distance is beyond the window limit: false if
  /// nothing is left.
  bool keep_window(Window_geometry& w, int h, double d_from, double d_to) const
  {
    double key;
    return keep_window(w, h, d_from, d_to, key);
  }
  /// The same, giving the smallest distance of what is kept.
  bool keep_window(Window_geometry& w, int h, double d_from, double d_to, double& key) const
  {
    return trim_by_edge_vertices(w, m_mesh.length(h), d_from, d_to, key) && key <= m_window_limit;
  }

  /// The same for a list window, whose end distances are kept.
  bool keep_window(Window& w, int h, double d_from, double d_to) const
  {
    double key;
    return trim_by_edge_vertices(w, w.d0, w.d1, m_mesh.length(h), d_from, d_to, key) && key <= m_window_limit;
  }

  /// Whether `d` lowers the distance of v; if so, records `arrival`, where the path giving it
  /// comes from (what a saddle's cone starts from).
  bool lowers(int v, double d, const Arrival& arrival)
  {
    if(!(d < m_distance[std::size_t(v)]))
      return false;
    m_arrival[std::size_t(v)] = arrival;
    return true;
  }

  /// The cone of v emitting at its distance (`saddle_cone_of`), set in `cone`, or nullptr:
  /// every direction. Reads only the distance and arrival of v.
  const Saddle_cone* cone_of(int v, Saddle_cone& cone) const
  {
    return saddle_cone_of(m_mesh, v, m_distance[std::size_t(v)], m_arrival[std::size_t(v)], cone);
  }
  /// The same in the solver's own cone, for vertices that emit on the thread running the solver.
  const Saddle_cone* cone_of(int v) { return cone_of(v, m_cone); }

  /// v emits every way from now on (until a path lowers its distance again).
  void forget_arrival(int v) { m_arrival[std::size_t(v)] = Arrival{}; }

  template <class Pool>
  void note_live_windows(const Pool& pool)
  {
    m_peak_windows = std::max(m_peak_windows, pool.live());
  }

  /// Starts the reports of a run to the caller's callback.
  void start_progress() { m_progress.start(); }
  /// Tells the caller's callback the fraction `done()` of the run, a few times a second, from the
  /// thread running run(); throws Geodesic_cancelled when the callback says so.
  template <class DoneFraction>
  void report_progress(DoneFraction done)
  {
    m_progress.report(done);
  }
  /// The same for a loop that calls it very often (the clock is read once in 64 calls).
  template <class DoneFraction>
  void report_progress_often(DoneFraction done)
  {
    m_progress.report_often(done);
  }

  /// Fills the statistics every solver reports at the end of its run.
  template <class Pool>
  void finish_statistics(const Pool& pool, Clock::time_point start)
  {
    note_live_windows(pool);
    m_statistics.vertices = m_mesh.number_of_mesh_vertices;
    m_statistics.faces = m_mesh.number_of_faces;
    m_statistics.peak_windows = m_peak_windows;
    m_statistics.peak_window_bytes = pool.bytes();
    m_statistics.seconds_solve = seconds_since(start);
  }

  const Solver_mesh& m_mesh;
  std::vector<Source_point> m_sources;
  std::vector<double> m_distance;
  std::vector<int> m_nearest_source;
  std::vector<double> m_emitted; // sigma of the last windows a pseudo-source emitted
  std::vector<Arrival> m_arrival = std::vector<Arrival>(m_mesh.number_of_vertices); // per vertex: the arrival of its distance
  Saddle_cone m_cone; // of the vertex emitting
  double m_max_distance;         // in the solver mesh's unit
  double m_window_limit;         // windows whose smallest distance is beyond it are dropped
  const double m_min_window_length;
  const std::size_t m_batch_size;
  const bool m_parallel;
  std::size_t m_peak_windows = 0;
  Geodesic_statistics m_statistics;
  Progress_reporter m_progress;
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_SOLVER_BASE_H
