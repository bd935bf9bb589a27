// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_MESH_SOLVER_MESH_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_MESH_SOLVER_MESH_H

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Tolerances.h>
#include <CGAL_ext/Geodesics_3/internal/support/Inlining.h>

#include <CGAL/number_type_config.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// std::atan2(y, x) to within 3e-15 rad, without the library call: a saddle's cone takes the
/// angle of each face around it each time it emits. The ratio of the smaller to the larger of
/// |x| and |y| is brought within tan(pi/16) of 0, tan(pi/8) or 1 (the angle within pi/16 of 0,
/// pi/8 or pi/4), where the Taylor series of the arctangent to t^17 is exact to 3e-15.
inline double polar_angle(double y, double x)
{
  const double pi = CGAL_PI;
  const double ax = std::abs(x), ay = std::abs(y);
  const double larger = std::max(ax, ay);
  if(!(larger > 0))
    return std::atan2(y, x); // zeros (and NaN)
  const double a = std::min(ax, ay) / larger;
  const double tan_pi_16 = 0.19891236737965800691, tan_3pi_16 = 0.66817863791929891999,
               tan_pi_8 = 0.41421356237309504880;
  double base = 0, t = a;
  if(a >= tan_3pi_16) {
    base = pi / 4;
    t = (a - 1) / (a + 1);
  } else if(a >= tan_pi_16) {
    base = pi / 8;
    t = (a - tan_pi_8) / (1 + a * tan_pi_8);
  }
  const double u = t * t;
  const double series =
    1 + u * (-1. / 3 + u * (1. / 5 + u * (-1. / 7 + u * (1. / 9 + u * (-1. / 11 + u * (1. / 13 + u * (-1. / 15 + u / 17)))))));
  double r = base + t * series;
  if(ay > ax)
    r = pi / 2 - r;
  if(x < 0)
    r = pi - r;
  return std::signbit(y) ? -r : r;
}

/// Geometry of one half-edge h = (A -> B) seen from its own face (A, B, C): the edge length and
/// the apex C in the half-edge's frame (A at the origin, B at (length, 0), C above the x-axis).
struct Halfedge_frame
{
  double length;
  double apex_x;
  double apex_y;
};

/// The one test of a degenerate triangle, from its side lengths and twice its area: a side of
/// zero length, or a height below `degenerate_height_ratio` of the longest side.
inline bool is_degenerate_shape(double a, double b, double c, double twice_area)
{
  const double longest = std::max({a, b, c});
  return !(std::min({a, b, c}) > 0) || !(twice_area > degenerate_height_ratio * longest * longest);
}

/// A flat, index-based copy of a triangle mesh: everything the propagation cores read, built in
/// one pass so that no generic graph traversal runs inside a hot loop.
///
/// Half-edges are implicit: face f owns half-edges 3f, 3f+1, 3f+2; half-edge 3f+k runs from
/// corner k to corner k+1 of the face, so next/prev/face are arithmetic.
struct Solver_mesh
{
  std::size_t number_of_vertices = 0;
  std::size_t number_of_faces = 0;

