// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_DETECT_REPETITIVE_PATTERNS_H
#define CGAL_EXT_DETECT_REPETITIVE_PATTERNS_H

/// \file detect_repetitive_patterns.h
/// Repetitive pattern detection from one marked instance (thesis chapter 5).

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>
#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>
#include <CGAL_ext/Geodesics_3/Named_function_parameters.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_detector.h>
#include <CGAL_ext/Geodesics_3/internal/support/Solver_arena.h>

#include <CGAL/boost/graph/properties.h>
#include <CGAL/tags.h>

#include <array>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL_ext {

/// \ingroup PkgGeodesics3Ref
/// The instance of a pattern that the user marks: a geodesic disk (a centre and a radius), or
/// any connected set of vertices (an elongated or irregular patch).
template <class TriangleMesh>
struct Pattern_patch
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  bool is_disk = false;                       ///< a disk, or else a vertex list
  vertex_descriptor center{};                 ///< the centre of a disk
  double radius = 0;                          ///< the radius of a disk
  std::vector<vertex_descriptor> vertices;    ///< the vertices of a vertex list

  /// the vertices within geodesic distance `radius` of `center`
  /// \param center the centre of the marked instance
  /// \param radius its geodesic radius, positive
  /// \return the patch
  static Pattern_patch disk(vertex_descriptor center, double radius)
  {
    Pattern_patch p;
    p.is_disk = true;
    p.center = center;
    p.radius = radius;
    return p;
  }
  /// the vertices of `range`, which must be connected through the mesh's edges; the centre is
  /// the patch's geodesic centroid (the vertex of least area-weighted mean squared geodesic
  /// distance to the patch's vertices)
  /// \tparam VertexRange a range of `vertex_descriptor`
  /// \param range the vertices of the marked instance
  /// \return the patch
  template <class VertexRange>
  static Pattern_patch of_vertices(const VertexRange& range)
  {
    Pattern_patch p;
    p.vertices.assign(range.begin(), range.end());
    return p;
  }
};

/// \ingroup PkgGeodesics3Ref
/// One instance of the pattern, as `detect_repetitive_patterns()` finds it.
template <class TriangleMesh, class Point_3>
struct Pattern_instance
{
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  vertex_descriptor center_vertex{}; ///< the vertex at the instance's centre (the image of the patch's centre)
  Point_3 center;                    ///< its position
  double scale = 1;                  ///< the instance's size over the patch's
  double energy = 0;                 ///< the energy of its correspondence (Eq. 5.4, lower is better; 0 for the patch)
  std::vector<vertex_descriptor> vertices; ///< its vertices
  /// the sample correspondence: (a sample of the patch, its image in this instance)
  std::vector<std::pair<vertex_descriptor, vertex_descriptor>> correspondence;
};

/// \ingroup PkgGeodesics3Ref
/// The instances of a pattern and their arrangement.
template <class TriangleMesh, class Point_3>
struct Repetitive_patterns
{
  std::vector<Pattern_instance<TriangleMesh, Point_3>> instances; ///< the marked patch first
  /// the arrangement: pairs of instances whose cells of the geodesic Voronoi diagram of the
  /// centres share a bisector (its dual graph), `first < second`
  std::vector<std::pair<std::size_t, std::size_t>> arrangement_edges;
  /// triples of instances whose cells meet at a Voronoi vertex
  std::vector<std::array<std::size_t, 3>> arrangement_triangles;
  /// \deprecated pass `statistics(s)` to `detect_repetitive_patterns()` instead, as to every
  /// long-running function of the package; this copy goes in the next release
  Pattern_statistics statistics;
};

