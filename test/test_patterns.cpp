// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Repetitive pattern detection (thesis chapter 5): each step on its own, then the whole pipeline
// on meshes with planted instances, scored by recall and precision.

#include "support/mesh_transformations.h"
#include "support/pattern_meshes.h"

#include <CGAL_ext/detect_repetitive_patterns.h>
#include <CGAL_ext/geodesic_distance_matrix.h>

#include <CGAL/Eigen_svd.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <random>
#include <set>
#include <string>
#include <vector>

using namespace test_support;
namespace internal = CGAL_ext::Geodesics_3::internal;

namespace {

typedef CGAL_ext::Repetitive_patterns<Mesh, Point> Patterns;

/// Runs the detection on `scene` and checks recall and precision, and that each instance's
/// correspondence keeps the distances from the centre (the patch's centre maps to the
/// instance's, its other samples around it at their distances, times the scale), on average to
/// 0.6 patch radii: images are samples, placed up to a spacing from where a patch sample maps,
/// and the correspondence of some instances is only that good (a random one is off by about a
/// radius).
/// `lambda`: approximate local rows (0: exact).
Patterns expect_found(const Pattern_scene& scene, double at_least, double lambda = 0)
{
  const Mesh& m = scene.mesh;
  const auto patch = scene.patch_radius > 0 ? CGAL_ext::Pattern_patch<Mesh>::disk(scene.patch_centre, scene.patch_radius)
                                            : CGAL_ext::Pattern_patch<Mesh>::of_vertices(scene.patch_vertices);
  const auto np = CGAL_ext::parameters::scale_range(scene.scales).approximation(lambda);
  const Patterns found =
    scene.stroke.empty()
      ? CGAL_ext::detect_repetitive_patterns<CGAL::Parallel_if_available_tag>(m, patch, np)
      : CGAL_ext::detect_repetitive_patterns<CGAL::Parallel_if_available_tag>(m, patch, np.stroke(scene.stroke));
  const Score s = score(found.instances, scene.truth);
  const auto& st = found.statistics;
  std::cout << s << "; " << m.number_of_vertices() << " vertices, " << st.samples << " samples ("
            << st.patch_samples << " in the patch), " << st.matches << " matches, " << st.clusters << " clusters, "
            << st.searches << " searches\n";
  EXPECT_GE(s.recall, at_least) << s;
  EXPECT_GE(s.precision, at_least) << s;
  EXPECT_FALSE(found.instances.empty());
  const auto& marked = found.instances.front();
  std::vector<int> instance_of(m.number_of_vertices(), -1); // no vertex in two instances
  for(std::size_t a = 0; a < found.instances.size(); ++a)
    for(Vertex v : found.instances[a].vertices) {
      EXPECT_EQ(instance_of[v.idx()], -1) << "vertex " << v << " in instances " << instance_of[v.idx()] << " and " << a;
      instance_of[v.idx()] = int(a);
    }
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

/// Ten round bumps on a coarse plane (6,561 vertices), the first marked: a quick whole run.
struct Small_scene
{
  Mesh mesh;
  CGAL_ext::Pattern_patch<Mesh> patch;
};

Small_scene ten_bumps()
{
  const double radius = 0.06;
  const std::vector<Planted> bumps = irregular_layout(10, 0.1, 0.9, 0.1, 0.9, 2.6 * radius, radius, 6);
  Small_scene scene;
  scene.mesh = bumpy_plane(81, 1.0 / 80, bumps, 0.4);
  scene.patch =
    CGAL_ext::Pattern_patch<Mesh>::disk(nearest_vertex(scene.mesh, Point(bumps[0].x, bumps[0].y, 0.024)), radius);
  return scene;
}

/// Each instance's scale is its nearest planted instance's size over the patch's, to `relative`.
void expect_scales(const Patterns& found, const Pattern_scene& scene, double relative)
{
  for(const auto& instance : found.instances) {
    const std::size_t nearest = scene.truth.nearest(instance.center);
    const double size = scene.truth.radii[nearest] / scene.patch_radius;
    EXPECT_NEAR(instance.scale, size, relative * size);
  }
}

} // namespace

TEST(Pattern_detection, Round_bumps_on_a_plane_laid_out_irregularly_with_noise)
{
  const Patterns found = expect_found(round_bumps_on_a_plane(121, 24, 0.06, 3, 0.05), 0.95);
  // the arrangement: a planar graph among the instances
  EXPECT_GE(found.arrangement_edges.size(), found.instances.size() - 1);
  EXPECT_LE(found.arrangement_edges.size(), 3 * found.instances.size());
}

TEST(Pattern_detection, Golf_ball_dimples)
{
  expect_found(dimples_on_a_sphere(32, 40, 0.24, 0.001), 0.95);
}

// lambda 4: the rows of this coarse ball (a patch radius of about 6 mean edges) are reset on the
// way, and the patch, the samples and the matches differ from the exact run's
TEST(Pattern_detection, Golf_ball_dimples_with_approximate_rows)
{
  expect_found(dimples_on_a_sphere(32, 40, 0.24, 0.001), 0.95, 4);
}

TEST(Pattern_detection, Bumps_around_a_cylinder)
{
  const Patterns found = expect_found(bumps_around_a_cylinder(128, 110, 30, 0.35, 8), 0.95);
  // Much of a cylinder looks like a bump's centre: the look-alikes near a seed that found
  // nothing are not searched from again (73 searches for the 27 instances; 607 without that).
  EXPECT_LE(found.statistics.searches, 3 * found.instances.size());
}

// Scored against the short semi-axis (the strict reading of "the instance radius"): 17 of the
// 18 instances found lie within a quarter of it of a planted one (0.944): the goal is 0.9.
TEST(Pattern_detection, Elongated_bumps_in_several_orientations_from_a_vertex_list)
{
  expect_found(elongated_bumps_on_a_plane(141, 20, 0.04, 21, 0.03), 0.9);
}

TEST(Pattern_detection, Bumps_of_three_sizes_with_a_scale_range)
{
  const Pattern_scene scene = bumps_of_three_sizes_on_a_plane(141, 22, 0.05, 5, 0.03);
  expect_scales(expect_found(scene, 0.9), scene, 0.2);
}

// Adaptive patterns with a stroke (thesis 5.3.3): bumps growing from left to right, the stroke
// from the marked (smallest) one to the right border restricts each sample's scale.
TEST(Pattern_detection, Growing_bumps_with_a_stroke)
{
  const Pattern_scene scene = growing_bumps_on_a_plane(141, 16, 0.04, 12, 0.03);
  expect_scales(expect_found(scene, 0.9), scene, 0.25);
}

// ---------------------------------------------------------------------------------------------
// The steps on their own

TEST(Pattern_steps, Mean_shift_finds_known_clusters)
{
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0, 0.05);
  const std::array<std::array<double, 3>, 3> centres = {{{0, 0, 0}, {3, 0, 0}, {0, 3, 1}}};
  std::vector<std::array<double, 3>> points;
  std::vector<std::size_t> group;
  for(std::size_t c = 0; c < centres.size(); ++c)
    for(int i = 0; i < 10; ++i) {
      points.push_back({centres[c][0] + noise(rng), centres[c][1] + noise(rng), centres[c][2] + noise(rng)});
      group.push_back(c);
    }
  const auto clusters = internal::weighted_mean_shift(points, std::vector<double>(points.size(), 1.0), 10);
  ASSERT_EQ(clusters.size(), 3u);
  for(const auto& cluster : clusters) {
    ASSERT_EQ(cluster.size(), 10u);
    for(std::size_t i : cluster)
      EXPECT_EQ(group[i], group[cluster.front()]);
  }
}

