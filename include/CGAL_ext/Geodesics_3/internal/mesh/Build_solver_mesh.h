// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_MESH_BUILD_SOLVER_MESH_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_MESH_BUILD_SOLVER_MESH_H

// The solver mesh built from any FaceListGraph of the caller: the flat arrays read, checked, scaled
// when the coordinates are extreme, ordered and repaired (Solver_mesh_order.h, Solver_mesh_repairs.h).

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh_order.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Solver_mesh_repairs.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/Dynamic_property_map.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

inline void Solver_mesh::finish(const std::vector<std::vector<int>>& glued_groups)
{
  number_of_mesh_vertices = position.size();
  number_of_mesh_faces = number_of_faces;
  std::vector<std::vector<int>> groups = glued_groups;
  // a clean mesh computes its frames once; degenerate faces are removed, and the frames redone
  const bool none_degenerate = compute_frames();
  check_glued_groups(glued_groups);
  if(!none_degenerate) {
    remove_degenerate_faces(groups);
    number_of_faces = corner_vertex.size() / 3;
    compute_frames();
  }
  // One outgoing half-edge per vertex, a border one when there is one, so that turning around
  // the vertex from it meets every face of its fan.
  first_outgoing.assign(position.size(), -1);
  std::vector<std::int32_t> corner_count(position.size(), 0);
  for(std::size_t h = 0; h < corner_vertex.size(); ++h) {
    if(is_face_removed(face(int(h))))
      continue;
    const int v = corner_vertex[h];
    ++corner_count[v];
    if(first_outgoing[v] < 0 || opposite_halfedge[h] < 0)
      first_outgoing[v] = static_cast<std::int32_t>(h);
  }
  split_non_manifold_vertices(corner_count);
  number_of_vertices = position.size();
  glue_vertices(groups);
  compute_vertex_flags();
  // the pseudo-source flags (from the angle sums) are all the solvers need of the corner angles
  std::vector<double>().swap(corner_angle);
  order_vertices();
}

/// Divides the positions by a power of two (exactly) when the mesh is so large or so small that
/// squared lengths would overflow or underflow: distances scale with the mesh.
inline void scale_to_unit(Solver_mesh& cache)
{
  double largest = 0;
  for(const auto& p : cache.position)
    for(int i = 0; i < 3; ++i)
      largest = std::max(largest, std::abs(p[i]));
  // Coordinates within 2^-60 .. 2^60 (1e-18 .. 1e18) are left alone; the fourth powers of
  // lengths that the solvers form stay within the range of doubles.
  const double high = std::ldexp(1., 60), low = std::ldexp(1., -60);
  if(!(largest > high || (largest < low && largest > 0)))
    return;
  const int exponent = std::ilogb(largest);
  cache.unit = std::ldexp(1., exponent);
  for(auto& p : cache.position)
    for(int i = 0; i < 3; ++i)
      p[i] = std::ldexp(p[i], -exponent);
}

/// Builds the solver mesh of `tm`. Vertex `v` of `tm` becomes index `cache_vertex(get(vim, v))`, face
/// `f` becomes index `cache_face(get(fim, f))`. Throws `Geodesic_error` for an empty mesh, a face that is not a triangle,
/// a non-finite coordinate, or degenerate triangles that cannot be removed.
template <class TriangleMesh, class VertexPointMap, class VertexIndexMap, class FaceIndexMap>
void build_solver_mesh(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim,
                      FaceIndexMap fim, Solver_mesh& cache,
                      const std::vector<std::vector<int>>& glued_groups = {})
{
  typedef typename boost::graph_traits<TriangleMesh>::halfedge_descriptor halfedge_descriptor;
  const std::size_t nv = static_cast<std::size_t>(num_vertices(tm));
  const std::size_t nf = static_cast<std::size_t>(num_faces(tm));
  if(nv == 0 || nf == 0)
    throw Geodesic_error("the mesh is empty (" + std::to_string(nv) + " vertices, " +
                         std::to_string(nf) + " faces)");
  if(nv >= std::size_t(std::numeric_limits<std::int32_t>::max()) ||
     3 * nf >= std::size_t(std::numeric_limits<std::int32_t>::max()))
    throw Geodesic_error("the mesh is too large for 32-bit indices");

  cache.number_of_vertices = nv;
  cache.number_of_faces = nf;
  cache.position.assign(nv, {0., 0., 0.});
  // Indices come from the caller's maps: each must be in range and used once.
  auto checked_index = [](auto index, std::size_t n, std::vector<std::uint8_t>& seen, const char* what) {
    const long long i = static_cast<long long>(index);
    if(i < 0 || std::size_t(i) >= n || seen[std::size_t(i)])
      throw Geodesic_error(std::string(what) + " index map gives " + std::to_string(i) + ", " +
                           (i < 0 || std::size_t(i) >= n ? "out of range [0, " + std::to_string(n) + ")"
                                                         : std::string("to two elements")));
    seen[std::size_t(i)] = 1;
    return std::size_t(i);
  };
  std::vector<std::uint8_t> seen(nv, 0);
  for(auto v : vertices(tm)) {
    const auto& p = get(vpm, v);
    const std::size_t i = checked_index(get(vim, v), nv, seen, "vertex");
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()), z = CGAL::to_double(p.z());
    if(!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
      std::ostringstream msg;
      msg << "vertex " << i << " has a non-finite coordinate (" << x << ", " << y << ", " << z << ")";
      throw Geodesic_error(msg.str());
    }
    cache.position[i] = {x, y, z};
  }
  scale_to_unit(cache);

  auto local_index = get(CGAL::dynamic_halfedge_property_t<int>(), tm);
  cache.corner_vertex.assign(3 * nf, -1);
  seen.assign(nf, 0);
  for(auto f : faces(tm)) {
    const std::size_t fi = checked_index(get(fim, f), nf, seen, "face");
    int k = 0;
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      if(k < 3) {
        cache.corner_vertex[3 * fi + k] = static_cast<std::int32_t>(get(vim, source(h, tm)));
        put(local_index, h, static_cast<int>(3 * fi + k));
      }
      ++k;
    }
    if(k != 3)
      throw Geodesic_error("face " + std::to_string(fi) + " has " + std::to_string(k) +
                           " vertices; only triangle meshes are supported");
  }
  cache.order_faces();
  // half-edge 3i+k of the caller's face i is half-edge k of its solver-mesh face
  auto in_cache = [&cache](int h) { return 3 * cache.cache_face(h / 3) + h % 3; };
  cache.opposite_halfedge.assign(3 * nf, -1);
  for(auto f : faces(tm)) {
    for(halfedge_descriptor h : CGAL::halfedges_around_face(halfedge(f, tm), tm)) {
      const halfedge_descriptor o = opposite(h, tm);
      if(!is_border(o, tm))
        cache.opposite_halfedge[std::size_t(in_cache(get(local_index, h)))] = in_cache(get(local_index, o));
    }
  }
  cache.finish(glued_groups);
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_MESH_BUILD_SOLVER_MESH_H
