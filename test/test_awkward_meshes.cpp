// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Meshes as users have them, solved exactly: non-manifold (pinched) vertices, vertices the
// caller glues into one point, degenerate (zero-area) triangles, isolated vertices, and
// coordinates of any scale.

#include "support/analytic_surfaces.h"
#include "support/checks.h"
#include "support/solve.h"

#include <CGAL_ext/Geodesics_3/polyline_length.h>
#include <CGAL_ext/Surface_mesh_geodesic_paths.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace test_support;
namespace params = CGAL_ext::parameters;

namespace {

// Every exact algorithm, sequential and on 1, 2 and 4 threads.
template <class NamedParameters>
std::vector<std::pair<std::string, std::vector<double>>> solve_all(const Mesh& m, const std::vector<Vertex>& sources,
                                                                   const NamedParameters& np)
{
  std::vector<std::pair<std::string, std::vector<double>>> out;
  out.emplace_back("VTP", solve(m, sources, np));
  out.emplace_back("MMP", solve(m, sources, np.algorithm(CGAL_ext::MMP)));
  out.emplace_back("FWP-MMP", solve(m, sources, np.algorithm(CGAL_ext::FWP_MMP)));
  for(int threads : {1, 2, 4}) {
    const std::string t = " T=" + std::to_string(threads);
    out.emplace_back("PVTP" + t, solve<CGAL::Parallel_tag>(m, sources, np.number_of_threads(threads)));
    out.emplace_back("PMMP" + t,
                     solve<CGAL::Parallel_tag>(m, sources, np.number_of_threads(threads).algorithm(CGAL_ext::MMP)));
  }
  return out;
}

double path_length(const Mesh& m, Vertex source, Vertex target)
{
  CGAL_ext::Surface_mesh_geodesic_paths<Mesh> paths(m);
  paths.add_source(source);
  paths.build();
  std::vector<Point> points;
  paths.shortest_path_points(target, std::back_inserter(points));
  return CGAL_ext::polyline_length(points);
}

// Two triangles sharing only vertex 0 (a bow-tie): Surface_mesh holds vertex 0 with two open
// fans. The way from one triangle to the other is through vertex 0.
TEST(NonManifoldVertex, BowTieIsSolvedThroughThePinch)
{
  const Mesh m = mesh_from_soup({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(-1, 0, 0), Point(0, -1, 0)},
                                {{0, 1, 2}, {0, 3, 4}});
  const std::vector<double> exact{1, 0, std::sqrt(2.), 2, 2};
  for(const auto& [name, d] : solve_all(m, {Vertex(1)}, params::default_values()))
    EXPECT_TRUE(agrees(d, exact, 2., 1e-15, "bow-tie " + name));
  EXPECT_NEAR(path_length(m, Vertex(1), Vertex(3)), 2., 1e-15);
}

// Two polyhedral cones (make_cone) that touch at their apexes: a double cone pinched at one
// point. Surface_mesh cannot hold two closed fans at one vertex, so each cone has its own apex
// and the caller glues them (what polygon_soup_to_geodesic_mesh reports for such a file). From
// a vertex of the first cone, a vertex of the second is reached through the apex: its distance
// is the sum of both developed radii, whatever the directions.
struct Double_cone
{
  Mesh mesh;
  Vertex apex_a, apex_b;
  std::vector<double> radius; // developed distance of each vertex to its cone's apex
  Vertex first_of_b;          // the vertices of the second cone come after the first's
};

Double_cone make_double_cone(double r, double height, int segments, int rings)
{
  const Mesh cone = make_cone(r, height, segments, rings);
  const auto dev = developed_map(cone);
  Double_cone d;
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  for(int copy = 0; copy < 2; ++copy) {
    const int offset = int(points.size());
    // the second cone turned upside down and rotated, its apex on the first's
    const double turn = 0.3;
    for(Vertex v : cone.vertices()) {
      const Point& p = cone.point(v);
      if(copy == 0)
        points.push_back(p);
      else
        points.push_back(Point(std::cos(turn) * p.x() - std::sin(turn) * p.y(),
                               std::sin(turn) * p.x() + std::cos(turn) * p.y(), 2 * height - p.z()));
      d.radius.push_back(std::sqrt(CGAL::squared_distance(get(dev, v), Point_2(0, 0))));
    }
    for(Mesh::Face_index f : cone.faces()) {
      const auto c = face_corners(cone, f);
      Triangle t{int(c[0].idx()) + offset, int(c[1].idx()) + offset, int(c[2].idx()) + offset};
      if(copy == 1)
        std::swap(t[1], t[2]); // mirrored: keep the outward orientation
      triangles.push_back(t);
    }
  }
  d.mesh = mesh_from_soup(points, triangles);
  d.apex_a = Vertex(0);
  d.first_of_b = Vertex(std::uint32_t(cone.number_of_vertices()));
  d.apex_b = d.first_of_b;
  return d;
}

TEST(NonManifoldVertex, DoubleConeGluedAtItsApexMatchesTheDevelopedDistances)
{
  const Double_cone dc = make_double_cone(1., 2., 12, 6);
  const std::vector<std::vector<Vertex>> glued{{dc.apex_a, dc.apex_b}};
  // a source on the first cone, on the third ring
  const Vertex source(1 + 2 * 12 + 5);
  for(const auto& [name, d] : solve_all(dc.mesh, {source}, params::glued_vertices(glued))) {
    double worst = 0;
    for(Vertex v : dc.mesh.vertices())
      if(v.idx() >= dc.first_of_b.idx())
        worst = std::max(worst, std::abs(d[v.idx()] - (dc.radius[source.idx()] + dc.radius[v.idx()])));
    EXPECT_LT(worst, 1e-12) << name << ": the second cone is reached through the apex";
    EXPECT_EQ(d[dc.apex_b.idx()], d[dc.apex_a.idx()]) << name;
  }
  // the path to the far cone goes through the apex, and is as long as the distance
  const Vertex target(dc.first_of_b.idx() + 1 + 4 * 12 + 7);
  CGAL_ext::Surface_mesh_geodesic_paths<Mesh> paths(dc.mesh, params::glued_vertices(glued));
  paths.add_source(source);
  paths.build();
  std::vector<Point> points;
  paths.shortest_path_points(target, std::back_inserter(points));
  const double expected = dc.radius[source.idx()] + dc.radius[target.idx()];
  EXPECT_NEAR(CGAL_ext::polyline_length(points), expected, 1e-12);
  EXPECT_NEAR(double(paths.distance(target)), expected, 1e-12);
  bool through_apex = false;
  for(const Point& p : points)
    through_apex |= p == dc.mesh.point(dc.apex_a);
  EXPECT_TRUE(through_apex);
}

TEST(NonManifoldVertex, WithoutGluingTheConesAreApart)
{
  const Double_cone dc = make_double_cone(1., 2., 12, 6);
  const std::vector<double> d = solve(dc.mesh, Vertex(5));
  EXPECT_EQ(d[dc.first_of_b.idx() + 3], inf);
}

// A second open fan of 4 triangles hanging from border vertex 3 of a grid.
TEST(NonManifoldVertex, OpenFanHangingFromAGridBorderVertex)
{
  Mesh m = make_grid(6, 1.);
  const Vertex apex(3);
  ASSERT_TRUE(m.is_border(apex));
  std::vector<Vertex> ring;
  for(int k = 0; k < 5; ++k)
    ring.push_back(m.add_vertex(Point(3 + 0.5 * std::cos(0.5 * k), 0.5 * std::sin(0.5 * k), 1)));
  for(int k = 0; k + 1 < 5; ++k)
    ASSERT_TRUE(m.add_face(apex, ring[k], ring[k + 1]).is_valid());
  // from grid vertex 0, (0, 0, 0): the fan is reached through the apex (3, 0, 0)
  for(const auto& [name, d] : solve_all(m, {Vertex(0)}, params::default_values()))
    for(Vertex v : ring)
      EXPECT_NEAR(d[v.idx()], 3 + distance_3(m.point(apex), m.point(v)), 1e-14) << name;
}

TEST(NonManifoldVertex, GluedVertexOutOfRangeIsAnError)
{
  const Mesh m = make_grid(4, 1.);
  const std::vector<std::vector<Vertex>> glued{{Vertex(0), Vertex(99)}};
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, Vertex(0), params::glued_vertices(glued)); },
                                    {"glued vertex", "99", "out of range"}));
  // a wormhole is no surface
  const std::vector<std::vector<Vertex>> apart{{Vertex(0), Vertex(15)}};
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, Vertex(0), params::glued_vertices(apart)); },
                                    {"glued vertices 0 and 15 are", "apart", "one point"}));
}