TEST(Pattern_steps, Embedding_separates_two_planted_consistent_groups)
{
  // a patch of `size` samples in the plane; two copies of it moved (and one turned) far apart,
  // plus matches to random samples: the clusters are the two copies. 8 samples make 24 matches
  // (the dense eigensolver), 24 make 72 (Lanczos).
  for(const std::size_t size : {8, 24}) {
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(0, 1);
    std::vector<Point_2> patch, mesh;
    for(std::size_t i = 0; i < size; ++i)
      patch.push_back(Point_2(u(rng), u(rng)));
    const auto place = [&](double dx, double dy, double turn) {
      for(const Point_2& p : patch)
        mesh.push_back(Point_2(dx + std::cos(turn) * p.x() - std::sin(turn) * p.y(),
                               dy + std::sin(turn) * p.x() + std::cos(turn) * p.y()));
    };
    place(5, 0, 0);
    place(0, 5, 1.0);
    for(std::size_t i = 0; i < 2 * size; ++i)
      mesh.push_back(Point_2(10 * u(rng), 10 * u(rng)));
    std::vector<internal::Pattern_match> matches;
    for(std::size_t i = 0; i < size; ++i) {
      matches.push_back({i, i, 1.0, 0.0});
      matches.push_back({i, size + i, 1.0, 0.0});
      matches.push_back({i, 2 * size + 2 * i, 1.0, 0.0});
    }
    ASSERT_EQ(matches.size() > std::size_t(internal::embedding_dense_limit), size == 24);
    const auto distance = [](const std::vector<Point_2>& points) {
      return [&points](std::size_t a, std::size_t b) { return std::sqrt(CGAL::squared_distance(points[a], points[b])); };
    };
    const auto clusters = internal::cluster_matches(matches, distance(patch), distance(mesh), 0.7, 0.0, size);
    std::size_t pure = 0;
    for(const auto& cluster : clusters) {
      std::set<std::size_t> copies;
      for(std::size_t m : cluster)
        copies.insert(matches[m].sample < size ? 0 : matches[m].sample < 2 * size ? 1 : 2);
      if(copies.size() == 1 && *copies.begin() < 2 && cluster.size() == size)
        ++pure;
    }
    EXPECT_EQ(pure, 2u) << clusters.size() << " clusters, patch of " << size;
  }
}

