// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_SETTINGS_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_SETTINGS_H

// What a pattern detection is asked: its constants and the marked patch, by vertex index, and
// the check of the constants' ranges.

#include <CGAL_ext/Geodesics_3/Geodesic_error.h>

#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// The constants of the pipeline. Lengths are relative to the patch's size (the radius of a disk
/// of its area: its radius when it is a geodesic disk), the search radius to the patch radius
/// (the largest geodesic distance from its centre to its vertices).
struct Pattern_settings
{
  double sample_spacing = 1.0 / 3;       ///< covering radius of the sampling
  double signature_radius = 1.0;         ///< radius of the disk of a signature
  int signature_rings = 6;               ///< N: rings of a signature
  double match_tolerance = 0.35;         ///< epsilon of Eq. 5.5, relative to the patch's mean signature norm
  std::size_t matches_per_sample = 24;   ///< candidate matches kept per patch sample, best first
  double consistency_cutoff = 0.7;       ///< c0 of Eq. 5.1
  double alpha = 1, beta = 1, gamma = 1; ///< weights of Eq. 5.4
  double search_radius = 3.0;            ///< how far from an instance's centre its neighbours are sought
  double scale_min = 1, scale_max = 1;   ///< instance size over patch size
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
  std::vector<std::size_t> vertices; ///< a vertex list (when not a disk)
};

/// Throws `Geodesic_error` naming the first setting out of its range.
inline void check_pattern_settings(const Pattern_settings& s)
{
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

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_SETTINGS_H
