// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Named parameters and mesh types: max_distance, stop_vertices, statistics, vertex_point_map,
// vertex/face index maps, algorithm; several connected components; CGAL::Polyhedron_3.

#include "support/checks.h"
#include "support/mesh_transformations.h"
#include "support/solve.h"

#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/boost/graph/Face_filtered_graph.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

using namespace test_support;
namespace params = CGAL_ext::parameters;

namespace {

std::size_t count_finite(const std::vector<double>& d)
{
  return std::size_t(std::count_if(d.begin(), d.end(), [](double x) { return std::isfinite(x); }));
}

// Sources of the option tests: one vertex, several vertices, or one face location.
enum Option_source { VERTEX, VERTICES, FACE };
const char* option_source_names[] = {"vertex", "vertices", "face"};

std::vector<double> solve_from(const Mesh& m, Option_source s, CGAL_ext::Geodesic_statistics& stats,
                               double max_distance = inf)
{
  const auto np = params::max_distance(max_distance).statistics(stats);
  switch(s) {
  case VERTEX: return solve(m, spread_vertices(m, 1, 3)[0], np);
  case VERTICES: return solve(m, spread_vertices(m, 3, 3), np);
  default: return solve(m, location(m.number_of_faces() / 3, 0.25, 0.5), np);
  }
}

// A distance strictly between two consecutive distinct finite values of `d`, near the quantile
// q, so that no vertex is within round-off of it.
double cut_between(const std::vector<double>& d, double q)
{
  std::vector<double> s;
  for(double x : d)
    if(std::isfinite(x))
      s.push_back(x);
  std::sort(s.begin(), s.end());
  std::size_t i = std::min(s.size() - 2, std::size_t(q * double(s.size())));
  while(i + 1 < s.size() && s[i + 1] - s[i] < 1e-9 * s.back())
    ++i;
  return 0.5 * (s[i] + s[i + 1]);
}

// ---------------------------------------------------------------------------------------------
// max_distance

class Max_distance : public ::testing::TestWithParam<std::tuple<const char*, Option_source, double>> {};

TEST_P(Max_distance, ExactWithinAndInfiniteBeyond)
{
  const Mesh& m = test_mesh(std::get<0>(GetParam()));
  const Option_source source = std::get<1>(GetParam());
  CGAL_ext::Geodesic_statistics full_stats, stats;
  const std::vector<double> full = solve_from(m, source, full_stats);
  const double D = cut_between(full, std::get<2>(GetParam()));
  const std::vector<double> limited = solve_from(m, source, stats, D);
  std::size_t within = 0;
  for(std::size_t i = 0; i < full.size(); ++i) {
    if(full[i] <= D) {
      ++within;
      ASSERT_LE(std::abs(limited[i] - full[i]), 1e-12 * full[i]) << "vertex " << i << " within D = " << D;
    } else {
      ASSERT_EQ(limited[i], inf) << "vertex " << i << " at " << full[i] << " beyond D = " << D;
    }
  }
  EXPECT_GT(within, 0u);
  EXPECT_LT(within, full.size());
  std::cout << "[ windows  ] max distance " << D << ": " << stats.windows_created << " windows, full solve "
            << full_stats.windows_created << std::endl;
  EXPECT_LT(stats.windows_created, full_stats.windows_created);
}

INSTANTIATE_TEST_SUITE_P(Options, Max_distance,
                         ::testing::Combine(::testing::Values("elephant", "mushroom", "fandisk"),
                                            ::testing::Values(VERTEX, VERTICES, FACE), ::testing::Values(0.1, 0.6)),
                         [](const ::testing::TestParamInfo<std::tuple<const char*, Option_source, double>>& i) {
                           return std::string(std::get<0>(i.param)) + "_" + option_source_names[std::get<1>(i.param)] +
                                  "_q" + std::to_string(int(100 * std::get<2>(i.param)));
                         });

TEST(Options, MaxDistanceZeroAndInfinity)
{
  const Mesh& m = test_mesh("elephant");
  const Vertex s = spread_vertices(m, 1, 5)[0];
  const std::vector<double> zero = solve(m, s, params::max_distance(0.));
  EXPECT_EQ(zero[s.idx()], 0.);
  EXPECT_EQ(count_finite(zero), 1u);
  EXPECT_EQ(solve(m, s, params::max_distance(inf)), solve(m, s));
  // from a face point, every vertex is at a positive distance: none is within 0
  EXPECT_EQ(count_finite(solve(m, location(10, 0.3, 0.3), params::max_distance(0.))), 0u);
}

// ---------------------------------------------------------------------------------------------
// stop_vertices

class Stop_vertices : public ::testing::TestWithParam<std::tuple<const char*, Option_source>> {};

TEST_P(Stop_vertices, StopVerticesAndEverythingFiniteAreExact)
{
  const Mesh& m = test_mesh(std::get<0>(GetParam()));
  const Option_source source = std::get<1>(GetParam());
  CGAL_ext::Geodesic_statistics full_stats, stats;
  const std::vector<double> full = solve_from(m, source, full_stats);
  // two stop vertices at about the 15% and 35% quantiles of the distance
  std::vector<std::size_t> order(full.size());
  for(std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return full[a] < full[b]; });
  const Vertex v1(static_cast<Mesh::size_type>(order[order.size() * 35 / 100]));
  const Vertex v2(static_cast<Mesh::size_type>(order[order.size() * 15 / 100]));
  const std::vector<Vertex> stops{v1, v2};
  const auto np = params::stop_vertices(stops).statistics(stats);
  std::vector<double> limited;
  switch(source) {
  case VERTEX: limited = solve(m, spread_vertices(m, 1, 3)[0], np); break;
  case VERTICES: limited = solve(m, spread_vertices(m, 3, 3), np); break;
  default: limited = solve(m, location(m.number_of_faces() / 3, 0.25, 0.5), np);
  }
  for(Vertex v : stops)
    EXPECT_NEAR(limited[v.idx()], full[v.idx()], 1e-12 * full[v.idx()]) << "stop vertex " << v;
  const double farthest = std::max(full[v1.idx()], full[v2.idx()]);
  for(std::size_t i = 0; i < full.size(); ++i) {
    if(std::isfinite(limited[i]))
      ASSERT_LE(std::abs(limited[i] - full[i]), 1e-12 * full[i]) << "vertex " << i;
    if(full[i] < farthest * (1 - 1e-9))
      ASSERT_TRUE(std::isfinite(limited[i])) << "vertex " << i << " at " << full[i] << " nearer than the stops";
    if(full[i] > farthest * (1 + 1e-9))
      ASSERT_EQ(limited[i], inf) << "vertex " << i << " at " << full[i] << " beyond the stops (" << farthest << ")";
  }
  std::cout << "[ windows  ] stop vertices at " << farthest << ": " << stats.windows_created
            << " windows, full solve " << full_stats.windows_created << std::endl;
  EXPECT_LT(stats.windows_created, full_stats.windows_created);
}