  std::vector<std::array<double, 3>> position; // per vertex
  std::vector<std::int32_t> corner_vertex;     // per half-edge: its source vertex
  std::vector<std::int32_t> opposite_halfedge; // per half-edge, -1 on the border
  std::vector<double> halfedge_length;         // per half-edge
  // per face f: the apex of half-edge 3f in the frame of 3f; with the lengths, the frames of the
  // face's other two half-edges follow (see `frame`)
  std::vector<std::array<double, 2>> first_apex;
  std::vector<double> corner_angle;            // per half-edge: the angle at its source vertex; only while built
  std::vector<std::int32_t> first_outgoing;    // per vertex, -1 if isolated; a border one first
  std::vector<std::uint8_t> is_border_vertex;  // per vertex
  std::vector<std::uint8_t> is_pseudo_source;  // per vertex: saddle, border or glued vertex
  // Vertices [0, number_of_mesh_vertices) are the caller's; a non-manifold vertex keeps its first
  // fan, and each other fan gets a copy numbered from number_of_mesh_vertices on.
  std::size_t number_of_mesh_vertices = 0;
  std::vector<std::int32_t> mesh_vertex_of_copy; // per copy: the caller's vertex
  // The caller's vertices are numbered in the order the solver mesh's faces first name them
  // (`order_vertices`), so that the vertices of nearby faces are near in memory too: caller's
  // vertex i is solver-mesh vertex `cache_vertex(i)`, and solver-mesh vertex v below number_of_mesh_vertices
  // is caller's vertex `mesh_vertex(v)`.
  std::vector<std::int32_t> cache_vertex_of_mesh_vertex; // per caller's vertex
  std::vector<std::int32_t> mesh_vertex_of_cache_vertex; // per solver-mesh vertex below number_of_mesh_vertices
  // Glued vertices are one point of the surface (the copies of a non-manifold vertex, and the
  // vertices the caller says are one point): per vertex, the next one of its group, in a cycle.
  // Empty when no vertex is glued.
  std::vector<std::int32_t> next_glued;
  // Faces [0, number_of_mesh_faces) are the caller's, stored in the order of a Z-order curve
  // through their centroids (`order_faces`): faces near on the surface are near in memory, and
  // a propagation reads a face's surroundings together. Caller's face i is solver-mesh face
  // `cache_face(i)`, solver-mesh face f is caller's face `mesh_face(f)`. A degenerate (zero-area)
  // face is removed: a cap (its middle vertex on its longest edge) by splitting the face beyond
  // that edge at the middle vertex, which adds a face numbered from number_of_mesh_faces on; a
  // needle (an edge of zero length) by gluing the ends of that edge and making its two other
  // neighbours adjacent.
  std::size_t number_of_mesh_faces = 0;
  std::vector<std::int32_t> cache_face_of_mesh_face; // per caller's face
  std::vector<std::int32_t> mesh_face_of_cache_face; // per solver-mesh face below number_of_mesh_faces
  std::vector<std::int32_t> mesh_face_of_added; // per added face
  std::vector<std::uint8_t> face_state;          // per face: 0 as given, or changed/removed; empty when none is
  std::vector<std::int32_t> mesh_corner_vertex;  // the caller's corners, kept when a face changed
  static constexpr std::uint8_t face_changed = 1, face_removed = 2;

  // Positions are stored divided by `unit`, a power of two (1 unless the mesh is very large or
  // very small), and every length inside the solvers is in that unit.
  double unit = 1;
  double mean_edge_length = 0;
  double mean_anisotropy = 1; // mean over faces of p H / (2 sqrt(3) S); 1 for equilateral
  double bbox_diagonal = 0;

  static int next(int h) { return h % 3 == 2 ? h - 2 : h + 1; }
  static int prev(int h) { return h % 3 == 0 ? h + 2 : h - 1; }
  static int face(int h) { return h / 3; }
  int source(int h) const { return corner_vertex[h]; }
  int target(int h) const { return corner_vertex[next(h)]; }
  int apex(int h) const { return corner_vertex[prev(h)]; }
  int opposite(int h) const { return opposite_halfedge[h]; }
  std::size_t number_of_halfedges() const { return corner_vertex.size(); }
  /// The caller's vertex that vertex `v` of the solver mesh is (itself, or the vertex it is a copy of).
  int mesh_vertex(int v) const
  {
    return std::size_t(v) < number_of_mesh_vertices ? mesh_vertex_of_cache_vertex[std::size_t(v)]
                                                    : mesh_vertex_of_copy[std::size_t(v) - number_of_mesh_vertices];
  }
  /// The solver-mesh vertex that the caller's vertex `mesh_v` is (the fan it keeps, if it was split).
  int cache_vertex(int mesh_v) const { return cache_vertex_of_mesh_vertex[std::size_t(mesh_v)]; }
  /// The caller's face that face `f` of the solver mesh is, or lies in.
  int mesh_face(int f) const
  {
    return std::size_t(f) < number_of_mesh_faces ? mesh_face_of_cache_face[std::size_t(f)]
                                                 : mesh_face_of_added[std::size_t(f) - number_of_mesh_faces];
  }
  /// The solver-mesh face that the caller's face `mesh_f` is (or was, if the solver mesh changed it).
  int cache_face(int mesh_f) const { return cache_face_of_mesh_face[std::size_t(mesh_f)]; }
  bool is_face_changed(int f) const { return !face_state.empty() && face_state[std::size_t(f)] != 0; }
  bool is_face_removed(int f) const { return !face_state.empty() && (face_state[std::size_t(f)] & face_removed); }

