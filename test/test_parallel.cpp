// Parallel (PVTP) and approximate (AVTP, PAVTP) propagation: the same distances for every
// thread count and batch size, exactness of PVTP, the limits and bounds of the approximation;
// nearest-source labels from every exact solver; distance matrices, solved in parallel across
// sources.
// This file is also built under ThreadSanitizer (test_parallel_tsan).
#include "support/checks.h"
#include "support/path_checks.h"
#include "support/solve.h"

#include <CGAL_ext/Geodesics_3/internal/support/Parallel_for.h>
#include <CGAL_ext/Surface_mesh_geodesic_paths.h>
#include <CGAL_ext/farthest_point_sampling.h>
#include <CGAL_ext/geodesic_distance_matrix.h>
#include <CGAL_ext/geodesic_voronoi_diagram.h>

#include <tbb/task_arena.h>

#include <atomic>
#include <chrono>
#include <numeric>
#include <random>
#include <stdexcept>
#include <thread>

namespace {

using namespace test_support;

using CGAL_ext::parameters::approximation;
using CGAL_ext::parameters::batch_size;
using CGAL_ext::parameters::number_of_threads;

/// mean of (approx - exact) / exact over vertices farther than 1e-12 from the sources
double mean_relative_error(const std::vector<double>& approx, const std::vector<double>& exact)
{
  double sum = 0;
  std::size_t n = 0;
  for(std::size_t i = 0; i < exact.size(); ++i)
    if(exact[i] > 1e-12 && std::isfinite(exact[i])) {
      sum += (approx[i] - exact[i]) / exact[i];
      ++n;
    }
  return n ? sum / double(n) : 0.;
}

struct Source_set
{
  std::string name;
  std::vector<Vertex> vertices;
  std::vector<Face_location> faces;
};

std::vector<Source_set> source_sets(const Mesh& m)
{
  const std::size_t n = m.number_of_vertices();
  return {{"vertex0", {Vertex(0)}, {}},
          {"three_vertices", {Vertex(0), Vertex(n / 3), Vertex(2 * n / 3)}, {}},
          {"face_points", {}, {location(7, 0.2, 0.3), location(m.number_of_faces() / 2, 0.6, 0.1)}}};
}

template <class ConcurrencyTag = CGAL::Sequential_tag, class NamedParameters = CGAL_ext::parameters::Default_named_parameters_type>
std::vector<double> solve_set(const Mesh& m, const Source_set& s,
                              const NamedParameters& np = CGAL_ext::parameters::default_values())
{
  return solve_mixed<ConcurrencyTag>(m, s.vertices, s.faces, np);
}

class Parallel_on_mesh : public ::testing::TestWithParam<std::string>
{};

// PVTP is exact: it matches sequential VTP to round-off, and gives bit-identical distances for
// every thread count (tasks write only their own slot, merged in a fixed order).
TEST_P(Parallel_on_mesh, pvtp_matches_vtp_for_every_thread_count_and_batch_size)
{
  const Mesh& m = test_mesh(GetParam());
  const double tolerance = 1e-12 * bbox_diagonal(m);
  for(const Source_set& s : source_sets(m)) {
    const std::vector<double> exact = solve_set(m, s);
    for(std::size_t k : {std::size_t(1), std::size_t(16), std::size_t(512)}) {
      const std::vector<double> one = solve_set<CGAL::Parallel_tag>(m, s, number_of_threads(1).batch_size(k));
      EXPECT_LE(max_difference(one, exact), tolerance) << s.name << ", batch " << k;
      for(int threads : {2, 4}) {
        const std::vector<double> many =
          solve_set<CGAL::Parallel_tag>(m, s, number_of_threads(threads).batch_size(k));
        EXPECT_EQ(max_difference(many, one), 0.) << s.name << ", batch " << k << ", " << threads << " threads";
      }
    }
  }
}

TEST_P(Parallel_on_mesh, parallel_max_distance_and_stop_vertices_match_sequential)
{
  const Mesh& m = test_mesh(GetParam());
  const double tolerance = 1e-12 * bbox_diagonal(m);
  const std::vector<Vertex> source = {Vertex(0)};
  const std::vector<double> full = solve(m, source);
  double farthest = 0;
  for(double d : full)
    if(std::isfinite(d))
      farthest = std::max(farthest, d);
  const double radius = 0.4 * farthest;
  for(int threads : {1, 2, 4}) {
    const std::vector<double> limited =
      solve<CGAL::Parallel_tag>(m, source, number_of_threads(threads).max_distance(radius));
    for(std::size_t i = 0; i < full.size(); ++i) {
      if(full[i] <= radius)
        EXPECT_NEAR(limited[i], full[i], tolerance) << "vertex " << i;
      else
        EXPECT_TRUE(std::isinf(limited[i])) << "vertex " << i << " at " << full[i] << " beyond " << radius;
    }
    const std::vector<Vertex> stops = {Vertex(m.number_of_vertices() / 2), Vertex(m.number_of_vertices() - 1)};
    const std::vector<double> stopped =
      solve<CGAL::Parallel_tag>(m, source, number_of_threads(threads).stop_vertices(stops));
    for(Vertex v : stops)
      EXPECT_NEAR(stopped[v.idx()], full[v.idx()], tolerance) << "stop vertex " << v;
    for(std::size_t i = 0; i < full.size(); ++i)
      if(std::isfinite(stopped[i]))
        EXPECT_NEAR(stopped[i], full[i], tolerance) << "vertex " << i;
  }
}

// A lambda larger than any distance never resets the wavefront: the result is exact.
TEST_P(Parallel_on_mesh, approximation_with_a_huge_lambda_is_exact)
{
  const Mesh& m = test_mesh(GetParam());
  const double tolerance = 1e-12 * bbox_diagonal(m);
  for(const Source_set& s : source_sets(m)) {
    const std::vector<double> exact = solve_set(m, s);
    CGAL_ext::Geodesic_statistics stats;
    const std::vector<double> approx = solve_set(m, s, approximation(1e12).statistics(stats));
    EXPECT_LE(max_difference(approx, exact), tolerance) << s.name;
    EXPECT_EQ(stats.wavefront_resets, 0u);
  }
}

// lambda -> 0 resets at every vertex: every vertex becomes a source relaxing its neighbours, so
// the result lies between the exact distance and Dijkstra's over the edges.
TEST_P(Parallel_on_mesh, approximation_with_a_tiny_lambda_lies_between_exact_and_dijkstra)
{
  const Mesh& m = test_mesh(GetParam());
  const double tolerance = 1e-12 * bbox_diagonal(m);
  const std::vector<Vertex> source = {Vertex(0)};
  CGAL_ext::Geodesic_statistics exact_stats, stats;
  const std::vector<double> exact = solve(m, source, CGAL_ext::parameters::statistics(exact_stats));
  const std::vector<double> approx = solve(m, source, approximation(1e-6).statistics(stats));
  const std::vector<double> dijkstra = steiner_upper_bound(m, Vertex(0), 0);
  for(std::size_t i = 0; i < exact.size(); ++i) {
    EXPECT_GE(approx[i], exact[i] - tolerance) << "vertex " << i;
    EXPECT_LE(approx[i], dijkstra[i] + tolerance) << "vertex " << i;
  }
  EXPECT_GT(stats.wavefront_resets, 100u);
  EXPECT_LT(stats.windows_created, exact_stats.windows_created);
}

// The approximation never goes below the exact distance, gets better as lambda grows, and at the
// thesis's lambda = 8 stays within 1% on average.
TEST_P(Parallel_on_mesh, approximation_error_is_bounded_and_shrinks_with_lambda)
{
  const Mesh& m = test_mesh(GetParam());
  const double tolerance = 1e-12 * bbox_diagonal(m);
  const std::vector<Vertex> source = {Vertex(0)};
  const std::vector<double> exact = solve(m, source);
  double previous_error = inf;
  for(double lambda : {1., 8., 32.}) {
    CGAL_ext::Geodesic_statistics stats;
    const std::vector<double> approx = solve(m, source, approximation(lambda).statistics(stats));
    for(std::size_t i = 0; i < exact.size(); ++i)
      ASSERT_GE(approx[i], exact[i] - tolerance) << "vertex " << i << ", lambda " << lambda;
    const double error = mean_relative_error(approx, exact);
    EXPECT_LE(error, previous_error + 1e-12) << "lambda " << lambda;
    if(lambda == 8.)
      EXPECT_LT(error, 0.01);
    previous_error = error;
  }
}

// The options of the exact solver work with the approximation too: several and face-point
// sources (in source_sets), a max distance, stop vertices.
TEST_P(Parallel_on_mesh, approximation_honours_max_distance_and_stop_vertices)
{
  const Mesh& m = test_mesh(GetParam());
  const double tolerance = 1e-12 * bbox_diagonal(m);
  for(const Source_set& s : source_sets(m)) {
    const std::vector<double> exact = solve_set(m, s);
    const std::vector<double> approx = solve_set(m, s, approximation(4.));
    double farthest = 0;
    for(double d : exact)
      if(std::isfinite(d))
        farthest = std::max(farthest, d);
    const double radius = 0.5 * farthest;
    for(int threads : {1, 2}) {
      const std::vector<double> limited =
        solve_set<CGAL::Parallel_tag>(m, s, approximation(4.).max_distance(radius).number_of_threads(threads));
      for(std::size_t i = 0; i < exact.size(); ++i) {
        if(std::isinf(limited[i]))
          EXPECT_GT(approx[i], radius - tolerance) << s.name << ", vertex " << i;
        else {
          EXPECT_LE(limited[i], radius) << s.name << ", vertex " << i;
          EXPECT_GE(limited[i], exact[i] - tolerance) << s.name << ", vertex " << i;
        }
        if(exact[i] < 0.7 * radius)
          EXPECT_TRUE(std::isfinite(limited[i])) << s.name << ", vertex " << i << " at " << exact[i];
      }
    }
    const std::vector<Vertex> stops = {Vertex(m.number_of_vertices() / 3), Vertex(m.number_of_vertices() - 2)};
    const std::vector<double> stopped = solve_set(m, s, approximation(4.).stop_vertices(stops));
    for(Vertex v : stops) {
      EXPECT_TRUE(std::isfinite(stopped[v.idx()])) << s.name << ", stop vertex " << v;
      EXPECT_GE(stopped[v.idx()], exact[v.idx()] - tolerance) << s.name << ", stop vertex " << v;
    }
  }
}

// PAVTP is AVTP on threads: bit-identical results for every thread count, for the same batch size.
TEST_P(Parallel_on_mesh, pavtp_equals_avtp_for_every_thread_count)
{
  const Mesh& m = test_mesh(GetParam());
  for(const Source_set& s : source_sets(m))
    for(double lambda : {0.5, 8.})
      for(std::size_t k : {std::size_t(16), CGAL_ext::default_batch_size}) {
        const std::vector<double> sequential = solve_set(m, s, approximation(lambda).batch_size(k));
        for(int threads : {1, 2, 4}) {
          const std::vector<double> parallel =
            solve_set<CGAL::Parallel_tag>(m, s, approximation(lambda).number_of_threads(threads).batch_size(k));
          EXPECT_EQ(max_difference(parallel, sequential), 0.)
            << s.name << ", lambda " << lambda << ", batch " << k << ", " << threads << " threads";
        }
      }
}

// Under ThreadSanitizer (about 10x slower) without fandisk, the slowest of them there (a
// quarter of that run): the races it could show are in the code the other meshes run.
#ifdef CGAL_EXT_THREAD_SANITIZER
#define CGAL_EXT_PARALLEL_TEST_MESHES "elephant", "mushroom", "cactus", "knot1"
#else
#define CGAL_EXT_PARALLEL_TEST_MESHES "elephant", "mushroom", "fandisk", "cactus", "knot1"
#endif
INSTANTIATE_TEST_SUITE_P(Meshes, Parallel_on_mesh, ::testing::Values(CGAL_EXT_PARALLEL_TEST_MESHES),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

/// A bumpy grid: jittered in x and y, random heights (many saddles), optionally with a square
/// hole in the middle (border vertices, isolated vertices inside the hole).
Mesh bumpy_grid(int n, double amplitude, unsigned seed, bool hole)
{
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> u(-1., 1.);
  std::vector<Point> points;
  for(int j = 0; j <= n; ++j)
    for(int i = 0; i <= n; ++i)
      points.push_back(Point(i + 0.3 * u(random), j + 0.3 * u(random), amplitude * u(random)));
  std::vector<Triangle> triangles;
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i)
      if(!(hole && i > n / 3 && i < 2 * n / 3 && j > n / 3 && j < 2 * n / 3))
        add_quad(triangles, j * (n + 1) + i, j * (n + 1) + i + 1, (j + 1) * (n + 1) + i + 1, (j + 1) * (n + 1) + i,
                 (i + j) % 2 == 1);
  return mesh_from_soup(points, triangles);
}

// The batched solvers take every reachable vertex (once at least) and match VTP, on meshes where
// buckets often hold only stale entries (a bucket of stale entries once ended the propagation
// early, leaving saddles that had to emit untaken).
TEST(Parallel, batched_solvers_take_every_reachable_vertex)
{
  for(unsigned seed = 1; seed <= 40; ++seed) {
    const Mesh m = bumpy_grid(15 + int(seed % 10), seed % 3 == 0 ? 0. : 0.8 + seed % 5, seed, seed % 2 == 1);
    // a vertex in a face (the L-shaped grids keep the vertices of their missing quadrant)
    Vertex start((seed * 37) % m.number_of_vertices());
    while(m.is_isolated(start))
      start = Vertex((start.idx() + 1) % m.number_of_vertices());
    const std::vector<Vertex> source = {start};
    const std::vector<double> exact = solve(m, source);
    const std::size_t reachable =
      std::size_t(std::count_if(exact.begin(), exact.end(), [](double d) { return std::isfinite(d); }));
    const double tolerance = 1e-12 * bbox_diagonal(m);
    for(std::size_t k : {std::size_t(1), std::size_t(2), std::size_t(512)}) {
      CGAL_ext::Geodesic_statistics parallel, no_reset;
      const std::vector<double> p = solve<CGAL::Parallel_tag>(m, source, batch_size(k).statistics(parallel));
      const std::vector<double> a = solve(m, source, approximation(1e300).batch_size(k).statistics(no_reset));
      EXPECT_GE(parallel.vertices_popped, reachable) << "seed " << seed << ", batch " << k;
      EXPECT_GE(no_reset.vertices_popped, reachable) << "seed " << seed << ", batch " << k;
      EXPECT_LE(max_difference(p, exact), tolerance) << "seed " << seed << ", batch " << k;
      EXPECT_LE(max_difference(a, exact), tolerance) << "seed " << seed << ", batch " << k;
    }
  }
}

TEST(Parallel, statistics_report_the_parallel_phases)
{
  const Mesh& m = test_mesh("elephant");
  CGAL_ext::Geodesic_statistics sequential, parallel;
  solve(m, std::vector<Vertex>{Vertex(0)}, CGAL_ext::parameters::statistics(sequential));
  solve<CGAL::Parallel_tag>(m, std::vector<Vertex>{Vertex(0)},
                            number_of_threads(2).statistics(parallel));
  EXPECT_GT(parallel.lists_propagated, 0u);
  EXPECT_GT(parallel.seconds_propagation, 0.);
  EXPECT_GE(parallel.seconds_merge, 0.);
  EXPECT_GE(parallel.seconds_selection, 0.);
  EXPECT_EQ(sequential.seconds_propagation, 0.); // the sequential solver has no such phases
  EXPECT_EQ(parallel.vertices, m.number_of_vertices());
  // Batches take vertices slightly out of order: a few more windows, not many.
  EXPECT_LT(double(parallel.windows_created), 1.25 * double(sequential.windows_created));
}

TEST(Parallel, parallel_if_available_is_parallel_with_tbb)
{
  const Mesh& m = test_mesh("elephant");
  const std::vector<Vertex> source = {Vertex(0)};
  EXPECT_EQ(max_difference(solve<CGAL::Parallel_if_available_tag>(m, source, batch_size(64)),
                           solve<CGAL::Parallel_tag>(m, source, batch_size(64))),
            0.);
}

TEST(Parallel, bad_parameters_throw)
{
  const Mesh& m = test_mesh("elephant");
  const std::vector<Vertex> source = {Vertex(0)};
  for(double lambda : {0., -1., std::numeric_limits<double>::quiet_NaN(), inf})
    EXPECT_TRUE(throws_geodesic_error([&] { solve(m, source, approximation(lambda)); }, {"lambda"})) << lambda;
  EXPECT_TRUE(throws_geodesic_error([&] { solve<CGAL::Parallel_tag>(m, source, number_of_threads(-1)); }, {"threads"}));
  EXPECT_TRUE(throws_geodesic_error([&] { solve<CGAL::Parallel_tag>(m, source, batch_size(0)); }, {"batch size"}));
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, source, approximation(8.).batch_size(0)); }, {"batch size"}));
}