// Distances scale with the mesh: at 1e-300, 1e300, or 1e6 away from the origin, the distances
// relative to the bounding-box diagonal are those of the mesh at its own scale.
Mesh transformed(const Mesh& m, double scale, double offset)
{
  Mesh t = m;
  for(Vertex v : t.vertices()) {
    const Point& p = t.point(v);
    t.point(v) = Point(p.x() * scale + offset, p.y() * scale + offset, p.z() * scale + offset);
  }
  return t;
}

TEST(AnyScale, DistancesScaleWithTheMesh)
{
  const Mesh& m = test_mesh("elephant");
  const double diag = bbox_diagonal(m);
  const std::vector<Vertex> sources{Vertex(0), Vertex(1000)};
  const auto reference = solve_all(m, sources, params::default_values());
  for(const auto& [scale, offset, tolerance] :
      std::vector<std::tuple<double, double, double>>{{1e-300, 0., 1e-13}, {1e300, 0., 1e-13}, {1., 1e6, 1e-9},
                                                      {1e-150, 1e-145, 1e-9}}) {
    const Mesh t = transformed(m, scale, offset);
    const auto ours = solve_all(t, sources, params::default_values());
    for(std::size_t a = 0; a < ours.size(); ++a) {
      std::vector<double> unit(ours[a].second.size());
      for(std::size_t i = 0; i < unit.size(); ++i)
        unit[i] = ours[a].second[i] / scale;
      std::ostringstream label;
      label << ours[a].first << " at scale " << scale << ", offset " << offset;
      EXPECT_TRUE(agrees(unit, reference[a].second, diag, tolerance, label.str()));
    }
  }
}

