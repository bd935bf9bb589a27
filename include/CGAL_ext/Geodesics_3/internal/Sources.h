// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_SOURCES_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_SOURCES_H

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Tolerances.h>
#include <CGAL_ext/Geodesics_3/internal/Mesh_cache.h>
#include <CGAL_ext/Geodesics_3/internal/Window.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
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

/// Throws when there is no source to start from.
/// Throws when there is no source, or when every source is a vertex in no face.
/// Whether vertex v (and every vertex glued to it) is in no face: no path leaves it.
inline bool is_isolated_point(const Mesh_cache& m, int v)
{
  bool any_face = false;
  m.for_each_copy_of_point(v, [&](int u) { any_face |= m.first_outgoing[std::size_t(u)] >= 0; });
  return !any_face;
}

inline void check_has_sources(const Mesh_cache& m, const std::vector<Source_point>& sources)
{
  if(sources.empty())
    throw Geodesic_error("no source was given");
  auto isolated = [&](const Source_point& s) { return s.vertex >= 0 && is_isolated_point(m, s.vertex); };
  if(std::all_of(sources.begin(), sources.end(), isolated))
    throw Geodesic_error("source vertex " + std::to_string(sources.front().vertex) +
                         " is in no face (an isolated vertex): no surface to measure distances on");
}

/// Throws unless `v` is a vertex index of the mesh; `role` names the point ("source", ...).
inline void check_vertex_index(const Mesh_cache& m, long v, const char* role)
{
  if(v < 0 || std::size_t(v) >= m.number_of_mesh_vertices)
    throw Geodesic_error(std::string(role) + " vertex " + std::to_string(v) + " is out of range (the mesh has " +
                         std::to_string(m.number_of_mesh_vertices) + " vertices)");
}

/// Barycentric coordinates with those below `barycentric_snap` made 0 (the point is then on an
/// edge or at a corner), the others scaled to sum to 1.
inline std::array<double, 3> snapped_barycentric(std::array<double, 3> b)
{
  double sum = 0;
  for(double& c : b) {
    if(c < barycentric_snap)
      c = 0;
    sum += c;
  }
  for(double& c : b)
    c /= sum;
  return b;
}

/// Checks a point of face `face` given by barycentric coordinates (the cache index of a face of
/// the caller, `Mesh_cache::cache_face`;
/// coordinates non-negative and summing to 1) and returns its coordinates with those that are
/// zero up to round-off made zero, summing to 1. `role` names the point in messages.
inline std::array<double, 3> checked_barycentric(const Mesh_cache& m, long face, const std::array<double, 3>& b,
                                                 const char* role)
{
  if(face < 0 || std::size_t(face) >= m.number_of_mesh_faces)
    throw Geodesic_error(std::string(role) + " face " + std::to_string(face) + " is out of range (the mesh has " +
                         std::to_string(m.number_of_mesh_faces) + " faces)");
  const double sum = b[0] + b[1] + b[2];
  if(!std::isfinite(sum) || std::abs(sum - 1.) > barycentric_sum_tolerance || b[0] < -barycentric_snap ||
     b[1] < -barycentric_snap || b[2] < -barycentric_snap) {
    std::ostringstream msg;
    msg.precision(17);
    msg << "barycentric coordinates (" << b[0] << ", " << b[1] << ", " << b[2] << ") of the " << role << " in face "
        << m.mesh_face(int(face)) << " must be non-negative and sum to 1";
    throw Geodesic_error(msg.str());
  }
  return snapped_barycentric(b);
}

/// Checks a source and turns a face point that sits on a corner into a vertex source.
inline Source_point normalized_source(const Mesh_cache& m, Source_point s)
{
  if(s.vertex >= 0) {
    check_vertex_index(m, s.vertex, "source");
    return s;
  }
  s.barycentric = checked_barycentric(m, s.face, s.barycentric, "source");
  m.relocate_face_point(s.face, s.barycentric);
  for(int k = 0; k < 3; ++k)
    if(s.barycentric[k] >= 1.) {
      Source_point v;
      v.vertex = m.source(3 * s.face + k);
      return v;
    }
  return s;
}

/// The start of the propagation from a (pseudo-)source at vertex v at distance `sigma`:
/// `relax(u, d)` for each neighbour u along its edge, and `add(g, w)` for a whole-edge window w
/// (in the frame of half-edge g) on each edge opposite v, entering the face beyond it.
template <class Relax, class Add>
void emit_vertex_windows(const Mesh_cache& m, int v, double sigma, Relax relax, Add add)
{
  m.for_each_outgoing(v, [&](int h) {
    relax(m.target(h), sigma + m.length(h));
    const int across = Mesh_cache::next(h); // the edge opposite v in this face
    relax(m.target(across), sigma + m.length(Mesh_cache::prev(h)));
    const int g = m.opposite(across);
    if(g < 0)
      return;
    const Halfedge_frame f = m.frame(across);
    Window_geometry w;
    w.b0 = 0;
    w.b1 = f.length;
    w.sx = f.length - f.apex_x; // g runs the other way along the same edge
    w.sy = -f.apex_y;
    w.sigma = sigma;
    add(g, w);
  });
}

/// Calls `f(face, barycentric)` for the face of a face-point source and, when the point lies on
/// an edge, for the face across that edge, with the point's coordinates in that face.
template <class Function>
void for_each_face_seeing(const Mesh_cache& m, const Source_point& s, Function f)
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
    bo[Mesh_cache::next(o) % 3] = b[k];
    f(Mesh_cache::face(o), bo);
  }
}

/// The start of the propagation from a source inside a face (or on an edge of it): `relax(u, d)`
/// for each corner u of the faces that see it directly, and `add(g, w)` for a window on each of
/// their edges that do not contain it (in this face and, for a point on an edge, in the face
/// across that edge).
template <class Relax, class Add>
void emit_face_point_windows(const Mesh_cache& m, const Source_point& s, Relax relax, Add add)
{
  auto emit_in_face = [&](int face, const std::array<double, 3>& b) {
    for(int k = 0; k < 3; ++k) {
      const int h = 3 * face + k;
      const Halfedge_frame f = m.frame(h);
      const std::array<double, 2> q = m.point_in_frame(h, b);
      const double x = q[0], y = q[1];
      relax(m.source(h), norm2d(x, y)); // distance to corner k, the origin of this frame
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

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_SOURCES_H
