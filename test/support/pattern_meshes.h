// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Meshes with planted repetitive patterns, whose instances are known: bumps laid out irregularly
// on a plane or a cylinder (round, elongated in several orientations, or of several sizes) and
// a golf ball (a sphere with dimples), with optional noise on the vertices.
#ifndef CGAL_EXT_TEST_SUPPORT_PATTERN_MESHES_H
#define CGAL_EXT_TEST_SUPPORT_PATTERN_MESHES_H

#include "analytic_surfaces.h"
#include "meshes.h"

#include <array>
#include <algorithm>
#include <cmath>
#include <map>
#include <ostream>
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

/// A sphere of radius 1 (an icosahedron whose faces are cut into `frequency`^2 triangles, points
/// pushed onto the sphere: 10 frequency^2 + 2 vertices) with a dimple of angular radius
/// `dimple_angle` and relative depth `depth` around each of `centres`.
inline Mesh golf_ball(int frequency, const std::vector<Vector>& centres, double dimple_angle, double depth)
{
  const double t = (1 + std::sqrt(5.0)) / 2;
  const std::vector<Point> corners = {Point(-1, t, 0), Point(1, t, 0),  Point(-1, -t, 0), Point(1, -t, 0),
                                      Point(0, -1, t), Point(0, 1, t),  Point(0, -1, -t), Point(0, 1, -t),
                                      Point(t, 0, -1), Point(t, 0, 1),  Point(-t, 0, -1), Point(-t, 0, 1)};
  const std::vector<Triangle> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  std::vector<Point> points;
  std::map<std::array<long long, 3>, int> index; // points on shared edges once
  const auto point_index = [&](const Point& p) {
    const std::array<long long, 3> key = {std::llround(p.x() * 1e9), std::llround(p.y() * 1e9),
                                          std::llround(p.z() * 1e9)};
    const auto it = index.find(key);
    if(it != index.end())
      return it->second;
    points.push_back(p);
    return index[key] = int(points.size()) - 1;
  };
  std::vector<Triangle> triangles;
  const int m = frequency;
  for(const Triangle& f : faces) {
    const Point &a = corners[std::size_t(f[0])], &b = corners[std::size_t(f[1])], &c = corners[std::size_t(f[2])];
    const auto at = [&](int i, int j) { // i steps towards b, j towards c
      const double u = double(i) / m, v = double(j) / m;
      return point_index(CGAL::ORIGIN + ((a - CGAL::ORIGIN) * (1 - u - v) + (b - CGAL::ORIGIN) * u + (c - CGAL::ORIGIN) * v));
    };
    for(int i = 0; i < m; ++i)
      for(int j = 0; i + j < m; ++j) {
        triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        if(i + j + 1 < m)
          triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
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

/// The vertex nearest to `p`.
inline Vertex nearest_vertex(const Mesh& m, const Point& p)
{
  Vertex best = *m.vertices().begin();
  for(Vertex v : m.vertices())
    if(CGAL::squared_distance(m.point(v), p) < CGAL::squared_distance(m.point(best), p))
      best = v;
  return best;
}

/// The planted instances: where each centre is on the surface and its radius.
struct Truth
{
  std::vector<Point> centres;
  std::vector<double> radii;
  std::vector<double> angles; ///< of the long axes, on a plane (empty elsewhere)

  /// The planted instance whose centre is nearest to `p`.
  std::size_t nearest(const Point& p) const
  {
    std::size_t best = 0;
    for(std::size_t i = 1; i < centres.size(); ++i)
      if(CGAL::squared_distance(p, centres[i]) < CGAL::squared_distance(p, centres[best]))
        best = i;
    return best;
  }

  /// How far `p` lies from the nearest planted centre.
  double distance_to_nearest(const Point& p) const { return std::sqrt(CGAL::squared_distance(p, centres[nearest(p)])); }
};

/// How found instances compare with the planted ones: a found centre is right when it lies
/// within a quarter of the instance radius of a planted centre not claimed yet.
struct Score
{
  double recall = 0, precision = 0;
  std::size_t found = 0, right = 0, planted = 0;
};

/// `instances` have a `center` point.
template <class Instances>
Score score(const Instances& instances, const Truth& truth)
{
  Score s;
  s.planted = truth.centres.size();
  s.found = instances.size();
  std::vector<bool> claimed(truth.centres.size(), false);
  for(const auto& instance : instances) {
    std::size_t best = truth.centres.size();
    double best_d = 0;
    for(std::size_t i = 0; i < truth.centres.size(); ++i) {
      const double d = std::sqrt(CGAL::squared_distance(instance.center, truth.centres[i]));
      if(!claimed[i] && d <= 0.25 * truth.radii[i] && (best == truth.centres.size() || d < best_d)) {
        best = i;
        best_d = d;
      }
    }
    if(best < truth.centres.size()) {
      claimed[best] = true;
      ++s.right;
    }
  }
  s.recall = double(s.right) / double(std::max<std::size_t>(1, s.planted));
  s.precision = double(s.right) / double(std::max<std::size_t>(1, s.found));
  return s;
}

inline std::ostream& operator<<(std::ostream& out, const Score& s)
{
  return out << "recall " << s.recall << " precision " << s.precision << " (" << s.right << " right of "
             << s.found << " found, " << s.planted << " planted)";
}

/// A mesh with planted instances, what they are, and the patch that marks one of them.
struct Pattern_scene
{
  Mesh mesh;
  Truth truth;
  Vertex patch_centre;                  ///< a disk patch, when `patch_radius` > 0
  double patch_radius = 0;
  std::vector<Vertex> patch_vertices;   ///< otherwise a vertex list
  std::pair<double, double> scales{1.0, 1.0};
  std::vector<Vertex> stroke;           ///< a stroke across instances of changing size, if any
};

/// `bumps` of `height` times their radius on the unit square, an n x n grid, vertices moved at
/// random by `noise` edge lengths; the truth radius of a bump is its (short) radius. The first
/// bump is marked as a disk.
inline Pattern_scene bumps_on_a_plane(int n, const std::vector<Planted>& bumps, double height, unsigned seed,
                                      double noise)
{
  Pattern_scene scene;
  const double h = 1.0 / (n - 1);
  scene.mesh = bumpy_plane(n, h, bumps, height);
  add_noise(scene.mesh, noise * h, seed + 1);
  for(const Planted& b : bumps) {
    scene.truth.centres.push_back(Point(b.x, b.y, height * b.radius));
    scene.truth.radii.push_back(b.radius);
    scene.truth.angles.push_back(b.angle);
  }
  scene.patch_centre = nearest_vertex(scene.mesh, scene.truth.centres[0]);
  scene.patch_radius = bumps[0].radius;
  return scene;
}

/// Round bumps of `radius` (height 0.4 radius) laid out irregularly on the unit square.
inline Pattern_scene round_bumps_on_a_plane(int n, int count, double radius, unsigned seed, double noise)
{
  return bumps_on_a_plane(n,
                          irregular_layout(count, 1.2 * radius, 1 - 1.2 * radius, 1.2 * radius, 1 - 1.2 * radius,
                                           2.5 * radius, radius, seed),
                          0.4, seed, noise);
}

/// A golf ball: `count` dimples of angular radius `angle` spread by the golden angle over a
/// sphere of 10 frequency^2 + 2 vertices, moved by `noise` (absolute); a dimple is marked.
inline Pattern_scene dimples_on_a_sphere(int frequency, int count, double angle, double noise)
{
  Pattern_scene scene;
  const std::vector<Vector> directions = fibonacci_directions(count);
  const double depth = 0.3;
  scene.mesh = golf_ball(frequency, directions, angle, depth);
  add_noise(scene.mesh, noise, 5);
  for(const Vector& d : directions) {
    scene.truth.centres.push_back(CGAL::ORIGIN + d * (1 - depth * angle));
    scene.truth.radii.push_back(angle);
  }
  scene.patch_centre = nearest_vertex(scene.mesh, scene.truth.centres[std::size_t(count) / 8]);
  scene.patch_radius = angle;
  return scene;
}

/// Round bumps laid out irregularly around an open cylinder of radius 1 and length 6.
inline Pattern_scene bumps_around_a_cylinder(int segments, int rows, int count, double radius, unsigned seed)
{
  Pattern_scene scene;
  const double r = 1, height = 0.35;
  const std::vector<Planted> bumps =
    irregular_layout(count, 0.4, 2 * pi * r - 0.4, 0.5, 5.5, 2.5 * radius, radius, seed);
  scene.mesh = bumpy_cylinder(r, segments, 6, rows, bumps, height);
  for(const Planted& b : bumps) {
    const double a = b.x / r, lifted = r + height * radius;
    scene.truth.centres.push_back(Point(lifted * std::cos(a), lifted * std::sin(a), b.y));
    scene.truth.radii.push_back(radius);
  }
  scene.patch_centre = nearest_vertex(scene.mesh, scene.truth.centres[0]);
  scene.patch_radius = radius;
  return scene;
}

/// Bumps twice as long as wide (short semi-axis `radius`), turned at random, on the unit
/// square; the first is marked by its vertices. Its truth radius is the short semi-axis.
inline Pattern_scene elongated_bumps_on_a_plane(int n, int count, double radius, unsigned seed, double noise)
{
  std::vector<Planted> bumps = irregular_layout(count, 2.4 * radius, 1 - 2.4 * radius, 2.4 * radius,
                                                1 - 2.4 * radius, 4.6 * radius, radius, seed);
  std::mt19937 rng(seed + 2);
  std::uniform_real_distribution<double> turn(0, pi);
  for(Planted& b : bumps) {
    b.stretch = 2;
    b.angle = turn(rng);
  }
  Pattern_scene scene = bumps_on_a_plane(n, bumps, 0.5, seed, noise);
  scene.patch_radius = 0;
  for(Vertex v : scene.mesh.vertices())
    if(bump_profile(bumps[0], scene.mesh.point(v).x(), scene.mesh.point(v).y()) > 0)
      scene.patch_vertices.push_back(v);
  return scene;
}

/// Round bumps of three sizes (0.75, 1 and 1.4 times `radius`) on the unit square; one of size
/// 1 is marked and the scale range is 0.6:1.6.
inline Pattern_scene bumps_of_three_sizes_on_a_plane(int n, int count, double radius, unsigned seed, double noise)
{
  std::vector<Planted> bumps = irregular_layout(count, 1.6 * radius, 1 - 1.6 * radius, 1.6 * radius,
                                                1 - 1.6 * radius, 3.4 * radius, radius, seed);
  for(std::size_t i = 0; i < bumps.size(); ++i)
    bumps[i].radius = radius * (i % 3 == 0 ? 1.0 : i % 3 == 1 ? 0.75 : 1.4);
  Pattern_scene scene = bumps_on_a_plane(n, bumps, 0.4, seed, noise);
  scene.scales = {0.6, 1.6};
  return scene;
}

/// Round bumps whose radius grows from left to right (`radius` x (0.8 + 1.2 x)) on the unit
/// square; the leftmost is marked, the scale range is 1:2 and the stroke runs along the grid
/// row through its centre to the right border (the user's stroke across instances of growing size).
inline Pattern_scene growing_bumps_on_a_plane(int n, int count, double radius, unsigned seed, double noise)
{
  const double largest = radius * 2.0;
  std::vector<Planted> bumps = irregular_layout(count, 1.2 * largest, 1 - 1.2 * largest, 1.2 * largest,
                                                1 - 1.2 * largest, 2.4 * largest, radius, seed);
  std::sort(bumps.begin(), bumps.end(), [](const Planted& a, const Planted& b) { return a.x < b.x; });
  for(Planted& b : bumps)
    b.radius = radius * (0.8 + 1.2 * b.x);
  Pattern_scene scene = bumps_on_a_plane(n, bumps, 0.4, seed, noise);
  scene.scales = {1.0, 2.0};
  const double h = 1.0 / (n - 1);
  const int row = int(std::lround(bumps[0].y / h)), first = int(std::lround(bumps[0].x / h));
  for(int i = first; i < n; ++i)
    scene.stroke.push_back(Vertex(std::size_t(row * n + i)));
  return scene;
}

} // namespace test_support

#endif // CGAL_EXT_TEST_SUPPORT_PATTERN_MESHES_H
