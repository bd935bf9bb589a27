// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_MMP_SOLVER_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_MMP_SOLVER_H

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Edge_window_store.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Priority_queues.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Solver_base.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Source_windows.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Window.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh.h>
#include <CGAL_ext/Geodesics_3/internal/support/Parallel_for.h>

#include <algorithm>
#include <cstdint>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// A window made by a propagation or a pseudo-source, before it is clipped into its edge; the
/// geometry is in the frame of `halfedge`.
struct New_window
{
  Window_geometry geometry;
  int halfedge;
  int source;
};

/// What the queue holds: a window (with the version it had when queued) or a pseudo-source
/// vertex. Comparisons never look at addresses: the heap's operations, and so the order of
/// equal keys, are the same from run to run.
struct Queue_item
{
  Edge_window* window;
  int vertex;
  std::uint32_t version;
  bool operator<(const Queue_item& o) const { return vertex != o.vertex ? vertex < o.vertex : version < o.version; }
};

/// Exact geodesic distances and paths by window propagation with windows kept on the edges (the
/// algorithm of Mitchell, Mount and Papadimitriou, thesis chapter 3), in three forms:
/// - MMP: windows in exact order of distance from a binary heap;
/// - FWP-MMP: windows taken bucket by bucket (Fast Wavefront Propagation), in no order inside a
///   bucket;
/// - PMMP (parallel): up to K windows are selected from the lowest buckets, propagated
///   in parallel, filed by edge, and clipped in parallel, one task per edge; the queue and the
///   vertex distances are updated sequentially, in a fixed order, so that every number of
///   threads gives the same windows.
///
/// Each edge keeps a partition of the parts of it reached so far (`Edge_window_store`). A window
/// that has been propagated may still be clipped there; its children stay and are clipped in
/// turn. Pseudo-sources (saddle and border vertices, and the sources) are queue items too:
/// when taken they emit windows onto the edges opposite them. Windows are also trimmed by the
/// distances of the end vertices of their edge (the exact filter shared with VTP).
///
/// After the run, the windows on the edges give the distance at any surface point and the
/// shortest path back to the nearest source (`Geodesic_path_tracer.h`).
class MMP_solver : public Solver_base
{
public:
  /// `settings` were checked by `read_solver_settings()`; `settings.algorithm` chooses the
  /// queue of the sequential forms (a binary heap for MMP, buckets for FWP-MMP). When
  /// `parallel` (PMMP), `run()` works on the threads of the task arena it is called in.
  MMP_solver(const Solver_mesh& mesh, const Solver_settings& settings, bool parallel)
    : Solver_base(mesh, settings, parallel)
    , m_emits_when_taken(mesh.is_pseudo_source)
    , m_windows(mesh, m_min_window_length, /*requeue_trimmed=*/!parallel && settings.algorithm == MMP)
    , m_use_heap(!parallel && settings.algorithm == MMP)
    , m_buckets(mesh.mean_edge_length)
  {
  }

  void run()
  {
    const auto start = Clock::now();
    check_has_sources(m_mesh, m_sources);
    m_main_slot = m_windows.use_one_slot_per_thread(m_parallel);
    m_front = 0;
    start_progress();
    start_from_sources();
    if(m_parallel)
      run_parallel();
    else if(m_use_heap)
      run_with_heap();
    else
      run_with_buckets();
    for(std::size_t v = 0; v < m_distance.size(); ++v)
      if(m_distance[v] > m_max_distance) {
        m_distance[v] = infinity();
        m_nearest_source[v] = -1;
      }
    finish_statistics(m_windows, start);
    m_statistics.windows_stored = m_windows.live();
    m_statistics.stored_window_bytes = m_windows.stored_bytes();
  }

  // ---- what the queries read (all const, and never written after run()) ----

  /// The windows kept on the edges.
  const Edge_window_store& windows() const { return m_windows; }

private:
  // What propagating one window gives.
  struct Propagation_output
  {
    Edge_window* window = nullptr;
    std::uint32_t version = 0; // PMMP: of the queue entry
    New_window children[2];
    int number_of_children = 0;
    Vertex_update apex{-1, -1, 0.};
    double deferred_key = -1; // >= 0: not propagated, to queue again with this key
  };

