// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_WINDOW_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_WINDOW_H

#include <CGAL_ext/Geodesics_3/Tolerances.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Double_pair.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh.h>
#include <CGAL_ext/Geodesics_3/internal/support/Inlining.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// The geometry of a window: a bundle of straight shortest paths from one (pseudo-)source,
/// unfolded into the plane, crossing the interval [b0, b1] of a half-edge h. Coordinates are in
/// the frame of h (source vertex at the origin, target at (length, 0), the face of h above the
/// x-axis); the pseudo-source (sx, sy) lies below or on the axis and `sigma` is its geodesic
/// distance.
struct Window_geometry
{
  double b0, b1;
  double sx, sy;
  double sigma;
};

/// A window of a list (VTP keeps its windows in lists per half-edge), with the distances at
/// the ends of its interval, kept equal to `distance_at(b0)` and `distance_at(b1)` so that
/// trimming and clipping reuse them, and the index of the source its paths come from: 64 bytes
/// with its padding, the size of a cache line, which the hot loops (sorting and clipping a list)
/// work on.
/// (Not `alignas(64)`: windows are passed and copied by value, and GCC notes at every such call
/// that passing over-aligned values changed ABI; the pool's blocks are aligned.)
struct Window : Window_geometry
{
  double d0, d1;
  int source;
};
static_assert(sizeof(Window) == 64, "a list window is one cache line");

/// The square root, correctly rounded as std::sqrt, without the test and library call that set
/// `errno` for a negative argument (compilers keep them unless told `-fno-math-errno`; the
/// kernel takes about ten square roots a window). A negative argument gives NaN either way.
inline double square_root(double x)
{
#if defined(__SSE2__)
  const __m128d v = _mm_set_sd(x);
  return _mm_cvtsd_f64(_mm_sqrt_sd(v, v));
#else
  return std::sqrt(x);
#endif
}

/// Planar length of (x, y). std::hypot guards against overflow at a large cost; coordinates of
/// a mesh are far from that range.
inline double norm2d(double x, double y) { return square_root(x * x + y * y); }

inline double distance_at(const Window_geometry& w, double x) { return w.sigma + norm2d(x - w.sx, w.sy); }

/// The same at two points side by side (the same bits as two calls).
inline Double_pair distance_at(const Window_geometry& w, Double_pair x)
{
  const Double_pair dx = x - Double_pair::both(w.sx);
  return Double_pair::both(w.sigma) + square_roots(dx * dx + Double_pair::both(w.sy * w.sy));
}

/// Whether the window holds no ray: its interval is empty, as trimming or clipping leave a
/// window they remove whole (b1 = b0), or NaN.
inline bool is_empty(const Window_geometry& w) { return !(w.b1 > w.b0); }

/// Where the path that gave a vertex its distance comes from: a point of that path's last
/// segment minus the vertex, in the frame of `halfedge`, a half-edge of a face with the vertex as
/// a corner that holds the segment's end at the vertex; `halfedge` is -1 when unknown (a
/// source). Floats: only the cone of a saddle reads it, with a tolerance far above their
/// precision.
struct Arrival
{
  std::int32_t halfedge = -1;
  float dx = 0, dy = 0;
};

/// A distance found for a vertex, applied after a parallel step (or after the emission that
/// found it).
struct Vertex_update
{
  int vertex;
  int source;
  double distance;
  Arrival arrival = Arrival{}; // where the path comes from (`emit_vertex_windows`)
};

/// The arrival at the point (vx, vy) of the frame of h from the point (x, y) of that frame.
inline Arrival arrival_from(int h, double x, double y, double vx, double vy)
{
  const float dx = float(x - vx), dy = float(y - vy);
  if(dx == 0 && dy == 0)
    return Arrival{};
  return Arrival{std::int32_t(h), dx, dy};
}

/// The arrival at the apex (cx, cy) of the frame of h of the path through window w that
/// `distance_to_apex` measured, p the point it gave: from the pseudo-source when the path is
/// straight, from p when it bends at an end of the window.
inline Arrival apex_arrival(int h, const Window_geometry& w, double p, double cx, double cy)
{
  return p > w.b0 && p < w.b1 ? arrival_from(h, w.sx, w.sy, cx, cy) : arrival_from(h, p, 0., cx, cy);
}

/// Makes `w`, whose geometry is set, a list window: its end distances computed, its paths from
/// source `source`.
inline void finish_list_window(Window& w, int source)
{
  const Double_pair d = distance_at(w, Double_pair(w.b0, w.b1));
  w.d0 = d.first();
  w.d1 = d.second();
  w.source = source;
}

