// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_VTP_SOLVER_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_VTP_SOLVER_H

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Priority_queues.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Solver_base.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Source_windows.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Window.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh.h>
#include <CGAL_ext/Geodesics_3/internal/support/Inlining.h>
#include <CGAL_ext/Geodesics_3/internal/support/Object_pool.h>
#include <CGAL_ext/Geodesics_3/internal/support/Parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// Where VTP keeps the windows of its lists.
typedef Run_pool<Window> Window_pool;

/// A list's windows where they are in the pool (`VTP_solver`'s buffers for a list and for the
/// passes of its sort, each filled whole before it is read).
typedef std::vector<Window*, Uninitialized_allocator<Window*>> Window_pointers;

/// Windows side by side in the pool: `count` from `first` (`Run_pool`).
struct Window_run
{
  std::uint32_t first;
  std::uint32_t count;
};

/// A chain of windows of a list (a run of the pool), and the step whose distances of the edge's
/// end vertices trimmed them (`VTP_solver::next_step`). A list is a few chains, each made by
/// one propagation (one run, or two when its block filled up) or emission.
struct List_chain
{
  Window_run run;
  std::uint32_t trimmed_at;
};

/// The windows that one propagation makes for one list: runs of the pool (the last one, still
/// growing, kept here rather than in the vector, which another thread's vector may sit beside).
struct Window_list
{
  std::vector<Window_run> earlier_runs;
  Window_run last_run{0, 0};

  void clear() { earlier_runs.clear(), last_run.count = 0; }
  bool empty() const { return last_run.count == 0; }
  /// Makes room for the runs of `n` windows made in a lane of their own.
  void reserve(std::size_t n)
  {
    const std::size_t runs = n / Window_pool::block_size + 1;
    if(earlier_runs.capacity() < runs) // (vector::reserve is a call even when it does nothing)
      earlier_runs.reserve(runs);
  }
  /// Appends a new window of `pool`, made in the `lane` of the thread's `slot` by
  /// `make(window)` in place, if it returns true; room for its run was made (`reserve`), so that
  /// nothing throws once the window is made. (Inlined: GCC leaves it out of line in
  /// `propagate`, which costs a call a window.)
  template <class Make>
  CGAL_EXT_ALWAYS_INLINE void push_back_made(Window_pool& pool, std::size_t slot, unsigned lane, Make make)
  {
    std::uint32_t index;
    if(!pool.make(slot, lane, index, make))
      return;
    if(Window_pool::continues_run(last_run.first, last_run.count, index)) {
      ++last_run.count;
      return;
    }
    if(last_run.count)
      earlier_runs.push_back(last_run);
    last_run = Window_run{index, 1};
  }
  /// Calls `f(run)` for the runs, the last made first.
  template <class F>
  void for_each_run_backwards(F f) const
  {
    if(last_run.count)
      f(last_run);
    for(auto r = earlier_runs.rbegin(); r != earlier_runs.rend(); ++r)
      f(*r);
  }
};

/// A list detached from its half-edge to be propagated: `chain_count` of the round's chains
/// from `first_chain` (`VTP_solver::detach`), holding `window_count` windows.
struct Detached_list
{
  int halfedge;
  std::uint32_t first_chain, chain_count, window_count;
};

/// One window list taken across its triangle: the work of one task of the propagation step.
/// `propagate()` fills it reading only shared state that no task writes; `merge()` applies it.
struct List_task
{
  int halfedge = -1;
  double apex_distance = 0; // shortest path to the apex found through the list
  int apex_source = -1;     // the source of that path
  Arrival apex_arrival;     // and where it comes from
  Window_list to_ac, to_cb; // children for the lists across A->C and C->B
  std::uint32_t trimmed_at = 0; // the step that trimmed the children
  // and those lists' half-edges (once there are children), so that the serial merge does not
  // read the mesh's opposites
  int to_ac_halfedge = -1, to_cb_halfedge = -1;
  std::vector<Window> propagated; // the list's windows as propagated, when they are recorded
};

/// What receives the windows of each list as VTP propagates it
/// (`VTP_solver::record_propagated_windows`).
class Propagated_window_recorder
{
public:
  virtual ~Propagated_window_recorder() = default;
  /// Called by each run, in the task arena it runs in, before it records any window; `parallel`
  /// is the solver's (per-thread storage then needs a slot per thread of the arena).
  virtual void start_run(bool parallel) = 0;
  /// The windows of the list of half-edge h as they cross its face, from the thread of `slot`.
  /// The lists of one edge (h and its opposite) come from one thread at a time, in the order of
  /// the merges; lists of different edges may come at once from different threads.
  virtual void record(int h, const std::vector<Window>& windows, std::size_t slot) = 0;
};

/// What a pseudo-source (a vertex, or a face point) emits, computed before it is applied: the
/// relaxations of its neighbours that lowered their distances when computed, and its windows,
/// each with the half-edge of the list it joins.
struct Vertex_emission
{
  int vertex = -1; // the emitting vertex (when it is one)
  std::vector<Vertex_update> relaxations;
  std::vector<std::pair<int, std::uint32_t>> windows; // the half-edge of the list, the window
  std::uint32_t trimmed_at = 0; // the step that trimmed the windows
  Saddle_cone cone;
};

/// Geodesic distances from any number of sources by vertex-oriented triangle propagation
/// (VTP, thesis chapter 4): exact, or approximate with the setting `approximation` (AVTP);
/// sequential, or parallel (PVTP / PAVTP, with TBB).
///
/// Windows are kept only on the wavefront, grouped in lists per half-edge: the list of
/// half-edge h holds windows on the edge of h that will enter the face of h. Vertices are taken
/// in order of tentative distance; taking a vertex schedules every list on its incident edges,
/// and the children of a list are scheduled at once while their edge has a taken vertex.
/// Saddle and border vertices are pseudo-sources: each time their distance drops after being
/// taken, they emit new windows.
///
/// A scheduled list is propagated in two steps: `propagate()` reads the list, the mesh and the
/// vertex distances and writes only its own `List_task` (children, apex distance);
/// `merge()` then updates the apex and appends the children to their lists. Sequentially
/// (VTP) each list is merged right after it is propagated; in parallel (PVTP) all the
/// scheduled lists are propagated at once, one task each, and merged afterwards in schedule
/// order, so that the result does not depend on the number of threads.
///
/// Pruning, each rule provably dropping only rays that another path matches or beats:
/// - trimming by the end vertices of the edge (an exact form of the filter of Xin and Wang);
/// - clipping the windows of a list against each other (Rule 2);
/// - "one angle, two sides" (Rule 1): the window giving the shortest path to the apex C splits
///   the edge at the point sp where that path crosses it; rays left of sp that would land on the
///   far side CB cross that path and are no shorter there, so they are dropped, and
///   symmetrically right of sp.
class VTP_solver : public Solver_base
{
public:
  /// The guard band of the approximation, in mean edge lengths (thesis 4.3.2, lambda_g).
  static constexpr double approximation_guard = 8.;
  /// Buckets are h / tau wide (thesis 4.2.2); a few slivers must not make them vanishingly thin.
  static constexpr double max_anisotropy = 4.;