TEST(AnyScale, PathPointsAreInTheMeshsCoordinates)
{
  const Mesh t = transformed(test_mesh("elephant"), 1e300, 0.);
  CGAL_ext::Surface_mesh_geodesic_paths<Mesh> paths(t);
  paths.add_source(Vertex(0));
  paths.build();
  std::vector<Point> points;
  paths.shortest_path_points(Vertex(1000), std::back_inserter(points));
  ASSERT_GE(points.size(), 2u);
  EXPECT_EQ(points.front(), t.point(Vertex(0)));
  EXPECT_EQ(points.back(), t.point(Vertex(1000)));
  EXPECT_NEAR(CGAL_ext::polyline_length(points) / double(paths.distance(Vertex(1000))), 1., 1e-9);
}

// ---------------------------------------------------------------------------------------------
// Degenerate triangles on a flat grid: the domain stays the square, so distances are Euclidean.

std::vector<double> euclidean_from(const Mesh& m, Vertex s)
{
  std::vector<double> d;
  for(Vertex v : m.vertices())
    d.push_back(distance_3(m.point(s), m.point(v)));
  return d;
}

void expect_euclidean(const Mesh& m, const std::string& what)
{
  for(const auto& [name, d] : solve_all(m, {Vertex(0)}, params::default_values()))
    EXPECT_TRUE(agrees(d, euclidean_from(m, Vertex(0)), bbox_diagonal(m), 1e-12, what + " " + name));
}

TEST(DegenerateTriangles, CapOnAGrid)
{
  Mesh m = make_grid(6, 1.);
  const Vertex v(14); // interior: moved onto the middle of the far edge of one of its faces
  const auto c = face_corners(m, m.face(m.halfedge(v)));
  std::vector<Vertex> others;
  for(Vertex w : c)
    if(w != v)
      others.push_back(w);
  m.point(v) = CGAL::midpoint(m.point(others[0]), m.point(others[1]));
  ASSERT_TRUE(CGAL::collinear(m.point(c[0]), m.point(c[1]), m.point(c[2])));
  expect_euclidean(m, "cap");
}

TEST(DegenerateTriangles, ZeroLengthEdgeOnAGrid)
{
  Mesh m = make_grid(6, 1.);
  const Vertex v(14), w(15);
  ASSERT_TRUE(m.halfedge(v, w).is_valid());
  m.point(v) = m.point(w); // two needles
  expect_euclidean(m, "zero-length edge");
}

TEST(DegenerateTriangles, NearlyZeroLengthEdgeOnAGrid)
{
  Mesh m = make_grid(6, 1.);
  const Vertex v(14), w(15);
  m.point(v) = Point(m.point(w).x() + 1e-14, m.point(w).y(), 0);
  expect_euclidean(m, "edge of length 1e-14");
}

