// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_SOURCE_POINTS_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_SOURCE_POINTS_H

// The sources of a propagation in the solver mesh's indices, checked: vertices, or points of
// faces by barycentric coordinates.

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Tolerances.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh.h>

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


/// A source in the solver mesh's indices: a vertex, or a point of a face given by barycentric
/// coordinates in the order of the face's corners.
struct Source_point
{
  int vertex = -1;
  int face = -1;
  std::array<double, 3> barycentric{{0., 0., 0.}};
};

/// Per source, whether an earlier one is the same point: a repeat emits nothing, so that the
/// first of equal sources is the nearest (with both, the windows of the later one could win the
/// clipping's ties).
inline std::vector<bool> repeated_sources(const std::vector<Source_point>& sources)
{
  if(sources.size() < 2) // the single-source runs of sampling and of matrix rows
    return std::vector<bool>(sources.size(), false);
  std::vector<std::size_t> order(sources.size());
  for(std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  auto key = [&](std::size_t i) {
    const Source_point& s = sources[i];
    return std::make_tuple(s.vertex, s.face, s.barycentric);
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(a) < key(b); });
  std::vector<bool> repeated(sources.size(), false);
  for(std::size_t i = 1; i < order.size(); ++i)
    if(key(order[i]) == key(order[i - 1]))
      repeated[order[i]] = true;
  return repeated;
}

/// Whether vertex v (and every vertex glued to it) is in no face: no path leaves it.
inline bool is_isolated_point(const Solver_mesh& m, int v)
{
  bool any_face = false;
  m.for_each_copy_of_point(v, [&](int u) { any_face |= m.first_outgoing[std::size_t(u)] >= 0; });
  return !any_face;
}

/// Throws when there is no source, or when every source is a vertex in no face.
inline void check_has_sources(const Solver_mesh& m, const std::vector<Source_point>& sources)
{
  if(sources.empty())
    throw Geodesic_error("no source was given");
  auto isolated = [&](const Source_point& s) { return s.vertex >= 0 && is_isolated_point(m, s.vertex); };
  if(std::all_of(sources.begin(), sources.end(), isolated))
    throw Geodesic_error("source vertex " + std::to_string(m.mesh_vertex(sources.front().vertex)) +
                         " is in no face (an isolated vertex): no surface to measure distances on");
}

/// Throws unless `v` is a vertex index of the mesh; `role` names the point ("source", ...).
inline void check_vertex_index(const Solver_mesh& m, long v, const char* role)
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

/// Checks a point of face `face` given by barycentric coordinates (the solver mesh index of a face of
/// the caller, `Solver_mesh::cache_face`;
/// coordinates non-negative and summing to 1) and returns its coordinates with those that are
/// zero up to round-off made zero, summing to 1. `role` names the point in messages.
inline std::array<double, 3> checked_barycentric(const Solver_mesh& m, long face, const std::array<double, 3>& b,
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
inline Source_point normalized_source(const Solver_mesh& m, Source_point s)
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

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_KERNEL_SOURCE_POINTS_H
