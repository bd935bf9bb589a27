// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_SAMPLES_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_SAMPLES_H

// The sampled surface of a pattern detection (doc/design.md, "Repetitive pattern detection",
// steps 2 and 3): exact farthest-point samples and their cells, the scales searched (and the
// stroke's), the vertices' curvatures, each sample's ring sums, signatures and near samples,
// and the exact distances among the patch's samples; with the queries matching and refinement
// ask of them.

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_curvature.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_patch_geometry.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_rows.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_settings.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_signatures.h>
#include <CGAL_ext/farthest_point_sampling.h>
#include <CGAL_ext/geodesic_distances.h>

#include <boost/iterator/function_output_iterator.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numeric>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// The samples of the surface, by sample index (sample 0 is the patch's centre), and what is
/// known of them. The detector owns it: it samples once the patch is set, then computes the
/// signatures; matching, refinement and the centres read it.
template <bool parallel, class TriangleMesh, class VertexPointMap, class VertexIndexMap>
class Pattern_samples
{
  typedef Pattern_mesh<parallel, TriangleMesh, VertexPointMap, VertexIndexMap> Mesh;
  typedef Pattern_rows<parallel, TriangleMesh, VertexPointMap, VertexIndexMap> Rows;
  typedef Pattern_patch_geometry<parallel, TriangleMesh, VertexPointMap, VertexIndexMap> Patch;
  typedef typename Rows::Row Row;
  typedef typename Mesh::vertex_descriptor vertex_descriptor;
  static constexpr std::size_t none = std::size_t(-1);
  // the straight-line separation of the sampling's seeds, in sample spacings
  static constexpr double seed_separation = 2;

public:
  Pattern_samples(const Mesh& mesh, const Pattern_settings& settings, Rows& rows, const Patch& patch)
    : m_mesh(mesh)
    , m_settings(settings)
    , m_rows(rows)
    , m_patch(patch)
  {
  }

  // Exact farthest-point samples covering the mesh within the spacing, the patch's centre first.
  // The sampling starts from straight-line seeds a few spacings apart: from them all at once,
  // one propagation covers the mesh a short way from each, where the first farthest points'
  // propagations would each sweep much of the mesh. The samples are as far apart and cover as
  // closely as farthest points from the centre alone (each sample after the seeds is the
  // farthest), but are not the same ones.
  template <class Report>
  void sample(const Report& report)
  {
    m_spacing = m_settings.sample_spacing * m_patch.size();
    std::vector<vertex_descriptor> samples;
    // the count expected of a covering at this spacing, for the progress only (samples are at
    // least a spacing apart, about one per (sqrt(3)/2) spacing^2)
    const std::vector<double>& area = m_patch.area();
    const double expected = std::accumulate(area.begin(), area.end(), 0.0) / (0.87 * m_spacing * m_spacing);
    m_cell.assign(m_mesh.vertex.size(), 0);
    farthest_point_sampling<typename Mesh::Concurrency>(
      m_mesh.tm, m_mesh.vertex.size(), boost::make_function_output_iterator([&](vertex_descriptor v) {
        samples.push_back(v);
        report(double(samples.size()) / expected);
      }),
      m_mesh.solver_parameters()
        .initial_samples(straight_line_seeds(seed_separation * m_spacing))
        .covering_radius(m_spacing)
        .vertex_source_map(CGAL::make_property_map(m_cell)));
    m_sample_vertex.clear();
    m_sample_of_vertex.assign(m_mesh.vertex.size(), none);
    for(vertex_descriptor v : samples) {
      m_sample_of_vertex[m_mesh.index(v)] = m_sample_vertex.size();
      m_sample_vertex.push_back(m_mesh.index(v));
    }
    m_patch_sample.clear();
    for(std::size_t s = 0; s < m_sample_vertex.size(); ++s)
      if(m_patch.in_patch(m_sample_vertex[s]))
        m_patch_sample.push_back(s);
    if(m_patch_sample.size() < 3)
      throw Geodesic_error("pattern detection: the patch holds " + std::to_string(m_patch_sample.size()) +
                           " samples, too few to match (mark a larger patch or lower sample_spacing)");
    m_landmark =
      std::size_t(std::find(m_patch_sample.begin(), m_patch_sample.end(), std::size_t(0)) - m_patch_sample.begin());
    set_stroke_scales();
  }

