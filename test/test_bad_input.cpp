// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Bad input: each case must throw CGAL_ext::Geodesic_error whose message names the problem and
// where it is.

#include "support/analytic_surfaces.h"
#include "support/checks.h"
#include "support/solve.h"

#include <limits>
#include <string>
#include <vector>

using namespace test_support;
namespace params = CGAL_ext::parameters;

namespace {

const double nan = std::numeric_limits<double>::quiet_NaN();

// A small valid mesh to break: the 6 x 6 planar grid (36 vertices, 50 faces).
Mesh small_grid() { return make_grid(6, 1.); }

void solve_quietly(const Mesh& m)
{
  solve(m, Vertex(0));
}

TEST(BadInput, EmptyMesh)
{
  const Mesh empty;
  EXPECT_TRUE(throws_geodesic_error([&] { solve(empty, std::vector<Vertex>{Vertex(0)}); }, {"empty", "0 vertices"}));
  // vertices without faces are no surface either
  Mesh points_only;
  points_only.add_vertex(Point(0, 0, 0));
  points_only.add_vertex(Point(1, 0, 0));
  EXPECT_TRUE(throws_geodesic_error([&] { solve_quietly(points_only); }, {"empty", "0 faces"}));
}

TEST(BadInput, QuadFace)
{
  Mesh m = small_grid();
  // a quad sharing an edge with the grid's border: grid vertices 4 -> 5 run along y = 0
  const Vertex a(4), b(5);
  ASSERT_TRUE(m.is_border(m.opposite(m.halfedge(a, b))));
  const Vertex c = m.add_vertex(Point(5, -1, 0)), d = m.add_vertex(Point(4, -1, 0));
  const Face quad = m.add_face(b, a, d, c);
  ASSERT_TRUE(quad.is_valid());
  EXPECT_TRUE(throws_geodesic_error([&] { solve_quietly(m); },
                                    {"face " + std::to_string(quad.idx()) + " has 4 vertices", "triangle"}));
}

class Non_finite : public ::testing::TestWithParam<double> {};

TEST_P(Non_finite, CoordinateIsRejected)
{
  Mesh m = small_grid();
  const Vertex v(14);
  m.point(v) = Point(m.point(v).x(), GetParam(), 0);
  EXPECT_TRUE(throws_geodesic_error([&] { solve_quietly(m); }, {"vertex 14 ", "non-finite"}));
}

INSTANTIATE_TEST_SUITE_P(BadInput, Non_finite,
                         ::testing::Values(nan, std::numeric_limits<double>::infinity(),
                                           -std::numeric_limits<double>::infinity()));

// A zero-area triangle inside a mesh: an interior grid vertex moved onto the segment joining
// the two other corners of one of its faces.
TEST(BadInput, SourceVertexOutOfRange)
{
  const Mesh m = small_grid();
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, Vertex(1000000)); },
                                    {"source vertex 1000000", "out of range", "36 vertices"}));
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, std::vector<Vertex>{Vertex(1), Vertex(36)}); },
                                    {"source vertex 36", "out of range"}));
}

// The caller's index maps must give each element its own index in range.
TEST(BadInput, IndexMapsOutOfRangeOrRepeated)
{
  const Mesh m = small_grid();
  auto vertex_index = get(CGAL::dynamic_vertex_property_t<std::size_t>(), m);
  for(Vertex v : m.vertices())
    put(vertex_index, v, std::size_t(v.idx()));
  put(vertex_index, Vertex(5), std::size_t(4)); // vertices 4 and 5 share an index
  EXPECT_TRUE(throws_geodesic_error(
    [&] { solve(m, Vertex(0), CGAL_ext::parameters::vertex_index_map(vertex_index)); },
    {"vertex index map", "4", "two elements"}));
  put(vertex_index, Vertex(5), std::size_t(36)); // one past the end
  EXPECT_TRUE(throws_geodesic_error(
    [&] { solve(m, Vertex(0), CGAL_ext::parameters::vertex_index_map(vertex_index)); },
    {"vertex index map", "36", "out of range"}));
  auto face_index = get(CGAL::dynamic_face_property_t<std::size_t>(), m);
  for(Face f : m.faces())
    put(face_index, f, std::size_t(f.idx()) + 1); // every face one too far: the last is out of range
  EXPECT_TRUE(throws_geodesic_error(
    [&] { solve(m, Vertex(0), CGAL_ext::parameters::face_index_map(face_index)); },
    {"face index map", "50", "out of range"}));
}

TEST(BadInput, SourceFaceOutOfRange)
{
  const Mesh m = small_grid();
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, location(1000000, 0.2, 0.2)); },
                                    {"source face 1000000", "out of range", "50 faces"}));
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, std::vector<Face_location>{location(3, 0.2, 0.2), location(50, 0.2, 0.2)}); },
                                    {"source face 50", "out of range"}));
}

struct Bad_barycentric
{
  const char* name;
  Barycentric b;
};

std::ostream& operator<<(std::ostream& os, const Bad_barycentric& c) { return os << c.name; }

class Barycentric_coordinates : public ::testing::TestWithParam<Bad_barycentric> {};

TEST_P(Barycentric_coordinates, AreRejected)
{
  const Mesh m = small_grid();
  const Face_location l(Face(7), GetParam().b);
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, l); }, {"barycentric", "face 7 ", "non-negative and sum to 1"}));
}

INSTANTIATE_TEST_SUITE_P(BadInput, Barycentric_coordinates,
                         ::testing::Values(Bad_barycentric{"negative", {{-0.1, 0.6, 0.5}}},
                                           Bad_barycentric{"slightly_negative", {{0.5, 0.5 + 1e-9, -1e-9}}},
                                           Bad_barycentric{"sum_below_1", {{0.3, 0.3, 0.3}}},
                                           Bad_barycentric{"sum_above_1", {{0.5, 0.5, 0.1}}},
                                           Bad_barycentric{"all_zero", {{0., 0., 0.}}},
                                           Bad_barycentric{"nan", {{nan, 0.5, 0.5}}},
                                           Bad_barycentric{"infinite", {{std::numeric_limits<double>::infinity(), 0., 0.}}}),
                         [](const ::testing::TestParamInfo<Bad_barycentric>& i) { return std::string(i.param.name); });

TEST(BadInput, NegativeOrNanMaxDistance)
{
  const Mesh m = small_grid();
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, Vertex(0), params::max_distance(-1.)); },
                                    {"max distance", "non-negative", "-1"}));
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, Vertex(0), params::max_distance(nan)); },
                                    {"max distance", "non-negative"}));
}

TEST(BadInput, StopVertexOutOfRange)
{
  const Mesh m = small_grid();
  EXPECT_TRUE(throws_geodesic_error(
    [&] { solve(m, Vertex(0), params::stop_vertices(std::vector<Vertex>{Vertex(3), Vertex(1000000)})); },
    {"stop vertex 1000000", "out of range", "36 vertices"}));
}

TEST(BadInput, NoSource)
{
  const Mesh m = small_grid();
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, std::vector<Vertex>{}); }, {"no source"}));
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, std::vector<Face_location>{}); }, {"no source"}));
}

TEST(BadInput, UnknownAlgorithm)
{
  const Mesh m = small_grid();
  EXPECT_TRUE(throws_geodesic_error(
    [&] { solve(m, Vertex(0), params::algorithm(static_cast<CGAL_ext::Geodesic_algorithm>(7))); },
    {"unknown geodesic algorithm 7"}));
}


} // namespace
