// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_PATCH_GEOMETRY_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_PATCH_GEOMETRY_H

// The marked patch of a pattern detection and its geometry: its vertices, centre, radius and
// size (thesis chapter 5; doc/design.md, "Repetitive pattern detection", step 1), with the
// vertex areas and the mean edge length of the mesh they are measured with.

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_curvature.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_rows.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_settings.h>
#include <CGAL_ext/geodesic_distances.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/number_type_config.h>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// The marked patch, by vertex index. The detector owns it and sets it first; the rows it needs
/// come from the detector's `Pattern_rows`.
template <bool parallel, class TriangleMesh, class VertexPointMap, class VertexIndexMap>
class Pattern_patch_geometry
{
  typedef Pattern_mesh<parallel, TriangleMesh, VertexPointMap, VertexIndexMap> Mesh;
  typedef Pattern_rows<parallel, TriangleMesh, VertexPointMap, VertexIndexMap> Rows;
  typedef typename Rows::Row Row;
  typedef typename Mesh::vertex_descriptor vertex_descriptor;

public:
  Pattern_patch_geometry(const Mesh& mesh, Rows& rows) : m_mesh(mesh), m_rows(rows) {}

  // The patch's vertices, centre and radius.
  void set_patch(const Pattern_patch_indices& patch)
  {
    const std::size_t n = m_mesh.vertex.size();
    m_area = vertex_areas(m_mesh.tm, m_mesh.vpm, m_mesh.vim);
    m_in_patch.assign(n, false);
    double total = 0, longest = 0;
    std::size_t count = 0;
    const TriangleMesh& tm = m_mesh.tm;
    for(auto e : edges(tm)) {
      const double length = std::sqrt(double(CGAL::squared_distance(get(m_mesh.vpm, source(halfedge(e, tm), tm)),
                                                                    get(m_mesh.vpm, target(halfedge(e, tm), tm)))));
      total += length;
      longest = std::max(longest, length);
      ++count;
    }
    m_mean_edge = count ? total / double(count) : 0.0;
    if(patch.is_disk) {
      if(patch.center >= n)
        throw Geodesic_error("pattern detection: the patch centre " + std::to_string(patch.center) +
                             " is not a vertex (the mesh has " + std::to_string(n) + ")");
      if(!(patch.radius > 0) || !std::isfinite(patch.radius))
        throw Geodesic_error("pattern detection: the patch radius must be positive, got " +
                             std::to_string(patch.radius));
      m_center = patch.center;
      const Row row = m_rows.local_row(m_center, patch.radius * (1 + 1e-12));
      double farthest = 0;
      for(const auto& [v, d] : row)
        if(d <= patch.radius) {
          m_in_patch[v] = true;
          farthest = std::max(farthest, d);
        }
      // the disk covers its whole component when a row longer by the longest edge reaches no
      // more vertices (a component that reaches beyond the radius has a vertex within an edge
      // beyond it)
      const Row beyond = m_rows.local_row(m_center, patch.radius + 1.01 * longest);
      if(beyond.size() == row.size())
        throw Geodesic_error("pattern detection: the patch radius " + std::to_string(patch.radius) +
                             " is larger than the mesh around the centre (every vertex there is within " +
                             std::to_string(farthest) + ")");
      m_radius = patch.radius;
      set_patch_vertices();
    } else {
      for(std::size_t v : patch.vertices) {
        if(v >= n)
          throw Geodesic_error("pattern detection: patch vertex " + std::to_string(v) +
                               " is out of range (the mesh has " + std::to_string(n) + " vertices)");
        m_in_patch[v] = true;
      }
      set_patch_vertices();
      set_patch_of_vertices(patch.vertices);
    }
    // the size of the patch: the radius of a disk of its area (its radius when it is a disk,
    // less when it is elongated, whose samples and signatures follow its width)
    const std::vector<double>& area = m_area;
    double patch_area = 0;
    for(std::size_t v = 0; v < n; ++v)
      if(m_in_patch[v])
        patch_area += area[v];
    m_size = std::min(m_radius, std::sqrt(patch_area / CGAL_PI));
    if(!(m_size > 0))
      throw Geodesic_error("pattern detection: the patch has no area");
  }

  bool in_patch(std::size_t v) const { return m_in_patch[v]; }
  // increasing; rows that must reach them all stop there
  const std::vector<std::size_t>& vertices() const { return m_patch_vertices; }
  std::size_t center() const { return m_center; }
  // the largest distance from the centre to a patch vertex
  double radius() const { return m_radius; }
  // the radius of a disk of the patch's area
  double size() const { return m_size; }
  // of the mesh's edges
  double mean_edge() const { return m_mean_edge; }
  // by vertex, of the whole mesh
  const std::vector<double>& area() const { return m_area; }

private:
  void set_patch_vertices()
  {
    m_patch_vertices.clear();
    for(std::size_t v = 0; v < m_mesh.vertex.size(); ++v)
      if(m_in_patch[v])
        m_patch_vertices.push_back(v);
  }

