// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESIC_DISTANCES_H
#define CGAL_EXT_GEODESIC_DISTANCES_H

/// \file geodesic_distances.h
/// The one-shot function computing exact geodesic distances from sources to every vertex.

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>
#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>
#include <CGAL_ext/Geodesics_3/Named_function_parameters.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/VTP_solver.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Mesh_setup.h>
#include <CGAL_ext/Geodesics_3/internal/support/Solver_arena.h>
#include <CGAL_ext/Surface_mesh_geodesic_paths.h>

#include <CGAL/tags.h>

#include <chrono>
#include <type_traits>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// computes the geodesic distance from the nearest of `sources` to every vertex of `tm` and
/// writes it to `vertex_distance_map`. By default distances are exact: those of the shortest
/// paths on the polyhedral surface. With `approximation(lambda)` they are approximate from above
/// (AVTP), the faster the smaller `lambda`.
///
/// With `CGAL::Parallel_tag` the window lists are propagated on TBB threads (PVTP, or PAVTP
/// with `approximation`); the distances are the same for every number of threads.
/// `CGAL::Parallel_if_available_tag` is parallel when TBB is linked and sequential otherwise.
///
/// Vertices that no source reaches (another connected component), and vertices beyond the
/// `max_distance` or beyond the farthest `stop_vertices`, get `+infinity`. A stop vertex that
/// no source reaches never settles: the propagation then covers everything it can reach.
///
/// Saddle and border vertices act as pseudo-sources, and so do vertices whose angle sum is
/// within 1e-6 of 2 pi (flat up to round-off): on meshes with large flat regions (CAD models)
/// this costs windows, never accuracy.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam VertexDistanceMap a model of `WritablePropertyMap` with
///         `boost::graph_traits<TriangleMesh>::%vertex_descriptor` as key and `double` as value
/// \tparam Sources a vertex, a face location `std::pair<face_descriptor, std::array<FT,3>>`
///         (barycentric coordinates in the order of the face's vertices, starting at
///         `source(halfedge(f, tm), tm)`), or a range of either
/// \tparam NamedParameters a sequence of named parameters, started from `CGAL_ext::parameters`
///
/// \param tm the triangle mesh; it must be a manifold triangle mesh without degenerate faces
/// \param vertex_distance_map receives the distance of every vertex
/// \param sources the source points; a duplicated source counts once
/// \param np optional named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{algorithm}
///     \cgalParamDescription{the solver}
///     \cgalParamType{`CGAL_ext::Geodesic_algorithm`}
///     \cgalParamDefault{`CGAL_ext::VTP`}
///   \cgalParamNEnd
///   \cgalParamNBegin{approximation}
///     \cgalParamDescription{`lambda`: every time the wavefront passes a multiple of `lambda` times the mean
///                           edge length its windows are dropped and its vertices become sources (AVTP);
///                           a small `lambda` is fast and coarse (towards Dijkstra over the edges), a large one
///                           exact}
///     \cgalParamType{`double`, positive}
///     \cgalParamDefault{none: exact distances}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{with `CGAL::Parallel_tag`: the number of threads (in a `tbb::task_arena`), `0` for
///                           as many as TBB chooses; TBB itself caps it at the number of cores unless the
///                           program raises the limit with a `tbb::global_control`; ignored when sequential}
///     \cgalParamType{`int`, non-negative}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{batch_size}
///     \cgalParamDescription{with `CGAL::Parallel_tag` or `approximation`: vertices are taken until this many
///                           window lists are scheduled, and the scheduled lists are propagated together; AVTP and
///                           PAVTP with the same batch size give the same distances}
///     \cgalParamType{`std::size_t`, positive}
///     \cgalParamDefault{`CGAL_ext::default_batch_size` (512)}
///   \cgalParamNEnd
///   \cgalParamNBegin{max_distance}
///     \cgalParamDescription{the propagation stops beyond this distance; farther vertices get `+infinity`}
///     \cgalParamType{`double`, non-negative}
///     \cgalParamDefault{`+infinity`}
///   \cgalParamNEnd
///   \cgalParamNBegin{stop_vertices}
///     \cgalParamDescription{the propagation stops once these vertices are settled; vertices farther than
///                           the farthest of them get `+infinity`}
///     \cgalParamType{a range of `boost::graph_traits<TriangleMesh>::%vertex_descriptor`}
///     \cgalParamDefault{none: every vertex is settled}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_source_map}
///     \cgalParamDescription{receives, for every vertex, the index of its nearest source in the order of
///                           `sources` (the Voronoi cell the vertex lies in), from the same propagation as the
///                           distances: the source of the path that gives the distance. Of duplicated sources
///                           the first wins; between different sources at the same distance the choice is the
///                           same for every number of threads. `CGAL_ext::no_source` (converted to the value
///                           type: -1 for a signed type) where the distance is `+infinity`. With an
///                           approximation the label is that of the approximate path}
///     \cgalParamType{a model of `WritablePropertyMap` with `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
///                    as key and an integer type as value}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{glued_vertices}
///     \cgalParamDescription{groups of vertices that are one point of the surface (the copies of a point that
///                           `polygon_soup_to_geodesic_mesh()` duplicated at a non-manifold vertex or edge): a
///                           path reaching one goes on from all of them. Vertices whose faces form several fans
///                           need no gluing: they are split and glued inside}
///     \cgalParamType{a range of ranges of `boost::graph_traits<TriangleMesh>::%vertex_descriptor`}
///     \cgalParamDefault{none: vertices at one place stay apart (the two sides of a cut)}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{told the fraction of the run done, in [0, 1] and never decreasing, from the
///                           calling thread, at the first check and then at most ten times a second;
///                           returning `false` stops the run with `Geodesic_cancelled`, the maps
///                           untouched}
///     \cgalParamType{callable as `bool(double)`, e.g. `std::function<bool(double)>`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{statistics}
///     \cgalParamDescription{receives windows created, peak live windows and seconds}
///     \cgalParamType{`CGAL_ext::Geodesic_statistics&`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map}
///     \cgalParamDescription{a property map associating points to the vertices of `tm`}
///     \cgalParamType{a model of `ReadablePropertyMap` with a 3D point as value type}
///     \cgalParamDefault{`boost::get(CGAL::vertex_point, tm)`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a property map associating to each vertex of `tm` a unique index between `0` and `num_vertices(tm) - 1`}
///     \cgalParamType{a model of `ReadablePropertyMap` with an integer value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
///   \cgalParamNBegin{face_index_map}
///     \cgalParamDescription{a property map associating to each face of `tm` a unique index between `0` and `num_faces(tm) - 1`}
///     \cgalParamType{a model of `ReadablePropertyMap` with an integer value type}
///     \cgalParamDefault{an automatically indexed internal map}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// Non-manifold vertices, degenerate (zero-area) triangles, isolated vertices (+infinity) and
/// coordinates of any scale are taken.
///
/// \throws Geodesic_error when `tm` is empty, has a face that is not a triangle, a non-finite
///         coordinate or only degenerate triangles, when a source, stop or glued vertex is out of
///         range, when every source is an isolated vertex,
///         when barycentric coordinates are not a convex combination, or when `max_distance` is
///         negative, `approximation` not positive, `number_of_threads` negative or `batch_size` zero;
///         `Geodesic_cancelled` when the `callback` returned `false`.
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class VertexDistanceMap,
          class Sources, class NamedParameters = parameters::Default_named_parameters_type>
