// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Meshes as users have them, solved exactly: non-manifold (pinched) vertices, vertices the
// caller glues into one point, and coordinates of any scale.

#include "support/analytic_surfaces.h"
#include "support/checks.h"
#include "support/solve.h"

#include <CGAL_ext/Surface_mesh_geodesic_paths.h>
#include <CGAL_ext/Geodesics_3/polyline_length.h>

#include <cmath>
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

} // namespace