INSTANTIATE_TEST_SUITE_P(Options, Stop_vertices,
                         ::testing::Combine(::testing::Values("elephant", "mushroom", "knot1"),
                                            ::testing::Values(VERTEX, VERTICES, FACE)),
                         [](const ::testing::TestParamInfo<std::tuple<const char*, Option_source>>& i) {
                           return std::string(std::get<0>(i.param)) + "_" + option_source_names[std::get<1>(i.param)];
                         });

TEST(Options, StopVertexSpecialCases)
{
  const Mesh& m = test_mesh("mushroom");
  const Vertex s = spread_vertices(m, 1, 5)[0];
  // stopping at the source: nothing else is wanted
  const std::vector<double> at_source = solve(m, s, params::stop_vertices(std::vector<Vertex>{s}));
  EXPECT_EQ(at_source[s.idx()], 0.);
  EXPECT_EQ(count_finite(at_source), 1u);
  // the same stop vertex twice is the stop vertex once
  const Vertex t = spread_vertices(m, 1, 700)[0];
  EXPECT_EQ(solve(m, s, params::stop_vertices(std::vector<Vertex>{t, t})),
            solve(m, s, params::stop_vertices(std::vector<Vertex>{t})));
  // an empty set of stop vertices stops nothing
  EXPECT_EQ(solve(m, s, params::stop_vertices(std::vector<Vertex>{})), solve(m, s));
}