/// \ingroup PkgGeodesics3Ref
/// finds the instances of the pattern that `patch` marks on `tm`, with a correspondence from the
/// patch's samples to each, and their arrangement (thesis chapter 5).
///
/// The pipeline: exact farthest-point samples of the mesh (the patch's centre first); the
/// signature of every sample (how the principal curvatures spread over the geodesic disk around
/// it, ring by ring); candidate matches from the patch's samples to the samples around it whose
/// signatures are alike; the matches grouped into candidate instances by the spectral embedding
/// of their geodesic consistency (Eq. 5.1-5.2) and a weighted mean shift (Eq. 5.3); each
/// candidate's correspondence refined by the energy of Eq. 5.4; region growing (Algorithm 7):
/// every new instance searches around itself for more, until none appears; each instance's
/// centre placed where the distances to its samples agree with the patch's; the arrangement as
/// the dual of the geodesic Voronoi diagram of the centres. Instances need not be regular,
/// equally spaced, isotropic or, with `scale_range`, of the patch's size.
///
/// The sample spacing and the signature radius are relative to the patch's size (the radius of
/// a disk of its area: its radius for a geodesic disk, less for an elongated patch, whose samples
/// then follow its width); the search radius is relative to the patch radius (the largest
/// geodesic distance from the patch's centre to its vertices). The centre of a vertex-list patch
/// is its geodesic centroid (on the medial axis of a symmetric patch: the landmark of the
/// thesis). Instance centres are vertices; the correspondence maps the patch's samples to
/// samples (to within about a spacing).
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default), `CGAL::Parallel_tag` or
///         `CGAL::Parallel_if_available_tag`: the propagations and curvatures on TBB threads
///         (the same instances for every number of threads)
/// \tparam TriangleMesh a model of `FaceListGraph` and `HalfedgeListGraph`
///
/// \param tm the triangle mesh
/// \param patch the marked instance
/// \param np optional named parameters among the ones listed below
///
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{sample_spacing}
///     \cgalParamDescription{the covering radius of the farthest-point sampling, relative to the patch's size}
///     \cgalParamType{`double`, positive} \cgalParamDefault{`1/3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{signature_radius}
///     \cgalParamDescription{the radius of the geodesic disk of a signature, relative to the patch's size}
///     \cgalParamType{`double`, positive} \cgalParamDefault{`1`}
///   \cgalParamNEnd
///   \cgalParamNBegin{signature_rings}
///     \cgalParamDescription{N: the rings (bands of distance) of a signature}
///     \cgalParamType{`int`, at least 1} \cgalParamDefault{`6`}
///   \cgalParamNEnd
///   \cgalParamNBegin{match_tolerance}
///     \cgalParamDescription{epsilon of Eq. 5.5: two samples match when their signatures differ by less than this
///                           times the mean signature norm of the patch's samples}
///     \cgalParamType{`double`, positive} \cgalParamDefault{`0.35`}
///   \cgalParamNEnd
///   \cgalParamNBegin{matches_per_sample}
///     \cgalParamDescription{candidate matches kept per patch sample and search, the most alike first}
///     \cgalParamType{`std::size_t`, positive} \cgalParamDefault{`24`}
///   \cgalParamNEnd
///   \cgalParamNBegin{consistency_cutoff}
///     \cgalParamDescription{c0 of Eq. 5.1; an instance's matched pairs must keep their distances to this ratio on average}
///     \cgalParamType{`double` in [0, 1)} \cgalParamDefault{`0.7`}
///   \cgalParamNEnd
///   \cgalParamNBegin{energy_weights}
///     \cgalParamDescription{alpha, beta and gamma of Eq. 5.4 (signature, consistency and landmark terms, each an
///                           average over the patch's samples)}
///     \cgalParamType{`std::array<double, 3>`, non-negative} \cgalParamDefault{`{1, 1, 1}`}
///   \cgalParamNEnd
///   \cgalParamNBegin{search_radius}
///     \cgalParamDescription{how far from an instance's centre (in patch radii, plus one) region growing looks for
///                           its neighbours}
///     \cgalParamType{`double`, positive} \cgalParamDefault{`3`}
///   \cgalParamNEnd
///   \cgalParamNBegin{scale_range}
///     \cgalParamDescription{the sizes of instances sought, relative to the patch (adaptive patterns, Eq. 5.5-5.6);
///                           the scales are searched about 10 % apart}
///     \cgalParamType{`std::pair<double, double>`, positive, first <= second} \cgalParamDefault{`{1, 1}`}
///   \cgalParamNEnd
///   \cgalParamNBegin{stroke}
///     \cgalParamDescription{with `scale_range`: a path of vertices that starts in the patch and crosses instances whose
///                           size changes along it (thesis 5.3.3). The scale goes geometrically from 1 at its start to
///                           the end of the range farthest from 1 at its end; each sample is matched only at scales
///                           within 20 % of its nearest stroke vertex's}
///     \cgalParamType{a range of `vertex_descriptor`, at least 2} \cgalParamDefault{none: every scale of the range}
///   \cgalParamNEnd
///   \cgalParamNBegin{approximation}
///     \cgalParamDescription{lambda of AVTP (as in `geodesic_distances()`) for every local distance row (the
///                           signatures, the distances between samples, the patch and the centres): faster on meshes
///                           that make many windows, with distances never below the exact ones; `0`: exact. The
///                           sampling, the patch's border distances and the arrangement stay exact}
///     \cgalParamType{`double`, non-negative} \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{number_of_threads}
///     \cgalParamDescription{with `CGAL::Parallel_tag`: the threads, `0` for TBB's choice}
///     \cgalParamType{`int`, non-negative} \cgalParamDefault{`0`}
///   \cgalParamNEnd
///   \cgalParamNBegin{callback}
///     \cgalParamDescription{called during the run with the fraction of it done (never decreasing, `1` at the end),
///                           from the calling thread; returning `false` stops the run, which then throws
///                           `Geodesic_error`}
///     \cgalParamType{an instance of `std::function<bool(double)>`} \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_instance_map}
///     \cgalParamDescription{receives the instance of every vertex: its index in the result's `instances`
///                           (the marked patch is 0), `CGAL_ext::no_source` (-1 in a signed map) for a vertex in
///                           none; a vertex of two overlapping instances gets the later one}
///     \cgalParamType{a writable property map, key `vertex_descriptor`, value an integer type}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{statistics}
///     \cgalParamDescription{receives the seconds of each step and what it counted}
///     \cgalParamType{`CGAL_ext::Pattern_statistics&`}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_point_map, vertex_index_map}
///     \cgalParamDescription{as in `geodesic_distances()`}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \return the instances, the marked patch first, and the arrangement
///
/// \throws Geodesic_error when the patch's centre or a vertex is out of range, its radius is not
///         positive or covers the whole component, its vertices are not connected, it holds
///         fewer than 3 samples or is flat, when the stroke has fewer than 2 vertices, a vertex out of
///         range or does not start in the patch, when a named parameter is out of its range, when the
///         callback stops the run, and for
///         what `geodesic_distances()` refuses in the mesh. A mesh with no other instance gives
///         just the patch.
template <class ConcurrencyTag = CGAL::Sequential_tag, class TriangleMesh,
          class NamedParameters = parameters::Default_named_parameters_type>
