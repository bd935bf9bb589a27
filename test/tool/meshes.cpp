// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of the tool `geodesic`: reading meshes. The mesh the tool makes of a file and its maps
// from the file's points and polygons, the file's polygons in one array, and meshes as users
// have them, which the tool repairs.

#include "tool_test_support.h"

#include <CGAL/IO/polygon_soup_io.h>

namespace tool_test::meshes {

// ---------------------------------------------------------------------------------------------
// What the tool relies on

// A clean file is its mesh as it is: vertex i is point i and face j polygon j, in the same
// cyclic order (the tests below that compare ids of the mesh and of the file rely on it).
TEST_F(Tool, the_mesh_of_a_clean_file_keeps_the_file_order)
{
  for(const std::string& name : {elephant, mushroom}) {
    const Mesh_file file = read_mesh_file(name);
    const Soup& soup = file.soup;
    EXPECT_FALSE(file.repairs.changed()) << file.repairs.summary();
    EXPECT_EQ(file.repairs.summary(), "");
    ASSERT_EQ(file.mesh.number_of_vertices(), soup.points.size());
    ASSERT_EQ(file.mesh.number_of_faces(), soup.polygons.size());
    for(std::size_t i = 0; i < soup.points.size(); ++i)
      ASSERT_EQ(file.vertex_of_point[i], Vertex_index(Mesh::size_type(i))) << name << " vertex " << i;
    for(std::size_t j = 0; j < soup.polygons.size(); ++j) {
      ASSERT_EQ(file.face_of_polygon[j], Face_index(Mesh::size_type(j))) << name << " face " << j;
      const std::array<std::size_t, 3> c = library_corners(file.mesh, file.face_of_polygon[j]);
      const auto& p = soup.polygons[j];
      const auto at = std::find(p.begin(), p.end(), c[0]) - p.begin();
      ASSERT_LT(at, 3) << name << " face " << j;
      ASSERT_EQ(c[1], p[(at + 1) % 3]) << name << " face " << j;
      ASSERT_EQ(c[2], p[(at + 2) % 3]) << name << " face " << j;
    }
    EXPECT_TRUE(file.vertex_of_point.is_identity()) << name; // kept as nothing
    EXPECT_TRUE(file.face_of_polygon.is_identity()) << name;
  }
}

// A repaired file keeps its maps: a point of a soup (polygons that share no point) goes to the
// vertex of its first copy, and a quad, split into triangles, to no face.
TEST_F(Tool, the_mesh_of_a_repaired_file_maps_each_point_and_polygon)
{
  tool::Soup soup;
  soup.points = {Point(0, 0, 0), Point(1, 0, 0), Point(1, 1, 0), Point(0, 1, 0),
                 Point(1, 0, 0), Point(2, 0, 0), Point(1, 1, 0)};
  soup.polygons = tool::Polygons{{0, 1, 2, 3}, {4, 5, 6}};
  const Mesh_file file = tool::make_mesh_file(soup);
  ASSERT_EQ(file.vertex_of_point.size(), 7u);
  ASSERT_EQ(file.face_of_polygon.size(), 2u);
  EXPECT_FALSE(file.vertex_of_point.is_identity());
  EXPECT_FALSE(file.face_of_polygon.is_identity());
  std::size_t points = 0;
  for(Vertex_index v : file.vertex_of_point)
    EXPECT_EQ(file.mesh.point(v), soup.points[points++]);
  EXPECT_EQ(points, 7u);
  EXPECT_EQ(file.vertex_of_point[4], file.vertex_of_point[1]);
  EXPECT_EQ(file.vertex_of_point[6], file.vertex_of_point[2]);
  EXPECT_EQ(file.face_of_polygon[0], Mesh::null_face());
  EXPECT_NE(file.face_of_polygon[1], Mesh::null_face());
}

// The file's polygons in one array: each polygon as it was given, in order; ids past 32 bits
// are an error, not a wrapped id.
TEST(Tool_polygons, one_array_keeps_each_polygon)
{
  const std::vector<std::vector<std::size_t>> given = {{0, 1, 2}, {2, 1, 3, 4}, {4, 5, 6, 7, 8}};
  const tool::Polygons polygons(given);
  ASSERT_EQ(polygons.size(), 3u);
  EXPECT_EQ(polygons[1].size(), 4u);
  EXPECT_EQ(polygons[2][4], 8u);
  EXPECT_EQ(polygons.to_vectors(), given);
  std::size_t corners = 0;
  for(const auto polygon : polygons)
    corners += polygon.size();
  EXPECT_EQ(corners, 12u);
  EXPECT_EQ(polygons, (tool::Polygons{{0, 1, 2}, {2, 1, 3, 4}, {4, 5, 6, 7, 8}}));
  // Triangles only keep no starts; a polygon after them is where the starts begin.
  const std::vector<std::vector<std::size_t>> triangles_first = {{0, 1, 2}, {2, 1, 3}, {3, 4, 5, 6}, {6, 7, 8}};
  tool::Polygons mixed;
  for(std::size_t i = 0; i < triangles_first.size(); ++i) {
    mixed.push_back(triangles_first[i]);
    ASSERT_EQ(mixed.size(), i + 1);
    EXPECT_EQ(mixed.to_vectors(), std::vector<std::vector<std::size_t>>(triangles_first.begin(),
                                                                          triangles_first.begin() + i + 1));
  }
  EXPECT_EQ(mixed[3][2], 8u);
  EXPECT_NE(mixed, polygons);
  EXPECT_NE((tool::Polygons{{0, 1, 2}}), (tool::Polygons{{0, 1, 2}, {}}));
  tool::Polygons too_large;
  EXPECT_THROW(too_large.push_back(std::vector<std::size_t>{0, 1, std::size_t(1) << 32}), tool::Tool_error);
  EXPECT_TRUE(too_large.empty()); // nothing of the refused polygon is kept
}

// ---------------------------------------------------------------------------------------------
// Meshes as users have them: the tool repairs them, says so in one line `note: ...`, and gives
// its results in the file's order of points.

const std::string unit_square_points = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n";

/// The distances in the plane from `source` to `points`, in their order.
std::vector<double> planar_distances(const Point& source, const std::vector<Point>& points)
{
  std::vector<double> d;
  for(const Point& p : points)
    d.push_back(distance_between(source, p));
  return d;
}

TEST_F(Tool, a_quad_is_triangulated)
{
  write("quad.off", "OFF\n4 1 0\n" + unit_square_points + "4 0 1 2 3\n");
  const std::vector<double> d = repaired_distances("distances quad.off --source 3", "triangulated 1 polygon");
  expect_same_distances(d, {1., std::sqrt(2.), 1., 0.}, 1e-15);
}

// One triangle's points after another's: the copies are merged, and every point of the file has
// its distance, as a face point of the file has its place.
TEST_F(Tool, a_soup_is_merged_and_results_follow_the_file)
{
  write("soup.off", "OFF\n6 2 0\n0 0 0\n1 0 0\n1 1 0\n0 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 3 4 5\n");
  const Soup soup = read_soup(path("soup.off").string());
  const std::string note = "merged 2 duplicate points";
  const std::vector<double> from_5 = repaired_distances("distances soup.off --source 5", note);
  expect_same_distances(from_5, planar_distances(soup.points[5], soup.points), 1e-15);
  const Point p = face_point(soup, 1, {{0.2, 0.3, 0.5}});
  expect_same_distances(repaired_distances("distances soup.off --source f:1:0.2:0.3:0.5", note),
                        planar_distances(p, soup.points), 1e-15);

  // the PLY holds the file's six points and two triangles, a distance each
  output_of("distances soup.off --source 5", "d.ply", "note: " + note + "\n");
  Distances_ply ply;
  ASSERT_NO_FATAL_FAILURE(read_distances_ply(path("d.ply"), ply));
  EXPECT_EQ(ply.points, soup.points);
  EXPECT_EQ(ply.mesh.number_of_faces(), 2u);
  expect_same_distances(ply.distances, from_5);
}

// STL repeats each point in every triangle: the vertex ids are the distinct points in the order
// of their first appearance, ASCII or binary alike; here the second triangle is also reversed.
TEST_F(Tool, stl_ascii_and_binary)
{
  const auto facet = [](const std::string& a, const std::string& b, const std::string& c) {
    return "facet normal 0 0 1\nouter loop\nvertex " + a + "\nvertex " + b + "\nvertex " + c +
           "\nendloop\nendfacet\n";
  };
  write("square.stl", "solid square\n" + facet("1 1 0", "0 0 0", "1 0 0") + facet("1 1 0", "0 0 0", "0 1 0") +
                        "endsolid square\n");
  const Soup soup = read_soup(path("square.stl").string());
  const std::vector<Point> first_appearance = {Point(1, 1, 0), Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)};
  ASSERT_EQ(soup.points, first_appearance);
  const std::string note = "merged 2 duplicate points, reversed 1 polygon to orient the surface";
  const std::vector<double> ascii = repaired_distances("distances square.stl --source 2", note);
  expect_same_distances(ascii, planar_distances(Point(1, 0, 0), first_appearance), 1e-15);

