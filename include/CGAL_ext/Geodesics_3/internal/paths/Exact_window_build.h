// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PATHS_EXACT_WINDOW_BUILD_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PATHS_EXACT_WINDOW_BUILD_H

// A VTP (PVTP) run whose windows are kept on the edges as MMP keeps its own, so that the path
// tracer (distances anywhere, shortest paths) and the Voronoi diagram can read them; and the one
// exact build either reads, MMP's or VTP's.

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Tolerances.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Edge_window_store.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/MMP_solver.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Solver_settings.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/VTP_solver.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Mesh_setup.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh.h>
#include <CGAL_ext/Geodesics_3/internal/support/Solver_arena.h>

#include <memory>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// VTP with every list's windows, as they cross their face, clipped into an `Edge_window_store`
/// (per edge in merge order, the same for every number of threads; PVTP records each round's
/// lists on its threads, edge by edge, as PMMP inserts its own windows). VTP drops a path only
/// where another one is at least as short (a vertex's distance and the segment from it, another
/// window of the list, or the kinked path through Rule 1's split point, never a shortest one),
/// so the shortest path to any point of a face enters it through one of its edges in a stored
/// window or passes through one of its corners: the tracer reads them as it reads MMP's.
/// Not copyable: the solver hands its windows to this object.
class VTP_with_windows : private Propagated_window_recorder
{
public:
  VTP_with_windows(const Solver_mesh& mesh, const Solver_settings& settings, bool parallel)
    : m_solver(mesh, settings, parallel)
    , m_windows(mesh, min_window_length_ratio * mesh.mean_edge_length, /*requeue_trimmed=*/false)
  {
    m_solver.record_propagated_windows(this);
  }
  VTP_with_windows(const VTP_with_windows&) = delete;
  VTP_with_windows& operator=(const VTP_with_windows&) = delete;

  VTP_solver& solver() { return m_solver; }
  const VTP_solver& solver() const { return m_solver; }
  const Edge_window_store& windows() const { return m_windows; }

private:
  void start_run(bool parallel) override
  {
    m_windows.use_one_slot_per_thread(parallel);
    m_insertion.resize(m_windows.number_of_slots());
  }

  void record(int h, const std::vector<Window>& list, std::size_t slot) override
  {
    Insertion_output& out = m_insertion[slot];
    for(const Window& w : list)
      m_windows.insert(w, h, w.source, slot, out);
    out.queued.clear(); // nothing is queued: the store is only read
    out.updates.clear();
  }

  VTP_solver m_solver;
  Edge_window_store m_windows;
  std::vector<Insertion_output> m_insertion; // per slot of the store's pool
};

/// The settings of a build whose windows are read anywhere on the surface (`what` names it in the
/// messages): exact, whole, VTP by default (PVTP in parallel: faster than MMP and PMMP, table in
/// doc/experiments.md).
template <class NamedParameters>
Solver_settings read_window_build_settings(const NamedParameters& np, const char* what)
{
  if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::stop_vertices_t>::value)
    throw Geodesic_error(std::string(what) + " takes no stop_vertices: its windows are read anywhere");
  const Solver_settings settings = read_solver_settings(np, VTP);
  if(settings.approximation > 0)
    throw Geodesic_error(std::string(what) + " is exact: it takes no approximation");
  return settings;
}

/// One exact build whose windows are read anywhere on the surface: MMP's (FWP-MMP, MMP, PMMP),
/// or VTP's (PVTP) when `settings.algorithm` is VTP.
class Exact_window_build
{
public:
  Exact_window_build(const Solver_mesh& mesh, const Solver_settings& settings, bool parallel)
  {
    if(settings.algorithm == VTP)
      m_vtp = std::make_unique<VTP_with_windows>(mesh, settings, parallel);
    else
      m_mmp = std::make_unique<MMP_solver>(mesh, settings, parallel);
  }

  Solver_base& solver() { return m_vtp ? static_cast<Solver_base&>(m_vtp->solver()) : *m_mmp; }
  const Solver_base& solver() const { return m_vtp ? static_cast<const Solver_base&>(m_vtp->solver()) : *m_mmp; }
  const Edge_window_store& windows() const { return m_vtp ? m_vtp->windows() : m_mmp->windows(); }

  /// The solver's statistics after `run`, with the store's windows and memory (MMP reports them
  /// itself).
  Geodesic_statistics statistics() const
  {
    Geodesic_statistics s = solver().statistics();
    if(m_vtp) {
      s.windows_stored = m_vtp->windows().live();
      s.stored_window_bytes = m_vtp->windows().stored_bytes();
    }
    return s;
  }

  /// Runs the solver in a task arena of `threads` (see `run_solver`).
  template <bool parallel>
  void run(int threads)
  {
    if(m_vtp)
      run_solver<parallel>(m_vtp->solver(), threads);
    else
      run_solver<parallel>(*m_mmp, threads);
  }

private:
  std::unique_ptr<MMP_solver> m_mmp;
  std::unique_ptr<VTP_with_windows> m_vtp; // one of the two
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PATHS_EXACT_WINDOW_BUILD_H
