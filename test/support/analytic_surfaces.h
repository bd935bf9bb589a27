// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Generated surfaces whose geodesic distances are known in closed form: planar grids (also
// L-shaped), an open cylinder and a cone (developable: their vertices carry their developed
// planar position), a cube and a regular tetrahedron; and those closed forms.
#ifndef CGAL_EXT_TEST_SUPPORT_ANALYTIC_SURFACES_H
#define CGAL_EXT_TEST_SUPPORT_ANALYTIC_SURFACES_H

#include "meshes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

namespace test_support {

/// The developed (unrolled) planar position of each vertex of a generated developable mesh,
/// stored as the property "v:developed"; the analytic tests compute exact distances from it.
inline Mesh::Property_map<Vertex, Point_2> developed_map(Mesh& m)
{
  return m.add_property_map<Vertex, Point_2>("v:developed", Point_2(0, 0)).first;
}
inline Mesh::Property_map<Vertex, Point_2> developed_map(const Mesh& m)
{
  auto found = m.property_map<Vertex, Point_2>("v:developed");
  if(!found.second)
    throw std::runtime_error("the mesh has no developed coordinates");
  return found.first;
}

/// The developed position of a face location. Faces that straddle the seam of a periodic
/// development (cylinder, cone) have corners developed on both ends: `unwrapped(ref, q)` moves
/// each corner q next to the first one, ref, before combining.
template <class Unwrap>
Point_2 developed_location(const Mesh& m, const Face_location& l, Unwrap unwrapped)
{
  const auto dev = developed_map(m);
  const auto c = face_corners(m, l.first);
  const Point_2 p0 = get(dev, c[0]);
  const Point_2 p1 = unwrapped(p0, get(dev, c[1]));
  const Point_2 p2 = unwrapped(p0, get(dev, c[2]));
  return Point_2(l.second[0] * p0.x() + l.second[1] * p1.x() + l.second[2] * p2.x(),
                 l.second[0] * p0.y() + l.second[1] * p1.y() + l.second[2] * p2.y());
}

// ---------------------------------------------------------------------------------------------
// Planar grids

/// A planar (z = 0) grid of n x n points of spacing h, each cell cut along one of its diagonals,
/// alternating like a checkerboard. Interior points are moved by up to `jitter` * h in x and y
/// (border points stay, so the domain stays the square). With `l_shape`, the cells of the
/// upper-right quadrant are left out: the domain is an L with one reflex corner at the grid
/// point (n/2, n/2).
inline Mesh make_grid(int n, double h, double jitter = 0, bool l_shape = false, unsigned seed = 1)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter * h, jitter * h);
  const int half = (n - 1) / 2;
  auto used = [&](int i, int j) { return !l_shape || i <= half || j <= half; };
  std::vector<Point> points;
  std::vector<int> index(n * n, -1);
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      if(!used(i, j))
        continue;
      double x = i * h, y = j * h;
      const bool border = i == 0 || j == 0 || i == n - 1 || j == n - 1 ||
                          (l_shape && (i == half || j == half) && i >= half && j >= half);
      if(jitter > 0 && !border) {
        x += u(rng);
        y += u(rng);
      }
      index[j * n + i] = int(points.size());
      points.push_back(Point(x, y, 0));
    }
  std::vector<Triangle> triangles;
  for(int j = 0; j + 1 < n; ++j)
    for(int i = 0; i + 1 < n; ++i) {
      if(l_shape && i >= half && j >= half)
        continue;
      add_quad(triangles, index[j * n + i], index[j * n + i + 1], index[(j + 1) * n + i + 1],
               index[(j + 1) * n + i], (i + j) % 2 == 0);
    }
  Mesh m = mesh_from_soup(points, triangles);
  auto dev = developed_map(m);
  for(Vertex v : m.vertices())
    put(dev, v, Point_2(m.point(v).x(), m.point(v).y()));
  return m;
}

/// The L-shaped domain of `make_grid(n, h, jitter, true)`: the square without the open quadrant
/// {x > corner.x, y > corner.y}, `corner` its reflex corner.
struct L_shape
{
  Point_2 corner;

  /// whether the open segment pq passes through the removed quadrant: q is hidden from p
  bool hides(const Point_2& p, const Point_2& q) const
  {
    double lo = 0, hi = 1;
    for(int axis = 0; axis < 2; ++axis) {
      const double a = axis ? p.y() : p.x(), b = axis ? q.y() : q.x(), t = axis ? corner.y() : corner.x();
      if(a == b) {
        if(!(a > t))
          return false;
        continue;
      }
      const double cross = (t - a) / (b - a); // where the coordinate equals t
      if(b > a)
        lo = std::max(lo, cross);
      else
        hi = std::min(hi, cross);
    }
    return lo < hi - 1e-15;
  }

