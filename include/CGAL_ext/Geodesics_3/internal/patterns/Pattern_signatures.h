// Copyright (c) 2026 The CGAL_ext geodesics developers.
#ifndef CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_SIGNATURES_H
#define CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_SIGNATURES_H

// The signature of a sample (thesis 5.2.2.2, after Gatzke et al.'s curvature maps): how the
// principal curvatures are spread over the geodesic disk around it, ring by ring from the centre.
//
// The thesis samples K radial geodesic paths of the disk at N points each and keeps, per
// distance from the centre, the mean and the variance of the curvatures over the K paths. Here
// every vertex of the disk takes part, weighted by its area and placed by its exact geodesic
// distance: the limit of that sampling as K grows, with no direction to choose. A ring of the
// disk gathers the vertices of a band of distances; the bands are kept fine (`Ring_sums`) so that
// the signature of any smaller radius, and of a scaled radius (adaptive patterns, Eq. 5.5), is a
// regrouping of the same sums: one propagation per sample serves every radius and scale.

#include <CGAL_ext/Geodesics_3/internal/patterns/Pattern_curvature.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL_ext {
namespace Geodesics_3 {
namespace internal {

/// The area-weighted sums of the curvatures of the vertices in each fine band of distance
/// around one sample.
class Ring_sums
{
public:
  Ring_sums() = default;
  Ring_sums(std::size_t bands, double band_width) : m_band_width(band_width), m_sums(bands * fields, 0.0) {}

  std::size_t bands() const { return m_sums.size() / fields; }
  double radius() const { return m_band_width * double(bands()); }

  void add(double distance, double area, const Principal_curvatures& k)
  {
    const std::size_t band = std::size_t(distance / m_band_width);
    if(band >= bands() || !(area > 0))
      return;
    double* s = &m_sums[band * fields];
    s[0] += area;
    s[1] += area * k.k_max;
    s[2] += area * k.k_min;
    s[3] += area * k.k_max * k.k_max;
    s[4] += area * k.k_min * k.k_min;
  }

  /// The signature of the disk of `radius` (at most `radius()`) in `rings` rings: per ring, the
  /// mean and the standard deviation of both principal curvatures, times `radius` so that disks
  /// of different sizes compare (a disk twice as large with half the curvature is the same shape).
  /// A ring with no vertex repeats the ring inside it.
  std::vector<double> signature(double radius, int rings) const
  {
    std::vector<double> f(std::size_t(rings) * 4, 0.0);
    const double ring_width = radius / rings;
    std::size_t band = 0;
    for(int r = 0; r < rings; ++r) {
      double s[fields] = {0, 0, 0, 0, 0};
      for(; band < bands() && (double(band) + 0.5) * m_band_width < (r + 1) * ring_width; ++band)
        for(int k = 0; k < fields; ++k)
          s[k] += m_sums[band * fields + k];
      double* out = &f[std::size_t(r) * 4];
      if(s[0] > 0) {
        const double mean_max = s[1] / s[0], mean_min = s[2] / s[0];
        out[0] = mean_max * radius;
        out[1] = mean_min * radius;
        out[2] = std::sqrt(std::max(0.0, s[3] / s[0] - mean_max * mean_max)) * radius;
        out[3] = std::sqrt(std::max(0.0, s[4] / s[0] - mean_min * mean_min)) * radius;
      } else if(r > 0) {
        std::copy(out - 4, out, out);
      }
    }
    return f;
  }

private:
  static constexpr int fields = 5; // area, then the area-weighted k_max, k_min, k_max^2, k_min^2
  double m_band_width = 1;
  std::vector<double> m_sums;
};

inline double signature_distance(const std::vector<double>& a, const std::vector<double>& b)
{
  double sum = 0;
  for(std::size_t i = 0; i < a.size(); ++i)
    sum += (a[i] - b[i]) * (a[i] - b[i]);
  return std::sqrt(sum);
}

} // namespace internal
} // namespace Geodesics_3
} // namespace CGAL_ext

#endif // CGAL_EXT_GEODESICS_3_INTERNAL_PATTERNS_PATTERN_SIGNATURES_H
