// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_WINDOW_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_WINDOW_H

#include <CGAL_ext/Geodesics_3/internal/Mesh_cache.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// A window: a bundle of straight shortest paths from one (pseudo-)source, unfolded into the
/// plane, crossing the interval [b0, b1] of a half-edge h. Coordinates are in the frame of h
/// (source vertex at the origin, target at (length, 0), the face of h above the x-axis); the
/// pseudo-source (sx, sy) lies below or on the axis and `sigma` is its geodesic distance.
struct Window
{
  double b0, b1;
  double sx, sy;
  double sigma;
  std::int32_t next; // next window of the same list, -1 at the end
};

inline double distance_at(const Window& w, double x) { return w.sigma + std::hypot(x - w.sx, w.sy); }

/// The smallest distance the window gives to a point of its interval.
inline double window_key(const Window& w)
{
  if(w.sx <= w.b0)
    return distance_at(w, w.b0);
  if(w.sx >= w.b1)
    return distance_at(w, w.b1);
  return w.sigma - w.sy;
}

/// The filter of Xin and Wang (thesis eqs 4.1-4.2): the window is useless when the path through
/// one end vertex of its edge is shorter at the far end of the window (hence at every point of
/// it). `d_from`/`d_to` are the current distances of the source/target vertex of the half-edge.
inline bool is_dominated_by_edge_vertices(const Window& w, double length, double d_from, double d_to)
{
  return distance_at(w, w.b1) > d_from + w.b1 || distance_at(w, w.b0) > d_to + (length - w.b0);
}

/// Where the line from the pseudo-source to the apex (cx, cy) crosses the x-axis.
inline double apex_crossing(const Window& w, double cx, double cy)
{
  return w.sx - w.sy * (cx - w.sx) / (cy - w.sy);
}

/// Length of the shortest path from the pseudo-source through a point p of the window to the
/// apex; `crossing` is `apex_crossing(w, ...)` and p is it clamped to the window.
inline double distance_to_apex(const Window& w, double crossing, double cx, double cy, double& p)
{
  if(crossing < w.b0)
    p = w.b0;
  else if(crossing > w.b1)
    p = w.b1;
  else {
    p = crossing;
    return w.sigma + std::hypot(cx - w.sx, cy - w.sy);
  }
  return distance_at(w, p) + std::hypot(cx - p, cy);
}

/// A segment E0 -> E1 of the parent frame that a child window lands on, with what is needed to
/// re-express rays in the child's frame (origin E0, x-axis along E0 -> E1).
struct Child_edge
{
  double e0x, e0y; // E0 in the parent frame
  double ux, uy;   // unit direction E0 -> E1
  double length;
};

/// The child of `w` made of the rays through [lo, hi] of the parent edge that land on `e`:
/// the interval is the rays' hits on `e`, the pseudo-source is moved to the child frame (where it
/// lies below the axis). Returns false when the child is empty or shorter than `min_length`.
inline bool make_child(const Window& w, double lo, double hi, const Child_edge& e,
                       double min_length, Window& child)
{
  // Ray from s through (x, 0) meets the line E0 + t (E1 - E0) at
  // t = cross(s - E0, d) / cross(E1 - E0, d), with d = (x - sx, -sy).
  const double rx = w.sx - e.e0x, ry = w.sy - e.e0y;
  auto hit = [&](double x) {
    const double dx = x - w.sx, dy = -w.sy;
    const double num = rx * dy - ry * dx;
    const double den = e.ux * dy - e.uy * dx;
    double t = den != 0 ? num / den : (num > 0 ? e.length : 0.);
    return std::min(std::max(t, 0.), e.length);
  };
  const double c0 = hit(lo), c1 = hit(hi);
  if(!(c1 - c0 > min_length))
    return false;
  child.b0 = c0;
  child.b1 = c1;
  child.sx = rx * e.ux + ry * e.uy;
  child.sy = -std::abs(e.ux * ry - e.uy * rx);
  child.sigma = w.sigma;
  return true;
}

/// The two child edges of the face of half-edge h = (A -> B) with apex C: the edge A -> C and the
/// edge C -> B, in the frame of h.
inline void child_edges(const Mesh_cache& m, int h, Child_edge& to_ac, Child_edge& to_cb)
{
  const Halfedge_frame& f = m.frame[h];
  const double l_ac = m.frame[Mesh_cache::prev(h)].length;
  const double l_cb = m.frame[Mesh_cache::next(h)].length;
  to_ac = Child_edge{0., 0., f.apex_x / l_ac, f.apex_y / l_ac, l_ac};
  to_cb = Child_edge{f.apex_x, f.apex_y, (f.length - f.apex_x) / l_cb, -f.apex_y / l_cb, l_cb};
}

/// A pool of windows addressed by index, recycling freed slots: no allocation per window once
/// the pool has grown to the size of the wavefront.
class Window_pool
{
public:
  std::int32_t allocate(const Window& w)
  {
    std::int32_t i;
    if(m_free >= 0) {
      i = m_free;
      m_free = m_windows[i].next;
      m_windows[i] = w;
    } else {
      i = static_cast<std::int32_t>(m_windows.size());
      m_windows.push_back(w);
    }
    ++m_live;
    m_peak = std::max(m_peak, m_live);
    return i;
  }
  void release(std::int32_t i)
  {
    m_windows[i].next = m_free;
    m_free = i;
    --m_live;
  }
  Window& operator[](std::int32_t i) { return m_windows[i]; }
  const Window& operator[](std::int32_t i) const { return m_windows[i]; }
  std::size_t live() const { return m_live; }
  std::size_t peak() const { return m_peak; }
  std::size_t capacity_bytes() const { return m_windows.capacity() * sizeof(Window); }

private:
  std::vector<Window> m_windows;
  std::int32_t m_free = -1;
  std::size_t m_live = 0;
  std::size_t m_peak = 0;
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_WINDOW_H