  /// the geodesic distance in the domain: straight, or around the reflex corner when hidden
  double distance(const Point_2& p, const Point_2& q) const
  {
    if(hides(p, q))
      return std::sqrt(CGAL::squared_distance(p, corner)) + std::sqrt(CGAL::squared_distance(corner, q));
    return std::sqrt(CGAL::squared_distance(p, q));
  }
};

/// the domain of `make_grid(n, h, jitter, true)`: its reflex corner is the grid point (n/2, n/2)
inline L_shape grid_l_shape(int n, double h)
{
  const int half = (n - 1) / 2;
  return L_shape{Point_2(half * h, half * h)};
}

// ---------------------------------------------------------------------------------------------
// The open cylinder

/// The development of the side of `make_cylinder`: a strip of width `width` (the number of
/// segments times the chord), periodic in its first coordinate.
struct Strip
{
  double width;

  /// q moved by the width, if need be, to within half the width of ref
  Point_2 unwrapped(const Point_2& ref, const Point_2& q) const
  {
    if(q.x() - ref.x() > width / 2)
      return Point_2(q.x() - width, q.y());
    if(ref.x() - q.x() > width / 2)
      return Point_2(q.x() + width, q.y());
    return q;
  }

  /// The geodesic distance between two developed points: the strip is convex across its
  /// height, so it is the smallest planar distance between p and the copies of q shifted by
  /// multiples of the width (two either way cover unwrapped points too).
  double distance(const Point_2& p, const Point_2& q) const
  {
    double best = inf;
    for(int shift = -2; shift <= 2; ++shift)
      best = std::min(best, std::hypot(q.x() - p.x() + shift * width, q.y() - p.y()));
    return best;
  }
};

/// the development of the side of `make_cylinder(r, segments, ...)`
inline Strip cylinder_strip(double r, int segments) { return Strip{segments * 2 * r * std::sin(pi / segments)}; }

/// An open polyhedral cylinder (side only): `segments` vertices around on a circle of radius r,
/// `rows` + 1 rings between z = 0 and z = height. The developed position of vertex (k, j) is
/// (k * chord, z_j), with chord = 2 r sin(pi / segments): the development is a strip of width
/// segments * chord, periodic in its first coordinate (`cylinder_strip`).
inline Mesh make_cylinder(double r, int segments, double height, int rows)
{
  const double chord = 2 * r * std::sin(pi / segments);
  std::vector<Point> points;
  std::vector<Point_2> developed;
  for(int j = 0; j <= rows; ++j)
    for(int k = 0; k < segments; ++k) {
      const double a = 2 * pi * k / segments, z = height * j / rows;
      points.push_back(Point(r * std::cos(a), r * std::sin(a), z));
      developed.push_back(Point_2(k * chord, z));
    }
  std::vector<Triangle> triangles;
  for(int j = 0; j < rows; ++j)
    for(int k = 0; k < segments; ++k) {
      const int k1 = (k + 1) % segments;
      add_quad(triangles, j * segments + k, j * segments + k1, (j + 1) * segments + k1,
               (j + 1) * segments + k, (j + k) % 2 == 0);
    }
  Mesh m = mesh_from_soup(points, triangles);
  auto dev = developed_map(m);
  for(Vertex v : m.vertices())
    put(dev, v, developed[v.idx()]);
  return m;
}

// ---------------------------------------------------------------------------------------------
// The cone

/// The development of the side of `make_cone`: a sector of angle `angle` around the apex at the
/// origin; the vertices are developed at polar angles in [0, angle).
struct Sector
{
  double angle;

  static double polar_angle(const Point_2& p) { return std::atan2(p.y(), p.x()); }

  /// q turned by the sector's angle, if need be, to within half of it of ref's polar angle
  Point_2 unwrapped(const Point_2& ref, const Point_2& q) const
  {
    const double d = polar_angle(q) - polar_angle(ref);
    const double turn = d > angle / 2 ? -angle : (d < -angle / 2 ? angle : 0.);
    return Point_2(q.x() * std::cos(turn) - q.y() * std::sin(turn), q.x() * std::sin(turn) + q.y() * std::cos(turn));
  }

