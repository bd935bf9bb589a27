// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of CGAL_ext::polygon_soup_to_geodesic_mesh(): each repair on small soups (the counts, the
// vertex of every input point, the face of every input triangle, the errors), and the distances
// on a real mesh written as binary STL, ASCII STL and a soup, which must be those of the mesh.

#include "support/meshes.h"

#include <CGAL_ext/geodesic_distances.h>
#include <CGAL_ext/polygon_soup_to_geodesic_mesh.h>

#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/boost/graph/helpers.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <filesystem>
#include <limits>
#include <map>
#include <string>
#include <iterator>
#include <vector>

namespace {

using namespace test_support;
namespace fs = std::filesystem;
namespace PMP = CGAL::Polygon_mesh_processing;
typedef std::vector<std::vector<std::size_t>> Polygons;

/// A soup made into a mesh, with what the function tells about it.
struct Prepared
{
  Mesh mesh;
  std::vector<Vertex> vertex_of_point;
  std::vector<Face> face_of_polygon;
  std::vector<std::vector<Vertex>> glued; // the vertices of each duplicated point
  CGAL_ext::Geodesic_mesh_repairs repairs;
};

/// The soup prepared; `merge` forces merging points at one place (by default only a soup whose
/// polygons share no point is merged).
Prepared prepare(const std::vector<Point>& points, const Polygons& polygons, bool merge = false)
{
  Prepared p;
  const auto np = CGAL_ext::parameters::glued_vertices_output(std::back_inserter(p.glued));
  if(merge)
    p.repairs = CGAL_ext::polygon_soup_to_geodesic_mesh(points, polygons, p.mesh, p.vertex_of_point,
                                                        p.face_of_polygon, np.merge_duplicate_points(true));
  else
    p.repairs = CGAL_ext::polygon_soup_to_geodesic_mesh(points, polygons, p.mesh, p.vertex_of_point,
                                                        p.face_of_polygon, np);
  return p;
}

/// What every prepared soup is: a valid triangle mesh in which each input point has a vertex at
/// its position, and each face listed for an input triangle has that triangle's points as corners.
void expect_prepared(const Prepared& p, const std::vector<Point>& points, const Polygons& polygons)
{
  EXPECT_TRUE(p.mesh.is_valid(false));
  if(p.repairs.isolated_points == 0) // CGAL's check does not take isolated vertices
    EXPECT_TRUE(CGAL::is_valid_polygon_mesh(p.mesh));
  EXPECT_TRUE(CGAL::is_triangle_mesh(p.mesh));
  // a triangulation removes a face and adds others in its place: no index is left unused
  EXPECT_EQ(p.mesh.number_of_removed_faces() + p.mesh.number_of_removed_edges() +
              p.mesh.number_of_removed_vertices(),
            0u);
  ASSERT_EQ(p.vertex_of_point.size(), points.size());
  for(std::size_t i = 0; i < points.size(); ++i) {
    ASSERT_TRUE(p.mesh.is_valid(p.vertex_of_point[i])) << "point " << i;
    EXPECT_EQ(p.mesh.point(p.vertex_of_point[i]), points[i]) << "point " << i;
  }
  ASSERT_EQ(p.face_of_polygon.size(), polygons.size());
  for(std::size_t j = 0; j < polygons.size(); ++j) {
    if(p.face_of_polygon[j] == Mesh::null_face())
      continue;
    std::vector<Point> corners, expected;
    for(Vertex v : face_corners(p.mesh, p.face_of_polygon[j]))
      corners.push_back(p.mesh.point(v));
    for(std::size_t id : polygons[j])
      expected.push_back(points[id]);
    std::sort(corners.begin(), corners.end());
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(corners, expected) << "polygon " << j;
  }
}

/// The message of the Geodesic_error that making a mesh of the soup throws; "" if none.
template <class Points, class PolygonRange>
std::string error_of(const Points& points, const PolygonRange& polygons)
{
  Mesh mesh;
  std::vector<Vertex> vertex_of_point;
  try {
    CGAL_ext::polygon_soup_to_geodesic_mesh(points, polygons, mesh, vertex_of_point);
  } catch(const CGAL_ext::Geodesic_error& e) {
    return e.what();
  }
  return "";
}

/// The distances from the vertex of input point `source` to the vertex of every input point.
std::vector<double> point_distances(const Prepared& p, std::size_t source)
{
  auto distance = get(CGAL::dynamic_vertex_property_t<double>(), p.mesh);
  CGAL_ext::geodesic_distances(p.mesh, distance, p.vertex_of_point[source],
                               CGAL_ext::parameters::glued_vertices(p.glued));
  std::vector<double> result;
  for(Vertex v : p.vertex_of_point)
    result.push_back(get(distance, v));
  return result;
}

const std::vector<Point> unit_square = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0)};

