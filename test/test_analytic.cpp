// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Exact distances on developable and simple polyhedral surfaces, where the geodesic distance is
// known in closed form: planar grids, an open cylinder, cones, a cube and a tetrahedron.

#include "support/analytic_surfaces.h"
#include "support/checks.h"
#include "support/solve.h"

#include <CGAL_ext/Geodesics_3/internal/kernel/Edge_window_store.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Source_windows.h>
#include <CGAL_ext/Geodesics_3/internal/kernel/Window.h>
#include <CGAL_ext/Geodesics_3/internal/support/Object_pool.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <optional>
#include <random>
#include <string>
#include <utility>
#include <vector>

using namespace test_support;

namespace {

// The exact distance field: the minimum over the sources of `distance(source position, vertex
// position)` in the development, where a face-location source is at the barycentric combination
// of its developed corners (unwrapped across the seam of a periodic development).
template <class Distance, class Unwrap>
std::vector<double> exact_field(const Mesh& m, const Sources& s, Distance distance, Unwrap unwrap)
{
  const auto dev = developed_map(m);
  std::vector<Point_2> from;
  for(Vertex v : s.vertices)
    from.push_back(get(dev, v));
  for(const Face_location& l : s.faces)
    from.push_back(developed_location(m, l, unwrap));
  std::vector<double> d(m.number_of_vertices(), inf);
  for(Vertex v : m.vertices())
    for(const Point_2& p : from)
      d[v.idx()] = std::min(d[v.idx()], distance(p, get(dev, v)));
  return d;
}

auto no_unwrap = [](const Point_2&, const Point_2& q) { return q; };

std::vector<double> solve_sources(const Mesh& m, const Sources& s) { return solve_mixed(m, s.vertices, s.faces); }

// ---------------------------------------------------------------------------------------------
// Planar grids: the geodesic distance is the Euclidean one in a convex domain; in the L-shaped
// domain, a target hidden from the source is reached around the reflex corner.

struct Planar_case
{
  const char* name;
  double jitter;
  bool l_shape;
  int source; // 0: interior vertex, 1: corner vertex, 2: face interior, 3: point on an edge, 4: two vertices
};

std::ostream& operator<<(std::ostream& os, const Planar_case& c) { return os << c.name; }

class Planar : public ::testing::TestWithParam<Planar_case> {};

TEST_P(Planar, EuclideanDistance)
{
  const Planar_case& c = GetParam();
  const int n = 30;
  const double h = 0.1;
  const Mesh m = make_grid(n, h, c.jitter, c.l_shape);
  for(Face f : m.faces()) { // the jittered grid must still be a flat, unfolded domain
    const auto t = face_corners(m, f);
    ASSERT_EQ(CGAL::orientation(Point_2(m.point(t[0]).x(), m.point(t[0]).y()),
                                Point_2(m.point(t[1]).x(), m.point(t[1]).y()),
                                Point_2(m.point(t[2]).x(), m.point(t[2]).y())),
              CGAL::LEFT_TURN)
      << "face " << f << " is flipped";
  }
  const L_shape l_shape = grid_l_shape(n, h);
  // vertex indices: the grid is numbered row by row (rows shortened in the L's upper half)
  Vertex interior, grid_corner(0);
  for(Vertex v : m.vertices()) {
    const Point& p = m.point(v);
    if(std::abs(p.x() - 7 * h) < 0.5 * h && std::abs(p.y() - 11 * h) < 0.5 * h)
      interior = v;
  }
  ASSERT_TRUE(interior.is_valid());
  Sources s;
  switch(c.source) {
  case 0: s.vertices = {interior}; break;
  case 1: s.vertices = {grid_corner}; break;
  case 2: s.faces = {location(37, 0.2, 0.3)}; break;
  case 3: s.faces = {location(101, 0.35, 0.65)}; break;
  default: s.vertices = {interior, Vertex(static_cast<Mesh::size_type>(m.number_of_vertices() - 1))};
  }
  auto distance = [&](const Point_2& p, const Point_2& q) {
    return c.l_shape ? l_shape.distance(p, q) : std::sqrt(CGAL::squared_distance(p, q));
  };
  const std::vector<double> exact = exact_field(m, s, distance, no_unwrap);
  EXPECT_TRUE(agrees_relative(solve_sources(m, s), exact, 1e-12, c.name));
}

INSTANTIATE_TEST_SUITE_P(
  Analytic, Planar,
  ::testing::Values(Planar_case{"grid_vertex", 0, false, 0}, Planar_case{"grid_corner", 0, false, 1},
                    Planar_case{"grid_face", 0, false, 2}, Planar_case{"grid_edge", 0, false, 3},
                    Planar_case{"grid_two_vertices", 0, false, 4},
                    Planar_case{"jittered_vertex", 0.2, false, 0}, Planar_case{"jittered_corner", 0.2, false, 1},
                    Planar_case{"jittered_face", 0.2, false, 2}, Planar_case{"jittered_edge", 0.2, false, 3},
                    Planar_case{"L_vertex", 0, true, 0}, Planar_case{"L_corner", 0, true, 1},
                    Planar_case{"L_face", 0, true, 2}, Planar_case{"L_jittered_vertex", 0.2, true, 0},
                    Planar_case{"L_jittered_two_vertices", 0.2, true, 4}),
  [](const ::testing::TestParamInfo<Planar_case>& i) { return std::string(i.param.name); });

// ---------------------------------------------------------------------------------------------
// The open polyhedral cylinder develops isometrically into a strip of width W = n * chord,
// periodic in its first coordinate; the strip is convex across its height, so the distance is
// the smallest planar distance between the source and the copies of the target shifted by W
// (Strip in support/analytic_surfaces.h).

struct Cylinder_case
{
  const char* name;
  int segments, rows;
  int source; // 0: bottom border vertex, 1: middle vertex, 2: face interior, 3: point on an edge, 4: mixed
};

std::ostream& operator<<(std::ostream& os, const Cylinder_case& c) { return os << c.name; }

class Cylinder : public ::testing::TestWithParam<Cylinder_case> {};

TEST_P(Cylinder, UnrolledStripDistance)
{
  const Cylinder_case& c = GetParam();
  const double r = 1.5, height = 4;
  const Mesh m = make_cylinder(r, c.segments, height, c.rows);
  const Strip strip = cylinder_strip(r, c.segments);
  const std::size_t nf = m.number_of_faces();
  Sources s;
  const Vertex middle(static_cast<Mesh::size_type>((c.rows / 2) * c.segments + c.segments / 3));
  switch(c.source) {
  case 0: s.vertices = {Vertex(0)}; break;
  case 1: s.vertices = {middle}; break;
  case 2: s.faces = {location(nf / 2 + 3, 0.25, 0.45)}; break;
  case 3: s.faces = {location(nf / 3 + 1, 0., 0.4)}; break;
  default:
    s.vertices = {middle};
    s.faces = {location(nf - 1, 0.3, 0.3)}; // a face on the seam (last column)
  }
  auto unwrap = [&](const Point_2& ref, const Point_2& q) { return strip.unwrapped(ref, q); };
  auto distance = [&](const Point_2& p, const Point_2& q) { return strip.distance(p, q); };
  EXPECT_TRUE(agrees_relative(solve_sources(m, s), exact_field(m, s, distance, unwrap), 1e-12, c.name));
}

INSTANTIATE_TEST_SUITE_P(Analytic, Cylinder,
                         ::testing::Values(Cylinder_case{"border_vertex", 24, 10, 0},
                                           Cylinder_case{"middle_vertex", 24, 10, 1},
                                           Cylinder_case{"face", 24, 10, 2}, Cylinder_case{"edge", 24, 10, 3},
                                           Cylinder_case{"mixed_on_seam", 24, 10, 4},
                                           Cylinder_case{"coarse_border_vertex", 7, 3, 0},
                                           Cylinder_case{"fine_middle_vertex", 64, 40, 1}),
                         [](const ::testing::TestParamInfo<Cylinder_case>& i) { return std::string(i.param.name); });

// ---------------------------------------------------------------------------------------------
// The polyhedral cone develops into a sector of angle theta around the apex. From the apex, the
// distance is the slant distance. When theta < pi the development cut along any generator is
// convex, so between two points at polar (r1, a1), (r2, a2) the distance is the planar one for
// the smaller of the two angular gaps |a1 - a2| and theta - |a1 - a2| (Sector in
// support/analytic_surfaces.h).

struct Cone_case
{
  const char* name;
  double radius, height;
  int segments, rings;
  int source; // 0: apex, 1: rim vertex, 2: interior vertex, 3: face interior, 4: rim and face
};

std::ostream& operator<<(std::ostream& os, const Cone_case& c) { return os << c.name; }

class Cone : public ::testing::TestWithParam<Cone_case> {};

TEST_P(Cone, DevelopedSectorDistance)
{
  const Cone_case& c = GetParam();
  const Mesh m = make_cone(c.radius, c.height, c.segments, c.rings);
  const Sector sector = cone_sector(c.radius, c.height, c.segments);
  if(c.source != 0)
    ASSERT_LT(sector.angle, pi) << "the closed form needs a sector narrower than pi";
  auto vertex = [&](int k, int j) { return Vertex(static_cast<Mesh::size_type>(1 + (j - 1) * c.segments + k)); };
  const std::size_t nf = m.number_of_faces();
  Sources s;
  switch(c.source) {
  case 0: s.vertices = {Vertex(0)}; break;
  case 1: s.vertices = {vertex(c.segments / 4, c.rings)}; break;
  case 2: s.vertices = {vertex(c.segments / 2, c.rings / 2)}; break;
  case 3: s.faces = {location(nf / 2 + 5, 0.2, 0.5)}; break;
  default:
    s.vertices = {vertex(1, c.rings)};
    s.faces = {location(nf - 2, 0.4, 0.35)}; // near the seam
  }
  auto unwrap = [&](const Point_2& ref, const Point_2& q) { return sector.unwrapped(ref, q); };
  auto distance = [&](const Point_2& p, const Point_2& q) { return sector.distance(p, q); };
  EXPECT_TRUE(agrees_relative(solve_sources(m, s), exact_field(m, s, distance, unwrap), 1e-12, c.name));
}

INSTANTIATE_TEST_SUITE_P(Analytic, Cone,
                         ::testing::Values(Cone_case{"flat_cone_apex", 2, 1, 40, 12, 0},
                                           Cone_case{"narrow_cone_apex", 1, 4, 32, 10, 0},
                                           Cone_case{"narrow_cone_rim_vertex", 1, 4, 32, 10, 1},
                                           Cone_case{"narrow_cone_interior_vertex", 1, 4, 32, 10, 2},
                                           Cone_case{"narrow_cone_face", 1, 4, 32, 10, 3},
                                           Cone_case{"narrow_cone_rim_and_face", 1, 4, 32, 10, 4},
                                           Cone_case{"coarse_narrow_cone_rim_vertex", 1, 3, 9, 2, 1}),
                         [](const ::testing::TestParamInfo<Cone_case>& i) { return std::string(i.param.name); });

// ---------------------------------------------------------------------------------------------
// A saddle: the pleated cone's apex has an angle sum above 2 pi. Developed around the apex,
// vertex (k, j) lies at radius j / rings and polar angle k alpha, and between two points the
// distance is the planar one across the smaller angular gap when that gap is below pi, and
// otherwise the sum of their radii: the path passes through the apex. The apex sends windows
// only into the directions a path through it can take, those at least pi from where its own
// shortest path arrives on both sides; a cone of directions placed or sized wrongly leaves the
// vertices behind the apex too far.

TEST(AnalyticSaddle, PleatedConeThroughTheApex)
{
  const int segments = 12, rings = 10;
  for(const double tilt : {0.35, 0.8}) {
    std::vector<std::pair<double, double>> developed;
    const Mesh m = make_pleated_cone(segments, rings, tilt, developed);
    const double total = segments * std::acos((std::cos(2 * pi / segments) - tilt * tilt) / (1 + tilt * tilt));
    ASSERT_GT(total, 2 * pi + 0.1) << "the apex must be a saddle";
    auto polar = [&](Vertex v) { return developed[v.idx()]; };
    auto distance = [&](Vertex a, Vertex b) {
      const auto [r1, a1] = polar(a);
      const auto [r2, a2] = polar(b);
      double gap = std::fmod(std::abs(a1 - a2), total);
      gap = std::min(gap, total - gap);
      return gap >= pi ? r1 + r2 : std::sqrt(std::max(0., r1 * r1 + r2 * r2 - 2 * r1 * r2 * std::cos(gap)));
    };
    auto vertex = [&](int k, int j) { return Vertex(static_cast<Mesh::size_type>(1 + (j - 1) * segments + k)); };
    for(const std::vector<Vertex>& sources :
        {std::vector<Vertex>{vertex(2, 6)}, std::vector<Vertex>{vertex(5, 10)}, std::vector<Vertex>{vertex(0, 3), vertex(7, 9)}}) {
      std::vector<double> exact(m.number_of_vertices(), inf);
      for(Vertex v : m.vertices())
        for(Vertex s : sources)
          exact[v.idx()] = std::min(exact[v.idx()], distance(s, v));
      // the vertices whose shortest path passes through the apex: their distance is the apex's
      // plus their radius
      std::size_t behind = 0;
      for(Vertex v : m.vertices())
        behind += v != Vertex(0) && exact[v.idx()] >= exact[0] + polar(v).first - 1e-12;
      const std::string name = "tilt " + std::to_string(tilt) + " from vertex " + std::to_string(sources[0].idx());
      ASSERT_GT(behind, std::size_t(segments)) << name << ": no vertex is reached through the apex";
      EXPECT_TRUE(agrees_relative(solve(m, sources), exact, 1e-12, name + " VTP"));
      EXPECT_TRUE(agrees_relative(solve<CGAL::Parallel_tag>(m, sources, CGAL_ext::parameters::number_of_threads(2)),
                                  exact, 1e-12, name + " PVTP"));
      EXPECT_TRUE(agrees_relative(solve(m, sources, CGAL_ext::parameters::algorithm(CGAL_ext::FWP_MMP)), exact, 1e-12,
                                  name + " FWP-MMP"));
      EXPECT_TRUE(agrees_relative(solve(m, sources, CGAL_ext::parameters::algorithm(CGAL_ext::MMP)), exact, 1e-12,
                                  name + " MMP"));
      // The approximation's saddles emit into their cone too: exact while no reset happens;
      // with resets (whose sources emit every way), every vertex reached and none below exact.
      EXPECT_TRUE(agrees_relative(solve(m, sources, CGAL_ext::parameters::approximation(1e6)), exact, 1e-12,
                                  name + " AVTP without a reset"));
      const std::vector<double> approximate = solve(m, sources, CGAL_ext::parameters::approximation(1.));
      for(Vertex v : m.vertices()) {
        EXPECT_TRUE(std::isfinite(approximate[v.idx()])) << name << " AVTP, vertex " << v.idx();
        EXPECT_GE(approximate[v.idx()], exact[v.idx()] * (1 - 1e-12)) << name << " AVTP, vertex " << v.idx();
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Cube [0, s]^3 from the corner O = (0, 0, 0). A point on one of the three faces through O is at
// its Euclidean distance. A point (s, y, z) of the far face x = s is reached across the face
// y = 0 or the face z = 0: unfolded, at distance min(hypot(s + y, z), hypot(s + z, y)) (and
// symmetrically for the faces y = s, z = s). So the adjacent corners are at s, the far corners
// of the three faces through O at s sqrt(2), and the opposite corner (s, s, s) at s sqrt(5).

class Cube : public ::testing::TestWithParam<int> {};

TEST_P(Cube, DistancesFromACorner)
{
  const int n = GetParam();
  const double side = 2.5;
  const Mesh m = make_cube(side, n);
  ASSERT_EQ(m.point(Vertex(0)), Point(0, 0, 0));
  std::vector<double> exact(m.number_of_vertices(), inf);
  for(Vertex v : m.vertices()) {
    const Point& p = m.point(v);
    const double c[3] = {p.x(), p.y(), p.z()};
    if(std::min({c[0], c[1], c[2]}) == 0) {
      exact[v.idx()] = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
      continue;
    }
    for(int axis = 0; axis < 3; ++axis)
      if(c[axis] == side) {
        const double y = c[(axis + 1) % 3], z = c[(axis + 2) % 3];
        exact[v.idx()] = std::min({exact[v.idx()], std::hypot(side + y, z), std::hypot(side + z, y)});
      }
  }
  const std::vector<double> d = solve(m, Vertex(0));
  EXPECT_TRUE(agrees_relative(d, exact, 1e-12, "cube n=" + std::to_string(n)));
  // the corners by name
  for(Vertex v : m.vertices())
    if(const std::optional<double> expected = cube_corner_distance(m.point(v), side))
      EXPECT_NEAR(d[v.idx()], *expected, 1e-12 * side) << "corner " << m.point(v);
}

INSTANTIATE_TEST_SUITE_P(Analytic, Cube, ::testing::Values(1, 2, 5, 12));

// A regular tetrahedron of edge a: from a vertex every other vertex is at a; from the centre of
// a face, its corners are at a / sqrt(3) and the opposite vertex, reached across an edge midpoint
// in the unfolding (the net is a triangle of side 2a), at 2a / sqrt(3).
TEST(AnalyticTetrahedron, VertexAndFaceCentreSources)
{
  const double a = 3;
  const Mesh m = make_tetrahedron(a);
  EXPECT_TRUE(agrees_relative(solve(m, Vertex(2)), {a, a, 0, a}, 1e-12, "tetrahedron from a vertex"));
  for(Face f : m.faces()) {
    const auto corners = face_corners(m, f);
    std::vector<double> exact(4, 2 * a / std::sqrt(3.));
    for(Vertex v : corners)
      exact[v.idx()] = a / std::sqrt(3.);
    EXPECT_TRUE(agrees_relative(solve(m, Face_location(f, Barycentric{{1. / 3, 1. / 3, 1. / 3}})), exact, 1e-12,
                                "tetrahedron from the centre of face " + std::to_string(f.idx())));
  }
}

// ---------------------------------------------------------------------------------------------
// The window toolkit against the distances it compares: on every piece of an overlap that
// `compare_on_overlap` reports, the window it names is the shorter one wherever sampled (away
// from the cut points). Random windows of a unit edge, and pairs built to share a pseudo-source
// height or an end distance, the cases where the pre-tests decide without the quadratic.
TEST(WindowToolkit, OverlapPiecesGoToTheShorterWindow)
{
  namespace gi = CGAL_ext::Geodesics_3::internal;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> unit(0., 1.);
  auto random_window = [&]() {
    gi::Window_geometry w;
    w.b0 = unit(random) * 0.5;
    w.b1 = 0.5 + unit(random) * 0.5;
    w.sx = -1 + 3 * unit(random);
    w.sy = -0.01 - 1.5 * unit(random);
    w.sigma = 0.5 * unit(random);
    return w;
  };
  int pieces = 0, split = 0;
  for(int pair = 0; pair < 20000; ++pair) {
    gi::Window_geometry w0 = random_window(), w1 = random_window();
    if(pair % 4 == 1)
      w1.sy = w0.sy; // the line through the pseudo-sources never meets the edge
    if(pair % 4 == 2) // equal distances at the start of the overlap
      w1.sigma = std::max(0., gi::distance_at(w0, std::max(w0.b0, w1.b0)) -
                                  gi::norm2d(std::max(w0.b0, w1.b0) - w1.sx, w1.sy));
    const double lo = std::max(w0.b0, w1.b0), hi = std::min(w0.b1, w1.b1);
    double cut[4];
    int winner[3];
    const int n = gi::compare_on_overlap(w0, w1, lo, hi, cut, winner);
    ASSERT_GE(n, 2);
    ASSERT_LE(n, 4);
    EXPECT_EQ(cut[0], lo);
    EXPECT_EQ(cut[n - 1], hi);
    split += n > 2;
    for(int i = 0; i + 1 < n; ++i) {
      ASSERT_LE(cut[i], cut[i + 1]);
      ++pieces;
      for(int k = 1; k < 10; ++k) {
        const double x = cut[i] + (cut[i + 1] - cut[i]) * k / 10.;
        if(x - cut[i] < 1e-9 || cut[i + 1] - x < 1e-9)
          continue;
        const double d0 = gi::distance_at(w0, x), d1 = gi::distance_at(w1, x);
        const double won = winner[i] == 0 ? d0 : d1, lost = winner[i] == 0 ? d1 : d0;
        ASSERT_LE(won, lost + 1e-12) << "pair " << pair << ", piece " << i << " of " << n - 1 << ", x = " << x;
      }
    }
  }
  EXPECT_GT(split, 1000); // overlaps where the windows cross were among them
  EXPECT_GT(pieces, 20000);
}

// VTP's window store: objects made one after the other form runs within a block of 64, found
// again by index, 64-byte aligned; a make that is not kept leaves its place to the next; two
// lanes make two runs at once; a block is made in again only once every object in it is freed;
// the live count and the bytes of the groups.
TEST(WindowToolkit, RunPoolMakesRunsAndTakesBlocksBack)
{
  namespace gi = CGAL_ext::Geodesics_3::internal;
  typedef gi::Run_pool<gi::Window> Pool;
  Pool pool;
  const std::uint32_t b = Pool::block_size;
  const std::size_t n = 3 * b + 5;
  std::vector<std::uint32_t> index(n);
  for(std::size_t i = 0; i < n; ++i) {
    gi::Window w;
    w.source = int(i);
    index[i] = pool.make_copy(0, 0, w);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(&pool[index[i]]) % 64, 0u);
    if(i > 0)
      EXPECT_EQ(Pool::continues_run(index[i - 1], 1, index[i]), i % b != 0) << "a run ends with its block, at " << i;
    std::uint32_t refused = Pool::nil;
    EXPECT_FALSE(pool.make(0, 0, refused, [](gi::Window&) { return false; }));
    EXPECT_EQ(refused, Pool::nil);
  }
  EXPECT_EQ(pool.live(), n);
  for(std::size_t i = 0; i < n; ++i)
    ASSERT_EQ(pool[index[i]].source, int(i)) << "a refused make did not take a place";
  const std::size_t bytes = pool.bytes();
  EXPECT_GT(bytes, n * sizeof(gi::Window));

  // Two lanes: objects made in turn in each form two runs.
  std::uint32_t first[2], count[2] = {0, 0};
  for(int k = 0; k < 10; ++k)
    for(unsigned lane = 0; lane < 2; ++lane) {
      const std::uint32_t i = pool.make_copy(0, lane, gi::Window{});
      if(count[lane] == 0)
        first[lane] = i;
      else
        ASSERT_TRUE(Pool::continues_run(first[lane], count[lane], i)) << "lane " << lane;
      ++count[lane];
    }
  pool.free_run(0, first[0], count[0]);
  pool.free_run(0, first[1], count[1]);
  EXPECT_EQ(pool.live(), n);

  // The first block, all but one of its objects freed, is not made in again; with the last
  // one freed it is (the lanes are given new blocks from those freed first).
  pool.free_run(0, index[0], b - 1);
  std::vector<std::uint32_t> made;
  for(std::uint32_t k = 0; k < 2 * b; ++k)
    made.push_back(pool.make_copy(0, 0, gi::Window{}));
  for(std::uint32_t i : made)
    ASSERT_NE(i / b, index[0] / b) << "a block with an object in use is not made in";
  pool.free_run(0, index[b - 1], 1);
  for(std::uint32_t k = 0; k < 2 * b; ++k)
    made.push_back(pool.make_copy(0, 0, gi::Window{}));
  EXPECT_NE(std::find_if(made.begin(), made.end(), [&](std::uint32_t i) { return i / b == index[0] / b; }),
            made.end())
    << "a block whose objects are all freed is made in again";
  for(std::uint32_t i : made)
    pool.free_run(0, i, 1);
  for(std::size_t i = b; i < n; ++i)
    pool.free_run(0, index[i], 1);
  EXPECT_EQ(pool.live(), 0u);
  // everything freed: as many objects again take no new memory
  for(std::size_t i = 0; i < n; ++i)
    pool.free_run(0, pool.make_copy(0, 0, gi::Window{}), 1);
  EXPECT_EQ(pool.bytes(), bytes);
}

// With several slots (one per thread), the blocks that one thread frees reach the other that
// makes (through the shared blocks), and a pool that goes back to one slot, objects of the slot
// that goes still alive, keeps every block: no memory grows while the windows alive stay few.
TEST(WindowToolkit, RunPoolSharesBlocksBetweenSlots)
{
#ifdef CGAL_LINKED_WITH_TBB
  namespace gi = CGAL_ext::Geodesics_3::internal;
  typedef gi::Run_pool<gi::Window> Pool;
  Pool pool;
  tbb::task_arena arena(2);
  arena.execute([&] { pool.use_one_slot_per_thread(true); });
  ASSERT_EQ(pool.number_of_slots(), 2u);
  // slot 0 makes, slot 1 frees, many times the objects of a group
  const std::size_t rounds = 200, per_round = 5 * Pool::block_size;
  std::vector<std::uint32_t> index(per_round);
  std::size_t bytes_after_first = 0;
  for(std::size_t r = 0; r < rounds; ++r) {
    for(std::uint32_t& i : index)
      i = pool.make_copy(0, r % 2, gi::Window{});
    for(std::uint32_t i : index)
      pool.free_run(1, i, 1);
    if(r == 0)
      bytes_after_first = pool.bytes();
  }
  EXPECT_EQ(pool.live(), 0u);
  EXPECT_LE(pool.bytes(), 2 * bytes_after_first) << "the freed blocks were made in again";
  // objects of the second slot still alive, its lanes in the middle of blocks, when it goes:
  // freed in the first slot, their blocks are made in again
  std::vector<std::uint32_t> alive;
  for(int k = 0; k < 70; ++k)
    alive.push_back(pool.make_copy(1, k % 2, gi::Window{}));
  const std::size_t bytes = pool.bytes();
  pool.use_one_slot_per_thread(false);
  ASSERT_EQ(pool.number_of_slots(), 1u);
  EXPECT_EQ(pool.live(), alive.size());
  for(std::uint32_t i : alive)
    pool.free_run(0, i, 1);
  for(std::size_t r = 0; r < rounds; ++r) {
    for(std::uint32_t& i : index)
      i = pool.make_copy(0, 0, gi::Window{});
    for(std::uint32_t i : index)
      pool.free_run(0, i, 1);
  }
  EXPECT_EQ(pool.bytes(), bytes) << "one slot keeps the blocks of both";
#else
  GTEST_SKIP() << "TBB is needed for a pool of several slots";
#endif
}

// The bits of a double, to compare values bit for bit (signed zeros, NaN's payload).
static std::uint64_t bits_of(double x)
{
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// The kernels' square root is std::sqrt's correctly rounded value, bit for bit, from denormals
// to the largest doubles; a negative argument gives NaN as std::sqrt does.
TEST(WindowToolkit, SquareRootIsStdSqrtBitForBit)
{
  namespace gi = CGAL_ext::Geodesics_3::internal;
  std::vector<double> values{0.,
                             -0.,
                             1.,
                             2.,
                             std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::min(),
                             std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::infinity()};
  std::mt19937_64 random(12);
  std::uniform_real_distribution<double> mantissa(1., 2.);
  std::uniform_int_distribution<int> exponent(-1070, 1020);
  for(int i = 0; i < 100000; ++i)
    values.push_back(std::ldexp(mantissa(random), exponent(random)));
  for(double x : values)
    ASSERT_EQ(bits_of(gi::square_root(x)), bits_of(std::sqrt(x))) << "x = " << x;
  EXPECT_TRUE(std::isnan(gi::square_root(-1.)));
  EXPECT_TRUE(std::isnan(gi::square_root(std::numeric_limits<double>::quiet_NaN())));
}

// Two values computed side by side (a window's two ends) are the bits of the scalar
// operations, NaN, infinities and signed zeros included; the clamp of a ray's parameter sends
// NaN and what is not above 0 to +0.
TEST(WindowToolkit, DoublePairIsTheScalarArithmetic)
{
  namespace gi = CGAL_ext::Geodesics_3::internal;
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> values{0., -0., 1., -1., 3., inf, -inf, nan, std::numeric_limits<double>::denorm_min(), 1e300};
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> any(-10., 10.);
  for(int i = 0; i < 2000; ++i)
    values.push_back(any(random));
  const double upper = 2.5;
  const auto clamp = [&](double t) { return t > 0 ? (t < upper ? t : upper) : 0.; };
  for(std::size_t i = 0; i + 1 < values.size(); ++i) {
    const double a = values[i], b = values[i + 1], c = values[values.size() - 1 - i];
    const gi::Double_pair x(a, b), y(c, a);
    const gi::Double_pair r = (x * x + gi::Double_pair::both(c)) / (x - y);
    ASSERT_EQ(bits_of(r.first()), bits_of((a * a + c) / (a - c))) << a << " " << b << " " << c;
    ASSERT_EQ(bits_of(r.second()), bits_of((b * b + c) / (b - a))) << a << " " << b << " " << c;
    const gi::Double_pair t = clamp_to(x, upper), s = square_roots(x);
    ASSERT_EQ(bits_of(t.first()), bits_of(clamp(a)));
    ASSERT_EQ(bits_of(t.second()), bits_of(clamp(b)));
    ASSERT_EQ(bits_of(s.first()), bits_of(gi::square_root(a))) << a;
    ASSERT_EQ(bits_of(s.second()), bits_of(gi::square_root(b))) << b;
  }
}

// The saddle cone's arctangent agrees with std::atan2 to 3e-15 rad in every quadrant, at the
// ends of its reduction intervals, on the axes and for ratios near 0 and 1.
TEST(WindowToolkit, PolarAngleIsAtan2)
{
  namespace gi = CGAL_ext::Geodesics_3::internal;
  std::vector<std::pair<double, double>> points{{0., 1.}, {0., -1.}, {-0., -1.}, {1., 0.}, {-1., 0.}, {1., 1.},
                                                {-1., -1.}, {1e-300, 1.}, {1., 1e-300}, {0.19891236737965800691, 1.},
                                                {0.66817863791929891999, 1.}, {0.41421356237309504880, -1.}};
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> coordinate(-1., 1.);
  std::uniform_int_distribution<int> exponent(-30, 30);
  for(int i = 0; i < 200000; ++i)
    points.emplace_back(std::ldexp(coordinate(random), exponent(random)), std::ldexp(coordinate(random), exponent(random)));
  for(const auto& [y, x] : points)
    ASSERT_NEAR(gi::polar_angle(y, x), std::atan2(y, x), 3e-15) << "y = " << y << ", x = " << x;
  EXPECT_EQ(gi::polar_angle(-0., -1.), std::atan2(-0., -1.)) << "the sign of a zero y chooses between pi and -pi";
  EXPECT_EQ(gi::polar_angle(0., 0.), 0.);
}

// MMP's window store: a new block's windows start at version 0 (the blocks are not zeroed, the
// version alone is initialized), and a freed window comes back first with the version it had.
TEST(WindowToolkit, ObjectPoolNewWindowsStartAtVersionZero)
{
  namespace gi = CGAL_ext::Geodesics_3::internal;
  gi::Object_pool<gi::Edge_window> pool;
  const std::size_t n = 2 * gi::Object_pool_slot<gi::Edge_window>::block_size + 3;
  std::vector<gi::Edge_window*> made;
  for(std::size_t i = 0; i < n; ++i) {
    gi::Edge_window* w = pool.allocate(0);
    ASSERT_EQ(w->version, 0u) << "window " << i;
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(w) % 64, 0u);
    w->version = std::uint32_t(i + 7);
    made.push_back(w);
  }
  EXPECT_EQ(pool.live(), n);
  pool.release(0, made[5]);
  gi::Edge_window* again = pool.allocate(0);
  EXPECT_EQ(again, made[5]);
  EXPECT_EQ(again->version, 12u);
  EXPECT_EQ(pool.live(), n);
}

} // namespace