  /// The geodesic distance between two developed points at polar (r1, a1) and (r2, a2). From the
  /// apex it is the other radius. When the sector is narrower than pi, the development cut along
  /// any generator is convex: the distance is the planar one across the smaller angular gap,
  /// |a1 - a2| or angle - |a1 - a2| (only differences of polar angles modulo the sector's angle
  /// matter, so unwrapped points may lie slightly outside [0, angle)). A gap of pi or more, which
  /// only a cone of angle above 2 pi has (a saddle at the apex), is crossed through the apex.
  double distance(const Point_2& p, const Point_2& q) const
  {
    const double r1 = std::hypot(p.x(), p.y()), r2 = std::hypot(q.x(), q.y());
    if(r1 == 0 || r2 == 0)
      return r1 + r2;
    double gap = std::fmod(std::abs(polar_angle(p) - polar_angle(q)), angle);
    gap = std::min(gap, angle - gap);
    if(gap >= pi)
      return r1 + r2;
    return std::sqrt(std::max(0., r1 * r1 + r2 * r2 - 2 * r1 * r2 * std::cos(gap)));
  }
};

/// the angle at the apex of each face of `make_cone(r, height, segments, ...)`:
/// 2 asin(chord / (2 slant))
inline double cone_face_angle(double r, double height, int segments)
{
  const double slant = std::hypot(r, height);
  const double chord = 2 * r * std::sin(pi / segments);
  return 2 * std::asin(chord / (2 * slant));
}

/// the development of the side of `make_cone(r, height, segments, ...)`: a sector of angle
/// segments times the apex angle of a face
inline Sector cone_sector(double r, double height, int segments)
{
  return Sector{segments * cone_face_angle(r, height, segments)};
}

/// A polyhedral cone (side only, open at the base): the apex (vertex 0) at (0, 0, height) and
/// `rings` rings of `segments` vertices on the generators, ring j at the fraction j / rings of
/// the slant from the apex; the last ring is the base circle of radius r. Every face lies in the
/// plane of the apex triangle it belongs to, so the cone develops into a planar sector
/// (`cone_sector`). The developed position (polar) of vertex (k, j) is radius j / rings * slant,
/// angle k * alpha, stored as a Cartesian Point_2.
inline Mesh make_cone(double r, double height, int segments, int rings)
{
  const double slant = std::hypot(r, height);
  const double alpha = cone_face_angle(r, height, segments);
  std::vector<Point> points{Point(0, 0, height)};
  std::vector<Point_2> developed{Point_2(0, 0)};
  for(int j = 1; j <= rings; ++j)
    for(int k = 0; k < segments; ++k) {
      const double a = 2 * pi * k / segments, t = double(j) / rings;
      points.push_back(Point(t * r * std::cos(a), t * r * std::sin(a), height * (1 - t)));
      developed.push_back(Point_2(t * slant * std::cos(k * alpha), t * slant * std::sin(k * alpha)));
    }
  auto id = [&](int k, int j) { return j == 0 ? 0 : 1 + (j - 1) * segments + (k % segments); };
  std::vector<Triangle> triangles;
  for(int k = 0; k < segments; ++k) {
    triangles.push_back({id(k, 0), id(k, 1), id(k + 1, 1)});
    for(int j = 1; j < rings; ++j) {
      triangles.push_back({id(k, j), id(k, j + 1), id(k + 1, j + 1)});
      triangles.push_back({id(k, j), id(k + 1, j + 1), id(k + 1, j)});
    }
  }
  Mesh m = mesh_from_soup(points, triangles);
  auto dev = developed_map(m);
  for(Vertex v : m.vertices())
    put(dev, v, developed[v.idx()]);
  return m;
}

