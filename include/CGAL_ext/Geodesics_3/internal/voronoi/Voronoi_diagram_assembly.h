// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_VORONOI_VORONOI_DIAGRAM_ASSEMBLY_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_VORONOI_VORONOI_DIAGRAM_ASSEMBLY_H

// The diagram as `geodesic_voronoi_diagram()` returns it, from what `Voronoi_builder` found face
// by face: the Voronoi vertices found in several faces merged into one, the bisector pieces
// joined into curves between them, points given back as the caller's face locations and
// positions, and the dual graph.

#include <CGAL_ext/Geodesics_3/internal/voronoi/Voronoi_builder.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <set>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// Fills `diagram`'s bisectors, Voronoi vertices, dual graph and unresolved parts from `builder`
/// (run), on the mesh of `mesh` (a `Mesh_setup`, for the caller's faces and unit).
template <class Point_3, class Diagram, class Setup>
void assemble_voronoi_diagram(const Setup& mesh, Voronoi_builder& builder, Diagram& diagram)
{
  typedef typename Diagram::FT FT;
  const Solver_mesh& cache = mesh.cache();
  auto point_of = [&](const Face_point& p) {
    typename Diagram::Point out;
    const std::array<double, 3> x = builder.position(p);
    int f = p.face;
    std::array<double, 3> b = p.b;
    if(cache.is_face_changed(p.face)) // a face the solver mesh split or removed: the caller's face
      cache.mesh_face_point(p.face, x, f, b);
    out.location = typename Diagram::Face_location(mesh.face_of(f), {{FT(b[0]), FT(b[1]), FT(b[2])}});
    out.point = Point_3(mesh.to_mesh_unit(x[0]), mesh.to_mesh_unit(x[1]), mesh.to_mesh_unit(x[2]));
    return out;
  };

  std::vector<Bisector_piece>& pieces = builder.pieces();
  std::vector<std::array<double, 3>> first(pieces.size()), last(pieces.size()), vertex_point;
  for(std::size_t i = 0; i < pieces.size(); ++i) {
    first[i] = builder.position(pieces[i].points.front());
    last[i] = builder.position(pieces[i].points.back());
  }
  const double tolerance = 1e-9 * cache.mean_edge_length;
  // A Voronoi vertex on an edge or a vertex of the mesh is found in every face around it, each
  // face seeing the cells it touches: one vertex, of all their cells.
  const std::vector<Voronoi_vertex_found>& found = builder.vertices();
  std::vector<std::array<double, 3>> found_point;
  for(const Voronoi_vertex_found& v : found)
    found_point.push_back(builder.position(v.location));
  std::vector<std::size_t> by_x(found.size()), root(found.size());
  for(std::size_t i = 0; i < found.size(); ++i)
    by_x[i] = root[i] = i;
  std::sort(by_x.begin(), by_x.end(), [&](std::size_t a, std::size_t b) {
    return found_point[a][0] < found_point[b][0] || (found_point[a][0] == found_point[b][0] && a < b);
  });
  for(std::size_t i = 0; i < by_x.size(); ++i)
    for(std::size_t j = i; j-- > 0 && found_point[by_x[i]][0] - found_point[by_x[j]][0] <= tolerance;) {
      if(within(found_point[by_x[i]], found_point[by_x[j]], tolerance)) {
        root[by_x[i]] = root[by_x[j]];
        break;
      }
    }
  std::vector<Voronoi_vertex_found> voronoi_vertices;
  std::vector<int> kept_as(found.size(), -1);
  for(std::size_t i = 0; i < found.size(); ++i) // in the order found: the first of each point is kept
    if(kept_as[root[i]] < 0) {
      kept_as[root[i]] = int(voronoi_vertices.size());
      voronoi_vertices.push_back(found[root[i]]);
      vertex_point.push_back(found_point[root[i]]);
    }
  for(std::size_t i = 0; i < found.size(); ++i) {
    kept_as[i] = kept_as[root[i]];
    std::vector<int>& cells = voronoi_vertices[std::size_t(kept_as[i])].sources;
    cells.insert(cells.end(), found[i].sources.begin(), found[i].sources.end());
    std::sort(cells.begin(), cells.end());
    cells.erase(std::unique(cells.begin(), cells.end()), cells.end());
  }
  for(Bisector_piece& piece : pieces) {
    if(piece.start_vertex >= 0)
      piece.start_vertex = kept_as[std::size_t(piece.start_vertex)];
    if(piece.end_vertex >= 0)
      piece.end_vertex = kept_as[std::size_t(piece.end_vertex)];
  }
  add_cells_of_bisector_ends(pieces, first, last, voronoi_vertices, vertex_point, tolerance);
  attach_to_vertices(pieces, first, last, voronoi_vertices, vertex_point, tolerance);
  std::set<std::pair<std::size_t, std::size_t>> pairs;
  for(const auto& line : join_pieces(pieces, first, last, tolerance)) {
    typename Diagram::Bisector bisector;
    const Bisector_piece& head = pieces[line.front().first];
    bisector.first_source = std::size_t(head.first_source);
    bisector.second_source = std::size_t(head.second_source);
    for(const auto& [index, reversed] : line) {
      const std::vector<Face_point>& points = pieces[index].points;
      // the first point of a piece after the first is the last of the one before
      const std::size_t skip = bisector.points.empty() ? 0 : 1;
      for(std::size_t k = skip; k < points.size(); ++k)
        bisector.points.push_back(point_of(reversed ? points[points.size() - 1 - k] : points[k]));
    }
    // a curve of round-off size (pieces met where a part was cut down around a vertex) is none
    double extent = 0;
    for(const auto& [index, reversed] : line)
      for(const Face_point& p : pieces[index].points) {
        const std::array<double, 3> x = builder.position(p), o = first[line.front().first];
        extent = std::max({extent, std::abs(x[0] - o[0]), std::abs(x[1] - o[1]), std::abs(x[2] - o[2])});
      }
    if(!(extent > 1e-6 * cache.mean_edge_length))
      continue;
    pairs.insert({bisector.first_source, bisector.second_source});
    diagram.bisectors.push_back(std::move(bisector));
  }
  std::set<std::array<std::size_t, 3>> triples;
  for(const Voronoi_vertex_found& v : voronoi_vertices) {
    typename Diagram::Vertex vertex;
    vertex.point = point_of(v.location);
    for(int s : v.sources)
      vertex.sources.push_back(std::size_t(s));
    const std::vector<std::size_t>& s = vertex.sources;
    for(std::size_t i = 0; i < s.size(); ++i)
      for(std::size_t j = i + 1; j < s.size(); ++j)
        for(std::size_t k = j + 1; k < s.size(); ++k)
          triples.insert({{s[i], s[j], s[k]}});
    diagram.vertices.push_back(vertex);
  }
  diagram.dual_edges.assign(pairs.begin(), pairs.end());
  diagram.dual_triangles.assign(triples.begin(), triples.end());
  diagram.unresolved_parts = builder.unresolved();
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_VORONOI_VORONOI_DIAGRAM_ASSEMBLY_H