  // ---- sources and pseudo-sources ----

  void start_from_sources()
  {
    const std::vector<bool> repeated = repeated_sources(m_sources);
    for(std::size_t i = 0; i < m_sources.size(); ++i) {
      const Source_point& s = m_sources[i];
      if(repeated[i])
        continue;
      const int index = int(i);
      if(s.vertex >= 0) {
        m_emits_when_taken[s.vertex] = 1;
        relax(Vertex_update{s.vertex, index, 0.});
      } else {
        emit_face_point_windows(
          m_mesh, s, [&](int u, double d, const Arrival& a) { relax(Vertex_update{u, index, d, a}); },
          [&](int g, const Window_geometry& w) { m_emitted_windows.push_back(New_window{w, g, index}); });
      }
    }
    insert_new_windows_now();
  }

  // A pseudo-source taken from the queue: windows on the edges opposite it (kept in
  // m_emitted_windows until they are clipped into their edges).
  void emit_from_vertex(int v)
  {
    const double sigma = m_distance[v];
    const int source = m_nearest_source[v];
    m_emitted[v] = sigma;
    emit_vertex_windows(
      m_mesh, v, sigma, [&](int u, double d, const Arrival& a) { relax(Vertex_update{u, source, d, a}); },
      [&](int g, const Window_geometry& w) { m_emitted_windows.push_back(New_window{w, g, source}); },
      cone_of(v));
  }

  void relax(const Vertex_update& u)
  {
    if(lowers(u.vertex, u.distance, u.arrival))
      m_mesh.for_each_copy_of_point(u.vertex, [&](int g) { set_distance(g, u); });
  }

  void set_distance(int v, const Vertex_update& u)
  {
    m_distance[v] = u.distance;
    m_nearest_source[v] = u.source;
    if(m_emits_when_taken[v])
      push(u.distance, Queue_item{nullptr, v, 0});
  }

  // ---- the queue ----

  void push(double key, const Queue_item& item)
  {
    if(m_use_heap)
      m_heap.push(key, item);
    else
      m_buckets.push(key, item);
  }

  bool is_stale(double key, const Queue_item& item) const
  {
    if(item.window)
      return item.window->version != item.version || !item.window->queued;
    return key != m_distance[item.vertex] || !(key < m_emitted[item.vertex]);
  }

  // Applies the part [first_*, end_*) of an insertion output: vertex distances, then the queue.
  void apply(const Insertion_output& out, std::size_t first_update, std::size_t end_update, std::size_t first_queued,
             std::size_t end_queued)
  {
    for(std::size_t i = first_update; i < end_update; ++i)
      relax(out.updates[i]);
    for(std::size_t i = first_queued; i < end_queued; ++i)
      push(out.queued[i].key, Queue_item{out.queued[i].window, -1, out.queued[i].version});
  }

  // ---- propagation and insertion, shared by the three forms ----

  // Takes a queued window across the face its rays enter: up to two children on the other
  // edges of the face, and a distance for the apex. Reads the window and the vertex distances
  // only, and writes the window's queued flag (only the thread that took its entry does). The
  // children are trimmed by their edge's end vertices when they are inserted.
  //
  // With buckets, a window keeps its queue entry when it is clipped (`Edge_window_store`), and
  // its end vertices' distances may have dropped since it was queued: if its smallest distance
  // after trimming now lies in a later bucket than those taken (`last_bucket_taken`), it is not
  // propagated but deferred, to be queued again with that key (its only valid entry).
  void propagate(Propagation_output& out, std::size_t last_bucket_taken) const
  {
    out.number_of_children = 0;
    out.apex.vertex = -1;
    out.deferred_key = -1;
    const Edge_window& ew = *out.window;
    const int h = ew.halfedge;
    Window_geometry w = m_windows.in_frame_of(ew, h);
    double key;
    const bool kept = keep_window(w, h, m_distance[m_mesh.source(h)], m_distance[m_mesh.target(h)], key);
    if(kept && !m_use_heap && m_buckets.index_of(key) > last_bucket_taken) {
      out.deferred_key = key;
      return;
    }
    out.window->queued = 0;
    if(!kept)
      return;
    const Halfedge_frame f = m_mesh.frame(h);
    const double crossing = apex_crossing(w, f.apex_x, f.apex_y);
    double p;
    const double via = distance_to_apex(w, crossing, f.apex_x, f.apex_y, p);
    out.apex = Vertex_update{m_mesh.apex(h), ew.source, via, apex_arrival(h, w, p, f.apex_x, f.apex_y)};
    make_children(w, face_crossing(m_mesh, h, f), crossing, crossing, m_min_window_length,
                  [&](int g, const Window_geometry& child, bool) {
                    out.children[out.number_of_children++] = New_window{child, g, ew.source};
                  });
  }

