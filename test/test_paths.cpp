// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Surface_mesh_geodesic_paths (MMP, FWP-MMP, PMMP): exact distances at vertices and at any
// point of a face, nearest sources and shortest paths, against the oracle
// CGAL::Surface_mesh_shortest_path and against the exact VTP solver; analytic surfaces; bad
// input and edge cases of the class; const queries from several threads at once.
//
// Tolerances: distances within 1e-9 of the bounding-box diagonal of the oracle's and 1e-12 of
// VTP's; a path's length within 1e-9 (relative) of the target's distance and of the oracle's
// path. Paths are compared with the oracle's polyline point by point (1e-6 of the diagonal); a
// target with two shortest paths may get either, so only a fraction of them is required to be
// close, while the lengths must always agree. The oracle is wrong at some points of border edges
// (see Oracle_paths in support/oracle.h): there the reference is VTP at a vertex inserted at the
// point. Section 4 (PMMP: bit-identical distances and paths for every number of threads) is in
// test_parallel.cpp, which is also run under ThreadSanitizer.

#include "support/analytic_surfaces.h"
#include "support/checks.h"
#include "support/mesh_transformations.h"
#include "support/oracle.h"
#include "support/path_checks.h"
#include "support/solve.h"

#include <CGAL_ext/Geodesics_3/polyline_length.h>
#include <CGAL_ext/Surface_mesh_geodesic_paths.h>

#include <algorithm>
#include <memory>
#include <optional>
#include <random>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

using namespace test_support;
namespace params = CGAL_ext::parameters;

