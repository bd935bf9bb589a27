// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESIC_VORONOI_DIAGRAM_H
#define CGAL_EXT_GEODESIC_VORONOI_DIAGRAM_H

/// \file geodesic_voronoi_diagram.h
/// The exact geodesic Voronoi diagram of points of a triangle mesh, cut across faces, and its
/// dual (the geodesic Delaunay graph).

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>
#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>
#include <CGAL_ext/Geodesics_3/Named_function_parameters.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Mesh_setup.h>
#include <CGAL_ext/Geodesics_3/internal/paths/Exact_window_build.h>
#include <CGAL_ext/Geodesics_3/internal/paths/Geodesic_path_tracer.h>
#include <CGAL_ext/Geodesics_3/internal/support/Solver_arena.h>
#include <CGAL_ext/Geodesics_3/internal/voronoi/Voronoi_builder.h>
#include <CGAL_ext/Geodesics_3/internal/voronoi/Voronoi_diagram_assembly.h>

#include <CGAL/Kernel_traits.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/tags.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <set>
#include <utility>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// The geodesic Voronoi diagram of sources on a triangle mesh, as `geodesic_voronoi_diagram()`
/// returns it. Sources are numbered in the order they were given.
template <class TriangleMesh, class Point_3>
struct Geodesic_voronoi_diagram
{
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  /// the number type of `Point_3`'s kernel
  typedef typename CGAL::Kernel_traits<Point_3>::Kernel::FT FT;
  /// a point of a face, as CGAL's `Polygon_mesh_processing` gives and takes it: barycentric
  /// coordinates in the order of its vertices from `source(halfedge(f))`
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, FT> Face_location;

  /// a point of the diagram: where it lies on the surface, and where in space
  struct Point
  {
    Face_location location;
    Point_3 point;
  };
  /// a curve where two cells meet: every point is as far from both sources, and no other
  /// source is nearer
  struct Bisector
  {
    std::size_t first_source, second_source; ///< the two sources, `first_source < second_source`
    std::vector<Point> points;               ///< a polyline across the faces it cuts
  };
  /// a point where three cells meet, or more (four symmetric sources meet at one point)
  struct Vertex
  {
    Point point;
    std::vector<std::size_t> sources; ///< increasing, three or more
  };

  /// by vertex index: the nearest source, or `no_source`. \deprecated pass
  /// `vertex_source_map(map)` to `geodesic_voronoi_diagram()` instead (as to `geodesic_distances()`);
  /// filled only when neither that nor `vertex_distance_map` is given, and gone in the next release
  std::vector<std::size_t> vertex_cell;
  /// by vertex index: the distance to the nearest source (`+infinity` if none). \deprecated pass
  /// `vertex_distance_map(map)` instead; filled as `vertex_cell` is
  std::vector<double> vertex_distance;
  std::vector<Bisector> bisectors;
  std::vector<Vertex> vertices;
  /// the dual graph (geodesic Delaunay): the pairs of sources whose cells share a bisector,
  /// each once, `first < second`, sorted
  std::vector<std::pair<std::size_t, std::size_t>> dual_edges;
  /// the triples of sources whose cells meet at a Voronoi vertex (every three of a vertex where
  /// more meet), each once, sorted
  std::vector<std::array<std::size_t, 3>> dual_triangles;
  /// parts of faces where more cells meet than the construction could tell apart (0 on every
  /// mesh of the tests); each is left out rather than guessed
  std::size_t unresolved_parts = 0;
};

/// \ingroup PkgGeodesics3Ref
/// computes the geodesic Voronoi diagram of `sources` on `tm`: the cell of every vertex (its
/// nearest source), the bisectors cut across faces, the Voronoi vertices where three cells meet,
/// and the dual graph.
///
/// The diagram is read from one exact multi-source propagation, whose windows give the distance
/// and nearest source at any point of the surface: VTP's by default (PVTP with
/// `CGAL::Parallel_tag`), kept as they are propagated across each face and clipped against each
/// other on each edge (VTP drops a path only where another is at least as short, so these
/// windows and the paths through the vertices give every distance), or with `algorithm(FWP_MMP)`
/// or `algorithm(MMP)` those MMP keeps (PMMP with `CGAL::Parallel_tag`); the same cells (VTP's
/// build is the quicker: it keeps fewer windows). In each face the nearest source is followed along the
/// boundary (each edge is cut where its windows change, and every change of the nearest source
/// is located by bisection to 1e-12 of the segment searched, at most an edge); a face crossed
/// by two cells holds one bisector, whose inner points are found the same way; a face where
/// three cells meet holds a Voronoi vertex, found by shrinking a triangle with a corner in each
/// cell to round-off; a face with more is cut in four, up to five times. Every point reported
/// is as far from its two (or three) sources as the solver's round-off allows. A cell that
/// crosses an edge or a face without containing any vertex is found too: it shows on the
/// windows of the edge, or as a source inside the face.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag`, `CGAL::Parallel_tag` or `CGAL::Parallel_if_available_tag`
/// \tparam TriangleMesh a model of `FaceListGraph`
/// \tparam Sources a vertex, a face location, or a range of either (as for `geodesic_distances()`)
///
/// \param tm the triangle mesh
/// \param sources the sites of the diagram; a duplicated source has an empty cell
/// \param np optional named parameters: `algorithm` (`VTP`, the default, `FWP_MMP` or `MMP`), `number_of_threads`,
///        `batch_size`, `glued_vertices`, `callback` (as for the paths' `build()`), `statistics` (a `Geodesic_statistics&`: the build's, and
///        `seconds_diagram`), `vertex_source_map` (receives each vertex's cell: the index of its nearest
///        source, `no_source` where none), `vertex_distance_map` (receives each vertex's distance to it),
///        and CGAL's `vertex_point_map`, `vertex_index_map`, `face_index_map`, as for `geodesic_distances()`
/// \return the diagram
///
/// \throws Geodesic_error for what `geodesic_distances()` throws, when there is no source, and for
///         `approximation`, `stop_vertices` or `max_distance` (every cell is whole and exact)
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class Sources,
          class NamedParameters = parameters::Default_named_parameters_type>
