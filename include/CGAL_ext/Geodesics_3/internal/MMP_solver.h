// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_MMP_SOLVER_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_MMP_SOLVER_H

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>
#include <CGAL_ext/Geodesics_3/internal/Mesh_cache.h>
#include <CGAL_ext/Geodesics_3/internal/Sources.h>
#include <CGAL_ext/Geodesics_3/internal/Parallel_loop.h>
#include <CGAL_ext/Geodesics_3/internal/Vertex_queue.h>
#include <CGAL_ext/Geodesics_3/internal/Window.h>

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

/// A window kept on an edge. The geometry is in the frame of the edge's reference half-edge
/// (`MMP_solver::reference()`), mirrored if need be so that the pseudo-source lies below the
/// axis: distances along the edge do not depend on the side.
struct alignas(64) Edge_window // one cache line
{
  Window_geometry geometry;
  int halfedge;          // the half-edge whose face the window's rays enter
  int source;            // the source its paths start from (index in the order sources were added)
  std::uint32_t version; // changes whenever the window changes or dies: older queue entries are stale
  std::uint8_t queued;   // waits to be propagated
  Edge_window* next;     // the next window of the edge (sorted by b0), or of the pool's free list
};

/// A window made by a propagation or a pseudo-source, before it is clipped into its edge; the
/// geometry is in the frame of `halfedge`.
struct New_window
{
  Window_geometry geometry;
  int halfedge;
  int source;
};

/// A distance found for a vertex, applied after a parallel step.
struct Vertex_update
{
  int vertex;
  int source;
  double distance;
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
/// - PMMP (`set_parallel()`): up to K windows are selected from the lowest buckets, propagated
///   in parallel, filed by edge, and clipped in parallel, one task per edge; the queue and the
///   vertex distances are updated sequentially, in a fixed order, so that every number of
///   threads gives the same windows.
///
/// Each edge keeps a partition of the parts of it reached so far: windows that do not overlap,
/// from either side (a path arriving from one side that is beaten by one from the other side
/// cannot be continued as a shortest path). A new window is clipped against the stored windows
/// it overlaps, both may lose parts, and a window losing the middle of its interval is split.
/// A window that has been propagated may still be clipped; its children stay and are clipped
/// in turn. Pseudo-sources (saddle and border vertices, and the sources) are queue items too:
/// when taken they emit windows onto the edges opposite them. Windows are also trimmed by the
/// distances of the end vertices of their edge (the exact filter shared with VTP).
///
/// After the run, the windows on the edges give the distance at any surface point and the
/// shortest path back to the nearest source (`Geodesic_path_tracer.h`).
class MMP_solver
{
public:
  enum Queue_kind
  {
    BINARY_HEAP,
    BUCKETS
  };

  explicit MMP_solver(const Mesh_cache& mesh)
    : m_mesh(mesh)
    , m_distance(mesh.number_of_vertices, infinity())
    , m_emitted(mesh.number_of_vertices, infinity())
    , m_nearest_source(mesh.number_of_vertices, -1)
    , m_emits(mesh.is_pseudo_source)
    , m_edge(mesh.number_of_halfedges(), nullptr)
    , m_buckets(mesh.mean_edge_length)
    , m_edge_batch(mesh.number_of_halfedges(), -1)
  {
    m_min_window_length = 1e-10 * mesh.mean_edge_length;
  }

  MMP_solver(const MMP_solver&) = delete;
  MMP_solver& operator=(const MMP_solver&) = delete;

  static double infinity() { return std::numeric_limits<double>::infinity(); }

  /// Adds a source; its index is the number of sources added before it. A source equal to an
  /// earlier one is kept in the count but starts nothing.
  void add_source(const Source_point& s)
  {
    const Source_point n = normalized_source(m_mesh, s);
    m_sources.push_back(n);
  }
  const std::vector<Source_point>& sources() const { return m_sources; }

  void set_max_distance(double d)
  {
    if(!(d >= 0))
      throw Geodesic_error("max distance must be non-negative, got " + std::to_string(d));
    m_max_distance = d;
  }
  double max_distance() const { return m_max_distance; }

  void set_queue(Queue_kind q) { m_queue_kind = q; }

  /// PMMP; the caller runs `run()` inside the `tbb::task_arena` that bounds the threads.
  void set_parallel()
  {
#ifndef CGAL_LINKED_WITH_TBB
    throw Geodesic_error("parallel propagation needs TBB (CGAL_LINKED_WITH_TBB is not defined)");
#endif
    m_parallel = true;
    m_queue_kind = BUCKETS;
  }

