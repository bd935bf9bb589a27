// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_SOURCE_WINDOWS_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_SOURCE_WINDOWS_H

// Where a propagation starts: the windows a source or a pseudo-source (a saddle or border vertex)
// emits, and the cone of directions in which a path can go on through a saddle vertex.

#include <CGAL_ext/Geodesics_3/Tolerances.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Source_points.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Window.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh.h>
#include <CGAL_ext/Geodesics_3/internal/support/Inlining.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// The directions in which a shortest path that reaches an interior vertex v along an arrival
/// can go on through v: those at least pi from the arrival on both sides. A path that turns by
/// less on one side is shortened by cutting the corner there, and the windows that passed beside
/// v carry the shorter path: windows of v outside the cone would only be clipped away, each
/// against every window of its edge. As angles around v, counter-clockwise from the half-edge
/// `m.first_outgoing[v]`: [start, start + width] modulo `total` (the angle sum at v), widened by
/// `saddle_angle_tolerance` on each side. `corners` holds the angle at v of each face, in the
/// order of `for_each_outgoing`.
struct Saddle_cone
{
  double start = 0, width = 0, total = 0;
  std::vector<double> corners;
};

/// Sets `cone` for v reached along `arrival` (whose half-edge is in a face around v).
inline void set_saddle_cone(const Solver_mesh& m, int v, const Arrival& arrival, Saddle_cone& cone)
{
  const double pi = CGAL_PI;
  const int g = arrival.halfedge;
  // hv: the half-edge of the arrival's face leaving v; (ux, uy): along it, in the frame of g
  const Halfedge_frame f = m.frame(g);
  int hv = g;
  double ux = 1, uy = 0;
  if(m.source(g) != v) {
    const bool at_target = m.target(g) == v;
    hv = at_target ? Solver_mesh::next(g) : Solver_mesh::prev(g);
    ux = at_target ? f.apex_x - f.length : -f.apex_x;
    uy = at_target ? f.apex_y : -f.apex_y;
  }
  const double dx = arrival.dx, dy = arrival.dy;
  const double within = polar_angle(ux * dy - uy * dx, ux * dx + uy * dy); // the arrival from hv
  double back = 0;
  bool found = false;
  cone.total = 0;
  cone.corners.clear();
  m.for_each_outgoing(v, [&](int h) {
    if(h == hv) {
      back = cone.total + within;
      found = true;
    }
    cone.corners.push_back(m.angle_at_source(h));
    cone.total += cone.corners.back();
  });
  if(!found) { // not a face around v (a removed one): every direction
    cone.width = cone.total;
    return;
  }
  cone.width = cone.total - 2 * pi + 2 * saddle_angle_tolerance;
  // back lies in [0, total) and total > pi: the start is in [0, 2 total), brought below total
  // by one subtraction, exact as std::fmod's
  cone.start = back + pi - saddle_angle_tolerance;
  if(cone.start >= cone.total)
    cone.start -= cone.total;
}

/// The cone for `emit_vertex_windows` of vertex v at distance `sigma` reached along `arrival`:
/// `cone`, set, for an interior, unglued vertex with a known arrival that is not a source
/// (sigma > 0); otherwise nullptr (every direction).
inline const Saddle_cone* saddle_cone_of(const Solver_mesh& m, int v, double sigma, const Arrival& arrival,
                                         Saddle_cone& cone)
{
  if(arrival.halfedge < 0 || !(sigma > 0) || m.is_border_vertex[std::size_t(v)] || m.is_glued(v))
    return nullptr;
  set_saddle_cone(m, v, arrival, cone);
  return &cone;
}

