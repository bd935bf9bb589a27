// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Surface_mesh_geodesic_paths (MMP, FWP-MMP, PMMP) where no oracle is needed: on surfaces whose
// distances and shortest paths are known in closed form (flat grids with straight paths and
// Euclidean distances, around a reflex corner; an open cylinder and a cone through their
// developments; a cube), and the contract of the class (the input it refuses, queries before
// build(), sources given twice, unreachable targets, max_distance, a target at a source, refused
// builds and moves, coordinates within round-off of an edge or a corner, const queries from
// several threads at once).
//
// Both are in one source, apart from test_paths_oracle.cpp: every source of test_paths compiles
// the class (sequential and parallel) anew, which costs more than these tests add.

#include "support/analytic_surfaces.h"
#include "support/checks.h"
#include "support/geodesic_paths.h"
#include "support/path_checks.h"
#include "support/solve.h"

#include <CGAL_ext/Geodesics_3/polyline_length.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

using namespace test_support;
namespace params = CGAL_ext::parameters;

namespace {

// ---------------------------------------------------------------------------------------------
// Analytic surfaces: flat grids (straight paths, Euclidean distances, around a reflex corner),
// an open cylinder and a cone (their developments), a cube

const double analytic_tolerance = 1e-12; // relative, distances (path lengths: length_tolerance)
// A path's points off the exact straight segment, / diagonal. Most are within 1e-15, but a target
// 1e-9 (barycentric) from a border corner of the flat grid gets a path that hugs the border edge
// and rises near the end, 5.9e-11 of the diagonal (1.3e-9 of an edge) off the segment: the tracer
// accepts a ray up to 1e-9 of an edge outside a window's interval and clamps the crossing. Such
// paths are longer than the distance by up to 8e-12 (relative) on the jittered grid.
const double straight_tolerance = 1e-9;

/// the largest distance of a path's points to the segment [a, b], and whether they go along it
/// from a to b (their projections never step back by more than `slack`)
double off_segment(const std::vector<Point>& path, const Point& a, const Point& b, bool& monotone, double slack)
{
  double off = 0, last = -inf;
  monotone = true;
  const Vector ab = b - a;
  for(const Point& p : path) {
    off = std::max(off, a == b ? distance_3(p, a) : std::sqrt(CGAL::squared_distance(p, K::Segment_3(a, b))));
    const double along = a == b ? 0. : ((p - a) * ab) / std::sqrt(ab.squared_length());
    monotone = monotone && along >= last - slack;
    last = along;
  }
  return off;
}

struct Grid_case
{
  const char* name;
  double jitter;
  bool face_source;
};

std::ostream& operator<<(std::ostream& os, const Grid_case& c) { return os << c.name; }

class Flat_grid : public ::testing::TestWithParam<Grid_case> {};

// On a flat convex grid every shortest path is the straight segment and every distance the
// Euclidean one, from a corner vertex or a face point, to vertices and face points.
TEST_P(Flat_grid, StraightPathsAndEuclideanDistances)
{
  const Grid_case& c = GetParam();
  const Mesh m = make_grid(21, 0.1, c.jitter);
  const double diag = bbox_diagonal(m);
  Sources s;
  if(c.face_source)
    s.faces = {location(301, 0.2, 0.3)};
  else
    s.vertices = {Vertex(0)}; // the corner (0, 0)
  const Point from = c.face_source ? location_point(m, s.faces[0]) : m.point(Vertex(0));
  for(int a = 0; a < 3; ++a) {
    std::unique_ptr<Paths> p = built<Paths>(m, s, params::algorithm(a == 0 ? CGAL_ext::MMP : CGAL_ext::FWP_MMP));
    std::unique_ptr<Parallel_paths> pp;
    if(a == 2)
      pp = built<Parallel_paths>(m, s, params::algorithm(CGAL_ext::FWP_MMP));
    double worst_distance = 0, worst_length = 0, worst_off = 0;
    auto check = [&](const Point& to, double d, const std::vector<Point>& path, const std::string& what) {
      const double exact = distance_3(from, to);
      const double e = exact > 0 ? std::abs(d - exact) / exact : d;
      EXPECT_LE(e, analytic_tolerance) << c.name << ", " << what << ": " << d << ", exact " << exact;
      worst_distance = std::max(worst_distance, e);
      const double length = CGAL_ext::polyline_length(path);
      const double el = exact > 0 ? std::abs(length - exact) / exact : length;
      EXPECT_LE(el, length_tolerance) << c.name << ", " << what << ": path length " << length << ", exact " << exact;
      worst_length = std::max(worst_length, el);
      bool monotone = false;
      const double off = off_segment(path, from, to, monotone, 1e-12 * diag) / diag;
      EXPECT_LE(off, straight_tolerance) << c.name << ", " << what << ": a point of the path is off the segment";
      EXPECT_TRUE(monotone) << c.name << ", " << what << ": the path steps back";
      worst_off = std::max(worst_off, off);
    };
    for(Vertex v : m.vertices()) {
      std::vector<Point> path;
      if(a == 2) {
        pp->shortest_path_points(v, std::back_inserter(path));
        check(m.point(v), pp->distance(v), path, "vertex " + std::to_string(v.idx()));
      } else {
        EXPECT_TRUE(is_valid_path(m, surface_path(*p, v))) << c.name << ", vertex " << v;
        p->shortest_path_points(v, std::back_inserter(path));
        check(m.point(v), p->distance(v), path, "vertex " + std::to_string(v.idx()));
      }
    }
    for(const Face_location& l : face_targets(m, 200, 11)) {
      std::vector<Point> path;
      if(a == 2) {
        pp->shortest_path_points(l, std::back_inserter(path));
        check(location_point(m, l), pp->distance(l), path, describe_target(l));
      } else {
        EXPECT_TRUE(is_valid_path(m, surface_path(*p, l))) << c.name << ", " << describe_target(l);
        p->shortest_path_points(l, std::back_inserter(path));
        check(location_point(m, l), p->distance(l), path, describe_target(l));
      }
    }
    std::cout << "[ error    ] " << c.name << " (" << (a == 0 ? "MMP" : a == 1 ? "FWP-MMP" : "PMMP")
              << "): relative distance error " << worst_distance << ", path length error " << worst_length
              << ", farthest point off the segment " << worst_off << " diag" << std::endl;
  }
}

INSTANTIATE_TEST_SUITE_P(Paths, Flat_grid,
                         ::testing::Values(Grid_case{"grid_corner", 0, false}, Grid_case{"grid_face", 0, true},
                                           Grid_case{"jittered_corner", 0.2, false},
                                           Grid_case{"jittered_face", 0.2, true}),
                         [](const ::testing::TestParamInfo<Grid_case>& i) { return std::string(i.param.name); });

// In an L-shaped flat domain a target hidden from the source is reached through the reflex
// corner (a border vertex): the path passes through that vertex, straight on either side.
TEST(Paths_analytic, AroundTheReflexCornerOfAnL)
{
  const int n = 21;
  const double h = 0.1;
  const Mesh m = make_grid(n, h, 0, true);
  const L_shape l_shape = grid_l_shape(n, h);
  const Point corner(l_shape.corner.x(), l_shape.corner.y(), 0); // (1, 1)
  auto planar = [](const Point& p) { return Point_2(p.x(), p.y()); };
  Vertex source, corner_vertex;
  for(Vertex v : m.vertices()) {
    if(distance_3(m.point(v), Point(0.2, 1.8, 0)) < 1e-9)
      source = v;
    if(distance_3(m.point(v), corner) < 1e-9)
      corner_vertex = v;
  }
  ASSERT_TRUE(source.is_valid() && corner_vertex.is_valid());
  Paths p(m);
  p.add_source(source);
  p.build();
  const Point from = m.point(source);
  std::size_t hidden = 0;
  for(Vertex v : m.vertices()) {
    const Point to = m.point(v);
    const bool blocked = l_shape.hides(planar(from), planar(to));
    const double exact = l_shape.distance(planar(from), planar(to));
    EXPECT_NEAR(p.distance(v), exact, analytic_tolerance * exact) << "vertex " << v;
    const std::vector<Path_point> path = surface_path(p, v);
    ASSERT_TRUE(is_valid_path(m, path)) << "vertex " << v;
    EXPECT_NEAR(CGAL_ext::polyline_length(positions(path)), exact, length_tolerance * exact) << "vertex " << v;
    if(!blocked)
      continue;
    ++hidden;
    const auto at_corner = std::find_if(path.begin(), path.end(), [&](const Path_point& q) {
      return q.kind == Path_point::VERTEX && q.vertex == corner_vertex;
    });
    ASSERT_NE(at_corner, path.end()) << "the path to hidden vertex " << v << " does not pass the reflex corner";
    bool monotone = false;
    const std::vector<Point> points = positions(path);
    const std::size_t k = std::size_t(at_corner - path.begin());
    EXPECT_LE(off_segment(std::vector<Point>(points.begin(), points.begin() + k + 1), from, corner, monotone, 1e-12),
              1e-12);
    EXPECT_LE(off_segment(std::vector<Point>(points.begin() + k, points.end()), corner, to, monotone, 1e-12), 1e-12);
  }
  EXPECT_GT(hidden, 20u);
}

// The open cylinder develops into a periodic strip: the distance between developed points is
// the smallest over the copies shifted by the strip's width (Strip::distance).
TEST(Paths_analytic, CylinderUnrolled)
{
  const double r = 1.5, height = 4;
  const int segments = 24, rows = 10;
  const Mesh m = make_cylinder(r, segments, height, rows);
  const Strip strip = cylinder_strip(r, segments);
  const auto dev = developed_map(m);
  const Vertex source(static_cast<Mesh::size_type>((rows / 2) * segments + segments / 3));
  auto unwrap = [&](const Point_2& ref, const Point_2& q) { return strip.unwrapped(ref, q); };
  for(int a = 0; a < 2; ++a) {
    Paths p(m);
    p.add_source(source);
    p.build(params::algorithm(a == 0 ? CGAL_ext::MMP : CGAL_ext::FWP_MMP));
    for(Vertex v : m.vertices()) {
      const double exact = strip.distance(get(dev, source), get(dev, v));
      EXPECT_NEAR(p.distance(v), exact, analytic_tolerance * exact) << "vertex " << v;
      const std::vector<Path_point> path = surface_path(p, v);
      ASSERT_TRUE(is_valid_path(m, path)) << "vertex " << v;
      EXPECT_NEAR(CGAL_ext::polyline_length(positions(path)), exact, length_tolerance * exact) << "vertex " << v;
    }
    for(const Face_location& l : face_targets(m, 120, 13)) {
      const double exact = strip.distance(get(dev, source), developed_location(m, l, unwrap));
      EXPECT_NEAR(p.distance(l), exact, analytic_tolerance * exact) << describe_target(l);
      const std::vector<Path_point> path = surface_path(p, l);
      ASSERT_TRUE(is_valid_path(m, path)) << describe_target(l);
      EXPECT_NEAR(CGAL_ext::polyline_length(positions(path)), exact, length_tolerance * exact) << describe_target(l);
    }
  }
}

// The cone develops into a sector of angle theta < pi: between two points the distance is the
// planar one across the smaller angular gap (Sector::distance). Its apex is not a saddle: no
// path passes it. From the apex, every path runs straight down a generator.
TEST(Paths_analytic, ConeDeveloped)
{
  const int segments = 32, rings = 10;
  const Mesh m = make_cone(1, 4, segments, rings);
  const Sector sector = cone_sector(1, 4, segments);
  ASSERT_LT(sector.angle, pi);
  const auto dev = developed_map(m);
  const Vertex rim(static_cast<Mesh::size_type>(1 + (rings - 1) * segments + segments / 4));
  Paths p(m);
  p.add_source(rim);
  p.build();
  for(Vertex v : m.vertices()) {
    const double exact = sector.distance(get(dev, rim), get(dev, v));
    EXPECT_NEAR(p.distance(v), exact, analytic_tolerance * exact) << "vertex " << v;
    const std::vector<Path_point> path = surface_path(p, v);
    ASSERT_TRUE(is_valid_path(m, path)) << "vertex " << v; // (it never passes the apex)
    EXPECT_NEAR(CGAL_ext::polyline_length(positions(path)), exact, length_tolerance * exact) << "vertex " << v;
  }
  Paths from_apex(m);
  from_apex.add_source(Vertex(0));
  from_apex.build();
  for(Vertex v : m.vertices()) {
    const std::vector<Point> path = positions(surface_path(from_apex, v));
    bool monotone = false;
    EXPECT_LE(off_segment(path, m.point(Vertex(0)), m.point(v), monotone, 1e-12), 1e-12) << "vertex " << v;
    EXPECT_TRUE(monotone) << "vertex " << v;
    EXPECT_NEAR(CGAL_ext::polyline_length(path), distance_3(m.point(Vertex(0)), m.point(v)), 1e-12) << "vertex " << v;
  }
}

// Cube [0, s]^3 from the corner (0, 0, 0): the opposite corner at s sqrt(5), the far corners of
// the three faces through the source at s sqrt(2); corners are not saddles, so no path passes
// one.
TEST(Paths_analytic, CubeFromACorner)
{
  const double side = 2.5;
  const Mesh m = make_cube(side, 4);
  Paths p(m);
  p.add_source(Vertex(0));
  p.build();
  for(Vertex v : m.vertices()) {
    const Point& q = m.point(v);
    const std::vector<Path_point> path = surface_path(p, v);
    ASSERT_TRUE(is_valid_path(m, path)) << "vertex " << v;
    EXPECT_NEAR(CGAL_ext::polyline_length(positions(path)), p.distance(v), 1e-12 * p.distance(v)) << "vertex " << v;
    if(const std::optional<double> exact = cube_corner_distance(q, side))
      EXPECT_NEAR(p.distance(v), *exact, 1e-12 * side) << "corner " << q;
  }
}

// ---------------------------------------------------------------------------------------------
// Bad input and edge cases of the class

const double nan = std::numeric_limits<double>::quiet_NaN();

TEST(Paths_bad_input, MeshesTheConstructorRefuses)
{
  const Mesh empty;
  EXPECT_TRUE(throws_geodesic_error([&] { Paths p(empty); }, {"empty"}));
  Mesh quad = make_grid(6, 1.);
  const Vertex a(4), b(5);
  const Vertex c = quad.add_vertex(Point(5, -1, 0)), d = quad.add_vertex(Point(4, -1, 0));
  const Face f = quad.add_face(b, a, d, c);
  ASSERT_TRUE(f.is_valid());
  EXPECT_TRUE(throws_geodesic_error([&] { Paths p(quad); }, {"face " + std::to_string(f.idx()), "triangle"}));
  for(double bad : {nan, inf}) {
    Mesh m = make_grid(6, 1.);
    m.point(Vertex(14)) = Point(m.point(Vertex(14)).x(), bad, 0);
    EXPECT_TRUE(throws_geodesic_error([&] { Paths p(m); }, {"vertex 14", "non-finite"}));
    EXPECT_TRUE(throws_geodesic_error([&] { Parallel_paths p(m); }, {"vertex 14", "non-finite"}));
  }
}

TEST(Paths_bad_input, QueriesNeedBuild)
{
  const Mesh m = make_grid(6, 1.);
  Paths p(m);
  const Face_location l = location(3, 0.2, 0.3);
  std::vector<Point> points;
  std::vector<Path_point> surface;
  auto all_queries_throw = [&](const std::string& when) {
    EXPECT_FALSE(p.is_built()) << when;
    EXPECT_TRUE(throws_geodesic_error([&] { p.distance(Vertex(1)); }, {"build()"})) << when;
    EXPECT_TRUE(throws_geodesic_error([&] { p.distance(l); }, {"build()"})) << when;
    EXPECT_TRUE(throws_geodesic_error([&] { p.nearest_source(Vertex(1)); }, {"build()"})) << when;
    EXPECT_TRUE(throws_geodesic_error([&] { p.nearest_source(l); }, {"build()"})) << when;
    EXPECT_TRUE(throws_geodesic_error([&] { p.shortest_path_points(Vertex(1), std::back_inserter(points)); },
                                      {"build()"}))
      << when;
    EXPECT_TRUE(throws_geodesic_error([&] { p.shortest_path_surface_points(l, std::back_inserter(surface)); },
                                      {"build()"}))
      << when;
    EXPECT_TRUE(throws_geodesic_error([&] { p.shortest_path_sequence(l, Recorder<Path_point>()); }, {"build()"}))
      << when;
    auto map = get(CGAL::dynamic_vertex_property_t<double>(), m);
    EXPECT_TRUE(throws_geodesic_error([&] { p.vertex_distances(map); }, {"build()"})) << when;
    EXPECT_TRUE(points.empty() && surface.empty()) << when;
  };
  all_queries_throw("no source");
  EXPECT_TRUE(throws_geodesic_error([&] { p.build(); }, {"no source"}));
  all_queries_throw("after a build without sources");
  EXPECT_EQ(p.add_source(Vertex(0)), 0u);
  all_queries_throw("source added, not built");
  p.build();
  EXPECT_TRUE(p.is_built());
  EXPECT_EQ(p.distance(Vertex(0)), 0.);
  // adding a source discards the build until build() runs again
  EXPECT_EQ(p.add_source(Vertex(35)), 1u);
  all_queries_throw("second source added after build()");
  p.build();
  EXPECT_TRUE(p.is_built());
  EXPECT_EQ(p.distance(Vertex(35)), 0.);
  EXPECT_EQ(p.nearest_source(Vertex(35)), 1u);
  EXPECT_EQ(p.nearest_source(Vertex(0)), 0u);
  EXPECT_TRUE(agrees(class_distances(m, p), solve(m, std::vector<Vertex>{Vertex(0), Vertex(35)}), bbox_diagonal(m),
                     vtp_tolerance, "two sources after a rebuild"));
  p.clear_sources();
  EXPECT_EQ(p.number_of_sources(), 0u);
  all_queries_throw("sources cleared");
  EXPECT_TRUE(throws_geodesic_error([&] { p.build(); }, {"no source"}));
}

TEST(Paths_bad_input, SourcesAndTargetsOutOfRange)
{
  const Mesh m = make_grid(6, 1.); // 36 vertices, 50 faces
  Paths p(m);
  const Vertex far_vertex(36);
  const Face far_face(50);
  EXPECT_TRUE(throws_geodesic_error([&] { p.add_source(far_vertex); }, {"source vertex 36", "out of range"}));
  EXPECT_TRUE(throws_geodesic_error([&] { p.add_source(Face_location(far_face, Barycentric{{0.2, 0.3, 0.5}})); },
                                    {"source face 50", "out of range"}));
  for(const Barycentric& b : {Barycentric{{0.5, 0.6, 0.}}, Barycentric{{-0.1, 0.6, 0.5}}, Barycentric{{nan, 0.5, 0.5}},
                              Barycentric{{inf, 0., 0.}}, Barycentric{{0., 0., 0.}}})
    EXPECT_TRUE(throws_geodesic_error([&] { p.add_source(Face(7), b); }, {"barycentric", "source", "face 7"}));
  EXPECT_EQ(p.number_of_sources(), 0u) << "a refused source was kept";
  p.add_source(Vertex(0));
  p.build();
  std::vector<Point> points;
  EXPECT_TRUE(throws_geodesic_error([&] { p.distance(far_vertex); }, {"target vertex 36", "out of range"}));
  EXPECT_TRUE(throws_geodesic_error([&] { p.nearest_source(far_vertex); }, {"target vertex 36", "out of range"}));
  EXPECT_TRUE(throws_geodesic_error([&] { p.shortest_path_points(far_vertex, std::back_inserter(points)); },
                                    {"target vertex 36", "out of range"}));
  const Face_location far_location(far_face, Barycentric{{0.2, 0.3, 0.5}});
  EXPECT_TRUE(throws_geodesic_error([&] { p.distance(far_location); }, {"target face 50", "out of range"}));
  EXPECT_TRUE(throws_geodesic_error([&] { p.shortest_path_points(far_location, std::back_inserter(points)); },
                                    {"target face 50", "out of range"}));
  for(const Barycentric& b : {Barycentric{{0.5, 0.6, 0.}}, Barycentric{{-0.1, 0.6, 0.5}}, Barycentric{{nan, 0.5, 0.5}},
                              Barycentric{{0., 0., 0.}}}) {
    EXPECT_TRUE(throws_geodesic_error([&] { p.distance(Face_location(Face(7), b)); }, {"barycentric", "target", "face 7"}));
    EXPECT_TRUE(throws_geodesic_error([&] { p.nearest_source(Face_location(Face(7), b)); }, {"barycentric", "target"}));
    EXPECT_TRUE(throws_geodesic_error(
      [&] { p.shortest_path_points(Face_location(Face(7), b), std::back_inserter(points)); }, {"barycentric", "target"}));
  }
  EXPECT_TRUE(points.empty());
}

TEST(Paths_bad_input, Parameters)
{
  const Mesh& m = test_mesh("elephant");
  const std::vector<Vertex> source = {Vertex(0)};
  Paths p(m);
  p.add_source(Vertex(0));
  EXPECT_TRUE(throws_geodesic_error([&] { p.build(params::algorithm(CGAL_ext::VTP).approximation(8.)); },
                                    {"approximation"}));
  EXPECT_TRUE(throws_geodesic_error([&] { p.build(params::algorithm(CGAL_ext::VTP).stop_vertices(source)); },
                                    {"stop_vertices"}));
  EXPECT_FALSE(p.is_built());
  EXPECT_TRUE(throws_geodesic_error([&] { p.build(params::max_distance(-1.)); }, {"max distance"}));
  EXPECT_TRUE(throws_geodesic_error([&] { p.build(params::batch_size(0)); }, {"batch size"}));
  Parallel_paths pp(m);
  pp.add_source(Vertex(0));
  EXPECT_TRUE(throws_geodesic_error([&] { pp.build(params::number_of_threads(-1)); }, {"threads"}));
  EXPECT_TRUE(throws_geodesic_error([&] { pp.build(params::batch_size(0)); }, {"batch size"}));
  EXPECT_TRUE(throws_geodesic_error([&] { pp.build(params::algorithm(CGAL_ext::VTP).approximation(8.)); },
                                    {"approximation"}));
  for(CGAL_ext::Geodesic_algorithm a : {CGAL_ext::MMP, CGAL_ext::FWP_MMP}) {
    EXPECT_TRUE(throws_geodesic_error([&] { solve(m, source, params::algorithm(a).approximation(8.)); },
                                      {"approximation"}));
    EXPECT_TRUE(throws_geodesic_error([&] { solve(m, source, params::algorithm(a).stop_vertices(source)); },
                                      {"stop_vertices"}));
    EXPECT_TRUE(throws_geodesic_error([&] { solve(m, source, params::algorithm(a).max_distance(-1.)); },
                                      {"max distance"}));
    EXPECT_TRUE(throws_geodesic_error([&] { solve(m, source, params::algorithm(a).batch_size(0)); }, {"batch size"}));
    EXPECT_TRUE(throws_geodesic_error(
      [&] { solve<CGAL::Parallel_tag>(m, source, params::algorithm(a).number_of_threads(-1)); }, {"threads"}));
    EXPECT_TRUE(throws_geodesic_error(
      [&] { solve<CGAL::Parallel_tag>(m, source, params::algorithm(a).approximation(8.)); }, {"approximation"}));
  }
  // the statistics of a build
  CGAL_ext::Geodesic_statistics stats;
  p.build(params::statistics(stats));
  EXPECT_EQ(stats.vertices, m.number_of_vertices());
  EXPECT_GT(stats.windows_created, 0u);
  EXPECT_GT(stats.windows_stored, 0u);
  EXPECT_LE(stats.windows_stored, stats.windows_created);
  EXPECT_EQ(p.statistics().windows_stored, stats.windows_stored);
  EXPECT_GT(stats.lists_propagated, 0u) << "the default is VTP (MMP propagates no lists)";
  p.build(params::statistics(stats).algorithm(CGAL_ext::FWP_MMP));
  EXPECT_EQ(stats.lists_propagated, 0u);
  EXPECT_GT(stats.windows_stored, 0u);
}

// A source given twice (also as a corner location and as the vertex) counts once, and the
// first index is the nearest source.
TEST(Paths_edge_cases, DuplicatedSources)
{
  const Mesh& m = test_mesh("elephant");
  const Vertex v(1234);
  const Face_location l = location(777, 0.3, 0.3);
  for(CGAL_ext::Geodesic_algorithm a : {CGAL_ext::VTP, CGAL_ext::FWP_MMP}) {
    SCOPED_TRACE(a == CGAL_ext::VTP ? "VTP" : "FWP-MMP");
    Paths once(m);
    once.add_source(v);
    once.add_source(l);
    once.build(params::algorithm(a));
    Paths twice(m);
    EXPECT_EQ(twice.add_source(corner_location(m, v)), 0u);
    EXPECT_EQ(twice.add_source(l), 1u);
    EXPECT_EQ(twice.add_source(v), 2u);
    EXPECT_EQ(twice.add_source(l), 3u);
    EXPECT_EQ(twice.number_of_sources(), 4u);
    twice.build(params::algorithm(a));
    EXPECT_EQ(max_difference(class_distances(m, twice), class_distances(m, once)), 0.);
    for(Vertex w : m.vertices())
      ASSERT_EQ(twice.nearest_source(w), once.nearest_source(w)) << "vertex " << w;
    EXPECT_EQ(twice.nearest_source(v), 0u);
    EXPECT_EQ(twice.nearest_source(l), 1u);
    for(const Face_location& t : face_targets(m, 40, 2)) {
      EXPECT_EQ(twice.distance(t), once.distance(t)) << describe_target(t);
      EXPECT_LT(twice.nearest_source(t), 2u) << describe_target(t);
    }
  }
}

// A component that no source reaches: infinite distance, no nearest source, no path (none of
// the three query forms writes anything), at vertices and at face points.
TEST(Paths_edge_cases, UnreachableTargets)
{
  const Mesh& m = test_mesh("blobby_3cc");
  for(int a = 0; a < 3; ++a) {
    Paths p(m);
    p.add_source(Vertex(0));
    p.build(params::algorithm(a == 0 ? CGAL_ext::MMP : CGAL_ext::FWP_MMP));
    std::size_t unreachable = 0, unreachable_faces = 0;
    for(Vertex v : m.vertices()) {
      if(std::isfinite(p.distance(v)))
        continue;
      ++unreachable;
      EXPECT_EQ(p.distance(v), inf);
      EXPECT_EQ(p.nearest_source(v), Paths::no_source);
      std::vector<Point> points;
      p.shortest_path_points(v, std::back_inserter(points));
      EXPECT_TRUE(points.empty());
      EXPECT_TRUE(surface_path(p, v).empty());
      EXPECT_TRUE(p.shortest_path_sequence(v, Recorder<Path_point>()).points.empty());
      if(unreachable % 50 == 0) { // a face location in the same component
        const Face_location l(corner_location(m, v).first, Barycentric{{0.2, 0.3, 0.5}});
        ++unreachable_faces;
        EXPECT_EQ(p.distance(l), inf);
        EXPECT_EQ(p.nearest_source(l), Paths::no_source);
        EXPECT_TRUE(surface_path(p, l).empty());
        EXPECT_TRUE(p.shortest_path_sequence(l, Recorder<Path_point>()).points.empty());
      }
    }
    EXPECT_GT(unreachable, m.number_of_vertices() / 10);
    EXPECT_GT(unreachable_faces, 3u);
  }
}

// With max_distance, points within it keep their distances and paths, the others are at
// +infinity and have none.
// The set-up of the max_distance tests: two sources on elephant, the unlimited build, and a
// radius of 0.4 times the largest vertex distance.
class Paths_max_distance : public ::testing::Test
{
protected:
  const Mesh& m = test_mesh("elephant");
  const double diag = bbox_diagonal(m);
  Sources s;
  std::unique_ptr<Paths> full;
  double radius = 0;