  /// PMMP: how many windows are selected together at most (the thesis's K).
  void set_batch_size(std::size_t k)
  {
    if(k == 0)
      throw Geodesic_error("batch size must be positive");
    m_batch_size = k;
  }

  void run()
  {
    const auto start = std::chrono::steady_clock::now();
    if(m_sources.empty())
      throw Geodesic_error("no source was given");
    m_main_slot = use_one_slot_per_thread(m_pool, m_parallel);
    start_from_sources();
    if(m_parallel)
      Thread_team::run(true, [this](Thread_team& team) { run_parallel(team); });
    else if(m_queue_kind == BINARY_HEAP)
      run_with_heap();
    else
      run_with_buckets();
    for(std::size_t v = 0; v < m_distance.size(); ++v)
      if(m_distance[v] > m_max_distance) {
        m_distance[v] = infinity();
        m_nearest_source[v] = -1;
      }
    note_live_windows();
    m_statistics.vertices = m_mesh.number_of_vertices;
    m_statistics.faces = m_mesh.number_of_faces;
    m_statistics.windows_stored = m_pool.live();
    m_statistics.peak_windows = m_peak_windows;
    m_statistics.peak_window_bytes = m_pool.bytes();
    m_statistics.stored_window_bytes = m_pool.bytes() + m_edge.size() * sizeof(Edge_window*);
    m_statistics.seconds_solve = seconds_since(start);
  }

  // ---- what the queries read (all const, and never written after run()) ----

  const Mesh_cache& mesh() const { return m_mesh; }
  const std::vector<double>& distances() const { return m_distance; }
  /// The nearest source of each vertex, -1 where none reaches.
  const std::vector<int>& nearest_sources() const { return m_nearest_source; }
  const Geodesic_statistics& statistics() const { return m_statistics; }

  /// The half-edge of an edge whose frame its windows are stored in.
  int reference(int h) const
  {
    const int o = m_mesh.opposite(h);
    return (o < 0 || h < o) ? h : o;
  }
  /// The windows of the edge of half-edge h, sorted along the reference half-edge.
  const Edge_window* windows_of_edge(int h) const { return m_edge[reference(h)]; }

  /// A stored window in the frame of half-edge h of its edge.
  Window_geometry in_frame_of(const Edge_window& w, int h) const
  {
    return h == reference(h) ? w.geometry : mirrored(w.geometry, m_mesh.frame[h].length);
  }

private:
  static double seconds_since(std::chrono::steady_clock::time_point t)
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
  }

  // The same window seen from the other half-edge of its edge; the pseudo-source stays below
  // the axis (the frame turns by a half turn, and the window's side with it).
  static Window_geometry mirrored(const Window_geometry& w, double length)
  {
    Window_geometry m = w;
    m.b0 = length - w.b1;
    m.b1 = length - w.b0;
    m.sx = length - w.sx;
    return m;
  }

  // What clipping new windows gives, applied to the queue and the vertices afterwards (at once
  // when sequential, after the parallel step in PMMP). One per thread: in PMMP each edge's
  // share is a range of its thread's output (`Edge_result`), applied in the edges' order.
  struct alignas(64) Edge_output // one cache line or more each: threads write their own often
  {
    std::vector<std::pair<double, Queue_item>> pushes;
    std::vector<Vertex_update> updates;
    std::vector<std::pair<double, double>> pieces, kept; // scratch
    std::size_t created = 0;
  };
  struct Edge_result
  {
    std::size_t slot;
    std::size_t first_push, end_push, first_update, end_update, created;
  };

  // What propagating one window gives.
  struct Propagation_output
  {
    Edge_window* window = nullptr;
    std::uint32_t version = 0; // PMMP: of the queue entry
    New_window children[2];
    int number_of_children = 0;
    Vertex_update apex{-1, -1, 0.};
  };

  // ---- sources and pseudo-sources ----

  void start_from_sources()
  {
    for(std::size_t i = 0; i < m_sources.size(); ++i) {
      const Source_point& s = m_sources[i];
      if(std::find_if(m_sources.begin(), m_sources.begin() + i, [&](const Source_point& t) {
           return t.vertex == s.vertex && t.face == s.face && t.barycentric == s.barycentric;
         }) != m_sources.begin() + i)
        continue; // a duplicate: the first one is the nearest
      const int index = int(i);
      if(s.vertex >= 0) {
        m_emits[s.vertex] = 1;
        relax(Vertex_update{s.vertex, index, 0.});
      } else {
        emit_face_point_windows(
          m_mesh, s, [&](int u, double d) { relax(Vertex_update{u, index, d}); },
          [&](int g, const Window_geometry& w) { m_new.push_back(New_window{w, g, index}); });
      }
    }
    insert_new_windows_now();
  }