// Lanczos (above the dense limit) gives the dense solver's embedding: three blocks of random
// positive weights, of different sizes, so that the three leading eigenvalues are apart.
TEST(Pattern_steps, Embedding_by_Lanczos_equals_the_dense_one)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0.5, 1);
  std::vector<Eigen::Triplet<double>> entries;
  const int sizes[] = {70, 50, 30};
  int first = 0;
  for(int size : sizes) {
    for(int a = first; a < first + size; ++a)
      for(int b = first; b < a; ++b)
        if(u(rng) < 0.8) {
          const double x = u(rng);
          entries.emplace_back(a, b, x);
          entries.emplace_back(b, a, x);
        }
    first += size;
  }
  Eigen::SparseMatrix<double> w(first, first);
  w.setFromTriplets(entries.begin(), entries.end());
  const auto dense = internal::spectral_embedding(w, first);
  const auto lanczos = internal::spectral_embedding(w, 0);
  ASSERT_EQ(dense.size(), lanczos.size());
  double largest = 0, difference = 0;
  for(std::size_t r = 0; r < dense.size(); ++r)
    for(std::size_t c = 0; c < 3; ++c) {
      largest = std::max(largest, std::abs(dense[r][c]));
      difference = std::max(difference, std::abs(dense[r][c] - lanczos[r][c]));
    }
  EXPECT_GT(largest, 0.1);
  EXPECT_LT(difference, 1e-8 * largest);
}

TEST(Pattern_steps, Curvatures_solved_by_QR_agree_with_CGALs_SVD_and_a_cylinder)
{
  // a noisy bump on a plane: flat, convex, concave and saddle points, and round-off in the rings
  Planted b;
  b.x = b.y = 0.5;
  b.radius = 0.2;
  Mesh m = bumpy_plane(41, 1.0 / 40, {b}, 0.4);
  add_noise(m, 0.002, 7);
  const auto vpm = get(CGAL::vertex_point, m);
  const auto vim = get(CGAL::vertex_index, m);
  const auto ours = internal::vertex_principal_curvatures(m, vpm, vim, false);
  const auto svd =
    internal::vertex_principal_curvatures<Mesh, decltype(vpm), decltype(vim), CGAL::Eigen_svd>(m, vpm, vim, false);
  double largest = 0, worst = 0;
  for(std::size_t i = 0; i < svd.size(); ++i) {
    largest = std::max({largest, std::abs(svd[i].k_max), std::abs(svd[i].k_min)});
    worst = std::max({worst, std::abs(ours[i].k_max - svd[i].k_max), std::abs(ours[i].k_min - svd[i].k_min)});
  }
  EXPECT_GT(largest, 1.0);
  EXPECT_LT(worst, 1e-9 * largest);

  // a cylinder of radius 1: curvatures 1 around it and 0 along it, away from its open ends (the
  // fit of a degree-2 jet to a polyhedral ring is off by O(h^2): 96 segments keep that small)
  const Mesh tube = make_cylinder(1.0, 96, 2.0, 48);
  const auto k = internal::vertex_principal_curvatures(tube, get(CGAL::vertex_point, tube),
                                                       get(CGAL::vertex_index, tube), false);
  std::size_t checked = 0;
  for(Vertex v : tube.vertices()) {
    const double z = tube.point(v).z();
    if(z < 0.5 || z > 1.5)
      continue;
    const auto& c = k[std::size_t(v)];
    EXPECT_NEAR(std::max(std::abs(c.k_max), std::abs(c.k_min)), 1.0, 0.02);
    EXPECT_LT(std::min(std::abs(c.k_max), std::abs(c.k_min)), 0.02);
    ++checked;
  }
  EXPECT_GT(checked, 400u);
}

