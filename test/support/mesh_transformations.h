// Copyright (c) 2026 The CGAL_ext geodesics developers.
// New meshes from the test meshes: scaled, moved, jittered, subdivided, cut open, several side
// by side, and refined copies of the same surface (a vertex inserted on an edge).
#ifndef CGAL_EXT_TEST_SUPPORT_MESH_TRANSFORMATIONS_H
#define CGAL_EXT_TEST_SUPPORT_MESH_TRANSFORMATIONS_H

#include "meshes.h"

#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/subdivision_method_3.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

namespace test_support {

// Each returns a new mesh with the same vertex and face indices unless said.

inline Mesh scaled(const Mesh& in, double factor)
{
  Mesh m = in;
  for(Vertex v : m.vertices())
    m.point(v) = CGAL::ORIGIN + factor * (m.point(v) - CGAL::ORIGIN);
  return m;
}

inline Mesh translated(const Mesh& in, const Vector& t)
{
  Mesh m = in;
  for(Vertex v : m.vertices())
    m.point(v) = m.point(v) + t;
  return m;
}

inline double mean_edge_length(const Mesh& m)
{
  double sum = 0;
  for(auto e : m.edges())
    sum += distance_3(m.point(m.vertex(e, 0)), m.point(m.vertex(e, 1)));
  return sum / double(m.number_of_edges());
}

/// every coordinate moved by a uniform random amount of at most `fraction` of the mean edge length
inline Mesh jittered(const Mesh& in, double fraction, unsigned seed = 7)
{
  Mesh m = in;
  const double a = fraction * mean_edge_length(in);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-a, a);
  for(Vertex v : m.vertices()) {
    const double dx = u(rng), dy = u(rng), dz = u(rng);
    m.point(v) = m.point(v) + Vector(dx, dy, dz);
  }
  return m;
}

/// one step of Loop subdivision (new vertices and faces)
inline Mesh loop_subdivided(const Mesh& in)
{
  Mesh m = in;
  CGAL::Subdivision_method_3::Loop_subdivision(m, CGAL::parameters::number_of_iterations(1));
  return m;
}

/// The mesh with `count` faces removed, spread over the face indices and chosen so that no two
/// removed faces share a vertex (every hole is a triangle, no vertex gets pinched). The result
/// is compacted: indices change.
inline Mesh cut_open(const Mesh& in, int count)
{
  Mesh m = in;
  std::vector<char> touched(m.number_of_vertices(), 0);
  std::vector<Face> removed;
  const std::size_t nf = m.number_of_faces();
  for(std::size_t start = 0; int(removed.size()) < count && start < nf; start += nf / (4 * count) + 1) {
    const Face f(static_cast<Mesh::size_type>(start));
    bool free = true;
    for(Vertex v : m.vertices_around_face(m.halfedge(f)))
      for(Vertex w : m.vertices_around_target(m.halfedge(v)))
        free = free && !touched[w.idx()] && !touched[v.idx()] && !m.is_border(v);
    if(!free)
      continue;
    for(Vertex v : m.vertices_around_face(m.halfedge(f)))
      touched[v.idx()] = 1;
    removed.push_back(f);
  }
  for(Face f : removed)
    CGAL::Euler::remove_face(m.halfedge(f), m);
  m.collect_garbage();
  return m;
}

/// The transformations the oracle comparisons run on real meshes: geometry the solvers have
/// never seen.
enum Transform { SCALED_DOWN, SCALED_UP, LOOP_SUBDIVIDED, JITTERED, CUT_OPEN };
constexpr const char* transform_names[] = {"scaled_1e-3", "scaled_1e3", "loop_subdivided", "jittered", "cut_open"};

inline Mesh transformed(const Mesh& m, Transform t)
{
  switch(t) {
  case SCALED_DOWN: return scaled(m, 1e-3);
  case SCALED_UP: return scaled(m, 1e3);
  case LOOP_SUBDIVIDED: return loop_subdivided(m);
  case JITTERED: return jittered(m, 1e-3);
  default: return cut_open(m, 6);
  }
}

/// The disjoint union of the meshes: the vertices of each part follow those of the previous
/// parts in their order, and so do the faces (face f of part k has the index of f plus the
/// faces of the parts before it; its corners may start at another vertex, see
/// `transferred_location`).
inline Mesh disjoint_union(const std::vector<const Mesh*>& parts)
{
  Mesh m;
  for(const Mesh* p : parts) {
    const std::size_t offset = m.number_of_vertices();
    for(Vertex v : p->vertices())
      m.add_vertex(p->point(v));
    for(Face f : p->faces()) {
      std::vector<Vertex> c;
      for(Vertex v : p->vertices_around_face(p->halfedge(f)))
        c.push_back(Vertex(static_cast<Mesh::size_type>(offset + v.idx())));
      if(m.add_face(c) == Mesh::null_face())
        throw std::runtime_error("disjoint_union: add_face failed");
    }
  }
  return m;
}

/// Inserts a vertex at p on the edge (a, b) of m and connects it to the opposite vertex of each
/// face of the edge: the surface is unchanged, existing vertex indices are kept.
inline Vertex insert_on_edge(Mesh& m, Vertex a, Vertex b, const Point& p)
{
  const auto h = m.halfedge(a, b);
  if(h == Mesh::null_halfedge())
    throw std::logic_error("insert_on_edge: no edge between the vertices");
  const auto hnew = CGAL::Euler::split_edge(h, m); // a -> new, followed by h: new -> b
  const Vertex v = m.target(hnew);
  m.point(v) = p;
  if(!m.is_border(h))
    CGAL::Euler::split_face(hnew, m.next(h), m);
  const auto o = m.opposite(h); // b -> new
  if(!m.is_border(o))
    CGAL::Euler::split_face(o, m.next(m.opposite(hnew)), m);
  return v;
}

} // namespace test_support

#endif // CGAL_EXT_TEST_SUPPORT_MESH_TRANSFORMATIONS_H