Repetitive_patterns<TriangleMesh, typename boost::property_traits<
                                    Geodesics_3::internal::Vertex_point_map_of<TriangleMesh, NamedParameters>>::value_type>
detect_repetitive_patterns(const TriangleMesh& tm, const Pattern_patch<TriangleMesh>& patch,
                           const NamedParameters& np = parameters::default_values())
{
  namespace internal = Geodesics_3::internal;
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef internal::Vertex_point_map_of<TriangleMesh, NamedParameters> Vertex_point_map;
  typedef typename boost::property_traits<Vertex_point_map>::value_type Point_3;
  constexpr bool parallel = internal::is_parallel_tag<ConcurrencyTag>();

  const Vertex_point_map vpm =
    choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point), get_const_property_map(CGAL::vertex_point, tm));
  const auto vim = CGAL::get_initialized_vertex_index_map(tm, np);

  internal::Pattern_settings s;
  s.sample_spacing = choose_parameter(get_parameter(np, internal_np::sample_spacing), s.sample_spacing);
  s.signature_radius = choose_parameter(get_parameter(np, internal_np::signature_radius), s.signature_radius);
  s.signature_rings = choose_parameter(get_parameter(np, internal_np::signature_rings), s.signature_rings);
  s.match_tolerance = choose_parameter(get_parameter(np, internal_np::match_tolerance), s.match_tolerance);
  s.matches_per_sample = choose_parameter(get_parameter(np, internal_np::matches_per_sample), s.matches_per_sample);
  s.consistency_cutoff = choose_parameter(get_parameter(np, internal_np::consistency_cutoff), s.consistency_cutoff);
  const std::array<double, 3> weights =
    choose_parameter(get_parameter(np, internal_np::energy_weights), std::array<double, 3>{s.alpha, s.beta, s.gamma});
  s.alpha = weights[0];
  s.beta = weights[1];
  s.gamma = weights[2];
  s.search_radius = choose_parameter(get_parameter(np, internal_np::search_radius), s.search_radius);
  const std::pair<double, double> scales =
    choose_parameter(get_parameter(np, internal_np::scale_range), std::pair<double, double>(1.0, 1.0));
  s.scale_min = scales.first;
  s.scale_max = scales.second;
  s.threads = choose_parameter(get_parameter(np, internal_np::number_of_threads), 0);
  s.approximation = double(choose_parameter(get_parameter(np, internal_np::approximation), s.approximation));
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::stroke_t>::value)
    for(auto v : get_parameter(np, internal_np::stroke))
      s.stroke.push_back(std::size_t(get(vim, v)));
  if constexpr(!parameters::is_default_parameter<NamedParameters, CGAL::internal_np::callback_t>::value)
    s.progress = get_parameter(np, CGAL::internal_np::callback);

  internal::Pattern_patch_indices indices;
  indices.is_disk = patch.is_disk;
  if(patch.is_disk) {
    indices.center = std::size_t(get(vim, patch.center));
    indices.radius = patch.radius;
  } else {
    if(patch.vertices.empty())
      throw Geodesic_error("pattern detection: the patch has no vertex and no radius");
    for(auto v : patch.vertices)
      indices.vertices.push_back(std::size_t(get(vim, v)));
  }
  // In an arena of the threads asked for: the steps' own loops (curvatures, signatures) take
  // those threads, not every core.
  internal::Detection_result found;
  internal::run_in_arena<parallel>(int(s.threads), [&] {
    internal::Pattern_detector<parallel, TriangleMesh, Vertex_point_map, decltype(vim)> detector(tm, vpm, vim, s);
    found = detector.run(indices);
  });

  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vertex_of_index(num_vertices(tm));
  for(auto v : vertices(tm))
    vertex_of_index[std::size_t(get(vim, v))] = v;
  Repetitive_patterns<TriangleMesh, Point_3> result;
  for(const internal::Detected_instance& d : found.instances) {
    Pattern_instance<TriangleMesh, Point_3> instance;
    instance.center_vertex = vertex_of_index[d.center];
    instance.center = get(vpm, instance.center_vertex);
    instance.scale = d.scale;
    instance.energy = d.energy;
    for(std::size_t v : d.vertices)
      instance.vertices.push_back(vertex_of_index[v]);
    for(const auto& [p, q] : d.correspondence)
      instance.correspondence.emplace_back(vertex_of_index[p], vertex_of_index[q]);
    result.instances.push_back(std::move(instance));
  }
  result.arrangement_edges = found.arrangement_edges;
  result.arrangement_triangles = found.arrangement_triangles;
  result.statistics = found.statistics;
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::statistics_t>::value) {
    typedef std::decay_t<decltype(get_parameter(np, internal_np::statistics))> Given;
    static_assert(std::is_convertible<Given, Pattern_statistics*>::value,
                  "CGAL_ext: detect_repetitive_patterns() reports a CGAL_ext::Pattern_statistics through `statistics`");
    *static_cast<Pattern_statistics*>(get_parameter(np, internal_np::statistics)) = found.statistics;
  }
  if constexpr(!parameters::is_default_parameter<NamedParameters, internal_np::vertex_instance_map_t>::value) {
    auto instance_map = get_parameter(np, internal_np::vertex_instance_map);
    typedef typename boost::property_traits<decltype(instance_map)>::value_type Label;
    for(auto v : vertices(tm))
      put(instance_map, v, Label(no_source));
    for(std::size_t i = 0; i < found.instances.size(); ++i)
      for(std::size_t v : found.instances[i].vertices)
        put(instance_map, vertex_of_index[v], Label(i));
  }
  return result;
}

} // namespace CGAL_ext

#endif // CGAL_EXT_DETECT_REPETITIVE_PATTERNS_H