// ---------------------------------------------------------------------------------------------
// Each repair

TEST(Polygon_soup_to_geodesic_mesh, a_clean_mesh_is_taken_as_it_is)
{
  const Polygons polygons = {{0, 1, 2}, {0, 2, 3}};
  const Prepared p = prepare(unit_square, polygons);
  expect_prepared(p, unit_square, polygons);
  EXPECT_FALSE(p.repairs.changed());
  EXPECT_EQ(p.repairs.summary(), "");
  EXPECT_EQ(p.mesh.number_of_vertices(), 4u);
  EXPECT_EQ(p.mesh.number_of_faces(), 2u);
  EXPECT_NE(p.face_of_polygon[0], p.face_of_polygon[1]);
}

TEST(Polygon_soup_to_geodesic_mesh, duplicate_points_are_merged_into_one_vertex)
{
  // each triangle its own points, as in an STL file
  const std::vector<Point> points = {unit_square[0], unit_square[1], unit_square[2],
                                     unit_square[0], unit_square[2], unit_square[3]};
  const Polygons polygons = {{0, 1, 2}, {3, 4, 5}};
  const Prepared p = prepare(points, polygons);
  expect_prepared(p, points, polygons);
  EXPECT_EQ(p.repairs.merged_points, 2u);
  EXPECT_EQ(p.repairs.summary(), "merged 2 duplicate points");
  EXPECT_TRUE(p.repairs.changed());
  EXPECT_EQ(p.mesh.number_of_vertices(), 4u);
  EXPECT_EQ(p.vertex_of_point[3], p.vertex_of_point[0]);
  EXPECT_EQ(p.vertex_of_point[4], p.vertex_of_point[2]);
  EXPECT_NE(p.face_of_polygon[0], Mesh::null_face());
  EXPECT_NE(p.face_of_polygon[1], Mesh::null_face());
  // one surface: the diagonal is crossed straight
  const std::vector<double> d = point_distances(p, 1);
  EXPECT_NEAR(d[5], std::sqrt(2.), 1e-15);
  EXPECT_EQ(d[3], d[0]);
}

// A mesh whose polygons share points keeps its points at one place apart (the two sides of a
// cut), unless asked to merge them.
TEST(Polygon_soup_to_geodesic_mesh, a_mesh_keeps_coincident_points_unless_asked)
{
  // two triangles sharing points 0 and 2; point 3 lies on point 0 but belongs to another triangle
  const std::vector<Point> points = {unit_square[0], unit_square[1], unit_square[2], unit_square[0], unit_square[3]};
  const Polygons polygons = {{0, 1, 2}, {0, 2, 4}, {3, 4, 2}};
  const Prepared kept = prepare(points, polygons);
  EXPECT_EQ(kept.repairs.merged_points, 0u);
  EXPECT_NE(kept.vertex_of_point[3], kept.vertex_of_point[0]);
  const Prepared merged = prepare(points, polygons, true);
  EXPECT_EQ(merged.repairs.merged_points, 1u);
  EXPECT_EQ(merged.vertex_of_point[3], merged.vertex_of_point[0]);
}

TEST(Polygon_soup_to_geodesic_mesh, polygons_are_triangulated_without_new_vertices)
{
  // a quad and a non-convex hexagon (an L) sharing the edge (1, 2)
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                                     Point(3, 0, 0), Point(3, 1, 0), Point(2, 1, 0), Point(2, 3, 0),
                                     Point(1, 3, 0)};
  const Polygons polygons = {{0, 1, 2, 3}, {1, 4, 5, 6, 7, 8, 2}};
  const Prepared p = prepare(points, polygons);
  expect_prepared(p, points, polygons);
  EXPECT_EQ(p.repairs.triangulated_polygons, 2u);
  EXPECT_EQ(p.repairs.summary(), "triangulated 2 polygons");
  EXPECT_EQ(p.mesh.number_of_vertices(), points.size());
  EXPECT_EQ(p.mesh.number_of_faces(), 2u + 5u);
  EXPECT_NEAR(PMP::area(p.mesh), 1. + 2. + 2., 1e-14);
  EXPECT_EQ(p.face_of_polygon[0], Mesh::null_face());
  EXPECT_EQ(p.face_of_polygon[1], Mesh::null_face());
  // around the L's inner corner, not across the gap
  const std::vector<double> d = point_distances(p, 5);
  EXPECT_NEAR(d[8], 1. + std::sqrt(5.), 1e-14);
}