TEST(Pattern_steps, Signatures_are_equal_on_congruent_patches)
{
  // two bumps at grid points whose neighbourhoods the grid repeats exactly (a translation by an
  // even number of cells keeps the diagonals)
  const double h = 1.0 / 80;
  Planted a, b;
  a.x = 20 * h, a.y = 20 * h, b.x = 56 * h, b.y = 50 * h;
  a.radius = b.radius = 0.1;
  const Mesh m = bumpy_plane(81, h, {a, b}, 0.4);
  const auto vpm = get(CGAL::vertex_point, m);
  const auto vim = get(CGAL::vertex_index, m);
  const auto curvature = internal::vertex_principal_curvatures(m, vpm, vim, false);
  const auto area = internal::vertex_areas(m, vpm, vim);
  const std::vector<Vertex> centres = {nearest_vertex(m, Point(a.x, a.y, 0.04)), nearest_vertex(m, Point(b.x, b.y, 0.04))};
  std::vector<std::vector<double>> signatures;
  CGAL_ext::geodesic_sparse_distance_rows(
    m, centres,
    [&](std::size_t, const std::vector<std::pair<std::size_t, double>>& row) {
      internal::Ring_sums sums(48, 0.1 / 48);
      for(const auto& [v, d] : row)
        sums.add(d, area[v], curvature[v]);
      signatures.push_back(sums.signature(0.1, 6));
    },
    CGAL_ext::parameters::max_distance(0.1));
  ASSERT_EQ(signatures.size(), 2u);
  EXPECT_GT(internal::signature_distance(signatures[0], std::vector<double>(24, 0.0)), 0.1);
  EXPECT_LT(internal::signature_distance(signatures[0], signatures[1]), 1e-9);
  // a smaller disk is a prefix of the same sums: its signature differs from the larger one's
  internal::Ring_sums sums(48, 0.1 / 48);
  EXPECT_EQ(sums.signature(0.05, 6).size(), 24u);
}

// ---------------------------------------------------------------------------------------------
// Bad input

namespace {
Mesh one_bump_plane()
{
  Planted b;
  b.x = b.y = 0.5;
  b.radius = 0.1;
  return bumpy_plane(61, 1.0 / 60, {b}, 0.4);
}
} // namespace

TEST(Pattern_bad_input, Refused_with_a_message_naming_what)
{
  const Mesh m = one_bump_plane();
  const Vertex centre = nearest_vertex(m, Point(0.5, 0.5, 0.04));
  typedef CGAL_ext::Pattern_patch<Mesh> Patch;
  const auto refuses = [&](const Patch& patch, const std::string& needle, auto np) {
    try {
      CGAL_ext::detect_repetitive_patterns(m, patch, np);
      ADD_FAILURE() << "no error, expected one about " << needle;
    } catch(const CGAL_ext::Geodesic_error& e) {
      EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    }
  };
  const auto none = CGAL_ext::parameters::default_values();
  refuses(Patch::disk(centre, 0), "radius must be positive", none);
  refuses(Patch::disk(centre, -1), "radius must be positive", none);
  refuses(Patch::disk(centre, 10), "larger than the mesh", none);
  refuses(Patch::disk(Vertex(100000), 0.1), "not a vertex", none);
  refuses(Patch::disk(centre, 0.004), "too few to match", none);
  refuses(Patch::disk(nearest_vertex(m, Point(0.1, 0.1, 0)), 0.05), "flat", none);
  refuses(Patch::of_vertices(std::vector<Vertex>{Vertex(0), Vertex(3000)}), "not connected", none);
  refuses(Patch::of_vertices(std::vector<Vertex>{Vertex(0), Vertex(100000)}), "out of range", none);
  refuses(Patch::of_vertices(std::vector<Vertex>{}), "no vertex", none);
  refuses(Patch::disk(centre, 0.1), "empty scale range", CGAL_ext::parameters::scale_range(std::make_pair(2.0, 1.0)));
  refuses(Patch::disk(centre, 0.1), "consistency_cutoff", CGAL_ext::parameters::consistency_cutoff(1.0));
  refuses(Patch::disk(centre, 0.1), "sample_spacing", CGAL_ext::parameters::sample_spacing(0.0));
  refuses(Patch::disk(centre, 0.1), "approximation", CGAL_ext::parameters::approximation(-1.0));
  refuses(Patch::disk(centre, 0.1), "stroke needs at least 2 vertices",
          CGAL_ext::parameters::stroke(std::vector<Vertex>{centre}));
  refuses(Patch::disk(centre, 0.1), "start in the marked instance",
          CGAL_ext::parameters::stroke(std::vector<Vertex>{Vertex(0), centre}));
  refuses(Patch::disk(centre, 0.1), "stroke vertex 100000 is out of range",
          CGAL_ext::parameters::stroke(std::vector<Vertex>{centre, Vertex(100000)}));
}