  // A pseudo-source taken from the queue: windows on the edges opposite it (kept in m_new).
  void emit_from_vertex(int v)
  {
    const double sigma = m_distance[v];
    const int source = m_nearest_source[v];
    m_emitted[v] = sigma;
    emit_vertex_windows(
      m_mesh, v, sigma, [&](int u, double d) { relax(Vertex_update{u, source, d}); },
      [&](int g, const Window_geometry& w) { m_new.push_back(New_window{w, g, source}); });
  }

  void relax(const Vertex_update& u)
  {
    if(u.distance < m_distance[u.vertex]) {
      m_distance[u.vertex] = u.distance;
      m_nearest_source[u.vertex] = u.source;
      if(m_emits[u.vertex])
        push(u.distance, Queue_item{nullptr, u.vertex, 0});
    }
  }

  // ---- the queue ----

  void push(double key, const Queue_item& item)
  {
    if(m_queue_kind == BINARY_HEAP)
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

  void apply(const Edge_output& out, const Edge_result& r)
  {
    for(std::size_t i = r.first_update; i < r.end_update; ++i)
      relax(out.updates[i]);
    for(std::size_t i = r.first_push; i < r.end_push; ++i)
      push(out.pushes[i].first, out.pushes[i].second);
    m_statistics.windows_created += r.created;
  }
  void apply(Edge_output& out)
  {
    apply(out, Edge_result{0, 0, out.pushes.size(), 0, out.updates.size(), out.created});
    out.updates.clear();
    out.pushes.clear();
    out.created = 0;
  }

  // ---- sequential MMP and FWP-MMP: each window is clipped into its edge as soon as it is made ----

  void take(const Queue_item& item)
  {
    if(item.window) {
      ++m_statistics.windows_propagated;
      Propagation_output& p = m_propagation_one;
      p.window = item.window;
      item.window->queued = 0;
      propagate(p);
      if(p.apex.vertex >= 0)
        relax(p.apex);
      for(int c = 0; c < p.number_of_children; ++c)
        m_new.push_back(p.children[c]);
    } else {
      emit_from_vertex(item.vertex);
    }
    insert_new_windows_now();
    if((++m_taken & 1023) == 0)
      note_live_windows();
  }

  void insert_new_windows_now()
  {
    for(const New_window& n : m_new) {
      insert_window(n, m_main_slot, m_output_one);
      apply(m_output_one);
    }
    m_new.clear();
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
      take(top.second);
    }
  }

  void run_with_buckets()
  {
    std::vector<Bucket_queue<Queue_item>::Entry>& bucket = m_bucket_entries;
    for(;;) {
      m_buckets.pop_lowest(bucket);
      if(bucket.empty())
        return;
      for(const auto& e : bucket)
        if(!is_stale(e.first, e.second) && e.first <= m_max_distance)
          take(e.second);
    }
  }

  // ---- PMMP ----

