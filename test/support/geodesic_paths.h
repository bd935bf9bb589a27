// Copyright (c) 2026 The CGAL_ext geodesics developers.
// What the tests of Surface_mesh_geodesic_paths (test_paths_*.cpp) share: the class on the test
// meshes, sources and targets, building and querying it, and the tolerances of its distances
// and path lengths.
#ifndef CGAL_EXT_TEST_SUPPORT_GEODESIC_PATHS_H
#define CGAL_EXT_TEST_SUPPORT_GEODESIC_PATHS_H

#include "meshes.h"

#include <CGAL_ext/Surface_mesh_geodesic_paths.h>

#include <memory>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace test_support {

typedef CGAL_ext::Surface_mesh_geodesic_paths<Mesh> Paths;
typedef CGAL_ext::Surface_mesh_geodesic_paths<Mesh, CGAL::Parallel_tag> Parallel_paths;
typedef Paths::Path_point Path_point;
typedef Mesh::Halfedge_index Halfedge;

const double vtp_tolerance = 1e-12;   // max |ours - VTP| / diagonal
const double length_tolerance = 1e-9; // |path length - distance| / distance

// ---------------------------------------------------------------------------------------------
// Sources and targets

enum Source_kind { VERTEX_SOURCE, FACE_SOURCE, EDGE_SOURCE, SEVERAL_SOURCES, BORDER_SOURCES, NEAR_VERTEX_SOURCE };
constexpr const char* source_names[] = {"vertex", "face", "edge", "several", "border", "near_vertex"};

inline Sources make_sources(const Mesh& m, Source_kind kind)
{
  const std::size_t nf = m.number_of_faces();
  Sources s;
  switch(kind) {
  case VERTEX_SOURCE: s.vertices = spread_vertices(m, 1, m.number_of_vertices() / 3); break;
  case FACE_SOURCE: s.faces = {location(nf / 2, 0.2, 0.3)}; break;
  case EDGE_SOURCE: s.faces = {location(nf / 5, 0., 0.6)}; break; // on the edge of corners 1 and 2
  case SEVERAL_SOURCES:
    s.vertices = spread_vertices(m, 3, 17);
    s.faces = {location(nf / 3, 0.45, 0.1), location(2 * nf / 3, 0.7, 0.)};
    break;
  case BORDER_SOURCES: { // a border vertex and a point of a border edge elsewhere
    std::vector<Halfedge> border;
    for(auto h : m.halfedges())
      if(m.is_border(h))
        border.push_back(h);
    if(border.empty())
      throw std::logic_error("make_sources: the mesh has no border");
    s.vertices = {m.target(border[border.size() / 4])};
    const auto h = m.opposite(border[(3 * border.size()) / 4]); // in a face
    const auto c = face_corners(m, m.face(h));
    Barycentric b{{0., 0., 0.}};
    for(int k = 0; k < 3; ++k)
      b[k] = c[k] == m.source(h) ? 0.35 : (c[k] == m.target(h) ? 0.65 : 0.);
    s.faces = {Face_location(m.face(h), b)};
    break;
  }
  case NEAR_VERTEX_SOURCE: s.faces = {location(nf / 7, 1 - 2e-7, 1e-7)}; break;
  }
  return s;
}

/// `count` face locations spread over the faces, cycling through six forms: inside the face
/// (twice), on an edge (one zero coordinate), at a corner (two zeros), and within 1e-9 of a
/// corner and 1e-10 of an edge (inside the face, not snapped to the corner or the edge)
inline std::vector<Face_location> face_targets(const Mesh& m, int count, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.05, 0.9);
  std::vector<Face_location> t;
  const std::size_t nf = m.number_of_faces();
  for(int i = 0; i < count; ++i) {
    const Face f(static_cast<Mesh::size_type>((seed + std::size_t(i) * nf / std::size_t(count)) % nf));
    Barycentric b{{0., 0., 0.}};
    const int k = i % 3;
    switch(i % 6) {
    case 0:
    case 1: {
      const double a = u(rng), c = (1 - a) * u(rng);
      b[k] = a;
      b[(k + 1) % 3] = c;
      b[(k + 2) % 3] = 1 - a - c;
      break;
    }
    case 2: {
      const double a = u(rng);
      b[k] = a;
      b[(k + 1) % 3] = 1 - a;
      break;
    }
    case 3: b[k] = 1; break;
    case 4:
      b[k] = 1 - 2e-9;
      b[(k + 1) % 3] = 1e-9;
      b[(k + 2) % 3] = 1e-9;
      break;
    default: {
      const double a = u(rng);
      b[k] = a;
      b[(k + 1) % 3] = 1 - a - 1e-10;
      b[(k + 2) % 3] = 1e-10;
    }
    }
    t.push_back(Face_location(f, b));
  }
  return t;
}