  /// Frees the positions and the map from the caller's vertices (`cache_vertex`), for a caller
  /// that wants distances only and has placed its sources and stop vertices:
  /// the propagation reads the frames, and only the placing of face points, paths and the
  /// Voronoi diagram's points read positions after `finish()`.
  void release_positions()
  {
    std::vector<std::array<double, 3>>().swap(position);
    std::vector<std::int32_t>().swap(cache_vertex_of_mesh_vertex);
  }

  /// A point of solver-mesh face `f`, one of the caller's (`cache_face(i)`; barycentric coordinates `b`
  /// in its corner order, which is the caller's), as a point of a live face of the solver mesh: itself
  /// unless the face was changed or removed.
  void relocate_face_point(int& f, std::array<double, 3>& b) const;
  /// The caller's face in which point `p` (solver-mesh unit) of solver-mesh face `f` lies, as its solver-mesh index
  /// `given_f` (`cache_face(mesh_face(f))`), and the point's barycentric coordinates in the
  /// corners the caller gave that face.
  void mesh_face_point(int f, const std::array<double, 3>& p, int& given_f, std::array<double, 3>& mesh_b) const;

  bool is_glued(int v) const { return !next_glued.empty() && next_glued[std::size_t(v)] != v; }
  /// Whether u and v are two vertices glued at one point.
  bool are_glued(int u, int v) const
  {
    bool found = false;
    if(u != v && is_glued(u))
      for_each_glued(u, [&](int w) { found |= w == v; });
    return found;
  }
  /// Calls `f(u)` for `v` and every vertex glued to it: the vertices of one point of the surface.
  template <class Function>
  void for_each_copy_of_point(int v, Function f) const
  {
    f(v);
    for_each_glued(v, f);
  }
  /// Calls `f(u)` for every other vertex glued to `v`.
  template <class Function>
  void for_each_glued(int v, Function f) const
  {
    if(next_glued.empty())
      return;
    for(int u = next_glued[std::size_t(v)]; u != v; u = next_glued[std::size_t(u)])
      f(u);
  }

  double length(int h) const { return halfedge_length[std::size_t(h)]; }

  /// The frame of half-edge h. Only the frame of the face's first half-edge is stored; the other
  /// two are that triangle seen from another side, which costs a division here but saves two
  /// thirds of the memory that frames per half-edge would take. (A removed face keeps the
  /// values of the mesh as given; nothing asks for its frames.)
  CGAL_EXT_ALWAYS_INLINE Halfedge_frame frame(int h) const
  {
    const std::array<double, 2>& c = first_apex[std::size_t(face(h))];
    const double len = halfedge_length[std::size_t(h)];
    switch(h % 3) {
    case 0:
      return Halfedge_frame{len, c[0], c[1]};
    case 1: { // B -> C, apex A; in the first frame A = (0, 0), B = (l, 0), C = c
      const double l = halfedge_length[std::size_t(h - 1)];
      const double ratio = l / len;
      return Halfedge_frame{len, (l - c[0]) * ratio, c[1] * ratio};
    }
    default: { // C -> A, apex B
      const double l = halfedge_length[std::size_t(h - 2)];
      const double inverse = 1 / len;
      return Halfedge_frame{len, (c[0] * (c[0] - l) + c[1] * c[1]) * inverse, c[1] * l * inverse};
    }
    }
  }