  // A vertex list: connected, with a border; its centre is the vertex farthest from its border
  // (on its medial axis: the landmark of an elongated patch), its radius the farthest vertex
  // from that centre.
  void set_patch_of_vertices(const std::vector<std::size_t>& list)
  {
    std::vector<std::size_t> stack{list.front()};
    std::vector<bool> seen(m_mesh.vertex.size(), false);
    seen[list.front()] = true;
    std::size_t reached = 0;
    std::vector<vertex_descriptor> border;
    while(!stack.empty()) {
      const std::size_t v = stack.back();
      stack.pop_back();
      ++reached;
      bool on_border = CGAL::is_border(m_mesh.vertex[v], m_mesh.tm) != boost::none;
      for(vertex_descriptor w : CGAL::vertices_around_target(m_mesh.vertex[v], m_mesh.tm)) {
        const std::size_t wi = m_mesh.index(w);
        if(!m_in_patch[wi])
          on_border = true;
        else if(!seen[wi]) {
          seen[wi] = true;
          stack.push_back(wi);
        }
      }
      if(on_border)
        border.push_back(m_mesh.vertex[v]);
    }
    const std::size_t distinct = m_patch_vertices.size();
    if(reached != distinct)
      throw Geodesic_error("pattern detection: the patch vertices are not connected (" + std::to_string(reached) +
                           " of " + std::to_string(distinct) + " reached from vertex " + std::to_string(list.front()) +
                           " through patch edges)");
    if(border.size() == distinct && distinct < 3)
      throw Geodesic_error("pattern detection: the patch has fewer than 3 vertices");
    std::vector<double> from_border(m_mesh.vertex.size(), 0.0);
    std::vector<vertex_descriptor> patch_vertices;
    for(std::size_t v : m_patch_vertices)
      patch_vertices.push_back(m_mesh.vertex[v]);
    geodesic_distances<typename Mesh::Concurrency>(m_mesh.tm, CGAL::make_property_map(from_border), border,
                                                   m_mesh.solver_parameters().stop_vertices(patch_vertices));
    std::size_t deepest = list.front();
    for(std::size_t v = 0; v < m_mesh.vertex.size(); ++v)
      if(m_in_patch[v] && from_border[v] > from_border[deepest])
        deepest = v;
    // The centre is the midpoint of the medial axis: the distance from the border is nearly flat
    // along the axis of an elongated patch, so its largest value alone may sit anywhere near
    // the middle. Among the vertices almost as deep as the deepest (the axis), the centre is the
    // one that is as far as possible from neither end of the patch's longest extent (the two
    // farthest-apart vertices found by two sweeps).
    const auto farthest_in_patch = [&](const Row& row) {
      std::size_t far = row.front().first;
      double d_far = -1;
      for(const auto& [v, d] : row)
        if(m_in_patch[v] && d > d_far) {
          far = v;
          d_far = d;
        }
      return far;
    };
    const std::size_t end_a = farthest_in_patch(patch_row(deepest));
    const Row row_a = patch_row(end_a);
    const std::size_t end_b = farthest_in_patch(row_a);
    const Row row_b = patch_row(end_b);
    std::vector<double> from_ends(m_mesh.vertex.size(), 0.0);
    for(const Row* row : {&row_a, &row_b})
      for(const auto& [v, d] : *row)
        from_ends[v] = std::max(from_ends[v], d);
    m_center = deepest;
    for(std::size_t v = 0; v < m_mesh.vertex.size(); ++v)
      if(m_in_patch[v] && from_border[v] >= 0.8 * from_border[deepest] && from_ends[v] < from_ends[m_center])
        m_center = v;
    m_center = patch_centroid(m_center);
    m_radius = 0;
    for(const auto& [v, d] : patch_row(m_center))
      m_radius = std::max(m_radius, d);
    if(!(m_radius > 0))
      throw Geodesic_error("pattern detection: the patch has no extent (all its vertices are at one point)");
  }

  // The patch's geodesic centroid among its vertices: the one whose area-weighted mean squared
  // distance to the patch's vertices is least (the centre of a symmetric patch whatever its
  // shape, and it weighs every vertex, so that a border's jagged edge moves it little), by
  // descent from `start`, with rows that stop once the patch's vertices are settled.
  std::size_t patch_centroid(std::size_t start)
  {
    const auto best = m_rows.descend(
      {start}, std::numeric_limits<double>::infinity(), same_stops_for_every_row(m_patch_vertices),
      [&](std::size_t, std::size_t, const Row& entries) {
        double c = 0;
        for(const auto& [v, d] : entries)
          if(m_in_patch[v])
            c += m_area[v] * d * d;
        return c;
      },
      [&](std::size_t, std::size_t v) { return bool(m_in_patch[v]); }, std::numeric_limits<int>::max());
    return best.front().first;
  }

  // The distances from `source` to the patch's vertices (the row stops once they are settled).
  Row patch_row(std::size_t source)
  {
    Row row;
    m_rows.for_each_local_row(
      {source}, std::numeric_limits<double>::infinity(),
      [&](std::size_t, const Row& entries) {
        for(const auto& entry : entries)
          if(m_in_patch[entry.first])
            row.push_back(entry);
      },
      m_patch_vertices);
    return row;
  }

  const Mesh& m_mesh;
  Rows& m_rows;
  std::vector<bool> m_in_patch;
  std::vector<std::size_t> m_patch_vertices; // increasing; rows that must reach them all stop there
  std::size_t m_center = 0;
  double m_radius = 0; // the largest distance from the centre to a patch vertex
  double m_size = 0;   // the radius of a disk of the patch's area
  double m_mean_edge = 0;
  std::vector<double> m_area; // by vertex
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_PATCH_GEOMETRY_H