/// The list window of `g` (`finish_list_window`).
inline Window list_window(const Window_geometry& g, int source)
{
  Window w;
  static_cast<Window_geometry&>(w) = g;
  finish_list_window(w, source);
  return w;
}

/// The smallest distance the window gives to a point of its interval.
inline double window_key(const Window_geometry& w)
{
  if(w.sx <= w.b0)
    return distance_at(w, w.b0);
  if(w.sx >= w.b1)
    return distance_at(w, w.b1);
  return w.sigma - w.sy;
}

/// The cuts of `trim_by_edge_vertices`, out of line: most windows need none.
CGAL_EXT_NOINLINE inline void cut_by_edge_vertices(Window_geometry& w, double& at_b0, double& at_b1, double length,
                                                   double d_from, double d_to)
{
  if(at_b0 - w.b0 > d_from) {
    // sigma + |s - x| = d_from + x
    const double r2 = w.sx * w.sx + w.sy * w.sy;
    const double k = d_from - w.sigma;
    const double x = (r2 - k * k) / (2 * (k + w.sx));
    if(std::isfinite(x)) { // not when the pseudo-source lies on the edge's line (0/0)
      w.b0 = std::min(std::max(x, w.b0), w.b1);
      at_b0 = distance_at(w, w.b0);
    }
  }
  if(at_b1 + w.b1 > d_to + length) {
    // sigma + |s - x| = d_to + length - x
    const double r2 = w.sx * w.sx + w.sy * w.sy;
    const double m = d_to + length - w.sigma;
    const double x = (m * m - r2) / (2 * (m - w.sx));
    if(std::isfinite(x)) {
      w.b1 = std::max(std::min(x, w.b1), w.b0);
      at_b1 = distance_at(w, w.b1);
    }
  }
}

/// The filter of Xin and Wang (thesis eqs 4.1-4.2), made exact: the part of the window where
/// the path through an end vertex of its edge is shorter is cut off. Along the edge,
/// D(x) - x is non-increasing and D(x) + x non-decreasing, so the part beaten by the source
/// vertex of the half-edge is an initial segment and the part beaten by its target a final one.
/// `d_from`/`d_to` are the current distances of the source/target vertex of the half-edge.
/// `at_b0`/`at_b1` are the distances at the ends of the window, updated with them.
/// Returns false when nothing is left; otherwise `key` is the window's smallest distance.
inline bool trim_by_edge_vertices(Window_geometry& w, double& at_b0, double& at_b1, double length, double d_from,
                                  double d_to, double& key)
{
  if(at_b1 - w.b1 > d_from || at_b0 + w.b0 > d_to + length)
    return false;
  if(at_b0 - w.b0 > d_from || at_b1 + w.b1 > d_to + length)
    cut_by_edge_vertices(w, at_b0, at_b1, length, d_from, d_to);
  key = (w.sx > w.b0 && w.sx < w.b1) ? w.sigma - w.sy : std::min(at_b0, at_b1);
  return !is_empty(w);
}

/// The same, the distances at the ends computed here.
inline bool trim_by_edge_vertices(Window_geometry& w, double length, double d_from, double d_to, double& key)
{
  double at_b0 = distance_at(w, w.b0), at_b1 = distance_at(w, w.b1);
  return trim_by_edge_vertices(w, at_b0, at_b1, length, d_from, d_to, key);
}

/// Where the line from the pseudo-source to the apex (cx, cy) crosses the x-axis.
inline double apex_crossing(const Window_geometry& w, double cx, double cy)
{
  return w.sx - w.sy * (cx - w.sx) / (cy - w.sy);
}

/// Length of the shortest path from the pseudo-source through a point p of the window to the
/// apex; `crossing` is `apex_crossing(w, ...)` and p is it clamped to the window.
inline double distance_to_apex(const Window_geometry& w, double crossing, double cx, double cy, double& p)
{
  if(crossing < w.b0)
    p = w.b0;
  else if(crossing > w.b1)
    p = w.b1;
  else {
    p = crossing;
    return w.sigma + norm2d(cx - w.sx, cy - w.sy);
  }
  return distance_at(w, p) + norm2d(cx - p, cy);
}

/// The same for a list window, whose end distances are known.
inline double distance_to_apex(const Window& w, double crossing, double cx, double cy, double& p)
{
  if(crossing < w.b0) {
    p = w.b0;
    return w.d0 + norm2d(cx - p, cy);
  }
  if(crossing > w.b1) {
    p = w.b1;
    return w.d1 + norm2d(cx - p, cy);
  }
  p = crossing;
  return w.sigma + norm2d(cx - w.sx, cy - w.sy);
}

