// Exact farthest-point sampling: each sample is the exact argmax of the distance to the samples
// before it (checked against single-source solves), the covering radius never grows, every
// thread count gives the same samples, and the propagations are incremental.
#include "support/checks.h"
#include "support/mesh_transformations.h"
#include "support/solve.h"

#include <CGAL_ext/farthest_point_sampling.h>

#include <algorithm>
#include <iterator>
#include <vector>

namespace {

using namespace test_support;
using CGAL_ext::parameters::number_of_threads;

/// A sampling and everything it reports.
struct Sampling
{
  std::vector<Vertex> samples;
  std::vector<double> radii;
  std::vector<double> distances;
  std::vector<long> labels;
  CGAL_ext::Geodesic_statistics statistics;
};

template <class ConcurrencyTag = CGAL::Sequential_tag,
          class NamedParameters = CGAL_ext::parameters::Default_named_parameters_type>
Sampling sample(const Mesh& m, std::size_t n, const NamedParameters& np = CGAL_ext::parameters::default_values())
{
  Sampling s;
  auto distance = get(CGAL::dynamic_vertex_property_t<double>(), m);
  auto label = get(CGAL::dynamic_vertex_property_t<long>(), m);
  CGAL_ext::farthest_point_sampling<ConcurrencyTag>(m, n, std::back_inserter(s.samples),
                                                    np.covering_radius_output_iterator(std::back_inserter(s.radii))
                                                      .vertex_distance_map(distance)
                                                      .vertex_source_map(label)
                                                      .statistics(s.statistics));
  for(Vertex v : vertices(m)) {
    s.distances.push_back(get(distance, v));
    s.labels.push_back(get(label, v));
  }
  return s;
}

/// The index of the largest value (the lowest index of the largest).
std::size_t argmax(const std::vector<double>& d)
{
  std::size_t best = 0;
  for(std::size_t i = 1; i < d.size(); ++i)
    if(d[i] > d[best])
      best = i;
  return best;
}

/// Checks, by one single-source solve per sample, that each sample after the first `initial`
/// ones is the vertex farthest from the ones before it and each covering radius the largest
/// distance to the samples so far, never increasing (the initial samples': the one after all of
/// them); returns the distance to the nearest sample.
std::vector<double> expect_each_sample_farthest(const Mesh& m, const Sampling& s, const std::string& name,
                                                std::size_t initial = 1)
{
  const double tolerance = 1e-12 * bbox_diagonal(m);
  // +infinity (a component no sample reaches yet) only equals itself
  auto same_distance = [&](double a, double b) { return std::isinf(b) ? a == b : std::abs(a - b) <= tolerance; };
  std::vector<double> nearest(m.number_of_vertices(), inf);
  for(std::size_t k = 0; k < s.samples.size(); ++k) {
    if(k >= initial) {
      const double farthest = nearest[argmax(nearest)];
      EXPECT_PRED2(same_distance, nearest[s.samples[k].idx()], farthest) << name << ": sample " << k;
      EXPECT_LE(s.radii[k], s.radii[k - 1]) << name << ": sample " << k;
    }
    const std::vector<double> d = solve(m, s.samples[k]);
    for(std::size_t v = 0; v < nearest.size(); ++v)
      nearest[v] = std::min(nearest[v], d[v]);
    if(k + 1 >= initial)
      EXPECT_PRED2(same_distance, s.radii[k], nearest[argmax(nearest)]) << name << ": radius after sample " << k;
    else
      EXPECT_EQ(s.radii[k], s.radii[initial - 1]) << name << ": radius after initial sample " << k;
  }
  return nearest;
}

// Each sample is the farthest vertex from the samples before it, by single-source exact
// solves; the covering radius after each sample is the largest of those distances and never
// grows; the final distances and labels are those of the samples' multi-source solve.
TEST(Farthest_point_sampling, each_sample_is_the_exact_farthest_vertex)
{
  for(const char* name : {"elephant", "mushroom"}) {
    const Mesh& m = test_mesh(name);
    const double tolerance = 1e-12 * bbox_diagonal(m);
    const std::size_t n = 12;
    const Sampling s = sample(m, n);
    ASSERT_EQ(s.samples.size(), n) << name;
    ASSERT_EQ(s.radii.size(), n) << name;
    // the default first sample: the farthest vertex from vertex 0
    const std::vector<double> from_0 = solve(m, Vertex(0));
    EXPECT_NEAR(from_0[s.samples[0].idx()], from_0[argmax(from_0)], tolerance) << name;

    const std::vector<double> nearest = expect_each_sample_farthest(m, s, name);
    EXPECT_LE(max_difference(s.distances, nearest), tolerance) << name;
    EXPECT_LE(max_difference(s.distances, solve(m, s.samples)), tolerance) << name;
    for(std::size_t k = 0; k < n; ++k)
      EXPECT_EQ(s.labels[s.samples[k].idx()], long(k)) << name << ": the cell of sample " << k;
    for(std::size_t v = 0; v < nearest.size(); ++v) {
      ASSERT_TRUE(s.labels[v] >= 0 && std::size_t(s.labels[v]) < n) << name << ": vertex " << v;
      EXPECT_NEAR(solve(m, s.samples[std::size_t(s.labels[v])])[v], nearest[v], tolerance)
        << name << ": vertex " << v;
      if(v > 200) // one solve per vertex checked: the first 200 do
        break;
    }
  }
}

// Hundreds of samples: the runs push more stale entries than the heap that finds the next
// sample may keep (four times the mesh), so it is rebuilt along the way; every sample is still
// the exact farthest.
TEST(Farthest_point_sampling, many_samples_stay_exact)
{
  const Mesh& m = test_mesh("elephant");
  const Sampling s = sample(m, 300);
  ASSERT_EQ(s.samples.size(), 300u);
  expect_each_sample_farthest(m, s, "elephant");
}

// Meshes the package has never seen: the mushroom scaled by 1e-3 and 1e3, subdivided,
// jittered, cut open, and with a copy of the elephant as a second component: every sample is still the exact
// farthest, the first samples of the two components before any second one.
TEST(Farthest_point_sampling, exact_on_transformed_and_disconnected_meshes)
{
  const Mesh& mushroom = test_mesh("mushroom");
  for(Transform t : {SCALED_DOWN, SCALED_UP, LOOP_SUBDIVIDED, JITTERED, CUT_OPEN}) {
    const Mesh m = transformed(mushroom, t);
    const Sampling s = sample(m, 10);
    ASSERT_EQ(s.samples.size(), 10u) << transform_names[t];
    expect_each_sample_farthest(m, s, std::string("mushroom ") + transform_names[t]);
  }
  const Mesh both = disjoint_union({&mushroom, &test_mesh("elephant")});
  const Sampling s = sample(both, 10);
  ASSERT_EQ(s.samples.size(), 10u);
  EXPECT_EQ(s.radii[0], inf);
  EXPECT_TRUE(std::isfinite(s.radii[1]));
  const std::size_t first_part = mushroom.number_of_vertices();
  EXPECT_NE(s.samples[0].idx() < first_part, s.samples[1].idx() < first_part);
  expect_each_sample_farthest(both, s, "mushroom and elephant");
}

// PVTP gives the same samples, radii, distances and labels for every thread count, and the
// same samples as VTP; a first sample and a covering radius are honoured.
TEST(Farthest_point_sampling, thread_counts_first_sample_and_covering_radius)
{
  const Mesh& m = test_mesh("elephant");
  const Sampling sequential = sample(m, 10);
  const Sampling one = sample<CGAL::Parallel_tag>(m, 10, number_of_threads(1));
  EXPECT_EQ(one.samples, sequential.samples);
  EXPECT_LE(max_difference(one.distances, sequential.distances), 1e-12 * bbox_diagonal(m));
  for(int threads : {2, 4}) {
    const Sampling many = sample<CGAL::Parallel_tag>(m, 10, number_of_threads(threads));
    EXPECT_EQ(many.samples, one.samples) << threads << " threads";
    EXPECT_EQ(many.radii, one.radii) << threads << " threads";
    EXPECT_EQ(many.distances, one.distances) << threads << " threads";
    EXPECT_EQ(many.labels, one.labels) << threads << " threads";
  }

  const Sampling from_100 = sample(m, 3, CGAL_ext::parameters::first_sample(Vertex(100)));
  EXPECT_EQ(from_100.samples.front(), Vertex(100));
  const std::vector<double> d = solve(m, Vertex(100));
  EXPECT_EQ(from_100.samples[1], Vertex(argmax(d)));

  // stop at the radius reached after the 6th sample: 6 samples, the same ones
  const Sampling covered = sample(m, 100, CGAL_ext::parameters::covering_radius(sequential.radii[5]));
  EXPECT_EQ(covered.samples, std::vector<Vertex>(sequential.samples.begin(), sequential.samples.begin() + 6));
  EXPECT_EQ(covered.radii.back(), sequential.radii[5]);
}

// On two threads or more, several samples' runs go at once, each kept when it provably computes
// what it would after the ones before it: the samples, radii, distances and labels are still
// those of one thread, many runs are kept, and a count or a covering radius that ends inside a
// batch stops at the same sample.
TEST(Farthest_point_sampling, samples_run_in_batches_change_nothing)
{
  const Mesh& m = test_mesh("elephant");
  const Sampling one = sample<CGAL::Parallel_tag>(m, 200, number_of_threads(1));
  EXPECT_EQ(one.statistics.batched_runs_kept + one.statistics.batched_runs_undone, 0u);
  for(int threads : {2, 4}) {
    const Sampling many = sample<CGAL::Parallel_tag>(m, 200, number_of_threads(threads));
    EXPECT_EQ(many.samples, one.samples) << threads << " threads";
    EXPECT_EQ(many.radii, one.radii) << threads << " threads";
    EXPECT_EQ(many.distances, one.distances) << threads << " threads";
    EXPECT_EQ(many.labels, one.labels) << threads << " threads";
    EXPECT_GE(many.statistics.batched_runs_kept, 20u) << threads << " threads";
    EXPECT_LT(many.statistics.batched_runs_kept, many.samples.size()) << threads << " threads";
  }
  for(std::size_t count : {50, 51}) {
    const Sampling first = sample<CGAL::Parallel_tag>(m, count, number_of_threads(2));
    EXPECT_EQ(first.samples, std::vector<Vertex>(one.samples.begin(), one.samples.begin() + long(count)));
    EXPECT_EQ(first.radii, std::vector<double>(one.radii.begin(), one.radii.begin() + long(count)));
    const Sampling covered =
      sample<CGAL::Parallel_tag>(m, 200, number_of_threads(2).covering_radius(one.radii[count - 1]));
    ASSERT_FALSE(covered.radii.empty());
    EXPECT_LE(covered.radii.back(), one.radii[count - 1]);
    EXPECT_EQ(covered.samples.size(),
              std::size_t(std::find_if(one.radii.begin(), one.radii.end(),
                                       [&](double r) { return r <= one.radii[count - 1]; }) -
                          one.radii.begin()) + 1);
  }
}

// Incremental: each new sample's propagation sweeps only its own cell. Solving every sample over
// the whole mesh would make 40 full solves' windows; the samples make a few, and the last ten,
// whose cells are small, make a small part of a full solve each.
TEST(Farthest_point_sampling, later_samples_sweep_only_their_cells)
{
  const Mesh& m = test_mesh("elephant");
  CGAL_ext::Geodesic_statistics full;
  auto unused = get(CGAL::dynamic_vertex_property_t<double>(), m);
  CGAL_ext::geodesic_distances(m, unused, Vertex(0), CGAL_ext::parameters::statistics(full));
  const std::size_t thirty = sample(m, 30).statistics.windows_created;
  const std::size_t forty = sample(m, 40).statistics.windows_created;
  EXPECT_LT(forty, 40 * full.windows_created / 5)
    << "40 samples made " << forty << " windows, one full solve " << full.windows_created;
  EXPECT_LT((forty - thirty) / 10, full.windows_created / 10)
    << "samples 31 to 40 made " << forty - thirty << " windows, one full solve " << full.windows_created;
}

// Initial samples are taken as given, in order, from one propagation; the samples after them
// are the exact farthest ones; the distances and labels are the multi-source solve's; PVTP gives
// the same for every thread count.
TEST(Farthest_point_sampling, initial_samples_then_farthest_points)
{
  const Mesh& m = test_mesh("elephant");
  const std::vector<Vertex> initial{Vertex(900), Vertex(100), Vertex(2000)};
  const std::size_t n = 10;
  const Sampling s = sample(m, n, CGAL_ext::parameters::initial_samples(initial));
  ASSERT_EQ(s.samples.size(), n);
  EXPECT_EQ(std::vector<Vertex>(s.samples.begin(), s.samples.begin() + 3), initial);
  const std::vector<double> nearest = expect_each_sample_farthest(m, s, "elephant", initial.size());
  const double tolerance = 1e-12 * bbox_diagonal(m);
  EXPECT_LE(max_difference(s.distances, nearest), tolerance);
  EXPECT_LE(max_difference(s.distances, solve(m, s.samples)), tolerance);
  for(std::size_t k = 0; k < n; ++k)
    EXPECT_EQ(s.labels[s.samples[k].idx()], long(k)) << "the cell of sample " << k;
  // one propagation for the three: fewer windows than three single-source ones
  const Sampling first_three = sample(m, 3, CGAL_ext::parameters::initial_samples(initial));
  EXPECT_EQ(first_three.samples, initial);
  std::size_t single = 0;
  for(Vertex v : initial)
    single += sample(m, 1, CGAL_ext::parameters::first_sample(v)).statistics.windows_created;
  EXPECT_LT(first_three.statistics.windows_created, single);

  const Sampling one = sample<CGAL::Parallel_tag>(m, 60, number_of_threads(1).initial_samples(initial));
  for(int threads : {2, 4}) {
    const Sampling many = sample<CGAL::Parallel_tag>(m, 60, number_of_threads(threads).initial_samples(initial));
    EXPECT_EQ(many.samples, one.samples) << threads << " threads";
    EXPECT_EQ(many.radii, one.radii) << threads << " threads";
    EXPECT_EQ(many.distances, one.distances) << threads << " threads";
    EXPECT_EQ(many.labels, one.labels) << threads << " threads";
  }
  // VTP's distances equal PVTP's to round-off: the first samples, before near ties
  const Sampling sequential = sample(m, 10, CGAL_ext::parameters::initial_samples(initial));
  EXPECT_EQ(std::vector<Vertex>(one.samples.begin(), one.samples.begin() + 10), sequential.samples);
}

// Several components each get a sample before any gets a second; a vertex in no face is a
// component of its own.
TEST(Farthest_point_sampling, every_component_is_sampled_first)
{
  // two unit squares far apart, and an isolated point
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  for(int c = 0; c < 2; ++c) {
    const int o = int(points.size());
    for(int j = 0; j <= 4; ++j)
      for(int i = 0; i <= 4; ++i)
        points.push_back(Point(i * 0.25 + 10 * c, j * 0.25, 0));
    for(int j = 0; j < 4; ++j)
      for(int i = 0; i < 4; ++i)
        add_quad(triangles, o + j * 5 + i, o + j * 5 + i + 1, o + (j + 1) * 5 + i + 1, o + (j + 1) * 5 + i, true);
  }
  Mesh m = mesh_from_soup(points, triangles);
  const Vertex isolated = m.add_vertex(Point(5, 5, 5));
  const Sampling s = sample(m, 4, CGAL_ext::parameters::first_sample(Vertex(0)));
  ASSERT_EQ(s.samples.size(), 4u);
  EXPECT_EQ(s.radii[0], inf);
  EXPECT_EQ(s.radii[1], inf);
  EXPECT_TRUE(std::isfinite(s.radii[2]));
  // the second and third samples: the first vertex of the other square, and the isolated one
  EXPECT_EQ(s.samples[1], Vertex(25));
  EXPECT_EQ(s.samples[2], isolated);
  EXPECT_EQ(s.distances[isolated.idx()], 0.);
  EXPECT_EQ(s.labels[isolated.idx()], 2);
  // the fourth: the corner of the first square opposite vertex 0
  EXPECT_EQ(s.samples[3], Vertex(24));
  EXPECT_NEAR(s.radii[3], std::sqrt(2.), 1e-12);

  // initial samples, the isolated vertex first, then two corners of the first square run
  // together from label 1 on: each its own label, the other square sampled next
  const Sampling from = sample(m, 4, CGAL_ext::parameters::initial_samples(std::vector<Vertex>{isolated, Vertex(0), Vertex(24)}));
  ASSERT_EQ(from.samples.size(), 4u);
  EXPECT_EQ(from.samples[3], Vertex(25));
  EXPECT_EQ(from.radii[0], inf);
  EXPECT_EQ(from.radii[2], inf);
  EXPECT_EQ(from.labels[isolated.idx()], 0);
  EXPECT_EQ(from.labels[0], 1);
  EXPECT_EQ(from.labels[24], 2);
  EXPECT_EQ(from.labels[1], 1);  // (0.25, 0), nearer vertex 0
  EXPECT_EQ(from.labels[23], 2); // (0.75, 1), nearer vertex 24
  EXPECT_NEAR(from.distances[12], std::sqrt(0.5), 1e-12); // the centre, as far from both corners
}

TEST(Farthest_point_sampling, bad_requests_are_named)
{
  const Mesh& m = test_mesh("elephant");
  std::vector<Vertex> out;
  auto fps = [&](std::size_t n, const auto& np) {
    return [&m, &out, n, np] { CGAL_ext::farthest_point_sampling(m, n, std::back_inserter(out), np); };
  };
  const auto none = CGAL_ext::parameters::default_values();
  EXPECT_TRUE(throws_geodesic_error(fps(0, none), {"at least 1"}));
  EXPECT_TRUE(throws_geodesic_error(fps(2776, none), {"2776 samples", "2775 vertices"}));
  EXPECT_TRUE(throws_geodesic_error(fps(3, CGAL_ext::parameters::covering_radius(0.)), {"covering radius", "positive"}));
  EXPECT_TRUE(throws_geodesic_error(fps(3, CGAL_ext::parameters::covering_radius(-1.)), {"covering radius"}));
  EXPECT_TRUE(throws_geodesic_error(fps(3, CGAL_ext::parameters::first_sample(Vertex(5000))),
                                    {"first sample vertex 5000", "out of range"}));
  EXPECT_TRUE(throws_geodesic_error(fps(3, CGAL_ext::parameters::max_distance(1.)), {"max_distance"}));
  using V = std::vector<Vertex>;
  EXPECT_TRUE(throws_geodesic_error(fps(3, CGAL_ext::parameters::initial_samples(V{})), {"initial_samples", "empty"}));
  EXPECT_TRUE(throws_geodesic_error(fps(3, CGAL_ext::parameters::initial_samples(V{Vertex(1), Vertex(5000)})),
                                    {"initial sample vertex 5000", "out of range"}));
  EXPECT_TRUE(throws_geodesic_error(fps(3, CGAL_ext::parameters::initial_samples(V{Vertex(7), Vertex(1), Vertex(7)})),
                                    {"initial sample 7", "twice"}));
  EXPECT_TRUE(throws_geodesic_error(fps(2, CGAL_ext::parameters::initial_samples(V{Vertex(1), Vertex(2), Vertex(3)})),
                                    {"3 initial samples", "2 samples"}));
  EXPECT_TRUE(throws_geodesic_error(
    fps(3, CGAL_ext::parameters::initial_samples(V{Vertex(1)}).first_sample(Vertex(2))), {"initial_samples", "first_sample"}));
  EXPECT_TRUE(throws_geodesic_error(fps(3, CGAL_ext::parameters::algorithm(CGAL_ext::MMP)), {"VTP"}));

  // 5 vertices but 4 distinct points (vertex 4 is vertex 2, by a zero-length edge)
  const Mesh needle = mesh_from_soup(
    {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0), Point(1, 1, 0)}, {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}});
  std::vector<Vertex> four;
  EXPECT_TRUE(throws_geodesic_error(
    [&] {
      CGAL_ext::farthest_point_sampling(needle, 3, std::back_inserter(four),
                                        CGAL_ext::parameters::initial_samples(std::vector<Vertex>{Vertex(2), Vertex(4)}));
    },
    {"initial samples 2 and 4", "one point"}));
  four.clear();
  CGAL_ext::farthest_point_sampling(needle, 4, std::back_inserter(four));
  EXPECT_EQ(four.size(), 4u);
  EXPECT_TRUE(throws_geodesic_error(
    [&] { CGAL_ext::farthest_point_sampling(needle, 5, std::back_inserter(four)); },
    {"5 samples", "after 4", "distance 0"}));
}

} // namespace
