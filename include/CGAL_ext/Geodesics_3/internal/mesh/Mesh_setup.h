// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_MESH_MESH_SETUP_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_MESH_MESH_SETUP_H

// What every public entry point does before a solver runs, written once: the caller's mesh turned
// into the solvers' `Solver_mesh` (with the way back from indices to descriptors) and its sources
// converted to the solver mesh's indices.

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>
#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>
#include <CGAL_ext/Geodesics_3/Named_function_parameters.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Source_points.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Build_solver_mesh.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/tags.h>


#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <iterator>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {


template <class T, class = void>
struct is_range : std::false_type {};
template <class T>
struct is_range<T, std::void_t<decltype(std::begin(std::declval<const T&>()))>> : std::true_type {};

/// Calls `f(s)` for `sources` when it is one source, for each of its elements when it is a range.
template <class Sources, class Function>
void for_each_source(const Sources& sources, Function f)
{
  if constexpr(is_range<Sources>::value) {
    for(const auto& s : sources)
      f(s);
  } else {
    f(sources);
  }
}

/// A triangle mesh of the caller as the solvers see it: the `Solver_mesh` (checked), and the
/// way between the caller's descriptors and the solver mesh's indices. The solver mesh is on the heap, so
/// that solvers referring to it survive a move of this object.
template <class TriangleMesh, class VertexPointMap>
class Mesh_setup
{
public:
  typedef boost::graph_traits<TriangleMesh> Graph_traits;
  typedef typename Graph_traits::vertex_descriptor vertex_descriptor;
  typedef typename Graph_traits::halfedge_descriptor halfedge_descriptor;
  typedef typename Graph_traits::face_descriptor face_descriptor;

  /// Reads `vertex_point_map`, `vertex_index_map` and `face_index_map` from `np` and builds
  /// the solver mesh; throws `Geodesic_error` when the mesh is not one the solvers take.
  template <class NamedParameters>
  Mesh_setup(const TriangleMesh& tm, const NamedParameters& np)
    : m_tm(&tm)
    , m_vpm(CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, CGAL::internal_np::vertex_point),
                                               get_const_property_map(CGAL::vertex_point, tm)))
    , m_cache(std::make_unique<Solver_mesh>())
  {
    const auto start = std::chrono::steady_clock::now();
    const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
    const auto fim = CGAL::get_initialized_face_index_map(tm, np);
    build_solver_mesh(tm, m_vpm, vim, fim, *m_cache, glued_groups(tm, np, vim));
    m_vertex_of_index.resize(m_cache->number_of_mesh_vertices);
    m_face_of_index.resize(m_cache->number_of_mesh_faces);
    for(vertex_descriptor v : vertices(tm))
      m_vertex_of_index[std::size_t(get(vim, v))] = v;
    for(face_descriptor f : faces(tm))
      m_face_of_index[std::size_t(get(fim, f))] = f;
    const Solver_mesh* cache = m_cache.get();
    // (an index out of range is passed on, for the check of the source or target to name it)
    m_vertex_index = [vim, cache](vertex_descriptor v) {
      const long long i = static_cast<long long>(get(vim, v));
      return i >= 0 && std::size_t(i) < cache->number_of_mesh_vertices ? cache->cache_vertex(int(i)) : int(i);
    };
    m_face_index = [fim, cache](face_descriptor f) {
      const long long i = static_cast<long long>(get(fim, f));
      return i >= 0 && std::size_t(i) < cache->number_of_mesh_faces ? cache->cache_face(int(i)) : int(i);
    };
    m_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }

  const TriangleMesh& mesh() const { return *m_tm; }
  const Solver_mesh& cache() const { return *m_cache; }
  /// See `Solver_mesh::release_positions()`.
  void release_positions() { m_cache->release_positions(); }
  const VertexPointMap& vertex_point_map() const { return m_vpm; }
  /// Seconds taken to build the solver mesh and check the mesh.
  double seconds() const { return m_seconds; }

  /// The solver mesh's index of vertex v (see `Solver_mesh::cache_vertex`).
  int index(vertex_descriptor v) const { return m_vertex_index(v); }
  /// The solver mesh's index of face f (see `Solver_mesh::cache_face`).
  int index(face_descriptor f) const { return m_face_index(f); }
  // (named *_of so that they hide none of the graph's free functions, found by ADL)
  /// The vertex of solver-mesh index i (a copy of a non-manifold vertex gives that vertex).
  vertex_descriptor vertex_of(int i) const { return m_vertex_of_index[std::size_t(m_cache->mesh_vertex(i))]; }
  /// The face of solver-mesh index i (a face the solver mesh added gives the face it lies in).
  face_descriptor face_of(int i) const { return m_face_of_index[std::size_t(m_cache->mesh_face(i))]; }
  /// The descriptor of solver-mesh half-edge 3f+k: the k-th after `halfedge(f)` (the solver mesh's corner
  /// order); f is a face the solver mesh did not change.
  halfedge_descriptor halfedge_of(int h) const
  {
    halfedge_descriptor d = halfedge(face_of(h / 3), *m_tm);
    for(int k = 0; k < h % 3; ++k)
      d = next(d, *m_tm);
    return d;
  }

  /// A source given as a vertex (checked: a descriptor out of the mesh would otherwise read
  /// as a face point).
  Source_point source_point(vertex_descriptor v) const
  {
    Source_point s;
    s.vertex = index(v);
    check_vertex_index(*m_cache, s.vertex, "source");
    return s;
  }
  /// A source given as a face location: a face and barycentric coordinates in the order of the
  /// face's vertices, starting at `source(halfedge(f))` (CGAL's Face_location convention).
  template <class FT>
  Source_point source_point(const std::pair<face_descriptor, std::array<FT, 3>>& location) const
  {
    Source_point s;
    s.face = index(location.first);
    for(int k = 0; k < 3; ++k)
      s.barycentric[k] = CGAL::to_double(location.second[k]);
    return s;
  }
  /// One source, or a range of them.
  template <class Sources>
  std::vector<Source_point> source_points(const Sources& sources) const
  {
    std::vector<Source_point> points;
    for_each_source(sources, [&](const auto& s) { points.push_back(source_point(s)); });
    return points;
  }

  /// Calls `f(vertex, i)` for each vertex of the mesh and its solver-mesh index i, in the solver mesh's
  /// order (which needs no map from the caller's indices: see `release_positions`).
  template <class Function>
  void for_each_vertex(Function f) const
  {
    for(std::size_t i = 0; i < m_vertex_of_index.size(); ++i)
      f(m_vertex_of_index[std::size_t(m_cache->mesh_vertex(int(i)))], i);
  }
  /// Writes `values[i]` to the vertex of solver-mesh index i (copies of a vertex have its value).
  template <class VertexValueMap, class T>
  void write_vertex_values(VertexValueMap map, const std::vector<T>& values) const
  {
    for_each_vertex([&](vertex_descriptor v, std::size_t i) { put(map, v, values[i]); });
  }
  /// Writes distances in the solver mesh's unit to the vertices, in the mesh's unit.
  template <class VertexDistanceMap>
  void write_vertex_distances(VertexDistanceMap map, const std::vector<double>& distances) const
  {
    const double unit = m_cache->unit;
    for_each_vertex([&](vertex_descriptor v, std::size_t i) { put(map, v, distances[i] * unit); });
  }
  /// Writes the nearest source of every vertex (-1 in `nearest`) as the map's value type, with
  /// `no_source` for -1.
  template <class VertexSourceMap>
  void write_vertex_sources(VertexSourceMap map, const std::vector<int>& nearest) const
  {
    typedef typename boost::property_traits<VertexSourceMap>::value_type Index;
    // none: -1 in a signed map, no_source (the largest value) in an unsigned one
    const Index none = std::is_signed<Index>::value ? Index(-1) : static_cast<Index>(no_source);
    for_each_vertex([&](vertex_descriptor v, std::size_t i) {
      put(map, v, nearest[i] < 0 ? none : static_cast<Index>(nearest[i]));
    });
  }
  /// A length or coordinate in the solver mesh's unit, in the mesh's.
  double to_mesh_unit(double d) const { return d * m_cache->unit; }

