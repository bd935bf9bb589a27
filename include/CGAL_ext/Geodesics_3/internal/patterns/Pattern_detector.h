// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_DETECTOR_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_DETECTOR_H

// Repetitive pattern detection (thesis chapter 5): the pipeline from a marked patch to its
// instances and their arrangement, on vertex indices. Every geodesic comes from the package's
// applications: the patch and the search neighbourhoods from local distance rows, the samples
// from exact farthest-point sampling, the signatures and the sample-to-sample distances from one
// local distance row per sample, the arrangement from the geodesic Voronoi diagram.
//
// Steps, each in its own header: curvatures (Pattern_curvature.h), signatures
// (Pattern_signatures.h), clustering of matches (Pattern_clustering.h), energy refinement
// (Pattern_refinement.h); this file does the sampling, the matching, the region growing
// (Algorithm 7), the centre of each instance and the arrangement.

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>
#include <CGAL_ext/Geodesics_3/internal/distance_rows/Distance_rows.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_curvature.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_refinement.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_signatures.h>
#include <CGAL_ext/farthest_point_sampling.h>
#include <CGAL_ext/geodesic_distances.h>
#include <CGAL_ext/geodesic_voronoi_diagram.h>

#include <boost/iterator/function_output_iterator.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numeric>
#include <optional>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// The constants of the pipeline. Lengths are relative to the patch's size (the radius of a disk
/// of its area: its radius when it is a geodesic disk), the search radius to the patch radius
/// (the largest geodesic distance from its centre to its vertices).
struct Pattern_settings
{
  double sample_spacing = 1.0 / 3;   ///< covering radius of the sampling
  double signature_radius = 1.0;     ///< radius of the disk of a signature
  int signature_rings = 6;           ///< N: rings of a signature
  double match_tolerance = 0.35;     ///< epsilon of Eq. 5.5, relative to the patch's mean signature norm
  std::size_t matches_per_sample = 24; ///< candidate matches kept per patch sample, best first
  double consistency_cutoff = 0.7;   ///< c0 of Eq. 5.1
  double alpha = 1, beta = 1, gamma = 1; ///< weights of Eq. 5.4
  double search_radius = 3.0;        ///< how far from an instance's centre its neighbours are sought
  double scale_min = 1, scale_max = 1; ///< instance size over patch size
  /// a vertex path from the marked patch across instances whose size changes along it (by
  /// vertex index; empty: none): the scale is 1 where it starts and the end of the range
  /// farthest from 1 where it ends, and each sample is matched only at scales within 20 % of
  /// the scale of its nearest stroke vertex (thesis 5.3.3)
  std::vector<std::size_t> stroke;
  int threads = 0;
  /// lambda of AVTP for the local rows; 0: exact
  double approximation = 0;
  /// called with the fraction of the run done, never decreasing, 1 at the end; `false` stops
  /// the run (empty: none)
  std::function<bool(double)> progress;
};

/// The marked patch, by vertex index: its vertices and the centre, or a centre and a radius.
struct Pattern_patch_indices
{
  bool is_disk = false;
  std::size_t center = std::size_t(-1); ///< with `radius`, for a disk
  double radius = 0;
  std::vector<std::size_t> vertices;    ///< a vertex list (when not a disk)
};

struct Detected_instance
{
  std::size_t center = 0; ///< vertex index
  double scale = 1;
  double energy = 0;
  std::vector<std::size_t> vertices; ///< vertex indices, increasing
  /// (patch sample vertex, its image vertex), for the patch samples that have an image
  std::vector<std::pair<std::size_t, std::size_t>> correspondence;
};

struct Detection_result
{
  std::vector<Detected_instance> instances; ///< the marked patch first
  std::vector<std::pair<std::size_t, std::size_t>> arrangement_edges;
  std::vector<std::array<std::size_t, 3>> arrangement_triangles;
  Pattern_statistics statistics;
};

template <bool parallel, class TriangleMesh, class VertexPointMap, class VertexIndexMap>
class Pattern_detector
{
  typedef boost::graph_traits<TriangleMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  typedef std::vector<std::pair<std::size_t, double>> Row;
  typedef std::chrono::steady_clock Clock;
  static constexpr std::size_t none = std::size_t(-1);
  // the straight-line separation of the sampling's seeds, in sample spacings
  static constexpr double seed_separation = 2;

public:
  Pattern_detector(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim, const Pattern_settings& settings)
    : m_tm(tm), m_vpm(vpm), m_vim(vim), m_settings(settings)
  {
    m_vertex.resize(num_vertices(tm));
    for(vertex_descriptor v : vertices(tm))
      m_vertex[std::size_t(get(vim, v))] = v;
    check_settings();
  }

  Detection_result run(const Pattern_patch_indices& patch)
  {
    Detection_result result;
    m_times = &result.statistics;
    auto start = Clock::now();
    set_patch(patch);
    report(Step::sampling, 0);
    sample();
    m_times->seconds_sampling = seconds_since(start);
    start = Clock::now();
    compute_signatures();
    m_times->seconds_signatures = seconds_since(start);
    grow_regions();
    report(Step::centres, 0);
    start = Clock::now();
    place_centres();
    merge_overlapping_instances();
    m_row_solvers.reset(); // the last row: their solver mesh and solvers go before the arrangement's
    m_times->seconds_optimization += seconds_since(start);
    report(Step::arrangement, 0);
    start = Clock::now();
    result.instances = collect_instances();
    arrange(result);
    m_times->seconds_arrangement = seconds_since(start);
    report(Step::arrangement, 1);
    return result;
  }

private:
  struct Instance
  {
    Pattern_correspondence correspondence;
    std::size_t scale_step = 0;
    std::size_t center_sample = 0;
    std::size_t center_vertex = 0;
    double center_cost = 0; // what place_centres minimised at the centre
  };

  enum class Step { sampling, signatures, growing, centres, arrangement };

  // Tells the caller's callback how far the run is: `within` of `step` done.
  void report(Step step, double within)
  {
    // where each step starts and ends, as a fraction of a run (the shares of a golf ball's)
    static constexpr double bounds[] = {0.0, 0.35, 0.65, 0.8, 0.87, 1.0};
    if(!m_settings.progress)
      return;
    const double a = bounds[int(step)], b = bounds[int(step) + 1];
    m_reported = std::max(m_reported, a + (b - a) * std::clamp(within, 0.0, 1.0));
    if(!m_settings.progress(m_reported))
      throw Geodesic_error("pattern detection: interrupted by the callback");
  }

  static double seconds_since(Clock::time_point start)
  {
    return std::chrono::duration<double>(Clock::now() - start).count();
  }

  typedef std::conditional_t<parallel, CGAL::Parallel_tag, CGAL::Sequential_tag> Concurrency;

  // The named parameters of every geodesic call of the pipeline.
  auto solver_parameters() const
  {
    return CGAL_ext::parameters::vertex_point_map(m_vpm).vertex_index_map(m_vim).number_of_threads(
      m_settings.threads);
  }