TEST(Polygon_soup_to_geodesic_mesh, what_has_fewer_than_3_distinct_points_is_removed)
{
  // point 4 is point 0 again
  const std::vector<Point> points = {unit_square[0], unit_square[1], unit_square[2], unit_square[3], unit_square[0]};
  const Polygons polygons = {{0, 1, 2}, {4, 0, 1}, {3, 3}, {}, {0, 2, 2, 3}, {2, 3, 2}};
  const Prepared p = prepare(points, polygons, true);
  expect_prepared(p, points, polygons);
  EXPECT_EQ(p.repairs.removed_polygons, 4u);
  EXPECT_EQ(p.repairs.merged_points, 1u);
  EXPECT_EQ(p.repairs.summary(), "merged 1 duplicate point, removed 4 polygons with fewer than 3 distinct points");
  EXPECT_EQ(p.mesh.number_of_faces(), 2u) << "the square";
  EXPECT_NE(p.face_of_polygon[0], Mesh::null_face());
  for(std::size_t j = 1; j < polygons.size(); ++j)
    EXPECT_EQ(p.face_of_polygon[j], Mesh::null_face()) << "polygon " << j;
}

TEST(Polygon_soup_to_geodesic_mesh, a_polygon_through_a_point_twice_is_split)
{
  // two triangles meeting at point 0, as one polygon: 0 1 2 0 3 4
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(-1, 0, 0), Point(0, -1, 0)};
  const Polygons polygons = {{0, 1, 2, 0, 3, 4}};
  const Prepared p = prepare(points, polygons);
  expect_prepared(p, points, polygons);
  EXPECT_EQ(p.repairs.split_polygons, 1u);
  EXPECT_EQ(p.repairs.triangulated_polygons, 0u);
  EXPECT_EQ(p.repairs.duplicated_points, 1u) << "point 0 is a non-manifold vertex";
  EXPECT_EQ(p.mesh.number_of_faces(), 2u);
  EXPECT_NEAR(point_distances(p, 1)[3], 2., 1e-15) << "through point 0";
}

// Two closed tetrahedra sharing one vertex: CGAL duplicates it to make a manifold mesh, and the
// solvers glue the copies, so geodesics pass from one tetrahedron to the other through it.
TEST(Polygon_soup_to_geodesic_mesh, two_tetrahedra_sharing_a_vertex)
{
  const std::vector<Point> points = {Point(0, 0, 0),  Point(1, 0, 0),  Point(0, 1, 0),  Point(0, 0, 1),
                                     Point(-1, 0, 0), Point(0, -1, 0), Point(0, 0, -1)};
  const Polygons polygons = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2},
                             {0, 5, 4}, {0, 4, 6}, {4, 5, 6}, {0, 6, 5}};
  const Prepared p = prepare(points, polygons);
  expect_prepared(p, points, polygons);
  EXPECT_EQ(p.repairs.duplicated_points, 1u);
  EXPECT_EQ(p.repairs.summary(),
            "duplicated 1 point at non-manifold vertices or edges (glued again: geodesics pass through them)");
  EXPECT_EQ(p.mesh.number_of_vertices(), 8u);
  EXPECT_TRUE(CGAL::is_closed(p.mesh));
  ASSERT_EQ(p.glued.size(), 1u);
  ASSERT_EQ(p.glued[0].size(), 2u);
  EXPECT_EQ(p.glued[0][0], p.vertex_of_point[0]);
  EXPECT_EQ(p.mesh.point(p.glued[0][1]), points[0]);
  const std::vector<double> d = point_distances(p, 1);
  EXPECT_NEAR(d[0], 1., 1e-15);
  for(std::size_t v : {4, 5, 6})
    EXPECT_NEAR(d[v], 2., 1e-15) << "point " << v;
  // without the groups, the tetrahedra are apart
  auto apart = get(CGAL::dynamic_vertex_property_t<double>(), p.mesh);
  CGAL_ext::geodesic_distances(p.mesh, apart, p.vertex_of_point[1]);
  EXPECT_EQ(get(apart, p.vertex_of_point[5]), inf);
}

