// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_REFINEMENT_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_REFINEMENT_H

// The correspondence of a candidate instance refined by the energy of Eq. 5.4 (thesis 5.2.4):
// a local search that moves one patch sample's image at a time to a nearby mesh sample and keeps
// the move only when the energy falls.
//
// Eq. 5.4 sums over the patch samples that have an image; read literally, leaving a sample
// without an image would lower the energy. Here every term is an average over all the patch's
// samples (pairs) and a sample without an image costs what the worst image would (a signature
// one whole patch signature away, no consistency with any other sample), so that the weights
// do not depend on the number of samples and a fuller correspondence is preferred.

#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_clustering.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// What the energy of one candidate instance is computed from.
struct Pattern_energy_terms
{
  std::size_t patch_samples = 0;
  std::size_t landmark = 0; ///< the patch sample that is the landmark (the patch's centre)
  double alpha = 1, beta = 1, gamma = 1;
  /// the signature distance (relative to the patch's signatures) of patch sample i and mesh sample q
  std::function<double(std::size_t, std::size_t)> signature_cost;
  std::function<double(std::size_t, std::size_t)> patch_distance;  ///< between patch samples
  /// whether a pair of patch samples is near enough that the distance between their images is
  /// known (the pairs that the consistency terms count)
  std::function<bool(std::size_t, std::size_t)> linked;
  std::function<double(std::size_t, std::size_t)> sample_distance; ///< between mesh samples
  double scale = 1; ///< instance size over patch size
  double slack = 0; ///< the sampling's spacing (see `match_consistency()`)
};

/// A correspondence from the patch's samples to mesh samples and its energy.
struct Pattern_correspondence
{
  static constexpr std::size_t unmapped = std::size_t(-1);
  std::vector<std::size_t> image; ///< by patch sample: a mesh sample, or `unmapped`
  double energy = std::numeric_limits<double>::infinity();
  double mean_consistency = 0; ///< of the pairs of patch samples, unmapped ones counting 0
  std::size_t mapped = 0;
};

class Pattern_energy
{
public:
  explicit Pattern_energy(const Pattern_energy_terms& terms) : m_terms(terms) {}

  double signature_term(std::size_t i, std::size_t q) const
  {
    return q == Pattern_correspondence::unmapped ? 1.0 : std::min(1.0, m_terms.signature_cost(i, q));
  }

  double consistency(std::size_t i, std::size_t qi, std::size_t j, std::size_t qj) const
  {
    if(qi == Pattern_correspondence::unmapped || qj == Pattern_correspondence::unmapped)
      return 0;
    return match_consistency(m_terms.patch_distance(i, j), m_terms.sample_distance(qi, qj), m_terms.scale,
                             m_terms.scale, m_terms.slack);
  }

  /// the part of the energy that depends on the image of patch sample i
  double local(const std::vector<std::size_t>& image, std::size_t i, std::size_t qi) const
  {
    const std::size_t k = m_terms.patch_samples;
    double inconsistency = 0;
    for(std::size_t j = 0; j < k; ++j)
      if(j != i && m_terms.linked(i, j))
        inconsistency += 1 - consistency(i, qi, j, image[j]);
    double e = m_terms.alpha * signature_term(i, qi) / double(k) + m_terms.beta * inconsistency / linked_pairs();
    if(i == m_terms.landmark)
      e += m_terms.gamma * signature_term(i, qi);
    return e;
  }

  void evaluate(Pattern_correspondence& c) const
  {
    const std::size_t k = m_terms.patch_samples;
    double signature = 0, consistent = 0;
    c.mapped = 0;
    for(std::size_t i = 0; i < k; ++i) {
      signature += signature_term(i, c.image[i]);
      c.mapped += c.image[i] != Pattern_correspondence::unmapped;
      for(std::size_t j = i + 1; j < k; ++j)
        if(m_terms.linked(i, j))
          consistent += consistency(i, c.image[i], j, c.image[j]);
    }
    c.mean_consistency = consistent / linked_pairs();
    c.energy = m_terms.alpha * signature / double(k) + m_terms.beta * (1 - c.mean_consistency) +
               m_terms.gamma * signature_term(m_terms.landmark, c.image[m_terms.landmark]);
  }

  /// the number of linked pairs (at least 1)
  double linked_pairs() const
  {
    if(m_linked_pairs == 0) {
      for(std::size_t i = 0; i < m_terms.patch_samples; ++i)
        for(std::size_t j = i + 1; j < m_terms.patch_samples; ++j)
          m_linked_pairs += m_terms.linked(i, j);
      m_linked_pairs = std::max<std::size_t>(m_linked_pairs, 1);
    }
    return double(m_linked_pairs);
  }

  const Pattern_energy_terms& terms() const { return m_terms; }

private:
  const Pattern_energy_terms& m_terms;
  mutable std::size_t m_linked_pairs = 0;
};