// ---------------------------------------------------------------------------------------------
// Several connected components: a component without a source is unreached (+infinity), and a
// reached component gets the distances it has alone.

TEST(Components, TwoShiftedCopies)
{
  const Mesh& m = test_mesh("elephant");
  const std::size_t nv = m.number_of_vertices();
  const double diag = bbox_diagonal(m);
  const Vector shift(3 * diag, 0, 0);
  const Mesh other = translated(m, shift);
  const Mesh both = disjoint_union({&m, &other});
  ASSERT_EQ(both.number_of_vertices(), 2 * nv);
  for(std::size_t i = 0; i < nv; i += 97) { // the union keeps the order: copy 1, then copy 2
    ASSERT_EQ(both.point(Vertex(Mesh::size_type(i))), m.point(Vertex(Mesh::size_type(i))));
    ASSERT_EQ(both.point(Vertex(Mesh::size_type(nv + i))), m.point(Vertex(Mesh::size_type(i))) + shift);
  }
  const Vertex s = spread_vertices(m, 1, 123)[0];
  const Face_location l = location(m.number_of_faces() / 2, 0.2, 0.2);
  const std::vector<double> alone = solve(m, s), alone_l = solve(m, l);

  const std::vector<double> first = solve(both, s);
  EXPECT_TRUE(agrees(std::vector<double>(first.begin(), first.begin() + nv), alone, diag, 1e-12, "reached copy"));
  EXPECT_EQ(count_finite(std::vector<double>(first.begin() + nv, first.end())), 0u) << "the unreached copy";

  const Face_location l2 = transferred_location(m, l, both, nv, m.number_of_faces());
  ASSERT_LT(std::sqrt(CGAL::squared_distance(location_point(both, l2), location_point(m, l) + shift)), 1e-12 * diag);
  const std::vector<double> second = solve(both, l2);
  EXPECT_EQ(count_finite(std::vector<double>(second.begin(), second.begin() + nv)), 0u) << "the unreached copy";
  EXPECT_TRUE(agrees(std::vector<double>(second.begin() + nv, second.end()), alone_l, diag, 1e-12, "reached copy 2"));

  // one source in each copy: each copy as alone
  const std::vector<double> each = solve_mixed(both, {s}, {l2});
  EXPECT_TRUE(agrees(std::vector<double>(each.begin(), each.begin() + nv), alone, diag, 1e-12, "copy 1 of 2"));
  EXPECT_TRUE(agrees(std::vector<double>(each.begin() + nv, each.end()), alone_l, diag, 1e-12, "copy 2 of 2"));
}

TEST(Components, BlobbyThreeComponents)
{
  const Mesh& m = test_mesh("blobby_3cc");
  Mesh copy = m;
  auto fcc = copy.add_property_map<Face, std::size_t>("f:cc", 0).first;
  ASSERT_EQ(CGAL::Polygon_mesh_processing::connected_components(copy, fcc), 3u);
  std::vector<std::size_t> vcc(m.number_of_vertices());
  for(Face f : copy.faces())
    for(Vertex v : copy.vertices_around_face(copy.halfedge(f)))
      vcc[v.idx()] = fcc[f];
  const double diag = bbox_diagonal(m);
  for(std::size_t component = 0; component < 3; ++component) {
    Vertex s;
    for(Vertex v : m.vertices())
      if(vcc[v.idx()] == component)
        s = v;
    const std::vector<double> d = solve(m, s);
    // the component alone, as a mesh of its own
    CGAL::Face_filtered_graph<Mesh> filtered(copy, component, fcc);
    Mesh part;
    std::unordered_map<Vertex, Vertex> to_part;
    CGAL::copy_face_graph(filtered, part, CGAL::parameters::vertex_to_vertex_map(boost::make_assoc_property_map(to_part)));
    const std::vector<double> alone = solve(part, to_part.at(s));
    for(Vertex v : m.vertices()) {
      if(vcc[v.idx()] != component)
        ASSERT_EQ(d[v.idx()], inf) << "vertex " << v << " of another component";
      else
        ASSERT_NEAR(d[v.idx()], alone[to_part.at(v).idx()], 1e-12 * diag) << "vertex " << v;
    }
  }
}