  /// `settings` were checked by `read_solver_settings()`. When `parallel` (PVTP), vertices are
  /// taken from buckets until the batch size of lists are scheduled, and the scheduled lists are
  /// propagated on the threads of the task arena `run()` is called in. With an approximation
  /// (AVTP), every time the wavefront passes a multiple of lambda times the mean edge length its
  /// windows are dropped and its vertices become sources carrying their distances.
  VTP_solver(const Solver_mesh& mesh, const Solver_settings& settings, bool parallel)
    : Solver_base(mesh, settings, parallel)
    , m_is_taken(mesh.number_of_vertices, 0)
    , m_emits_when_taken(mesh.is_pseudo_source)
    , m_is_stop(mesh.number_of_vertices, 0)
    , m_head(mesh.number_of_halfedges(), Window_pool::nil)
    , m_list_flags(mesh.number_of_halfedges(), 0)
    , m_buckets(mesh.mean_edge_length / std::min(std::max(1., mesh.mean_anisotropy), max_anisotropy))
    , m_reset_step(settings.approximation * mesh.mean_edge_length)
    , m_min_clipped_overlap(min_clipped_overlap_ratio * mesh.mean_edge_length)
    // What a reset keeps depends on the order in which lists were propagated: the approximation
    // always takes vertices in batches from buckets, so that run sequentially or on any number
    // of threads it gives the same distances.
    , m_batched(parallel || settings.approximation > 0)
  {
  }

  void add_stop_vertex(int v)
  {
    check_vertex_index(m_mesh, v, "stop");
    if(!m_is_stop[v]) {
      m_is_stop[v] = 1;
      m_stop_vertices.push_back(v);
    }
  }

  /// Hands every list's windows as they are propagated across its face (trimmed by the edge's
  /// vertices and clipped against each other, before the children are made) to `recorder`
  /// (null: none, the default), per edge in the order of the merges (the same for every number
  /// of threads); in parallel, each round's lists are recorded on the threads, edge by edge.
  /// No path is dropped unless another is at least as short, so these windows and the paths
  /// through a vertex give the distance at any point of any face they enter
  /// (`geodesic_voronoi_diagram` reads them). The recorder must outlive the runs.
  void record_propagated_windows(Propagated_window_recorder* recorder)
  {
    m_recorder = recorder;
    if(recorder && m_batched)
      m_round_task.assign(m_mesh.number_of_halfedges(), -1);
    else
      m_round_task = std::vector<int>();
  }

  /// Makes the solver ready for another run on the same mesh with the same settings, without
  /// sources or stop vertices: only what the last run wrote is reset, so that a run costs what
  /// it sweeps, not the size of the mesh (the window lists are all empty after a run).
  void reset()
  {
    if(m_started_from_a_field) {
      std::fill(m_distance.begin(), m_distance.end(), infinity());
      std::fill(m_nearest_source.begin(), m_nearest_source.end(), -1);
      std::fill(m_emitted.begin(), m_emitted.end(), infinity());
      std::fill(m_is_taken.begin(), m_is_taken.end(), 0);
      m_emits_when_taken = m_mesh.is_pseudo_source;
    } else {
      for(int v : m_reached) {
        m_distance[v] = infinity();
        m_nearest_source[v] = -1;
      }
    }
    forget_run();
    m_started_from_a_field = false;
    m_first_source_index = 0;
  }

  /// Sets the max distance of the runs from now on, given in the mesh's unit (as
  /// `Solver_settings::max_distance`; `max_distance()` gives it back in the solver mesh's); between
  /// runs only.
  void set_max_distance_in_mesh_unit(double max_distance)
  {
    check_max_distance(max_distance);
    m_max_distance = max_distance / m_mesh.unit;
    m_window_limit = m_max_distance;
  }

  /// With stop vertices, the run goes on to this distance (in the mesh's unit) at least, even
  /// once they are all settled; for the next run only.
  void set_stop_floor_in_mesh_unit(double floor) { m_stop_floor = floor / m_mesh.unit; }

  /// Makes the solver ready for another run that starts from the distance field the last one
  /// left instead of +infinity, its sources numbered from `first_source_index` on; only what the
  /// last run wrote is reset. The run lowers the field where its own sources are nearer, and
  /// only there, since the trimming by edge vertices drops every window that cannot lower a
  /// vertex.
  void keep_field_for_next_run(int first_source_index)
  {
    forget_run();
    m_started_from_a_field = true;
    m_first_source_index = first_source_index;
  }

  /// Sets the distance and nearest source of a point that no propagation reaches (a vertex in
  /// no face, and the vertices glued to it), for the field the next run starts from; they count
  /// as reached, as if a run had set them.
  void set_isolated_point(int v, double d, int source)
  {
    m_mesh.for_each_copy_of_point(v, [&](int u) {
      note_reached(u);
      m_distance[u] = d;
      m_nearest_source[u] = source;
    });
  }

  /// The vertices whose distance the last run (or `set_isolated_point` since) set (some are
  /// +infinity again when beyond the limit), each once.
  const std::vector<int>& reached_vertices() const { return m_reached; }

  /// Makes the runs from now on note every vertex whose distance they read or write, for a
  /// caller that runs this solver beside another one from the same field: a run that read no
  /// vertex the other one changed computes what it would have computed after it.
  void note_reads()
  {
    if(m_read_stamp.empty())
      m_read_stamp.assign(m_mesh.number_of_vertices, 0);
  }
  /// Whether the last run read or wrote the distance of v (`note_reads()` on).
  bool was_read(int v) const { return m_read_stamp[std::size_t(v)] == m_run; }

  /// Takes the distances and nearest sources of `vertices` from `other`, a solver of the same
  /// mesh (the field the next run starts from, `keep_field_for_next_run`).
  void copy_field_from(const VTP_solver& other, const std::vector<int>& vertices)
  {
    for(int v : vertices) {
      m_distance[v] = other.m_distance[v];
      m_nearest_source[v] = other.m_nearest_source[v];
    }
  }