  // Trims a new window by its edge's end vertices and clips it into the store. Writes only the
  // edge's windows, the pool's `slot` and `out`.
  void insert_window(const New_window& n, std::size_t slot, Insertion_output& out)
  {
    const int h = n.halfedge;
    Window_geometry g = n.geometry;
    if(keep_window(g, h, m_distance[m_mesh.source(h)], m_distance[m_mesh.target(h)]))
      m_windows.insert(g, h, n.source, slot, out);
  }

  // ---- sequential MMP and FWP-MMP: each window is clipped into its edge as soon as it is made ----

  void take(const Queue_item& item, std::size_t last_bucket_taken)
  {
    if(item.window) {
      Propagation_output& p = m_propagation_one;
      p.window = item.window;
      propagate(p, last_bucket_taken);
      if(p.deferred_key >= 0) {
        ++m_statistics.windows_deferred;
        push(p.deferred_key, item);
        return;
      }
      ++m_statistics.windows_propagated;
      if(p.apex.vertex >= 0)
        relax(p.apex);
      for(int c = 0; c < p.number_of_children; ++c)
        m_emitted_windows.push_back(p.children[c]);
    } else {
      emit_from_vertex(item.vertex);
    }
    insert_new_windows_now();
    if((++m_items_taken & 1023) == 0)
      note_live_windows(m_windows);
  }

  void insert_new_windows_now()
  {
    Insertion_output& out = m_output_one;
    for(const New_window& n : m_emitted_windows) {
      insert_window(n, m_main_slot, out);
      apply(out, 0, out.updates.size(), 0, out.queued.size());
      m_statistics.windows_created += out.created;
      out.updates.clear();
      out.queued.clear();
      out.created = 0;
    }
    m_emitted_windows.clear();
  }

  // How far the run is, for the caller's callback: the share of the vertices whose distance is
  // behind the front (the key of the windows taken last), which are settled, or of the max
  // distance. (A window reaches vertices far ahead of the front, so that the vertices reached
  // would say too much; the count reads every vertex, but only at a report, a few times a second.)
  double done_fraction(double front) const
  {
    const auto settled = std::count_if(m_distance.begin(), m_distance.end(), [front](double d) { return d <= front; });
    const double by_vertices = double(settled) / double(std::max<std::size_t>(1, m_distance.size()));
    return m_max_distance < infinity() && m_max_distance > 0 ? std::max(by_vertices, front / m_max_distance)
                                                             : by_vertices;
  }

  void run_with_heap()
  {
    while(!m_heap.empty()) {
      const auto top = m_heap.top();
      m_heap.pop();
      if(is_stale(top.first, top.second))
        continue;
      if(top.first > m_max_distance)
        break;
      take(top.second, std::size_t(-1));
      report_progress_often([&] { return done_fraction(top.first); });
    }
  }

  void run_with_buckets()
  {
    std::vector<Bucket_queue<Queue_item>::Entry>& bucket = m_bucket_entries;
    for(;;) {
      m_buckets.pop_lowest(bucket);
      if(bucket.empty())
        return;
      const std::size_t taken = m_buckets.index_of_lowest();
      for(const auto& e : bucket)
        if(!is_stale(e.first, e.second) && e.first <= m_max_distance) {
          take(e.second, taken);
          report_progress_often([&] { return done_fraction(e.first); });
        }
    }
  }

  // ---- PMMP: rounds of five steps (thesis chapter 3.3), each in a fixed order ----

  // Chunks of the parallel steps: a propagation is tiny and taking a chunk costs a transfer of
  // the loop's shared state between cores; an edge's clipping is larger and uneven.
  static constexpr std::size_t propagation_grain = 128;
  static constexpr std::size_t clipping_grain = 4;

