// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESIC_DISTANCES_H
#define CGAL_EXT_GEODESIC_DISTANCES_H

/// \file geodesic_distances.h
/// The one-shot function computing exact geodesic distances from sources to every vertex.

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>
#include <CGAL_ext/Geodesics_3/Named_function_parameters.h>
#include <CGAL_ext/Geodesics_3/internal/MMP_solver.h>
#include <CGAL_ext/Geodesics_3/internal/Mesh_cache.h>
#include <CGAL_ext/Geodesics_3/internal/VTP_solver.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <array>
#include <chrono>
#include <iterator>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// The solvers that `geodesic_distances()` can run, chosen with the named parameter
/// `algorithm`.
enum Geodesic_algorithm
{
  /// exact vertex-oriented triangle propagation (thesis chapter 4.1), the default of
  /// `geodesic_distances()`; with `CGAL::Parallel_tag`: PVTP
  VTP,
  /// exact window propagation with the windows kept on the edges, taken in exact order of
  /// distance from a binary heap (Mitchell, Mount and Papadimitriou; thesis chapter 3)
  MMP,
  /// MMP with the windows taken bucket by bucket (fast wavefront propagation), the default of
  /// `Surface_mesh_geodesic_paths`; with `CGAL::Parallel_tag`: PMMP
  FWP_MMP
};

/// \ingroup PkgGeodesics3Ref
/// The default of the named parameter `batch_size`: how many window lists the batched solvers
/// (parallel or approximate) propagate together at most.
constexpr std::size_t default_batch_size = 512;

/// \ingroup PkgGeodesics3Ref
/// The default of the named parameter `batch_size` for PMMP: how many windows are selected and
/// propagated together at most (the thesis's K; its running time stops changing beyond 1000).
constexpr std::size_t default_window_batch_size = 1024;

namespace Geodesics_3 {
namespace internal {

template <class T, class = void>
struct is_range : std::false_type {};
template <class T>
struct is_range<T, std::void_t<decltype(std::begin(std::declval<const T&>()))>> : std::true_type {};

// One source given as a vertex.
template <class TriangleMesh, class VIM, class FIM>
Source_point to_source_point(const TriangleMesh&, VIM vim, FIM,
                             typename boost::graph_traits<TriangleMesh>::vertex_descriptor v)
{
  Source_point s;
  s.vertex = static_cast<int>(get(vim, v));
  return s;
}

// One source given as a face location: a face and barycentric coordinates in the order of the
// face's vertices, starting at `source(halfedge(f))` (CGAL's Face_location convention).
template <class TriangleMesh, class VIM, class FIM, class FT>
Source_point to_source_point(
  const TriangleMesh&, VIM, FIM fim,
  const std::pair<typename boost::graph_traits<TriangleMesh>::face_descriptor, std::array<FT, 3>>& location)
{
  Source_point s;
  s.face = static_cast<int>(get(fim, location.first));
  for(int k = 0; k < 3; ++k)
    s.barycentric[k] = CGAL::to_double(location.second[k]);
  return s;
}

template <class TriangleMesh, class VIM, class FIM, class Sources>
std::vector<Source_point> to_source_points(const TriangleMesh& tm, VIM vim, FIM fim, const Sources& sources)
{
  std::vector<Source_point> points;
  if constexpr(is_range<Sources>::value) {
    for(const auto& s : sources)
      points.push_back(to_source_point(tm, vim, fim, s));
  } else {
    points.push_back(to_source_point(tm, vim, fim, sources));
  }
  return points;
}

// The named parameter `batch_size`, checked, or `fallback`.
template <class NamedParameters>
std::size_t batch_size_parameter(const NamedParameters& np, std::size_t fallback)
{
  const auto batch = CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::batch_size),
                                                        fallback);
  if(!(batch > 0))
    throw Geodesic_error("batch size must be positive, got " + std::to_string(batch));
  return static_cast<std::size_t>(batch);
}

// The named parameter `number_of_threads`, checked (0: TBB's choice).
template <class NamedParameters>
int number_of_threads_parameter(const NamedParameters& np)
{
  const long threads = static_cast<long>(
    CGAL::parameters::choose_parameter(CGAL::parameters::get_parameter(np, internal_np::number_of_threads), 0));
  if(threads < 0)
    throw Geodesic_error("number of threads must be non-negative, got " + std::to_string(threads));
  return int(threads);
}

// Sets up an MMP solver from the named parameters: the queue from `algorithm` (a binary heap
// for MMP, buckets for FWP-MMP), `max_distance`, `batch_size`, and PMMP when parallel.
template <bool parallel, class NamedParameters>
void configure_mmp_solver(MMP_solver& solver, Geodesic_algorithm algorithm, const NamedParameters& np)
{
  solver.set_max_distance(CGAL::parameters::choose_parameter(
    CGAL::parameters::get_parameter(np, internal_np::max_distance), std::numeric_limits<double>::infinity()));
  solver.set_queue(algorithm == MMP ? MMP_solver::BINARY_HEAP : MMP_solver::BUCKETS);
  solver.set_batch_size(batch_size_parameter(np, default_window_batch_size));
  if constexpr(parallel)
    solver.set_parallel();
}