Geodesic_voronoi_diagram<TriangleMesh, typename boost::property_traits<
                                         Geodesics_3::internal::Vertex_point_map_of<TriangleMesh, NamedParameters>>::value_type>
geodesic_voronoi_diagram(const TriangleMesh& tm, const Sources& sources,
                         const NamedParameters& np = parameters::default_values())
{
  namespace internal = Geodesics_3::internal;
  using parameters::is_default_parameter;
  constexpr bool parallel = internal::is_parallel_tag<ConcurrencyTag>();
  typedef internal::Vertex_point_map_of<TriangleMesh, NamedParameters> Vertex_point_map;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point_3;
  typedef Geodesic_voronoi_diagram<TriangleMesh, Point_3> Diagram;

  if constexpr(!is_default_parameter<NamedParameters, internal_np::max_distance_t>::value)
    throw Geodesic_error("a Voronoi diagram takes no max_distance: every cell is whole");
  const internal::Solver_settings settings = internal::read_window_build_settings(np, "a Voronoi diagram");
  const internal::Mesh_setup<TriangleMesh, Vertex_point_map> mesh(tm, np);
  const internal::Solver_mesh& cache = mesh.cache();
  // the windows the diagram is read from: those MMP keeps on the edges, or VTP's as it propagated them
  internal::Exact_window_build build(cache, settings, parallel);
  internal::Solver_base& solver = build.solver();
  const internal::Edge_window_store& windows = build.windows();
  for(const internal::Source_point& s : mesh.source_points(sources))
    solver.add_source(s);
  build.run<parallel>(settings.number_of_threads);
  const internal::Geodesic_path_tracer tracer(windows, solver.distances(), solver.nearest_sources(), solver.sources(),
                                              solver.max_distance());
  const auto diagram_start = std::chrono::steady_clock::now();
  internal::Voronoi_builder builder(cache, windows, tracer);
  internal::run_in_arena<parallel>(settings.number_of_threads, [&] { builder.run(solver.sources(), parallel); });

  Diagram diagram;
  constexpr bool source_map = !is_default_parameter<NamedParameters, internal_np::vertex_source_map_t>::value;
  constexpr bool distance_map = !is_default_parameter<NamedParameters, internal_np::vertex_distance_map_t>::value;
  if constexpr(source_map)
    mesh.write_vertex_sources(parameters::get_parameter(np, internal_np::vertex_source_map), solver.nearest_sources());
  if constexpr(distance_map)
    mesh.write_vertex_distances(parameters::get_parameter(np, internal_np::vertex_distance_map), solver.distances());
  if constexpr(!source_map && !distance_map) { // the deprecated vectors, for callers that pass no map
    const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
    diagram.vertex_cell.resize(cache.number_of_mesh_vertices);
    diagram.vertex_distance.resize(cache.number_of_mesh_vertices);
    mesh.write_vertex_sources(boost::make_iterator_property_map(diagram.vertex_cell.begin(), vim),
                              solver.nearest_sources());
    mesh.write_vertex_distances(boost::make_iterator_property_map(diagram.vertex_distance.begin(), vim),
                                solver.distances());
  }
  internal::assemble_voronoi_diagram<Point_3>(mesh, builder, diagram);
  Geodesic_statistics statistics = build.statistics();
  statistics.seconds_diagram = std::chrono::duration<double>(std::chrono::steady_clock::now() - diagram_start).count();
  internal::report_statistics(settings, statistics, mesh.seconds());
  return diagram;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESIC_VORONOI_DIAGRAM_H