/// The start of the propagation from a (pseudo-)source at vertex v at distance `sigma`:
/// `relax(u, d, arrival)` for each neighbour u along its edge, and `add(g, w)` for a window w
/// (in the frame of half-edge g) on each edge opposite v, entering the face beyond it: the whole
/// edge, or with `cone` the part of it seen from v within the cone, if any.
template <class Relax, class Add>
void emit_vertex_windows(const Solver_mesh& m, int v, double sigma, Relax relax, Add add,
                         const Saddle_cone* cone = nullptr)
{
  if(cone && !(cone->width < cone->total))
    cone = nullptr;
  std::size_t k = 0;
  double around = 0; // the angle from m.first_outgoing[v] to h
  // (inlined: GCC left the body out of line, a call and its register saves a face)
  m.for_each_outgoing(v, [&](int h) CGAL_EXT_ALWAYS_INLINE {
    const Halfedge_frame fh = m.frame(h);
    relax(m.target(h), sigma + m.length(h), arrival_from(h, 0., 0., fh.length, 0.));
    const int across = Solver_mesh::next(h); // the edge opposite v in this face
    relax(m.target(across), sigma + m.length(Solver_mesh::prev(h)), arrival_from(h, 0., 0., fh.apex_x, fh.apex_y));
    const int g = m.opposite(across);
    double t0 = 0, t1 = 0, corner = 0; // the part of the face's corner at v within the cone
    if(cone) {
      corner = cone->corners[k++];
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for(double start : {cone->start, cone->start - cone->total}) {
        const double a = std::max(around, start), b = std::min(around + corner, start + cone->width);
        if(a <= b) {
          lo = std::min(lo, a);
          hi = std::max(hi, b);
        }
      }
      t0 = lo - around;
      t1 = hi - around;
      around += corner;
      if(!(t0 <= t1))
        return;
    }
    if(g < 0)
      return;
    const Halfedge_frame f = m.frame(across);
    Window_geometry w;
    w.b0 = 0;
    w.b1 = f.length;
    w.sx = f.length - f.apex_x; // g runs the other way along the same edge
    w.sy = -f.apex_y;
    w.sigma = sigma;
    if(cone) {
      // where the ray from v at angle t of the corner meets B -> C, as a fraction of it from B
      // (in the frame of h: v = (0, 0), B = (l, 0), C the apex)
      auto fraction = [&](double t) {
        const double c = std::cos(t), s = std::sin(t);
        return fh.length * s / (fh.apex_y * c - (fh.apex_x - fh.length) * s);
      };
      if(t1 < corner)
        w.b0 = std::min(std::max((1 - fraction(t1)) * f.length, 0.), f.length);
      if(t0 > 0)
        w.b1 = std::min(std::max((1 - fraction(t0)) * f.length, 0.), f.length);
      if(is_empty(w))
        return;
    }
    add(g, w);
  });
}

/// Calls `f(face, barycentric)` for the face of a face-point source and, when the point lies on
/// an edge, for the face across that edge, with the point's coordinates in that face.
template <class Function>
void for_each_face_seeing(const Solver_mesh& m, const Source_point& s, Function f)
{
  const auto& b = s.barycentric;
  f(s.face, b);
  for(int k = 0; k < 3; ++k) {
    if(b[(k + 2) % 3] > 0)
      continue;
    // The point lies on half-edge 3f+k: express it in the face across.
    const int h = 3 * s.face + k;
    const int o = m.opposite(h);
    if(o < 0)
      continue;
    std::array<double, 3> bo{{0., 0., 0.}};
    bo[o % 3] = b[(k + 1) % 3]; // o starts where h ends
    bo[Solver_mesh::next(o) % 3] = b[k];
    f(Solver_mesh::face(o), bo);
  }
}

/// The start of the propagation from a source inside a face (or on an edge of it): `relax(u, d)`
/// for each corner u of the faces that see it directly, and `add(g, w)` for a window on each of
/// their edges that do not contain it (in this face and, for a point on an edge, in the face
/// across that edge).
template <class Relax, class Add>
void emit_face_point_windows(const Solver_mesh& m, const Source_point& s, Relax relax, Add add)
{
  auto emit_in_face = [&](int face, const std::array<double, 3>& b) {
    for(int k = 0; k < 3; ++k) {
      const int h = 3 * face + k;
      const Halfedge_frame f = m.frame(h);
      const std::array<double, 2> q = m.point_in_frame(h, b);
      const double x = q[0], y = q[1];
      relax(m.source(h), norm2d(x, y), arrival_from(h, x, y, 0., 0.)); // corner k, the origin of this frame
      if(b[(k + 2) % 3] <= 0)
        continue; // the point lies on this edge
      const int g = m.opposite(h);
      if(g < 0)
        continue;
      Window_geometry w;
      w.b0 = 0;
      w.b1 = f.length;
      w.sx = f.length - x;
      w.sy = -y;
      w.sigma = 0;
      add(g, w);
    }
  };
  for_each_face_seeing(m, s, emit_in_face);
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_SOURCE_WINDOWS_H