// Three triangles on the edge (0, 1): CGAL cuts them apart along it; the copies of its end
// points are glued, so every point is reached (through the end points).
TEST(Polygon_soup_to_geodesic_mesh, three_triangles_on_one_edge)
{
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(0.5, 1, 0), Point(0.5, -1, 0),
                                     Point(0.5, 0, 1)};
  const Polygons polygons = {{0, 1, 2}, {1, 0, 3}, {1, 0, 4}};
  const Prepared p = prepare(points, polygons);
  expect_prepared(p, points, polygons);
  EXPECT_GT(p.repairs.duplicated_points, 0u);
  EXPECT_EQ(p.repairs.non_manifold_edges, 1u);
  EXPECT_NE(p.repairs.summary().find("1 edge is shared by 3 or more polygons (paths cross such an edge only at its end "
                                     "points)"),
            std::string::npos)
    << p.repairs.summary();
  EXPECT_EQ(p.mesh.number_of_faces(), 3u);
  for(std::size_t j = 0; j < polygons.size(); ++j)
    EXPECT_NE(p.face_of_polygon[j], Mesh::null_face()) << "polygon " << j;
  const std::vector<double> d = point_distances(p, 2);
  for(std::size_t v : {3, 4}) {
    EXPECT_LT(d[v], inf) << "point " << v;
    EXPECT_GE(d[v], distance_3(points[2], points[v]) - 1e-15) << "point " << v;
  }
}

// The bound across a non-manifold edge: three unit squares (pages) hinged on one edge (the
// spine). CGAL cuts the pages apart along the spine where it cannot keep them together; the
// solvers glue the spine's end points only, so a page reached across the cut is reached through
// an end of the spine: the distance is the shorter way through an end, never below the true
// geodesic (the pages unfolded into one plane) and above it by at most the spine's length.
TEST(Polygon_soup_to_geodesic_mesh, across_a_non_manifold_edge_through_its_ends)
{
  const double pi = 3.14159265358979323846;
  std::vector<Point> points = {Point(0, 0, 0), Point(0, 0, 1)}; // the spine
  Polygons polygons;
  for(int page = 0; page < 3; ++page) {
    const double a = 2 * pi * page / 3;
    const std::size_t bottom = points.size(), top = bottom + 1;
    points.emplace_back(std::cos(a), std::sin(a), 0.);
    points.emplace_back(std::cos(a), std::sin(a), 1.);
    polygons.push_back({0, bottom, top});
    polygons.push_back({0, top, 1});
  }
  const Prepared p = prepare(points, polygons);
  expect_prepared(p, points, polygons);
  EXPECT_GT(p.glued.size(), 0u);
  const std::vector<double> d = point_distances(p, 2); // the bottom outer corner of page 0
  int through_the_ends = 0;
  for(std::size_t target : {5, 7}) { // the top outer corners of pages 1 and 2
    const double unfolded = std::sqrt(2. * 2. + 1.);           // straight across the spine
    const double via_ends = 1. + std::sqrt(2.);                 // through a spine end
    EXPECT_GE(d[target], unfolded - 1e-14) << "point " << target;
    EXPECT_LE(d[target], via_ends + 1e-14) << "point " << target;
    EXPECT_LE(d[target] - unfolded, 1. + 1e-14) << "at most the spine's length more";
    through_the_ends += std::abs(d[target] - via_ends) < 1e-14;
  }
  EXPECT_GE(through_the_ends, 1) << "a page cut off along the spine is reached through its ends";
}

TEST(Polygon_soup_to_geodesic_mesh, polygons_are_reversed_to_orient_the_surface)
{
  const Polygons polygons = {{0, 1, 2}, {0, 3, 2}};
  const Prepared p = prepare(unit_square, polygons);
  expect_prepared(p, unit_square, polygons);
  EXPECT_EQ(p.repairs.reversed_polygons, 1u);
  EXPECT_EQ(p.repairs.summary(), "reversed 1 polygon to orient the surface");
  EXPECT_TRUE(CGAL::is_valid_polygon_mesh(p.mesh));
  EXPECT_NEAR(point_distances(p, 1)[3], std::sqrt(2.), 1e-15);
}