/// Lowers the energy of `c` by moving one image at a time. The moves of patch sample i are to
/// the mesh samples within `step` of its image, or, when it has none, to those at about its
/// patch distance (within `step`) from the image of the nearest mapped patch sample.
/// `neighbours(q)` lists the mesh samples near q with their distances, `usable(q)` tells which
/// mesh samples may be images.
inline void refine_correspondence(
  Pattern_correspondence& c, const Pattern_energy& energy,
  const std::function<const std::vector<std::pair<std::size_t, double>>&(std::size_t)>& neighbours,
  const std::function<bool(std::size_t)>& usable, double step, int max_sweeps = 20)
{
  const Pattern_energy_terms& t = energy.terms();
  const std::size_t k = t.patch_samples;
  std::vector<std::size_t> used; // mesh samples that are images, kept sorted
  const auto refresh_used = [&] {
    used.clear();
    for(std::size_t q : c.image)
      if(q != Pattern_correspondence::unmapped)
        used.push_back(q);
    std::sort(used.begin(), used.end());
  };
  refresh_used();
  const auto is_used = [&](std::size_t q) { return std::binary_search(used.begin(), used.end(), q); };

  for(int sweep = 0; sweep < max_sweeps; ++sweep) {
    bool moved = false;
    for(std::size_t i = 0; i < k; ++i) {
      const std::size_t current = c.image[i];
      double best = energy.local(c.image, i, current);
      std::size_t best_q = current;
      const auto consider = [&](std::size_t q) {
        if(q == current || is_used(q) || !usable(q))
          return;
        const double e = energy.local(c.image, i, q);
        if(e < best - 1e-12) {
          best = e;
          best_q = q;
        }
      };
      if(current != Pattern_correspondence::unmapped) {
        for(const auto& [q, d] : neighbours(current))
          if(d <= step)
            consider(q);
      } else {
        std::size_t anchor = Pattern_correspondence::unmapped;
        double anchor_distance = std::numeric_limits<double>::infinity();
        for(std::size_t j = 0; j < k; ++j)
          if(c.image[j] != Pattern_correspondence::unmapped && t.linked(i, j) && t.patch_distance(i, j) < anchor_distance) {
            anchor = j;
            anchor_distance = t.patch_distance(i, j);
          }
        if(anchor == Pattern_correspondence::unmapped)
          continue;
        const double want = anchor_distance * t.scale;
        for(const auto& [q, d] : neighbours(c.image[anchor]))
          if(std::abs(d - want) <= step)
            consider(q);
      }
      if(best_q != current) {
        c.image[i] = best_q;
        refresh_used();
        moved = true;
      }
    }
    if(!moved)
      break;
  }
  energy.evaluate(c);
}

/// A correspondence built around a given image of the landmark: the other patch samples, the
/// nearest to the landmark first, each take, among the usable mesh samples at about its patch
/// distance (within `step`) from the image of its nearest mapped (linked) patch sample, the one
/// that lowers the energy most given the images chosen so far. Moving single images cannot
/// shift a whole correspondence (on a flat region a shifted one keeps every distance), this can.
inline Pattern_correspondence correspondence_around(
  std::size_t landmark_image, const Pattern_energy& energy,
  const std::function<const std::vector<std::pair<std::size_t, double>>&(std::size_t)>& neighbours,
  const std::function<bool(std::size_t)>& usable, double step)
{
  const Pattern_energy_terms& t = energy.terms();
  const std::size_t k = t.patch_samples;
  Pattern_correspondence c;
  c.image.assign(k, Pattern_correspondence::unmapped);
  c.image[t.landmark] = landmark_image;
  std::vector<std::size_t> order;
  for(std::size_t i = 0; i < k; ++i)
    if(i != t.landmark)
      order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return t.patch_distance(a, t.landmark) < t.patch_distance(b, t.landmark);
  });
  std::vector<std::size_t> used{landmark_image};
  for(std::size_t i : order) {
    std::size_t anchor = Pattern_correspondence::unmapped;
    for(std::size_t j = 0; j < k; ++j)
      if(c.image[j] != Pattern_correspondence::unmapped && t.linked(i, j) &&
         (anchor == Pattern_correspondence::unmapped || t.patch_distance(i, j) < t.patch_distance(i, anchor)))
        anchor = j;
    if(anchor == Pattern_correspondence::unmapped)
      continue;
    const double want = t.patch_distance(i, anchor) * t.scale;
    double best = energy.local(c.image, i, Pattern_correspondence::unmapped);
    for(const auto& [q, d] : neighbours(c.image[anchor])) {
      if(std::abs(d - want) > step || !usable(q) || std::find(used.begin(), used.end(), q) != used.end())
        continue;
      const double e = energy.local(c.image, i, q);
      if(e < best - 1e-12) {
        best = e;
        c.image[i] = q;
      }
    }
    if(c.image[i] != Pattern_correspondence::unmapped)
      used.push_back(c.image[i]);
  }
  energy.evaluate(c);
  return c;
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_REFINEMENT_H