  Paths_max_distance()
  {
    s.vertices = {Vertex(100)};
    s.faces = {location(2000, 0.2, 0.5)};
    full = built<Paths>(m, s, params::algorithm(CGAL_ext::FWP_MMP));
    double farthest = 0;
    for(Vertex v : m.vertices())
      farthest = std::max(farthest, full->distance(v));
    radius = 0.4 * farthest;
    mmp = built<Paths>(m, s, params::algorithm(CGAL_ext::MMP).max_distance(radius));
    fwp = built<Paths>(m, s, params::max_distance(radius).algorithm(CGAL_ext::FWP_MMP));
    pmmp = built<Parallel_paths>(m, s, params::max_distance(radius).algorithm(CGAL_ext::FWP_MMP));
  }

  std::unique_ptr<Paths> mmp, fwp; // built with max_distance(radius)
  std::unique_ptr<Parallel_paths> pmmp;
};

TEST_F(Paths_max_distance, DistancesAndPaths)
{
  const double band = 1e-12 * diag;
  const std::vector<double> function_mmp =
    solve_mixed(m, s.vertices, s.faces, params::algorithm(CGAL_ext::MMP).max_distance(radius));
  std::size_t inside = 0, outside = 0;
  for(Vertex v : m.vertices()) {
    const double d = full->distance(v);
    const double limited[4] = {mmp->distance(v), fwp->distance(v), pmmp->distance(v), function_mmp[v.idx()]};
    for(double e : limited) {
      if(d < radius - band) {
        EXPECT_NEAR(e, d, band) << "vertex " << v;
      } else if(d > radius + band) {
        EXPECT_EQ(e, inf) << "vertex " << v << " at " << d << " beyond " << radius;
      }
    }
    if(d < radius - band)
      ++inside;
    else if(d > radius + band)
      ++outside;
  }
  EXPECT_GT(inside, 100u);
  EXPECT_GT(outside, 100u);
  for(const Face_location& t : face_targets(m, 200, 17)) {
    const double d = full->distance(t);
    const std::vector<Path_point> path = surface_path(*fwp, t);
    if(d < radius - band) {
      EXPECT_NEAR(fwp->distance(t), d, band) << describe_target(t);
      EXPECT_NEAR(mmp->distance(t), d, band) << describe_target(t);
      ASSERT_TRUE(is_valid_path(m, path)) << describe_target(t);
      EXPECT_NEAR(CGAL_ext::polyline_length(positions(path)), d, length_tolerance * d) << describe_target(t);
      EXPECT_EQ(fwp->nearest_source(t), full->nearest_source(t)) << describe_target(t);
    } else if(d > radius + band) {
      EXPECT_EQ(fwp->distance(t), inf) << describe_target(t);
      EXPECT_EQ(mmp->distance(t), inf) << describe_target(t);
      EXPECT_EQ(pmmp->distance(t), inf) << describe_target(t);
      EXPECT_TRUE(path.empty()) << describe_target(t);
      EXPECT_TRUE(surface_path(*mmp, t).empty()) << describe_target(t);
    }
  }
}

// Beyond max_distance a face point has no nearest source, as a vertex has none.
TEST_F(Paths_max_distance, NearestSourceOfFacePoints)
{
  for(Vertex v : m.vertices()) // vertices do it right
    if(full->distance(v) > radius + 1e-12 * diag) {
      ASSERT_EQ(fwp->nearest_source(v), Paths::no_source) << "vertex " << v;
    }
  std::size_t beyond = 0;
  std::vector<std::string> wrong;
  for(const Face_location& t : face_targets(m, 200, 17)) {
    if(!(full->distance(t) > radius + 1e-12 * diag))
      continue;
    ++beyond;
    const std::size_t named[3] = {mmp->nearest_source(t), fwp->nearest_source(t), pmmp->nearest_source(t)};
    if(named[0] != Paths::no_source || named[1] != Paths::no_source || named[2] != Parallel_paths::no_source) {
      std::ostringstream msg;
      msg.precision(17);
      msg << describe_target(t) << " at " << full->distance(t) << " > " << radius << ": distance "
          << fwp->distance(t) << ", nearest_source " << named[1] << " (MMP " << named[0] << ", PMMP " << named[2]
          << ")";
      wrong.push_back(msg.str());
    }
  }
  EXPECT_GT(beyond, 50u);
  if(!wrong.empty())
    ADD_FAILURE() << "nearest_source(face location) names a source for a point beyond max_distance "
                 << "(distance +infinity; vertices correctly give no_source): " << wrong.size() << " of " << beyond
                 << " face points beyond radius " << radius << " on elephant from vertex 100 and face 2000 at "
                 << "(0.2, 0.5, 0.3), e.g. " << wrong[0];
}

// A target at the source: distance 0 and a path of length 0 that starts and ends there.
TEST(Paths_edge_cases, TargetAtTheSource)
{
  const Mesh& m = test_mesh("elephant");
  const double diag = bbox_diagonal(m);
  const Vertex v(321);
  const Face_location inside = location(1500, 0.25, 0.35), on_edge = location(2500, 0., 0.3);
  Paths p(m);
  p.add_source(v);
  p.add_source(inside);
  p.add_source(on_edge);
  p.build();
  // the vertex, also named as a corner of each of its faces
  std::vector<Path_point> path = surface_path(p, v);
  ASSERT_EQ(path.size(), 1u);
  EXPECT_TRUE(path[0].kind == Path_point::VERTEX && path[0].vertex == v && path[0].point == m.point(v));
  EXPECT_EQ(p.distance(v), 0.);
  EXPECT_EQ(p.nearest_source(v), 0u);
  for(Face f : m.faces_around_target(m.halfedge(v))) {
    Barycentric b{{0., 0., 0.}};
    const auto c = face_corners(m, f);
    for(int k = 0; k < 3; ++k)
      b[k] = c[k] == v ? 1. : 0.;
    const std::vector<Path_point> corner = surface_path(p, Face_location(f, b));
    ASSERT_EQ(corner.size(), 1u);
    EXPECT_TRUE(corner[0].kind == Path_point::VERTEX && corner[0].vertex == v);
    EXPECT_EQ(p.distance(Face_location(f, b)), 0.);
  }
  // the face points: a one-point path too, where the target is
  int index = 1;
  for(const Face_location& l : {inside, on_edge}) {
    const Point at = location_point(m, l);
    path = surface_path(p, l);
    ASSERT_EQ(path.size(), 1u) << describe_target(l);
    EXPECT_TRUE(ends_at_target(m, l, path[0])) << describe_target(l);
    EXPECT_TRUE(is_valid_path(m, path)) << describe_target(l);
    for(const Path_point& q : path)
      EXPECT_LE(distance_3(q.point, at), 1e-15 * diag) << describe_target(l);
    EXPECT_LE(p.distance(l), 1e-15 * diag) << describe_target(l);
    EXPECT_EQ(p.nearest_source(l), std::size_t(index)) << describe_target(l);
    std::cout << "[ info     ] a target at source " << index << " (" << (index == 1 ? "inside a face" : "on an edge")
              << "): distance " << p.distance(l) << ", path of " << path.size() << " point(s), kinds";
    for(const Path_point& q : path)
      std::cout << " " << (q.kind == Path_point::VERTEX ? "vertex" : q.kind == Path_point::EDGE ? "edge" : "face");
    std::cout << std::endl;
    ++index;
  }
  // the edge source seen from the face across
  const Face_location other = across(m, on_edge);
  ASSERT_NE(other.first, Mesh::null_face());
  EXPECT_LE(p.distance(other), 1e-15 * diag);
  EXPECT_EQ(p.nearest_source(other), 2u);
}

// A build() refused for a bad parameter keeps the previous build; a moved object keeps answering.
TEST(Paths_edge_cases, RefusedBuildKeepsThePreviousOneAndMovesKeepTheBuild)
{
  const Mesh& m = test_mesh("elephant");
  const Sources s = make_sources(m, SEVERAL_SOURCES);
  auto p = built<Paths>(m, s, params::algorithm(CGAL_ext::FWP_MMP));
  const std::vector<double> before = class_distances(m, *p);
  const Face_location l = location(3000, 0.1, 0.6);
  const std::vector<Path_point> path = surface_path(*p, l);
  EXPECT_TRUE(throws_geodesic_error([&] { p->build(params::algorithm(CGAL_ext::VTP).approximation(8.)); },
                                    {"approximation"}));
  EXPECT_TRUE(throws_geodesic_error([&] { p->build(params::max_distance(-1.)); }, {"max distance"}));
  EXPECT_TRUE(throws_geodesic_error([&] { p->build(params::batch_size(0)); }, {"batch size"}));
  ASSERT_TRUE(p->is_built());
  EXPECT_EQ(max_difference(class_distances(m, *p), before), 0.);
  EXPECT_TRUE(identical_paths(surface_path(*p, l), path));
  Paths moved(std::move(*p));
  p.reset();
  ASSERT_TRUE(moved.is_built());
  EXPECT_EQ(max_difference(class_distances(m, moved), before), 0.);
  EXPECT_TRUE(identical_paths(surface_path(moved, l), path));
  std::vector<Paths> several;
  several.push_back(std::move(moved));
  several.emplace_back(m);
  several.back().add_source(Vertex(0));
  several.back().build();
  EXPECT_EQ(max_difference(class_distances(m, several.front()), before), 0.); // (moved again by the vector)
  EXPECT_TRUE(identical_paths(surface_path(several.front(), l), path));
}

// Coordinates within round-off of a corner or an edge are that corner or edge.
TEST(Paths_edge_cases, NearlyOnAnEdgeOrACorner)
{
  const Mesh& m = test_mesh("elephant");
  Paths p(m);
  p.add_source(Vertex(10));
  p.build();
  const Face f(900);
  const auto c = face_corners(m, f);
  const std::vector<Path_point> corner = surface_path(p, Face_location(f, Barycentric{{1 - 2e-13, 1e-13, 1e-13}}));
  ASSERT_FALSE(corner.empty());
  EXPECT_TRUE(corner.back().kind == Path_point::VERTEX && corner.back().vertex == c[0]);
  const std::vector<Path_point> edge = surface_path(p, Face_location(f, Barycentric{{0.4, 0.6 - 1e-13, 1e-13}}));
  ASSERT_FALSE(edge.empty());
  EXPECT_EQ(edge.back().kind, Path_point::EDGE);
  EXPECT_TRUE(is_valid_path(m, edge));
  const Face_location exact_edge(f, Barycentric{{0.4, 0.6, 0.}});
  EXPECT_NEAR(p.distance(Face_location(f, Barycentric{{0.4, 0.6 - 1e-13, 1e-13}})), p.distance(exact_edge),
              1e-12 * bbox_diagonal(m));
}

// CGAL::Parallel_if_available_tag is the parallel build with TBB (PVTP's windows by default).
TEST(Paths_edge_cases, ParallelIfAvailable)
{
  const Mesh& m = test_mesh("elephant");
  CGAL_ext::Surface_mesh_geodesic_paths<Mesh, CGAL::Parallel_if_available_tag> p(m);
  p.add_source(Vertex(5));
  p.build(params::batch_size(64));
  Parallel_paths q(m);
  q.add_source(Vertex(5));
  q.build(params::batch_size(64));
  EXPECT_EQ(max_difference(class_distances(m, p), class_distances(m, q)), 0.);
}

// ---------------------------------------------------------------------------------------------
// Const queries from several threads at once give what they give one at a time.

template <class P>
void check_concurrent_queries(const Mesh& m, const P& p, const std::string& label)
{
  typedef typename P::Path_point Point_of_path;
  const std::vector<Vertex> vertices = spread_vertices(m, 150, 3);
  const std::vector<Face_location> locations = face_targets(m, 150, 21);
  struct Answers
  {
    std::vector<double> distances;
    std::vector<std::size_t> sources;
    std::vector<std::vector<Point_of_path>> paths;
  };
  // query i, in an order that depends on the thread
  auto run = [&](Answers& out, std::size_t first) {
    const std::size_t n = vertices.size() + locations.size();
    out.distances.assign(n, 0.);
    out.sources.assign(n, 0);
    out.paths.assign(n, {});
    for(std::size_t j = 0; j < n; ++j) {
      const std::size_t i = (first + j * 7) % n; // 7 is prime to n = 300
      if(i < vertices.size()) {
        out.distances[i] = p.distance(vertices[i]);
        out.sources[i] = p.nearest_source(vertices[i]);
        p.shortest_path_surface_points(vertices[i], std::back_inserter(out.paths[i]));
      } else {
        const Face_location& l = locations[i - vertices.size()];
        out.distances[i] = p.distance(l);
        out.sources[i] = p.nearest_source(l);
        p.shortest_path_surface_points(l, std::back_inserter(out.paths[i]));
      }
    }
  };
  Answers sequential;
  run(sequential, 0);
  const int threads = 4;
  std::vector<Answers> concurrent(threads);
  std::vector<std::thread> pool;
  for(int t = 0; t < threads; ++t)
    pool.emplace_back([&, t] { run(concurrent[std::size_t(t)], std::size_t(t) * 37); });
  for(std::thread& t : pool)
    t.join();
  for(int t = 0; t < threads; ++t) {
    const Answers& a = concurrent[std::size_t(t)];
    EXPECT_EQ(max_difference(a.distances, sequential.distances), 0.) << label << ", thread " << t;
    EXPECT_EQ(a.sources, sequential.sources) << label << ", thread " << t;
    for(std::size_t i = 0; i < a.paths.size(); ++i)
      ASSERT_TRUE(identical_paths(a.paths[i], sequential.paths[i])) << label << ", thread " << t << ", query " << i;
  }
}

TEST(Paths_threads, ConstQueriesFromSeveralThreads)
{
  const Mesh& m = test_mesh("elephant");
  const Sources s = make_sources(m, SEVERAL_SOURCES);
  check_concurrent_queries(m, *built<Paths>(m, s, params::algorithm(CGAL_ext::FWP_MMP)), "FWP-MMP");
  check_concurrent_queries(m, *built<Parallel_paths>(m, s, params::number_of_threads(2).algorithm(CGAL_ext::FWP_MMP)), "PMMP");
}

} // namespace
