// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_MESH_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_MESH_H

// The mesh of a pattern detection as its steps see it: by vertex index, with the named
// parameters of every geodesic call they make.

#include <CGAL_ext/Geodesics_3/Named_function_parameters.h>

#include <CGAL/tags.h>
#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <type_traits>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// The caller's mesh and maps, and its vertices by index (every step of the detection works on
/// vertex indices). The detector owns it; its parts read it.
template <bool parallel, class TriangleMesh, class VertexPointMap, class VertexIndexMap>
struct Pattern_mesh
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  typedef std::conditional_t<parallel, CGAL::Parallel_tag, CGAL::Sequential_tag> Concurrency;

  Pattern_mesh(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim, int threads)
    : tm(tm)
    , vpm(vpm)
    , vim(vim)
    , threads(threads)
  {
    vertex.resize(num_vertices(tm));
    for(vertex_descriptor v : vertices(tm))
      vertex[std::size_t(get(vim, v))] = v;
  }

  std::size_t index(vertex_descriptor v) const { return std::size_t(get(vim, v)); }

  // The named parameters of every geodesic call of the pipeline.
  auto solver_parameters() const
  {
    return CGAL_ext::parameters::vertex_point_map(vpm).vertex_index_map(vim).number_of_threads(threads);
  }

  const TriangleMesh& tm;
  VertexPointMap vpm;
  VertexIndexMap vim;
  int threads;
  std::vector<vertex_descriptor> vertex; // by index
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_MESH_H