/// The points of (lo, hi) where two windows of the same edge give equal distances, sorted;
/// returns how many (0 to 2). With delta = sigma0 - sigma1, D1 = D0 reads
/// |x - s1| = |x - s0| + delta; squaring once gives alpha x + beta = 2 delta |x - s0|, and a
/// second time a quadratic. A root of the quadratic is kept only if it solves the first
/// equation too: squaring adds spurious roots.
// Out of line: called for a third of the pairs only, and inlined it made `compare_on_overlap`
// too large to be inlined where the other two thirds are decided.
CGAL_EXT_NOINLINE inline int equal_distance_points(const Window_geometry& w0, const Window_geometry& w1, double lo,
                                                   double hi, double roots[2])
{
  const double delta = w0.sigma - w1.sigma;
  const double alpha = 2 * (w0.sx - w1.sx);
  const double beta = w1.sx * w1.sx + w1.sy * w1.sy - w0.sx * w0.sx - w0.sy * w0.sy - delta * delta;
  int n = 0;
  auto keep = [&](double x) CGAL_EXT_ALWAYS_INLINE {
    // |x - s1| = |x - s0| + delta needs |x - s0| + delta >= 0 (true when delta >= 0), and then
    // alpha x + beta has the sign of delta; both are checked (the pieces' winners are checked
    // again at their midpoints)
    if(x > lo && x < hi && (alpha * x + beta) * delta >= 0 && (delta >= 0 || norm2d(x - w0.sx, w0.sy) + delta >= 0))
      roots[n++] = x;
  };
  if(delta == 0) {
    if(alpha != 0)
      keep(-beta / alpha);
    return n;
  }
  const double d2 = 4 * delta * delta;
  const double a = alpha * alpha - d2;
  const double b = 2 * alpha * beta + 2 * d2 * w0.sx;
  const double c = beta * beta - d2 * (w0.sx * w0.sx + w0.sy * w0.sy);
  if(std::abs(a) <= quadratic_cancellation_ratio * (alpha * alpha + d2)) {
    if(b != 0)
      keep(-c / b);
    return n;
  }
  const double disc = b * b - 4 * a * c;
  if(disc < 0)
    return 0;
  // the numerically stable pair of roots
  const double q = -0.5 * (b + std::copysign(square_root(disc), b));
  double r0 = q / a, r1 = q != 0 ? c / q : r0;
  if(r0 > r1)
    std::swap(r0, r1);
  keep(r0);
  if(r1 != r0)
    keep(r1);
  return n;
}

/// Compares two windows of the same edge on their overlap [lo, hi]: splits it at the points
/// where they give equal distances into `n - 1` pieces (1 to 3), [cut[i], cut[i+1]], and tells
/// which window is shorter on each (`winner[i]`: 0 for w0, 1 for w1). Returns n.
/// `lo0`, `hi0` (`lo1`, `hi1`) are the distances w0 (w1) gives at lo and hi.
inline int compare_on_overlap(const Window_geometry& w0, const Window_geometry& w1, double lo, double hi, double lo0,
                              double hi0, double lo1, double hi1, double cut[4], int winner[3])
{
  // A distance is convex along the edge: its largest value on the overlap is at an end. When
  // one window's largest value is no more than the other's smallest, no equation is solved.
  auto smallest = [&](const Window_geometry& w, double d_lo, double d_hi) {
    return (w.sx > lo && w.sx < hi) ? w.sigma - w.sy : std::min(d_lo, d_hi);
  };
  cut[0] = lo;
  if(std::max(lo0, hi0) <= smallest(w1, lo1, hi1)) {
    cut[1] = hi;
    winner[0] = 0;
    return 2;
  }
  if(std::max(lo1, hi1) < smallest(w0, lo0, hi0)) {
    cut[1] = hi;
    winner[0] = 1;
    return 2;
  }
  // f = D1 - D0 is monotone on either side of the point where the line through the two
  // pseudo-sources meets the edge (where f' = 0: the rays from both to a point of the edge have
  // the same direction only there). On an overlap that does not hold that point, f has one sign
  // throughout when it has that sign at an end and not the other at the other end.
  const double f_lo = lo1 - lo0, f_hi = hi1 - hi0;
  // (bitwise operators: one unpredictable branch rather than several)
  const bool positive = ((f_lo > 0) | (f_hi > 0)) & (f_lo >= 0) & (f_hi >= 0);
  const bool negative = ((f_lo < 0) | (f_hi < 0)) & (f_lo <= 0) & (f_hi <= 0);
  if(positive | negative) {
    const double dx = w1.sx - w0.sx, dy = w1.sy - w0.sy;
    const double side_lo = dy * (lo - w0.sx) + dx * w0.sy, side_hi = dy * (hi - w0.sx) + dx * w0.sy;
    if(!(side_lo * side_hi < 0)) {
      cut[1] = hi;
      winner[0] = (f_lo < 0 || f_hi < 0) ? 1 : 0;
      return 2;
    }
  }
  int n = 1 + equal_distance_points(w0, w1, lo, hi, cut + 1);
  cut[n++] = hi;
  // One point of equal distance between ends where f has opposite signs: the ends tell the
  // winners, with no distance evaluated.
  if(n == 3 && ((f_lo > 0 && f_hi < 0) || (f_lo < 0 && f_hi > 0))) {
    winner[0] = f_lo < 0 ? 1 : 0;
    winner[1] = f_hi < 0 ? 1 : 0;
    return n;
  }
  // Winner of each piece between consecutive cut points. On a tie w0 wins: two different
  // straight paths of equal length meeting on the edge cannot both continue as shortest paths.
  for(int i = 0; i + 1 < n; ++i) {
    const double x = 0.5 * (cut[i] + cut[i + 1]);
    winner[i] = distance_at(w1, x) < distance_at(w0, x) ? 1 : 0;
  }
  return n;
}