  void run_parallel(Thread_team& team)
  {
    std::vector<Bucket_queue<Queue_item>::Entry>& bucket = m_bucket_entries;
    std::vector<Propagation_output>& selected = m_selected;
    for(;;) {
      // 1. Selection: up to K window entries from the lowest buckets (stale ones are recognized
      // by the propagation tasks, in parallel); pseudo-sources emit at once.
      auto start = std::chrono::steady_clock::now();
      std::size_t n = 0;
      while(n < m_batch_size) {
        m_buckets.pop_lowest(bucket, m_batch_size - n);
        if(bucket.empty())
          break;
        for(const auto& e : bucket) {
          if(e.first > m_max_distance)
            continue;
          if(!e.second.window) {
            if(!is_stale(e.first, e.second))
              emit_from_vertex(e.second.vertex);
            continue;
          }
          if(selected.size() <= n)
            selected.resize(n + 1);
          selected[n].window = e.second.window;
          selected[n++].version = e.second.version;
        }
      }
      m_statistics.seconds_selection += seconds_since(start);
      if(n == 0 && m_new.empty())
        return;

      // 2. Propagation, in parallel: each task reads its window and the vertex distances, and
      // writes only its own output and its window's queued flag (each queue entry names one
      // version of a window, and only the window's current version is ever queued once).
      start = std::chrono::steady_clock::now();
      // Chunks of 128: a propagation takes ~40 ns, and taking a chunk moves the team's ticket
      // and count between the cores (~0.1-0.2 us each here); 32 cost 20 % of the step at T=2.
      team.for_each_index(n, 128, [&](std::size_t i, std::size_t) {
        Propagation_output& p = selected[i];
        if(p.window->version != p.version || !p.window->queued) {
          p.number_of_children = 0;
          p.apex.vertex = -1;
          p.window = nullptr;
          return;
        }
        p.window->queued = 0;
        propagate(p);
      });
      m_statistics.seconds_propagation += seconds_since(start);

      // 3. Organization: apex distances, then the new windows linked by edge in a fixed order
      // (children of selected window i are numbered 2i and 2i+1, emitted windows follow).
      start = std::chrono::steady_clock::now();
      if(m_child_next.size() < 2 * n + m_new.size())
        m_child_next.resize(2 * n + m_new.size());
      for(std::size_t i = 0; i < n; ++i) {
        const Propagation_output& p = selected[i];
        if(!p.window)
          continue;
        ++m_statistics.windows_propagated;
        if(p.apex.vertex >= 0)
          relax(p.apex);
        for(int c = 0; c < p.number_of_children; ++c)
          file_by_edge(p.children[c].halfedge, int(2 * i) + c);
      }
      for(std::size_t i = 0; i < m_new.size(); ++i)
        file_by_edge(m_new[i].halfedge, int(2 * n + i));
      auto child = [&](int id) -> const New_window& {
        return std::size_t(id) < 2 * n ? selected[std::size_t(id) / 2].children[id % 2] : m_new[std::size_t(id) - 2 * n];
      };
      m_statistics.seconds_organization += seconds_since(start);

      // 4. Clipping, in parallel: one task per edge; it reads the vertex distances and writes
      // only its edge's windows, and its thread's pool slot and output.
      start = std::chrono::steady_clock::now();
      const std::size_t edges = m_active_edges.size();
      if(m_edge_results.size() < edges)
        m_edge_results.resize(edges);
      m_thread_outputs.resize(m_pool.number_of_slots());
      team.for_each_index(edges, 4, [&](std::size_t j, std::size_t slot) {
        Edge_output& out = m_thread_outputs[slot];
        Edge_result r{slot, out.pushes.size(), 0, out.updates.size(), 0, out.created};
        for(int id = m_active_edges[j].first_child; id >= 0; id = m_child_next[std::size_t(id)])
          insert_window(child(id), slot, out);
        r.end_push = out.pushes.size();
        r.end_update = out.updates.size();
        r.created = out.created - r.created;
        m_edge_results[j] = r;
      });
      m_statistics.seconds_clipping += seconds_since(start);

      // 5. Pushing: the queue and the vertex distances, edge by edge in filing order.
      start = std::chrono::steady_clock::now();
      for(std::size_t j = 0; j < edges; ++j) {
        apply(m_thread_outputs[m_edge_results[j].slot], m_edge_results[j]);
        m_edge_batch[std::size_t(m_active_edges[j].edge)] = -1;
      }
      for(Edge_output& out : m_thread_outputs) {
        out.pushes.clear();
        out.updates.clear();
        out.created = 0;
      }
      m_active_edges.clear();
      m_new.clear();
      note_live_windows();
      m_statistics.seconds_pushing += seconds_since(start);
    }
  }

  // Appends new window `id` to the list of its edge, making the edge active if it is not.
  void file_by_edge(int halfedge, int id)
  {
    const int e = reference(halfedge);
    int& batch = m_edge_batch[std::size_t(e)];
    if(batch < 0) {
      batch = int(m_active_edges.size());
      m_active_edges.push_back(Active_edge{e, id, id});
    } else {
      Active_edge& a = m_active_edges[std::size_t(batch)];
      m_child_next[std::size_t(a.last_child)] = id;
      a.last_child = id;
    }
    m_child_next[std::size_t(id)] = -1;
  }

  // ---- propagation and clipping, shared by the three forms ----

  // Trims a window (in the frame of h) by the distances of the end vertices of h's edge and by
  // the max distance: false if nothing is left.
  bool keep_window(Window_geometry& w, int h, double d_from, double d_to) const
  {
    double key;
    return trim_by_edge_vertices(w, m_mesh.frame[h].length, d_from, d_to, key) && key <= m_max_distance;
  }

