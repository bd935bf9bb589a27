// Copyright (c) 2026 The CGAL_ext geodesics developers.
// geodesic_distances() as the tests call it: distances in a vector in vertex order, from vertex
// sources, face-location sources, or both.
#ifndef CGAL_EXT_TEST_SUPPORT_SOLVE_H
#define CGAL_EXT_TEST_SUPPORT_SOLVE_H

#include "meshes.h"

#include <CGAL_ext/geodesic_distances.h>

#include <limits>
#include <vector>

namespace test_support {

/// the solver's distances, in the order of vertices(g); a vertex the solver did not write is NaN
template <class ConcurrencyTag = CGAL::Sequential_tag, class Graph, class SourceRange,
          class NamedParameters = CGAL_ext::parameters::Default_named_parameters_type>
std::vector<double> solve(const Graph& g, const SourceRange& sources,
                          const NamedParameters& np = CGAL_ext::parameters::default_values())
{
  auto map = get(CGAL::dynamic_vertex_property_t<double>(), g);
  for(auto v : vertices(g))
    put(map, v, std::numeric_limits<double>::quiet_NaN());
  CGAL_ext::geodesic_distances<ConcurrencyTag>(g, map, sources, np);
  std::vector<double> out;
  for(auto v : vertices(g))
    out.push_back(get(map, v));
  return out;
}

/// The solver from vertex and face sources together. `geodesic_distances` takes one range
/// type, so the vertices are passed as corner locations (coordinate 1 at the vertex), which the
/// solver turns back into vertex sources (test_oracle checks that the results are identical).
template <class ConcurrencyTag = CGAL::Sequential_tag,
          class NamedParameters = CGAL_ext::parameters::Default_named_parameters_type>
std::vector<double> solve_mixed(const Mesh& m, const std::vector<Vertex>& vertex_sources,
                                const std::vector<Face_location>& face_sources,
                                const NamedParameters& np = CGAL_ext::parameters::default_values())
{
  if(face_sources.empty())
    return solve<ConcurrencyTag>(m, vertex_sources, np);
  std::vector<Face_location> all;
  for(Vertex v : vertex_sources)
    all.push_back(corner_location(m, v));
  all.insert(all.end(), face_sources.begin(), face_sources.end());
  return solve<ConcurrencyTag>(m, all, np);
}

} // namespace test_support

#endif // CGAL_EXT_TEST_SUPPORT_SOLVE_H