TEST(Components, IsolatedVertexIsUnreached)
{
  Mesh m = test_mesh("cactus");
  const std::vector<double> before = solve(m, Vertex(3));
  const Vertex isolated = m.add_vertex(Point(0, 0, 0));
  const std::vector<double> after = solve(m, Vertex(3));
  EXPECT_EQ(after[isolated.idx()], inf);
  EXPECT_EQ(std::vector<double>(after.begin(), after.begin() + before.size()), before);
}

// ---------------------------------------------------------------------------------------------
// statistics

TEST(Options, StatisticsAreFilled)
{
  const Mesh& m = test_mesh("mushroom");
  CGAL_ext::Geodesic_statistics stats;
  stats.vertices = stats.faces = stats.windows_created = 123456789; // must be overwritten
  stats.seconds_setup = stats.seconds_solve = -1;
  const std::vector<double> d = solve(m, spread_vertices(m, 2, 9), params::statistics(stats));
  EXPECT_EQ(stats.vertices, m.number_of_vertices());
  EXPECT_EQ(stats.faces, m.number_of_faces());
  EXPECT_GT(stats.windows_created, 0u);
  EXPECT_NE(stats.windows_created, 123456789u);
  EXPECT_GT(stats.peak_windows, 0u);
  EXPECT_LE(stats.peak_windows, stats.windows_created);
  EXPECT_GE(stats.peak_window_bytes, stats.peak_windows * sizeof(CGAL_ext::Geodesics_3::internal::Window));
  EXPECT_GE(stats.vertices_popped, count_finite(d)); // every reached vertex is taken at least once
  EXPECT_GT(stats.lists_propagated, 0u);
  EXPECT_GE(stats.seconds_setup, 0.);
  EXPECT_GE(stats.seconds_solve, 0.);
  EXPECT_LT(stats.seconds_setup + stats.seconds_solve, 60.);

  // the same object reused on another mesh describes the new solve only
  const Mesh& small = test_mesh("cactus");
  solve(small, Vertex(0), params::statistics(stats).max_distance(inf));
  EXPECT_EQ(stats.vertices, small.number_of_vertices());
  EXPECT_EQ(stats.faces, small.number_of_faces());
  EXPECT_LE(stats.peak_windows, stats.windows_created);
}

TEST(Options, ExplicitAlgorithmIsTheDefault)
{
  const Mesh& m = test_mesh("knot1");
  EXPECT_EQ(solve(m, Vertex(5), params::algorithm(CGAL_ext::VTP)), solve(m, Vertex(5)));
}

// ---------------------------------------------------------------------------------------------
// vertex_point_map: the geometry comes from the map, not from the mesh's points.

TEST(Options, VertexPointMapScalesTheDistances)
{
  Mesh m = test_mesh("mushroom");
  const double factor = 3.75;
  auto scaled_points = m.add_property_map<Vertex, Point>("v:scaled", Point(0, 0, 0)).first;
  for(Vertex v : m.vertices())
    put(scaled_points, v, CGAL::ORIGIN + factor * (m.point(v) - CGAL::ORIGIN));
  const std::vector<Vertex> vs = spread_vertices(m, 2, 40);
  const Face_location l = location(77, 0.1, 0.8);
  const std::vector<double> plain = solve_mixed(m, vs, {l});
  std::vector<double> expected(plain);
  for(double& x : expected)
    x *= factor;
  const std::vector<double> through_map = solve_mixed(m, vs, {l}, params::vertex_point_map(scaled_points));
  EXPECT_TRUE(agrees_relative(through_map, expected, 1e-12, "vertex_point_map scaled by 3.75"));
  EXPECT_EQ(solve_mixed(m, vs, {l}), plain) << "the mesh's own points are used without the parameter";
}

// ---------------------------------------------------------------------------------------------
// CGAL::Polyhedron_3, with and without ids, and explicit index maps: the same distances as on
// the Surface_mesh read from the same file (same vertex and face order).

typedef CGAL::Polyhedron_3<K, CGAL::Polyhedron_items_with_id_3> Polyhedron_with_ids;
typedef CGAL::Polyhedron_3<K> Polyhedron;