  // Takes a window across the face its rays enter: up to two children on the other edges of
  // the face, and a distance for the apex. Reads the window and the vertex distances only.
  // The children are trimmed by their edge's end vertices when they are clipped into it.
  void propagate(Propagation_output& out) const
  {
    out.number_of_children = 0;
    out.apex.vertex = -1;
    const Edge_window& ew = *out.window;
    const int h = ew.halfedge;
    Window_geometry w = in_frame_of(ew, h);
    const double d_from = m_distance[m_mesh.source(h)], d_to = m_distance[m_mesh.target(h)];
    if(!keep_window(w, h, d_from, d_to))
      return;
    const Halfedge_frame& f = m_mesh.frame[h];
    const double crossing = apex_crossing(w, f.apex_x, f.apex_y);
    double p;
    const double via = distance_to_apex(w, crossing, f.apex_x, f.apex_y, p);
    out.apex = Vertex_update{m_mesh.apex(h), ew.source, via};
    Child_edge to_ac, to_cb;
    child_edges(m_mesh, h, to_ac, to_cb);
    const int g_ac = m_mesh.opposite(Mesh_cache::prev(h)); // runs from A to C
    const int g_cb = m_mesh.opposite(Mesh_cache::next(h)); // runs from C to B
    Window_geometry child;
    if(g_ac >= 0) {
      const double hi = std::min(w.b1, crossing);
      if(hi > w.b0 && make_child(w, w.b0, hi, to_ac, m_min_window_length, child))
        out.children[out.number_of_children++] = New_window{child, g_ac, ew.source};
    }
    if(g_cb >= 0) {
      const double lo = std::max(w.b0, crossing);
      if(w.b1 > lo && make_child(w, lo, w.b1, to_cb, m_min_window_length, child))
        out.children[out.number_of_children++] = New_window{child, g_cb, ew.source};
    }
  }

  // Removes [a, b] from a sorted list of disjoint intervals.
  static void subtract(std::vector<std::pair<double, double>>& intervals, double a, double b)
  {
    std::size_t n = intervals.size();
    for(std::size_t i = 0; i < n; ++i) {
      auto& iv = intervals[i];
      if(iv.second <= a || iv.first >= b)
        continue;
      if(iv.first < a && iv.second > b) { // the middle goes: split
        intervals.insert(intervals.begin() + i + 1, std::make_pair(b, iv.second));
        intervals[i].second = a;
        return;
      }
      if(iv.first < a)
        iv.second = a;
      else if(iv.second > b)
        iv.first = b;
      else
        iv.second = iv.first; // all of it
    }
  }

  void drop_short(std::vector<std::pair<double, double>>& intervals) const
  {
    intervals.erase(std::remove_if(intervals.begin(), intervals.end(),
                                   [&](const std::pair<double, double>& iv) {
                                     return !(iv.second - iv.first > m_min_window_length);
                                   }),
                    intervals.end());
  }

  Edge_window* allocate(std::size_t slot, const Edge_window& model)
  {
    Edge_window* p = m_pool.allocate(slot);
    const std::uint32_t version = p->version + 1; // never that of an entry still queued for it
    *p = model;
    p->version = version;
    return p;
  }