  void check_settings() const
  {
    const Pattern_settings& s = m_settings;
    const auto positive = [](double x, const char* what) {
      if(!(x > 0) || !std::isfinite(x))
        throw Geodesic_error(std::string("pattern detection: ") + what + " must be positive and finite, got " +
                             std::to_string(x));
    };
    positive(s.sample_spacing, "sample_spacing");
    positive(s.signature_radius, "signature_radius");
    positive(s.match_tolerance, "match_tolerance");
    positive(s.search_radius, "search_radius");
    positive(s.scale_min, "the smallest scale");
    positive(s.scale_max, "the largest scale");
    if(s.scale_min > s.scale_max)
      throw Geodesic_error("pattern detection: empty scale range " + std::to_string(s.scale_min) + ":" +
                           std::to_string(s.scale_max));
    if(s.signature_rings < 1)
      throw Geodesic_error("pattern detection: signature_rings must be at least 1");
    if(s.matches_per_sample < 1)
      throw Geodesic_error("pattern detection: matches_per_sample must be at least 1");
    if(!(s.consistency_cutoff >= 0 && s.consistency_cutoff < 1))
      throw Geodesic_error("pattern detection: consistency_cutoff must be in [0, 1), got " +
                           std::to_string(s.consistency_cutoff));
    if(!(s.alpha >= 0 && s.beta >= 0 && s.gamma >= 0))
      throw Geodesic_error("pattern detection: the energy weights must not be negative");
    if(s.threads < 0)
      throw Geodesic_error("pattern detection: number_of_threads must not be negative");
    // its own message: here 0 is allowed (exact rows), unlike the solvers' lambda
    if(!(s.approximation >= 0) || !std::isfinite(s.approximation))
      throw Geodesic_error("pattern detection: approximation must be 0 (exact) or positive and finite, got " +
                           std::to_string(s.approximation));
  }

  // Local distance rows from `sources` (vertex indices), within `radius` and, when `stop` (vertex
  // indices) is not empty, until each of its vertices is settled: `hand_over(i, row)` in order.
  template <class HandOver>
  void for_each_local_row(const std::vector<std::size_t>& sources, double radius, const HandOver& hand_over,
                          const std::vector<std::size_t>& stop = {})
  {
    for_each_local_row_stopping(sources, radius, same_stops_for_every_row(stop), hand_over);
  }

  // The same, the stop vertices of row i (and its stop floor) set by `add_stops(i, solver)`.
  template <class AddStops, class HandOver>
  void for_each_local_row_stopping(const std::vector<std::size_t>& sources, double radius, const AddStops& add_stops,
                                   const HandOver& hand_over)
  {
    if(!m_row_solvers) {
      if(m_settings.approximation > 0)
        m_row_solvers.emplace(m_tm, solver_parameters().approximation(m_settings.approximation));
      else
        m_row_solvers.emplace(m_tm, solver_parameters());
    }
    std::vector<Source_point> points;
    for(std::size_t v : sources)
      points.push_back(m_row_solvers->mesh().source_point(m_vertex[v]));
    m_row_solvers->template for_each_row_stopping<Row>(
      points, radius, add_stops,
      [](const VTP_solver& solver, const auto& mesh, Row& row) { make_sparse_row(solver, mesh, row); }, hand_over);
    m_times->distance_rows += sources.size();
  }

  // One local distance row from `source`, within `radius`.
  Row local_row(std::size_t source, double radius)
  {
    Row row;
    for_each_local_row({source}, radius, [&](std::size_t, const Row& entries) { row = entries; });
    return row;
  }

  // The distances from `source` to the patch's vertices (the row stops once they are settled).
  Row patch_row(std::size_t source)
  {
    Row row;
    for_each_local_row(
      {source}, std::numeric_limits<double>::infinity(),
      [&](std::size_t, const Row& entries) {
        for(const auto& entry : entries)
          if(m_in_patch[entry.first])
            row.push_back(entry);
      },
      m_patch_vertices);
    return row;
  }