  /// The angle of face(h) at the source of h (the corner angles of the setup and of a saddle's
  /// cone are this one).
  double angle_at_source(int h) const
  {
    const Halfedge_frame f = frame(h);
    return polar_angle(f.apex_y, f.apex_x);
  }

  /// The point of face(h) with barycentric coordinates b (in the order of the face's corners)
  /// in the frame of h: h's source at the origin, its target at (length, 0), the apex above.
  std::array<double, 2> point_in_frame(int h, const std::array<double, 3>& b) const
  {
    const int k = h % 3;
    const Halfedge_frame f = frame(h);
    return {{b[(k + 1) % 3] * f.length + b[(k + 2) % 3] * f.apex_x, b[(k + 2) % 3] * f.apex_y}};
  }

  /// The barycentric coordinates (of the plane of face(h), in the order of its corners) of the
  /// point (x, y) of the frame of h: the inverse of `point_in_frame`.
  std::array<double, 3> barycentric_in_frame(int h, double x, double y) const
  {
    const std::size_t k = std::size_t(h % 3);
    const Halfedge_frame f = frame(h);
    std::array<double, 3> b;
    b[(k + 2) % 3] = y / f.apex_y;
    b[(k + 1) % 3] = (x - b[(k + 2) % 3] * f.apex_x) / f.length;
    b[k] = 1 - b[(k + 1) % 3] - b[(k + 2) % 3];
    return b;
  }

  /// Calls `f(h)` for each half-edge leaving `v`, turning around `v` from the border (if any).
  template <class Function>
  void for_each_outgoing(int v, Function f) const
  {
    const int start = first_outgoing[v];
    if(start < 0)
      return;
    int h = start;
    do {
      f(h);
      h = opposite_halfedge[prev(h)];
    } while(h >= 0 && h != start);
  }

  /// The lowest and highest coordinates of the positions (+infinity and -infinity when none).
  std::array<std::array<double, 3>, 2> bounding_box() const
  {
    std::array<double, 3> low, high;
    low.fill(std::numeric_limits<double>::infinity());
    high.fill(-std::numeric_limits<double>::infinity());
    for(const std::array<double, 3>& p : position)
      for(int i = 0; i < 3; ++i) {
        low[i] = std::min(low[i], p[i]);
        high[i] = std::max(high[i], p[i]);
      }
    return {{low, high}};
  }

  /// Puts the faces, whose corners `corner_vertex` holds in the caller's order, in the order of
  /// a curve through their centroids (the positions must be set).
  void order_faces();
  /// Computes the frames, angles and flags once `position`, `corner_vertex` and
  /// `opposite_halfedge` are set: splits non-manifold vertices into one copy per fan, and glues
  /// the copies and the vertices of each of `glued_groups` (the caller's indices, checked).
  /// Removes degenerate triangles (see `face_state`).
  void finish(const std::vector<std::vector<int>>& glued_groups = {});

private:
  void remove_degenerate_faces(std::vector<std::vector<int>>& glued_groups);
  void split_face_at(int y, int c);
  bool compute_frames(); // false if a face is degenerate
  void split_non_manifold_vertices(const std::vector<std::int32_t>& corner_count);
  void order_vertices();
  void glue_vertices(const std::vector<std::vector<int>>& groups);
  void check_glued_groups(const std::vector<std::vector<int>>& groups) const;
  void compute_vertex_flags();
};

