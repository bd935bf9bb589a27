// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The meshes of the test suite and places on them: the types every test uses, the data meshes
// read once per process, meshes built from triangle soups, face locations and sources.
#ifndef CGAL_EXT_TEST_SUPPORT_MESHES_H
#define CGAL_EXT_TEST_SUPPORT_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/bbox.h>
#include <CGAL/Surface_mesh.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace test_support {

typedef CGAL::Epick K;
typedef K::Point_3 Point;
typedef K::Point_2 Point_2;
typedef K::Vector_3 Vector;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex;
typedef Mesh::Face_index Face;
typedef std::array<double, 3> Barycentric;
typedef std::pair<Face, Barycentric> Face_location;
typedef std::array<int, 3> Triangle;

const double inf = std::numeric_limits<double>::infinity();
const double pi = 3.14159265358979323846;

/// The vertex indices of a triangle of `m`, from the source of its half-edge on.
inline Triangle corners_of(const Mesh& m, Face f)
{
  Triangle t;
  std::size_t k = 0;
  for(Vertex v : m.vertices_around_face(m.halfedge(f)))
    t[k++] = int(v.idx());
  return t;
}

// ---------------------------------------------------------------------------------------------
// Meshes read from files

inline Mesh read_off(const std::string& path)
{
  Mesh m;
  std::ifstream in(path);
  if(!in || !CGAL::IO::read_OFF(in, m) || m.is_empty())
    throw std::runtime_error("cannot read the mesh " + path);
  return m;
}

/// the file of a test mesh by name: the repository's data/ copy for elephant and mushroom, else
/// CGAL's data mesh (fandisk, cactus, ...)
inline std::string test_mesh_path(const std::string& name)
{
  const bool ours = name == "elephant" || name == "mushroom";
  return std::string(ours ? CGAL_EXT_DATA_DIR : CGAL_EXT_CGAL_MESHES) + "/" + name + ".off";
}

/// a test mesh by name (see `test_mesh_path`), read once per process
inline const Mesh& test_mesh(const std::string& name)
{
  static std::map<std::string, Mesh> cache;
  auto it = cache.find(name);
  if(it == cache.end())
    it = cache.emplace(name, read_off(test_mesh_path(name))).first;
  return it->second;
}

// ---------------------------------------------------------------------------------------------
// Meshes built from triangle soups

/// a triangle mesh from a soup whose triangles are consistently oriented; fails the test (and
/// throws) when Surface_mesh refuses a face
inline Mesh mesh_from_soup(const std::vector<Point>& points, const std::vector<Triangle>& triangles)
{
  Mesh m;
  std::vector<Vertex> v;
  for(const Point& p : points)
    v.push_back(m.add_vertex(p));
  for(const Triangle& t : triangles) {
    if(m.add_face(v[t[0]], v[t[1]], v[t[2]]) == Mesh::null_face()) {
      ADD_FAILURE() << "Surface_mesh refused the face (" << t[0] << ", " << t[1] << ", " << t[2] << ")";
      throw std::runtime_error("bad soup");
    }
  }
  return m;
}

/// Two triangles for the quad (a, b, c, d), split along a-c or, if not `first_diagonal`, b-d
/// (alternating the diagonal avoids a preferred direction in the tests' meshes).
inline void add_quad(std::vector<Triangle>& triangles, int a, int b, int c, int d, bool first_diagonal)
{
  if(first_diagonal) {
    triangles.push_back({a, b, c});
    triangles.push_back({a, c, d});
  } else {
    triangles.push_back({a, b, d});
    triangles.push_back({b, c, d});
  }
}

// ---------------------------------------------------------------------------------------------
// Geometry

inline double distance_3(const Point& a, const Point& b) { return std::sqrt(CGAL::squared_distance(a, b)); }

inline double bbox_diagonal(const Mesh& m)
{
  const CGAL::Bbox_3 b = CGAL::Polygon_mesh_processing::bbox(m);
  return std::sqrt(CGAL::square(b.xmax() - b.xmin()) + CGAL::square(b.ymax() - b.ymin()) +
                   CGAL::square(b.zmax() - b.zmin()));
}