  /// Runs the propagation; distances beyond the max distance, or beyond the farthest stop
  /// vertex when stop vertices are given, are +infinity.
  void run()
  {
    const auto start = Clock::now();
    check_has_sources(m_mesh, m_sources);
    m_main_slot = m_pool.use_one_slot_per_thread(m_parallel);
    m_list_buffers.resize(m_pool.number_of_slots());
    if(m_recorder)
      m_recorder->start_run(m_parallel);
    const std::vector<bool> repeated = repeated_sources(m_sources);
    for(const Source_point& s : m_sources) {
      if(repeated[std::size_t(&s - m_sources.data())])
        continue;
      const int index = m_first_source_index + int(&s - m_sources.data());
      if(s.vertex >= 0) {
        note_read(s.vertex);
        m_emits_when_taken[s.vertex] = 1;
        next_step(); // after the windows of a face point emitted before
        relax(s.vertex, 0., index);
      } else {
        emit_from_face_point(s, index);
      }
    }
    m_next_reset = m_reset_step;
    start_progress();
    do {
      if(m_batched)
        take_vertices_in_batches();
      else
        take_vertices_one_by_one();
    } while(flush_waiting_lists());

    update_stop_limit();
    const double l = limit();
    if(l < infinity())
      for(int v : m_reached)
        if(m_distance[v] > l) {
          m_distance[v] = infinity();
          m_nearest_source[v] = -1;
        }
    finish_statistics(m_pool, start);
  }

private:
  // Resets what a run wrote apart from the distances and nearest sources, and its sources,
  // stop vertices, queues and statistics.
  void forget_run()
  {
    for(int v : m_reached) {
      m_emitted[v] = infinity();
      m_is_taken[v] = 0;
      m_emits_when_taken[v] = m_mesh.is_pseudo_source[v];
    }
    m_reached.clear();
    if(++m_run == 0) { // the read stamps wrapped around: none may look current
      std::fill(m_read_stamp.begin(), m_read_stamp.end(), 0);
      m_run = 1;
    }
    if(m_step >= first_step_to_wrap) { // no window is left: the steps can start again
      std::fill(m_set_at.begin(), m_set_at.end(), 0);
      m_step = 0;
    }
    m_first_step_of_run = ++m_step;
    m_sources.clear();
    for(int v : m_stop_vertices)
      m_is_stop[v] = 0;
    m_stop_vertices.clear();
    if(m_recorder) { // what a run that threw may have left of a round being recorded
      std::fill(m_round_task.begin(), m_round_task.end(), -1);
      for(List_task& task : m_tasks)
        task.propagated.clear();
      m_task_one.propagated.clear();
    }
    m_stops_taken = 0;
    m_vertices_taken = 0;
    m_front = 0;
    m_stop_limit = infinity();
    m_stop_floor = 0;
    m_heap.clear();
    m_deferred_emissions = 0; // none is left, unless a run threw
    m_buckets.clear();
    m_window_limit = m_max_distance;
    m_peak_windows = 0;
    m_statistics = Geodesic_statistics();
  }

  // The distance up to which results are wanted.
  double limit() const { return std::min(m_max_distance, m_stop_limit); }

  // Once every stop vertex is taken, nothing beyond the farthest of them (and the floor) is
  // wanted. Distances only decrease, so a limit computed earlier is never too small: it is
  // refreshed only now and then, when it is cheap to do so.
  void update_stop_limit()
  {
    if(m_stop_vertices.empty() || m_stops_taken < m_stop_vertices.size())
      return;
    double farthest = 0;
    for(int v : m_stop_vertices)
      farthest = std::max(farthest, m_distance[v]);
    m_stop_limit = std::max(farthest, m_stop_floor);
  }

  void relax(int v, double d, int source, const Arrival& arrival = Arrival{})
  {
    if(lowers(v, d, arrival))
      m_mesh.for_each_copy_of_point(v, [&](int u) { set_distance(u, d, source); });
  }

  // Every distance a run reads is of a vertex it sets, or of the faces of the lists it
  // propagates and around the vertices it emits from, or of a source.
  void note_read(int v)
  {
    if(!m_read_stamp.empty())
      m_read_stamp[std::size_t(v)] = m_run;
  }

  void note_reached(int v)
  {
    if(m_set_at[v] < m_first_step_of_run)
      m_reached.push_back(v);
    m_set_at[v] = m_step;
  }

  // The steps of a run: each propagation of a list and each emission (sequential), or each
  // phase of a round (batched: the emissions computed, then applied; the lists propagated, then
  // merged). A window is trimmed against the distances of its edge's end vertices at its step,
  // a distance set at a step is noted with it, and the window must be trimmed again when taken
  // only if a vertex of its edge was set at a later step (`propagate`). A step that sets a
  // distance before it makes windows (sequential: a list's apex, a vertex's emission, which
  // relaxes the ends of an edge before its window) made them against the distance it set; a
  // step that may make a window before it sets a distance of its edge (a face point's emission)
  // takes a second step for its relaxations. A run that uses up the 32-bit steps (some 2^31
  // steps, hundreds of millions of vertices) goes on with every window trimmed again.
  void next_step()
  {
    if(!out_of_steps())
      ++m_step;
  }
  bool out_of_steps() const { return m_step == last_step; }

  void set_distance(int v, double d, int source)
  {
    note_reached(v);
    note_read(v);
    m_distance[v] = d;
    m_nearest_source[v] = source;
    if(!m_is_taken[v] || m_emits_when_taken[v]) {
      if(m_batched)
        m_buckets.push(d, v);
      else
        m_heap.push(d, v);
    }
  }

  // How far the run is, for the caller's callback: the share of the vertices taken, or of the
  // distance limit reached when there is one.
  double done_fraction() const
  {
    const double by_vertices = double(m_vertices_taken) / double(std::max<std::size_t>(1, m_mesh.number_of_vertices));
    const double l = limit();
    return l < infinity() && l > 0 ? std::max(by_vertices, m_front / l) : by_vertices;
  }

  // Sequential VTP: the nearest vertex is taken, and everything it schedules is propagated
  // before the next one.
  void take_vertices_one_by_one()
  {
    while(!m_heap.empty()) {
      const Vertex_entry top = m_heap.top();
      if(top.first > m_distance[top.second]) { // stale
        m_heap.pop();
        continue;
      }
      if(top.first > limit())
        return;
      m_heap.pop();
      reset_wavefront_before(top.first);
      take_vertex(top.second);
      drain();
      report_progress_often([&] { return done_fraction(); });
    }
  }

  // PVTP: vertices are taken from the lowest buckets until enough lists are scheduled, then
  // the lists are propagated in parallel batches until none is left. Vertices beyond the limit,
  // or beyond the next reset radius of the approximation, wait: the reset happens, as in the
  // sequential version, once every vertex before it is taken and every list drained.
  void take_vertices_in_batches()
  {
    std::vector<Vertex_entry>& bucket = m_bucket_entries;
    for(;;) {
      const auto start = Clock::now();
      const double barrier = m_reset_step > 0 ? std::min(limit(), m_next_reset) : limit();
      bool took_any = false;
      double lowest_waiting = infinity();
      // One bucket a round that gives a vertex: its vertices lie in a band about one edge wide,
      // close enough to the true order that taking them together costs few extra windows. A
      // bucket of stale entries only does not count.
      while(!took_any && m_scheduled_lists.size() < m_batch_size && lowest_waiting == infinity()) {
        m_buckets.pop_lowest(bucket);
        if(bucket.empty())
          break;
        for(std::size_t i = 0; i < bucket.size(); ++i) {
          if(i + take_lookahead < bucket.size())
            prefetch_take(bucket[i + take_lookahead].second);
          const Vertex_entry& e = bucket[i];
          if(e.first > m_distance[e.second])
            continue; // stale
          if(e.first > barrier || m_scheduled_lists.size() >= m_batch_size) {
            m_buckets.push(e.first, e.second);
            if(e.first > barrier)
              lowest_waiting = std::min(lowest_waiting, e.first);
            continue;
          }
          take_vertex(e.second);
          took_any = true;
        }
      }
      emit_deferred();
      m_statistics.seconds_selection += seconds_since(start);
      if(took_any) {
        drain();
        report_progress([&] { return done_fraction(); });
        continue;
      }
      if(lowest_waiting == infinity() || lowest_waiting > limit())
        return;
      reset_wavefront_before(lowest_waiting);
    }
  }