/// The same, the distances at lo and hi computed here.
inline int compare_on_overlap(const Window_geometry& w0, const Window_geometry& w1, double lo, double hi, double cut[4], int winner[3])
{
  return compare_on_overlap(w0, w1, lo, hi, distance_at(w0, lo), distance_at(w0, hi), distance_at(w1, lo),
                            distance_at(w1, hi), cut, winner);
}

/// Clips two list windows of the same edge against each other where they overlap: a window
/// loses the part of the overlap where the other one is strictly shorter, when that part is at
/// an end of its interval. When w0's interval holds the whole overlap strictly inside it and w0
/// loses a part of it, w0 is split, if `split` is given: it keeps what comes before the last
/// part it loses, and `*split` receives what comes after it (of two windows sorted by where they
/// start, only the first can hold the other). Other losses strictly inside an interval are left
/// alone. Returns a bit set: 1 if w0 became empty, 2 if w1 did, 4 if w0 was split.
inline int clip_pair(Window& w0, Window& w1, Window* split = nullptr)
{
  const double lo = std::max(w0.b0, w1.b0), hi = std::min(w0.b1, w1.b1);
  if(!(hi > lo))
    return 0;
  // lo and hi are ends of the windows: where they are a window's own end, its distance is known
  const double lo0 = lo == w0.b0 ? w0.d0 : distance_at(w0, lo);
  const double hi0 = hi == w0.b1 ? w0.d1 : distance_at(w0, hi);
  const double lo1 = lo == w1.b0 ? w1.d0 : distance_at(w1, lo);
  const double hi1 = hi == w1.b1 ? w1.d1 : distance_at(w1, hi);
  double cut[4];
  int winner[3];
  const int n = compare_on_overlap(w0, w1, lo, hi, lo0, hi0, lo1, hi1, cut, winner);
  // A window gives up the pieces the other one wins from each end of the overlap that is an end
  // of its own interval, inwards. With `right`, one that holds the overlap strictly inside is
  // split at the last piece it loses (`right` receives the part after it): the window inside
  // it is the shorter there, and would otherwise be clipped against it again list after list.
  // Returns 1 if nothing is left of the window, 2 if it was split.
  auto trim = [&](Window& w, double d_lo, double d_hi, int other, Window* right) {
    int first = 0, last = n - 2;
    if(w.b0 == lo)
      while(first <= last && winner[first] == other)
        ++first;
    if(w.b1 == hi)
      while(last >= first && winner[last] == other)
        --last;
    if(first > last) {
      if(w.b0 == lo && w.b1 == hi)
        return 1;
      if(w.b0 == lo) {
        w.b0 = hi;
        w.d0 = d_hi;
      } else {
        w.b1 = lo;
        w.d1 = d_lo;
      }
      return 0;
    }
    if(first > 0) {
      w.b0 = cut[first];
      w.d0 = distance_at(w, w.b0);
    }
    if(last < n - 2) {
      w.b1 = cut[last + 1];
      w.d1 = distance_at(w, w.b1);
    }
    if(right && w.b0 < lo && w.b1 > hi)
      for(int k = n - 2; k >= 0; --k)
        if(winner[k] == other) {
          // the distances at the overlap's ends are known
          *right = w;
          right->b0 = cut[k + 1];
          right->d0 = right->b0 == hi ? d_hi : distance_at(w, right->b0);
          w.b1 = cut[k];
          w.d1 = w.b1 == lo ? d_lo : distance_at(w, w.b1);
          return 2;
        }
    return 0;
  };
  const int outcome0 = trim(w0, lo0, hi0, 1, split);
  const int outcome1 = trim(w1, lo1, hi1, 0, nullptr);
  return (outcome0 == 1 ? 1 : outcome0 == 2 ? 4 : 0) | (outcome1 == 1 ? 2 : 0);
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
inline bool make_child(const Window_geometry& w, double lo, double hi, const Child_edge& e,
                       double min_length, Window_geometry& child)
{
  // Ray from s through (x, 0) meets the line E0 + t (E1 - E0) at
  // t = cross(s - E0, d) / cross(E1 - E0, d), with d = (x - sx, -sy).
  // (the rays through lo and hi side by side)
  const double rx = w.sx - e.e0x, ry = w.sy - e.e0y, dy = -w.sy;
  const Double_pair dx = Double_pair(lo, hi) - Double_pair::both(w.sx);
  const Double_pair num = Double_pair::both(rx * dy) - Double_pair::both(ry) * dx;
  const Double_pair den = Double_pair::both(e.ux * dy) - Double_pair::both(e.uy) * dx;
  // clamped to [0, length]; where den is 0 the ray is parallel to the edge: num / den is
  // +-infinity, clamped to the end the signs of num and of den's zero give, or NaN (num is 0
  // too), taken as 0
  const Double_pair t = clamp_to(num / den, e.length);
  const double c0 = t.first(), c1 = t.second();
  if(!(c1 - c0 > min_length))
    return false;
  child.b0 = c0;
  child.b1 = c1;
  child.sx = rx * e.ux + ry * e.uy;
  child.sy = -std::abs(e.ux * ry - e.uy * rx);
  child.sigma = w.sigma;
  return true;
}

/// Where the windows on half-edge h = (A -> B, apex C) go across its face: the half-edges beyond
/// the edges A -> C and C -> B (-1 on the border; the first runs from A to C, the second from C to
/// B), and those two edges in the frame of h (`f`, which is `m.frame(h)`).
struct Face_crossing
{
  int to_ac, to_cb;
  Child_edge ac, cb;
};

inline Face_crossing face_crossing(const Solver_mesh& m, int h, const Halfedge_frame& f)
{
  const double l_ac = m.length(Solver_mesh::prev(h));
  const double l_cb = m.length(Solver_mesh::next(h));
  return Face_crossing{m.opposite(Solver_mesh::prev(h)), m.opposite(Solver_mesh::next(h)),
                       Child_edge{0., 0., f.apex_x / l_ac, f.apex_y / l_ac, l_ac},
                       Child_edge{f.apex_x, f.apex_y, (f.length - f.apex_x) / l_cb, -f.apex_y / l_cb, l_cb}};
}

/// The parts of `w` that cross the face onto an edge with a face beyond: the rays through
/// [b0, min(b1, ac_end)] onto A -> C and those through [max(b0, cb_start), b1] onto C -> B, each
/// non-empty one given as `part(halfedge beyond, onto_ac, lo, hi, edge)`.
template <class Part>
CGAL_EXT_ALWAYS_INLINE inline void for_each_child_part(const Window_geometry& w, const Face_crossing& c, double ac_end,
                                                       double cb_start, Part part)
{
  if(c.to_ac >= 0) {
    const double hi = std::min(w.b1, ac_end);
    if(hi > w.b0)
      part(c.to_ac, true, w.b0, hi, c.ac);
  }
  if(c.to_cb >= 0) {
    const double lo = std::max(w.b0, cb_start);
    if(w.b1 > lo)
      part(c.to_cb, false, lo, w.b1, c.cb);
  }
}

/// The children of `w` across the face (`for_each_child_part`): `add(halfedge, child, onto_ac)`
/// receives each child at least `min_length` long, in the frame of the half-edge beyond.
template <class Add>
CGAL_EXT_ALWAYS_INLINE inline void make_children(const Window_geometry& w, const Face_crossing& c, double ac_end,
                                                 double cb_start, double min_length, Add add)
{
  Window_geometry child;
  for_each_child_part(w, c, ac_end, cb_start,
                      [&](int g, bool onto_ac, double lo, double hi, const Child_edge& e) CGAL_EXT_ALWAYS_INLINE {
                        if(make_child(w, lo, hi, e, min_length, child))
                          add(g, child, onto_ac);
                      });
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_WINDOW_H