// ---------------------------------------------------------------------------------------------
// PMMP (Surface_mesh_geodesic_paths and geodesic_distances with CGAL::Parallel_tag), and the
// class built from PVTP's windows: for a given batch size, the same windows whatever the number
// of threads, so bit-identical distances (at vertices and at face points), nearest sources and
// paths. The mesh is small (2.8k vertices) because this also runs under ThreadSanitizer.

typedef CGAL_ext::Surface_mesh_geodesic_paths<Mesh, CGAL::Parallel_tag> Parallel_paths;

struct Pmmp_answers
{
  std::vector<double> vertex_distances, function_distances, point_distances;
  std::vector<std::size_t> sources;
  std::vector<std::vector<Parallel_paths::Path_point>> paths;
  std::size_t windows = 0, deferred = 0, stored = 0;
};

TEST(Parallel_paths, pmmp_and_pvtp_windows_are_identical_for_every_thread_count_and_match_vtp)
{
  for(CGAL_ext::Geodesic_algorithm algorithm : {CGAL_ext::FWP_MMP, CGAL_ext::VTP}) {
    SCOPED_TRACE(algorithm == CGAL_ext::VTP ? "PVTP's windows" : "PMMP");
    const Mesh& m = test_mesh("elephant");
    const double tolerance = 1e-12 * bbox_diagonal(m);
    const std::size_t nf = m.number_of_faces();
    const std::vector<Vertex> vertex_sources = {Vertex(0), Vertex(m.number_of_vertices() / 2)};
    const std::vector<Face_location> face_sources = {location(nf / 3, 0.2, 0.3), location(2 * nf / 3, 0., 0.4)};
    const std::vector<double> vtp = solve_mixed(m, vertex_sources, face_sources);
    const std::vector<Vertex> vertex_targets = spread_vertices(m, 25, 7);
    std::vector<Face_location> point_targets;
    for(std::size_t i = 0; i < 25; ++i)
      point_targets.push_back(i % 2 ? location((i * nf) / 25 + 3, 0.3, 0.25) : location((i * nf) / 25 + 1, 0., 0.35));

    auto run = [&](int threads, std::size_t batch) {
      Pmmp_answers a;
      Parallel_paths p(m);
      p.add_sources(vertex_sources);
      p.add_sources(face_sources);
      CGAL_ext::Geodesic_statistics stats;
      p.build(number_of_threads(threads).batch_size(batch).statistics(stats).algorithm(algorithm));
      a.windows = stats.windows_created;
      a.deferred = stats.windows_deferred;
      a.stored = stats.windows_stored; // the store's contents, whichever thread inserted them
      for(Vertex v : m.vertices()) {
        a.vertex_distances.push_back(p.distance(v));
        a.sources.push_back(p.nearest_source(v));
      }
      for(const Face_location& l : point_targets) {
        a.point_distances.push_back(p.distance(l));
        a.sources.push_back(p.nearest_source(l));
        a.paths.emplace_back();
        p.shortest_path_surface_points(l, std::back_inserter(a.paths.back()));
      }
      for(Vertex v : vertex_targets) {
        a.paths.emplace_back();
        p.shortest_path_surface_points(v, std::back_inserter(a.paths.back()));
      }
      a.function_distances = solve_mixed<CGAL::Parallel_tag>(
        m, vertex_sources, face_sources,
        CGAL_ext::parameters::algorithm(CGAL_ext::FWP_MMP).number_of_threads(threads).batch_size(batch));
      return a;
    };

    std::size_t deferred = 0;
    for(std::size_t batch : {std::size_t(1), std::size_t(64), std::size_t(1024)}) {
      const Pmmp_answers one = run(1, batch);
      deferred += one.deferred;
      EXPECT_LE(max_difference(one.vertex_distances, vtp), tolerance) << "batch " << batch;
      EXPECT_LE(max_difference(one.function_distances, vtp), tolerance) << "batch " << batch;
      for(const auto& path : one.paths)
        EXPECT_TRUE(is_valid_path(m, path)) << "batch " << batch;
      for(int threads : {2, 4}) {
        const Pmmp_answers many = run(threads, batch);
        const std::string where = "batch " + std::to_string(batch) + ", " + std::to_string(threads) + " threads";
        EXPECT_EQ(max_difference(many.vertex_distances, one.vertex_distances), 0.) << where;
        EXPECT_EQ(max_difference(many.function_distances, one.function_distances), 0.) << where;
        EXPECT_EQ(max_difference(many.point_distances, one.point_distances), 0.) << where;
        EXPECT_EQ(many.sources, one.sources) << where;
        EXPECT_EQ(many.windows, one.windows) << where;
        EXPECT_EQ(many.stored, one.stored) << where;
        EXPECT_EQ(many.deferred, one.deferred) << where;
        ASSERT_EQ(many.paths.size(), one.paths.size());
        for(std::size_t i = 0; i < one.paths.size(); ++i)
          EXPECT_TRUE(identical_paths(many.paths[i], one.paths[i])) << where << ", path " << i;
      }
    }
    // PMMP: windows whose distance moved to a later bucket while they waited were taken out of
    // order and queued again: the runs above went through that path
    if(algorithm == CGAL_ext::FWP_MMP)
      EXPECT_GT(deferred, 0u);
  }
}

} // namespace