// A soup that is already an oriented manifold skips CGAL's orientation (whose edge sets take
// several times the soup's memory): the check must say no wherever the orientation would change
// something, as CGAL's own test of a soup that makes a polygon mesh does.
TEST(Polygon_soup_to_geodesic_mesh, the_check_that_skips_the_orientation_agrees_with_CGAL)
{
  const std::vector<Point> seven(7, Point(0, 0, 0));
  const Polygons tetrahedron = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  Polygons one_face_reversed = tetrahedron;
  std::reverse(one_face_reversed[2].begin(), one_face_reversed[2].end());
  Polygons pinched = tetrahedron; // two closed fans at point 0
  for(const Polygons::value_type& f : Polygons{{0, 5, 4}, {0, 4, 6}, {4, 5, 6}, {0, 6, 5}})
    pinched.push_back(f);
  const std::vector<std::pair<const char*, Polygons>> cases = {
    {"tetrahedron", tetrahedron},
    {"one face reversed", one_face_reversed},
    {"two tetrahedra at a point", pinched},
    {"open fan", {{0, 1, 2}, {0, 2, 3}, {0, 3, 4}}},
    {"closed fan of a quad and triangles", {{0, 1, 2, 3}, {0, 3, 4}, {0, 4, 1}}},
    {"two open fans at a point", {{0, 1, 2}, {0, 3, 4}}},
    {"three triangles on an edge", {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}},
    {"an edge twice in one direction", {{0, 1, 2}, {0, 1, 3}}},
    {"a closed fan and an open one at a point", {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {0, 4, 5}}},
  };
  for(const auto& [name, polygons] : cases) {
    CGAL_ext::Geodesics_3::internal::Soup_in_repair<Point> soup;
    soup.points = seven;
    soup.polygons = polygons;
    EXPECT_EQ(CGAL_ext::Geodesics_3::internal::is_oriented_manifold(soup), PMP::is_polygon_soup_a_polygon_mesh(polygons))
      << name;
  }
  // a real mesh as read, and with one face reversed
  std::vector<Point> points;
  Polygons polygons;
  ASSERT_TRUE(CGAL::IO::read_polygon_soup(std::string(CGAL_EXT_CGAL_MESHES) + "/elephant.off", points, polygons));
  CGAL_ext::Geodesics_3::internal::Soup_in_repair<Point> soup;
  soup.points = points;
  soup.polygons = polygons;
  EXPECT_TRUE(CGAL_ext::Geodesics_3::internal::is_oriented_manifold(soup));
  std::reverse(soup.polygons[100].begin(), soup.polygons[100].end());
  EXPECT_FALSE(CGAL_ext::Geodesics_3::internal::is_oriented_manifold(soup));
  std::reverse(polygons[100].begin(), polygons[100].end());
  const Prepared p = prepare(points, polygons);
  EXPECT_EQ(p.repairs.reversed_polygons, 1u);
}

TEST(Polygon_soup_to_geodesic_mesh, isolated_points_are_isolated_vertices)
{
  std::vector<Point> points = unit_square;
  points.push_back(Point(5, 5, 5));
  const Polygons polygons = {{0, 1, 2}, {0, 2, 3}};
  const Prepared p = prepare(points, polygons);
  expect_prepared(p, points, polygons);
  EXPECT_EQ(p.repairs.isolated_points, 1u);
  EXPECT_FALSE(p.repairs.changed());
  EXPECT_EQ(p.repairs.summary(), "1 point is in no face (at infinite distance)");
  EXPECT_TRUE(p.mesh.is_isolated(p.vertex_of_point[4]));
  EXPECT_EQ(point_distances(p, 0)[4], inf);
}

