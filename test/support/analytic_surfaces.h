// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Generated surfaces whose geodesic distances are known in closed form: planar grids (also
// L-shaped), an open cylinder and a cone (developable: their vertices carry their developed
// planar position), a cube and a regular tetrahedron.
#ifndef CGAL_EXT_TEST_SUPPORT_ANALYTIC_SURFACES_H
#define CGAL_EXT_TEST_SUPPORT_ANALYTIC_SURFACES_H

#include "meshes.h"

#include <cmath>
#include <map>
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

/// An open polyhedral cylinder (side only): `segments` vertices around on a circle of radius r,
/// `rows` + 1 rings between z = 0 and z = height. The developed position of vertex (k, j) is
/// (k * chord, z_j), with chord = 2 r sin(pi / segments): the development is a strip of width
/// segments * chord, periodic in its first coordinate.
inline Mesh make_cylinder(double r, int segments, double height, int rows)
{
  const double pi = 3.14159265358979323846;
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

/// A polyhedral cone (side only, open at the base): the apex (vertex 0) at (0, 0, height) and
/// `rings` rings of `segments` vertices on the generators, ring j at the fraction j / rings of
/// the slant from the apex; the last ring is the base circle of radius r. Every face lies in the
/// plane of the apex triangle it belongs to, so the cone develops into a planar sector of angle
/// segments * alpha, alpha = 2 asin(chord / (2 slant)). The developed position (polar) of vertex
/// (k, j) is radius j / rings * slant, angle k * alpha, stored as a Cartesian Point_2.
inline Mesh make_cone(double r, double height, int segments, int rings, double* sector_angle = nullptr)
{
  const double pi = 3.14159265358979323846;
  const double slant = std::hypot(r, height);
  const double chord = 2 * r * std::sin(pi / segments);
  const double alpha = 2 * std::asin(chord / (2 * slant));
  if(sector_angle)
    *sector_angle = segments * alpha;
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
          if((a + b) % 2 == 0) {
            triangles.push_back({q[0], q[1], q[2]});
            triangles.push_back({q[0], q[2], q[3]});
          } else {
            triangles.push_back({q[0], q[1], q[3]});
            triangles.push_back({q[1], q[2], q[3]});
          }
        }
    }
  return mesh_from_soup(points, triangles);
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