  // Curvatures, then one local row per sample: its signature's ring sums and its distances to
  // the samples near it.
  template <class Report>
  void compute_signatures(const Report& report)
  {
    set_scales();
    compute_patch_distances();
    m_curvature = vertex_principal_curvatures(m_mesh.tm, m_mesh.vpm, m_mesh.vim, parallel && m_settings.threads != 1);
    const std::vector<Principal_curvatures>& curvature = m_curvature;
    const std::vector<double>& area = m_patch.area();
    const double signature_radius = m_settings.signature_radius * m_patch.size();
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
    m_rows.for_each_local_row(m_sample_vertex, row_radius, [&](std::size_t s, const Row& entries) {
      for(const auto& [v, d] : entries) {
        if(d < largest)
          m_rings[s].add(d, area[v], curvature[v]);
        const std::size_t t = m_sample_of_vertex[v];
        if(t != none && t != s && d <= m_pair_radius)
          m_near[s].emplace_back(t, d);
      }
      std::sort(m_near[s].begin(), m_near[s].end());
      report(double(s + 1) / double(n));
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

  double spacing() const { return m_spacing; }
  std::size_t count() const { return m_sample_vertex.size(); }
  std::size_t vertex(std::size_t q) const { return m_sample_vertex[q]; }
  // by vertex: its nearest sample
  const std::vector<std::size_t>& cell() const { return m_cell; }
  // the samples in the patch
  const std::vector<std::size_t>& patch_samples() const { return m_patch_sample; }
  // the centre's index among them
  std::size_t landmark() const { return m_landmark; }
  const std::vector<double>& scales() const { return m_scales; }
  // Whether sample q is matched at scale step `step`: with a stroke, only at the scales within
  // 20 % of the stroke's scale near it.
  bool matched_at(std::size_t step, std::size_t q) const
  {
    return m_stroke_scale.empty() || !(std::abs(std::log(m_scales[step] / m_stroke_scale[q])) > std::log(1.2));
  }
  const std::vector<Principal_curvatures>& curvature() const { return m_curvature; }
  // Empty ring sums in the samples' bands.
  Ring_sums empty_ring_sums() const { return Ring_sums(m_rings.front().bands(), m_band_width); }
  // the samples within the pair radius of sample q, by sample
  const Row& near(std::size_t q) const { return m_near[q]; }
  // the signature of patch sample i, at scale 1
  const std::vector<double>& patch_signature(std::size_t i) const { return m_patch_signature[i]; }
  double signature_norm() const { return m_signature_norm; }

  double sample_distance(std::size_t a, std::size_t b) const
  {
    if(a == b)
      return 0;
    const Row& row = m_near[a];
    const auto it =
      std::lower_bound(row.begin(), row.end(), std::make_pair(b, -std::numeric_limits<double>::infinity()));
    return it != row.end() && it->first == b ? it->second : std::numeric_limits<double>::infinity();
  }

  double patch_distance(std::size_t i, std::size_t j) const { return m_patch_distance[i * m_patch_sample.size() + j]; }

  // Pairs of patch samples whose images, if consistent at any scale of the range, lie within
  // the sample rows' radius: the pairs the consistency terms count.
  bool linked(std::size_t i, std::size_t j) const
  {
    return i != j && patch_distance(i, j) * m_scales.back() <= m_settings.consistency_cutoff * m_pair_radius;
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

  std::size_t nearest_scale_step(double scale) const
  {
    std::size_t best = 0;
    for(std::size_t s = 1; s < m_scales.size(); ++s)
      if(std::abs(std::log(m_scales[s] / scale)) < std::abs(std::log(m_scales[best] / scale)))
        best = s;
    return best;
  }

private:
  // Vertices at least `separation` apart in straight line, the patch's centre first, each next
  // one the farthest in straight line from those before: a geodesic distance is never shorter,
  // so they are as far apart on the surface.
  std::vector<vertex_descriptor> straight_line_seeds(double separation) const
  {
    const std::size_t n = m_mesh.vertex.size();
    std::vector<std::array<double, 3>> point(n);
    for(std::size_t v = 0; v < n; ++v) {
      const auto p = get(m_mesh.vpm, m_mesh.vertex[v]);
      point[v] = {double(p.x()), double(p.y()), double(p.z())};
    }
    std::vector<double> nearest(n, std::numeric_limits<double>::infinity());
    std::vector<vertex_descriptor> seeds;
    for(std::size_t seed = m_patch.center();;) {
      seeds.push_back(m_mesh.vertex[seed]);
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
      if(v >= m_mesh.vertex.size())
        throw Geodesic_error("pattern detection: stroke vertex " + std::to_string(v) +
                             " is out of range (the mesh has " + std::to_string(m_mesh.vertex.size()) + " vertices)");
    if(!m_patch.in_patch(stroke.front()))
      throw Geodesic_error("pattern detection: the stroke must start in the marked instance (vertex " +
                           std::to_string(stroke.front()) + " is not in it)");
    std::vector<double> along{0.0};
    for(std::size_t k = 1; k < stroke.size(); ++k)
      along.push_back(along.back() +
                      std::sqrt(double(CGAL::squared_distance(get(m_mesh.vpm, m_mesh.vertex[stroke[k - 1]]),
                                                              get(m_mesh.vpm, m_mesh.vertex[stroke[k]])))));
    if(!(along.back() > 0))
      throw Geodesic_error("pattern detection: the stroke has no length");
    const double end = std::abs(std::log(m_settings.scale_max)) >= std::abs(std::log(m_settings.scale_min))
                         ? m_settings.scale_max
                         : m_settings.scale_min;
    std::vector<vertex_descriptor> sources;
    for(std::size_t v : stroke)
      sources.push_back(m_mesh.vertex[v]);
    std::vector<double> distance(m_mesh.vertex.size(), 0.0);
    std::vector<std::size_t> nearest(m_mesh.vertex.size(), none);
    geodesic_distances<typename Mesh::Concurrency>(
      m_mesh.tm, CGAL::make_property_map(distance), sources,
      m_mesh.solver_parameters().vertex_source_map(CGAL::make_property_map(nearest)));
    m_stroke_scale.assign(m_sample_vertex.size(), 1.0);
    for(std::size_t q = 0; q < m_sample_vertex.size(); ++q) {
      const std::size_t k = nearest[m_sample_vertex[q]];
      if(k < stroke.size())
        m_stroke_scale[q] = std::pow(end, along[k] / along.back());
    }
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
    m_rows.for_each_local_row(sources, 2.01 * m_patch.radius(), [&](std::size_t i, const Row& entries) {
      for(const auto& [v, d] : entries)
        if(m_sample_of_vertex[v] != none && index[m_sample_of_vertex[v]] != none)
          m_patch_distance[i * k + index[m_sample_of_vertex[v]]] = d;
    });
  }

  const Mesh& m_mesh;
  const Pattern_settings& m_settings;
  Rows& m_rows;
  const Patch& m_patch;

  double m_spacing = 0;
  double m_pair_radius = 0;
  std::vector<double> m_patch_distance; // between patch samples, k x k

  std::vector<std::size_t> m_sample_vertex;    // by sample
  std::vector<std::size_t> m_sample_of_vertex; // by vertex: its sample, or none
  std::vector<std::size_t> m_cell;             // by vertex: its nearest sample
  std::vector<std::size_t> m_patch_sample;     // the samples in the patch
  std::size_t m_landmark = 0;                  // the centre's index among them

  std::vector<double> m_scales;
  std::vector<double> m_stroke_scale;                        // by sample, with a stroke: the scale near it
  std::vector<Principal_curvatures> m_curvature;             // by vertex
  double m_band_width = 1;                                   // of the ring sums
  std::vector<Ring_sums> m_rings;                            // by sample
  std::vector<Row> m_near;                                   // by sample: the samples within m_pair_radius
  std::vector<std::vector<std::vector<double>>> m_signature; // by scale step, then sample
  std::vector<std::vector<double>> m_patch_signature;        // by patch sample, at scale 1
  double m_signature_norm = 1;
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_SAMPLES_H