TEST(Pattern_bad_input, A_mesh_with_no_other_instance_gives_just_the_patch)
{
  const Mesh m = one_bump_plane();
  const auto found = CGAL_ext::detect_repetitive_patterns(
    m, CGAL_ext::Pattern_patch<Mesh>::disk(nearest_vertex(m, Point(0.5, 0.5, 0.04)), 0.1));
  ASSERT_EQ(found.instances.size(), 1u);
  EXPECT_EQ(found.instances[0].scale, 1.0);
  EXPECT_TRUE(found.arrangement_edges.empty());
  EXPECT_GT(found.instances[0].vertices.size(), 50u);
}

TEST(Pattern_detection, Same_instances_for_1_2_and_4_threads)
{
  const Small_scene scene = ten_bumps();
  const Mesh& m = scene.mesh;
  const auto& patch = scene.patch;
  std::vector<std::vector<Vertex>> centres;
  for(int threads : {1, 2, 4}) {
    const auto found = CGAL_ext::detect_repetitive_patterns<CGAL::Parallel_if_available_tag>(
      m, patch, CGAL_ext::parameters::number_of_threads(threads));
    centres.emplace_back();
    for(const auto& instance : found.instances)
      centres.back().push_back(instance.center_vertex);
  }
  EXPECT_GE(centres[0].size(), 9u);
  EXPECT_EQ(centres[0], centres[1]);
  EXPECT_EQ(centres[0], centres[2]);
}

// The constants of the pipeline are relative to the patch and the mesh. Scaled by a power of
// two (every length then exactly scaled, round-off included), the scene gives the same
// instances at the same vertices. Scaled by 1e-3 and by 1e3, round-off differs, and the
// centres' descent may end at a neighbour of the vertex it found at scale 1 (a signature sums
// vertices by bands of distance: a vertex on a band's edge moves with the last bit): the same
// number of instances, each within two edge lengths of one found at scale 1.
TEST(Pattern_detection, Same_instances_at_any_scale)
{
  const Small_scene scene = ten_bumps();
  auto centres_of = [](const Mesh& m, const CGAL_ext::Pattern_patch<Mesh>& patch) {
    std::vector<Vertex> centres;
    for(const auto& instance : CGAL_ext::detect_repetitive_patterns<CGAL::Parallel_if_available_tag>(m, patch).instances)
      centres.push_back(instance.center_vertex);
    return centres;
  };
  const std::vector<Vertex> at_one = centres_of(scene.mesh, scene.patch);
  ASSERT_GE(at_one.size(), 9u);
  Truth found_at_one;
  for(Vertex a : at_one)
    found_at_one.centres.push_back(scene.mesh.point(a));
  const double edge = mean_edge_length(scene.mesh);
  for(double factor : {0.125, 2.0, 1e-3, 1e3}) {
    const auto patch = CGAL_ext::Pattern_patch<Mesh>::disk(scene.patch.center, factor * scene.patch.radius);
    const std::vector<Vertex> centres = centres_of(scaled(scene.mesh, factor), patch);
    if(factor == 0.125 || factor == 2.0) {
      EXPECT_EQ(centres, at_one) << "scaled by " << factor;
      continue;
    }
    ASSERT_EQ(centres.size(), at_one.size()) << "scaled by " << factor;
    for(Vertex c : centres)
      EXPECT_LE(found_at_one.distance_to_nearest(scene.mesh.point(c)), 2 * edge)
        << "scaled by " << factor << ": the instance at " << c;
  }
}

