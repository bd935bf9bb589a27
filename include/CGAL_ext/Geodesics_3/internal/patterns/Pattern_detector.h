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
// (Pattern_refinement.h). The detector owns the parts of a run: the mesh by vertex index
// (Pattern_mesh.h), its local rows and their descent (Pattern_rows.h), the marked patch
// (Pattern_patch_geometry.h) and the sampled surface (Pattern_samples.h); this file does the
// matching, the region growing (Algorithm 7), the centre of each instance and the arrangement.

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>
#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_clustering.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_mesh.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_patch_geometry.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_refinement.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_rows.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_samples.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_settings.h>
#include <CGAL_ext/Geodesics_3/internal/support/Progress_reporter.h>
#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_signatures.h>
#include <CGAL_ext/geodesic_voronoi_diagram.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <queue>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

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
  typedef Pattern_mesh<parallel, TriangleMesh, VertexPointMap, VertexIndexMap> Mesh;
  typedef Pattern_rows<parallel, TriangleMesh, VertexPointMap, VertexIndexMap> Rows;
  typedef typename Rows::Row Row;
  typedef typename Mesh::vertex_descriptor vertex_descriptor;
  typedef std::chrono::steady_clock Clock;
  static constexpr std::size_t none = std::size_t(-1);

public:
  Pattern_detector(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim, const Pattern_settings& settings)
    : m_mesh(tm, vpm, vim, settings.threads)
    , m_settings(settings)
    , m_rows(m_mesh, m_settings.approximation)
    , m_patch(m_mesh, m_rows)
    , m_samples(m_mesh, m_settings, m_rows, m_patch)
  {
    check_pattern_settings(m_settings);
  }
  // the parts hold references to one another
  Pattern_detector(const Pattern_detector&) = delete;
  Pattern_detector& operator=(const Pattern_detector&) = delete;

  Detection_result run(const Pattern_patch_indices& patch)
  {
    Detection_result result;
    m_times = &result.statistics;
    auto start = Clock::now();
    m_patch.set_patch(patch);
    m_times->patch_radius = m_patch.radius();
    report(Step::sampling, 0);
    m_samples.sample([&](double within) { report(Step::sampling, within); });
    m_times->samples = m_samples.count();
    m_times->patch_samples = m_samples.patch_samples().size();
    m_times->seconds_sampling = seconds_since(start);
    start = Clock::now();
    m_samples.compute_signatures([&](double within) { report(Step::signatures, within); });
    m_times->seconds_signatures = seconds_since(start);
    grow_regions();
    report(Step::centres, 0);
    start = Clock::now();
    place_centres();
    merge_overlapping_instances();
    // the last row: the rows' solver mesh and solvers go before the arrangement's
    m_times->distance_rows += m_rows.release();
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

  // Tells the caller's callback how far the run is: `within` of `step` done (a few times a
  // second at most, and at the end of the run).
  void report(Step step, double within)
  {
    // where each step starts and ends, as a fraction of a run (the shares of a golf ball's)
    static constexpr double bounds[] = {0.0, 0.35, 0.65, 0.8, 0.87, 1.0};
    const double a = bounds[int(step)], b = bounds[int(step) + 1];
    const double done = a + (b - a) * std::clamp(within, 0.0, 1.0);
    if(done >= 1.)
      m_progress.report_now(done);
    else
      m_progress.report([done] { return done; });
  }

  static double seconds_since(Clock::time_point start)
  {
    return std::chrono::duration<double>(Clock::now() - start).count();
  }

  // Algorithm 7: from the marked patch, each new instance searches its own neighbourhood for
  // more, until no new one appears.
  void grow_regions()
  {
    const std::size_t k = m_samples.patch_samples().size();
    m_used.assign(m_samples.count(), false);
    Instance marked;
    marked.correspondence.image = m_samples.patch_samples();
    marked.center_sample = 0;
    marked.center_vertex = m_patch.center();
    marked.correspondence.mapped = k;
    marked.correspondence.energy = 0;
    marked.correspondence.mean_consistency = 1;
    marked.scale_step = none;
    m_instances.assign(1, marked);
    for(std::size_t s : m_samples.patch_samples())
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
    std::vector<bool> near_fruitless_seed(m_samples.count(), false);
    for(;;) {
      while(!to_search.empty()) {
        const Instance& from = m_instances[to_search.front()];
        to_search.pop();
        search(from.center_sample, from.scale_step == none ? 1.0 : m_samples.scales()[from.scale_step]);
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
        const double s = std::max(1.0, m_samples.scales().back());
        const double ruled_out = std::clamp(m_settings.search_radius * s - s, 0.0, 2.0) * m_patch.radius();
        for(std::size_t q : m_samples.neighbourhood(seed, ruled_out))
          near_fruitless_seed[q] = true;
      }
    }
  }

  // Free samples whose signature is within three times the tolerance of the landmark's (its
  // nearest sample may be a spacing off an instance's centre), the most alike first.
  std::vector<std::size_t> landmark_lookalikes() const
  {
    std::vector<std::pair<double, std::size_t>> alike;
    for(std::size_t q = 0; q < m_samples.count(); ++q) {
      if(m_used[q])
        continue;
      double cost = std::numeric_limits<double>::infinity();
      for(std::size_t step = 0; step < m_samples.scales().size(); ++step)
        cost = std::min(cost, m_samples.signature_cost(m_samples.landmark(), step, q));
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
      const double scale = instance.scale_step == none ? 1.0 : m_samples.scales()[instance.scale_step];
      if(m_samples.sample_distance(q, instance.center_sample) <= scale * m_patch.size() * 1.5)
        return false;
    }
    return true;
  }

  std::vector<Instance> search_around(std::size_t center_sample, double scale)
  {
    auto start = Clock::now();
    const std::size_t k = m_samples.patch_samples().size();
    const double reach =
      (m_settings.search_radius * std::max(scale, m_samples.scales().back()) + 1.0) * m_patch.radius();
    const std::vector<std::size_t> candidates = m_samples.neighbourhood(center_sample, reach);
    std::vector<bool> in_neighbourhood(m_samples.count(), false);
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
        for(std::size_t step = 0; step < m_samples.scales().size(); ++step) {
          if(!m_samples.matched_at(step, q))
            continue;
          const double cost = m_samples.signature_cost(i, step, q);
          if(cost < best.signature_distance) {
            best.signature_distance = cost;
            best.scale = m_samples.scales()[step];
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
        return m_samples.linked(i, j) ? m_samples.patch_distance(i, j) : std::numeric_limits<double>::infinity();
      },
      [&](std::size_t a, std::size_t b) { return m_samples.sample_distance(a, b); }, m_settings.consistency_cutoff,
      m_samples.spacing(), k);
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

  // A cluster's correspondence, refined by Eq. 5.4; false when it is not a new instance.
  bool make_instance(const std::vector<Pattern_match>& matches, const std::vector<std::size_t>& cluster,
                     const std::vector<bool>& in_neighbourhood, const std::vector<Instance>& found_now,
                     Instance& instance) const
  {
    const std::size_t k = m_samples.patch_samples().size();
    std::vector<double> scales;
    for(std::size_t m : cluster)
      scales.push_back(matches[m].scale);
    std::nth_element(scales.begin(), scales.begin() + std::ptrdiff_t(scales.size() / 2), scales.end());
    instance.scale_step = m_samples.nearest_scale_step(scales[scales.size() / 2]);
    const double scale = m_samples.scales()[instance.scale_step];

    // start from the most consistent match of each patch sample in the cluster
    std::vector<double> support(cluster.size(), 0.0);
    for(std::size_t a = 0; a < cluster.size(); ++a)
      for(std::size_t b = 0; b < cluster.size(); ++b) {
        const Pattern_match& ma = matches[cluster[a]];
        const Pattern_match& mb = matches[cluster[b]];
        if(ma.patch_sample != mb.patch_sample && ma.sample != mb.sample &&
           m_samples.linked(ma.patch_sample, mb.patch_sample))
          support[a] +=
            match_consistency(m_samples.patch_distance(ma.patch_sample, mb.patch_sample),
                              m_samples.sample_distance(ma.sample, mb.sample), scale, scale, m_samples.spacing());
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
    terms.landmark = m_samples.landmark();
    terms.alpha = m_settings.alpha;
    terms.beta = m_settings.beta;
    terms.gamma = m_settings.gamma;
    terms.scale = scale;
    terms.slack = m_samples.spacing();
    std::size_t step = instance.scale_step;
    terms.signature_cost = [this, &step](std::size_t i, std::size_t q) { return m_samples.signature_cost(i, step, q); };
    terms.patch_distance = [this](std::size_t i, std::size_t j) { return m_samples.patch_distance(i, j); };
    terms.linked = [this](std::size_t i, std::size_t j) { return m_samples.linked(i, j); };
    terms.sample_distance = [this](std::size_t a, std::size_t b) { return m_samples.sample_distance(a, b); };
    const Pattern_energy energy(terms);
    std::vector<bool> taken_now(m_samples.count(), false);
    for(const Instance& other : found_now)
      for(std::size_t q : other.correspondence.image)
        if(q != Pattern_correspondence::unmapped)
          taken_now[q] = true;
    const auto near = [this](std::size_t q) -> const Row& { return m_samples.near(q); };
    const auto usable = [&](std::size_t q) { return in_neighbourhood[q] && !m_used[q] && !taken_now[q]; };
    const double step_length = 2 * m_samples.spacing() * scale;
    refine_correspondence(c, energy, near, usable, step_length);
    // then the correspondences rebuilt around the samples near the landmark's image
    if(c.image[m_samples.landmark()] != Pattern_correspondence::unmapped) {
      const Pattern_correspondence first = c;
      for(const auto& [q, d] : m_samples.near(first.image[m_samples.landmark()])) {
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
    if(m_samples.scales().size() > 1) {
      const std::size_t first = step;
      double lowest = c.energy;
      for(std::size_t t = first > 3 ? first - 3 : 0; t < std::min(m_samples.scales().size(), first + 4); ++t) {
        step = t;
        terms.scale = m_samples.scales()[t];
        Pattern_correspondence at = c;
        energy.evaluate(at);
        if(at.energy < lowest) {
          lowest = at.energy;
          instance.scale_step = t;
        }
      }
      step = instance.scale_step;
      terms.scale = m_samples.scales()[step];
      refine_correspondence(c, energy, near, usable, 2 * m_samples.spacing() * terms.scale);
    }

    // accept a correspondence that maps the landmark and at least two thirds of the samples, whose
    // mapped pairs keep their distances (on average to 0.85 of the cut-off: the pairs of a true
    // instance on an anisotropic triangulation fall a little short of it) and whose landmark looks
    // like the patch's centre (within twice the match tolerance: the landmark's image is a
    // sample, up to a spacing from where the centre maps)
    if(c.image[m_samples.landmark()] == Pattern_correspondence::unmapped || 3 * c.mapped < 2 * k)
      return false;
    constexpr double acceptance = 0.85;
    double consistent = 0;
    std::size_t pairs = 0;
    for(std::size_t i = 0; i < k; ++i)
      for(std::size_t j = i + 1; j < k; ++j)
        if(c.image[i] != Pattern_correspondence::unmapped && c.image[j] != Pattern_correspondence::unmapped &&
           m_samples.linked(i, j)) {
          consistent += energy.consistency(i, c.image[i], j, c.image[j]);
          ++pairs;
        }
    if(pairs == 0 || consistent / double(pairs) < acceptance * m_settings.consistency_cutoff)
      return false;
    if(m_samples.signature_cost(m_samples.landmark(), step, c.image[m_samples.landmark()]) >
       2 * m_settings.match_tolerance)
      return false;
    instance.center_sample = c.image[m_samples.landmark()];
    instance.center_vertex = m_samples.vertex(instance.center_sample);
    // a new instance: its centre is farther than the mean of the two sizes from every other's
    // centre, and farther than 1.5 spacings from every other's images (an elongated instance's
    // centre may be farther than its size from a shifted copy of itself, not from its samples)
    const double scale_found = m_samples.scales()[instance.scale_step];
    const auto overlaps = [&](const Instance& other) {
      const double scale = scale_found;
      const double other_scale = other.scale_step == none ? 1.0 : m_samples.scales()[other.scale_step];
      if(m_samples.sample_distance(instance.center_sample, other.center_sample) <
         0.5 * (scale + other_scale) * m_patch.size())
        return true;
      for(std::size_t q : other.correspondence.image)
        if(q != Pattern_correspondence::unmapped && m_samples.sample_distance(instance.center_sample, q) <
                                                      1.5 * m_samples.spacing() * std::min(scale, other_scale))
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
    const std::size_t k = m_samples.patch_samples().size();
    if(n < 2)
      return;
    const int rings = m_settings.signature_rings;
    const double signature_radius = m_settings.signature_radius * m_patch.size();
    const std::vector<double>& target = m_samples.patch_signature(m_samples.landmark());
    const std::size_t patch_centre = m_samples.vertex(m_samples.patch_samples()[m_samples.landmark()]);
    const double target_moment =
      curvature_moment(patch_centre, m_rows.local_row(patch_centre, signature_radius), signature_radius);
    // the images as far as the patch's farthest samples, with a spacing to spare (for an
    // elongated patch, those along its axis, beyond the signature's disk, tell the most)
    const double reach = std::max(signature_radius, m_patch.radius() + m_samples.spacing()) * m_samples.scales().back();

    std::vector<Row> allowed(n); // the vertices within two spacings of the landmark's image
    const auto is_allowed = [&](std::size_t a, std::size_t v) {
      return std::binary_search(allowed[a].begin(), allowed[a].end(),
                                std::make_pair(v, -std::numeric_limits<double>::infinity()),
                                [](const auto& x, const auto& y) { return x.first < y.first; });
    };
    const auto cost = [&](std::size_t a, std::size_t centre, const Row& entries) {
      const Instance& instance = m_instances[a];
      const double scale = m_samples.scales()[instance.scale_step];
      if(allowed[a].empty()) // the first row of the instance: its start's
        for(const auto& entry : entries)
          if(entry.second <= 2 * m_samples.spacing() * scale)
            allowed[a].push_back(entry);
      const double radius = signature_radius * scale;
      Ring_sums sums = m_samples.empty_ring_sums();
      for(const auto& [v, d] : entries)
        if(d < radius)
          sums.add(d, m_patch.area()[v], m_samples.curvature()[v]);
      double squares = 0;
      std::size_t counted = 0;
      for(std::size_t i = 0; i < k; ++i) {
        const std::size_t q = instance.correspondence.image[i];
        if(q == Pattern_correspondence::unmapped)
          continue;
        const auto it = std::lower_bound(entries.begin(), entries.end(),
                                         std::make_pair(m_samples.vertex(q), -std::numeric_limits<double>::infinity()));
        if(it == entries.end() || it->first != m_samples.vertex(q))
          continue;
        const double want = m_samples.patch_distance(m_samples.landmark(), i) * scale;
        squares += (it->second - want) * (it->second - want);
        ++counted;
      }
      return centre_signature_weight * signature_distance(target, sums.signature(radius, rings)) /
               m_samples.signature_norm() +
             (counted ? std::sqrt(squares / double(counted)) / (m_patch.size() * scale) : 0.0) +
             centre_moment_weight * std::abs(curvature_moment(centre, entries, radius) - target_moment);
    };
    // the walkers are the instances but the patch: walker w is instance w + 1
    std::vector<std::size_t> start;
    for(std::size_t a = 1; a < n; ++a)
      start.push_back(m_instances[a].center_vertex);
    const int max_steps =
      2 + int(std::ceil(3 * m_samples.spacing() * m_samples.scales().back() / std::max(m_patch.mean_edge(), 1e-300)));
    // A row needs the signature's disk, the vertices allowed, and the images within `reach`:
    // it stops once the images are settled (when they all lie within `reach`), its costs the
    // same as a row to `reach`.
    std::vector<std::vector<std::size_t>> image_vertices(n);
    for(std::size_t a = 1; a < n; ++a)
      for(std::size_t q : m_instances[a].correspondence.image)
        if(q != Pattern_correspondence::unmapped)
          image_vertices[a].push_back(m_samples.vertex(q));
    const auto add_stops = [&](std::size_t w, Row_stops& stops) {
      const double scale = m_samples.scales()[m_instances[w + 1].scale_step];
      for(std::size_t v : image_vertices[w + 1])
        stops.add_stop_vertex(v);
      stops.set_stop_floor_in_mesh_unit(std::max(signature_radius, 2 * m_samples.spacing()) * scale);
    };
    const auto placed = m_rows.descend(
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
    const std::vector<double>& area = m_patch.area();
    const std::vector<Principal_curvatures>& curvature = m_samples.curvature();
    const auto c = get(m_mesh.vpm, m_mesh.vertex[centre]);
    double moment[3] = {0, 0, 0}, weight = 0;
    for(const auto& [u, d] : entries) {
      if(!(d < radius))
        continue;
      const double w = area[u] * (std::abs(curvature[u].k_max) + std::abs(curvature[u].k_min));
      const auto offset = get(m_mesh.vpm, m_mesh.vertex[u]) - c;
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
    const auto size = [&](std::size_t a) { return m_patch.size() * m_samples.scales()[m_instances[a].scale_step]; };
    double largest = 0;
    std::vector<std::size_t> sources;
    for(std::size_t a = 0; a < n; ++a) {
      largest = std::max(largest, size(a));
      sources.push_back(m_instances[a].center_vertex);
    }
    std::vector<std::size_t> instance_at(m_mesh.vertex.size(), none);
    for(std::size_t a = 0; a < n; ++a)
      instance_at[m_instances[a].center_vertex] = a;
    const auto cost = [&](std::size_t a) { return a == 0 ? -1.0 : m_instances[a].center_cost; };
    std::vector<bool> dropped(n, false);
    m_rows.for_each_local_row(sources, largest, [&](std::size_t a, const Row& entries) {
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
      d.scale = instance.scale_step == none ? 1.0 : m_samples.scales()[instance.scale_step];
      d.energy = instance.correspondence.energy;
      for(std::size_t i = 0; i < m_samples.patch_samples().size(); ++i)
        if(instance.correspondence.image[i] != Pattern_correspondence::unmapped)
          d.correspondence.emplace_back(m_samples.vertex(m_samples.patch_samples()[i]),
                                        m_samples.vertex(instance.correspondence.image[i]));
      out.push_back(std::move(d));
    }
    out.front().vertices = m_patch.vertices();
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
      centres.push_back(m_mesh.vertex[d.center]);
    // each vertex's cell (the index of its nearest centre) and its distance to it, by vertex index
    std::vector<std::size_t> cell(m_mesh.vertex.size(), no_source);
    std::vector<double> distance(m_mesh.vertex.size(), std::numeric_limits<double>::infinity());
    const auto diagram = geodesic_voronoi_diagram<typename Mesh::Concurrency>(
      m_mesh.tm, centres,
      m_mesh.solver_parameters()
        .algorithm(VTP)
        .vertex_source_map(boost::make_iterator_property_map(cell.begin(), m_mesh.vim))
        .vertex_distance_map(boost::make_iterator_property_map(distance.begin(), m_mesh.vim)));
    result.arrangement_edges = diagram.dual_edges;
    result.arrangement_triangles = diagram.dual_triangles;
    std::vector<std::size_t> owner(m_samples.count(), none);
    for(std::size_t a = 1; a < m_instances.size(); ++a)
      for(std::size_t q : m_instances[a].correspondence.image)
        if(q != Pattern_correspondence::unmapped)
          owner[q] = a;
    for(std::size_t v = 0; v < m_mesh.vertex.size(); ++v) {
      const std::size_t a = cell[v];
      if(a == 0 || a >= result.instances.size())
        continue;
      const bool near = distance[v] <= m_patch.size() * result.instances[a].scale;
      const bool sampled = m_samples.cell()[v] < owner.size() && owner[m_samples.cell()[v]] == a;
      if(near || sampled)
        result.instances[a].vertices.push_back(v);
    }
  }

  Mesh m_mesh;
  Pattern_settings m_settings;
  Rows m_rows;
  Pattern_patch_geometry<parallel, TriangleMesh, VertexPointMap, VertexIndexMap> m_patch;
  Pattern_samples<parallel, TriangleMesh, VertexPointMap, VertexIndexMap> m_samples;
  Pattern_statistics* m_times = nullptr;
  Progress_reporter m_progress{m_settings.progress, "pattern detection"};

  std::vector<bool> m_used; // samples that are images of an accepted instance (or of the patch)
  std::vector<Instance> m_instances;
};

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_DETECTOR_H