// Runs a solver, in a task arena of `threads` threads (0: TBB's choice) when parallel: the
// arena bounds the threads of this call only, never a process-wide setting.
template <bool parallel, class Solver>
void run_solver(Solver& solver, int threads)
{
#ifdef CGAL_LINKED_WITH_TBB
  if constexpr(parallel) {
    tbb::task_arena arena(threads > 0 ? threads : tbb::task_arena::automatic);
    sanitizer_release(&solver);
    arena.execute([&] {
      sanitizer_acquire(&solver);
      solver.run();
      sanitizer_release(&solver);
    });
    sanitizer_acquire(&solver);
    return;
  }
#endif
  (void)threads;
  solver.run();
}

} // namespace internal
} // namespace Geodesics_3

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
/// \throws Geodesic_error when `tm` is empty, not a manifold triangle mesh, has a non-finite
///         coordinate or a degenerate triangle, when a source or stop vertex is out of range,
///         when barycentric coordinates are not a convex combination, or when `max_distance` is
///         negative, `approximation` not positive, `number_of_threads` negative or `batch_size` zero.
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class VertexDistanceMap,
          class Sources, class NamedParameters = parameters::Default_named_parameters_type>
void geodesic_distances(const TriangleMesh& tm, VertexDistanceMap vertex_distance_map,
                        const Sources& sources, const NamedParameters& np = parameters::default_values())
{
#ifndef CGAL_LINKED_WITH_TBB
  static_assert(!std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value,
                "CGAL_ext::geodesic_distances: CGAL::Parallel_tag needs TBB (CGAL_LINKED_WITH_TBB); "
                "use CGAL::Sequential_tag or CGAL::Parallel_if_available_tag");
#endif
  constexpr bool parallel = std::is_same<ConcurrencyTag, CGAL::Parallel_tag>::value;
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;

  const auto start = std::chrono::steady_clock::now();
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  const auto fim = CGAL::get_initialized_face_index_map(tm, np);
  const Geodesic_algorithm algorithm =
    choose_parameter(get_parameter(np, CGAL::internal_np::algorithm), VTP);
  if(algorithm != VTP && algorithm != MMP && algorithm != FWP_MMP)
    throw Geodesic_error("unknown geodesic algorithm " + std::to_string(int(algorithm)));
  constexpr bool has_approximation = !std::is_same<decltype(get_parameter(np, internal_np::approximation)),
                                                   CGAL::internal_np::Param_not_found>::value;
  constexpr bool has_stop_vertices = !std::is_same<decltype(get_parameter(np, internal_np::stop_vertices)),
                                                   CGAL::internal_np::Param_not_found>::value;
  const int threads = Geodesics_3::internal::number_of_threads_parameter(np);
  const double max_distance = choose_parameter(get_parameter(np, internal_np::max_distance),
                                               Geodesics_3::internal::VTP_solver::infinity());

  Geodesics_3::internal::Mesh_cache cache;
  Geodesics_3::internal::build_mesh_cache(tm, vpm, vim, fim, cache);
  const auto sources_in_cache = Geodesics_3::internal::to_source_points(tm, vim, fim, sources);
  auto finish = [&](const auto& solver, double seconds_setup) {
    const std::vector<double>& d = solver.distances();
    for(vertex_descriptor v : vertices(tm))
      put(vertex_distance_map, v, d[get(vim, v)]);
    Geodesic_statistics* stats = choose_parameter(get_parameter(np, internal_np::statistics),
                                                  static_cast<Geodesic_statistics*>(nullptr));
    if(stats) {
      *stats = solver.statistics();
      stats->seconds_setup = seconds_setup;
    }
  };

  if(algorithm != VTP) {
    if(has_approximation)
      throw Geodesic_error("approximation works with the VTP algorithm only");
    if(has_stop_vertices)
      throw Geodesic_error("stop_vertices works with the VTP algorithm only");
    Geodesics_3::internal::MMP_solver solver(cache);
    for(const auto& s : sources_in_cache)
      solver.add_source(s);
    Geodesics_3::internal::configure_mmp_solver<parallel>(solver, algorithm, np);
    const double seconds_setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Geodesics_3::internal::run_solver<parallel>(solver, threads);
    finish(solver, seconds_setup);
    return;
  }

  Geodesics_3::internal::VTP_solver solver(cache);
  for(const auto& s : sources_in_cache)
    solver.add_source(s);
  solver.set_max_distance(max_distance);
  if constexpr(has_approximation)
    solver.set_approximation(double(get_parameter(np, internal_np::approximation)));
  solver.set_batch_size(Geodesics_3::internal::batch_size_parameter(np, default_batch_size));
  if constexpr(parallel)
    solver.set_parallel();
  if constexpr(has_stop_vertices) {
    for(vertex_descriptor v : get_parameter(np, internal_np::stop_vertices))
      solver.add_stop_vertex(static_cast<int>(get(vim, v)));
  }
  const double seconds_setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Geodesics_3::internal::run_solver<parallel>(solver, threads);
  finish(solver, seconds_setup);
}

} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESIC_DISTANCES_H
