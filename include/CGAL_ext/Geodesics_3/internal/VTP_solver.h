// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_VTP_SOLVER_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_VTP_SOLVER_H

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>
#include <CGAL_ext/Geodesics_3/internal/Mesh_cache.h>
#include <CGAL_ext/Geodesics_3/internal/Window.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <sstream>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// A source in the cache's indices: a vertex, or a point of a face given by barycentric
/// coordinates in the order of the face's corners.
struct Source_point
{
  int vertex = -1;
  int face = -1;
  std::array<double, 3> barycentric{{0., 0., 0.}};
};

/// Checks a face-point source and turns one that sits on a corner into a vertex source.
inline Source_point normalized_source(const Mesh_cache& m, Source_point s)
{
  if(s.vertex >= 0) {
    if(std::size_t(s.vertex) >= m.number_of_vertices)
      throw Geodesic_error("source vertex " + std::to_string(s.vertex) + " is out of range (the mesh has " +
                           std::to_string(m.number_of_vertices) + " vertices)");
    return s;
  }
  if(s.face < 0 || std::size_t(s.face) >= m.number_of_faces)
    throw Geodesic_error("source face " + std::to_string(s.face) + " is out of range (the mesh has " +
                         std::to_string(m.number_of_faces) + " faces)");
  const auto& b = s.barycentric;
  const double sum = b[0] + b[1] + b[2];
  if(!std::isfinite(sum) || std::abs(sum - 1.) > 1e-9 || b[0] < -1e-12 || b[1] < -1e-12 || b[2] < -1e-12) {
    std::ostringstream msg;
    msg.precision(17);
    msg << "barycentric coordinates (" << b[0] << ", " << b[1] << ", " << b[2] << ") of the source in face "
        << s.face << " must be non-negative and sum to 1";
    throw Geodesic_error(msg.str());
  }
  // Snap coordinates that are zero up to round-off, so that a point on an edge is treated as such.
  std::array<double, 3> snapped = b;
  double snapped_sum = 0;
  for(double& c : snapped) {
    if(c < 1e-12)
      c = 0;
    snapped_sum += c;
  }
  for(int k = 0; k < 3; ++k) {
    s.barycentric[k] = snapped[k] / snapped_sum;
    if(s.barycentric[k] >= 1.) {
      Source_point v;
      v.vertex = m.source(3 * s.face + k);
      return v;
    }
  }
  return s;
}

/// Exact single- or multi-source geodesic distances by vertex-oriented triangle propagation
/// (VTP, thesis chapter 4.1), sequential.
///
/// Windows are kept only on the wavefront, grouped in lists per half-edge: the list of
/// half-edge h holds windows on the edge of h that will enter the face of h. Vertices are taken
/// in order of tentative distance; taking a vertex sweeps its one-ring, i.e. propagates every
/// list on its incident edges, and the children are propagated on at once while their edge has
/// a vertex already taken. Saddle and border vertices are pseudo-sources: each time their
/// distance drops after being taken, they emit new windows.
///
/// Pruning (each provably drops only paths that another path matches or beats):
/// - the filter of Xin and Wang against the two end vertices of the edge;
/// - "one angle, two sides": the window giving the shortest path to the apex C splits the edge
///   at the point sp where that path crosses it; rays of any window left of sp that would land
///   on the far side CB cross that path, and are no shorter where they cross, so they are
///   dropped (and symmetrically right of sp).
class VTP_solver
{
public:
  explicit VTP_solver(const Mesh_cache& mesh)
    : m_mesh(mesh)
    , m_distance(mesh.number_of_vertices, infinity())
    , m_emitted(mesh.number_of_vertices, infinity())
    , m_taken(mesh.number_of_vertices, 0)
    , m_is_source_vertex(mesh.number_of_vertices, 0)
    , m_is_stop(mesh.number_of_vertices, 0)
    , m_head(mesh.number_of_halfedges(), -1)
    , m_tail(mesh.number_of_halfedges(), -1)
    , m_queued(mesh.number_of_halfedges(), 0)
    , m_pending(mesh.number_of_halfedges(), 0)
  {
    m_min_window_length = 1e-10 * mesh.mean_edge_length;
  }

  static double infinity() { return std::numeric_limits<double>::infinity(); }

  void add_source(const Source_point& s) { m_sources.push_back(normalized_source(m_mesh, s)); }

