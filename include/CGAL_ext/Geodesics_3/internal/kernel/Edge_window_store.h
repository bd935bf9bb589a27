// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_EDGE_WINDOW_STORE_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_EDGE_WINDOW_STORE_H

#include <CGAL_ext/Geodesics_3/internal/kernel/Window.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh.h>
#include <CGAL_ext/Geodesics_3/internal/support/Object_pool.h>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// A window kept on an edge. The geometry is in the frame of the edge's reference half-edge
/// (`Edge_window_store::reference()`), mirrored if need be so that the pseudo-source lies below
/// the axis: distances along the edge do not depend on the side.
struct alignas(64) Edge_window // one cache line
{
  Window_geometry geometry;
  int halfedge;              // the half-edge whose face the window's rays enter
  int source;                // the source its paths start from (index in the order sources were added)
  std::uint32_t version = 0; // changes when the window is freed (and, with requeue_trimmed, clipped): older entries
                             // are stale; the one member a new block initializes (Object_pool)
  std::uint8_t queued;       // waits to be propagated
  Edge_window* next;         // the next window of the edge (sorted by b0), or of the pool's free list
};

/// A window to (re)queue with its smallest distance and its current version.
struct Queued_window
{
  double key;
  Edge_window* window;
  std::uint32_t version;
};

/// What inserting windows into the store gives besides the store itself: windows to queue,
/// vertex distances, and the number of windows made. Also holds the insertion's scratch space,
/// so that one output per thread makes insertions allocation-free.
struct alignas(64) Insertion_output // one cache line or more each: threads write their own often
{
  std::vector<Queued_window> queued;
  std::vector<Vertex_update> updates;
  std::size_t created = 0;
  std::vector<std::pair<double, double>> new_pieces, kept_pieces; // scratch
};

/// The windows kept on the edges by the MMP family: for each edge, a partition of the parts of
/// it reached so far into windows that do not overlap, from either side (a path arriving from
/// one side that is beaten by one from the other side cannot be continued as a shortest path),
/// sorted along the edge in a singly linked list.
///
/// Inserting a window clips it against the stored windows it overlaps: each loses the parts
/// where the other is strictly shorter (a stored window keeps a tie), a stored window losing the
/// middle of its interval is split, and pieces shorter than the minimum length vanish.
/// Insertions into different edges may run at once on different threads, each with its own pool
/// slot and output.
class Edge_window_store
{
public:
  /// When `requeue_trimmed`, a queued window that loses part of its interval is queued again
  /// with its new smallest distance (its older entry goes stale); otherwise its entry stays
  /// valid, with a key that may now be too low, and the queue's user checks the key when the
  /// window is taken.
  Edge_window_store(const Solver_mesh& mesh, double min_window_length, bool requeue_trimmed)
    : m_mesh(mesh)
    , m_edge(mesh.number_of_halfedges())
    , m_sole_source(mesh.number_of_halfedges(), no_window)
    , m_min_window_length(min_window_length)
    , m_requeue_trimmed(requeue_trimmed)
  {
  }

  Edge_window_store(const Edge_window_store&) = delete;
  Edge_window_store& operator=(const Edge_window_store&) = delete;

  const Solver_mesh& mesh() const { return m_mesh; }

  /// The half-edge of an edge whose frame its windows are stored in.
  int reference(int h) const
  {
    const int o = m_mesh.opposite(h);
    return (o < 0 || h < o) ? h : o;
  }
  /// The windows of the edge of half-edge h, sorted along the reference half-edge.
  const Edge_window* windows_of_edge(int h) const { return m_edge[reference(h)].first; }

  /// What `sole_source_of_edge` gives for an edge that never held a window, and for one that
  /// held windows of two sources or more.
  static constexpr int no_window = -1, several_sources = -2;
  /// The source of every window the edge of half-edge h has held since the store was made, when
  /// they all came from one; otherwise `no_window` or `several_sources`. A window beaten later
  /// still counts: the answer is about the past, so that keeping it costs no walk.
  int sole_source_of_edge(int h) const { return m_sole_source[std::size_t(reference(h))]; }

  /// A stored window in the frame of half-edge h of its edge.
  Window_geometry in_frame_of(const Edge_window& w, int h) const
  {
    return h == reference(h) ? w.geometry : mirrored(w.geometry, m_mesh.length(h));
  }
  /// A position along the edge of half-edge h, between the frames of h and of the edge's
  /// reference half-edge (either way: the change is its own inverse).
  double position_across_frames(double x, int h) const { return h == reference(h) ? x : m_mesh.length(h) - x; }

  /// See `Object_pool::use_one_slot_per_thread()`.
  std::size_t use_one_slot_per_thread(bool parallel) { return m_pool.use_one_slot_per_thread(parallel); }
  std::size_t number_of_slots() const { return m_pool.number_of_slots(); }
  /// Windows stored, exact between parallel steps.
  std::size_t live() const { return m_pool.live(); }
  /// Memory of the windows' pool.
  std::size_t bytes() const { return m_pool.bytes(); }
  /// Memory of the windows and of the edges' lists.
  std::size_t stored_bytes() const { return m_pool.bytes() + m_edge.size() * sizeof(Edge_list); }