TEST(DegenerateTriangles, FaceShrunkToAPointOnAGrid)
{
  Mesh m = make_grid(6, 1.);
  const auto c = face_corners(m, m.face(m.halfedge(Vertex(14))));
  for(Vertex w : c)
    m.point(w) = m.point(Vertex(14));
  expect_euclidean(m, "a face shrunk to a point");
}

// Flat triangles stacked on one segment of the x-axis, between two real triangles below it and
// two above (the points and faces of CGAL's degtri_sliding.off): the caps face each other, and
// each is split at the other's middle vertex until none is left. The surface is the plane: a
// vertex is reached straight, or around the corner at vertex 3 (2, 0) where the lower triangles
// end.
TEST(DegenerateTriangles, FlatTrianglesStackedOnOneSegment)
{
  const Mesh m = mesh_from_soup({Point(4, -2, 0), Point(6, 0, 0), Point(4, 0, 0), Point(2, 0, 0), Point(1, 0, 0),
                                 Point(3, 0, 0), Point(5, 0, 0), Point(3, 2, 0)},
                                {{0, 1, 2}, {0, 2, 3}, {3, 2, 4}, {2, 1, 6}, {2, 6, 4}, {4, 6, 5}, {5, 6, 7}, {4, 5, 7}});
  const double r8 = std::sqrt(8.), r5 = std::sqrt(5.);
  const std::vector<double> exact{0, r8, 2, r8, r8 + 1, r5, r5, std::sqrt(17.)};
  for(const auto& [name, d] : solve_all(m, {Vertex(0)}, params::default_values()))
    EXPECT_TRUE(agrees(d, exact, bbox_diagonal(m), 1e-14, "stacked flat triangles " + name));
  // and from the top: vertex 7 reaches the bottom straight through the axis
  const std::vector<double> from_top = solve(m, Vertex(7));
  EXPECT_NEAR(from_top[0], std::sqrt(17.), 1e-14);
}

// In a real mesh: an edge (a, b) cut at its midpoint m. The reference splits both faces on the
// edge at m; the degenerate version keeps one of them whole and closes the gap with the
// zero-area cap (b, m, a). Same surface, same vertices: same distances, and a point of the face
// kept whole is found in the cap's neighbour.
struct Cut_edge
{
  Mesh with_cap, reference;
  Face kept_face; // (b, a, x) in the mesh with the cap
  Vertex a, b, x, middle;
};

Cut_edge cut_an_edge(const Mesh& m, Mesh::Halfedge_index h)
{
  std::vector<Point> points;
  for(Vertex v : m.vertices())
    points.push_back(m.point(v));
  Cut_edge cut;
  cut.a = m.source(h);
  cut.b = m.target(h);
  const Vertex y = m.target(m.next(h)), x = m.target(m.next(m.opposite(h)));
  cut.x = x;
  cut.middle = Vertex(std::uint32_t(points.size()));
  points.push_back(CGAL::midpoint(m.point(cut.a), m.point(cut.b)));
  const int a = int(cut.a.idx()), b = int(cut.b.idx()), mid = int(cut.middle.idx());
  std::vector<Triangle> common, with_cap, reference;
  for(Face f : m.faces())
    if(f != m.face(h) && f != m.face(m.opposite(h))) {
      const auto c = face_corners(m, f);
      common.push_back({int(c[0].idx()), int(c[1].idx()), int(c[2].idx())});
    }
  // the face of h, (a, b, y), is split at m in both
  common.push_back({a, mid, int(y.idx())});
  common.push_back({mid, b, int(y.idx())});
  reference = with_cap = common;
  reference.push_back({b, mid, int(x.idx())});
  reference.push_back({mid, a, int(x.idx())});
  with_cap.push_back({b, a, int(x.idx())});
  with_cap.push_back({b, mid, a});
  cut.reference = mesh_from_soup(points, reference);
  cut.with_cap = mesh_from_soup(points, with_cap);
  cut.kept_face = Face(std::uint32_t(with_cap.size() - 2));
  return cut;
}