/// the location of a face point expressed in the face across its edge (it must lie on one); the
/// null face on a border edge
inline Face_location across(const Mesh& m, const Face_location& l)
{
  const auto c = face_corners(m, l.first);
  for(int k = 0; k < 3; ++k)
    if(l.second[k] == 0) {
      const Vertex a = c[(k + 1) % 3], b = c[(k + 2) % 3];
      const auto h = m.opposite(m.halfedge(a, b));
      if(m.is_border(h))
        return Face_location(Mesh::null_face(), l.second);
      const Face g = m.face(h);
      const auto d = face_corners(m, g);
      Barycentric bg{{0., 0., 0.}};
      for(int i = 0; i < 3; ++i)
        bg[i] = d[i] == a ? l.second[(k + 1) % 3] : (d[i] == b ? l.second[(k + 2) % 3] : 0.);
      return Face_location(g, bg);
    }
  throw std::logic_error("across: not on an edge");
}

inline std::string describe_target(Vertex v) { return "vertex " + std::to_string(v.idx()); }
inline std::string describe_target(const Face_location& l)
{
  std::ostringstream s;
  s.precision(17);
  s << "face " << l.first << " (" << l.second[0] << ", " << l.second[1] << ", " << l.second[2] << ")";
  return s.str();
}

// ---------------------------------------------------------------------------------------------
// Building and querying

/// the paths object of type P for the sources, built with `np`
template <class P, class NamedParameters = CGAL_ext::parameters::Default_named_parameters_type>
std::unique_ptr<P> built(const Mesh& m, const Sources& s,
                         const NamedParameters& np = CGAL_ext::parameters::default_values())
{
  std::unique_ptr<P> p(new P(m));
  for(Vertex v : s.vertices)
    p->add_source(v);
  for(const Face_location& l : s.faces)
    p->add_source(l);
  p->build(np);
  return p;
}

/// the distances the class gives at the vertices, in vertex order
template <class P>
std::vector<double> class_distances(const Mesh& m, const P& p)
{
  std::vector<double> d;
  for(Vertex v : m.vertices())
    d.push_back(p.distance(v));
  return d;
}

/// the shortest path to a target, as the class's path points
template <class P, class Target>
std::vector<typename P::Path_point> surface_path(const P& p, const Target& t)
{
  std::vector<typename P::Path_point> path;
  p.shortest_path_surface_points(t, std::back_inserter(path));
  return path;
}

/// records what shortest_path_sequence() visits, as path points
template <class PathPoint>
struct Recorder
{
  std::vector<PathPoint> points;

  void operator()(Vertex v)
  {
    PathPoint p;
    p.kind = PathPoint::VERTEX;
    p.vertex = v;
    points.push_back(p);
  }
  void operator()(Halfedge h, double t)
  {
    PathPoint p;
    p.kind = PathPoint::EDGE;
    p.halfedge = h;
    p.t = t;
    points.push_back(p);
  }
  void operator()(Face f, const Barycentric& b)
  {
    PathPoint p;
    p.kind = PathPoint::FACE;
    p.face = f;
    p.barycentric = b;
    points.push_back(p);
  }
};

} // namespace test_support

#endif // CGAL_EXT_TEST_SUPPORT_GEODESIC_PATHS_H