  /// Clips window `g` (in the frame of half-edge h, from source `source`) into the windows of
  /// its edge. Writes only the edge's windows, the pool's `slot` and `out`: the windows to queue
  /// (its surviving pieces, the extra pieces of a split queued window, and with
  /// `requeue_trimmed` queued windows clipped in place) and the distances of the edge's end
  /// vertices that a piece reaches.
  void insert(const Window_geometry& g, int h, int source, std::size_t slot, Insertion_output& out)
  {
    const int e = reference(h);
    const double length = m_mesh.length(h);
    const Window_geometry c = h == e ? g : mirrored(g, length);

    std::vector<std::pair<double, double>>& pieces = out.new_pieces; // what the new window keeps
    std::vector<std::pair<double, double>>& kept = out.kept_pieces;  // what a stored window keeps
    // clear and push_back rather than assign(1, x): assign is an out-of-line call, per insertion.
    pieces.clear();
    pieces.emplace_back(c.b0, c.b1);
    Edge_window* before = nullptr; // the stored window before the current one
    Edge_list& list = m_edge[e];
    Edge_window* w = list.first;
    double cut[4];
    int winner[3];
    // the walk to the first window that overlaps starts from the last insertion's, when that
    // lies before this one
    if(Edge_window* hint = list.walk_start; hint && hint->geometry.b1 <= c.b0) {
      before = hint;
      w = hint->next;
    }
    while(w && w->geometry.b1 <= c.b0) {
      before = w;
      w = w->next;
    }
    Edge_window* const last_before_overlap = before; // not changed below: the second pass starts here
    if(last_before_overlap)
      list.walk_start = last_before_overlap;
    while(w && !pieces.empty()) {
      Window_geometry& s = w->geometry;
      if(s.b0 >= c.b1)
        break;
      const int m = compare_on_overlap(s, c, std::max(s.b0, c.b0), std::min(s.b1, c.b1), cut, winner);
      kept.clear();
      kept.emplace_back(s.b0, s.b1);
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
        (before ? before->next : list.first) = after;
        if(list.walk_start == w)
          list.walk_start = before;
        ++w->version;
        m_pool.release(slot, w);
        w = after;
        continue;
      }
      // The stored window keeps one piece or more, in place.
      s.b0 = kept[0].first;
      s.b1 = kept[0].second;
      if(m_requeue_trimmed) {
        ++w->version;
        if(w->queued)
          out.queued.push_back(Queued_window{window_key(s), w, w->version});
      }
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
          out.queued.push_back(Queued_window{window_key(p->geometry), p, p->version});
      }
      before = last;
      w = after;
    }
    drop_short(pieces);
    if(pieces.empty())
      return;
    int& sole = m_sole_source[std::size_t(e)];
    if(sole != source)
      sole = sole == no_window ? source : several_sources;

    // The new window's pieces fill gaps between stored windows: link each where it belongs.
    before = last_before_overlap;
    w = before ? before->next : list.first;
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
      model.source = source;
      model.queued = 1;
      Edge_window* p = allocate(slot, model);
      p->next = w;
      (before ? before->next : list.first) = p;
      before = p;
      ++out.created;
      out.queued.push_back(Queued_window{window_key(p->geometry), p, p->version});
      // A piece reaching an end of the edge gives that vertex a distance.
      if(iv.first <= 0)
        out.updates.push_back(
          Vertex_update{m_mesh.source(e), source, distance_at(c, 0.), arrival_at_end(g, h, m_mesh.source(e))});
      if(iv.second >= length)
        out.updates.push_back(
          Vertex_update{m_mesh.target(e), source, distance_at(c, length), arrival_at_end(g, h, m_mesh.target(e))});
    }
  }

private:
  // The arrival at end vertex v of half-edge h of the path from the pseudo-source of g (in the
  // frame of h, below it): that path crosses the face across h, where the pseudo-source, turned
  // by a half turn into the frame of the opposite half-edge, lies above its axis.
  Arrival arrival_at_end(const Window_geometry& g, int h, int v) const
  {
    const int o = m_mesh.opposite(h);
    if(o < 0)
      return Arrival{};
    const double length = m_mesh.length(h);
    return arrival_from(o, length - g.sx, -g.sy, v == m_mesh.source(o) ? 0. : length, 0.);
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

  const Solver_mesh& m_mesh;
  // The windows of an edge: the first, and one (or null) where the last insertion's walk ended.
  // An edge holds tens of windows, scattered in memory, and insertions come along it: a walk
  // from there rather than from the start of the list touches fewer. Side by side, both come
  // in one cache line.
  struct Edge_list
  {
    Edge_window* first = nullptr;
    Edge_window* walk_start = nullptr;
  };
  std::vector<Edge_list> m_edge; // at each edge's reference half-edge
  std::vector<int> m_sole_source; // the same; see sole_source_of_edge
  Object_pool<Edge_window> m_pool;
  const double m_min_window_length;
  const bool m_requeue_trimmed;
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_EDGE_WINDOW_STORE_H
