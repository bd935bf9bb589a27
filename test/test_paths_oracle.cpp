// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Surface_mesh_geodesic_paths (MMP, FWP-MMP, PMMP, and built from VTP's windows) on real meshes:
// exact distances at vertices and at any point of a face, nearest sources and shortest paths, against the oracle
// CGAL::Surface_mesh_shortest_path and against the exact VTP solver.
//
// Tolerances: distances within 1e-9 of the bounding-box diagonal of the oracle's and 1e-12 of
// VTP's; a path's length within 1e-9 (relative) of the target's distance and of the oracle's
// path. Paths are compared with the oracle's polyline point by point (1e-6 of the diagonal); a
// target with two shortest paths may get either, so only a fraction of them is required to be
// close, while the lengths must always agree. The oracle is wrong at some points of border edges
// (see Oracle_paths in support/oracle.h): there the reference is VTP at a vertex inserted at the
// point.
//
// The other source of test_paths, test_paths_analytic_and_api.cpp, has the surfaces with
// closed-form distances and the contract of the class (bad input, edge cases, const queries
// from several threads). PMMP's bit-identical distances and paths for every number of threads
// are tested in test_parallel.cpp, which is also run under ThreadSanitizer.

#include "support/checks.h"
#include "support/geodesic_paths.h"
#include "support/mesh_transformations.h"
#include "support/oracle.h"
#include "support/path_checks.h"
#include "support/solve.h"

#include <CGAL_ext/Geodesics_3/polyline_length.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

using namespace test_support;
namespace params = CGAL_ext::parameters;