  ASSERT_TRUE(CGAL::IO::write_polygon_soup(path("binary.stl").string(), soup.points, soup.polygons.to_vectors(),
                                           CGAL::parameters::use_binary_mode(true)));
  EXPECT_EQ(read_soup(path("binary.stl").string()).points, first_appearance);
  EXPECT_EQ(repaired_distances("distances binary.stl --source 2", note), ascii);

  const Result r = run("distances square.stl --source 2 --stats --output d.txt");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(lines_of(r.err).front(), "note: " + note);
  const auto kv = parse_key_values(r.err.substr(r.err.find('\n') + 1));
  EXPECT_EQ(kv.at("vertices"), "4");
  EXPECT_EQ(kv.at("faces"), "2");
  EXPECT_EQ(kv.at("merged_points"), "2");
  EXPECT_EQ(kv.at("reversed_polygons"), "1");
  EXPECT_EQ(kv.at("duplicated_points"), "0");
}

// Two triangles meeting at vertex 0 only: the vertex is split to make a mesh and glued again by
// the solvers, so distances and paths go through it.
TEST_F(Tool, a_non_manifold_vertex_is_passed_through)
{
  write("bowtie.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n");
  const std::string note =
    "duplicated 1 point at non-manifold vertices or edges (glued again: geodesics pass through them)";
  expect_same_distances(repaired_distances("distances bowtie.off --source 1", note),
                        {1., 0., std::sqrt(2.), 2., 2.}, 1e-15);
  const std::vector<Point> p = parse_points(output_of("path bowtie.off --source 1 --target 3", "p.txt",
                                                      "note: " + note + "\n"));
  ASSERT_GE(p.size(), 3u);
  EXPECT_EQ(p.front(), Point(1, 0, 0));
  EXPECT_EQ(p.back(), Point(-1, 0, 0));
  EXPECT_NEAR(polyline_length(p), 2., 1e-15);
}