/// `count` vertices spread over the index range
inline std::vector<Vertex> spread_vertices(const Mesh& m, int count, std::size_t offset = 0)
{
  std::vector<Vertex> v;
  for(int i = 0; i < count; ++i)
    v.push_back(Vertex(static_cast<Mesh::size_type>((offset + i * m.number_of_vertices() / count) %
                                                     m.number_of_vertices())));
  return v;
}

// ---------------------------------------------------------------------------------------------
// Face locations

/// the three vertices of f in the order of the barycentric coordinates of a face location:
/// source(halfedge(f)), target(halfedge(f)), target(next(halfedge(f)))
inline std::array<Vertex, 3> face_corners(const Mesh& m, Face f)
{
  const auto h = m.halfedge(f);
  return {{m.source(h), m.target(h), m.target(m.next(h))}};
}

inline Point location_point(const Mesh& m, const Face_location& l)
{
  const auto c = face_corners(m, l.first);
  return CGAL::barycenter(m.point(c[0]), l.second[0], m.point(c[1]), l.second[1], m.point(c[2]), l.second[2]);
}

/// A face location at the barycentric coordinates (a, b, 1 - a - b) of face index i.
inline Face_location location(std::size_t i, double a, double b)
{
  return Face_location(Face(static_cast<Mesh::size_type>(i)), Barycentric{{a, b, 1 - a - b}});
}

/// The face location of vertex v: a corner of one of its faces, with coordinate 1 there.
inline Face_location corner_location(const Mesh& m, Vertex v)
{
  for(auto h : m.halfedges_around_target(m.halfedge(v)))
    if(!m.is_border(h)) {
      const Face f = m.face(h);
      Barycentric b{{0., 0., 0.}};
      const auto c = face_corners(m, f);
      for(int k = 0; k < 3; ++k)
        b[k] = c[k] == v ? 1. : 0.;
      return Face_location(f, b);
    }
  throw std::runtime_error("isolated vertex");
}

/// The face location `l` of `from` expressed on `to`, where vertex i of `from` is vertex
/// i + vertex_offset of `to` and face f is face f + face_offset: the coordinates are permuted
/// to the corner order of the face in `to`.
inline Face_location transferred_location(const Mesh& from, const Face_location& l, const Mesh& to,
                                          std::size_t vertex_offset, std::size_t face_offset)
{
  const Face g(static_cast<Mesh::size_type>(l.first.idx() + face_offset));
  const auto c = face_corners(from, l.first), d = face_corners(to, g);
  Barycentric b{{0., 0., 0.}};
  for(int i = 0; i < 3; ++i)
    for(int k = 0; k < 3; ++k)
      if(d[i].idx() == c[k].idx() + vertex_offset)
        b[i] = l.second[k];
  return Face_location(g, b);
}

/// how many barycentric coordinates are zero: 1 on an edge, 2 at a corner
inline int zero_coordinates(const Barycentric& b) { return (b[0] == 0) + (b[1] == 0) + (b[2] == 0); }

/// The index of the only zero barycentric coordinate of a face location (a point of an edge
/// of its face, opposite that corner), or -1 if none or several are zero.
inline int only_zero_coordinate(const Face_location& l)
{
  int zeros = 0, zero = -1;
  for(int k = 0; k < 3; ++k)
    if(l.second[k] == 0) {
      ++zeros;
      zero = k;
    }
  return zeros == 1 ? zero : -1;
}

/// whether a face location lies on a border edge (exactly one zero coordinate, no face across)
inline bool on_border_edge(const Mesh& m, const Face_location& l)
{
  const auto c = face_corners(m, l.first);
  const int zero = only_zero_coordinate(l);
  return zero >= 0 && m.is_border(m.opposite(m.halfedge(c[(zero + 1) % 3], c[(zero + 2) % 3])));
}

// ---------------------------------------------------------------------------------------------
// Sources

/// Vertex and face-location sources together; source i is the i-th in the order vertices, then
/// face locations (the order in which the tests add them to Surface_mesh_geodesic_paths).
struct Sources
{
  std::vector<Vertex> vertices;
  std::vector<Face_location> faces;

  std::size_t size() const { return vertices.size() + faces.size(); }
};

} // namespace test_support

#endif // CGAL_EXT_TEST_SUPPORT_MESHES_H
