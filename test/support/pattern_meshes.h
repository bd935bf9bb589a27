// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Meshes with planted repetitive patterns, whose instances are known: bumps laid out irregularly
// on a plane or a cylinder (round, elongated in several orientations, or of several sizes) and
// a golf ball (a sphere with dimples), with optional noise on the vertices.
#ifndef CGAL_EXT_TEST_SUPPORT_PATTERN_MESHES_H
#define CGAL_EXT_TEST_SUPPORT_PATTERN_MESHES_H

#include "analytic_surfaces.h"
#include "meshes.h"

#include <cmath>
#include <random>
#include <vector>

namespace test_support {

/// One planted instance: where its centre is (in the plane of the layout), how large it is, and
/// how it is stretched (semi-axes `radius * stretch` along `angle` and `radius` across).
struct Planted
{
  double x = 0, y = 0;
  double radius = 1;
  double stretch = 1;
  double angle = 0;
};

/// A smooth bump of height 1 at the centre, 0 from the (stretched) radius on: (1 - s^2)^2.
inline double bump_profile(const Planted& p, double x, double y)
{
  const double c = std::cos(p.angle), s = std::sin(p.angle);
  const double u = ((x - p.x) * c + (y - p.y) * s) / (p.radius * p.stretch);
  const double v = (-(x - p.x) * s + (y - p.y) * c) / p.radius;
  const double r2 = u * u + v * v;
  return r2 < 1 ? (1 - r2) * (1 - r2) : 0.0;
}

/// Up to `count` instance centres in [x_lo, x_hi] x [y_lo, y_hi] thrown at random, at least
/// `spacing` apart (an irregular layout, not a grid).
inline std::vector<Planted> irregular_layout(int count, double x_lo, double x_hi, double y_lo, double y_hi,
                                             double spacing, double radius, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> ux(x_lo, x_hi), uy(y_lo, y_hi);
  std::vector<Planted> out;
  for(int attempt = 0; attempt < 20000 && int(out.size()) < count; ++attempt) {
    Planted p;
    p.x = ux(rng);
    p.y = uy(rng);
    p.radius = radius;
    bool free = true;
    for(const Planted& q : out)
      free = free && std::hypot(p.x - q.x, p.y - q.y) >= spacing;
    if(free)
      out.push_back(p);
  }
  return out;
}

/// Moves every vertex by up to `amount` in each coordinate, at random.
inline void add_noise(Mesh& m, double amount, unsigned seed)
{
  if(amount <= 0)
    return;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-amount, amount);
  for(Vertex v : m.vertices()) {
    const Point& p = m.point(v);
    m.point(v) = Point(p.x() + u(rng), p.y() + u(rng), p.z() + u(rng));
  }
}

/// An n x n grid of spacing h with a bump of `height` times the radius of each instance.
inline Mesh bumpy_plane(int n, double h, const std::vector<Planted>& bumps, double height)
{
  Mesh m = make_grid(n, h);
  for(Vertex v : m.vertices()) {
    const Point& p = m.point(v);
    double z = 0;
    for(const Planted& b : bumps)
      z += height * b.radius * bump_profile(b, p.x(), p.y());
    m.point(v) = Point(p.x(), p.y(), z);
  }
  return m;
}

/// A cylinder of radius r with bumps outwards; a bump's (x, y) is (arc length around, height).
inline Mesh bumpy_cylinder(double r, int segments, double length, int rows, const std::vector<Planted>& bumps,
                           double height)
{
  Mesh m = make_cylinder(r, segments, length, rows);
  for(Vertex v : m.vertices()) {
    const Point& p = m.point(v);
    const double angle = std::atan2(p.y(), p.x());
    const double arc = (angle < 0 ? angle + 2 * pi : angle) * r;
    double lift = 0;
    for(const Planted& b : bumps)
      for(double wrap : {-2 * pi * r, 0.0, 2 * pi * r}) // the layout wraps around
        lift += height * b.radius * bump_profile(b, arc + wrap, p.z());
    const double scale = (r + lift) / r;
    m.point(v) = Point(p.x() * scale, p.y() * scale, p.z());
  }
  return m;
}

/// The unit directions of `count` points spread over the sphere by the golden angle (irregular
/// neighbourhoods, no lattice).
inline std::vector<Vector> fibonacci_directions(int count)
{
  std::vector<Vector> out;
  const double golden = pi * (3 - std::sqrt(5.0));
  for(int i = 0; i < count; ++i) {
    const double z = 1 - 2 * (i + 0.5) / count;
    const double rho = std::sqrt(1 - z * z);
    out.push_back(Vector(rho * std::cos(golden * i), rho * std::sin(golden * i), z));
  }
  return out;
}

/// A sphere of radius 1 (a subdivided icosahedron, `levels` times) with a dimple of angular
/// radius `dimple_angle` and relative depth `depth` around each of `centres`.
inline Mesh golf_ball(int levels, const std::vector<Vector>& centres, double dimple_angle, double depth)
{
  const double t = (1 + std::sqrt(5.0)) / 2;
  std::vector<Point> points = {Point(-1, t, 0), Point(1, t, 0),  Point(-1, -t, 0), Point(1, -t, 0),
                               Point(0, -1, t), Point(0, 1, t),  Point(0, -1, -t), Point(0, 1, -t),
                               Point(t, 0, -1), Point(t, 0, 1),  Point(-t, 0, -1), Point(-t, 0, 1)};
  std::vector<Triangle> triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                     {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                     {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                     {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for(int level = 0; level < levels; ++level) {
    std::map<std::pair<int, int>, int> middle;
    const auto mid = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = middle.find(key);
      if(it != middle.end())
        return it->second;
      points.push_back(CGAL::midpoint(points[std::size_t(a)], points[std::size_t(b)]));
      return middle[key] = int(points.size()) - 1;
    };
    std::vector<Triangle> finer;
    for(const Triangle& f : triangles) {
      const int a = mid(f[0], f[1]), b = mid(f[1], f[2]), c = mid(f[2], f[0]);
      finer.push_back({f[0], a, c});
      finer.push_back({f[1], b, a});
      finer.push_back({f[2], c, b});
      finer.push_back({a, b, c});
    }
    triangles.swap(finer);
  }
  for(Point& p : points) {
    const Vector d = (p - CGAL::ORIGIN) / std::sqrt((p - CGAL::ORIGIN).squared_length());
    double radius = 1;
    for(const Vector& c : centres) {
      const double angle = std::acos(std::max(-1.0, std::min(1.0, d * c)));
      if(angle < dimple_angle) {
        const double s = angle / dimple_angle;
        radius -= depth * dimple_angle * (1 - s * s) * (1 - s * s);
      }
    }
    p = CGAL::ORIGIN + d * radius;
  }
  return mesh_from_soup(points, triangles);
}

} // namespace test_support

#endif // CGAL_EXT_TEST_SUPPORT_PATTERN_MESHES_H