// Three triangles on edge (0, 1) and an isolated point; every point of the file has a distance.
TEST_F(Tool, a_non_manifold_edge_and_an_isolated_point)
{
  write("edge3.off", "OFF\n6 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n7 7 7\n3 0 1 2\n3 1 0 3\n3 1 0 4\n");
  const std::vector<double> d =
    repaired_distances("distances edge3.off --source 0",
                       "duplicated 4 points at non-manifold vertices or edges (glued again: geodesics pass "
                       "through them), 1 edge is shared by 3 or more polygons (paths cross such an edge only "
                       "at its end points), 1 point is in no face (at infinite distance)");
  expect_same_distances(d, {0., 1., 1., 1., 1., infinity}, 1e-15);
}

// A face point on a triangle that orienting the surface reversed keeps the file's order.
TEST_F(Tool, a_face_point_on_a_reversed_triangle)
{
  write("flipped.off", "OFF\n4 2 0\n" + unit_square_points + "3 0 1 2\n3 0 3 2\n");
  const Soup soup = read_soup(path("flipped.off").string());
  const std::string note = "reversed 1 polygon to orient the surface";
  const Point p = face_point(soup, 1, {{0.6, 0.3, 0.1}});
  expect_same_distances(repaired_distances("distances flipped.off --source f:1:0.6:0.3:0.1", note),
                        planar_distances(p, soup.points), 1e-15);
  const std::vector<Point> path = parse_points(output_of("path flipped.off --source 1 --target f:1:0.6:0.3:0.1",
                                                         "p.txt", "note: " + note + "\n"));
  ASSERT_GE(path.size(), 2u);
  EXPECT_LT(distance_between(path.back(), p), 1e-15);
  EXPECT_NEAR(polyline_length(path), distance_between(soup.points[1], p), 1e-15);
}

} // namespace tool_test::meshes
