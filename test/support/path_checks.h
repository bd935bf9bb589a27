// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Checks of the shortest paths of CGAL_ext::Surface_mesh_geodesic_paths: what every shortest
// path must be, where it starts and ends, distances to polylines, and path comparisons. The
// templates take the class's Path_point type, so this header does not need the class.
#ifndef CGAL_EXT_TEST_SUPPORT_PATH_CHECKS_H
#define CGAL_EXT_TEST_SUPPORT_PATH_CHECKS_H

#include "meshes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

namespace test_support {

/// the sum of the angles at v of the faces around v
inline double angle_sum(const Mesh& m, Vertex v)
{
  double sum = 0;
  for(auto h : m.halfedges_around_target(m.halfedge(v))) {
    if(m.is_border(h))
      continue;
    const Vector a = m.point(m.source(h)) - m.point(v), b = m.point(m.target(m.next(h))) - m.point(v);
    sum += std::atan2(std::sqrt(CGAL::cross_product(a, b).squared_length()), a * b);
  }
  return sum;
}

/// whether a shortest path may pass through v: a border vertex, or a saddle (angle sum above
/// 2 pi, up to the 1e-6 the solvers also use)
inline bool is_saddle_or_border(const Mesh& m, Vertex v)
{
  return m.is_border(v) || angle_sum(m, v) > 2 * pi - 1e-6;
}

/// the distance from p to the polyline (to its only point if it has one, +infinity if empty)
inline double distance_to_polyline(const Point& p, const std::vector<Point>& line)
{
  if(line.size() == 1)
    return distance_3(p, line[0]);
  double d = inf;
  for(std::size_t i = 1; i < line.size(); ++i)
    d = std::min(d, line[i - 1] == line[i] ? distance_3(p, line[i])
                                           : std::sqrt(CGAL::squared_distance(p, K::Segment_3(line[i - 1], line[i]))));
  return d;
}

/// the largest distance from a point of `points` to the polyline `line`
inline double max_distance_to_polyline(const std::vector<Point>& points, const std::vector<Point>& line)
{
  double d = 0;
  for(const Point& p : points)
    d = std::max(d, distance_to_polyline(p, line));
  return d;
}

/// the positions of a path's points
template <class PathPoint>
std::vector<Point> positions(const std::vector<PathPoint>& path)
{
  std::vector<Point> p;
  for(const PathPoint& q : path)
    p.push_back(q.point);
  return p;
}

/// the position of a path point computed from where it lies (vertex, edge and t, face and
/// barycentric coordinates), independently of its `point`
template <class PathPoint>
Point path_point_position(const Mesh& m, const PathPoint& p)
{
  if(p.kind == PathPoint::VERTEX)
    return m.point(p.vertex);
  if(p.kind == PathPoint::EDGE)
    return CGAL::barycenter(m.point(m.source(p.halfedge)), 1 - p.t, m.point(m.target(p.halfedge)), p.t);
  return location_point(m, Face_location(p.face, Barycentric{{p.barycentric[0], p.barycentric[1], p.barycentric[2]}}));
}

/// the faces whose closure contains a path point (a face point with a zero coordinate also
/// lies in the face across that edge, or around that vertex)
template <class PathPoint>
std::vector<Face> faces_of(const Mesh& m, const PathPoint& p)
{
  std::vector<Face> faces;
  auto around = [&](Vertex v) {
    for(Face f : m.faces_around_target(m.halfedge(v)))
      if(f != Mesh::null_face())
        faces.push_back(f);
  };
  if(p.kind == PathPoint::VERTEX)
    around(p.vertex);
  else if(p.kind == PathPoint::EDGE) {
    for(auto h : {p.halfedge, m.opposite(p.halfedge)})
      if(!m.is_border(h))
        faces.push_back(m.face(h));
  } else {
    faces.push_back(p.face);
    const auto c = face_corners(m, p.face);
    const int zeros = zero_coordinates(p.barycentric);
    for(int k = 0; k < 3; ++k) {
      if(p.barycentric[k] != 0)
        continue;
      if(zeros == 2 && p.barycentric[(k + 1) % 3] != 0)
        around(c[(k + 1) % 3]);
      if(zeros == 1) {
        const auto h = m.opposite(m.halfedge(c[(k + 1) % 3], c[(k + 2) % 3]));
        if(!m.is_border(h))
          faces.push_back(m.face(h));
      }
    }
  }
  std::sort(faces.begin(), faces.end());
  faces.erase(std::unique(faces.begin(), faces.end()), faces.end());
  return faces;
}

/// Checks what every shortest path must be, whatever its ends: not empty; each point where it
/// says it is (its `point` within `slack` x diagonal of the position its kind gives, an edge
/// parameter strictly inside (0, 1), barycentric coordinates non-negative and summing to 1);
/// consecutive points in the closure of a common face; interior points never inside a face, and
/// interior vertices saddles or border vertices (a geodesic cannot bend at any other vertex).
template <class PathPoint>
::testing::AssertionResult is_valid_path(const Mesh& m, const std::vector<PathPoint>& path, double slack = 1e-14)
{
  if(path.empty())
    return ::testing::AssertionFailure() << "empty path";
  const double eps = slack * bbox_diagonal(m);
  auto describe = [&](std::size_t i) {
    const PathPoint& p = path[i];
    std::ostringstream s;
    s.precision(17);
    s << "point " << i << " of " << path.size() << " (";
    if(p.kind == PathPoint::VERTEX)
      s << "vertex " << p.vertex;
    else if(p.kind == PathPoint::EDGE)
      s << "edge " << m.source(p.halfedge) << "->" << m.target(p.halfedge) << " at t=" << p.t;
    else
      s << "face " << p.face << " at (" << p.barycentric[0] << ", " << p.barycentric[1] << ", " << p.barycentric[2]
        << ")";
    s << ", position " << p.point << ")";
    return s.str();
  };
  for(std::size_t i = 0; i < path.size(); ++i) {
    const PathPoint& p = path[i];
    if(p.kind == PathPoint::EDGE && !(p.t > 0 && p.t < 1))
      return ::testing::AssertionFailure() << describe(i) << ": edge parameter outside (0, 1)";
    if(p.kind == PathPoint::FACE) {
      const double sum = p.barycentric[0] + p.barycentric[1] + p.barycentric[2];
      if(!(std::abs(sum - 1) <= 1e-12) || !(p.barycentric[0] >= 0 && p.barycentric[1] >= 0 && p.barycentric[2] >= 0))
        return ::testing::AssertionFailure() << describe(i) << ": not a convex combination";
    }
    const double off = distance_3(p.point, path_point_position(m, p));
    if(!(off <= eps))
      return ::testing::AssertionFailure() << describe(i) << ": " << off << " away from where its kind places it";
    if(i > 0) {
      const std::vector<Face> a = faces_of(m, path[i - 1]), b = faces_of(m, p);
      std::vector<Face> common;
      std::set_intersection(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(common));
      if(common.empty())
        return ::testing::AssertionFailure() << describe(i - 1) << " and " << describe(i) << " share no face";
    }
    if(i == 0 || i + 1 == path.size())
      continue;
    if(p.kind == PathPoint::FACE)
      return ::testing::AssertionFailure() << describe(i) << ": an interior point inside a face";
    if(p.kind == PathPoint::VERTEX && !is_saddle_or_border(m, p.vertex))
      return ::testing::AssertionFailure() << describe(i) << ": passes through a vertex of angle sum "
                                           << angle_sum(m, p.vertex) << " (neither saddle nor border)";
  }
  return ::testing::AssertionSuccess();
}

/// The first point of a path is source i of `s`, exactly.
template <class PathPoint>
::testing::AssertionResult starts_at_source(const Mesh& m, const Sources& s, std::size_t i, const PathPoint& p)
{
  if(i < s.vertices.size()) {
    const Vertex v = s.vertices[i];
    if(p.kind != PathPoint::VERTEX || p.vertex != v || p.point != m.point(v))
      return ::testing::AssertionFailure() << "the path does not start at source vertex " << v << " (kind "
                                           << int(p.kind) << ", at " << p.point << ")";
    return ::testing::AssertionSuccess();
  }
  const Face_location& l = s.faces[i - s.vertices.size()];
  const double off = distance_3(p.point, location_point(m, l));
  const std::vector<Face> f = faces_of(m, p);
  if(!(off <= 1e-14 * bbox_diagonal(m)) || std::find(f.begin(), f.end(), l.first) == f.end())
    return ::testing::AssertionFailure() << "the path starts " << off << " away from source " << i << " in face "
                                         << l.first << " (kind " << int(p.kind) << ")";
  return ::testing::AssertionSuccess();
}

/// The last point of a path is the target, exactly, and says where it is.
template <class PathPoint>
::testing::AssertionResult ends_at_target(const Mesh& m, Vertex v, const PathPoint& p)
{
  if(p.kind != PathPoint::VERTEX || p.vertex != v || p.point != m.point(v))
    return ::testing::AssertionFailure() << "the path does not end at vertex " << v;
  return ::testing::AssertionSuccess();
}
template <class PathPoint>
::testing::AssertionResult ends_at_target(const Mesh& m, const Face_location& l, const PathPoint& p)
{
  const double off = distance_3(p.point, location_point(m, l));
  if(!(off <= 1e-14 * bbox_diagonal(m)))
    return ::testing::AssertionFailure() << "the path ends " << off << " away from the target";
  const auto c = face_corners(m, l.first);
  switch(zero_coordinates(l.second)) {
  case 0:
    if(p.kind != PathPoint::FACE || p.face != l.first)
      return ::testing::AssertionFailure() << "a target inside face " << l.first << " ends as kind " << int(p.kind);
    for(int k = 0; k < 3; ++k)
      if(!(std::abs(p.barycentric[k] - l.second[k]) <= 1e-15))
        return ::testing::AssertionFailure() << "the target's coordinate " << k << " is " << p.barycentric[k];
    break;
  case 1: {
    if(p.kind != PathPoint::EDGE)
      return ::testing::AssertionFailure() << "a target on an edge ends as kind " << int(p.kind);
    const std::vector<Face> f = faces_of(m, p);
    if(std::find(f.begin(), f.end(), l.first) == f.end())
      return ::testing::AssertionFailure() << "the target's edge is not an edge of face " << l.first;
    break;
  }
  default:
    for(int k = 0; k < 3; ++k)
      if(l.second[k] == 1 && (p.kind != PathPoint::VERTEX || p.vertex != c[k]))
        return ::testing::AssertionFailure() << "a target at corner " << c[k] << " ends as kind " << int(p.kind);
  }
  return ::testing::AssertionSuccess();
}

/// whether two paths name the same places (kinds, vertices, half-edges and parameters, faces
/// and barycentric coordinates), point for point and bit for bit; positions are not compared
template <class PathPoint>
bool same_places(const std::vector<PathPoint>& a, const std::vector<PathPoint>& b)
{
  if(a.size() != b.size())
    return false;
  for(std::size_t i = 0; i < a.size(); ++i) {
    const PathPoint &p = a[i], &q = b[i];
    if(p.kind != q.kind)
      return false;
    if(p.kind == PathPoint::VERTEX && p.vertex != q.vertex)
      return false;
    if(p.kind == PathPoint::EDGE && (p.halfedge != q.halfedge || p.t != q.t))
      return false;
    if(p.kind == PathPoint::FACE && (p.face != q.face || p.barycentric != q.barycentric))
      return false;
  }
  return true;
}

/// whether two paths are the same, point for point and bit for bit, positions included
template <class PathPoint>
bool identical_paths(const std::vector<PathPoint>& a, const std::vector<PathPoint>& b)
{
  if(!same_places(a, b))
    return false;
  for(std::size_t i = 0; i < a.size(); ++i)
    if(a[i].point != b[i].point)
      return false;
  return true;
}

} // namespace test_support

#endif // CGAL_EXT_TEST_SUPPORT_PATH_CHECKS_H