TEST(Polygon_soup_to_geodesic_mesh, errors_name_what_and_where)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<Point> points = unit_square;
  points[2] = Point(1, nan, 0);
  EXPECT_EQ(error_of(points, Polygons{{0, 1, 2}}), "point 2 has a non-finite coordinate (1, nan, 0)");
  points[2] = Point(inf, 1, 0);
  EXPECT_EQ(error_of(points, Polygons{{0, 1, 3}}), "point 2 has a non-finite coordinate (inf, 1, 0)");

  EXPECT_EQ(error_of(unit_square, Polygons{{0, 1, 2}, {0, 2, 9}}), "polygon 1 uses point 9, but the soup has 4 points");
  EXPECT_EQ(error_of(unit_square, std::vector<std::array<int, 3>>{{0, -1, 2}}),
            "polygon 0 uses point -1, but the soup has 4 points");
  EXPECT_EQ(error_of(unit_square, Polygons{}), "no faces: the soup has 4 points and no polygon (a point cloud)");
  EXPECT_EQ(error_of(std::vector<Point>{}, Polygons{}), "no faces: the soup is empty");
  EXPECT_EQ(error_of(unit_square, Polygons{{0, 1}, {2, 2, 2}}),
            "no faces left: each of the 2 polygons has fewer than 3 distinct points");
  const std::vector<Point> on_a_line = {Point(0, 0, 0), Point(1, 0, 0), Point(2, 0, 0), Point(3, 0, 0)};
  EXPECT_EQ(error_of(on_a_line, Polygons{{0, 1, 2, 3}}),
            "polygon 0 (4 points) cannot be triangulated without new points: it is flat or crosses itself");
}

TEST(Polygon_soup_to_geodesic_mesh, summary_counts_with_thousands_separators)
{
  CGAL_ext::Geodesic_mesh_repairs r;
  r.merged_points = 1234567;
  r.triangulated_polygons = 40;
  r.isolated_points = 2;
  EXPECT_EQ(r.summary(),
            "merged 1,234,567 duplicate points, triangulated 40 polygons, 2 points are in no face (at infinite distance)");
  r = CGAL_ext::Geodesic_mesh_repairs();
  r.split_polygons = 1;
  r.removed_polygons = 1000;
  EXPECT_EQ(r.summary(),
            "removed 1,000 polygons with fewer than 3 distinct points, split 1 polygon passing twice through a point");
}

// Any FaceListGraph: a Polyhedron_3, from polygons as arrays of ints.
TEST(Polygon_soup_to_geodesic_mesh, any_triangle_mesh_and_polygon_type)
{
  typedef CGAL::Polyhedron_3<K> Polyhedron;
  Polyhedron polyhedron;
  std::vector<boost::graph_traits<Polyhedron>::vertex_descriptor> vertex_of_point;
  const std::vector<std::array<int, 4>> quads = {{0, 1, 2, 3}};
  const CGAL_ext::Geodesic_mesh_repairs r =
    CGAL_ext::polygon_soup_to_geodesic_mesh(unit_square, quads, polyhedron, vertex_of_point);
  EXPECT_EQ(r.triangulated_polygons, 1u);
  EXPECT_TRUE(CGAL::is_triangle_mesh(polyhedron));
  ASSERT_EQ(vertex_of_point.size(), 4u);
  for(std::size_t i = 0; i < 4; ++i)
    EXPECT_EQ(vertex_of_point[i]->point(), unit_square[i]);
}

// From a polygon mesh: a Surface_mesh of a quad and a triangle.
TEST(Polygon_soup_to_geodesic_mesh, from_a_polygon_mesh)
{
  Mesh quads;
  std::vector<Vertex> v;
  for(const Point& p : unit_square)
    v.push_back(quads.add_vertex(p));
  v.push_back(quads.add_vertex(Point(2, 0.5, 0)));
  quads.add_face(v[0], v[1], v[2], v[3]);
  quads.add_face(v[1], v[4], v[2]);
  Mesh mesh;
  auto vertex_in_mesh = quads.add_property_map<Vertex, Vertex>("v:in_mesh").first;
  const CGAL_ext::Geodesic_mesh_repairs r = CGAL_ext::polygon_mesh_to_geodesic_mesh(quads, mesh, vertex_in_mesh);
  EXPECT_EQ(r.summary(), "triangulated 1 polygon");
  EXPECT_EQ(mesh.number_of_faces(), 3u);
  for(Vertex u : quads.vertices())
    EXPECT_EQ(mesh.point(vertex_in_mesh[u]), quads.point(u));
}

// ---------------------------------------------------------------------------------------------
// A real mesh in the forms users have: the same distances, point for point

/// The test mesh's points rounded to float (what binary STL holds), and its triangles.
void float_soup(const Mesh& mesh, std::vector<Point>& points, Polygons& triangles)
{
  for(Vertex v : mesh.vertices()) {
    const Point& p = mesh.point(v);
    points.emplace_back(float(p.x()), float(p.y()), float(p.z()));
  }
  for(Face f : mesh.faces()) {
    triangles.emplace_back();
    for(Vertex v : face_corners(mesh, f))
      triangles.back().push_back(std::size_t(v));
  }
}