/// A pleated cone: a saddle of angle sum above 2 pi at the apex (vertex 0, at the origin), flat
/// everywhere else. Its `segments` generators (an even number) leave the apex upwards and
/// downwards in turn, at slope `tilt`; `rings` rings of vertices on them, vertex
/// 1 + (j - 1) segments + k on generator k at the fraction j / rings of the unit slant; each quad
/// between two rings and two generators has a vertex inside it (off the generators, at an angle
/// around the apex that changes from ring to ring: the apex reaches these only by windows). The faces between two
/// generators lie in one plane through the apex, so the surface develops around the apex into a
/// sector of angle `segments` times the angle alpha between two generators (above 2 pi when the
/// pleats are deep). `polar` receives each vertex's developed polar coordinates (radius, angle in
/// [0, segments alpha)). Between points more than pi apart around the apex, the shortest path
/// passes through it.
inline Mesh make_pleated_cone(int segments, int rings, double tilt, std::vector<std::pair<double, double>>& polar)
{
  std::vector<Vector> generator;
  for(int k = 0; k < segments; ++k) {
    const double a = 2 * pi * k / segments;
    const Vector u(std::cos(a), std::sin(a), k % 2 == 0 ? tilt : -tilt);
    generator.push_back(u / std::sqrt(u.squared_length()));
  }
  const double alpha = std::acos(generator[0] * generator[1]);
  std::vector<Point> points{Point(0, 0, 0)};
  polar.assign(1, {0., 0.});
  for(int j = 1; j <= rings; ++j)
    for(int k = 0; k < segments; ++k) {
      const double t = double(j) / rings;
      points.push_back(CGAL::ORIGIN + t * generator[std::size_t(k)]);
      polar.emplace_back(t, k * alpha);
    }
  auto id = [&](int k, int j) { return j == 0 ? 0 : 1 + (j - 1) * segments + (k % segments); };
  std::vector<Triangle> triangles;
  for(int k = 0; k < segments; ++k) {
    triangles.push_back({id(k, 0), id(k, 1), id(k + 1, 1)});
    for(int j = 1; j < rings; ++j) {
      // a point inside the quad, between the middles of its sides on the generators, nearer one
      // or the other from ring to ring (so that, over the rings, such points lie at many angles
      // around the apex), in 3D and in the sector's development (turned so that generator k lies
      // on the x-axis)
      const double middle = 0.5 * (double(j) + double(j + 1)) / rings, f = (j % 7 + 0.5) / 7;
      const Vector& g0 = generator[std::size_t(k)];
      const Vector& g1 = generator[std::size_t((k + 1) % segments)];
      points.push_back(CGAL::ORIGIN + middle * ((1 - f) * g0 + f * g1));
      const double x = middle * ((1 - f) + f * std::cos(alpha)), y = middle * f * std::sin(alpha);
      polar.emplace_back(std::hypot(x, y), k * alpha + std::atan2(y, x));
      const int c = int(points.size()) - 1;
      triangles.push_back({id(k, j), id(k, j + 1), c});
      triangles.push_back({id(k, j + 1), id(k + 1, j + 1), c});
      triangles.push_back({id(k + 1, j + 1), id(k + 1, j), c});
      triangles.push_back({id(k + 1, j), id(k, j), c});
    }
  }
  return mesh_from_soup(points, triangles);
}

// ---------------------------------------------------------------------------------------------
// The cube and the regular tetrahedron

/// The surface of the cube [0, side]^3, each face cut into n x n squares, each square into two
/// triangles (alternating diagonals). Vertex 0 is the corner (0, 0, 0).
inline Mesh make_cube(double side, int n)
{
  std::map<std::array<int, 3>, int> index;
  std::vector<Point> points;
  auto id = [&](int i, int j, int k) {
    const std::array<int, 3> key{{i, j, k}};
    auto it = index.find(key);
    if(it != index.end())
      return it->second;
    index.emplace(key, int(points.size()));
    points.push_back(Point(side * i / n, side * j / n, side * k / n));
    return int(points.size()) - 1;
  };
  id(0, 0, 0);
  std::vector<Triangle> triangles;
  // For each axis and each side (0 or n), the square grid in the two other axes, oriented outwards.
  for(int axis = 0; axis < 3; ++axis)
    for(int level : {0, n}) {
      const int u = (axis + 1) % 3, w = (axis + 2) % 3;
      for(int a = 0; a < n; ++a)
        for(int b = 0; b < n; ++b) {
          auto corner = [&](int da, int db) {
            std::array<int, 3> c{};
            c[axis] = level;
            c[u] = a + da;
            c[w] = b + db;
            return id(c[0], c[1], c[2]);
          };
          int q[4] = {corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)};
          if(level == 0)
            std::swap(q[1], q[3]); // (u, w, axis) is direct: turn the other way on the low side
          add_quad(triangles, q[0], q[1], q[2], q[3], (a + b) % 2 == 0);
        }
    }
  return mesh_from_soup(points, triangles);
}

/// The distance on the cube [0, side]^3 from the corner (0, 0, 0) to the corner p, by name: the
/// three adjacent corners at side, the far corners of the three faces through (0, 0, 0) at
/// side sqrt(2), the opposite corner at side sqrt(5); nothing when p is not a corner.
inline std::optional<double> cube_corner_distance(const Point& p, double side)
{
  const int at_side = (p.x() == side) + (p.y() == side) + (p.z() == side);
  const int at_zero = (p.x() == 0) + (p.y() == 0) + (p.z() == 0);
  if(at_side + at_zero != 3)
    return std::nullopt;
  return at_side == 0 ? 0 : at_side == 1 ? side : at_side == 2 ? side * std::sqrt(2.) : side * std::sqrt(5.);
}

/// The regular tetrahedron of edge length `a`.
inline Mesh make_tetrahedron(double a)
{
  const double s = a / std::sqrt(8.);
  return mesh_from_soup({Point(s, s, s), Point(s, -s, -s), Point(-s, s, -s), Point(-s, -s, s)},
                        {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}});
}

} // namespace test_support

#endif // CGAL_EXT_TEST_SUPPORT_ANALYTIC_SURFACES_H
