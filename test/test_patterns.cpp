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

/// The planted instances: where each centre is on the surface and its radius.
struct Truth
{
  std::vector<Point> centres;
  std::vector<double> radii;
};

/// Runs the detection and checks recall and precision against `truth`, and that each instance's
/// correspondence keeps the distances from the centre (the patch's centre maps to the
/// instance's, its other samples around it at their distances, times the scale), on average to
/// 0.6 patch radii: images are samples, placed up to a spacing from where a patch sample maps,
/// and the correspondence of some instances is only that good (a random one is off by about a
/// radius).
template <class NamedParameters = CGAL_ext::parameters::Default_named_parameters_type>
Patterns expect_found(const Mesh& m, const CGAL_ext::Pattern_patch<Mesh>& patch, const Truth& truth, double at_least,
                      const NamedParameters& np = CGAL_ext::parameters::default_values())
{
  const Patterns found = CGAL_ext::detect_repetitive_patterns<CGAL::Parallel_if_available_tag>(m, patch, np);
  const Score s = score(found, truth.centres, truth.radii);
  const auto& st = found.statistics;
  std::cout << s << "; " << m.number_of_vertices() << " vertices, " << st.samples << " samples ("
            << st.patch_samples << " in the patch), " << st.matches << " matches, " << st.clusters << " clusters, "
            << st.searches << " searches\n";
  EXPECT_GE(s.recall, at_least) << s;
  EXPECT_GE(s.precision, at_least) << s;
  EXPECT_FALSE(found.instances.empty());
  const auto& marked = found.instances.front();
  for(const auto& instance : found.instances) {
    EXPECT_FALSE(instance.correspondence.empty());
    EXPECT_FALSE(instance.vertices.empty());
    if(instance.correspondence.empty())
      continue;
    double off = 0;
    for(const auto& [p, q] : instance.correspondence)
      off += std::abs(std::sqrt(CGAL::squared_distance(m.point(q), instance.center)) -
                      instance.scale * std::sqrt(CGAL::squared_distance(m.point(p), marked.center)));
    EXPECT_LE(off / double(instance.correspondence.size()), 0.6 * st.patch_radius * instance.scale)
      << instance.correspondence.size() << " mapped, energy " << instance.energy;
  }
  return found;
}

} // namespace

TEST(Pattern_detection, Round_bumps_on_a_plane_laid_out_irregularly_with_noise)
{
  const double radius = 0.06;
  const std::vector<Planted> bumps = irregular_layout(24, 0.08, 0.92, 0.08, 0.92, 2.6 * radius, radius, 3);
  Mesh m = bumpy_plane(121, 1.0 / 120, bumps, 0.4);
  add_noise(m, 0.05 / 120, 11);
  Truth truth;
  for(const Planted& b : bumps) {
    truth.centres.push_back(Point(b.x, b.y, 0.4 * radius));
    truth.radii.push_back(radius);
  }
  const Patterns found = expect_found(
    m, CGAL_ext::Pattern_patch<Mesh>::disk(nearest_vertex(m, truth.centres[0]), radius), truth, 0.95);
  // the arrangement: a planar graph among the instances
  EXPECT_GE(found.arrangement_edges.size(), found.instances.size() - 1);
  EXPECT_LE(found.arrangement_edges.size(), 3 * found.instances.size());
}

TEST(Pattern_detection, Golf_ball_dimples)
{
  const std::vector<Vector> directions = fibonacci_directions(40);
  const double angle = 0.24, depth = 0.3;
  Mesh m = golf_ball(5, directions, angle, depth);
  add_noise(m, 0.001, 5);
  Truth truth;
  for(const Vector& d : directions) {
    truth.centres.push_back(CGAL::ORIGIN + d * (1 - depth * angle));
    truth.radii.push_back(angle);
  }
  expect_found(m, CGAL_ext::Pattern_patch<Mesh>::disk(nearest_vertex(m, truth.centres[5]), angle), truth, 0.95);
}

TEST(Pattern_detection, Bumps_around_a_cylinder)
{
  const double r = 1, radius = 0.35;
  const std::vector<Planted> bumps =
    irregular_layout(30, 0.4, 2 * CGAL_PI * r - 0.4, 0.5, 5.5, 2.5 * radius, radius, 8);
  Mesh m = bumpy_cylinder(r, 128, 6, 110, bumps, 0.35);
  Truth truth;
  for(const Planted& b : bumps) {
    const double a = b.x / r, lifted = r + 0.35 * radius;
    truth.centres.push_back(Point(lifted * std::cos(a), lifted * std::sin(a), b.y));
    truth.radii.push_back(radius);
  }
  expect_found(m, CGAL_ext::Pattern_patch<Mesh>::disk(nearest_vertex(m, truth.centres[0]), radius), truth, 0.95);
}

TEST(Pattern_detection, Elongated_bumps_in_several_orientations_from_a_vertex_list)
{
  const double radius = 0.04;
  std::vector<Planted> bumps = irregular_layout(20, 0.1, 0.9, 0.1, 0.9, 4.6 * radius, radius, 21);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> turn(0, CGAL_PI);
  for(Planted& b : bumps) {
    b.stretch = 2;
    b.angle = turn(rng);
  }
  Mesh m = bumpy_plane(141, 1.0 / 140, bumps, 0.5);
  add_noise(m, 0.03 / 140, 2);
  Truth truth;
  for(const Planted& b : bumps) {
    truth.centres.push_back(Point(b.x, b.y, 0.5 * radius));
    truth.radii.push_back(radius); // the short semi-axis: the strict reading of "the instance radius"
  }
  std::vector<Vertex> patch;
  for(Vertex v : m.vertices())
    if(bump_profile(bumps[0], m.point(v).x(), m.point(v).y()) > 0)
      patch.push_back(v);
  expect_found(m, CGAL_ext::Pattern_patch<Mesh>::of_vertices(patch), truth, 0.9);
}

TEST(Pattern_detection, Bumps_of_three_sizes_with_a_scale_range)
{
  const double radius = 0.05;
  std::vector<Planted> bumps = irregular_layout(22, 0.1, 0.9, 0.1, 0.9, 3.4 * radius, radius, 5);
  for(std::size_t i = 0; i < bumps.size(); ++i)
    bumps[i].radius = radius * (i % 3 == 0 ? 1.0 : i % 3 == 1 ? 0.75 : 1.4);
  Mesh m = bumpy_plane(141, 1.0 / 140, bumps, 0.4);
  add_noise(m, 0.03 / 140, 9);
  Truth truth;
  for(const Planted& b : bumps) {
    truth.centres.push_back(Point(b.x, b.y, 0.4 * b.radius));
    truth.radii.push_back(b.radius);
  }
  const Patterns found =
    expect_found(m, CGAL_ext::Pattern_patch<Mesh>::disk(nearest_vertex(m, truth.centres[0]), radius), truth, 0.9,
                 CGAL_ext::parameters::scale_range(std::make_pair(0.6, 1.6)));
  for(const auto& instance : found.instances) {
    std::size_t nearest = 0;
    for(std::size_t i = 1; i < truth.centres.size(); ++i)
      if(CGAL::squared_distance(instance.center, truth.centres[i]) <
         CGAL::squared_distance(instance.center, truth.centres[nearest]))
        nearest = i;
    EXPECT_NEAR(instance.scale, truth.radii[nearest] / radius, 0.2 * truth.radii[nearest] / radius);
  }
}