inline bool Solver_mesh::compute_frames()
{
  bool none_degenerate = true;
  const std::size_t nh = corner_vertex.size();
  halfedge_length.resize(nh);
  first_apex.resize(number_of_faces);
  corner_angle.resize(nh);
  double length_sum = 0;
  std::size_t edge_count = 0;
  double anisotropy_sum = 0;
  for(std::size_t f = 0; f < number_of_faces; ++f) {
    if(is_face_removed(int(f)))
      continue;
    const std::array<double, 3>* p[3];
    for(int k = 0; k < 3; ++k)
      p[k] = &position[corner_vertex[3 * f + k]];
    auto minus = [](const std::array<double, 3>& u, const std::array<double, 3>& v) {
      return std::array<double, 3>{{u[0] - v[0], u[1] - v[1], u[2] - v[2]}};
    };
    auto norm = [](const std::array<double, 3>& u) { return std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]); };
    for(int k = 0; k < 3; ++k) {
      const std::size_t h = 3 * f + k;
      halfedge_length[h] = norm(minus(*p[(k + 1) % 3], *p[k]));
      const int o = opposite_halfedge[h];
      if(o < 0 || static_cast<std::size_t>(o) > h) {
        length_sum += halfedge_length[h];
        ++edge_count;
      }
    }
    // the apex C of the first half-edge A -> B in its frame
    const std::array<double, 3> ab = minus(*p[1], *p[0]), ac = minus(*p[2], *p[0]);
    const double a = halfedge_length[3 * f], b = halfedge_length[3 * f + 1], c = halfedge_length[3 * f + 2];
    const double twice_area = norm({{ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]}});
    first_apex[f] = {{(ab[0] * ac[0] + ab[1] * ac[1] + ab[2] * ac[2]) / a, twice_area / a}};
    const double area = 0.5 * a * first_apex[f][1];
    if(is_degenerate_shape(a, b, c, 2 * area)) {
      none_degenerate = false; // removed, and the frames computed again
      continue;
    }
    // the corner angles from the frames the solvers use
    for(int k = 0; k < 3; ++k)
      corner_angle[3 * f + k] = angle_at_source(int(3 * f) + k);
    anisotropy_sum += 0.5 * (a + b + c) * std::max({a, b, c}) / (2 * std::sqrt(3.) * area);
  }
  mean_edge_length = edge_count ? length_sum / double(edge_count) : 0.;
  const std::size_t live_faces = number_of_faces - std::size_t(std::count_if(face_state.begin(), face_state.end(),
                                                                           [](std::uint8_t s) { return s & face_removed; }));
  mean_anisotropy = live_faces ? anisotropy_sum / double(live_faces) : 1.;
  return none_degenerate;
}