  // What taking v reads first, asked of the caches a few vertices ahead (the vertices of a
  // bucket are scattered).
  void prefetch_take(int v) const
  {
#if defined(__GNUC__)
    __builtin_prefetch(&m_distance[std::size_t(v)]);
    __builtin_prefetch(&m_emitted[std::size_t(v)]);
    __builtin_prefetch(&m_is_taken[std::size_t(v)]);
    __builtin_prefetch(&m_mesh.first_outgoing[std::size_t(v)]);
#else
    (void)v;
#endif
  }

  bool inside_swept_region(int h) const { return m_is_taken[m_mesh.source(h)] || m_is_taken[m_mesh.target(h)]; }

  void schedule(int h)
  {
    if(m_head[h] != Window_pool::nil && !(m_list_flags[h] & in_scheduled_lists)) {
      m_list_flags[h] |= in_scheduled_lists;
      m_scheduled_lists.push_back(h);
    }
  }

  // Adds a run of windows, trimmed at step `trimmed_at`, to the list of half-edge h, and
  // schedules the list when it lies in the swept region (or when every list is being flushed);
  // otherwise it waits. The order of windows in a list does not matter: they are sorted when
  // the list is propagated. Only the list's chain nodes are written, no window: a window is
  // written by the thread that makes it alone.
  void add_chain(int h, Window_run run, std::uint32_t trimmed_at)
  {
    std::uint32_t node = m_free_chain_node;
    if(node != Window_pool::nil)
      m_free_chain_node = m_chain_nodes[node].next;
    else {
      node = std::uint32_t(m_chain_nodes.size());
      m_chain_nodes.emplace_back();
    }
    m_chain_nodes[node] = Chain_node{List_chain{run, trimmed_at}, m_head[h]};
    m_head[h] = node;
    m_statistics.windows_created += run.count;
    if(m_flushing || inside_swept_region(h))
      schedule(h);
    else if(!(m_list_flags[h] & in_waiting_lists)) {
      m_list_flags[h] |= in_waiting_lists;
      m_waiting_lists.push_back(h);
    }
  }

  // A pseudo-source at vertex v: whole-edge windows on the edges opposite v, and its
  // neighbours relaxed along the edges, at once (VTP) or once the vertices of the round are taken
  // (batched: `emit_deferred`).
  void emit_from_vertex(int v)
  {
    m_emitted[v] = m_distance[v];
    if(!m_read_stamp.empty())
      m_mesh.for_each_outgoing(v, [&](int h) {
        note_read(m_mesh.target(h));
        note_read(m_mesh.apex(h));
      });
    if(m_batched) {
      if(m_deferred_emissions == m_emissions.size())
        m_emissions.emplace_back();
      m_emissions[m_deferred_emissions++].vertex = v;
      return;
    }
    m_window_limit = limit();
    m_emission_one.vertex = v;
    next_step();
    compute_emission(m_emission_one, m_main_slot);
    apply_emission(m_emission_one);
  }

  // The emissions of the vertices taken in a round, computed in parallel and applied in the
  // order the vertices were taken, once the round's vertices are taken. So, unlike when each
  // vertex emitted as it was taken: an emission does not see the relaxations of the others of
  // its round, and may keep a few more windows; a vertex one of them lowers is taken in this
  // round at its former distance (it emits again when taken at the lower one); and the
  // emissions' lists do not count towards the round's batch of lists. Every path stays a real
  // path, and the order stays the same for any number of threads.
  void emit_deferred()
  {
    const std::size_t n = m_deferred_emissions;
    if(n == 0)
      return;
    m_window_limit = limit();
    next_step();
    for_each_index(m_parallel, n, emission_grain,
                   [this](std::size_t i, std::size_t slot) { compute_emission(m_emissions[i], slot); });
    next_step(); // each emission's windows are trimmed again where the round's relaxations lowered a vertex
    for(std::size_t i = 0; i < n; ++i)
      apply_emission(m_emissions[i]);
    m_deferred_emissions = 0;
  }

  // What `e.vertex` emits at its distance. Reads only the mesh and the vertices' distances,
  // nearest sources and arrivals, which nothing writes while emissions are computed; writes only
  // `e` and the pool's `slot`.
  void compute_emission(Vertex_emission& e, std::size_t slot)
  {
    const int v = e.vertex;
    compute_windows(e, slot, m_nearest_source[v], [&](auto relax, auto add) {
      // A saddle emits only into its cone (a vertex a reset of the approximation made a source
      // has no arrival: every way).
      emit_vertex_windows(m_mesh, v, m_distance[v], relax, add, cone_of(v, e.cone));
    });
  }

  // What `emit(relax, add)` (an emitter of Source_windows.h, paths from `source`) gives, into `e`: the
  // relaxations that lower a distance now, and the windows kept, allocated in the pool's `slot`.
  // A window's edge is trimmed with the distances of its ends as the emission's own relaxations
  // so far leave them, as if they had been applied.
  template <class Emit>
  void compute_windows(Vertex_emission& e, std::size_t slot, int source, Emit emit)
  {
    e.relaxations.clear();
    e.windows.clear();
    e.trimmed_at = m_step;
    auto distance = [&](int u) {
      double d = m_distance[u];
      for(const Vertex_update& r : e.relaxations)
        if(r.vertex == u || m_mesh.are_glued(r.vertex, u))
          d = std::min(d, r.distance);
      return d;
    };
    emit(
      [&](int u, double d, const Arrival& a) {
        if(d < m_distance[u]) // otherwise the relaxation would find nothing to lower
          e.relaxations.push_back({u, source, d, a});
      },
      [&](int g, const Window_geometry& geometry) {
        Window w = list_window(geometry, source);
        if(keep_window(w, g, distance(m_mesh.source(g)), distance(m_mesh.target(g)))) {
          reserve_one_more(e.windows);
          e.windows.push_back({g, m_pool.make_copy(slot, 0, w)});
        }
      });
  }

  void apply_emission(const Vertex_emission& e)
  {
    for(const Vertex_update& r : e.relaxations)
      relax(r.vertex, r.distance, r.source, r.arrival);
    for(const auto& [g, index] : e.windows)
      add_chain(g, Window_run{index, 1}, e.trimmed_at);
    note_live_windows(m_pool);
  }