  void set_max_distance(double d)
  {
    if(!(d >= 0))
      throw Geodesic_error("max distance must be non-negative, got " + std::to_string(d));
    m_max_distance = d;
  }

  void add_stop_vertex(int v)
  {
    if(v < 0 || std::size_t(v) >= m_mesh.number_of_vertices)
      throw Geodesic_error("stop vertex " + std::to_string(v) + " is out of range (the mesh has " +
                           std::to_string(m_mesh.number_of_vertices) + " vertices)");
    if(!m_is_stop[v]) {
      m_is_stop[v] = 1;
      m_stop_vertices.push_back(v);
    }
  }

  /// Runs the propagation; distances beyond the max distance, or beyond the farthest stop
  /// vertex when stop vertices are given, are +infinity.
  void run()
  {
    const auto start = std::chrono::steady_clock::now();
    if(m_sources.empty())
      throw Geodesic_error("no source was given");
    for(const Source_point& s : m_sources) {
      if(s.vertex >= 0) {
        m_is_source_vertex[s.vertex] = 1;
        relax(s.vertex, 0.);
      } else {
        emit_from_face_point(s);
      }
    }
    for(;;) {
      while(!m_queue.empty()) {
        const auto top = m_queue.top();
        if(top.first > m_distance[top.second]) { // stale entry
          m_queue.pop();
          continue;
        }
        if(top.first > limit())
          break;
        m_queue.pop();
        take_vertex(top.second);
        drain();
      }
      if(!flush_pending())
        break;
    }
    update_stop_limit();
    const double l = limit();
    if(l < infinity())
      for(double& d : m_distance)
        if(d > l)
          d = infinity();
    m_statistics.vertices = m_mesh.number_of_vertices;
    m_statistics.faces = m_mesh.number_of_faces;
    m_statistics.peak_windows = m_pool.peak();
    m_statistics.peak_window_bytes = m_pool.capacity_bytes();
    m_statistics.seconds_solve =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  const std::vector<double>& distances() const { return m_distance; }
  const Geodesic_statistics& statistics() const { return m_statistics; }

private:
  typedef std::pair<double, int> Queue_entry;

  // The distance up to which results are wanted.
  double limit() const { return std::min(m_max_distance, m_stop_limit); }

  // Once every stop vertex is taken, nothing beyond the farthest of them is wanted. Distances
  // only decrease, so a limit computed earlier is never too small: it is refreshed only now and
  // then, when it is cheap to do so.
  void update_stop_limit()
  {
    if(m_stop_vertices.empty() || m_stops_taken < m_stop_vertices.size())
      return;
    double farthest = 0;
    for(int v : m_stop_vertices)
      farthest = std::max(farthest, m_distance[v]);
    m_stop_limit = farthest;
  }

  bool emits_windows(int v) const { return m_mesh.is_pseudo_source[v] || m_is_source_vertex[v]; }

  void relax(int v, double d)
  {
    if(d < m_distance[v]) {
      m_distance[v] = d;
      if(!m_taken[v] || emits_windows(v))
        m_queue.push(Queue_entry(d, v));
    }
  }

  bool inside_swept_region(int h) const
  {
    return m_taken[m_mesh.source(h)] || m_taken[m_mesh.target(h)];
  }

  void schedule(int h)
  {
    if(m_head[h] >= 0 && !m_queued[h]) {
      m_queued[h] = 1;
      m_fifo.push_back(h);
    }
  }

  // Appends a window to the list of half-edge h (if it survives the end-vertex filter) and
  // schedules the list when it lies in the swept region.
  void insert_window(int h, Window w)
  {
    const double length = m_mesh.frame[h].length;
    double key;
    if(!trim_by_edge_vertices(w, length, m_distance[m_mesh.source(h)], m_distance[m_mesh.target(h)], key) ||
       key > m_limit_cache)
      return;
    const std::int32_t i = m_pool.allocate(w);
    m_pool[i].next = -1;
    if(m_tail[h] >= 0)
      m_pool[m_tail[h]].next = i;
    else
      m_head[h] = i;
    m_tail[h] = i;
    ++m_statistics.windows_created;
    if(m_force || inside_swept_region(h))
      schedule(h);
    else if(!m_pending[h]) {
      m_pending[h] = 1;
      m_pending_lists.push_back(h);
    }
  }

  // A pseudo-source at vertex v: whole-edge windows on the edges opposite v, and its
  // neighbours relaxed along the edges.
  void emit_from_vertex(int v)
  {
    const double sigma = m_distance[v];
    m_emitted[v] = sigma;
    m_limit_cache = limit();
    m_mesh.for_each_outgoing(v, [&](int h) {
      relax(m_mesh.target(h), sigma + m_mesh.frame[h].length);
      const int across = Mesh_cache::next(h); // the edge opposite v in this face
      relax(m_mesh.target(across), sigma + m_mesh.frame[Mesh_cache::prev(h)].length);
      const int g = m_mesh.opposite(across);
      if(g < 0)
        return;
      const Halfedge_frame& f = m_mesh.frame[across];
      Window w;
      w.b0 = 0;
      w.b1 = f.length;
      w.sx = f.length - f.apex_x; // g runs the other way along the same edge
      w.sy = -f.apex_y;
      w.sigma = sigma;
      insert_window(g, w);
    });
  }

  // A source inside a face (or on an edge of it): windows on the face's edges that do not
  // contain it, in this face and, for a point on an edge, in the face across that edge.
  void emit_from_face_point(const Source_point& s)
  {
    m_limit_cache = limit();
    const auto& b = s.barycentric;
    emit_in_face(s.face, b);
    for(int k = 0; k < 3; ++k) {
      if(b[(k + 2) % 3] > 0)
        continue;
      // The point lies on half-edge 3f+k: express it in the face across.
      const int h = 3 * s.face + k;
      const int o = m_mesh.opposite(h);
      if(o < 0)
        continue;
      std::array<double, 3> bo{{0., 0., 0.}};
      bo[o % 3] = b[(k + 1) % 3];                    // o starts where h ends
      bo[Mesh_cache::next(o) % 3] = b[k];
      emit_in_face(Mesh_cache::face(o), bo);
    }
  }

  void emit_in_face(int face, const std::array<double, 3>& b)
  {
    for(int k = 0; k < 3; ++k) {
      const int h = 3 * face + k;
      const Halfedge_frame& f = m_mesh.frame[h];
      // The point in the frame of h: corner k at 0, corner k+1 at (length, 0), corner k+2 at the apex.
      const double x = b[(k + 1) % 3] * f.length + b[(k + 2) % 3] * f.apex_x;
      const double y = b[(k + 2) % 3] * f.apex_y;
      // distance to corner k (the origin of this frame)
      relax(m_mesh.source(h), std::hypot(x, y));
      if(b[(k + 2) % 3] <= 0)
        continue; // the point lies on this edge
      const int g = m_mesh.opposite(h);
      if(g < 0)
        continue;
      Window w;
      w.b0 = 0;
      w.b1 = f.length;
      w.sx = f.length - x;
      w.sy = -y;
      w.sigma = 0;
      insert_window(g, w);
    }
  }

  void take_vertex(int v)
  {
    ++m_statistics.vertices_popped;
    if(!m_taken[v]) {
      m_taken[v] = 1;
      if(m_is_stop[v] && ++m_stops_taken == m_stop_vertices.size())
        update_stop_limit();
    }
    if(emits_windows(v) && m_distance[v] < m_emitted[v])
      emit_from_vertex(v);
    m_mesh.for_each_outgoing(v, [&](int h) {
      const int in = Mesh_cache::prev(h);
      schedule(h);
      schedule(in);
      if(m_mesh.opposite(h) >= 0)
        schedule(m_mesh.opposite(h));
      if(m_mesh.opposite(in) >= 0)
        schedule(m_mesh.opposite(in));
    });
  }

  void drain()
  {
    m_limit_cache = limit();
    for(std::size_t i = 0; i < m_fifo.size(); ++i)
      propagate_list(m_fifo[i]);
    m_fifo.clear();
  }

  // Propagates every list that still holds windows, whether or not its edge was swept; used
  // once no vertex within the limit is left, so that every path shorter than the limit is done.
  bool flush_pending()
  {
    update_stop_limit();
    m_force = true;
    for(int h : m_pending_lists) {
      m_pending[h] = 0;
      schedule(h);
    }
    m_pending_lists.clear();
    const bool any = !m_fifo.empty();
    drain();
    m_force = false;
    return any;
  }

  // Takes the windows of list h across the face of h.
  void propagate_list(int h)
  {
    m_queued[h] = 0;
    m_scratch.clear();
    for(std::int32_t i = m_head[h]; i >= 0;) {
      const std::int32_t next = m_pool[i].next;
      m_scratch.push_back(m_pool[i]);
      m_pool.release(i);
      i = next;
    }
    m_head[h] = m_tail[h] = -1;
    ++m_statistics.lists_propagated;

    const Halfedge_frame& f = m_mesh.frame[h];
    const double d_from = m_distance[m_mesh.source(h)];
    const double d_to = m_distance[m_mesh.target(h)];
    std::size_t n = 0;
    for(Window w : m_scratch) {
      double key;
      if(trim_by_edge_vertices(w, f.length, d_from, d_to, key) && key <= m_limit_cache)
        m_scratch[n++] = w;
    }
    m_scratch.resize(n);
    if(n == 0)
      return;
    prune_pairs();

    // "One angle, two sides": the window with the shortest path to the apex splits the edge.
    double best = infinity(), split = 0;
    for(const Window& w : m_scratch) {
      double p;
      const double d = distance_to_apex(w, apex_crossing(w, f.apex_x, f.apex_y), f.apex_x, f.apex_y, p);
      if(d < best) {
        best = d;
        split = p;
      }
    }
    relax(m_mesh.apex(h), best);

    const int g_ac = m_mesh.opposite(Mesh_cache::prev(h));
    const int g_cb = m_mesh.opposite(Mesh_cache::next(h));
    Child_edge to_ac, to_cb;
    child_edges(m_mesh, h, to_ac, to_cb);
    Window child;
    for(const Window& w : m_scratch) {
      const double crossing = apex_crossing(w, f.apex_x, f.apex_y);
      if(g_ac >= 0) {
        const double hi = std::min({w.b1, split, crossing});
        if(hi > w.b0 && make_child(w, w.b0, hi, to_ac, m_min_window_length, child))
          insert_window(g_ac, child);
      }
      if(g_cb >= 0) {
        const double lo = std::max({w.b0, split, crossing});
        if(w.b1 > lo && make_child(w, lo, w.b1, to_cb, m_min_window_length, child))
          insert_window(g_cb, child);
      }
    }
  }

  // Rule 2: windows of the list are clipped against each other where they overlap.
  void prune_pairs()
  {
    if(m_scratch.size() < 2)
      return;
    std::sort(m_scratch.begin(), m_scratch.end(),
              [](const Window& a, const Window& b) { return a.b0 < b.b0; });
    const std::size_t n = m_scratch.size();
    for(std::size_t i = 0; i < n; ++i) {
      Window& wi = m_scratch[i];
      for(std::size_t j = i + 1; j < n && wi.b1 > wi.b0; ++j) {
        Window& wj = m_scratch[j];
        if(wj.b0 >= wi.b1)
          break; // sorted by where they start (skipping a pair only keeps more windows)
        if(!(wj.b1 > wj.b0))
          continue;
        const int emptied = clip_pair(wi, wj);
        if(emptied & 1)
          wi.b1 = wi.b0;
        if(emptied & 2)
          wj.b1 = wj.b0;
      }
    }
    m_scratch.erase(std::remove_if(m_scratch.begin(), m_scratch.end(),
                                   [](const Window& w) { return !(w.b1 > w.b0); }),
                    m_scratch.end());
  }

  const Mesh_cache& m_mesh;
  std::vector<double> m_distance;
  std::vector<double> m_emitted; // sigma of the last windows a vertex emitted
  std::vector<std::uint8_t> m_taken;
  std::vector<std::uint8_t> m_is_source_vertex;
  std::vector<std::uint8_t> m_is_stop;
  std::vector<std::int32_t> m_head, m_tail;
  std::vector<std::uint8_t> m_queued, m_pending;
  std::vector<int> m_pending_lists;
  std::vector<int> m_fifo;
  std::vector<Window> m_scratch;
  std::priority_queue<Queue_entry, std::vector<Queue_entry>, std::greater<Queue_entry>> m_queue;
  Window_pool m_pool;
  std::vector<Source_point> m_sources;
  std::vector<int> m_stop_vertices;
  std::size_t m_stops_taken = 0;
  double m_max_distance = infinity();
  double m_stop_limit = infinity();
  double m_limit_cache = infinity();
  double m_min_window_length = 0;
  bool m_force = false;
  Geodesic_statistics m_statistics;
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_VTP_SOLVER_H