template <class P>
P read_polyhedron(const std::string& name)
{
  P p;
  const std::string path = test_mesh_path(name);
  std::ifstream in(path);
  if(!CGAL::IO::read_OFF(in, p))
    throw std::runtime_error("cannot read " + path);
  return p;
}

// The sources of `m` expressed on `p`: vertices and faces by position in the iteration order,
// barycentric coordinates permuted to the corner order of p's face.
template <class P>
std::vector<std::pair<typename boost::graph_traits<P>::face_descriptor, Barycentric>>
to_polyhedron(const Mesh& m, const P& p, const std::vector<Vertex>& vs, const std::vector<Face_location>& ls)
{
  typedef typename boost::graph_traits<P>::face_descriptor face_descriptor;
  std::vector<std::pair<face_descriptor, Barycentric>> out;
  std::vector<Face_location> all = ls;
  for(Vertex v : vs)
    all.push_back(corner_location(m, v));
  for(const Face_location& l : all) {
    const face_descriptor f = *std::next(faces(p).begin(), l.first.idx());
    const auto c = face_corners(m, l.first);
    const auto h = halfedge(f, p);
    const typename boost::graph_traits<P>::vertex_descriptor pc[3] = {source(h, p), target(h, p), target(next(h, p), p)};
    Barycentric b{{0., 0., 0.}};
    for(int i = 0; i < 3; ++i)
      for(int k = 0; k < 3; ++k)
        if(get(CGAL::vertex_point, p, pc[i]) == m.point(c[k]))
          b[i] = l.second[k];
    EXPECT_NEAR(b[0] + b[1] + b[2], 1., 1e-15) << "the faces of the two meshes do not match";
    out.emplace_back(f, b);
  }
  return out;
}

class Polyhedron_mesh : public ::testing::TestWithParam<const char*> {};

TEST_P(Polyhedron_mesh, SameDistancesAsSurfaceMesh)
{
  const std::string name = GetParam();
  const Mesh& m = test_mesh(name);
  const double diag = bbox_diagonal(m);
  const std::vector<Vertex> vs = spread_vertices(m, 2, 21);
  const std::vector<Face_location> ls = {location(m.number_of_faces() / 4, 0.3, 0.6), location(9, 0., 0.5)};
  const std::vector<double> expected = solve_mixed(m, vs, ls);

  Polyhedron_with_ids with_ids = read_polyhedron<Polyhedron_with_ids>(name);
  ASSERT_EQ(num_vertices(with_ids), m.number_of_vertices());
  // ids left as read (not initialized): the function must initialize its index maps itself
  EXPECT_TRUE(agrees(solve(with_ids, to_polyhedron(m, with_ids, vs, ls)), expected, diag, 1e-12,
                     name + " Polyhedron with uninitialized ids"));
  CGAL::set_halfedgeds_items_id(with_ids);
  EXPECT_TRUE(agrees(solve(with_ids, to_polyhedron(m, with_ids, vs, ls)), expected, diag, 1e-12,
                     name + " Polyhedron with ids"));

  Polyhedron plain = read_polyhedron<Polyhedron>(name);
  const auto plain_sources = to_polyhedron(m, plain, vs, ls);
  EXPECT_TRUE(agrees(solve(plain, plain_sources), expected, diag, 1e-12, name + " Polyhedron without ids"));

  // explicit index maps, numbering vertices and faces backwards
  typedef boost::graph_traits<Polyhedron>::vertex_descriptor pv;
  typedef boost::graph_traits<Polyhedron>::face_descriptor pf;
  std::map<pv, int> vindex;
  std::map<pf, int> findex;
  int i = int(num_vertices(plain));
  for(pv v : vertices(plain))
    vindex[v] = --i;
  i = int(num_faces(plain));
  for(pf f : faces(plain))
    findex[f] = --i;
  EXPECT_TRUE(agrees(solve(plain, plain_sources,
                           params::vertex_index_map(boost::make_assoc_property_map(vindex))
                             .face_index_map(boost::make_assoc_property_map(findex))),
                     expected, diag, 1e-12, name + " Polyhedron with explicit index maps"));
}

INSTANTIATE_TEST_SUITE_P(Options, Polyhedron_mesh, ::testing::Values("mushroom", "cactus"));

} // namespace