class Polygon_soup_forms : public ::testing::TestWithParam<const char*>
{
protected:
  void SetUp() override
  {
    m_dir = fs::temp_directory_path() / ("test_polygon_soup_" + std::to_string(::getpid()));
    fs::create_directories(m_dir);
  }
  void TearDown() override { fs::remove_all(m_dir); }

  std::string file(const std::string& name) const { return (m_dir / name).string(); }

  fs::path m_dir;
};

TEST_P(Polygon_soup_forms, stl_and_soups_give_the_distances_of_the_mesh)
{
  std::vector<Point> points;
  Polygons triangles;
  float_soup(test_mesh(GetParam()), points, triangles);
  const auto precision = CGAL::parameters::stream_precision(17);
  ASSERT_TRUE(CGAL::IO::write_polygon_soup(file("mesh.off"), points, triangles, precision));

  // the reference: the mesh read as a mesh, from its first point
  Mesh reference;
  ASSERT_TRUE(CGAL::IO::read_polygon_mesh(file("mesh.off"), reference));
  auto reference_distance = reference.add_property_map<Vertex, double>("v:distance", inf).first;
  CGAL_ext::geodesic_distances(reference, reference_distance, Vertex(0));
  std::map<Point, double> distance_at;
  for(Vertex v : reference.vertices())
    distance_at[reference.point(v)] = reference_distance[v];
  const double tolerance = 1e-12 * bbox_diagonal(reference);

  // every triangle its own three points
  std::vector<Point> soup_points;
  Polygons soup_triangles;
  for(const auto& t : triangles) {
    soup_triangles.push_back({soup_points.size(), soup_points.size() + 1, soup_points.size() + 2});
    for(std::size_t id : t)
      soup_points.push_back(points[id]);
  }
  ASSERT_TRUE(CGAL::IO::write_polygon_soup(file("soup.off"), soup_points, soup_triangles, precision));
  ASSERT_TRUE(CGAL::IO::write_polygon_soup(file("binary.stl"), points, triangles,
                                           CGAL::parameters::use_binary_mode(true)));
  ASSERT_TRUE(CGAL::IO::write_polygon_soup(file("ascii.stl"), points, triangles,
                                           CGAL::parameters::use_binary_mode(false).stream_precision(17)));

  for(const char* name : {"mesh.off", "soup.off", "binary.stl", "ascii.stl"}) {
    SCOPED_TRACE(name);
    std::vector<Point> read_points;
    Polygons read_polygons;
    ASSERT_TRUE(CGAL::IO::read_polygon_soup(file(name), read_points, read_polygons));
    ASSERT_EQ(read_polygons.size(), triangles.size());
    const Prepared p = prepare(read_points, read_polygons);
    expect_prepared(p, read_points, read_polygons);
    EXPECT_EQ(p.repairs.merged_points, std::string(name) == "soup.off" ? soup_points.size() - points.size() : 0u);
    EXPECT_EQ(p.mesh.number_of_vertices(), points.size());
    // the source: the reference's vertex 0, wherever the file has it (STL: first appearance)
    const std::size_t source = std::find(read_points.begin(), read_points.end(), points[0]) - read_points.begin();
    ASSERT_LT(source, read_points.size());
    const std::vector<double> d = point_distances(p, source);
    for(std::size_t i = 0; i < read_points.size(); ++i) {
      ASSERT_EQ(distance_at.count(read_points[i]), 1u) << "point " << i;
      const double expected = distance_at[read_points[i]];
      if(expected < inf)
        EXPECT_NEAR(d[i], expected, tolerance) << "point " << i;
      else
        EXPECT_EQ(d[i], inf) << "point " << i << " (in another component)";
    }
  }
}

// Every mesh of CGAL's data set the tests use but elephant-with-holes, whose 65 pairs of vertices
// at one place (the sides of its cuts) an STL file or a soup cannot hold apart.
INSTANTIATE_TEST_SUITE_P(Real_meshes, Polygon_soup_forms,
                         ::testing::Values("elephant", "fandisk", "mushroom", "cactus", "bunny00", "armadillo",
                                           "knot1", "cylinder", "blobby_3cc", "oblong", "man"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param); });

} // namespace