private:
  // The named parameter `glued_vertices` (a range of ranges of vertices), in indices, checked.
  template <class NamedParameters, class VertexIndexMap>
  static std::vector<std::vector<int>> glued_groups(const TriangleMesh& tm, const NamedParameters& np,
                                                    const VertexIndexMap& vim)
  {
    std::vector<std::vector<int>> groups;
    if constexpr(!CGAL::parameters::is_default_parameter<NamedParameters, internal_np::glued_vertices_t>::value) {
      const long long n = static_cast<long long>(num_vertices(tm));
      for(const auto& group : CGAL::parameters::get_parameter(np, internal_np::glued_vertices)) {
        groups.emplace_back();
        for(vertex_descriptor v : group) {
          const long long i = static_cast<long long>(get(vim, v));
          if(i < 0 || i >= n)
            throw Geodesic_error("glued vertex index " + std::to_string(i) + " is out of range [0, " +
                                 std::to_string(n) + ")");
          groups.back().push_back(int(i));
        }
      }
    }
    return groups;
  }

  const TriangleMesh* m_tm; // a pointer, so that the object can be moved
  VertexPointMap m_vpm;
  std::unique_ptr<Solver_mesh> m_cache;
  std::vector<vertex_descriptor> m_vertex_of_index;
  std::vector<face_descriptor> m_face_of_index;
  std::function<int(vertex_descriptor)> m_vertex_index;
  std::function<int(face_descriptor)> m_face_index;
  double m_seconds = 0;
};

/// The vertex point map type of `TriangleMesh` with the named parameters `NamedParameters`.
template <class TriangleMesh, class NamedParameters>
using Vertex_point_map_of = typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type;

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_MESH_MESH_SETUP_H
