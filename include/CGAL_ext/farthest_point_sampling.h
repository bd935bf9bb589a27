// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_FARTHEST_POINT_SAMPLING_H
#define CGAL_EXT_FARTHEST_POINT_SAMPLING_H

/// \file farthest_point_sampling.h
/// Exact geodesic farthest-point sampling of the vertices of a triangle mesh.

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>
#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>
#include <CGAL_ext/Geodesics_3/Named_function_parameters.h>
#include <CGAL_ext/Geodesics_3/internal/mesh/Mesh_setup.h>
#include <CGAL_ext/Geodesics_3/internal/sampling/Farthest_point_sampler.h>
#include <CGAL_ext/Geodesics_3/internal/support/Progress_reporter.h>
#include <CGAL_ext/Geodesics_3/internal/support/Solver_arena.h>

#include <CGAL/iterator.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// samples the vertices of `tm` by farthest points, with exact geodesic distances: each sample
/// after the first (after the `initial_samples`, when given) is the vertex farthest from all the
/// samples before it (the lowest index of those at the largest distance). Vertices of a
/// component with no sample yet are at `+infinity`, so every component gets a sample before any
/// gets a second one (among the samples after the initial ones).
///
/// The sampling is incremental: the propagation of each new sample starts from the distance
/// field of the samples before it and prunes every window that cannot lower a vertex's
/// distance, so it sweeps only the region that the new sample takes over (the cell of its
/// Voronoi diagram), not the whole mesh. The distances, the samples and the labels are those of
/// the exact multi-source solve from the samples, to round-off.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` (each
///         propagation in parallel, PVTP; on two threads or more, two samples' propagations at
///         once where the second one provably computes what it would compute after the first
///         (see `Geodesic_statistics::batched_runs_kept`); the same samples for every number of
///         threads) or `CGAL::Parallel_if_available_tag`
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
/// \tparam OutputIterator an output iterator accepting `boost::graph_traits<TriangleMesh>::%vertex_descriptor`
/// \tparam NamedParameters a sequence of named parameters, started from `CGAL_ext::parameters`
///
/// \param tm the triangle mesh (non-manifold vertices, degenerate faces and isolated vertices are taken,
///        as by `geodesic_distances()`)
/// \param number_of_samples how many samples at most: at least 1 and at most the number of vertices
/// \param samples receives the samples, in order, as they are found
/// \param np optional named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{first_sample}
///     \cgalParamDescription{the first sample}
///     \cgalParamType{`boost::graph_traits<TriangleMesh>::%vertex_descriptor`}
///     \cgalParamDefault{the vertex farthest from vertex 0 (from the first vertex in a face, if vertex 0 is in none)}
///   \cgalParamNEnd
///   \cgalParamNBegin{initial_samples}
///     \cgalParamDescription{the first samples, in order, taken as they are (they need not be far apart); the
///                           sampling goes on from them by farthest points. Their distance field comes from one
///                           propagation from all of them, and the covering radius reported after each of them
///                           is the one after all of them. Faster than a long run of farthest points when
///                           vertices known to be far apart are at hand: the first samples' propagations sweep
///                           most of the mesh each, one from many samples sweeps it once, a short way from each}
///     \cgalParamType{a range of `boost::graph_traits<TriangleMesh>::%vertex_descriptor`, distinct, at most
///                    `number_of_samples`; not with `first_sample`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{covering_radius}
///     \cgalParamDescription{stop as soon as every vertex is within this distance of a sample (with fewer than
///                           `number_of_samples` samples, then; the initial samples are all taken)}
///     \cgalParamType{`double`, positive}
///     \cgalParamDefault{none: `number_of_samples` samples}
///   \cgalParamNEnd
///   \cgalParamNBegin{covering_radius_output_iterator}
///     \cgalParamDescription{receives, after each sample, the covering radius: the largest distance from a vertex to its
///                           nearest sample so far (non-increasing; `+infinity` while a component has no sample;
///                           for each initial sample, the one after all of them)}
///     \cgalParamType{an output iterator accepting `double`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_distance_map}
///     \cgalParamDescription{receives the distance from every vertex to its nearest sample}
///     \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` keys and `double` values}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_source_map}
///     \cgalParamDescription{receives the index (in the order of the samples) of every vertex's nearest sample: its
///                           geodesic Voronoi cell}
///     \cgalParamType{a model of `WritablePropertyMap` with `vertex_descriptor` keys and integer values}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{approximation}
///     \cgalParamDescription{sample with AVTP's approximate distances (see `geodesic_distances()`): faster, and
///                           the samples are then the farthest up to the approximation}
///     \cgalParamType{`double`, positive}
///     \cgalParamDefault{none: exact distances}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{with `CGAL::Parallel_tag`: the threads of each propagation, `0` for TBB's choice}
///     \cgalParamType{`int`, non-negative}
///     \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{batch_size}
///     \cgalParamDescription{with `CGAL::Parallel_tag` or `approximation`: as in `geodesic_distances()`}
///     \cgalParamType{`std::size_t`, positive}
///     \cgalParamDefault{`CGAL_ext::default_batch_size`}
///   \cgalParamNEnd
///   \cgalParamNBegin{glued_vertices}
///     \cgalParamDescription{as in `geodesic_distances()`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{told the fraction of the samples found (or of the covering radius reached), a few times a second at most, from
///                           the calling thread; returning `false` stops with `Geodesic_cancelled`, the maps untouched}
///     \cgalParamType{callable as `bool(double)`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{statistics}
///     \cgalParamDescription{receives the windows and seconds of the samples' propagations together (not of
///                           the solve that finds the default first sample)}
///     \cgalParamType{`CGAL_ext::Geodesic_statistics&`}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, vertex_index_map, face_index_map}
///     \cgalParamDescription{as in `geodesic_distances()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the output iterator past the last sample
///
/// \throws Geodesic_error when `number_of_samples` is 0 or more than the number of vertices, when
///         `covering_radius` is not positive, when `first_sample` is out of range, when
///         `initial_samples` is empty, repeats a vertex, holds one out of range or more than
///         `number_of_samples`, or comes with `first_sample`, when fewer
///         distinct samples exist than asked (every vertex is a sample or at distance 0 from one
///         before the last is taken), for an `algorithm` other than VTP, for `max_distance` or
///         `stop_vertices`, and for what `geodesic_distances()` refuses in the mesh
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh, class OutputIterator,
          class NamedParameters = parameters::Default_named_parameters_type>