  // The patch's vertices, centre and radius.
  void set_patch(const Pattern_patch_indices& patch)
  {
    const std::size_t n = m_vertex.size();
    m_area = vertex_areas(m_tm, m_vpm, m_vim);
    m_in_patch.assign(n, false);
    double total = 0, longest = 0;
    std::size_t count = 0;
    for(auto e : edges(m_tm)) {
      const double length = std::sqrt(double(CGAL::squared_distance(get(m_vpm, source(halfedge(e, m_tm), m_tm)),
                                                                     get(m_vpm, target(halfedge(e, m_tm), m_tm)))));
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
      const Row row = local_row(m_center, patch.radius * (1 + 1e-12));
      double farthest = 0;
      for(const auto& [v, d] : row)
        if(d <= patch.radius) {
          m_in_patch[v] = true;
          farthest = std::max(farthest, d);
        }
      // the disk covers its whole component when a row longer by the longest edge reaches no
      // more vertices (a component that reaches beyond the radius has a vertex within an edge
      // beyond it)
      const Row beyond = local_row(m_center, patch.radius + 1.01 * longest);
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
    m_times->patch_radius = m_radius;
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

  void set_patch_vertices()
  {
    m_patch_vertices.clear();
    for(std::size_t v = 0; v < m_vertex.size(); ++v)
      if(m_in_patch[v])
        m_patch_vertices.push_back(v);
  }

  // A vertex list: connected, with a border; its centre is the vertex farthest from its border
  // (on its medial axis: the landmark of an elongated patch), its radius the farthest vertex
  // from that centre.
  void set_patch_of_vertices(const std::vector<std::size_t>& list)
  {
    std::vector<std::size_t> stack{list.front()};
    std::vector<bool> seen(m_vertex.size(), false);
    seen[list.front()] = true;
    std::size_t reached = 0;
    std::vector<vertex_descriptor> border;
    while(!stack.empty()) {
      const std::size_t v = stack.back();
      stack.pop_back();
      ++reached;
      bool on_border = CGAL::is_border(m_vertex[v], m_tm) != boost::none;
      for(vertex_descriptor w : CGAL::vertices_around_target(m_vertex[v], m_tm)) {
        const std::size_t wi = std::size_t(get(m_vim, w));
        if(!m_in_patch[wi])
          on_border = true;
        else if(!seen[wi]) {
          seen[wi] = true;
          stack.push_back(wi);
        }
      }
      if(on_border)
        border.push_back(m_vertex[v]);
    }
    const std::size_t distinct = m_patch_vertices.size();
    if(reached != distinct)
      throw Geodesic_error("pattern detection: the patch vertices are not connected (" + std::to_string(reached) +
                           " of " + std::to_string(distinct) + " reached from vertex " +
                           std::to_string(list.front()) + " through patch edges)");
    if(border.size() == distinct && distinct < 3)
      throw Geodesic_error("pattern detection: the patch has fewer than 3 vertices");
    std::vector<double> from_border(m_vertex.size(), 0.0);
    std::vector<vertex_descriptor> patch_vertices;
    for(std::size_t v : m_patch_vertices)
      patch_vertices.push_back(m_vertex[v]);
    geodesic_distances<Concurrency>(m_tm, CGAL::make_property_map(from_border), border,
                                    solver_parameters().stop_vertices(patch_vertices));
    std::size_t deepest = list.front();
    for(std::size_t v = 0; v < m_vertex.size(); ++v)
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
    std::vector<double> from_ends(m_vertex.size(), 0.0);
    for(const Row* row : {&row_a, &row_b})
      for(const auto& [v, d] : *row)
        from_ends[v] = std::max(from_ends[v], d);
    m_center = deepest;
    for(std::size_t v = 0; v < m_vertex.size(); ++v)
      if(m_in_patch[v] && from_border[v] >= 0.8 * from_border[deepest] && from_ends[v] < from_ends[m_center])
        m_center = v;
    m_center = patch_centroid(m_center);
    m_radius = 0;
    for(const auto& [v, d] : patch_row(m_center))
      m_radius = std::max(m_radius, d);
    if(!(m_radius > 0))
      throw Geodesic_error("pattern detection: the patch has no extent (all its vertices are at one point)");
  }

  // A descent over vertices for several walkers at once (the patch's centroid, the instances'
  // centres). Walker w starts at start[w]; every step evaluates the vertices tried, one local
  // row each (within `radius`, and until the stop vertices that `add_stops(w, stops)` gives
  // walker w's rows are settled), in one batch:
  // first the starts, then the unvisited neighbours of each moving walker's best vertex that
  // `may_visit(w, vertex)` lets in. `cost(w, vertex, row)` is a vertex's cost; a walker stops
  // when none of its vertices tried costs less than its best, and all stop after `max_steps`.
  // Returns each walker's best vertex and its cost.
  template <class AddStops, class Cost, class MayVisit>
  std::vector<std::pair<std::size_t, double>> descend(const std::vector<std::size_t>& start, double radius,
                                                      const AddStops& add_stops, const Cost& cost,
                                                      const MayVisit& may_visit, int max_steps)
  {
    const std::size_t n = start.size();
    std::vector<std::pair<std::size_t, double>> best(n);
    std::vector<std::vector<std::size_t>> visited(n);
    std::vector<std::pair<std::size_t, std::size_t>> tried; // (walker, vertex)
    for(std::size_t w = 0; w < n; ++w) {
      best[w] = {start[w], std::numeric_limits<double>::infinity()};
      visited[w].push_back(start[w]);
      tried.emplace_back(w, start[w]);
    }
    for(int step = 0; step < max_steps && !tried.empty(); ++step) {
      std::vector<std::size_t> sources;
      for(const auto& t : tried)
        sources.push_back(t.second);
      std::vector<bool> moved(n, false);
      for_each_local_row_stopping(
        sources, radius, [&](std::size_t r, Row_stops& stops) { add_stops(tried[r].first, stops); },
        [&](std::size_t r, const Row& entries) {
          const auto [w, v] = tried[r];
          const double c = cost(w, v, entries);
          if(c < best[w].second) {
            best[w] = {v, c};
            moved[w] = true;
          }
        });
      tried.clear();
      for(std::size_t w = 0; w < n; ++w) {
        if(!moved[w])
          continue;
        for(vertex_descriptor u : CGAL::vertices_around_target(m_vertex[best[w].first], m_tm)) {
          const std::size_t ui = std::size_t(get(m_vim, u));
          if(std::find(visited[w].begin(), visited[w].end(), ui) == visited[w].end()) {
            visited[w].push_back(ui);
            if(may_visit(w, ui))
              tried.emplace_back(w, ui);
          }
        }
      }
    }
    return best;
  }

  // The patch's geodesic centroid among its vertices: the one whose area-weighted mean squared
  // distance to the patch's vertices is least (the centre of a symmetric patch whatever its
  // shape, and it weighs every vertex, so that a border's jagged edge moves it little), by
  // descent from `start`, with rows that stop once the patch's vertices are settled.
  std::size_t patch_centroid(std::size_t start)
  {
    return descend(
             {start}, std::numeric_limits<double>::infinity(), same_stops_for_every_row(m_patch_vertices),
             [&](std::size_t, std::size_t, const Row& entries) {
               double c = 0;
               for(const auto& [v, d] : entries)
                 if(m_in_patch[v])
                   c += m_area[v] * d * d;
               return c;
             },
             [&](std::size_t, std::size_t v) { return bool(m_in_patch[v]); }, std::numeric_limits<int>::max())
      .front()
      .first;
  }

  // The scale the stroke gives each sample: its nearest stroke vertex's, the scale going
  // geometrically from 1 at the stroke's start to the end of the range farthest from 1 at its
  // end, by arc length.
  void set_stroke_scales()
  {
    m_stroke_scale.clear();
    const std::vector<std::size_t>& stroke = m_settings.stroke;
    if(stroke.empty())
      return;
    if(stroke.size() < 2)
      throw Geodesic_error("pattern detection: a stroke needs at least 2 vertices");
    for(std::size_t v : stroke)
      if(v >= m_vertex.size())
        throw Geodesic_error("pattern detection: stroke vertex " + std::to_string(v) + " is out of range (the mesh has " +
                             std::to_string(m_vertex.size()) + " vertices)");
    if(!m_in_patch[stroke.front()])
      throw Geodesic_error("pattern detection: the stroke must start in the marked instance (vertex " +
                           std::to_string(stroke.front()) + " is not in it)");
    std::vector<double> along{0.0};
    for(std::size_t k = 1; k < stroke.size(); ++k)
      along.push_back(along.back() + std::sqrt(double(CGAL::squared_distance(get(m_vpm, m_vertex[stroke[k - 1]]),
                                                                             get(m_vpm, m_vertex[stroke[k]])))));
    if(!(along.back() > 0))
      throw Geodesic_error("pattern detection: the stroke has no length");
    const double end = std::abs(std::log(m_settings.scale_max)) >= std::abs(std::log(m_settings.scale_min))
                         ? m_settings.scale_max
                         : m_settings.scale_min;
    std::vector<vertex_descriptor> sources;
    for(std::size_t v : stroke)
      sources.push_back(m_vertex[v]);
    std::vector<double> distance(m_vertex.size(), 0.0);
    std::vector<std::size_t> nearest(m_vertex.size(), none);
    geodesic_distances<Concurrency>(m_tm, CGAL::make_property_map(distance), sources,
                                    solver_parameters().vertex_source_map(CGAL::make_property_map(nearest)));
    m_stroke_scale.assign(m_sample_vertex.size(), 1.0);
    for(std::size_t q = 0; q < m_sample_vertex.size(); ++q) {
      const std::size_t k = nearest[m_sample_vertex[q]];
      if(k < stroke.size())
        m_stroke_scale[q] = std::pow(end, along[k] / along.back());
    }
  }

  // Vertices at least `separation` apart in straight line, the patch's centre first, each next
  // one the farthest in straight line from those before: a geodesic distance is never shorter,
  // so they are as far apart on the surface.
  std::vector<vertex_descriptor> straight_line_seeds(double separation) const
  {
    const std::size_t n = m_vertex.size();
    std::vector<std::array<double, 3>> point(n);
    for(std::size_t v = 0; v < n; ++v) {
      const auto p = get(m_vpm, m_vertex[v]);
      point[v] = {double(p.x()), double(p.y()), double(p.z())};
    }
    std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
    std::vector<vertex_descriptor> seeds;
    for(std::size_t seed = m_center;;) {
      seeds.push_back(m_vertex[seed]);
      const std::array<double, 3> c = point[seed];
      double farthest = 0;
      for(std::size_t v = 0; v < n; ++v) {
        const double dx = point[v][0] - c[0], dy = point[v][1] - c[1], dz = point[v][2] - c[2];
        nearest[v] = std::min(nearest[v], dx * dx + dy * dy + dz * dz);
        if(nearest[v] > farthest) {
          farthest = nearest[v];
          seed = v;
        }
      }
      if(!(farthest >= separation * separation))
        return seeds;
    }
  }

  // Exact farthest-point samples covering the mesh within the spacing, the patch's centre first.
  // The sampling starts from straight-line seeds a few spacings apart: from them all at once,
  // one propagation covers the mesh a short way from each, where the first farthest points'
  // propagations would each sweep much of the mesh. The samples are as far apart and cover as
  // closely as farthest points from the centre alone (each sample after the seeds is the
  // farthest), but are not the same ones.
  void sample()
  {
    m_spacing = m_settings.sample_spacing * m_size;
    std::vector<vertex_descriptor> samples;
    // the count expected of a covering at this spacing, for the progress only (samples are at
    // least a spacing apart, about one per (sqrt(3)/2) spacing^2)
    const double expected = std::accumulate(m_area.begin(), m_area.end(), 0.0) / (0.87 * m_spacing * m_spacing);
    m_cell.assign(m_vertex.size(), 0);
    farthest_point_sampling<Concurrency>(
      m_tm, m_vertex.size(), boost::make_function_output_iterator([&](vertex_descriptor v) {
        samples.push_back(v);
        report(Step::sampling, double(samples.size()) / expected);
      }),
      solver_parameters()
        .initial_samples(straight_line_seeds(seed_separation * m_spacing))
        .covering_radius(m_spacing)
        .vertex_source_map(CGAL::make_property_map(m_cell)));
    m_sample_vertex.clear();
    m_sample_of_vertex.assign(m_vertex.size(), none);
    for(vertex_descriptor v : samples) {
      m_sample_of_vertex[std::size_t(get(m_vim, v))] = m_sample_vertex.size();
      m_sample_vertex.push_back(std::size_t(get(m_vim, v)));
    }
    m_patch_sample.clear();
    for(std::size_t s = 0; s < m_sample_vertex.size(); ++s)
      if(m_in_patch[m_sample_vertex[s]])
        m_patch_sample.push_back(s);
    if(m_patch_sample.size() < 3)
      throw Geodesic_error("pattern detection: the patch holds " + std::to_string(m_patch_sample.size()) +
                           " samples, too few to match (mark a larger patch or lower sample_spacing)");
    m_landmark = std::size_t(std::find(m_patch_sample.begin(), m_patch_sample.end(), std::size_t(0)) -
                             m_patch_sample.begin());
    set_stroke_scales();
    m_times->samples = m_sample_vertex.size();
    m_times->patch_samples = m_patch_sample.size();
  }

  // The scales searched: a geometric progression over the range, about 10 % apart.
  void set_scales()
  {
    m_scales.clear();
    const double a = m_settings.scale_min, b = m_settings.scale_max;
    const int steps = a == b ? 1 : 1 + int(std::ceil(std::log(b / a) / std::log(1.1)));
    for(int i = 0; i < steps; ++i)
      m_scales.push_back(steps == 1 ? a : a * std::pow(b / a, double(i) / (steps - 1)));
  }

  // Curvatures, then one local row per sample: its signature's ring sums and its distances to
  // the samples near it.
  void compute_signatures()
  {
    set_scales();
    compute_patch_distances();
    m_curvature = vertex_principal_curvatures(m_tm, m_vpm, m_vim, parallel && m_settings.threads != 1);
    const std::vector<Principal_curvatures>& curvature = m_curvature;
    const std::vector<double>& area = m_area;
    const double signature_radius = m_settings.signature_radius * m_size;
    const double largest = signature_radius * std::max(1.0, m_scales.back());
    const double smallest = signature_radius * std::min(1.0, m_scales.front());
    const double band = smallest / (4.0 * m_settings.signature_rings);
    m_band_width = band;
    const std::size_t bands = std::size_t(std::ceil(largest / band)) + 1;
    // pairs of samples within the signature's disk: the consistency terms count the pairs of
    // patch samples whose images would lie that near (`linked`)
    m_pair_radius = largest;
    const double row_radius = std::max(m_pair_radius, largest);
    const std::size_t n = m_sample_vertex.size();
    m_rings.assign(n, Ring_sums(bands, band));
    m_near.assign(n, Row());
    for_each_local_row(
      m_sample_vertex, row_radius,
      [&](std::size_t s, const Row& entries) {
        for(const auto& [v, d] : entries) {
          if(d < largest)
            m_rings[s].add(d, area[v], curvature[v]);
          const std::size_t t = m_sample_of_vertex[v];
          if(t != none && t != s && d <= m_pair_radius)
            m_near[s].emplace_back(t, d);
        }
        std::sort(m_near[s].begin(), m_near[s].end());
        report(Step::signatures, double(s + 1) / double(n));
      });

    const int rings = m_settings.signature_rings;
    m_signature.assign(m_scales.size(), std::vector<std::vector<double>>(n));
    for(std::size_t k = 0; k < m_scales.size(); ++k)
      for(std::size_t s = 0; s < n; ++s)
        m_signature[k][s] = m_rings[s].signature(signature_radius * m_scales[k], rings);
    m_patch_signature.clear();
    double norm = 0;
    for(std::size_t s : m_patch_sample) {
      m_patch_signature.push_back(m_rings[s].signature(signature_radius, rings));
      norm += signature_distance(m_patch_signature.back(), std::vector<double>(m_patch_signature.back().size(), 0.0));
    }
    m_signature_norm = norm / double(m_patch_sample.size());
    if(!(m_signature_norm > 0))
      throw Geodesic_error("pattern detection: the patch is flat (no curvature to match)");
  }

  double sample_distance(std::size_t a, std::size_t b) const
  {
    if(a == b)
      return 0;
    const Row& row = m_near[a];
    const auto it = std::lower_bound(row.begin(), row.end(), std::make_pair(b, -std::numeric_limits<double>::infinity()));
    return it != row.end() && it->first == b ? it->second : std::numeric_limits<double>::infinity();
  }

  double patch_distance(std::size_t i, std::size_t j) const { return m_patch_distance[i * m_patch_sample.size() + j]; }

  // Pairs of patch samples whose images, if consistent at any scale of the range, lie within
  // the sample rows' radius: the pairs the consistency terms count.
  bool linked(std::size_t i, std::size_t j) const
  {
    return i != j && patch_distance(i, j) * m_scales.back() <= m_settings.consistency_cutoff * m_pair_radius;
  }

  // The exact distances among the patch samples (one row each, within the patch's diameter).
  void compute_patch_distances()
  {
    const std::size_t k = m_patch_sample.size();
    m_patch_distance.assign(k * k, std::numeric_limits<double>::infinity());
    std::vector<std::size_t> index(m_sample_vertex.size(), none);
    std::vector<std::size_t> sources;
    for(std::size_t i = 0; i < k; ++i) {
      index[m_patch_sample[i]] = i;
      sources.push_back(m_sample_vertex[m_patch_sample[i]]);
    }
    for_each_local_row(sources, 2.01 * m_radius, [&](std::size_t i, const Row& entries) {
      for(const auto& [v, d] : entries)
        if(m_sample_of_vertex[v] != none && index[m_sample_of_vertex[v]] != none)
          m_patch_distance[i * k + index[m_sample_of_vertex[v]]] = d;
    });
  }

  double signature_cost(std::size_t i, std::size_t scale_step, std::size_t q) const
  {
    return signature_distance(m_patch_signature[i], m_signature[scale_step][q]) / m_signature_norm;
  }

  // The samples within `radius` of sample `from`, by shortest paths in the graph of near samples
  // (an upper bound of the geodesic distance: the neighbourhood is never larger than asked).
  std::vector<std::size_t> neighbourhood(std::size_t from, double radius) const
  {
    std::vector<double> distance(m_sample_vertex.size(), std::numeric_limits<double>::infinity());
    typedef std::pair<double, std::size_t> Entry;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    distance[from] = 0;
    queue.emplace(0.0, from);
    std::vector<std::size_t> found;
    while(!queue.empty()) {
      const auto [d, s] = queue.top();
      queue.pop();
      if(d > distance[s])
        continue;
      found.push_back(s);
      for(const auto& [t, e] : m_near[s])
        if(d + e <= radius && d + e < distance[t]) {
          distance[t] = d + e;
          queue.emplace(d + e, t);
        }
    }
    std::sort(found.begin(), found.end());
    return found;
  }

  // Algorithm 7: from the marked patch, each new instance searches its own neighbourhood for
  // more, until no new one appears.
  void grow_regions()
  {
    const std::size_t k = m_patch_sample.size();
    m_used.assign(m_sample_vertex.size(), false);
    Instance marked;
    marked.correspondence.image = m_patch_sample;
    marked.center_sample = 0;
    marked.center_vertex = m_center;
    marked.correspondence.mapped = k;
    marked.correspondence.energy = 0;
    marked.correspondence.mean_consistency = 1;
    marked.scale_step = none;
    m_instances.assign(1, marked);
    for(std::size_t s : m_patch_sample)
      m_used[s] = true;
    std::queue<std::size_t> to_search;
    to_search.push(0);
    const auto search = [&](std::size_t center_sample, double scale) {
      ++m_times->searches;
      for(Instance& found : search_around(center_sample, scale)) {
        m_instances.push_back(found);
        for(std::size_t q : found.correspondence.image)
          if(q != Pattern_correspondence::unmapped)
            m_used[q] = true;
        to_search.push(m_instances.size() - 1);
      }
      // a guess: each instance found is searched around once
      report(Step::growing, double(m_times->searches) / double(m_instances.size() + 1));
    };
    std::vector<std::size_t> seeds;
    std::size_t next_seed = 0;
    std::vector<bool> near_fruitless_seed(m_sample_vertex.size(), false);
    for(;;) {
      while(!to_search.empty()) {
        const Instance& from = m_instances[to_search.front()];
        to_search.pop();
        search(from.center_sample, from.scale_step == none ? 1.0 : m_scales[from.scale_step]);
      }
      // Region growing reaches the instances near others; an instance farther than the search
      // radius from all found ones is reached from a seed: a free sample that looks like the
      // patch's centre, away from every instance found so far.
      if(next_seed == 0)
        seeds = landmark_lookalikes();
      while(next_seed < seeds.size() && (near_fruitless_seed[seeds[next_seed]] || !is_free_seed(seeds[next_seed])))
        ++next_seed;
      if(next_seed == seeds.size())
        break;
      const std::size_t seed = seeds[next_seed++];
      const std::size_t found_before = m_instances.size();
      search(seed, 1.0);
      // A search from a seed looks at the samples within (search radius x s + 1) R of it, s the
      // largest scale (at least 1): an instance of radius at most s R centred within (search
      // radius x s + 1 - s) R of a seed that found nothing lies in that seed's neighbourhood,
      // so the look-alikes within (search radius x s - s) R, a patch radius to spare (the
      // neighbourhood's paths through samples are longer than geodesics), and at most 2 R (as
      // the defaults give), are not searched again (on a curved background, such as a
      // cylinder's, most of the surface looks like the centre).
      if(m_instances.size() == found_before) {
        const double s = std::max(1.0, m_scales.back());
        const double ruled_out = std::clamp(m_settings.search_radius * s - s, 0.0, 2.0) * m_radius;
        for(std::size_t q : neighbourhood(seed, ruled_out))
          near_fruitless_seed[q] = true;
      }
    }
  }

  // Free samples whose signature is within three times the tolerance of the landmark's (its
  // nearest sample may be a spacing off an instance's centre), the most alike first.
  std::vector<std::size_t> landmark_lookalikes() const
  {
    std::vector<std::pair<double, std::size_t>> alike;
    for(std::size_t q = 0; q < m_sample_vertex.size(); ++q) {
      if(m_used[q])
        continue;
      double cost = std::numeric_limits<double>::infinity();
      for(std::size_t step = 0; step < m_scales.size(); ++step)
        cost = std::min(cost, signature_cost(m_landmark, step, q));
      if(cost <= 3 * m_settings.match_tolerance)
        alike.emplace_back(cost, q);
    }
    std::sort(alike.begin(), alike.end());
    std::vector<std::size_t> out;
    for(const auto& a : alike)
      out.push_back(a.second);
    return out;
  }

  bool is_free_seed(std::size_t q) const
  {
    if(m_used[q])
      return false;
    for(const Instance& instance : m_instances) {
      const double scale = instance.scale_step == none ? 1.0 : m_scales[instance.scale_step];
      if(sample_distance(q, instance.center_sample) <= scale * m_size * 1.5)
        return false;
    }
    return true;
  }

  std::vector<Instance> search_around(std::size_t center_sample, double scale)
  {
    auto start = Clock::now();
    const std::size_t k = m_patch_sample.size();
    const double reach = (m_settings.search_radius * std::max(scale, m_scales.back()) + 1.0) * m_radius;
    const std::vector<std::size_t> candidates = neighbourhood(center_sample, reach);
    std::vector<bool> in_neighbourhood(m_sample_vertex.size(), false);
    for(std::size_t q : candidates)
      in_neighbourhood[q] = true;

    // candidate matches: per patch sample, the samples (and their best scale) whose signature is
    // within the tolerance, the closest first
    std::vector<Pattern_match> matches;
    for(std::size_t i = 0; i < k; ++i) {
      std::vector<Pattern_match> mine;
      for(std::size_t q : candidates) {
        if(m_used[q])
          continue;
        Pattern_match best{i, q, 1.0, std::numeric_limits<double>::infinity()};
        for(std::size_t step = 0; step < m_scales.size(); ++step) {
          if(!m_stroke_scale.empty() && std::abs(std::log(m_scales[step] / m_stroke_scale[q])) > std::log(1.2))
            continue;
          const double cost = signature_cost(i, step, q);
          if(cost < best.signature_distance) {
            best.signature_distance = cost;
            best.scale = m_scales[step];
          }
        }
        if(best.signature_distance <= m_settings.match_tolerance)
          mine.push_back(best);
      }
      const std::size_t keep = std::min(mine.size(), m_settings.matches_per_sample);
      std::partial_sort(mine.begin(), mine.begin() + std::ptrdiff_t(keep), mine.end(),
                        [](const Pattern_match& a, const Pattern_match& b) {
                          return a.signature_distance < b.signature_distance ||
                                 (a.signature_distance == b.signature_distance && a.sample < b.sample);
                        });
      matches.insert(matches.end(), mine.begin(), mine.begin() + std::ptrdiff_t(keep));
    }
    m_times->matches += matches.size();
    m_times->seconds_matching += seconds_since(start);

    start = Clock::now();
    const std::vector<std::vector<std::size_t>> clusters = cluster_matches(
      matches,
      [&](std::size_t i, std::size_t j) {
        return linked(i, j) ? patch_distance(i, j) : std::numeric_limits<double>::infinity();
      },
      [&](std::size_t a, std::size_t b) { return sample_distance(a, b); }, m_settings.consistency_cutoff, m_spacing,
      k);
    m_times->clusters += clusters.size();
    m_times->seconds_clustering += seconds_since(start);

    start = Clock::now();
    std::vector<Instance> found;
    for(const std::vector<std::size_t>& cluster : clusters) {
      Instance instance;
      if(make_instance(matches, cluster, in_neighbourhood, found, instance))
        found.push_back(instance);
    }
    m_times->seconds_optimization += seconds_since(start);
    return found;
  }

  std::size_t nearest_scale_step(double scale) const
  {
    std::size_t best = 0;
    for(std::size_t s = 1; s < m_scales.size(); ++s)
      if(std::abs(std::log(m_scales[s] / scale)) < std::abs(std::log(m_scales[best] / scale)))
        best = s;
    return best;
  }

  // A cluster's correspondence, refined by Eq. 5.4; false when it is not a new instance.
  bool make_instance(const std::vector<Pattern_match>& matches, const std::vector<std::size_t>& cluster,
                     const std::vector<bool>& in_neighbourhood, const std::vector<Instance>& found_now,
                     Instance& instance) const
  {
    const std::size_t k = m_patch_sample.size();
    std::vector<double> scales;
    for(std::size_t m : cluster)
      scales.push_back(matches[m].scale);
    std::nth_element(scales.begin(), scales.begin() + std::ptrdiff_t(scales.size() / 2), scales.end());
    instance.scale_step = nearest_scale_step(scales[scales.size() / 2]);
    const double scale = m_scales[instance.scale_step];

    // start from the most consistent match of each patch sample in the cluster
    std::vector<double> support(cluster.size(), 0.0);
    for(std::size_t a = 0; a < cluster.size(); ++a)
      for(std::size_t b = 0; b < cluster.size(); ++b) {
        const Pattern_match& ma = matches[cluster[a]];
        const Pattern_match& mb = matches[cluster[b]];
        if(ma.patch_sample != mb.patch_sample && ma.sample != mb.sample && linked(ma.patch_sample, mb.patch_sample))
          support[a] += match_consistency(patch_distance(ma.patch_sample, mb.patch_sample),
                                          sample_distance(ma.sample, mb.sample), scale, scale, m_spacing);
      }
    std::vector<std::size_t> order(cluster.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return support[a] > support[b]; });
    Pattern_correspondence& c = instance.correspondence;
    c.image.assign(k, Pattern_correspondence::unmapped);
    std::vector<std::size_t> taken;
    for(std::size_t a : order) {
      const Pattern_match& m = matches[cluster[a]];
      if(c.image[m.patch_sample] == Pattern_correspondence::unmapped &&
         std::find(taken.begin(), taken.end(), m.sample) == taken.end()) {
        c.image[m.patch_sample] = m.sample;
        taken.push_back(m.sample);
      }
    }

    Pattern_energy_terms terms;
    terms.patch_samples = k;
    terms.landmark = m_landmark;
    terms.alpha = m_settings.alpha;
    terms.beta = m_settings.beta;
    terms.gamma = m_settings.gamma;
    terms.scale = scale;
    terms.slack = m_spacing;
    std::size_t step = instance.scale_step;
    terms.signature_cost = [this, &step](std::size_t i, std::size_t q) { return signature_cost(i, step, q); };
    terms.patch_distance = [this](std::size_t i, std::size_t j) { return patch_distance(i, j); };
    terms.linked = [this](std::size_t i, std::size_t j) { return linked(i, j); };
    terms.sample_distance = [this](std::size_t a, std::size_t b) { return sample_distance(a, b); };
    const Pattern_energy energy(terms);
    std::vector<bool> taken_now(m_sample_vertex.size(), false);
    for(const Instance& other : found_now)
      for(std::size_t q : other.correspondence.image)
        if(q != Pattern_correspondence::unmapped)
          taken_now[q] = true;
    const auto near = [this](std::size_t q) -> const Row& { return m_near[q]; };
    const auto usable = [&](std::size_t q) { return in_neighbourhood[q] && !m_used[q] && !taken_now[q]; };
    const double step_length = 2 * m_spacing * scale;
    refine_correspondence(c, energy, near, usable, step_length);
    // then the correspondences rebuilt around the samples near the landmark's image
    if(c.image[m_landmark] != Pattern_correspondence::unmapped) {
      const Pattern_correspondence first = c;
      for(const auto& [q, d] : m_near[first.image[m_landmark]]) {
        if(d > step_length || !usable(q))
          continue;
        Pattern_correspondence other = correspondence_around(q, energy, near, usable, step_length);
        refine_correspondence(other, energy, near, usable, step_length);
        if(other.energy < c.energy)
          c = other;
      }
    }
    // the scale of the correspondence: the median of its matches' is a start; the scales near it
    // are tried on the refined correspondence and the one of lowest energy kept
    if(m_scales.size() > 1) {
      const std::size_t first = step;
      double lowest = c.energy;
      for(std::size_t t = first > 3 ? first - 3 : 0; t < std::min(m_scales.size(), first + 4); ++t) {
        step = t;
        terms.scale = m_scales[t];
        Pattern_correspondence at = c;
        energy.evaluate(at);
        if(at.energy < lowest) {
          lowest = at.energy;
          instance.scale_step = t;
        }
      }
      step = instance.scale_step;
      terms.scale = m_scales[step];
      refine_correspondence(c, energy, near, usable, 2 * m_spacing * terms.scale);
    }

    // accept a correspondence that maps the landmark and at least two thirds of the samples, whose
    // mapped pairs keep their distances (on average to 0.85 of the cut-off: the pairs of a true
    // instance on an anisotropic triangulation fall a little short of it) and whose landmark looks
    // like the patch's centre (within twice the match tolerance: the landmark's image is a
    // sample, up to a spacing from where the centre maps)
    if(c.image[m_landmark] == Pattern_correspondence::unmapped || 3 * c.mapped < 2 * k)
      return false;
    constexpr double acceptance = 0.85;
    double consistent = 0;
    std::size_t pairs = 0;
    for(std::size_t i = 0; i < k; ++i)
      for(std::size_t j = i + 1; j < k; ++j)
        if(c.image[i] != Pattern_correspondence::unmapped && c.image[j] != Pattern_correspondence::unmapped &&
           linked(i, j)) {
          consistent += energy.consistency(i, c.image[i], j, c.image[j]);
          ++pairs;
        }
    if(pairs == 0 || consistent / double(pairs) < acceptance * m_settings.consistency_cutoff)
      return false;
    if(signature_cost(m_landmark, step, c.image[m_landmark]) > 2 * m_settings.match_tolerance)
      return false;
    instance.center_sample = c.image[m_landmark];
    instance.center_vertex = m_sample_vertex[instance.center_sample];
    // a new instance: its centre is farther than the mean of the two sizes from every other's
    // centre, and farther than 1.5 spacings from every other's images (an elongated instance's
    // centre may be farther than its size from a shifted copy of itself, not from its samples)
    const double scale_found = m_scales[instance.scale_step];
    const auto overlaps = [&](const Instance& other) {
      const double scale = scale_found;
      const double other_scale = other.scale_step == none ? 1.0 : m_scales[other.scale_step];
      if(sample_distance(instance.center_sample, other.center_sample) < 0.5 * (scale + other_scale) * m_size)
        return true;
      for(std::size_t q : other.correspondence.image)
        if(q != Pattern_correspondence::unmapped &&
           sample_distance(instance.center_sample, q) < 1.5 * m_spacing * std::min(scale, other_scale))
          return true;
      return false;
    };
    return std::none_of(m_instances.begin(), m_instances.end(), overlaps) &&
           std::none_of(found_now.begin(), found_now.end(), overlaps);
  }

  // Each instance's centre: from the landmark's image (a sample, up to a spacing away from
  // where the patch's centre maps), a descent over the vertices within two spacings of it to
  // the one whose own signature is most like the patch centre's and whose distances to the
  // images of the patch samples best agree with the patch centre's distances to them (the root
  // mean square of the differences over the images within a row, relative to the patch's
  // size), and whose disk's curvature moment (`curvature_moment`) is the patch centre's: the
  // signature alone hardly changes along the axis of an elongated instance, the distances alone
  // are off by up to a spacing each. One `descend` for all instances: a row gives the signature,
  // the moment and the distances.
  void place_centres()
  {
    // the signature term weighs more than the distances: the images the distances are measured
    // to are samples, each up to a spacing off (the weight's sweep: doc/experiments.md)
    constexpr double centre_signature_weight = 4;
    // the moment's weight (its sweep: doc/experiments.md); the moment is a small number (an
    // offset over the radius)
    constexpr double centre_moment_weight = 30;
    const std::size_t n = m_instances.size();
    const std::size_t k = m_patch_sample.size();
    if(n < 2)
      return;
    const int rings = m_settings.signature_rings;
    const double signature_radius = m_settings.signature_radius * m_size;
    const std::vector<double>& target = m_patch_signature[m_landmark];
    const std::size_t patch_centre = m_sample_vertex[m_patch_sample[m_landmark]];
    const double target_moment =
      curvature_moment(patch_centre, local_row(patch_centre, signature_radius), signature_radius);
    // the images as far as the patch's farthest samples, with a spacing to spare (for an
    // elongated patch, those along its axis, beyond the signature's disk, tell the most)
    const double reach = std::max(signature_radius, m_radius + m_spacing) * m_scales.back();

    std::vector<Row> allowed(n); // the vertices within two spacings of the landmark's image
    const auto is_allowed = [&](std::size_t a, std::size_t v) {
      return std::binary_search(allowed[a].begin(), allowed[a].end(),
                                std::make_pair(v, -std::numeric_limits<double>::infinity()),
                                [](const auto& x, const auto& y) { return x.first < y.first; });
    };
    const auto cost = [&](std::size_t a, std::size_t centre, const Row& entries) {
      const Instance& instance = m_instances[a];
      const double scale = m_scales[instance.scale_step];
      if(allowed[a].empty()) // the first row of the instance: its start's
        for(const auto& entry : entries)
          if(entry.second <= 2 * m_spacing * scale)
            allowed[a].push_back(entry);
      const double radius = signature_radius * scale;
      Ring_sums sums(m_rings.front().bands(), m_band_width);
      for(const auto& [v, d] : entries)
        if(d < radius)
          sums.add(d, m_area[v], m_curvature[v]);
      double squares = 0;
      std::size_t counted = 0;
      for(std::size_t i = 0; i < k; ++i) {
        const std::size_t q = instance.correspondence.image[i];
        if(q == Pattern_correspondence::unmapped)
          continue;
        const auto it = std::lower_bound(entries.begin(), entries.end(),
                                         std::make_pair(m_sample_vertex[q], -std::numeric_limits<double>::infinity()));
        if(it == entries.end() || it->first != m_sample_vertex[q])
          continue;
        const double want = patch_distance(m_landmark, i) * scale;
        squares += (it->second - want) * (it->second - want);
        ++counted;
      }
      return centre_signature_weight * signature_distance(target, sums.signature(radius, rings)) / m_signature_norm +
             (counted ? std::sqrt(squares / double(counted)) / (m_size * scale) : 0.0) +
             centre_moment_weight * std::abs(curvature_moment(centre, entries, radius) - target_moment);
    };
    // the walkers are the instances but the patch: walker w is instance w + 1
    std::vector<std::size_t> start;
    for(std::size_t a = 1; a < n; ++a)
      start.push_back(m_instances[a].center_vertex);
    const int max_steps = 2 + int(std::ceil(3 * m_spacing * m_scales.back() / std::max(m_mean_edge, 1e-300)));
    // A row needs the signature's disk, the vertices allowed, and the images within `reach`:
    // it stops once the images are settled (when they all lie within `reach`), its costs the
    // same as a row to `reach`.
    std::vector<std::vector<std::size_t>> image_vertices(n);
    for(std::size_t a = 1; a < n; ++a)
      for(std::size_t q : m_instances[a].correspondence.image)
        if(q != Pattern_correspondence::unmapped)
          image_vertices[a].push_back(m_sample_vertex[q]);
    const auto add_stops = [&](std::size_t w, Row_stops& stops) {
      const double scale = m_scales[m_instances[w + 1].scale_step];
      for(std::size_t v : image_vertices[w + 1])
        stops.add_stop_vertex(v);
      stops.set_stop_floor_in_mesh_unit(std::max(signature_radius, 2 * m_spacing) * scale);
    };
    const auto placed = descend(
      start, reach, add_stops,
      [&](std::size_t w, std::size_t v, const Row& entries) { return cost(w + 1, v, entries); },
      [&](std::size_t w, std::size_t v) { return is_allowed(w + 1, v); }, max_steps);
    for(std::size_t a = 1; a < n; ++a) {
      m_instances[a].center_vertex = placed[a - 1].first;
      m_instances[a].center_cost = placed[a - 1].second;
    }
  }

  // The curvature moment of the disk of `radius` around vertex `centre` (`entries`: a row from
  // it): the length of the mean offset of the disk's vertices from the centre, each weighted by
  // its area and its absolute curvatures, over the radius. Rings of distance around the centre
  // (the signature) hardly change as the centre slides along an elongated instance; the side
  // where the curvature lies does.
  double curvature_moment(std::size_t centre, const Row& entries, double radius) const
  {
    const auto c = get(m_vpm, m_vertex[centre]);
    double moment[3] = {0, 0, 0}, weight = 0;
    for(const auto& [u, d] : entries) {
      if(!(d < radius))
        continue;
      const double w = m_area[u] * (std::abs(m_curvature[u].k_max) + std::abs(m_curvature[u].k_min));
      const auto offset = get(m_vpm, m_vertex[u]) - c;
      moment[0] += w * CGAL::to_double(offset.x());
      moment[1] += w * CGAL::to_double(offset.y());
      moment[2] += w * CGAL::to_double(offset.z());
      weight += w;
    }
    return weight > 0 ? std::sqrt(moment[0] * moment[0] + moment[1] * moment[1] + moment[2] * moment[2]) / (weight * radius)
                      : 0.0;
  }

  // Instances are accepted apart (each centre farther than the mean of the two sizes from every
  // other's) with centres at samples; the centres' descent may bring two of them onto one
  // instance. Of two whose centres are now that close, the one whose centre is less like the
  // patch's (the cost the descent minimised) goes; never the patch.
  void merge_overlapping_instances()
  {
    const std::size_t n = m_instances.size();
    if(n < 2)
      return;
    const auto size = [&](std::size_t a) { return m_size * m_scales[m_instances[a].scale_step]; };
    double largest = 0;
    std::vector<std::size_t> sources;
    for(std::size_t a = 0; a < n; ++a) {
      largest = std::max(largest, size(a));
      sources.push_back(m_instances[a].center_vertex);
    }
    std::vector<std::size_t> instance_at(m_vertex.size(), none);
    for(std::size_t a = 0; a < n; ++a)
      instance_at[m_instances[a].center_vertex] = a;
    const auto cost = [&](std::size_t a) { return a == 0 ? -1.0 : m_instances[a].center_cost; };
    std::vector<bool> dropped(n, false);
    for_each_local_row(sources, largest, [&](std::size_t a, const Row& entries) {
      for(const auto& [v, d] : entries) {
        const std::size_t b = instance_at[v];
        if(b == none || b == a || d >= 0.5 * (size(a) + size(b)))
          continue;
        // rows come in order: a decision for a pair is taken once, at the first of the two
        if(b > a && !dropped[a] && !dropped[b])
          dropped[cost(a) <= cost(b) ? b : a] = true;
      }
    });
    std::size_t kept = 0;
    for(std::size_t a = 0; a < n; ++a)
      if(!dropped[a]) {
        if(kept != a)
          m_instances[kept] = std::move(m_instances[a]);
        ++kept;
      }
    m_instances.resize(kept);
  }

  std::vector<Detected_instance> collect_instances() const
  {
    std::vector<Detected_instance> out;
    for(std::size_t a = 0; a < m_instances.size(); ++a) {
      const Instance& instance = m_instances[a];
      Detected_instance d;
      d.center = instance.center_vertex;
      d.scale = instance.scale_step == none ? 1.0 : m_scales[instance.scale_step];
      d.energy = instance.correspondence.energy;
      for(std::size_t i = 0; i < m_patch_sample.size(); ++i)
        if(instance.correspondence.image[i] != Pattern_correspondence::unmapped)
          d.correspondence.emplace_back(m_sample_vertex[m_patch_sample[i]],
                                        m_sample_vertex[instance.correspondence.image[i]]);
      out.push_back(std::move(d));
    }
    out.front().vertices = m_patch_vertices;
    return out;
  }

  // The arrangement, and the members of each instance but the patch (whose are its own): the
  // vertices of its cell of the Voronoi diagram of the centres (so that no vertex is in two
  // instances) within its size of its centre, or whose nearest sample is one of its images (an
  // elongated instance reaches beyond its size along its axis).
  void arrange(Detection_result& result) const
  {
    if(result.instances.size() < 2)
      return;
    std::vector<vertex_descriptor> centres;
    for(const Detected_instance& d : result.instances)
      centres.push_back(m_vertex[d.center]);
    // each vertex's cell (the index of its nearest centre) and its distance to it, by vertex index
    std::vector<std::size_t> cell(m_vertex.size(), no_source);
    std::vector<double> distance(m_vertex.size(), std::numeric_limits<double>::infinity());
    const auto diagram = geodesic_voronoi_diagram<Concurrency>(
      m_tm, centres,
      solver_parameters()
        .algorithm(VTP)
        .vertex_source_map(boost::make_iterator_property_map(cell.begin(), m_vim))
        .vertex_distance_map(boost::make_iterator_property_map(distance.begin(), m_vim)));
    result.arrangement_edges = diagram.dual_edges;
    result.arrangement_triangles = diagram.dual_triangles;
    std::vector<std::size_t> owner(m_sample_vertex.size(), none);
    for(std::size_t a = 1; a < m_instances.size(); ++a)
      for(std::size_t q : m_instances[a].correspondence.image)
        if(q != Pattern_correspondence::unmapped)
          owner[q] = a;
    for(std::size_t v = 0; v < m_vertex.size(); ++v) {
      const std::size_t a = cell[v];
      if(a == 0 || a >= result.instances.size())
        continue;
      const bool near = distance[v] <= m_size * result.instances[a].scale;
      const bool sampled = m_cell[v] < owner.size() && owner[m_cell[v]] == a;
      if(near || sampled)
        result.instances[a].vertices.push_back(v);
    }
  }

  const TriangleMesh& m_tm;
  VertexPointMap m_vpm;
  VertexIndexMap m_vim;
  Pattern_settings m_settings;
  Pattern_statistics* m_times = nullptr;
  double m_reported = 0;
  std::vector<vertex_descriptor> m_vertex;

  // the solvers of every local row (made at the first row, released after the last)
  std::optional<Row_solvers<parallel, TriangleMesh, VertexPointMap>> m_row_solvers;
  std::vector<bool> m_in_patch;
  std::vector<std::size_t> m_patch_vertices; // increasing; rows that must reach them all stop there
  std::size_t m_center = 0;
  double m_radius = 0; // the largest distance from the centre to a patch vertex
  double m_size = 0;   // the radius of a disk of the patch's area
  double m_spacing = 0;
  double m_pair_radius = 0;
  std::vector<double> m_patch_distance; // between patch samples, k x k

  std::vector<std::size_t> m_sample_vertex;    // by sample
  std::vector<std::size_t> m_sample_of_vertex; // by vertex: its sample, or none
  std::vector<std::size_t> m_cell;             // by vertex: its nearest sample
  std::vector<std::size_t> m_patch_sample;     // the samples in the patch
  std::size_t m_landmark = 0;                  // the centre's index among them

  std::vector<double> m_scales;
  std::vector<double> m_stroke_scale; // by sample, with a stroke: the scale near it
  std::vector<Principal_curvatures> m_curvature; // by vertex
  std::vector<double> m_area;                    // by vertex
  double m_band_width = 1;                       // of the ring sums
  double m_mean_edge = 0;
  std::vector<Ring_sums> m_rings;                             // by sample
  std::vector<Row> m_near;                                    // by sample: the samples within m_pair_radius
  std::vector<std::vector<std::vector<double>>> m_signature;  // by scale step, then sample
  std::vector<std::vector<double>> m_patch_signature;         // by patch sample, at scale 1
  double m_signature_norm = 1;

  std::vector<bool> m_used; // samples that are images of an accepted instance (or of the patch)
  std::vector<Instance> m_instances;
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_DETECTOR_H