// Two copies of the scene side by side, not connected, the patch marked in the first: the
// second copy's instances are found too (region growing cannot cross to it; the seeds reach
// it), each where the first copy has one (the translation rounds coordinates: within two edge
// lengths, and one instance more or less).
TEST(Pattern_detection, Instances_in_another_component_are_found)
{
  const Small_scene scene = ten_bumps();
  const Vector shift(2, 0, 0);
  const Mesh copy = translated(scene.mesh, shift);
  const Mesh both = disjoint_union({&scene.mesh, &copy});
  const auto found = CGAL_ext::detect_repetitive_patterns<CGAL::Parallel_if_available_tag>(both, scene.patch);
  Truth first; // the instances found in the first copy
  std::vector<Point> second;
  for(const auto& instance : found.instances)
    (instance.center_vertex.idx() < scene.mesh.number_of_vertices() ? first.centres : second)
      .push_back(both.point(instance.center_vertex));
  ASSERT_GE(first.centres.size(), 9u);
  EXPECT_GE(second.size() + 1, first.centres.size());
  EXPECT_LE(second.size(), first.centres.size() + 1);
  const double edge = mean_edge_length(scene.mesh);
  for(const Point& c : second)
    EXPECT_LE(first.distance_to_nearest(c - shift), 2 * edge) << "the instance at " << c;
}

// The callback hears the fraction done, never decreasing, from the start to 1, a few times a
// second at most; its false stops the run with Geodesic_cancelled.
TEST(Pattern_detection, Progress_reaches_the_callback_which_can_stop_the_run)
{
  const Small_scene scene = ten_bumps();
  const Mesh& m = scene.mesh;
  const auto& patch = scene.patch;
  std::vector<double> heard;
  const std::function<bool(double)> listen = [&](double done) {
    heard.push_back(done);
    return true;
  };
  const auto start = std::chrono::steady_clock::now();
  const auto found = CGAL_ext::detect_repetitive_patterns(m, patch, CGAL_ext::parameters::callback(listen));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(found.instances.size(), 9u);
  ASSERT_GE(heard.size(), 2u);
  EXPECT_TRUE(std::is_sorted(heard.begin(), heard.end()));
  EXPECT_EQ(heard.front(), 0.0);
  EXPECT_EQ(heard.back(), 1.0);
  // one at the start, one at the end, at most one in each tenth of a second between
  EXPECT_LE(double(heard.size()), 2 + 10 * seconds + 1) << seconds << " s";

  std::size_t calls = 0;
  const std::function<bool(double)> stop = [&](double) {
    ++calls;
    return false;
  };
  try {
    CGAL_ext::detect_repetitive_patterns(m, patch, CGAL_ext::parameters::callback(stop));
    ADD_FAILURE() << "the run went on after the callback said stop";
  } catch(const CGAL_ext::Geodesic_cancelled& e) {
    EXPECT_NE(std::string(e.what()).find("cancelled"), std::string::npos) << e.what();
  }
  EXPECT_EQ(calls, 1u);
}

// Real meshes of CGAL's data set (no planted instances): the pipeline runs through, the marked
// patch comes first, every instance is a vertex of the mesh with members and a correspondence.
TEST(Pattern_detection, Runs_on_real_meshes)
{
  for(const std::string name : {"elephant", "knot1", "fandisk"}) {
    const Mesh& m = test_mesh(name);
    const Vertex centre = spread_vertices(m, 3)[1];
    const auto found = CGAL_ext::detect_repetitive_patterns<CGAL::Parallel_if_available_tag>(
      m, CGAL_ext::Pattern_patch<Mesh>::disk(centre, 0.04 * bbox_diagonal(m)));
    ASSERT_FALSE(found.instances.empty()) << name;
    EXPECT_EQ(found.instances.front().center_vertex, centre) << name;
    for(const auto& instance : found.instances) {
      EXPECT_TRUE(m.is_valid(instance.center_vertex)) << name;
      EXPECT_FALSE(instance.vertices.empty()) << name;
      EXPECT_FALSE(instance.correspondence.empty()) << name;
    }
    std::cout << name << ": " << found.instances.size() << " instances, " << found.statistics.samples << " samples\n";
  }
}