  void emit_from_face_point(const Source_point& s, int source)
  {
    m_window_limit = limit();
    next_step();
    compute_windows(m_emission_one, m_main_slot, source,
                    [&](auto relax, auto add) { emit_face_point_windows(m_mesh, s, relax, add); });
    next_step(); // a window may come before the relaxation of an end of its edge
    apply_emission(m_emission_one);
  }

  void take_vertex(int v)
  {
    ++m_statistics.vertices_popped;
    m_front = m_distance[v];
    if(!m_is_taken[v]) {
      m_is_taken[v] = 1;
      ++m_vertices_taken;
      if(m_is_stop[v] && ++m_stops_taken == m_stop_vertices.size())
        update_stop_limit();
    }
    if(m_emits_when_taken[v] && m_distance[v] < m_emitted[v])
      emit_from_vertex(v);
    // The lists on the edges at v: h and prev(h) of each face of the walk around v, and the
    // opposite of the first h (every other opposite is one of those), in the order that
    // scheduling each face's two and their opposites in turn gave.
    bool first = true;
    m_mesh.for_each_outgoing(v, [&](int h) {
      schedule(h);
      schedule(Solver_mesh::prev(h));
      if(first && m_mesh.opposite(h) >= 0)
        schedule(m_mesh.opposite(h)); // each other opposite is the h or prev(h) of a face of the walk
      first = false;
    });
  }

  // AVTP (thesis Algorithm 5): before a vertex beyond the next reset radius r is taken, the
  // windows of the wavefront within the guard band r + lambda_g h are dropped, and the queued
  // vertices within the band become sources carrying their tentative distance.
  void reset_wavefront_before(double d)
  {
    if(m_reset_step <= 0 || d <= m_next_reset)
      return;
    const auto start = Clock::now();
    // When several radii are passed at once, one reset at the last of them does.
    const double r = std::max(m_next_reset, std::floor(d / m_reset_step) * m_reset_step);
    const double guard = r + approximation_guard * m_mesh.mean_edge_length;
    // The windows that carried a marked vertex's path are dropped: it emits every way (no
    // arrival), unless a later path lowers its distance.
    auto mark = [&](const Vertex_entry& e) {
      if(!m_is_taken[e.second] && m_distance[e.second] <= guard) {
        m_emits_when_taken[e.second] = 1;
        forget_arrival(e.second);
      }
    };
    if(m_batched)
      m_buckets.for_each(mark);
    else
      m_heap.for_each(mark);
    // Windows wait only on lists outside the swept region; a list goes when both its end
    // vertices are within the band. Lists that were emptied or swept since they were recorded
    // are forgotten here, so that each reset costs the size of the wavefront, not of its history.
    std::size_t kept = 0;
    for(int h : m_waiting_lists) {
      if(m_head[h] != Window_pool::nil && m_distance[m_mesh.source(h)] <= guard &&
         m_distance[m_mesh.target(h)] <= guard)
        clear_list(h);
      if(m_head[h] != Window_pool::nil && !inside_swept_region(h))
        m_waiting_lists[kept++] = h;
      else
        m_list_flags[h] &= std::uint8_t(~in_waiting_lists);
    }
    m_waiting_lists.resize(kept);
    m_next_reset = r + m_reset_step;
    ++m_statistics.wavefront_resets;
    m_statistics.seconds_selection += seconds_since(start);
  }

  void clear_list(int h)
  {
    free_chains(m_head[h]);
    m_head[h] = Window_pool::nil;
  }

  // Frees the chains from node `first` on (nil: none), their windows and their nodes (serial).
  void free_chains(std::uint32_t first) { free_chain_nodes(first, free_runs(first, m_main_slot)); }

  // Frees the windows of the chains from node `first` on into the pool's `slot`; returns the
  // last node (nil if `first` is).
  std::uint32_t free_runs(std::uint32_t first, std::size_t slot)
  {
    std::uint32_t last = first;
    for(std::uint32_t node = first; node != Window_pool::nil; node = m_chain_nodes[node].next) {
      m_pool.free_run(slot, m_chain_nodes[node].chain.run.first, m_chain_nodes[node].chain.run.count);
      last = node;
    }
    return last;
  }

  // Gives the chain nodes from `first` to `last` along their links (none if `first` is nil)
  // back to the nodes' free list.
  void free_chain_nodes(std::uint32_t first, std::uint32_t last)
  {
    if(first == Window_pool::nil)
      return;
    m_chain_nodes[last].next = m_free_chain_node;
    m_free_chain_node = first;
  }

  // Propagates the scheduled lists, and the lists they schedule, until none is left.
  void drain()
  {
    m_window_limit = limit();
    if(!m_batched) {
      List_task& task = m_task_one;
      for(std::size_t i = 0; i < m_scheduled_lists.size(); ++i) {
        // (the list read along its nodes: copying them, as a round does, only costs here)
        const int h = m_scheduled_lists[i];
        const std::uint32_t first = take_list(h);
        std::uint32_t windows = 0;
        for(std::uint32_t node = first; node != Window_pool::nil; node = m_chain_nodes[node].next)
          windows += m_chain_nodes[node].chain.run.count;
        next_step();
        propagate(h, windows, Node_chains{m_chain_nodes.data(), first}, task, m_main_slot);
        free_chains(first);
        merge(task);
        note_live_windows(m_pool);
      }
      m_scheduled_lists.clear();
      return;
    }
    while(!m_scheduled_lists.empty()) {
      const std::size_t n = m_scheduled_lists.size();
      if(m_tasks.size() < n)
        m_tasks.resize(n);
      m_detached.clear();
      m_round_chains.clear();
      for(std::size_t i = 0; i < n; ++i) {
        detach(m_scheduled_lists[i]);
        if(m_recorder)
          m_round_task[std::size_t(m_scheduled_lists[i])] = int(i);
      }
      m_scheduled_lists.clear();
      auto start = Clock::now();
      next_step();
      propagate_tasks(n);
      if(m_recorder)
        record_round(n);
      m_statistics.seconds_propagation += seconds_since(start);
      start = Clock::now();
      next_step(); // the children of a list are trimmed again where a merge lowered a vertex
      for(std::size_t i = 0; i < n; ++i) {
        if(i + merge_lookahead < n)
          prefetch_merge(m_tasks[i + merge_lookahead]);
        merge(m_tasks[i]);
      }
      note_live_windows(m_pool);
      m_statistics.seconds_merge += seconds_since(start);
    }
  }

  void propagate_tasks(std::size_t n)
  {
    // Each task reads shared state that no task writes, and writes only itself and its
    // thread's pool slot. The windows of the tasks of a chunk (at most `list_grain`) are asked
    // for at once: the windows of a round were made by any thread.
    for_each_chunk(m_parallel, n, list_grain, [this](std::size_t begin, std::size_t end, std::size_t slot) {
      for(std::size_t first = begin; first < end; first += list_grain) {
        const std::size_t last = std::min(end, first + list_grain);
        for(std::size_t i = first; i < last; ++i)
          for(const List_chain& c : chains_of(m_detached[i]))
            prefetch_run(c.run);
        for(std::size_t i = first; i < last; ++i) {
          const Detached_list& d = m_detached[i];
          propagate(d.halfedge, d.window_count, chains_of(d), m_tasks[i], slot);
          for(const List_chain& c : chains_of(d))
            m_pool.free_run(slot, c.run.first, c.run.count);
        }
      }
    });
  }