void geodesic_distances(const TriangleMesh& tm, VertexDistanceMap vertex_distance_map,
                        const Sources& sources, const NamedParameters& np = parameters::default_values())
{
  namespace internal = Geodesics_3::internal;
  constexpr bool parallel = internal::is_parallel_tag<ConcurrencyTag>();
  const auto start = std::chrono::steady_clock::now();
  typedef internal::Vertex_point_map_of<TriangleMesh, NamedParameters> Vertex_point_map;
  const internal::Solver_settings settings = internal::read_solver_settings(np, VTP);

  if(settings.algorithm != VTP) { // the MMP family keeps its windows for queries: the same as a build
    Surface_mesh_geodesic_paths<TriangleMesh, ConcurrencyTag, Vertex_point_map> paths(tm, np);
    internal::for_each_source(sources, [&](const auto& s) { paths.add_source(s); });
    paths.build(np);
    paths.vertex_distances(vertex_distance_map);
    if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::vertex_source_map_t>::value)
      paths.vertex_sources(parameters::get_parameter(np, internal_np::vertex_source_map));
    return;
  }

  internal::Mesh_setup<TriangleMesh, Vertex_point_map> mesh(tm, np);
  std::vector<internal::Source_point> points;
  for(const internal::Source_point& s : mesh.source_points(sources))
    points.push_back(internal::normalized_source(mesh.cache(), s));
  std::vector<int> stops;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::stop_vertices_t>::value) {
    for(auto v : parameters::get_parameter(np, internal_np::stop_vertices))
      stops.push_back(mesh.index(v));
  }
  // The sources are placed: distances need no more. Freed before the solver's arrays are made,
  // so that the two never take memory together.
  mesh.release_positions();
  internal::VTP_solver solver(mesh.cache(), settings, parallel);
  for(const internal::Source_point& s : points)
    solver.add_normalized_source(s);
  for(int v : stops)
    solver.add_stop_vertex(v);
  const double seconds_setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  internal::run_solver<parallel>(solver, settings.number_of_threads);
  mesh.write_vertex_distances(vertex_distance_map, solver.distances());
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::vertex_source_map_t>::value)
    mesh.write_vertex_sources(parameters::get_parameter(np, internal_np::vertex_source_map), solver.nearest_sources());
  internal::report_statistics(settings, solver.statistics(), seconds_setup);
}

} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESIC_DISTANCES_H