  // The part of a thread's insertion output that one active edge wrote.
  struct Edge_result
  {
    std::size_t slot;
    std::size_t first_queued, end_queued, first_update, end_update, created;
  };
  struct Active_edge
  {
    int edge;
    int first_child, last_child; // the new windows filed under it, linked through m_round.child_next
  };
  // The scratch space of a round, kept from round to round.
  struct Round
  {
    std::vector<Propagation_output> selected;
    std::vector<int> edge_batch; // per reference half-edge: its index among the active edges, or -1
    std::vector<Active_edge> active_edges;
    std::vector<int> child_next;
    std::vector<Insertion_output> thread_outputs; // per pool slot
    std::vector<Edge_result> edge_results;        // per active edge
    std::size_t last_bucket_taken = 0;            // the highest bucket the selection took from
  };

  void run_parallel()
  {
    m_round.edge_batch.assign(m_mesh.number_of_halfedges(), -1);
    for(;;) {
      auto start = Clock::now();
      const std::size_t n = select_windows();
      m_statistics.seconds_selection += seconds_since(start);
      if(n == 0 && m_emitted_windows.empty())
        return;
      report_progress([&] { return done_fraction(m_front); });
      start = Clock::now();
      propagate_selected(n);
      m_statistics.seconds_propagation += seconds_since(start);
      start = Clock::now();
      organize_by_edge(n);
      m_statistics.seconds_organization += seconds_since(start);
      start = Clock::now();
      clip_by_edge(n);
      m_statistics.seconds_clipping += seconds_since(start);
      start = Clock::now();
      apply_by_edge();
      m_statistics.seconds_pushing += seconds_since(start);
    }
  }

  // 1. Selection: up to K window entries from the lowest buckets (stale ones are recognized by
  // the propagation tasks, in parallel); pseudo-sources emit at once. Returns how many.
  std::size_t select_windows()
  {
    std::vector<Bucket_queue<Queue_item>::Entry>& bucket = m_bucket_entries;
    std::vector<Propagation_output>& selected = m_round.selected;
    std::size_t n = 0;
    m_round.last_bucket_taken = 0;
    while(n < m_batch_size) {
      m_buckets.pop_lowest(bucket, m_batch_size - n);
      if(bucket.empty())
        break;
      m_round.last_bucket_taken = std::max(m_round.last_bucket_taken, m_buckets.index_of_lowest());
      for(const auto& e : bucket) {
        if(e.first > m_max_distance)
          continue;
        if(!e.second.window) {
          if(!is_stale(e.first, e.second))
            emit_from_vertex(e.second.vertex);
          // (the vertices a round takes may sweep much of the mesh before its first window)
          report_progress_often([&] { return done_fraction(m_front); });
          continue;
        }
        if(n == 0) // the round's lowest window key: every distance below it is settled
          m_front = std::max(m_front, e.first);
        if(selected.size() <= n)
          selected.resize(n + 1);
        selected[n].window = e.second.window;
        selected[n++].version = e.second.version;
      }
    }
    return n;
  }

  // 2. Propagation, in parallel: each task reads its window and the vertex distances, and
  // writes only its own output and its window's queued flag (each queue entry names one
  // version of a window, and a window has at most one valid entry).
  void propagate_selected(std::size_t n)
  {
    for_each_index(m_parallel, n, propagation_grain, [this](std::size_t i, std::size_t) {
      Propagation_output& p = m_round.selected[i];
      if(p.window->version != p.version || !p.window->queued) {
        p.number_of_children = 0;
        p.apex.vertex = -1;
        p.deferred_key = -1;
        p.window = nullptr;
        return;
      }
      propagate(p, m_round.last_bucket_taken);
    });
  }

  // The new window of number `id`: children of selected window i are numbered 2i and 2i+1,
  // windows emitted by pseudo-sources follow.
  const New_window& new_window(std::size_t n, int id) const
  {
    return std::size_t(id) < 2 * n ? m_round.selected[std::size_t(id) / 2].children[id % 2]
                                   : m_emitted_windows[std::size_t(id) - 2 * n];
  }