  // The round's propagated lists to the recorder, in parallel by edge: the task of the lower
  // index records its list, then the list on the other side of its edge when it is in the round
  // too (the merges' order on each edge); the other task records nothing.
  void record_round(std::size_t n)
  {
    for_each_index(m_parallel, n, list_grain, [this](std::size_t i, std::size_t slot) {
      List_task& task = m_tasks[i];
      const int opposite = m_mesh.opposite(task.halfedge);
      const int other = opposite >= 0 ? m_round_task[std::size_t(opposite)] : -1;
      if(other >= 0 && std::size_t(other) < i)
        return;
      record_task(task, slot);
      if(other >= 0)
        record_task(m_tasks[std::size_t(other)], slot);
    });
    for(std::size_t i = 0; i < n; ++i)
      m_round_task[std::size_t(m_tasks[i].halfedge)] = -1;
  }

  void record_task(List_task& task, std::size_t slot)
  {
    if(!task.propagated.empty()) {
      m_recorder->record(task.halfedge, task.propagated, slot);
      task.propagated.clear();
    }
  }

  // Propagates every list that still holds windows, whether or not its edge was swept; used
  // once no vertex within the limit is left, so that every path shorter than the limit is done.
  // Returns whether anything was propagated (vertices may then need to be taken again).
  bool flush_waiting_lists()
  {
    update_stop_limit();
    m_flushing = true;
    for(int h : m_waiting_lists) {
      m_list_flags[h] &= std::uint8_t(~in_waiting_lists);
      schedule(h);
    }
    m_waiting_lists.clear();
    const bool any = !m_scheduled_lists.empty();
    drain();
    m_flushing = false;
    return any;
  }

  // The chains of a list detached for a round.
  struct Chain_range
  {
    const List_chain* first;
    const List_chain* last;
    const List_chain* begin() const { return first; }
    const List_chain* end() const { return last; }
  };
  Chain_range chains_of(const Detached_list& list) const
  {
    const List_chain* first = m_round_chains.data() + list.first_chain;
    return Chain_range{first, first + list.chain_count};
  }

  // Takes the list of h out for the round (`m_detached`): its chains are copied to the
  // round's, side by side, and their nodes freed at once. (The chain nodes and the tasks are
  // written by the serial steps: read by the thread that propagates the list, each would be a
  // line that another core wrote.)
  void detach(int h)
  {
    const std::uint32_t first = take_list(h);
    const std::uint32_t first_chain = std::uint32_t(m_round_chains.size());
    std::uint32_t windows = 0, last = Window_pool::nil;
    for(std::uint32_t node = first; node != Window_pool::nil; node = m_chain_nodes[node].next) {
      m_round_chains.push_back(m_chain_nodes[node].chain);
      windows += m_chain_nodes[node].chain.run.count;
      last = node;
    }
    const std::uint32_t chain_count = std::uint32_t(m_round_chains.size()) - first_chain;
    m_detached.push_back(Detached_list{h, first_chain, chain_count, windows});
    free_chain_nodes(first, last);
  }

  // Takes the list off half-edge h (unscheduled, its head nil); returns its newest chain node.
  std::uint32_t take_list(int h)
  {
    m_list_flags[h] &= std::uint8_t(~in_scheduled_lists);
    const std::uint32_t first = m_head[h];
    m_head[h] = Window_pool::nil;
    if(!m_read_stamp.empty()) {
      note_read(m_mesh.source(h));
      note_read(m_mesh.target(h));
      note_read(m_mesh.apex(h));
    }
    return first;
  }

  // A thread's buffers for the list it propagates (one a thread rather than one a task, so that
  // they stay in the thread's cache from list to list): the list's windows (where they are in
  // the pool), what sorting them needs beside them, and the windows that splits added. Each on
  // its own cache lines: two threads' buffers side by side would share a line that both write
  // at each window they add.
  struct alignas(64) List_buffers
  {
    Window_pointers windows;
    std::vector<std::size_t> run_starts;
    Window_pointers merged;
    std::vector<std::uint32_t> extra; // windows made for the parts of split windows
    std::vector<double> crossings; // per window: where its ray to the apex crosses the edge
  };

  // Asks the processor for the windows of a run.
  void prefetch_run(Window_run run) const
  {
#if defined(__GNUC__)
    const Window* w = &m_pool[run.first];
    for(std::uint32_t k = 0; k < run.count; ++k)
      __builtin_prefetch(w + k);
#else
    (void)run;
#endif
  }

  // Takes the `window_count` windows of the list of h (`chains`: the round's copy, or along
  // the nodes) across the face of h, into `task`. Reads the mesh and the vertex distances;
  // writes only `task` and what belongs to `slot` (the calling thread's): the pool's slot,
  // which gives the children, and the slot's `List_buffers`. The caller frees the list's runs
  // once it returns (not before: the windows are read in place).
  template <class Chains>
  void propagate(int h, std::size_t window_count, const Chains& chains, List_task& task, std::size_t slot)
  {
    task.halfedge = h;
    List_buffers& buffers = m_list_buffers[slot];
    Window_pointers& windows = buffers.windows;
    task.to_ac.clear();
    task.to_cb.clear();
    task.trimmed_at = m_step;
    task.apex_distance = infinity();
    task.apex_source = -1;
    task.apex_arrival = Arrival{};
    windows.clear();
    buffers.extra.clear();
    const Halfedge_frame f = m_mesh.frame(h);
    const double d_from = m_distance[m_mesh.source(h)];
    const double d_to = m_distance[m_mesh.target(h)];
    // The list's windows are worked on where they are in the pool, through pointers, and freed
    // by the caller after: the children are allocated before, so that none takes the place of
    // a window still read. Trimming a window again against the distances it was trimmed with
    // would leave it as it is: only the chains trimmed before a step that set a distance of the
    // edge's end vertices are (every chain, under a finite limit, which trimming applies too).
    const std::uint32_t stale_before = m_window_limit < infinity() || out_of_steps()
                                         ? std::numeric_limits<std::uint32_t>::max()
                                         : std::max(m_set_at[m_mesh.source(h)], m_set_at[m_mesh.target(h)]);
    windows.resize(window_count);
    Window** list = windows.data();
    std::size_t kept = 0;
    for(const List_chain& c : chains) {
      Window* const run = &m_pool[c.run.first];
      if(c.trimmed_at >= stale_before)
        for(std::uint32_t i = 0; i < c.run.count; ++i)
          list[kept++] = run + i;
      else
        for(std::uint32_t i = 0; i < c.run.count; ++i)
          if(keep_window(run[i], h, d_from, d_to))
            list[kept++] = run + i;
    }
    windows.resize(kept);
    if(!windows.empty())
      propagate_windows(task, slot, buffers, f, d_from, d_to);
    for(std::uint32_t i : buffers.extra)
      m_pool.free_run(slot, i, 1);
  }