  // Clips a new window into the windows of its edge: both lose the parts where the other is
  // shorter (a stored window keeps a tie), pieces shorter than the minimum length vanish.
  // Writes only the edge's windows, the pool's `slot` and `out`.
  void insert_window(const New_window& n, std::size_t slot, Edge_output& out)
  {
    const int h = n.halfedge;
    const int e = reference(h);
    const double length = m_mesh.frame[h].length;
    Window_geometry g = n.geometry;
    if(!keep_window(g, h, m_distance[m_mesh.source(h)], m_distance[m_mesh.target(h)]))
      return;
    const Window_geometry c = h == e ? g : mirrored(g, length);

    std::vector<std::pair<double, double>>& pieces = out.pieces; // what the new window keeps
    std::vector<std::pair<double, double>>& kept = out.kept;     // what a stored window keeps
    pieces.assign(1, std::make_pair(c.b0, c.b1));
    Edge_window* before = nullptr; // the stored window before the current one
    Edge_window* w = m_edge[e];
    double cut[4];
    int winner[3];
    while(w && w->geometry.b1 <= c.b0) {
      before = w;
      w = w->next;
    }
    Edge_window* const last_before_overlap = before; // not changed below: the second pass starts here
    while(w && !pieces.empty()) {
      Window_geometry& s = w->geometry;
      if(s.b0 >= c.b1)
        break;
      const int m = compare_on_overlap(s, c, std::max(s.b0, c.b0), std::min(s.b1, c.b1), cut, winner);
      kept.assign(1, std::make_pair(s.b0, s.b1));
      bool changed = false;
      for(int i = 0; i + 1 < m; ++i) {
        if(winner[i] == 0)
          subtract(pieces, cut[i], cut[i + 1]);
        else {
          subtract(kept, cut[i], cut[i + 1]);
          changed = true;
        }
      }
      Edge_window* after = w->next;
      if(!changed) {
        before = w;
        w = after;
        continue;
      }
      drop_short(kept);
      if(kept.empty()) { // the stored window is beaten everywhere
        (before ? before->next : m_edge[e]) = after;
        ++w->version;
        m_pool.release(slot, w);
        w = after;
        continue;
      }
      // The stored window keeps one piece or more, in place.
      ++w->version;
      s.b0 = kept[0].first;
      s.b1 = kept[0].second;
      if(w->queued)
        out.pushes.emplace_back(window_key(s), Queue_item{w, -1, w->version});
      Edge_window* last = w;
      for(std::size_t i = 1; i < kept.size(); ++i) {
        Edge_window* p = allocate(slot, *w);
        p->geometry.b0 = kept[i].first;
        p->geometry.b1 = kept[i].second;
        p->next = last->next;
        last->next = p;
        last = p;
        ++out.created;
        if(p->queued)
          out.pushes.emplace_back(window_key(p->geometry), Queue_item{p, -1, p->version});
      }
      before = last;
      w = after;
    }
    drop_short(pieces);
    if(pieces.empty())
      return;

    // The new window's pieces fill gaps between stored windows: link each where it belongs.
    before = last_before_overlap;
    w = before ? before->next : m_edge[e];
    for(const auto& iv : pieces) {
      while(w && w->geometry.b0 < iv.first) {
        before = w;
        w = w->next;
      }
      Edge_window model;
      model.geometry = c;
      model.geometry.b0 = iv.first;
      model.geometry.b1 = iv.second;
      model.halfedge = h;
      model.source = n.source;
      model.queued = 1;
      Edge_window* p = allocate(slot, model);
      p->next = w;
      (before ? before->next : m_edge[e]) = p;
      before = p;
      ++out.created;
      out.pushes.emplace_back(window_key(p->geometry), Queue_item{p, -1, p->version});
      // A piece reaching an end of the edge gives that vertex a distance.
      if(iv.first <= 0)
        out.updates.push_back(Vertex_update{m_mesh.source(e), n.source, distance_at(c, 0.)});
      if(iv.second >= length)
        out.updates.push_back(Vertex_update{m_mesh.target(e), n.source, distance_at(c, length)});
    }
  }

  void note_live_windows() { m_peak_windows = std::max(m_peak_windows, m_pool.live()); }

  const Mesh_cache& m_mesh;
  std::vector<double> m_distance;
  std::vector<double> m_emitted; // sigma of the last windows a pseudo-source emitted
  std::vector<int> m_nearest_source;
  std::vector<std::uint8_t> m_emits; // pseudo-source or source
  std::vector<Edge_window*> m_edge;  // the windows of each edge, at its reference half-edge
  std::vector<Source_point> m_sources;
  Object_pool<Edge_window> m_pool;
  std::size_t m_main_slot = 0;
  Queue_kind m_queue_kind = BUCKETS;
  Min_heap<Queue_item> m_heap;
  Bucket_queue<Queue_item> m_buckets;
  std::vector<Bucket_queue<Queue_item>::Entry> m_bucket_entries;
  std::vector<New_window> m_new; // windows emitted by pseudo-sources, waiting to be clipped
  Edge_output m_output_one;
  Propagation_output m_propagation_one;
  // PMMP
  std::vector<Propagation_output> m_selected;
  std::vector<int> m_edge_batch; // per reference half-edge: its index among the active edges, or -1
  struct Active_edge
  {
    int edge;
    int first_child, last_child; // the new windows filed under it, linked through m_child_next
  };
  std::vector<Active_edge> m_active_edges;
  std::vector<int> m_child_next;
  std::vector<Edge_output> m_thread_outputs; // per pool slot
  std::vector<Edge_result> m_edge_results;   // per active edge
  std::size_t m_batch_size = 1024;
  bool m_parallel = false;
  double m_max_distance = infinity();
  double m_min_window_length = 0;
  std::size_t m_peak_windows = 0;
  std::size_t m_taken = 0;
  Geodesic_statistics m_statistics;
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_MMP_SOLVER_H