// ---- the parallel loop of PVTP and PMMP: oneTBB's parallel_for in the caller's task arena ----

namespace {

using CGAL_ext::Geodesics_3::internal::for_each_index;

TEST(Parallel_for, every_index_is_done_once_for_every_thread_count_grain_and_size)
{
  for(int threads : {1, 2, 4})
    for(std::size_t grain : {std::size_t(1), std::size_t(3), std::size_t(32)}) {
      tbb::task_arena arena(threads);
      arena.execute([&] {
        // Many short loops in a row, as a solver runs them; each index writes only its own cell.
        for(std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(5), std::size_t(1000), std::size_t(4097)}) {
          for(int round = 0; round < 50; ++round) {
            std::vector<int> visits(n, 0);
            std::vector<std::size_t> slot_of(n, std::size_t(-1));
            for_each_index(true, n, grain, [&](std::size_t i, std::size_t slot) {
              ++visits[i];
              slot_of[i] = slot;
            });
            for(std::size_t i = 0; i < n; ++i) {
              ASSERT_EQ(visits[i], 1) << "index " << i << " of " << n << ", threads " << threads << ", grain " << grain;
              ASSERT_LT(slot_of[i], std::size_t(threads));
            }
          }
        }
      });
    }
}

TEST(Parallel_for, an_exception_in_a_loop_reaches_the_caller_and_the_next_loop_runs)
{
  for(int threads : {1, 2, 4}) {
    tbb::task_arena arena(threads);
    arena.execute([&] {
      for(std::size_t thrower : {std::size_t(0), std::size_t(517), std::size_t(999)}) {
        std::vector<std::atomic<int>> visits(1000);
        EXPECT_THROW(for_each_index(true, 1000, 4,
                                    [&](std::size_t i, std::size_t) {
                                      ++visits[i];
                                      if(i == thrower)
                                        throw std::runtime_error("index " + std::to_string(i));
                                    }),
                     std::runtime_error);
        // No index ran twice (indices after the exception may be skipped).
        EXPECT_EQ(visits[thrower], 1);
        EXPECT_EQ(std::count_if(visits.begin(), visits.end(), [](const std::atomic<int>& v) { return v > 1; }), 0);
        std::vector<std::size_t> values(100, 0);
        for_each_index(true, 100, 1, [&](std::size_t i, std::size_t) { values[i] = i; });
        EXPECT_EQ(std::accumulate(values.begin(), values.end(), std::size_t(0)), std::size_t(4950));
      }
    });
  }
}