  // 3. Organization: deferred windows queued again, apex distances, then the new windows
  // linked by edge in a fixed order.
  void organize_by_edge(std::size_t n)
  {
    if(m_round.child_next.size() < 2 * n + m_emitted_windows.size())
      m_round.child_next.resize(2 * n + m_emitted_windows.size());
    for(std::size_t i = 0; i < n; ++i) {
      const Propagation_output& p = m_round.selected[i];
      if(!p.window)
        continue;
      if(p.deferred_key >= 0) {
        ++m_statistics.windows_deferred;
        push(p.deferred_key, Queue_item{p.window, -1, p.version});
        continue;
      }
      ++m_statistics.windows_propagated;
      if(p.apex.vertex >= 0)
        relax(p.apex);
      for(int c = 0; c < p.number_of_children; ++c)
        file_by_edge(p.children[c].halfedge, int(2 * i) + c);
    }
    for(std::size_t i = 0; i < m_emitted_windows.size(); ++i)
      file_by_edge(m_emitted_windows[i].halfedge, int(2 * n + i));
  }

  // Appends new window `id` to the list of its edge, making the edge active if it is not.
  void file_by_edge(int halfedge, int id)
  {
    const int e = m_windows.reference(halfedge);
    int& batch = m_round.edge_batch[std::size_t(e)];
    if(batch < 0) {
      batch = int(m_round.active_edges.size());
      m_round.active_edges.push_back(Active_edge{e, id, id});
    } else {
      Active_edge& a = m_round.active_edges[std::size_t(batch)];
      m_round.child_next[std::size_t(a.last_child)] = id;
      a.last_child = id;
    }
    m_round.child_next[std::size_t(id)] = -1;
  }

  // 4. Clipping, in parallel: one task per edge; it reads the vertex distances and writes only
  // its edge's windows, and its thread's pool slot and output.
  void clip_by_edge(std::size_t n)
  {
    const std::size_t edges = m_round.active_edges.size();
    if(m_round.edge_results.size() < edges)
      m_round.edge_results.resize(edges);
    m_round.thread_outputs.resize(m_windows.number_of_slots());
    for_each_index(m_parallel, edges, clipping_grain, [this, n](std::size_t j, std::size_t slot) {
      Insertion_output& out = m_round.thread_outputs[slot];
      Edge_result r{slot, out.queued.size(), 0, out.updates.size(), 0, out.created};
      for(int id = m_round.active_edges[j].first_child; id >= 0; id = m_round.child_next[std::size_t(id)])
        insert_window(new_window(n, id), slot, out);
      r.end_queued = out.queued.size();
      r.end_update = out.updates.size();
      r.created = out.created - r.created;
      m_round.edge_results[j] = r;
    });
  }

  // 5. Pushing: the vertex distances and the queue, edge by edge in filing order.
  void apply_by_edge()
  {
    for(std::size_t j = 0; j < m_round.active_edges.size(); ++j) {
      const Edge_result& r = m_round.edge_results[j];
      apply(m_round.thread_outputs[r.slot], r.first_update, r.end_update, r.first_queued, r.end_queued);
      m_statistics.windows_created += r.created;
      m_round.edge_batch[std::size_t(m_round.active_edges[j].edge)] = -1;
    }
    for(Insertion_output& out : m_round.thread_outputs) {
      out.queued.clear();
      out.updates.clear();
      out.created = 0;
    }
    m_round.active_edges.clear();
    m_emitted_windows.clear();
    note_live_windows(m_windows);
  }

  std::vector<std::uint8_t> m_emits_when_taken; // pseudo-source or source
  Edge_window_store m_windows;
  std::size_t m_main_slot = 0; // the pool slot of the thread running run()
  double m_front = 0;          // PMMP: the lowest window key of the last round (for the callback)
  const bool m_use_heap;       // MMP; otherwise buckets
  Min_heap<Queue_item> m_heap;
  Bucket_queue<Queue_item> m_buckets;
  std::vector<Bucket_queue<Queue_item>::Entry> m_bucket_entries;
  std::vector<New_window> m_emitted_windows; // by pseudo-sources (and sequentially, children), to insert
  Insertion_output m_output_one;
  Propagation_output m_propagation_one;
  std::size_t m_items_taken = 0;
  Round m_round; // PMMP
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_MMP_SOLVER_H