namespace {

typedef CGAL_ext::Surface_mesh_geodesic_paths<Mesh> Paths;
typedef CGAL_ext::Surface_mesh_geodesic_paths<Mesh, CGAL::Parallel_tag> Parallel_paths;
typedef Paths::Path_point Path_point;
typedef Mesh::Halfedge_index Halfedge;

const double oracle_tolerance = 1e-9; // max |ours - oracle| / diagonal
const double vtp_tolerance = 1e-12;   // max |ours - VTP| / diagonal
const double length_tolerance = 1e-9; // |path length - distance| / distance
const double close_tolerance = 1e-6;  // a point of our path to the oracle's polyline / diagonal
const double close_fraction = 0.95;   // of the paths, at least this many close to the oracle's

// ---------------------------------------------------------------------------------------------
// Sources: vertices first, then face locations; source i of a set is the i-th in that order,
// which is the order they are added to the class (so nearest_source() returns that index).

enum Source_kind { VERTEX_SOURCE, FACE_SOURCE, EDGE_SOURCE, SEVERAL_SOURCES, BORDER_SOURCES, NEAR_VERTEX_SOURCE };
const char* source_names[] = {"vertex", "face", "edge", "several", "border", "near_vertex"};

Sources make_sources(const Mesh& m, Source_kind kind)
{
  const std::size_t nf = m.number_of_faces();
  Sources s;
  switch(kind) {
  case VERTEX_SOURCE: s.vertices = spread_vertices(m, 1, m.number_of_vertices() / 3); break;
  case FACE_SOURCE: s.faces = {location(nf / 2, 0.2, 0.3)}; break;
  case EDGE_SOURCE: s.faces = {location(nf / 5, 0., 0.6)}; break; // on the edge of corners 1 and 2
  case SEVERAL_SOURCES:
    s.vertices = spread_vertices(m, 3, 17);
    s.faces = {location(nf / 3, 0.45, 0.1), location(2 * nf / 3, 0.7, 0.)};
    break;
  case BORDER_SOURCES: { // a border vertex and a point of a border edge elsewhere
    std::vector<Mesh::Halfedge_index> border;
    for(auto h : m.halfedges())
      if(m.is_border(h))
        border.push_back(h);
    if(border.empty())
      throw std::logic_error("make_sources: the mesh has no border");
    s.vertices = {m.target(border[border.size() / 4])};
    const auto h = m.opposite(border[(3 * border.size()) / 4]); // in a face
    const auto c = face_corners(m, m.face(h));
    Barycentric b{{0., 0., 0.}};
    for(int k = 0; k < 3; ++k)
      b[k] = c[k] == m.source(h) ? 0.35 : (c[k] == m.target(h) ? 0.65 : 0.);
    s.faces = {Face_location(m.face(h), b)};
    break;
  }
  case NEAR_VERTEX_SOURCE: s.faces = {location(nf / 7, 1 - 2e-7, 1e-7)}; break;
  }
  return s;
}

/// the paths object of type P for the sources, built with `np`
template <class P, class NamedParameters = CGAL_ext::parameters::Default_named_parameters_type>
std::unique_ptr<P> built(const Mesh& m, const Sources& s,
                         const NamedParameters& np = CGAL_ext::parameters::default_values())
{
  std::unique_ptr<P> p(new P(m));
  for(Vertex v : s.vertices)
    p->add_source(v);
  for(const Face_location& l : s.faces)
    p->add_source(l);
  p->build(np);
  return p;
}

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

template <class P>
std::vector<double> class_distances(const Mesh& m, const P& p)
{
  std::vector<double> d;
  for(Vertex v : m.vertices())
    d.push_back(p.distance(v));
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
  auto fwp = built<Paths>(m, s); // FWP-MMP, the default
  auto pmmp = built<Parallel_paths>(m, s, params::number_of_threads(2));
  const std::vector<std::pair<std::string, std::vector<double>>> runs = {
    {"geodesic_distances MMP", solve_mixed(m, s.vertices, s.faces, params::algorithm(CGAL_ext::MMP))},
    {"geodesic_distances FWP-MMP", solve_mixed(m, s.vertices, s.faces, params::algorithm(CGAL_ext::FWP_MMP))},
    {"geodesic_distances PMMP", solve_mixed<CGAL::Parallel_tag>(
                                  m, s.vertices, s.faces, params::algorithm(CGAL_ext::FWP_MMP).number_of_threads(2))},
    {"class MMP", class_distances(m, *mmp)},
    {"class FWP-MMP", class_distances(m, *fwp)},
    {"class PMMP", class_distances(m, *pmmp)}};
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
// 1. Vertex distances on CGAL's meshes and on transformed copies

class Vertex_distances : public ::testing::TestWithParam<Mesh_and_sources> {};

TEST_P(Vertex_distances, MatchOracleAndVtp)
{
  const std::string name = std::get<0>(GetParam());
  const Mesh& m = test_mesh(name);
  const Sources s = make_sources(m, std::get<1>(GetParam()));
  check_vertex_distances(m, s, name + " " + source_names[std::get<1>(GetParam())]);
  if(name == "blobby_3cc") { // three components: the other two are unreachable from one source
    auto fwp = built<Paths>(m, s);
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
  auto fwp = built<Paths>(m, s);
  auto pmmp = built<Parallel_paths>(m, s, params::number_of_threads(2));
  EXPECT_TRUE(agrees(class_distances(m, *fwp), vtp, diag, vtp_tolerance, name + " class FWP-MMP vs VTP"));
  EXPECT_TRUE(agrees(class_distances(m, *pmmp), vtp, diag, vtp_tolerance, name + " class PMMP vs VTP"));
  EXPECT_TRUE(agrees(solve_mixed(m, s.vertices, s.faces, params::algorithm(CGAL_ext::MMP)), vtp, diag, vtp_tolerance,
                     name + " geodesic_distances MMP vs VTP"));
  double worst = 0;
  for(Vertex v : spread_vertices(m, 40, 9)) {
    std::vector<Path_point> path;
    fwp->shortest_path_surface_points(v, std::back_inserter(path));
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
// Targets

/// `count` face locations spread over the faces, cycling through six forms: inside the face
/// (twice), on an edge (one zero coordinate), at a corner (two zeros), and within 1e-9 of a
/// corner and 1e-10 of an edge (inside the face, not snapped to the corner or the edge)
std::vector<Face_location> face_targets(const Mesh& m, int count, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0.05, 0.9);
  std::vector<Face_location> t;
  const std::size_t nf = m.number_of_faces();
  for(int i = 0; i < count; ++i) {
    const Face f(static_cast<Mesh::size_type>((seed + std::size_t(i) * nf / std::size_t(count)) % nf));
    Barycentric b{{0., 0., 0.}};
    const int k = i % 3;
    switch(i % 6) {
    case 0:
    case 1: {
      const double a = u(rng), c = (1 - a) * u(rng);
      b[k] = a;
      b[(k + 1) % 3] = c;
      b[(k + 2) % 3] = 1 - a - c;
      break;
    }
    case 2: {
      const double a = u(rng);
      b[k] = a;
      b[(k + 1) % 3] = 1 - a;
      break;
    }
    case 3: b[k] = 1; break;
    case 4:
      b[k] = 1 - 2e-9;
      b[(k + 1) % 3] = 1e-9;
      b[(k + 2) % 3] = 1e-9;
      break;
    default: {
      const double a = u(rng);
      b[k] = a;
      b[(k + 1) % 3] = 1 - a - 1e-10;
      b[(k + 2) % 3] = 1e-10;
    }
    }
    t.push_back(Face_location(f, b));
  }
  return t;
}

/// the location of a face point expressed in the face across its edge (it must lie on one)
Face_location across(const Mesh& m, const Face_location& l)
{
  const auto c = face_corners(m, l.first);
  for(int k = 0; k < 3; ++k)
    if(l.second[k] == 0) {
      const Vertex a = c[(k + 1) % 3], b = c[(k + 2) % 3];
      const auto h = m.opposite(m.halfedge(a, b));
      if(m.is_border(h))
        return Face_location(Mesh::null_face(), l.second);
      const Face g = m.face(h);
      const auto d = face_corners(m, g);
      Barycentric bg{{0., 0., 0.}};
      for(int i = 0; i < 3; ++i)
        bg[i] = d[i] == a ? l.second[(k + 1) % 3] : (d[i] == b ? l.second[(k + 2) % 3] : 0.);
      return Face_location(g, bg);
    }
  throw std::logic_error("across: not on an edge");
}

std::string describe_target(Vertex v)
{
  return "vertex " + std::to_string(v.idx());
}
std::string describe_target(const Face_location& l)
{
  std::ostringstream s;
  s.precision(17);
  s << "face " << l.first << " (" << l.second[0] << ", " << l.second[1] << ", " << l.second[2] << ")";
  return s.str();
}

// ---------------------------------------------------------------------------------------------
// 2. Distances at face points (inside faces, on edges, at corners) against the oracle

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
  auto fwp = built<Paths>(m, s);
  auto pmmp = built<Parallel_paths>(m, s);
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
  double worst[3] = {0, 0, 0};
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
    const double d[3] = {mmp->distance(t), fwp->distance(t), pmmp->distance(t)};
    for(int a = 0; a < 3; ++a) {
      const double e = max_difference({d[a]}, {o});
      if(e > oracle_tolerance * diag)
        ADD_FAILURE() << label << ": algorithm " << a << " (MMP, FWP-MMP, PMMP) at " << describe_target(t) << ": "
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
      continue;
    }
    ASSERT_LT(ns, s.size()) << label << ", " << describe_target(t);
    if(s.size() == 1) {
      EXPECT_EQ(ns, 0u);
      continue;
    }
    for(const std::size_t n : {ns, mmp->nearest_source(t), pmmp->nearest_source(t)}) {
      ASSERT_LT(n, s.size());
      const double named = alone.empty() ? alone_ours[n]->distance(t) : alone[n]->distance(t);
      EXPECT_LE(std::abs(named - d[1]), oracle_tolerance * diag)
        << label << ": " << describe_target(t) << " at " << d[1] << " names source " << n << " at " << named;
    }
  }
  std::cout << "[ error    ] " << label << ": " << checked << " face points (" << on_edges << " on inner edges, "
            << on_border << " on border edges, where the oracle was wrong at " << oracle_wrong_on_border
            << "), max |ours - reference| / diag = " << worst[0] << " (MMP), " << worst[1] << " (FWP-MMP), "
            << worst[2] << " (PMMP)" << std::endl;
  EXPECT_GT(checked, 200u);
}

INSTANTIATE_TEST_SUITE_P(Paths, Face_point_distances, ::testing::ValuesIn(mesh_and_sources_cases()),
                         mesh_and_sources_name);

// ---------------------------------------------------------------------------------------------
// 3. Shortest paths

/// records what shortest_path_sequence() visits, as path points
template <class Path_point>
struct Recorder
{
  std::vector<Path_point> points;

  void operator()(Vertex v)
  {
    Path_point p;
    p.kind = Path_point::VERTEX;
    p.vertex = v;
    points.push_back(p);
  }
  void operator()(Halfedge h, double t)
  {
    Path_point p;
    p.kind = Path_point::EDGE;
    p.halfedge = h;
    p.t = t;
    points.push_back(p);
  }
  void operator()(Face f, const Barycentric& b)
  {
    Path_point p;
    p.kind = Path_point::FACE;
    p.face = f;
    p.barycentric = b;
    points.push_back(p);
  }
};

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
  auto fwp = built<Paths>(m, s);
  auto pmmp = built<Parallel_paths>(m, s);
  const std::vector<Vertex> vertex_targets = spread_vertices(m, 30, 101);
  std::vector<Face_location> face_targets_kept;
  for(const Face_location& l : face_targets(m, 30, 3))
    if(reference.can_query(l.first))
      face_targets_kept.push_back(l);
  Path_statistics all;
  const char* algorithm_names[] = {"MMP", "FWP-MMP", "PMMP"};
  for(int a = 0; a < 3; ++a) {
    const std::string label = name + " " + source_names[kind] + " " + algorithm_names[a];
    Path_statistics stats;
    auto check = [&](const auto& target) { // the build of algorithm a
      if(a == 0)
        check_path(m, s, *mmp, target, reference, stats, label);
      else if(a == 1)
        check_path(m, s, *fwp, target, reference, stats, label);
      else
        check_path(m, s, *pmmp, target, reference, stats, label);
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
// 2b. Points where the oracle cannot be trusted, or where round-off of the windows matters: points of
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
  auto fwp = built<Paths>(m, s);
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
    const std::vector<Path_point> path = [&] {
      std::vector<Path_point> p;
      fwp->shortest_path_surface_points(t, std::back_inserter(p));
      return p;
    }();
    ASSERT_TRUE(is_valid_path(m, path)) << name << ", " << describe_target(t);
    EXPECT_TRUE(ends_at_target(m, t, path.back())) << name << ", " << describe_target(t);
    EXPECT_LE(std::abs(CGAL_ext::polyline_length(positions(path)) - d), length_tolerance * d) << name << ", " << describe_target(t);
  }
  std::cout << "[ error    ] " << name << ": " << reachable << " points of border edges and near corners and edges: max "
            << "|ours - exact| / diag = " << worst << " (below the exact distance by up to " << worst_below
            << "); the oracle: max " << worst_oracle << ", wrong (> 1e-9 diag) at " << oracle_wrong << std::endl;
  EXPECT_GT(reachable, 20u);
}

INSTANTIATE_TEST_SUITE_P(Paths, Inserted_vertex_reference,
                         ::testing::Values("elephant-with-holes", "blobby_3cc", "mushroom", "elephant"),
                         [](const ::testing::TestParamInfo<const char*>& i) { return test_name(i.param); });

// ---------------------------------------------------------------------------------------------
// 5. Analytic surfaces: flat grids (straight paths, Euclidean distances, around a reflex corner),
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

template <class Target>
std::vector<Path_point> surface_path(const Paths& p, const Target& t)
{
  std::vector<Path_point> path;
  p.shortest_path_surface_points(t, std::back_inserter(path));
  return path;
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
    std::unique_ptr<Paths> p = a == 0 ? built<Paths>(m, s, params::algorithm(CGAL_ext::MMP)) : built<Paths>(m, s);
    std::unique_ptr<Parallel_paths> pp;
    if(a == 2)
      pp = built<Parallel_paths>(m, s);
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
// 6. Bad input and edge cases of the class

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
  EXPECT_TRUE(throws_geodesic_error([&] { p.build(params::algorithm(CGAL_ext::VTP)); }, {"MMP"}));
  EXPECT_FALSE(p.is_built());
  EXPECT_TRUE(throws_geodesic_error([&] { p.build(params::max_distance(-1.)); }, {"max distance"}));
  EXPECT_TRUE(throws_geodesic_error([&] { p.build(params::batch_size(0)); }, {"batch size"}));
  Parallel_paths pp(m);
  pp.add_source(Vertex(0));
  EXPECT_TRUE(throws_geodesic_error([&] { pp.build(params::number_of_threads(-1)); }, {"threads"}));
  EXPECT_TRUE(throws_geodesic_error([&] { pp.build(params::batch_size(0)); }, {"batch size"}));
  EXPECT_TRUE(throws_geodesic_error([&] { pp.build(params::algorithm(CGAL_ext::VTP)); }, {"MMP"}));
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
  EXPECT_EQ(p.statistics().windows_stored, stats.windows_stored);
}

// A source given twice (also as a corner location and as the vertex) counts once, and the
// first index is the nearest source.
TEST(Paths_edge_cases, DuplicatedSources)
{
  const Mesh& m = test_mesh("elephant");
  const Vertex v(1234);
  const Face_location l = location(777, 0.3, 0.3);
  Paths once(m);
  once.add_source(v);
  once.add_source(l);
  once.build();
  Paths twice(m);
  EXPECT_EQ(twice.add_source(corner_location(m, v)), 0u);
  EXPECT_EQ(twice.add_source(l), 1u);
  EXPECT_EQ(twice.add_source(v), 2u);
  EXPECT_EQ(twice.add_source(l), 3u);
  EXPECT_EQ(twice.number_of_sources(), 4u);
  twice.build();
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
    full = built<Paths>(m, s);
    double farthest = 0;
    for(Vertex v : m.vertices())
      farthest = std::max(farthest, full->distance(v));
    radius = 0.4 * farthest;
    mmp = built<Paths>(m, s, params::algorithm(CGAL_ext::MMP).max_distance(radius));
    fwp = built<Paths>(m, s, params::max_distance(radius));
    pmmp = built<Parallel_paths>(m, s, params::max_distance(radius));
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
  auto p = built<Paths>(m, s);
  const std::vector<double> before = class_distances(m, *p);
  const Face_location l = location(3000, 0.1, 0.6);
  const std::vector<Path_point> path = surface_path(*p, l);
  EXPECT_TRUE(throws_geodesic_error([&] { p->build(params::algorithm(CGAL_ext::VTP)); }, {"MMP"}));
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

// CGAL::Parallel_if_available_tag is PMMP with TBB.
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
// 7. Const queries from several threads at once give what they give one at a time.

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
  check_concurrent_queries(m, *built<Paths>(m, s), "FWP-MMP");
  check_concurrent_queries(m, *built<Parallel_paths>(m, s, params::number_of_threads(2)), "PMMP");
}

} // namespace
