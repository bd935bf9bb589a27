// Copyright (c) 2026 The CGAL_ext geodesics developers.
// One convention for every public function: per-vertex results through property maps, surface
// points as CGAL's Polygon_mesh_processing::Face_location, statistics through the `statistics`
// named parameter. What was given another way before (the Voronoi diagram's vectors, the paths
// class's accessor, the patterns' result member) still works, and agrees, for one release.

#include "support/checks.h"
#include "support/pattern_meshes.h"

#include <CGAL_ext/Surface_mesh_geodesic_paths.h>
#include <CGAL_ext/detect_repetitive_patterns.h>
#include <CGAL_ext/farthest_point_sampling.h>
#include <CGAL_ext/geodesic_distance_matrix.h>
#include <CGAL_ext/geodesic_distances.h>
#include <CGAL_ext/geodesic_voronoi_diagram.h>

#include <CGAL/Polygon_mesh_processing/locate.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <functional>
#include <iterator>
#include <string>
#include <type_traits>
#include <vector>

using namespace test_support;

namespace conventions {

namespace PMP = CGAL::Polygon_mesh_processing;

static_assert(std::is_same<CGAL_ext::Surface_mesh_geodesic_paths<Mesh>::Face_location, PMP::Face_location<Mesh, double>>::value,
              "the paths class takes CGAL's Face_location");
static_assert(std::is_same<CGAL_ext::Geodesic_voronoi_diagram<Mesh, Point>::Face_location,
                           PMP::Face_location<Mesh, double>>::value,
              "the Voronoi diagram gives CGAL's Face_location");
static_assert(std::is_same<Face_location, PMP::Face_location<Mesh, double>>::value,
              "the tests' face locations are CGAL's");

std::vector<Face_location> some_sources(const Mesh& m)
{
  const std::size_t nf = m.number_of_faces();
  return {location(nf / 7, 0.2, 0.3), location(nf / 2, 0.5, 0.25), location(4 * nf / 5, 0.1, 0.1),
          location(nf / 3, 1., 0.)};
}

TEST(Conventions, voronoi_cells_and_distances_through_property_maps)
{
  const Mesh& m = test_mesh("elephant");
  const std::vector<Face_location> sources = some_sources(m);
  // without a map: the deprecated vectors, by vertex index
  const auto old_way = CGAL_ext::geodesic_voronoi_diagram(m, sources);
  ASSERT_EQ(old_way.vertex_cell.size(), m.number_of_vertices());

  std::vector<long> cell(m.number_of_vertices(), 99);
  std::vector<double> distance(m.number_of_vertices(), -1);
  CGAL_ext::Geodesic_statistics stats;
  stats.windows_created = 123456789; // must be overwritten
  const auto diagram = CGAL_ext::geodesic_voronoi_diagram(
    m, sources,
    CGAL_ext::parameters::vertex_source_map(CGAL::make_property_map(cell))
      .vertex_distance_map(CGAL::make_property_map(distance))
      .statistics(stats));
  EXPECT_TRUE(diagram.vertex_cell.empty()) << "the vectors are left empty when the maps are given";
  EXPECT_TRUE(diagram.vertex_distance.empty());
  std::size_t in_a_cell = 0;
  for(std::size_t v = 0; v < m.number_of_vertices(); ++v) {
    const std::size_t c = old_way.vertex_cell[v];
    EXPECT_EQ(cell[v], c == CGAL_ext::no_source ? -1L : long(c)) << "vertex " << v;
    EXPECT_EQ(distance[v], old_way.vertex_distance[v]) << "vertex " << v;
    in_a_cell += cell[v] >= 0 ? 1 : 0;
  }
  EXPECT_EQ(in_a_cell, m.number_of_vertices());
  // the same distances as geodesic_distances() from the same sources, and the same cells
  std::vector<double> solved(m.number_of_vertices());
  std::vector<long> nearest(m.number_of_vertices());
  CGAL_ext::geodesic_distances(m, CGAL::make_property_map(solved), sources,
                               CGAL_ext::parameters::vertex_source_map(CGAL::make_property_map(nearest)));
  EXPECT_EQ(distance, solved);
  EXPECT_EQ(cell, nearest);
  EXPECT_EQ(diagram.dual_edges, old_way.dual_edges);

  EXPECT_EQ(stats.vertices, m.number_of_vertices());
  EXPECT_EQ(stats.faces, m.number_of_faces());
  EXPECT_GT(stats.windows_created, 0u);
  EXPECT_NE(stats.windows_created, 123456789u);
  EXPECT_GT(stats.windows_stored, 0u);
  EXPECT_GT(stats.seconds_diagram, 0.);
  EXPECT_GE(stats.seconds_setup, 0.);
}

TEST(Conventions, paths_statistics_through_the_named_parameter)
{
  const Mesh& m = test_mesh("mushroom");
  CGAL_ext::Surface_mesh_geodesic_paths<Mesh> paths(m);
  paths.add_source(Vertex(0));
  CGAL_ext::Geodesic_statistics stats;
  paths.build(CGAL_ext::parameters::statistics(stats));
  EXPECT_GT(stats.windows_stored, 0u);
  EXPECT_EQ(stats.vertices, m.number_of_vertices());
  EXPECT_EQ(paths.statistics().windows_stored, stats.windows_stored); // the deprecated accessor agrees
  EXPECT_EQ(paths.statistics().windows_created, stats.windows_created);
}

TEST(Conventions, matrix_statistics_sum_the_rows)
{
  const Mesh& m = test_mesh("mushroom");
  const std::vector<Vertex> sources = {Vertex(0), Vertex(100), Vertex(300), Vertex(700), Vertex(1000)};
  std::size_t windows = 0, popped = 0, peak = 0;
  for(Vertex s : sources) {
    CGAL_ext::Geodesic_statistics one;
    std::vector<double> d(m.number_of_vertices());
    CGAL_ext::geodesic_distances(m, CGAL::make_property_map(d), s, CGAL_ext::parameters::statistics(one));
    windows += one.windows_created;
    popped += one.vertices_popped;
    peak = std::max(peak, one.peak_windows);
  }
  ASSERT_GT(windows, 0u);
  const auto check = [&](const CGAL_ext::Geodesic_statistics& s, const std::string& what) {
    EXPECT_EQ(s.windows_created, windows) << what;
    EXPECT_EQ(s.vertices_popped, popped) << what;
    EXPECT_EQ(s.peak_windows, peak) << what;
    EXPECT_EQ(s.vertices, m.number_of_vertices()) << what;
    EXPECT_GT(s.seconds_solve, 0.) << what;
  };
  CGAL_ext::Geodesic_statistics dense;
  CGAL_ext::geodesic_distance_matrix(m, sources, CGAL_ext::parameters::statistics(dense));
  check(dense, "dense, sequential");
  for(int threads : {1, 2, 4}) {
    CGAL_ext::Geodesic_statistics parallel;
    CGAL_ext::geodesic_distance_matrix<CGAL::Parallel_tag>(
      m, sources, CGAL_ext::parameters::number_of_threads(threads).statistics(parallel));
    check(parallel, "dense, " + std::to_string(threads) + " threads");
  }
  // a local matrix sweeps less
  CGAL_ext::Geodesic_statistics local;
  CGAL_ext::geodesic_sparse_distance_matrix(m, sources,
                                            CGAL_ext::parameters::max_distance(0.1 * bbox_diagonal(m)).statistics(local));
  EXPECT_GT(local.windows_created, 0u);
  EXPECT_LT(local.windows_created, windows);
}

TEST(Conventions, pattern_instances_through_a_vertex_map_and_statistics_through_the_parameter)
{
  const Pattern_scene scene = round_bumps_on_a_plane(121, 24, 0.06, 3, 0.05);
  const Mesh& m = scene.mesh;
  const auto patch = CGAL_ext::Pattern_patch<Mesh>::disk(scene.patch_centre, scene.patch_radius);
  std::vector<int> instance(m.number_of_vertices(), 99);
  CGAL_ext::Pattern_statistics stats;
  const auto found = CGAL_ext::detect_repetitive_patterns<CGAL::Parallel_if_available_tag>(
    m, patch, CGAL_ext::parameters::vertex_instance_map(CGAL::make_property_map(instance)).statistics(stats));
  ASSERT_GE(found.instances.size(), 2u);
  std::vector<int> expected(m.number_of_vertices(), -1);
  for(std::size_t i = 0; i < found.instances.size(); ++i)
    for(Vertex v : found.instances[i].vertices)
      expected[v.idx()] = int(i);
  EXPECT_EQ(instance, expected);
  EXPECT_EQ(instance[scene.patch_centre.idx()], 0) << "the marked patch is instance 0";
  // the deprecated result member agrees with what the parameter received
  EXPECT_GT(stats.samples, 0u);
  EXPECT_EQ(stats.samples, found.statistics.samples);
  EXPECT_EQ(stats.matches, found.statistics.matches);
  EXPECT_EQ(stats.seconds_sampling, found.statistics.seconds_sampling);
  EXPECT_GT(stats.seconds_sampling, 0.);
}

/// A `callback` that records the fractions it is told, and answers `go_on`.
struct Recording_callback
{
  std::vector<double> fractions;
  bool go_on = true;
  std::function<bool(double)> function()
  {
    return [this](double f) {
      fractions.push_back(f);
      return go_on;
    };
  }
  /// The fractions were in [0, 1] and never went back.
  void check(const std::string& what) const
  {
    for(std::size_t i = 0; i < fractions.size(); ++i) {
      EXPECT_GE(fractions[i], 0.) << what;
      EXPECT_LE(fractions[i], 1.) << what;
      if(i > 0)
        EXPECT_GE(fractions[i], fractions[i - 1]) << what;
    }
  }
};

/// Runs `solve(callback)` twice: told to go on, it reports and finishes; told to stop, it
/// throws Geodesic_cancelled at its first report. `solve` fills what `untouched` checks.
template <class Solve, class Untouched>
void check_callback(const std::string& what, Solve solve, Untouched untouched)
{
  Recording_callback going_on;
  solve(going_on.function());
  EXPECT_GE(going_on.fractions.size(), 1u) << what << ": the callback is called at least once";
  going_on.check(what);
  Recording_callback stopping;
  stopping.go_on = false;
  EXPECT_THROW(solve(stopping.function()), CGAL_ext::Geodesic_cancelled) << what;
  EXPECT_EQ(stopping.fractions.size(), 1u) << what << ": cancelled at the first report";
  untouched(what);
}

TEST(Conventions, callback_reports_progress_and_cancels_leaving_the_maps_untouched)
{
  const Mesh& m = test_mesh("elephant");
  const std::size_t n = m.number_of_vertices();
  std::vector<double> distance(n, -7.);
  std::vector<long> label(n, -7);
  const auto still_sentinels = [&](const std::string& what) {
    EXPECT_TRUE(std::all_of(distance.begin(), distance.end(), [](double d) { return d == -7.; })) << what;
    EXPECT_TRUE(std::all_of(label.begin(), label.end(), [](long l) { return l == -7; })) << what;
  };
  // (each solve starts from the sentinels: a cancelled one must leave them)
  const auto np_with = [&](const std::function<bool(double)>& callback) {
    std::fill(distance.begin(), distance.end(), -7.);
    std::fill(label.begin(), label.end(), -7);
    return CGAL_ext::parameters::callback(callback).vertex_source_map(CGAL::make_property_map(label));
  };
  for(const CGAL_ext::Geodesic_algorithm algorithm : {CGAL_ext::VTP, CGAL_ext::FWP_MMP, CGAL_ext::MMP}) {
    const std::string what = "geodesic_distances, algorithm " + std::to_string(int(algorithm));
    check_callback(what, [&](const std::function<bool(double)>& callback) {
      CGAL_ext::geodesic_distances(m, CGAL::make_property_map(distance), Vertex(0),
                                   np_with(callback).algorithm(algorithm));
    }, still_sentinels);
  }
  for(int threads : {1, 2, 4}) {
    const std::string what = "PVTP on " + std::to_string(threads) + " threads";
    check_callback(what, [&](const std::function<bool(double)>& callback) {
      CGAL_ext::geodesic_distances<CGAL::Parallel_tag>(m, CGAL::make_property_map(distance), Vertex(0),
                                                       np_with(callback).number_of_threads(threads));
    }, still_sentinels);
  }
  check_callback("farthest-point sampling", [&](const std::function<bool(double)>& callback) {
    std::vector<Vertex> samples;
    CGAL_ext::farthest_point_sampling(m, 20, std::back_inserter(samples),
                                      np_with(callback).vertex_distance_map(CGAL::make_property_map(distance)));
  }, still_sentinels);
  const std::vector<Vertex> rows = {Vertex(0), Vertex(100), Vertex(300), Vertex(700), Vertex(1000), Vertex(2000)};
  std::size_t rows_received = 0;
  check_callback("distance rows", [&](const std::function<bool(double)>& callback) {
    rows_received = 0;
    CGAL_ext::geodesic_distance_rows<CGAL::Parallel_tag>(
      m, rows, [&](std::size_t, const std::vector<double>&) { ++rows_received; },
      CGAL_ext::parameters::callback(callback).number_of_threads(2));
  }, [&](const std::string& what) { EXPECT_LT(rows_received, rows.size()) << what << ": the rows stop"; });
  CGAL_ext::Surface_mesh_geodesic_paths<Mesh> paths(m);
  paths.add_source(Vertex(0));
  check_callback("paths build", [&](const std::function<bool(double)>& callback) {
    paths.build(CGAL_ext::parameters::callback(callback));
  }, [&](const std::string& what) { EXPECT_FALSE(paths.is_built()) << what; });
}

} // namespace conventions