TEST(DegenerateTriangles, CapInARealMeshMatchesTheSplitMesh)
{
  const Mesh& elephant = test_mesh("elephant");
  const Cut_edge cut = cut_an_edge(elephant, elephant.halfedge(Face(100)));
  const double diag = bbox_diagonal(elephant);
  const std::vector<double> reference = solve(cut.reference, Vertex(0));
  for(const auto& [name, d] : solve_all(cut.with_cap, {Vertex(0)}, params::default_values()))
    EXPECT_TRUE(agrees(d, reference, diag, 1e-12, "cap in the elephant, " + name));

  // a source in the face kept whole, (b, a, x) = 0.2 b + 0.3 a + 0.5 x, is the point
  // (0.4, 0.1, 0.5) of (m, a, x) in the reference
  const auto corners = face_corners(cut.with_cap, cut.kept_face);
  Barycentric in_kept{{0., 0., 0.}};
  for(int k = 0; k < 3; ++k)
    in_kept[k] = corners[k] == cut.b ? 0.2 : (corners[k] == cut.a ? 0.3 : 0.5);
  Face in_reference;
  for(Face f : cut.reference.faces()) {
    const auto c = face_corners(cut.reference, f);
    if(std::count(c.begin(), c.end(), cut.middle) && std::count(c.begin(), c.end(), cut.a) &&
       std::count(c.begin(), c.end(), cut.x))
      in_reference = f;
  }
  ASSERT_TRUE(in_reference.is_valid());
  const auto rc = face_corners(cut.reference, in_reference);
  Barycentric in_ref{{0., 0., 0.}};
  for(int k = 0; k < 3; ++k)
    in_ref[k] = rc[k] == cut.middle ? 0.4 : (rc[k] == cut.a ? 0.1 : 0.5);
  const std::vector<double> from_point_reference = solve(cut.reference, std::vector<Face_location>{{in_reference, in_ref}});
  const std::vector<double> from_point =
    solve(cut.with_cap, std::vector<Face_location>{{cut.kept_face, in_kept}});
  EXPECT_TRUE(agrees(from_point, from_point_reference, diag, 1e-12, "from a point of the face kept whole"));

  // the path to that point: as long as its distance, and its last point is the point
  CGAL_ext::Surface_mesh_geodesic_paths<Mesh> paths(cut.with_cap);
  paths.add_source(Vertex(0));
  paths.build();
  std::vector<Point> points;
  const Face_location target{cut.kept_face, in_kept};
  paths.shortest_path_points(target, std::back_inserter(points));
  ASSERT_GE(points.size(), 2u);
  EXPECT_LT(distance_3(points.back(), location_point(cut.with_cap, target)), 1e-12 * diag);
  EXPECT_NEAR(CGAL_ext::polyline_length(points), double(paths.distance(target)), 1e-12 * diag);
}

// In a real mesh: vertex b moved onto its neighbour a makes two needles; the reference is the
// mesh with the edge collapsed (b's faces given to a, the two needles gone, b left isolated).
TEST(DegenerateTriangles, ZeroLengthEdgeInARealMeshMatchesTheCollapsedMesh)
{
  const Mesh& elephant = test_mesh("elephant");
  const Mesh::Halfedge_index h = elephant.halfedge(Face(200));
  const Vertex a = elephant.source(h), b = elephant.target(h);
  std::vector<Point> points;
  for(Vertex v : elephant.vertices())
    points.push_back(v == b ? elephant.point(a) : elephant.point(v));
  std::vector<Triangle> needles, collapsed;
  for(Face f : elephant.faces()) {
    const auto c = face_corners(elephant, f);
    Triangle t{int(c[0].idx()), int(c[1].idx()), int(c[2].idx())};
    needles.push_back(t);
    if(std::count(c.begin(), c.end(), a) && std::count(c.begin(), c.end(), b))
      continue;
    for(int& i : t)
      if(i == int(b.idx()))
        i = int(a.idx());
    collapsed.push_back(t);
  }
  const Mesh with_needles = mesh_from_soup(points, needles), reference = mesh_from_soup(points, collapsed);
  std::vector<double> expected = solve(reference, Vertex(0));
  ASSERT_EQ(expected[b.idx()], inf); // isolated in the reference
  expected[b.idx()] = expected[a.idx()];
  for(const auto& [name, d] : solve_all(with_needles, {Vertex(0)}, params::default_values()))
    EXPECT_TRUE(agrees(d, expected, bbox_diagonal(elephant), 1e-12, "needles in the elephant, " + name));
}

// ---------------------------------------------------------------------------------------------
// Isolated vertices: +infinity, and no source on their own.

