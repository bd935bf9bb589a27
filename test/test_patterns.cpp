// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Repetitive pattern detection (thesis chapter 5): each step on its own, then the whole pipeline
// on meshes with planted instances, scored by recall and precision.

#include "support/pattern_meshes.h"

#include <CGAL_ext/detect_repetitive_patterns.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using namespace test_support;
namespace internal = CGAL_ext::Geodesics_3::internal;

namespace {

typedef CGAL_ext::Repetitive_patterns<Mesh, Point> Patterns;

Vertex nearest_vertex(const Mesh& m, const Point& p)
{
  Vertex best = *m.vertices().begin();
  for(Vertex v : m.vertices())
    if(CGAL::squared_distance(m.point(v), p) < CGAL::squared_distance(m.point(best), p))
      best = v;
  return best;
}

/// How the found instances compare with the planted ones: a found centre is right when it lies
/// within a quarter of the instance radius of a planted centre not claimed yet.
struct Score
{
  double recall = 0, precision = 0;
  std::size_t found = 0, right = 0, planted = 0;
};

Score score(const Patterns& found, const std::vector<Point>& centres, const std::vector<double>& radii)
{
  Score s;
  s.planted = centres.size();
  s.found = found.instances.size();
  std::vector<bool> claimed(centres.size(), false);
  for(const auto& instance : found.instances) {
    std::size_t best = centres.size();
    double best_d = 0;
    for(std::size_t i = 0; i < centres.size(); ++i) {
      const double d = std::sqrt(CGAL::squared_distance(instance.center, centres[i]));
      if(!claimed[i] && d <= 0.25 * radii[i] && (best == centres.size() || d < best_d)) {
        best = i;
        best_d = d;
      }
    }
    if(best < centres.size()) {
      claimed[best] = true;
      ++s.right;
    }
  }
  s.recall = double(s.right) / double(std::max<std::size_t>(1, s.planted));
  s.precision = double(s.right) / double(std::max<std::size_t>(1, s.found));
  return s;
}

std::ostream& operator<<(std::ostream& out, const Score& s)
{
  return out << "recall " << s.recall << " precision " << s.precision << " (" << s.right << " right of "
             << s.found << " found, " << s.planted << " planted)";
}

} // namespace

TEST(Pattern_detection, Round_bumps_on_a_plane_laid_out_irregularly)
{
  const double radius = 0.06;
  const std::vector<Planted> bumps = irregular_layout(24, 0.08, 0.92, 2.6 * radius, radius, 3);
  Mesh m = bumpy_plane(121, 1.0 / 120, bumps, 0.4);
  std::vector<Point> centres;
  std::vector<double> radii;
  for(const Planted& b : bumps) {
    centres.push_back(Point(b.x, b.y, 0.4 * radius));
    radii.push_back(radius);
  }
  const Vertex centre = nearest_vertex(m, centres[0]);
  const Patterns found =
    CGAL_ext::detect_repetitive_patterns(m, CGAL_ext::Pattern_patch<Mesh>::disk(centre, radius));
  const Score s = score(found, centres, radii);
  const auto& st = found.statistics;
  std::cout << s << "; samples " << st.samples << " (" << st.patch_samples << " in the patch), matches "
            << st.matches << ", clusters " << st.clusters << ", searches " << st.searches << "\n";
  EXPECT_GE(s.recall, 0.95) << s;
  EXPECT_GE(s.precision, 0.95) << s;
}