TEST(Parallel_for, a_sequential_loop_runs_in_order_in_slot_0_on_any_thread)
{
  // Sequential per-thread storage has one slot, whichever thread of an arena calls: even on a
  // TBB worker (slot > 0) a sequential loop gives slot 0.
  tbb::task_arena arena(4);
  arena.execute([] {
    // (the package's own parallel loop stands for the caller's: its hand-overs are stated to TSan)
    for_each_index(true, 16, 1, [](std::size_t, std::size_t) {
      std::vector<std::size_t> order;
      for_each_index(false, 10, 3, [&](std::size_t i, std::size_t slot) {
        order.push_back(i);
        EXPECT_EQ(slot, std::size_t(0));
      });
      std::vector<std::size_t> expected(10);
      std::iota(expected.begin(), expected.end(), std::size_t(0));
      EXPECT_EQ(order, expected);
    });
  });
}

TEST(Parallel_for, sequential_solvers_run_inside_a_callers_parallel_loop)
{
  // A user's parallel loop calling the sequential solvers (AVTP takes its batched path through
  // the parallel loop, sequentially) gets the same distances on every worker thread.
  const Mesh& m = test_mesh("elephant");
  const std::vector<Vertex> source{Vertex(0)};
  const std::vector<double> exact = solve(m, source);
  const std::vector<double> approximate = solve(m, source, CGAL_ext::parameters::approximation(8.));
  tbb::task_arena arena(4);
  std::vector<std::vector<double>> exact_runs(8), approximate_runs(8);
  arena.execute([&] {
    for_each_index(true, 8, 1, [&](std::size_t i, std::size_t) {
      exact_runs[i] = solve(m, source);
      approximate_runs[i] = solve(m, source, CGAL_ext::parameters::approximation(8.));
    });
  });
  for(std::size_t i = 0; i < 8; ++i) {
    EXPECT_EQ(exact_runs[i], exact) << "run " << i;
    EXPECT_EQ(approximate_runs[i], approximate) << "run " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Nearest-source labels (vertex_source_map), from the same propagation as the distances

/// The distances and nearest-source labels of one run of geodesic_distances.
struct Labelled_run
{
  std::vector<double> distances;
  std::vector<long> labels;
};

template <class ConcurrencyTag = CGAL::Sequential_tag, class Sources, class NamedParameters>
Labelled_run solve_with_labels(const Mesh& m, const Sources& sources, const NamedParameters& np)
{
  auto labels = get(CGAL::dynamic_vertex_property_t<long>(), m);
  for(Vertex v : vertices(m))
    put(labels, v, -2);
  Labelled_run run;
  run.distances = solve<ConcurrencyTag>(m, sources, np.vertex_source_map(labels));
  for(Vertex v : vertices(m))
    run.labels.push_back(get(labels, v));
  return run;
}

// The label of every vertex is a source at the vertex's distance: the argmin of the
// single-source distances, ties aside; for every exact solver and thread count, and the same
// labels for every thread count of one solver.
TEST(Source_labels, every_exact_solver_labels_each_vertex_with_its_nearest_source)
{
  using CGAL_ext::parameters::algorithm;
  for(const char* name : {"elephant", "mushroom"}) {
    const Mesh& m = test_mesh(name);
    const double diag = bbox_diagonal(m);
    std::vector<Face_location> sources;
    for(Vertex v : spread_vertices(m, 4, 5))
      sources.push_back(corner_location(m, v));
    sources.push_back(location(3, 0.2, 0.3));
    sources.push_back(location(m.number_of_faces() / 2, 0.5, 0.25));
    std::vector<std::vector<double>> single;
    for(const Face_location& s : sources)
      single.push_back(solve(m, std::vector<Face_location>{s}));

    auto check = [&](const std::string& label, const Labelled_run& run) {
      std::size_t decided = 0;
      for(std::size_t v = 0; v < m.number_of_vertices(); ++v) {
        double nearest = inf;
        std::size_t argmin = 0;
        for(std::size_t i = 0; i < sources.size(); ++i)
          if(single[i][v] < nearest) {
            nearest = single[i][v];
            argmin = i;
          }
        ASSERT_GE(run.labels[v], 0) << label << ": vertex " << v << " has no label";
        ASSERT_LT(std::size_t(run.labels[v]), sources.size()) << label << ": vertex " << v;
        EXPECT_LE(single[std::size_t(run.labels[v])][v] - nearest, 1e-12 * diag) << label << ": vertex " << v;
        EXPECT_NEAR(run.distances[v], nearest, 1e-12 * diag) << label << ": vertex " << v;
        // where the nearest source is clearly nearest, the label is exactly it
        bool clear = true;
        for(std::size_t i = 0; i < sources.size(); ++i)
          if(i != argmin && single[i][v] - nearest < 1e-9 * diag)
            clear = false;
        if(clear) {
          ++decided;
          EXPECT_EQ(std::size_t(run.labels[v]), argmin) << label << ": vertex " << v;
        }
      }
      EXPECT_GT(decided, m.number_of_vertices() * 9 / 10) << label;
    };
    const std::string mesh(name);
    check(mesh + " VTP", solve_with_labels(m, sources, CGAL_ext::parameters::default_values()));
    check(mesh + " MMP", solve_with_labels(m, sources, algorithm(CGAL_ext::MMP)));
    check(mesh + " FWP-MMP", solve_with_labels(m, sources, algorithm(CGAL_ext::FWP_MMP)));
    std::vector<long> pvtp, pmmp;
    for(int threads : {1, 2, 4}) {
      const std::string t = " T=" + std::to_string(threads);
      const Labelled_run p = solve_with_labels<CGAL::Parallel_tag>(m, sources, number_of_threads(threads));
      check(mesh + " PVTP" + t, p);
      const Labelled_run q =
        solve_with_labels<CGAL::Parallel_tag>(m, sources, algorithm(CGAL_ext::FWP_MMP).number_of_threads(threads));
      check(mesh + " PMMP" + t, q);
      if(threads == 1) {
        pvtp = p.labels;
        pmmp = q.labels;
      }
      EXPECT_EQ(p.labels, pvtp) << mesh << " PVTP" << t << ": the same labels for every thread count";
      EXPECT_EQ(q.labels, pmmp) << mesh << " PMMP" << t << ": the same labels for every thread count";
    }
  }
}

// Unreachable vertices (beyond max_distance, or in another component) get no_source: -1 in a
// signed map, CGAL_ext::no_source in a std::size_t map; a duplicated source counts once (the
// first one).
TEST(Source_labels, unreachable_vertices_get_no_source_and_a_duplicate_source_the_first_index)
{
  using CGAL_ext::parameters::algorithm;
  const Mesh& m = test_mesh("elephant");
  const double radius = 0.2 * bbox_diagonal(m);
  const std::vector<Vertex> sources{Vertex(0), Vertex(0), Vertex(100)};
  for(CGAL_ext::Geodesic_algorithm a : {CGAL_ext::VTP, CGAL_ext::FWP_MMP}) {
    const Labelled_run run = solve_with_labels(m, sources, algorithm(a).max_distance(radius));
    auto unsigned_labels = get(CGAL::dynamic_vertex_property_t<std::size_t>(), m);
    solve(m, sources, algorithm(a).max_distance(radius).vertex_source_map(unsigned_labels));
    std::size_t unreached = 0;
    for(Vertex v : vertices(m)) {
      const std::size_t i = v.idx();
      if(run.distances[i] == inf) {
        ++unreached;
        EXPECT_EQ(run.labels[i], -1) << "vertex " << i;
        EXPECT_EQ(get(unsigned_labels, v), CGAL_ext::no_source) << "vertex " << i;
      } else {
        EXPECT_TRUE(run.labels[i] == 0 || run.labels[i] == 2) << "vertex " << i << ": label " << run.labels[i];
        EXPECT_EQ(get(unsigned_labels, v), std::size_t(run.labels[i]));
      }
    }
    EXPECT_GT(unreached, 0u);
    EXPECT_EQ(run.labels[0], 0);
    EXPECT_EQ(run.labels[100], 2);
  }
}

// The Voronoi diagram's faces are handled in blocks on the arena's threads, each block writing
// its own output: the same diagram, point for point, for every thread count.
TEST(Geodesic_voronoi_parallel, the_same_diagram_for_every_thread_count)
{
  const Mesh& m = test_mesh("elephant");
  const std::vector<Vertex> sources = spread_vertices(m, 6, 11);
  for(CGAL_ext::Geodesic_algorithm algorithm : {CGAL_ext::FWP_MMP, CGAL_ext::VTP}) {
    SCOPED_TRACE(algorithm == CGAL_ext::VTP ? "PVTP's windows" : "PMMP");
    const auto one =
      CGAL_ext::geodesic_voronoi_diagram<CGAL::Parallel_tag>(m, sources, number_of_threads(1).algorithm(algorithm));
    ASSERT_FALSE(one.bisectors.empty());
    for(int threads : {2, 4}) {
      const auto many = CGAL_ext::geodesic_voronoi_diagram<CGAL::Parallel_tag>(
        m, sources, number_of_threads(threads).algorithm(algorithm));
      EXPECT_EQ(many.vertex_cell, one.vertex_cell) << threads << " threads";
      EXPECT_EQ(many.dual_edges, one.dual_edges) << threads << " threads";
      EXPECT_EQ(many.dual_triangles, one.dual_triangles) << threads << " threads";
      ASSERT_EQ(many.bisectors.size(), one.bisectors.size()) << threads << " threads";
      for(std::size_t i = 0; i < one.bisectors.size(); ++i) {
        ASSERT_EQ(many.bisectors[i].points.size(), one.bisectors[i].points.size()) << threads << " threads";
        for(std::size_t k = 0; k < one.bisectors[i].points.size(); ++k)
          EXPECT_EQ(many.bisectors[i].points[k].point, one.bisectors[i].points[k].point);
      }
      ASSERT_EQ(many.vertices.size(), one.vertices.size());
      for(std::size_t i = 0; i < one.vertices.size(); ++i)
        EXPECT_EQ(many.vertices[i].point.point, one.vertices[i].point.point);
    }
  }
}

// Farthest-point sampling runs several samples at once on two threads or more, each in a
// solver of its own, and keeps a run only when it read nothing the runs before it changed: the
// same samples, radii, distances and labels as on one thread.
TEST(Farthest_point_sampling_parallel, batched_runs_give_the_samples_of_one_thread)
{
  const Mesh& m = test_mesh("elephant");
  auto sample = [&](int threads, std::vector<double>& distances, std::vector<long>& labels,
                    CGAL_ext::Geodesic_statistics& statistics) {
    std::vector<Vertex> samples;
    auto distance = get(CGAL::dynamic_vertex_property_t<double>(), m);
    auto label = get(CGAL::dynamic_vertex_property_t<long>(), m);
    CGAL_ext::farthest_point_sampling<CGAL::Parallel_tag>(
      m, 60, std::back_inserter(samples),
      number_of_threads(threads).vertex_distance_map(distance).vertex_source_map(label).statistics(statistics));
    distances.clear();
    labels.clear();
    for(Vertex v : vertices(m)) {
      distances.push_back(get(distance, v));
      labels.push_back(get(label, v));
    }
    return samples;
  };
  std::vector<double> d1, d;
  std::vector<long> l1, l;
  CGAL_ext::Geodesic_statistics s1, s;
  const std::vector<Vertex> one = sample(1, d1, l1, s1);
  for(int threads : {2, 4}) {
    EXPECT_EQ(sample(threads, d, l, s), one) << threads << " threads";
    EXPECT_EQ(d, d1) << threads << " threads";
    EXPECT_EQ(l, l1) << threads << " threads";
    EXPECT_GT(s.batched_runs_kept, 0u) << threads << " threads";
  }
}

// ---------------------------------------------------------------------------------------------
// Distance matrices: one row per source, solved in parallel across sources

TEST(Distance_matrix, rows_are_single_source_solves_in_order_for_every_thread_count)
{
  const Mesh& m = test_mesh("elephant");
  // more sources than the first batch (4 a thread) holds: the later batches are larger, their
  // rows reused
  const std::vector<Vertex> sources = spread_vertices(m, 30);
  std::vector<std::vector<double>> expected;
  for(Vertex s : sources)
    expected.push_back(solve(m, s));
  auto check = [&](const std::string& label, auto solve_rows) {
    std::size_t next = 0;
    solve_rows([&](std::size_t i, const std::vector<double>& row) {
      EXPECT_EQ(i, next++) << label << ": rows come in the order of the sources";
      EXPECT_EQ(row, expected[i]) << label << ": row " << i;
    });
    EXPECT_EQ(next, sources.size()) << label;
  };
  check("sequential", [&](auto f) { CGAL_ext::geodesic_distance_rows(m, sources, f); });
  for(int threads : {1, 2, 4})
    check("T=" + std::to_string(threads), [&](auto f) {
      CGAL_ext::geodesic_distance_rows<CGAL::Parallel_tag>(m, sources, f, number_of_threads(threads));
    });
}

TEST(Distance_matrix, square_matrix_is_symmetric_and_a_local_one_is_cut_at_the_radius)
{
  const Mesh& m = test_mesh("elephant");
  const std::vector<Vertex> sources = spread_vertices(m, 12);
  const std::size_t n = m.number_of_vertices();
  const std::vector<double> full = CGAL_ext::geodesic_distance_matrix<CGAL::Parallel_tag>(m, sources, number_of_threads(2));
  ASSERT_EQ(full.size(), sources.size() * n);
  const double diag = bbox_diagonal(m);
  for(std::size_t i = 0; i < sources.size(); ++i) {
    EXPECT_EQ(full[i * n + sources[i].idx()], 0.);
    for(std::size_t j = 0; j < i; ++j)
      EXPECT_NEAR(full[i * n + sources[j].idx()], full[j * n + sources[i].idx()], 1e-12 * diag) << i << ", " << j;
  }
  // within a radius: the same entries, +infinity beyond
  const double radius = 0.1 * diag;
  const std::vector<double> local = CGAL_ext::geodesic_distance_matrix<CGAL::Parallel_tag>(
    m, sources, number_of_threads(2).max_distance(radius));
  for(std::size_t k = 0; k < full.size(); ++k)
    EXPECT_EQ(local[k], full[k] <= radius ? full[k] : inf) << "entry " << k;
}

// Sparse rows: exactly the finite entries of single-source solves within the radius, by vertex
// index, for every thread count (each thread's solver is reset between rows: rows after a far-
// reaching one must not keep its distances); the CSR matrix holds the same entries.
TEST(Distance_matrix, sparse_rows_are_the_entries_within_the_radius)
{
  const Mesh& m = test_mesh("elephant");
  const double radius = 0.08 * bbox_diagonal(m);
  std::vector<Vertex> sources = spread_vertices(m, 10);
  sources.push_back(sources.front()); // a row again after others
  std::vector<std::vector<std::pair<std::size_t, double>>> expected;
  std::size_t entries = 0;
  for(Vertex s : sources) {
    const std::vector<double> d = solve(m, s, CGAL_ext::parameters::max_distance(radius));
    expected.emplace_back();
    for(std::size_t v = 0; v < d.size(); ++v)
      if(d[v] < inf)
        expected.back().emplace_back(v, d[v]);
    entries += expected.back().size();
  }
  EXPECT_LT(entries, sources.size() * m.number_of_vertices() / 5) << "the radius is local";
  for(int threads : {1, 2, 4}) {
    std::size_t next = 0;
    CGAL_ext::geodesic_sparse_distance_rows<CGAL::Parallel_tag>(
      m, sources,
      [&](std::size_t i, const std::vector<std::pair<std::size_t, double>>& row) {
        EXPECT_EQ(i, next++);
        EXPECT_EQ(row, expected[i]) << threads << " threads, row " << i;
      },
      number_of_threads(threads).max_distance(radius));
    EXPECT_EQ(next, sources.size());
  }
  const CGAL_ext::Geodesic_sparse_matrix csr =
    CGAL_ext::geodesic_sparse_distance_matrix(m, sources, CGAL_ext::parameters::max_distance(radius));
  ASSERT_EQ(csr.rows, sources.size());
  EXPECT_EQ(csr.columns, m.number_of_vertices());
  ASSERT_EQ(csr.row_begin.size(), sources.size() + 1);
  ASSERT_EQ(csr.column.size(), entries);
  ASSERT_EQ(csr.value.size(), entries);
  for(std::size_t i = 0; i < sources.size(); ++i) {
    ASSERT_EQ(csr.row_begin[i + 1] - csr.row_begin[i], expected[i].size()) << "row " << i;
    for(std::size_t k = 0; k < expected[i].size(); ++k) {
      EXPECT_EQ(csr.column[csr.row_begin[i] + k], expected[i][k].first);
      EXPECT_EQ(csr.value[csr.row_begin[i] + k], expected[i][k].second);
    }
  }
}

// The solvers kept across calls (what the pattern detection asks its rows of): each call with its
// own max distance or stop vertices gives the rows of fresh solves, after rows of other limits.
TEST(Distance_matrix, row_solvers_give_fresh_rows_call_after_call)
{
  namespace internal = CGAL_ext::Geodesics_3::internal;
  const Mesh& m = test_mesh("elephant");
  const double diagonal = bbox_diagonal(m);
  const std::vector<Vertex> sources = spread_vertices(m, 6);
  const std::vector<Vertex> stop = {Vertex(17), Vertex(400), Vertex(1200)};
  typedef std::vector<std::pair<std::size_t, double>> Row;
  const auto row_of = [](const std::vector<double>& d) {
    Row row;
    for(std::size_t v = 0; v < d.size(); ++v)
      if(d[v] < inf)
        row.emplace_back(v, d[v]);
    return row;
  };
  for(int threads : {1, 2, 4}) {
    const auto np = number_of_threads(threads);
    internal::Row_solvers<true, Mesh, internal::Vertex_point_map_of<Mesh, std::decay_t<decltype(np)>>> solvers(m, np);
    std::vector<internal::Source_point> points;
    for(Vertex s : sources)
      points.push_back(solvers.mesh().source_point(s));
    std::vector<int> stop_indices;
    for(Vertex v : stop)
      stop_indices.push_back(int(v));
    for(double radius : {0.1 * diagonal, 0.03 * diagonal, inf, 0.2 * diagonal}) {
      const bool stops = radius == inf;
      std::size_t next = 0;
      solvers.for_each_row<Row>(
        points, radius, stops ? stop_indices : std::vector<int>{},
        [](const internal::VTP_solver& solver, const auto& mesh, Row& row) { internal::make_sparse_row(solver, mesh, row); },
        [&](std::size_t i, const Row& row) {
          ASSERT_EQ(i, next++);
          const std::vector<double> fresh = stops ? solve(m, sources[i], CGAL_ext::parameters::stop_vertices(stop))
                                                  : solve(m, sources[i], CGAL_ext::parameters::max_distance(radius));
          EXPECT_EQ(row, row_of(fresh)) << threads << " threads, radius " << radius << ", row " << i;
          if(stops)
            for(Vertex v : stop)
              EXPECT_LT(fresh[std::size_t(v)], inf) << "a stop vertex is in its row";
        });
      EXPECT_EQ(next, sources.size());
    }
  }
}

TEST(Distance_matrix, face_point_sources_and_errors)
{
  const Mesh& m = test_mesh("elephant");
  const std::vector<Face_location> points{location(10, 0.2, 0.3), location(500, 0.6, 0.1)};
  const std::vector<double> matrix = CGAL_ext::geodesic_distance_matrix(m, points);
  const std::vector<double> second(matrix.begin() + std::ptrdiff_t(m.number_of_vertices()), matrix.end());
  EXPECT_EQ(second, solve(m, std::vector<Face_location>{points[1]}));
  EXPECT_TRUE(throws_geodesic_error([&] { CGAL_ext::geodesic_distance_matrix(m, std::vector<Vertex>{}); },
                                    {"no source"}));
  EXPECT_TRUE(throws_geodesic_error(
    [&] { CGAL_ext::geodesic_distance_matrix(m, std::vector<Vertex>{Vertex(0)}, CGAL_ext::parameters::algorithm(CGAL_ext::MMP)); },
    {"VTP"}));
}

} // namespace