namespace mesh_geometry {
inline double distance(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
}
inline double twice_area(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c)
{
  const double ab[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double ac[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return std::hypot(ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]);
}
/// Barycentric coordinates of the projection of p on the plane of (a, b, c); false if degenerate.
inline bool barycentric(const std::array<double, 3>& a, const std::array<double, 3>& b, const std::array<double, 3>& c,
                        const std::array<double, 3>& p, std::array<double, 3>& out)
{
  double v0[3], v1[3], v2[3];
  for(int i = 0; i < 3; ++i) {
    v0[i] = b[i] - a[i];
    v1[i] = c[i] - a[i];
    v2[i] = p[i] - a[i];
  }
  auto dot = [](const double* x, const double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  const double d00 = dot(v0, v0), d01 = dot(v0, v1), d11 = dot(v1, v1), d20 = dot(v2, v0), d21 = dot(v2, v1);
  const double denominator = d00 * d11 - d01 * d01;
  if(!(denominator > 0))
    return false;
  out[1] = (d11 * d20 - d01 * d21) / denominator;
  out[2] = (d00 * d21 - d01 * d20) / denominator;
  out[0] = 1 - out[1] - out[2];
  return true;
}
} // namespace mesh_geometry

inline bool is_degenerate_triangle(const std::array<double, 3>& a, const std::array<double, 3>& b,
                                   const std::array<double, 3>& c)
{
  using mesh_geometry::distance;
  return is_degenerate_shape(distance(a, b), distance(b, c), distance(c, a), mesh_geometry::twice_area(a, b, c));
}

inline void Solver_mesh::relocate_face_point(int& f, std::array<double, 3>& b) const
{
  if(!is_face_changed(f))
    return;
  std::array<double, 3> p{{0., 0., 0.}};
  for(int k = 0; k < 3; ++k)
    for(int i = 0; i < 3; ++i)
      p[i] += b[k] * position[std::size_t(mesh_corner_vertex[std::size_t(3 * f + k)])][i];
  // the live face, around the corners, in which p lies deepest
  double deepest = -std::numeric_limits<double>::infinity();
  int best = -1;
  std::array<double, 3> best_b{{1., 0., 0.}};
  auto consider = [&](int h) {
    const int g = face(h);
    std::array<double, 3> c;
    if(!mesh_geometry::barycentric(position[std::size_t(corner_vertex[std::size_t(3 * g)])],
                                   position[std::size_t(corner_vertex[std::size_t(3 * g + 1)])],
                                   position[std::size_t(corner_vertex[std::size_t(3 * g + 2)])], p, c))
      return;
    const double depth = std::min({c[0], c[1], c[2]});
    if(depth > deepest) {
      deepest = depth;
      best = g;
      best_b = c;
    }
  };
  for(int k = 0; k < 3; ++k) {
    for_each_copy_of_point(mesh_corner_vertex[std::size_t(3 * f + k)], [&](int u) { for_each_outgoing(u, consider); });
  }
  if(best < 0)
    throw Geodesic_error("a point of degenerate face " + std::to_string(mesh_face(f)) + " lies in no face of the mesh");
  for(double& x : best_b)
    x = std::max(0., x);
  const double sum = best_b[0] + best_b[1] + best_b[2];
  for(double& x : best_b)
    x /= sum;
  f = best;
  b = best_b;
}

inline void Solver_mesh::mesh_face_point(int f, const std::array<double, 3>& p, int& given_f,
                                        std::array<double, 3>& mesh_b) const
{
  given_f = cache_face(mesh_face(f));
  // the corners of the caller's face, as given (a face the solver mesh added lies in a changed one)
  const auto& corners = is_face_changed(f) ? mesh_corner_vertex : corner_vertex;
  const std::size_t c = std::size_t(given_f);
  mesh_geometry::barycentric(position[std::size_t(corners[3 * c])], position[std::size_t(corners[3 * c + 1])],
                             position[std::size_t(corners[3 * c + 2])], p, mesh_b);
  for(double& x : mesh_b)
    x = std::max(0., x);
  const double sum = mesh_b[0] + mesh_b[1] + mesh_b[2];
  for(double& x : mesh_b)
    x /= sum;
}

inline void Solver_mesh::compute_vertex_flags()
{
  const std::size_t nv = position.size();
  is_border_vertex.assign(nv, 0);
  is_pseudo_source.assign(nv, 0);
  const double two_pi = 2 * CGAL_PI;
  for(std::size_t v = 0; v < nv; ++v) {
    double sum = 0;
    for_each_outgoing(int(v), [&](int h) { sum += corner_angle[h]; });
    const int h0 = first_outgoing[v];
    is_border_vertex[v] = (h0 >= 0 && opposite_halfedge[h0] < 0) ? 1 : 0;
    // a glued vertex passes paths on to the other fans through it, as a saddle does
    is_pseudo_source[v] =
      (is_border_vertex[v] || sum > two_pi - saddle_angle_tolerance || is_glued(int(v))) ? 1 : 0;
  }

  const auto [lo, hi] = bounding_box();
  bbox_diagonal = position.empty() ? 0. : std::hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_MESH_SOLVER_MESH_H