// The solver mesh stores a frame for the first half-edge of each face only and derives the other two
// (Solver_mesh::frame): on thin, obtuse and needle-like triangles in any orientation, away from
// the origin, each frame is the triangle seen from its half-edge up to what rounding the
// coordinates allows: their last bit (eps R) turns the half-edge's direction by eps R / length,
// which moves a point at the longest side's distance by eps R longest / length. The reference
// is computed from the same coordinates in long double.
TEST(MeshCache, DerivedFramesAreTheTriangleSeenFromEachSide)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1., 1.);
  const std::vector<std::array<Point, 3>> shapes{
    {{Point(0, 0, 0), Point(1, 0, 0), Point(0.3, 0.8, 0)}},      // acute
    {{Point(0, 0, 0), Point(1, 0, 0), Point(1.7, 0.2, 0)}},      // obtuse at B
    {{Point(0, 0, 0), Point(1, 0, 0), Point(-0.6, 0.1, 0)}},     // obtuse at A
    {{Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 1e-7, 0)}},     // a cap, nearly flat
    {{Point(0, 0, 0), Point(1, 0, 0), Point(1 + 1e-6, 2e-6, 0)}}, // a needle
    {{Point(0, 0, 0), Point(1e-5, 0, 0), Point(0.4, 3e-6, 0)}}};  // a short side and two long
  Mesh m;
  std::vector<std::array<Point, 3>> placed;
  for(int copy = 0; copy < 20; ++copy)
    for(const auto& t : shapes) {
      // a rotation (Gram-Schmidt of random vectors), a scale, and a shift of up to 100 sizes
      // (draws in braces: evaluated in order, the same triangles for every compiler)
      const Vector a{u(rng), u(rng), u(rng)}, b0{u(rng), u(rng), u(rng)};
      const Vector e0 = a / std::sqrt(a.squared_length());
      const Vector b = b0 - (b0 * e0) * e0;
      const Vector e1 = b / std::sqrt(b.squared_length());
      const Vector e2 = CGAL::cross_product(e0, e1);
      const double scale = std::pow(10., 3 * u(rng));
      const Vector shift = 100 * scale * Vector{u(rng), u(rng), u(rng)};
      std::array<Point, 3> p;
      for(int k = 0; k < 3; ++k)
        p[k] = CGAL::ORIGIN + shift + scale * (t[k].x() * e0 + t[k].y() * e1 + t[k].z() * e2);
      placed.push_back(p);
      const Vertex v0 = m.add_vertex(p[0]), v1 = m.add_vertex(p[1]), v2 = m.add_vertex(p[2]);
      m.add_face(v0, v1, v2);
    }
  CGAL_ext::Geodesics_3::internal::Solver_mesh cache;
  CGAL_ext::Geodesics_3::internal::build_solver_mesh(m, get(CGAL::vertex_point, m), get(CGAL::vertex_index, m),
                                                    get(CGAL::face_index, m), cache);
  ASSERT_EQ(cache.number_of_faces, placed.size());
  typedef std::array<long double, 3> Exact_vector;
  auto minus = [](const Point& p, const Point& q) {
    return Exact_vector{{(long double)p.x() - q.x(), (long double)p.y() - q.y(), (long double)p.z() - q.z()}};
  };
  auto dot = [](const Exact_vector& x, const Exact_vector& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  for(std::size_t f = 0; f < placed.size(); ++f) {
    double coordinate = 0, longest = 0;
    for(int k = 0; k < 3; ++k) {
      coordinate = std::max({coordinate, std::abs(placed[f][k].x()), std::abs(placed[f][k].y()), std::abs(placed[f][k].z())});
      longest = std::max(longest, std::sqrt(CGAL::squared_distance(placed[f][k], placed[f][(k + 1) % 3])));
    }
    for(int k = 0; k < 3; ++k) {
      const int h = 3 * cache.cache_face(int(f)) + k;
      // the mesh's vertices are numbered in the order added, three a face
      const Point& a = placed[f][std::size_t(cache.mesh_vertex(cache.source(h))) % 3];
      const Point& b = placed[f][std::size_t(cache.mesh_vertex(cache.target(h))) % 3];
      const Point& c = placed[f][std::size_t(cache.mesh_vertex(cache.apex(h))) % 3];
      const Exact_vector ab = minus(b, a), ac = minus(c, a);
      const Exact_vector cross{{ab[1] * ac[2] - ab[2] * ac[1], ab[2] * ac[0] - ab[0] * ac[2], ab[0] * ac[1] - ab[1] * ac[0]}};
      const long double length = std::sqrt(dot(ab, ab));
      const auto frame = cache.frame(h);
      const double tolerance = 16 * std::numeric_limits<double>::epsilon() * coordinate * longest / double(length);
      SCOPED_TRACE("face " + std::to_string(f) + ", half-edge " + std::to_string(k));
      EXPECT_NEAR(frame.length, double(length), 4 * std::numeric_limits<double>::epsilon() * coordinate);
      EXPECT_NEAR(frame.apex_x, double(dot(ab, ac) / length), tolerance);
      EXPECT_NEAR(frame.apex_y, double(std::sqrt(dot(cross, cross)) / length), tolerance);
      EXPECT_GT(frame.apex_y, 0.);
    }
  }
}