  // The rest of `propagate` for the list's windows kept, `buffers.windows` (not empty).
  void propagate_windows(List_task& task, std::size_t slot, List_buffers& buffers, const Halfedge_frame& f,
                         double d_from, double d_to)
  {
    const int h = task.halfedge;
    Window_pointers& windows = buffers.windows;
    sort_by_start(buffers);
    prune_pairs(windows, m_min_clipped_overlap, [&](const Window& right) {
      reserve_one_more(buffers.extra);
      const std::uint32_t index = m_pool.make_copy(slot, 0, right);
      buffers.extra.push_back(index);
      return &m_pool[index];
    });
    if(m_recorder)
      keep_for_record(task, windows);

    // "One angle, two sides": the window with the shortest path to the apex splits the edge.
    double best = infinity(), split = 0;
    const Window* best_window = nullptr;
    // (the size and the data at hand: through the vectors, GCC loads them again at each window)
    const std::size_t n = windows.size();
    if(buffers.crossings.size() < n)
      buffers.crossings.resize(n);
    Window* const* list = windows.data();
    double* crossings = buffers.crossings.data();
    for(std::size_t i = 0; i < n; ++i) {
      const Window& w = *list[i];
      if(is_empty(w))
        continue; // clipped away (an empty window makes no child either)
      double at;
      const double d = distance_to_apex(w, crossings[i] = apex_crossing(w, f.apex_x, f.apex_y), f.apex_x, f.apex_y, at);
      if(d < best) {
        best = d;
        split = at;
        best_window = &w;
      }
    }
    task.apex_distance = best;
    if(best_window) {
      task.apex_source = best_window->source;
      task.apex_arrival = apex_arrival(h, *best_window, split, f.apex_x, f.apex_y);
    }

    const double d_apex = std::min(m_distance[m_mesh.apex(h)], best);
    const Face_crossing across = face_crossing(m_mesh, h, f);
    task.to_ac.reserve(n); // (a window has at most one child on each side)
    task.to_cb.reserve(n);
    task.to_ac_halfedge = across.to_ac;
    task.to_cb_halfedge = across.to_cb;
    for(std::size_t i = 0; i < n; ++i) {
      const Window& w = *list[i];
      if(is_empty(w))
        continue;
      const double crossing = crossings[i];
      // (each child made in its place in the pool, where it stays if it is kept)
      for_each_child_part(
        w, across, std::min(split, crossing), std::max(split, crossing),
        [&](int g, bool onto_ac, double lo, double hi, const Child_edge& e) CGAL_EXT_ALWAYS_INLINE {
          (onto_ac ? task.to_ac : task.to_cb).push_back_made(m_pool, slot, onto_ac ? 0 : 1, [&](Window& child) {
            if(!make_child(w, lo, hi, e, m_min_window_length, child))
              return false;
            finish_list_window(child, w.source);
            // A -> C runs from the source of h to the apex, C -> B from the apex to the target
            return onto_ac ? keep_window(child, g, d_from, d_apex) : keep_window(child, g, d_apex, d_to);
          });
        });
    }
  }

  // Out of line: inlined, its copy made GCC leave the list's sort out of line (more instructions).
  CGAL_EXT_NOINLINE static void keep_for_record(List_task& task, const Window_pointers& windows)
  {
    task.propagated.clear();
    for(const Window* w : windows)
      if(!is_empty(*w)) // not clipped away
        task.propagated.push_back(*w);
  }

  // Applies a propagated task: updates the apex, adds the children to their lists.
  void merge(List_task& task)
  {
    ++m_statistics.lists_propagated;
    const int h = task.halfedge;
    if(m_recorder && !m_batched)
      record_task(task, m_main_slot);
    if(task.apex_distance < infinity())
      relax(m_mesh.apex(h), task.apex_distance, task.apex_source, task.apex_arrival);
    // (the last run first: a list is read from its newest node, so that its windows come in the
    // order they were made, as when they are one run)
    task.to_ac.for_each_run_backwards([&](Window_run run) { add_chain(task.to_ac_halfedge, run, task.trimmed_at); });
    task.to_cb.for_each_run_backwards([&](Window_run run) { add_chain(task.to_cb_halfedge, run, task.trimmed_at); });
  }

  // What `merge(task)` will read, asked of the caches a few tasks ahead: the merges are serial
  // and read scattered entries, which the propagation of the tasks did not bring to this core.
  // (The children's edges end at the face's vertices, or at vertices glued to them where a
  // degenerate face was removed: those are only not prefetched.)
  void prefetch_merge(const List_task& task) const
  {
#if defined(__GNUC__)
    const int h = task.halfedge;
    __builtin_prefetch(&m_distance[std::size_t(m_mesh.apex(h))]);
    for(int v : {m_mesh.source(h), m_mesh.target(h), m_mesh.apex(h)})
      __builtin_prefetch(&m_is_taken[std::size_t(v)]);
    for(const auto& [g, chain] : {std::make_pair(task.to_ac_halfedge, &task.to_ac),
                                  std::make_pair(task.to_cb_halfedge, &task.to_cb)})
      if(!chain->empty()) {
        __builtin_prefetch(&m_head[std::size_t(g)]);
        __builtin_prefetch(&m_list_flags[std::size_t(g)]);
      }
#else
    (void)task;
#endif
  }

  // Rule 2: windows of the list (sorted by where they start) are clipped against each other
  // where they overlap by at least `min_overlap` (min_clipped_overlap_ratio): leaving two
  // windows unclipped is safe, since a rule only ever drops rays. A window clipped away is left
  // in place, empty (`is_empty`): it makes no child, and the loops after skip it, which costs
  // less than closing the gaps.
  template <class Make_room>
  static void prune_pairs(Window_pointers& windows, double min_overlap, Make_room make_room)
  {
    if(windows.size() < 2)
      return;
    Window** w = windows.data(); // and n: refreshed after a split adds a window
    std::size_t n = windows.size();
    // (the emptiness tests are written out here: through `is_empty`, GCC compiled the loop worse)
    for(std::size_t i = 0; i < n; ++i) {
      Window& wi = *w[i];
      for(std::size_t j = i + 1; j < n && wi.b1 > wi.b0; ++j) {
        Window& wj = *w[j];
        if(wj.b0 >= wi.b1)
          break; // sorted by where they start (skipping a pair only keeps more windows)
        if(!(wj.b1 > wj.b0) || std::min(wi.b1, wj.b1) - wj.b0 < min_overlap)
          continue;
        Window right;
        const int outcome = clip_pair(wi, wj, &right);
        if(outcome & 1)
          wi.b1 = wi.b0;
        if(outcome & 2)
          wj.b1 = wj.b0;
        if(outcome & 4) {
          Window* room = make_room(right);
          auto at = std::upper_bound(windows.begin() + std::ptrdiff_t(j) + 1, windows.end(), room, starts_before);
          windows.insert(at, room);
          w = windows.data();
          n = windows.size();
        }
      }
    }
  }