OutputIterator farthest_point_sampling(const TriangleMesh& tm, std::size_t number_of_samples, OutputIterator samples,
                                       const NamedParameters& np = parameters::default_values())
{
  namespace internal = Geodesics_3::internal;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  constexpr bool parallel = internal::is_parallel_tag<ConcurrencyTag>();
  const auto start = std::chrono::steady_clock::now();
  typedef internal::Vertex_point_map_of<TriangleMesh, NamedParameters> Vertex_point_map;
  const internal::Solver_settings settings = internal::read_solver_settings(np, VTP);
  if(settings.algorithm != VTP)
    throw Geodesic_error("farthest-point sampling runs VTP, got algorithm " + std::to_string(int(settings.algorithm)));
  if constexpr(!is_default_parameter<NamedParameters, internal_np::max_distance_t>::value ||
               !is_default_parameter<NamedParameters, internal_np::stop_vertices_t>::value)
    throw Geodesic_error("farthest-point sampling takes no max_distance or stop_vertices (use covering_radius)");
  double radius = 0; // in the mesh's unit; 0: none
  if constexpr(!is_default_parameter<NamedParameters, internal_np::covering_radius_t>::value) {
    radius = double(get_parameter(np, internal_np::covering_radius));
    if(!(radius > 0)) {
      std::ostringstream msg;
      msg << "covering radius must be positive, got " << radius;
      throw Geodesic_error(msg.str());
    }
  }

  const internal::Mesh_setup<TriangleMesh, Vertex_point_map> mesh(tm, np);
  const internal::Solver_mesh& cache = mesh.cache();
  if(number_of_samples < 1)
    throw Geodesic_error("the number of samples must be at least 1, got 0");
  if(number_of_samples > cache.number_of_mesh_vertices)
    throw Geodesic_error("asked for " + std::to_string(number_of_samples) + " samples, but the mesh has only " +
                         std::to_string(cache.number_of_mesh_vertices) + " vertices");
  std::vector<int> initial; // the caller's first samples, or the one first sample
  if constexpr(!is_default_parameter<NamedParameters, internal_np::initial_samples_t>::value) {
    if constexpr(!is_default_parameter<NamedParameters, internal_np::first_sample_t>::value)
      throw Geodesic_error("farthest-point sampling takes initial_samples or first_sample, not both");
    for(const auto& v : get_parameter(np, internal_np::initial_samples)) {
      initial.push_back(mesh.index(v));
      internal::check_vertex_index(cache, initial.back(), "initial sample");
    }
    if(initial.empty())
      throw Geodesic_error("initial_samples is empty");
    if(initial.size() > number_of_samples)
      throw Geodesic_error(std::to_string(initial.size()) + " initial samples, more than the " +
                           std::to_string(number_of_samples) + " samples asked for");
    // distinct points: a vertex given twice, or two vertices glued at one point, would leave
    // the later sample an empty cell
    std::vector<int> sample_at(cache.number_of_vertices, -1);
    for(std::size_t i = 0; i < initial.size(); ++i) {
      const int earlier = sample_at[std::size_t(initial[i])];
      if(earlier >= 0) {
        const int a = cache.mesh_vertex(initial[std::size_t(earlier)]), b = cache.mesh_vertex(initial[i]);
        throw Geodesic_error(a == b ? "initial sample " + std::to_string(a) + " is given twice"
                                    : "initial samples " + std::to_string(a) + " and " + std::to_string(b) +
                                        " are one point of the surface (glued)");
      }
      cache.for_each_copy_of_point(initial[i], [&](int u) { sample_at[std::size_t(u)] = int(i); });
    }
  } else if constexpr(!is_default_parameter<NamedParameters, internal_np::first_sample_t>::value) {
    initial.push_back(mesh.index(get_parameter(np, internal_np::first_sample)));
    internal::check_vertex_index(cache, initial.back(), "first sample");
  } else {
    // (without the callback: the sampling reports, from the start, the samples found)
    internal::Solver_settings first_settings = settings;
    first_settings.callback = {};
    initial.push_back(internal::default_first_sample<parallel>(cache, first_settings));
  }
  const double seconds_setup = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  auto radius_out = parameters::choose_parameter(get_parameter(np, internal_np::covering_radius_output_iterator),
                                                 CGAL::Emptyset_iterator());
  // The sampler's solvers run on any thread: the caller's callback is told of the samples here.
  internal::Solver_settings sampler_settings = settings;
  internal::Progress_reporter progress(std::exchange(sampler_settings.callback, {}), "farthest-point sampling");
  internal::Farthest_point_sampler<parallel> sampler(cache, sampler_settings);
  const auto enough = [&](std::size_t count, double covering) {
    return count == number_of_samples || (radius > 0 && mesh.to_mesh_unit(covering) <= radius);
  };
  std::size_t written = 0;
  const auto write_new_samples = [&] {
    for(; written < sampler.samples().size(); ++written) {
      *samples++ = mesh.vertex_of(sampler.samples()[written]);
      *radius_out++ = mesh.to_mesh_unit(sampler.covering_radii()[written]);
    }
  };
  sampler.add_initial_samples(initial);
  for(write_new_samples();; write_new_samples()) {
    const double covering = sampler.covering_radius();
    if(enough(sampler.samples().size(), covering))
      break;
    if(covering == 0)
      throw Geodesic_error("asked for " + std::to_string(number_of_samples) + " samples, but after " +
                           std::to_string(sampler.samples().size()) +
                           " every vertex is a sample or at distance 0 from one: no other distinct sample exists");
    progress.report([&] {
      return std::max(double(sampler.samples().size()) / double(number_of_samples),
                      radius > 0 ? radius / mesh.to_mesh_unit(covering) : 0.);
    });
    sampler.add_samples(sampler.farthest_vertex(), enough);
  }

  if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_distance_map_t>::value)
    mesh.write_vertex_distances(get_parameter(np, internal_np::vertex_distance_map), sampler.distances());
  if constexpr(!is_default_parameter<NamedParameters, internal_np::vertex_source_map_t>::value)
    mesh.write_vertex_sources(get_parameter(np, internal_np::vertex_source_map), sampler.nearest_samples());
  Geodesic_statistics statistics = sampler.statistics();
  statistics.vertices = cache.number_of_mesh_vertices;
  statistics.faces = cache.number_of_faces;
  internal::report_statistics(settings, statistics, seconds_setup);
  return samples;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_FARTHEST_POINT_SAMPLING_H