// The solver mesh stores the faces along a Z-order curve of their centroids and converts face
// indices both ways. The elephant's faces, shuffled: the solver mesh puts neighbouring faces together
// again, its two maps are inverse and keep each face's corners, and a face-point source on the
// shuffled mesh gives the distances it gives on the mesh as read.
TEST(MeshCache, FacesAreStoredAlongACurveAndConvertedBack)
{
  const Mesh& original = test_mesh("elephant");
  std::vector<Point> points;
  for(Vertex v : vertices(original))
    points.push_back(original.point(v));
  std::vector<Triangle> triangles;
  for(Face f : faces(original))
    triangles.push_back(corners_of(original, f));
  std::shuffle(triangles.begin(), triangles.end(), std::mt19937(3));
  const Mesh shuffled = mesh_from_soup(points, triangles);

  CGAL_ext::Geodesics_3::internal::Solver_mesh cache;
  CGAL_ext::Geodesics_3::internal::build_solver_mesh(shuffled, get(CGAL::vertex_point, shuffled),
                                                    get(CGAL::vertex_index, shuffled), get(CGAL::face_index, shuffled),
                                                    cache);
  ASSERT_EQ(cache.number_of_faces, num_faces(shuffled));
  auto centroid = [&](Face f) {
    const auto h = halfedge(f, shuffled);
    return CGAL::centroid(shuffled.point(source(h, shuffled)), shuffled.point(target(h, shuffled)),
                          shuffled.point(target(next(h, shuffled), shuffled)));
  };
  std::vector<Face> face_of_index(num_faces(shuffled));
  for(Face f : faces(shuffled))
    face_of_index[f.idx()] = f;
  double step_in_cache = 0, step_as_given = 0;
  for(std::size_t i = 0; i < face_of_index.size(); ++i) {
    const int c = cache.cache_face(int(i));
    ASSERT_GE(c, 0);
    ASSERT_LT(std::size_t(c), cache.number_of_faces);
    EXPECT_EQ(cache.mesh_face(c), int(i));
    int k = 0; // corner k is source(halfedge(f)) advanced k times
    for(auto h : CGAL::halfedges_around_face(halfedge(face_of_index[i], shuffled), shuffled))
      EXPECT_EQ(cache.mesh_vertex(cache.source(3 * c + k++)), int(source(h, shuffled).idx())) << "face " << i;
    if(i > 0) {
      step_as_given += std::sqrt(CGAL::squared_distance(centroid(face_of_index[i - 1]), centroid(face_of_index[i])));
      step_in_cache += std::sqrt(CGAL::squared_distance(centroid(face_of_index[std::size_t(cache.mesh_face(int(i) - 1))]),
                                                        centroid(face_of_index[std::size_t(cache.mesh_face(int(i)))])));
    }
  }
  EXPECT_LT(step_in_cache, 0.1 * step_as_given);

  // the shuffled mesh's face with the corners of the original's face 100, and the point at its
  // centroid (the same point whichever corner a face starts at)
  auto corner_set = [](const Mesh& m, Face f) {
    Triangle t = corners_of(m, f);
    std::sort(t.begin(), t.end());
    return t;
  };
  const Triangle wanted = corner_set(original, Face(100));
  Face in_shuffled;
  for(Face f : faces(shuffled))
    if(corner_set(shuffled, f) == wanted)
      in_shuffled = f;
  ASSERT_NE(in_shuffled, Face());
  const Barycentric third{{1. / 3, 1. / 3, 1. / 3}};
  EXPECT_TRUE(agrees(solve(shuffled, std::vector<Face_location>{{in_shuffled, third}}),
                     solve(original, std::vector<Face_location>{{Face(100), third}}), bbox_diagonal(original), 1e-14,
                     "a face-point source on the shuffled faces against the faces as read"));
}