  // The order of a list's windows: by where they start.
  static bool starts_before(const Window* a, const Window* b) { return a->b0 < b->b0; }


  // Sorts a list's windows by where they start. A list is a few chains of children, each
  // sorted (in the order of its parent list): the runs of windows that start in order are
  // merged pairwise, in passes between `windows` and `merged`, which costs a copy of the list a
  // pass rather than a move per pair out of order (lists of a few long chains that interleave
  // have many). Stable, as the order of equal starts is the list's.
  static void sort_by_start(List_buffers& buffers)
  {
    Window_pointers& windows = buffers.windows;
    const std::size_t n = windows.size();
    // (the last start kept at hand: read through the pointers, it would be loaded again)
    double last = windows[0]->b0;
    std::size_t i = 1;
    for(; i < n && !(windows[i]->b0 < last); ++i)
      last = windows[i]->b0;
    if(i >= n)
      return; // one run
    std::vector<std::size_t>& runs = buffers.run_starts; // then the end
    runs.clear();
    runs.push_back(0);
    runs.push_back(i);
    for(++i; i < n; ++i)
      if(starts_before(windows[i], windows[i - 1]))
        runs.push_back(i);
    runs.push_back(n);
    buffers.merged.resize(n);
    while(runs.size() > 2) {
      std::size_t kept = 0;
      for(std::size_t r = 0; r + 1 < runs.size(); r += 2) {
        const std::size_t a = runs[r], m = runs[r + 1], b = r + 2 < runs.size() ? runs[r + 2] : m;
        std::merge(windows.begin() + std::ptrdiff_t(a), windows.begin() + std::ptrdiff_t(m),
                   windows.begin() + std::ptrdiff_t(m), windows.begin() + std::ptrdiff_t(b),
                   buffers.merged.begin() + std::ptrdiff_t(a), starts_before);
        runs[kept++] = a;
      }
      runs[kept++] = n;
      runs.resize(kept);
      windows.swap(buffers.merged);
    }
  }

  // Chunks of a fixed size: lists are small units of work, but uneven.
  static constexpr std::size_t list_grain = 8;
  static constexpr std::size_t emission_grain = 4;
  static constexpr std::size_t merge_lookahead = 8; // tasks
  static constexpr std::size_t take_lookahead = 8;  // vertices

  std::vector<std::uint8_t> m_is_taken;
  std::vector<std::uint8_t> m_emits_when_taken; // pseudo-source, source, or made a source by a reset
  std::vector<std::uint8_t> m_is_stop;
  // The lists' chains: per half-edge, the node of its list's newest chain (or nil), each node
  // linking to the next older one; the nodes not in use are linked from m_free_chain_node.
  struct Chain_node
  {
    List_chain chain;
    std::uint32_t next;
  };
  // The chains of a list along its nodes from `first` (`Chain_range`: copied for a round).
  struct Node_chains
  {
    const Chain_node* nodes;
    std::uint32_t first;
    struct iterator
    {
      const Chain_node* nodes;
      std::uint32_t node;
      const List_chain& operator*() const { return nodes[node].chain; }
      iterator& operator++()
      {
        node = nodes[node].next;
        return *this;
      }
      bool operator!=(const iterator& other) const { return node != other.node; }
    };
    iterator begin() const { return iterator{nodes, first}; }
    iterator end() const { return iterator{nodes, Window_pool::nil}; }
  };
  std::vector<std::uint32_t> m_head;
  std::vector<Chain_node> m_chain_nodes;
  std::vector<Detached_list> m_detached; // batched: the lists detached for the round
  std::vector<List_chain> m_round_chains; // and their chains
  std::uint32_t m_free_chain_node = Window_pool::nil;
  // per half-edge: whether its list is in m_scheduled_lists, in m_waiting_lists
  static constexpr std::uint8_t in_scheduled_lists = 1, in_waiting_lists = 2;
  std::vector<std::uint8_t> m_list_flags;
  std::vector<int> m_waiting_lists;   // lists holding windows outside the swept region
  std::vector<int> m_scheduled_lists; // lists to propagate, in order
  Vertex_heap m_heap;
  Vertex_buckets m_buckets;
  std::vector<Vertex_entry> m_bucket_entries;
  List_task m_task_one;
  Vertex_emission m_emission_one;
  std::vector<Vertex_emission> m_emissions; // batched: the first m_deferred_emissions are the
  std::size_t m_deferred_emissions = 0;     // round's, waiting; the rest is storage kept for reuse
  std::vector<List_task> m_tasks;
  std::vector<List_buffers> m_list_buffers; // per pool slot
  Window_pool m_pool;
  std::size_t m_main_slot = 0; // the pool slot of the thread running run()
  std::vector<int> m_stop_vertices;
  std::size_t m_stops_taken = 0;
  std::size_t m_vertices_taken = 0; // distinct vertices taken in this run (for the callback)
  double m_front = 0;               // the distance of the last vertex taken (for the callback)
  int m_first_source_index = 0; // the number of the first source (keep_field_for_next_run)
  bool m_started_from_a_field = false;
  std::vector<int> m_reached;        // vertices whose distance this run set, each once
  std::vector<std::uint32_t> m_set_at = std::vector<std::uint32_t>(m_mesh.number_of_vertices, 0); // per vertex: the step that last set its distance
  std::uint32_t m_step = 1;             // the current step (`next_step`)
  std::uint32_t m_first_step_of_run = 1; // a vertex set at an earlier step is not reached yet in this run
  static constexpr std::uint32_t first_step_to_wrap = std::uint32_t(1) << 31;
  // The steps stop here: every window is trimmed again from then on (`stale_before`), so that
  // windows and distances of the same step are never taken as trimmed against each other.
  static constexpr std::uint32_t last_step = std::numeric_limits<std::uint32_t>::max() - 1;
  std::vector<std::uint32_t> m_read_stamp; // per vertex: the last run that read it (empty: not noted)
  std::uint32_t m_run = 1;
  double m_stop_limit = infinity();
  double m_stop_floor = 0; // see set_stop_floor_in_mesh_unit
  const double m_reset_step; // lambda h, or 0 for exact propagation
  const double m_min_clipped_overlap; // see min_clipped_overlap_ratio
  double m_next_reset = 0;
  bool m_flushing = false; // lists are scheduled whether or not they are in the swept region
  const bool m_batched;    // take vertices from buckets, propagate lists in batches
  Propagated_window_recorder* m_recorder = nullptr; // see record_propagated_windows
  std::vector<int> m_round_task; // batched, with a recorder: per half-edge, its task in the round or -1
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_VTP_SOLVER_H