namespace {

const double oracle_tolerance = 1e-9; // max |ours - oracle| / diagonal
const double close_tolerance = 1e-6;  // a point of our path to the oracle's polyline / diagonal
const double close_fraction = 0.95;   // of the paths, at least this many close to the oracle's

/// VTP from each source alone
std::vector<std::vector<double>> per_source_distances(const Mesh& m, const Sources& s)
{
  std::vector<std::vector<double>> d;
  for(Vertex v : s.vertices)
    d.push_back(solve(m, v));
  for(const Face_location& l : s.faces)
    d.push_back(solve(m, l));
  return d;
}

/// Checks nearest_source(v) at every vertex: the distance from the named source alone (VTP) is
/// the distance (so a tie may name either), and no_source exactly where the distance is infinite.
template <class P>
::testing::AssertionResult nearest_sources_are_right(const Mesh& m, const P& p,
                                                     const std::vector<std::vector<double>>& per_source)
{
  const double eps = 2 * vtp_tolerance * bbox_diagonal(m);
  for(Vertex v : m.vertices()) {
    const double d = p.distance(v);
    const std::size_t ns = p.nearest_source(v);
    if(std::isinf(d)) {
      if(ns != P::no_source)
        return ::testing::AssertionFailure() << "unreachable vertex " << v << " has nearest source " << ns;
      continue;
    }
    if(ns >= per_source.size())
      return ::testing::AssertionFailure() << "vertex " << v << " at " << d << " has nearest source " << ns << " of "
                                           << per_source.size();
    if(!(std::abs(per_source[ns][v.idx()] - d) <= eps)) {
      std::ostringstream msg;
      msg.precision(17);
      msg << "vertex " << v << " at " << d << " names source " << ns << " which is at " << per_source[ns][v.idx()]
          << "; each source:";
      for(const auto& ds : per_source)
        msg << " " << ds[v.idx()];
      return ::testing::AssertionFailure() << msg.str();
    }
  }
  return ::testing::AssertionSuccess();
}

// Every algorithm, through geodesic_distances() and through the class, against the oracle and
// VTP; nearest sources against VTP from each source alone.
void check_vertex_distances(const Mesh& m, const Sources& s, const std::string& label)
{
  const double diag = bbox_diagonal(m);
  const std::vector<double> reference = oracle(m, s.vertices, s.faces);
  const std::vector<double> vtp = solve_mixed(m, s.vertices, s.faces);
  ASSERT_TRUE(agrees(vtp, reference, diag, oracle_tolerance, label + " VTP (the reference's check)"));

  auto mmp = built<Paths>(m, s, params::algorithm(CGAL_ext::MMP));
  auto fwp = built<Paths>(m, s, params::algorithm(CGAL_ext::FWP_MMP));
  auto pmmp = built<Parallel_paths>(m, s, params::number_of_threads(2).algorithm(CGAL_ext::FWP_MMP));
  auto vtp_windows = built<Paths>(m, s, params::algorithm(CGAL_ext::VTP));
  auto pvtp_windows = built<Parallel_paths>(m, s, params::algorithm(CGAL_ext::VTP).number_of_threads(2));
  const std::vector<std::pair<std::string, std::vector<double>>> runs = {
    {"geodesic_distances MMP", solve_mixed(m, s.vertices, s.faces, params::algorithm(CGAL_ext::MMP))},
    {"geodesic_distances FWP-MMP", solve_mixed(m, s.vertices, s.faces, params::algorithm(CGAL_ext::FWP_MMP))},
    {"geodesic_distances PMMP", solve_mixed<CGAL::Parallel_tag>(
                                  m, s.vertices, s.faces, params::algorithm(CGAL_ext::FWP_MMP).number_of_threads(2))},
    {"class MMP", class_distances(m, *mmp)},
    {"class FWP-MMP", class_distances(m, *fwp)},
    {"class PMMP", class_distances(m, *pmmp)},
    {"class VTP", class_distances(m, *vtp_windows)},
    {"class PVTP", class_distances(m, *pvtp_windows)}};
  for(const auto& r : runs) {
    EXPECT_TRUE(agrees(r.second, reference, diag, oracle_tolerance, label + " " + r.first + " vs oracle"));
    EXPECT_TRUE(agrees(r.second, vtp, diag, vtp_tolerance, label + " " + r.first + " vs VTP"));
  }
  // vertex_distances() writes what distance(v) returns
  auto map = get(CGAL::dynamic_vertex_property_t<double>(), m);
  fwp->vertex_distances(map);
  for(Vertex v : m.vertices())
    ASSERT_EQ(max_difference({get(map, v)}, {fwp->distance(v)}), 0.) << label << ", vertex " << v;

  const auto per_source = per_source_distances(m, s);
  EXPECT_TRUE(nearest_sources_are_right(m, *mmp, per_source)) << label << " MMP";
  EXPECT_TRUE(nearest_sources_are_right(m, *fwp, per_source)) << label << " FWP-MMP";
  EXPECT_TRUE(nearest_sources_are_right(m, *pmmp, per_source)) << label << " PMMP";
  EXPECT_TRUE(nearest_sources_are_right(m, *vtp_windows, per_source)) << label << " VTP";
  EXPECT_TRUE(nearest_sources_are_right(m, *pvtp_windows, per_source)) << label << " PVTP";
  if(s.vertices.size() + s.faces.size() > 1) { // every source is the nearest of some vertex
    std::vector<int> named(s.size(), 0);
    for(Vertex v : m.vertices())
      if(fwp->nearest_source(v) != Paths::no_source)
        named[fwp->nearest_source(v)] = 1;
    EXPECT_EQ(std::count(named.begin(), named.end(), 1), int(s.size())) << label;
  }
}

typedef std::tuple<const char*, Source_kind> Mesh_and_sources;

std::string mesh_and_sources_name(const ::testing::TestParamInfo<Mesh_and_sources>& i)
{
  return test_name(std::string(std::get<0>(i.param)) + "_" + source_names[std::get<1>(i.param)]);
}

/// every kind of source on the small meshes; fandisk (6.5k vertices, where the oracle is slower)
/// with fewer
std::vector<Mesh_and_sources> mesh_and_sources_cases()
{
  std::vector<Mesh_and_sources> cases;
  for(const char* name : {"elephant", "mushroom", "cactus", "knot1", "cylinder", "elephant-with-holes", "blobby_3cc"})
    for(Source_kind k : {VERTEX_SOURCE, FACE_SOURCE, EDGE_SOURCE, SEVERAL_SOURCES})
      cases.push_back(Mesh_and_sources(name, k));
  for(const char* name : {"mushroom", "cylinder", "elephant-with-holes", "blobby_3cc"})
    cases.push_back(Mesh_and_sources(name, BORDER_SOURCES));
  for(const char* name : {"elephant", "knot1", "mushroom"})
    cases.push_back(Mesh_and_sources(name, NEAR_VERTEX_SOURCE));
  cases.push_back(Mesh_and_sources("fandisk", VERTEX_SOURCE));
  cases.push_back(Mesh_and_sources("fandisk", EDGE_SOURCE));
  return cases;
}

// ---------------------------------------------------------------------------------------------
// Vertex distances on CGAL's meshes and on transformed copies

class Vertex_distances : public ::testing::TestWithParam<Mesh_and_sources> {};

TEST_P(Vertex_distances, MatchOracleAndVtp)
{
  const std::string name = std::get<0>(GetParam());
  const Mesh& m = test_mesh(name);
  const Sources s = make_sources(m, std::get<1>(GetParam()));
  check_vertex_distances(m, s, name + " " + source_names[std::get<1>(GetParam())]);
  if(name == "blobby_3cc") { // three components: the other two are unreachable from one source
    auto fwp = built<Paths>(m, s, params::algorithm(CGAL_ext::FWP_MMP));
    std::size_t unreachable = 0;
    for(Vertex v : m.vertices())
      unreachable += std::isinf(fwp->distance(v));
    if(s.size() == 1) {
      EXPECT_GT(unreachable, m.number_of_vertices() / 10);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Paths, Vertex_distances, ::testing::ValuesIn(mesh_and_sources_cases()),
                         mesh_and_sources_name);
// man: 17k vertices, slivers of 0.03 degree, and the oracle is slow there
INSTANTIATE_TEST_SUITE_P(PathsLarger, Vertex_distances,
                         ::testing::Values(std::make_tuple("fandisk", SEVERAL_SOURCES),
                                           std::make_tuple("man", SEVERAL_SOURCES)),
                         mesh_and_sources_name);

class Transformed_distances : public ::testing::TestWithParam<std::tuple<const char*, Transform>> {};

TEST_P(Transformed_distances, MatchOracleAndVtp)
{
  const std::string name = std::get<0>(GetParam());
  const Mesh m = transformed(test_mesh(name), std::get<1>(GetParam()));
  check_vertex_distances(m, make_sources(m, SEVERAL_SOURCES), name + " " + transform_names[std::get<1>(GetParam())]);
}

INSTANTIATE_TEST_SUITE_P(Paths, Transformed_distances,
                         ::testing::Values(std::make_tuple("elephant", SCALED_DOWN),
                                           std::make_tuple("mushroom", SCALED_UP),
                                           std::make_tuple("cactus", LOOP_SUBDIVIDED),
                                           std::make_tuple("knot1", JITTERED),
                                           std::make_tuple("fandisk", JITTERED),
                                           std::make_tuple("elephant", CUT_OPEN)),
                         [](const ::testing::TestParamInfo<std::tuple<const char*, Transform>>& i) {
                           return test_name(std::string(std::get<0>(i.param)) + "_" +
                                            transform_names[std::get<1>(i.param)]);
                         });

// Meshes without the oracle: bunny00 (37.7k vertices, too slow for it) and oblong (slivers of
// 0.013 degree, where it is wrong, see test_oracle.cpp): against VTP, and paths whose length is
// the distance.
class Without_oracle : public ::testing::TestWithParam<const char*> {};

TEST_P(Without_oracle, MatchVtpAndPathsHaveTheirLength)
{
  const std::string name = GetParam();
  const Mesh& m = test_mesh(name);
  const double diag = bbox_diagonal(m);
  Sources s;
  s.vertices = {Vertex(168)};
  s.faces = {location(m.number_of_faces() / 2, 0.3, 0.3)};
  const std::vector<double> vtp = solve_mixed(m, s.vertices, s.faces);
  auto fwp = built<Paths>(m, s, params::algorithm(CGAL_ext::FWP_MMP));
  auto pmmp = built<Parallel_paths>(m, s, params::number_of_threads(2).algorithm(CGAL_ext::FWP_MMP));
  EXPECT_TRUE(agrees(class_distances(m, *fwp), vtp, diag, vtp_tolerance, name + " class FWP-MMP vs VTP"));
  EXPECT_TRUE(agrees(class_distances(m, *pmmp), vtp, diag, vtp_tolerance, name + " class PMMP vs VTP"));
  EXPECT_TRUE(agrees(solve_mixed(m, s.vertices, s.faces, params::algorithm(CGAL_ext::MMP)), vtp, diag, vtp_tolerance,
                     name + " geodesic_distances MMP vs VTP"));
  double worst = 0;
  for(Vertex v : spread_vertices(m, 40, 9)) {
    const std::vector<Path_point> path = surface_path(*fwp, v);
    ASSERT_TRUE(is_valid_path(m, path)) << name << ", vertex " << v;
    const double d = fwp->distance(v), length = CGAL_ext::polyline_length(positions(path));
    EXPECT_LE(std::abs(length - d), length_tolerance * d) << name << ", vertex " << v;
    worst = std::max(worst, std::abs(length - d) / d);
  }
  std::cout << "[ paths    ] " << name << ": |length - distance| / distance <= " << worst << std::endl;
}

INSTANTIATE_TEST_SUITE_P(Paths, Without_oracle, ::testing::Values("oblong", "bunny00"),
                         [](const ::testing::TestParamInfo<const char*>& i) { return std::string(i.param); });

// ---------------------------------------------------------------------------------------------
// Distances at face points (inside faces, on edges, at corners) against the oracle

class Face_point_distances : public ::testing::TestWithParam<Mesh_and_sources> {};

TEST_P(Face_point_distances, MatchOracle)
{
  const std::string name = std::get<0>(GetParam());
  const Source_kind kind = std::get<1>(GetParam());
  const std::string label = name + " " + source_names[kind];
  const Mesh& m = test_mesh(name);
  const double diag = bbox_diagonal(m);
  const Sources s = make_sources(m, kind);
  Oracle_paths reference(m, s.vertices, s.faces);
  auto mmp = built<Paths>(m, s, params::algorithm(CGAL_ext::MMP));
  auto fwp = built<Paths>(m, s, params::algorithm(CGAL_ext::FWP_MMP));
  auto pmmp = built<Parallel_paths>(m, s, params::algorithm(CGAL_ext::FWP_MMP));
  auto vtp_windows = built<Paths>(m, s, params::algorithm(CGAL_ext::VTP));
  // each source alone, for the nearest source: the oracle on small meshes, else our own FWP-MMP
  // (checked against the oracle from single sources by the other cases)
  std::vector<std::unique_ptr<Oracle_paths>> alone;
  std::vector<std::unique_ptr<Paths>> alone_ours;
  if(s.size() > 1) {
    for(std::size_t i = 0; i < s.size(); ++i) {
      Sources one;
      if(i < s.vertices.size())
        one.vertices = {s.vertices[i]};
      else
        one.faces = {s.faces[i - s.vertices.size()]};
      if(m.number_of_vertices() < 3000)
        alone.emplace_back(new Oracle_paths(m, one.vertices, one.faces));
      else
        alone_ours.push_back(built<Paths>(m, one));
    }
  }
  double worst[4] = {0, 0, 0, 0};
  std::size_t checked = 0, on_edges = 0, on_border = 0, oracle_wrong_on_border = 0;
  for(const Face_location& t : face_targets(m, 240, 5)) {
    if(!reference.can_query(t.first))
      continue;
    ++checked;
    // the oracle, except on border edges where it is sometimes wrong (see Oracle_paths)
    double o = reference.distance(t);
    if(on_border_edge(m, t)) {
      ++on_border;
      const double exact = distance_at_edge_point(m, s.vertices, s.faces, t);
      oracle_wrong_on_border += !(max_difference({o}, {exact}) <= oracle_tolerance * diag);
      o = exact;
    }
    const double d[4] = {mmp->distance(t), fwp->distance(t), pmmp->distance(t), vtp_windows->distance(t)};
    for(int a = 0; a < 4; ++a) {
      const double e = max_difference({d[a]}, {o});
      if(e > oracle_tolerance * diag)
        ADD_FAILURE() << label << ": algorithm " << a << " (MMP, FWP-MMP, PMMP, VTP) at " << describe_target(t) << ": "
                      << d[a] << ", reference " << o;
      worst[a] = std::max(worst[a], e / diag);
    }
    if(zero_coordinates(t.second) == 2) { // a corner is the vertex
      const auto c = face_corners(m, t.first);
      for(int k = 0; k < 3; ++k)
        if(t.second[k] == 1) {
          EXPECT_EQ(max_difference({d[1]}, {fwp->distance(c[k])}), 0.) << label << ", corner of face " << t.first;
        }
    }
    if(zero_coordinates(t.second) == 1 && !on_border_edge(m, t)) { // the same edge point seen from the face across
      const Face_location other = across(m, t);
      ++on_edges;
      EXPECT_LE(max_difference({fwp->distance(other)}, {d[1]}), vtp_tolerance * diag)
        << label << ", edge point " << describe_target(t) << " seen from face " << other.first;
      EXPECT_EQ(fwp->nearest_source(other), fwp->nearest_source(t)) << label << ", " << describe_target(t);
    }
    const std::size_t ns = fwp->nearest_source(t);
    if(std::isinf(d[1])) {
      EXPECT_EQ(ns, Paths::no_source) << label << ", " << describe_target(t);
      EXPECT_EQ(mmp->nearest_source(t), Paths::no_source) << label << ", " << describe_target(t);
      EXPECT_EQ(pmmp->nearest_source(t), Parallel_paths::no_source) << label << ", " << describe_target(t);
      EXPECT_EQ(vtp_windows->nearest_source(t), Paths::no_source) << label << ", " << describe_target(t);
      continue;
    }
    ASSERT_LT(ns, s.size()) << label << ", " << describe_target(t);
    if(s.size() == 1) {
      EXPECT_EQ(ns, 0u);
      continue;
    }
    for(const std::size_t n : {ns, mmp->nearest_source(t), pmmp->nearest_source(t), vtp_windows->nearest_source(t)}) {
      ASSERT_LT(n, s.size());
      const double named = alone.empty() ? alone_ours[n]->distance(t) : alone[n]->distance(t);
      EXPECT_LE(std::abs(named - d[1]), oracle_tolerance * diag)
        << label << ": " << describe_target(t) << " at " << d[1] << " names source " << n << " at " << named;
    }
  }
  std::cout << "[ error    ] " << label << ": " << checked << " face points (" << on_edges << " on inner edges, "
            << on_border << " on border edges, where the oracle was wrong at " << oracle_wrong_on_border
            << "), max |ours - reference| / diag = " << worst[0] << " (MMP), " << worst[1] << " (FWP-MMP), "
            << worst[2] << " (PMMP), " << worst[3] << " (VTP)" << std::endl;
  EXPECT_GT(checked, 200u);
}

INSTANTIATE_TEST_SUITE_P(Paths, Face_point_distances, ::testing::ValuesIn(mesh_and_sources_cases()),
                         mesh_and_sources_name);

// ---------------------------------------------------------------------------------------------
// Shortest paths

/// What the path checks measured over many targets.
struct Path_statistics
{
  std::size_t paths = 0, unreachable = 0, without_oracle_path = 0, close = 0, vertices_passed = 0, points = 0;
  double worst_length = 0;      // |length - distance| / distance
  double worst_oracle = 0;      // |distance - oracle| / diagonal
  double worst_oracle_length = 0; // |length - oracle's path length| / oracle's
  double worst_far = 0;         // max distance of our points to the oracle's polyline / diagonal
  std::vector<std::string> not_close;

  void print(const std::string& label) const
  {
    std::cout << "[ paths    ] " << label << ": " << paths << " paths (" << points << " points, " << vertices_passed
              << " through vertices), " << unreachable << " unreachable, " << without_oracle_path
              << " on border edges (no oracle path); |length - distance| / distance <= "
              << worst_length << ", |distance - oracle| / diag <= " << worst_oracle
              << ", |length - oracle length| / length <= " << worst_oracle_length << "; " << close << " of "
              << paths - unreachable - without_oracle_path << " within " << close_tolerance << " diag of the oracle's path (farthest "
              << worst_far << " diag)" << std::endl;
    for(const std::string& s : not_close)
      std::cout << "[ paths    ]   not close: " << s << std::endl;
  }
};

/// The reference distance of a target: the oracle's, except at points of border edges where it
/// is sometimes wrong (see Oracle_paths): there, VTP's at a vertex inserted at the point.
double reference_distance(const Mesh&, const Sources&, Oracle_paths& reference, Vertex v)
{
  return reference.distance(v);
}
double reference_distance(const Mesh& m, const Sources& s, Oracle_paths& reference, const Face_location& l)
{
  return on_border_edge(m, l) ? distance_at_edge_point(m, s.vertices, s.faces, l) : reference.distance(l);
}
bool oracle_path_is_unreliable(const Mesh&, Vertex) { return false; }
bool oracle_path_is_unreliable(const Mesh& m, const Face_location& l) { return on_border_edge(m, l); }

/// Every check of one path of `paths` to `target`: the three query forms agree, the path is
/// valid, starts at its nearest source and ends at the target, its length is the distance; the
/// distance and the path against the oracle's.
template <class P, class Target>
void check_path(const Mesh& m, const Sources& s, const P& paths, const Target& target, Oracle_paths& reference,
                Path_statistics& stats, const std::string& label)
{
  const double diag = bbox_diagonal(m);
  const std::string where = label + ", target " + describe_target(target);
  std::vector<typename P::Path_point> surface;
  paths.shortest_path_surface_points(target, std::back_inserter(surface));
  std::vector<Point> points;
  paths.shortest_path_points(target, std::back_inserter(points));
  typedef typename P::Path_point Point_of_path;
  const Recorder<Point_of_path> visited = paths.shortest_path_sequence(target, Recorder<Point_of_path>());
  const double d = paths.distance(target);
  const double o = reference_distance(m, s, reference, target);
  ++stats.paths;
  if(std::isinf(d)) {
    ++stats.unreachable;
    EXPECT_TRUE(surface.empty() && points.empty() && visited.points.empty()) << where << ": unreachable, yet a path";
    EXPECT_TRUE(std::isinf(o)) << where << ": the oracle reaches it at " << o;
    EXPECT_EQ(paths.nearest_source(target), P::no_source) << where;
    return;
  }
  ASSERT_TRUE(is_valid_path(m, surface)) << where;
  EXPECT_EQ(points, positions(surface)) << where << ": shortest_path_points differs";
  EXPECT_TRUE(same_places(visited.points, surface)) << where << ": shortest_path_sequence differs";
  const std::size_t ns = paths.nearest_source(target);
  ASSERT_LT(ns, s.size()) << where;
  EXPECT_TRUE(starts_at_source(m, s, ns, surface.front())) << where;
  EXPECT_TRUE(ends_at_target(m, target, surface.back())) << where;
  stats.points += surface.size();
  for(std::size_t i = 1; i + 1 < surface.size(); ++i)
    stats.vertices_passed += surface[i].kind == Point_of_path::VERTEX;

  const double length = CGAL_ext::polyline_length(points);
  const double length_error = d > 0 ? std::abs(length - d) / d : length;
  EXPECT_LE(length_error, length_tolerance) << where << ": length " << length << ", distance " << d;
  stats.worst_length = std::max(stats.worst_length, length_error);
  const double oracle_error = max_difference({d}, {o}) / diag;
  EXPECT_LE(oracle_error, oracle_tolerance) << where << ": distance " << d << ", oracle " << o;
  stats.worst_oracle = std::max(stats.worst_oracle, oracle_error);

  if(oracle_path_is_unreliable(m, target)) {
    ++stats.without_oracle_path;
    return;
  }
  const std::vector<Point> theirs = reference.path(target);
  ASSERT_FALSE(theirs.empty()) << where << ": the oracle has no path";
  const double their_length = CGAL_ext::polyline_length(theirs);
  const double oracle_length_error = length > 0 ? std::abs(length - their_length) / length : their_length;
  EXPECT_LE(oracle_length_error, length_tolerance) << where << ": length " << length << ", oracle's " << their_length;
  stats.worst_oracle_length = std::max(stats.worst_oracle_length, oracle_length_error);
  const double far = std::max(max_distance_to_polyline(points, theirs), max_distance_to_polyline(theirs, points)) / diag;
  stats.worst_far = std::max(stats.worst_far, far);
  if(far <= close_tolerance)
    ++stats.close;
  else {
    std::ostringstream msg;
    msg << describe_target(target) << " (" << surface.size() << " points, the oracle's " << theirs.size() << ", "
        << far << " diag apart, length " << length << ")";
    stats.not_close.push_back(msg.str());
  }
}

class Shortest_paths : public ::testing::TestWithParam<Mesh_and_sources> {};

TEST_P(Shortest_paths, ValidAndMatchOracle)
{
  const std::string name = std::get<0>(GetParam());
  const Source_kind kind = std::get<1>(GetParam());
  const Mesh& m = test_mesh(name);
  const Sources s = make_sources(m, kind);
  Oracle_paths reference(m, s.vertices, s.faces);
  auto mmp = built<Paths>(m, s, params::algorithm(CGAL_ext::MMP));
  auto fwp = built<Paths>(m, s, params::algorithm(CGAL_ext::FWP_MMP));
  auto pmmp = built<Parallel_paths>(m, s, params::algorithm(CGAL_ext::FWP_MMP));
  auto vtp_windows = built<Paths>(m, s, params::algorithm(CGAL_ext::VTP));
  const std::vector<Vertex> vertex_targets = spread_vertices(m, 30, 101);
  std::vector<Face_location> face_targets_kept;
  for(const Face_location& l : face_targets(m, 30, 3))
    if(reference.can_query(l.first))
      face_targets_kept.push_back(l);
  Path_statistics all;
  const char* algorithm_names[] = {"MMP", "FWP-MMP", "PMMP", "VTP"};
  for(int a = 0; a < 4; ++a) {
    const std::string label = name + " " + source_names[kind] + " " + algorithm_names[a];
    Path_statistics stats;
    auto check = [&](const auto& target) { // the build of algorithm a
      if(a == 0)
        check_path(m, s, *mmp, target, reference, stats, label);
      else if(a == 1)
        check_path(m, s, *fwp, target, reference, stats, label);
      else if(a == 2)
        check_path(m, s, *pmmp, target, reference, stats, label);
      else
        check_path(m, s, *vtp_windows, target, reference, stats, label);
    };
    for(Vertex v : vertex_targets)
      check(v);
    for(const Face_location& l : face_targets_kept)
      check(l);
    stats.print(label);
    const std::size_t reachable = stats.paths - stats.unreachable - stats.without_oracle_path;
    EXPECT_GE(double(stats.close), close_fraction * double(reachable)) << label;
  }
}

INSTANTIATE_TEST_SUITE_P(Paths, Shortest_paths, ::testing::ValuesIn(mesh_and_sources_cases()),
                         mesh_and_sources_name);

// ---------------------------------------------------------------------------------------------
// Points where the oracle cannot be trusted, or where round-off of the windows matters: points of
// border edges (the oracle is sometimes wrong there, see Oracle_paths), and points within 1e-9
// of a corner or 1e-10 of an edge. The reference is VTP at a vertex inserted at the point (the
// same surface, refined).
class Inserted_vertex_reference : public ::testing::TestWithParam<const char*> {};

TEST_P(Inserted_vertex_reference, BorderEdgesAndNearlyCorners)
{
  const std::string name = GetParam();
  const Mesh& m = test_mesh(name);
  const double diag = bbox_diagonal(m);
  const Sources s{spread_vertices(m, 2, 17), {}};
  auto fwp = built<Paths>(m, s, params::algorithm(CGAL_ext::FWP_MMP));
  auto mmp = built<Paths>(m, s, params::algorithm(CGAL_ext::MMP));
  Oracle_paths reference(m, s.vertices);
  std::vector<Face_location> targets;
  std::vector<Mesh::Halfedge_index> border;
  for(auto h : m.halfedges())
    if(m.is_border(h))
      border.push_back(h);
  for(std::size_t i = 0; i < 40 && !border.empty(); ++i) { // points of border edges
    const auto h = m.opposite(border[(i * border.size()) / 40]);
    const auto c = face_corners(m, m.face(h));
    const double t = 0.05 + 0.9 * double((i * 7) % 40) / 40;
    Barycentric b{{0., 0., 0.}};
    for(int k = 0; k < 3; ++k)
      b[k] = c[k] == m.source(h) ? 1 - t : (c[k] == m.target(h) ? t : 0.);
    targets.push_back(Face_location(m.face(h), b));
  }
  const std::size_t nf = m.number_of_faces();
  for(std::size_t i = 0; i < 40; ++i) { // near a corner, near an edge
    const int k = int(i % 3);
    Barycentric b{{0., 0., 0.}};
    if(i % 2) {
      b[k] = 1 - 2e-9;
      b[(k + 1) % 3] = b[(k + 2) % 3] = 1e-9;
    } else {
      b[k] = 0.3 + 0.01 * double(i);
      b[(k + 1) % 3] = 1 - b[k] - 1e-10;
      b[(k + 2) % 3] = 1e-10;
    }
    targets.push_back(Face_location(Face(static_cast<Mesh::size_type>((i * 7919) % nf)), b));
  }
  double worst = 0, worst_below = 0, worst_oracle = 0;
  std::size_t oracle_wrong = 0, reachable = 0;
  for(const Face_location& t : targets) {
    const double exact = zero_coordinates(t.second) == 1 ? distance_at_edge_point(m, s.vertices, s.faces, t)
                                              : distance_at_face_point(m, s.vertices, s.faces, t);
    const double d = fwp->distance(t), o = reference.distance(t);
    EXPECT_LE(max_difference({d}, {exact}), oracle_tolerance * diag)
      << name << ", " << describe_target(t) << ": " << d << ", exact " << exact;
    EXPECT_LE(max_difference({mmp->distance(t)}, {exact}), oracle_tolerance * diag) << name << ", " << describe_target(t);
    if(std::isinf(exact))
      continue;
    ++reachable;
    worst = std::max(worst, std::abs(d - exact) / diag);
    worst_below = std::max(worst_below, (exact - d) / diag);
    worst_oracle = std::max(worst_oracle, std::abs(o - exact) / diag);
    oracle_wrong += !(std::abs(o - exact) <= oracle_tolerance * diag);
    const std::vector<Path_point> path = surface_path(*fwp, t);
    ASSERT_TRUE(is_valid_path(m, path)) << name << ", " << describe_target(t);
    EXPECT_TRUE(ends_at_target(m, t, path.back())) << name << ", " << describe_target(t);
    EXPECT_LE(std::abs(CGAL_ext::polyline_length(positions(path)) - d), length_tolerance * d)
      << name << ", " << describe_target(t);
  }
  std::cout << "[ error    ] " << name << ": " << reachable << " points of border edges and near corners and edges: max "
            << "|ours - exact| / diag = " << worst << " (below the exact distance by up to " << worst_below
            << "); the oracle: max " << worst_oracle << ", wrong (> 1e-9 diag) at " << oracle_wrong << std::endl;
  EXPECT_GT(reachable, 20u);
}

INSTANTIATE_TEST_SUITE_P(Paths, Inserted_vertex_reference,
                         ::testing::Values("elephant-with-holes", "blobby_3cc", "mushroom", "elephant"),
                         [](const ::testing::TestParamInfo<const char*>& i) { return test_name(i.param); });

} // namespace