// The solver mesh numbers the caller's vertices in the order its faces name them: on a mesh whose
// vertices are shuffled, vertices near in the solver mesh are near on the surface, the two maps are
// inverse, each solver-mesh vertex sits at its caller's vertex, and the distances (given back by the
// caller's vertices) are those of the mesh as read, from a vertex source and with stop vertices.
TEST(MeshCache, VerticesAreNumberedAlongTheFacesAndConvertedBack)
{
  const Mesh& original = test_mesh("elephant");
  const std::size_t n = num_vertices(original);
  std::vector<int> shuffled_index(n);
  std::iota(shuffled_index.begin(), shuffled_index.end(), 0);
  std::shuffle(shuffled_index.begin(), shuffled_index.end(), std::mt19937(5));
  std::vector<Point> points(n);
  for(Vertex v : vertices(original))
    points[std::size_t(shuffled_index[v.idx()])] = original.point(v);
  std::vector<Triangle> triangles;
  for(Face f : faces(original)) {
    Triangle t = corners_of(original, f);
    for(int& c : t)
      c = shuffled_index[std::size_t(c)];
    triangles.push_back(t);
  }
  const Mesh shuffled = mesh_from_soup(points, triangles);
  ASSERT_EQ(num_vertices(shuffled), n);

  CGAL_ext::Geodesics_3::internal::Solver_mesh cache;
  CGAL_ext::Geodesics_3::internal::build_solver_mesh(shuffled, get(CGAL::vertex_point, shuffled),
                                                    get(CGAL::vertex_index, shuffled), get(CGAL::face_index, shuffled),
                                                    cache);
  double step_in_cache = 0, step_as_given = 0;
  for(std::size_t i = 0; i < n; ++i) {
    const int c = cache.cache_vertex(int(i));
    ASSERT_GE(c, 0);
    ASSERT_LT(std::size_t(c), n);
    EXPECT_EQ(cache.mesh_vertex(c), int(i));
    const Point& p = shuffled.point(Vertex(std::uint32_t(i)));
    EXPECT_EQ(cache.position[std::size_t(c)][0], p.x()) << "vertex " << i;
    EXPECT_EQ(cache.position[std::size_t(c)][2], p.z()) << "vertex " << i;
    if(i > 0) {
      step_as_given += std::sqrt(CGAL::squared_distance(shuffled.point(Vertex(std::uint32_t(i - 1))), p));
      step_in_cache += std::sqrt(CGAL::squared_distance(
        shuffled.point(Vertex(std::uint32_t(cache.mesh_vertex(int(i) - 1)))),
        shuffled.point(Vertex(std::uint32_t(cache.mesh_vertex(int(i)))))));
    }
  }
  EXPECT_LT(step_in_cache, 0.2 * step_as_given);

  const Vertex source_as_read(100), source_shuffled{std::uint32_t(shuffled_index[100])};
  const std::vector<double> as_read = solve(original, source_as_read);
  const std::vector<double> on_shuffled = solve(shuffled, source_shuffled);
  const std::vector<Vertex> stops{Vertex(std::uint32_t(shuffled_index[7])), Vertex(std::uint32_t(shuffled_index[9]))};
  const std::vector<double> stopped = solve(shuffled, source_shuffled, params::stop_vertices(stops));
  const double diagonal = bbox_diagonal(original);
  for(std::size_t v = 0; v < n; ++v) {
    const std::size_t s = std::size_t(shuffled_index[v]);
    EXPECT_NEAR(on_shuffled[s], as_read[v], 1e-14 * diagonal) << "vertex " << v;
    if(stopped[s] < inf)
      EXPECT_NEAR(stopped[s], as_read[v], 1e-14 * diagonal) << "vertex " << v;
  }
  for(const Vertex& v : stops)
    EXPECT_LT(stopped[v.idx()], inf) << "stop vertex " << v.idx();
}

TEST(IsolatedVertex, IsUnreachedAndCannotBeTheOnlySource)
{
  Mesh m = make_grid(4, 1.);
  const Vertex lonely = m.add_vertex(Point(10, 10, 0));
  for(const auto& [name, d] : solve_all(m, {Vertex(0)}, params::default_values()))
    EXPECT_EQ(d[lonely.idx()], inf) << name;
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, lonely); }, {"source vertex 16", "isolated"}));
  EXPECT_TRUE(throws_geodesic_error([&] { solve(m, lonely, params::algorithm(CGAL_ext::MMP)); }, {"isolated"}));
  // with another source, it is just one more source
  const std::vector<double> d = solve(m, std::vector<Vertex>{lonely, Vertex(0)});
  EXPECT_EQ(d[lonely.idx()], 0.);
  EXPECT_EQ(d[5], std::sqrt(2.));
}

} // namespace
