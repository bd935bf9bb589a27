// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of the tool `geodesic`: `geodesic path`, between vertices and face points, with every
// algorithm, as text, OBJ and PLY.

#include "tool_test_support.h"

#include "tool_options.h"

namespace tool_test::paths {

// ---------------------------------------------------------------------------------------------
// Shortest paths

TEST_F(Tool, path_between_two_vertices)
{
  const Soup soup = read_soup(elephant);
  const std::vector<double> vtp = distances("distances '" + elephant + "' --source 0 --algorithm vtp");
  const std::vector<Point> p = path_points("path '" + elephant + "' --source 0 --target 1500");
  ASSERT_GE(p.size(), 3u);
  // from the source to the target, their positions read back exactly (17 significant digits)
  EXPECT_EQ(p.front(), soup.points[0]);
  EXPECT_EQ(p.back(), soup.points[1500]);
  EXPECT_NEAR(polyline_length(p), vtp[1500], 1e-9 * vtp[1500]);
  EXPECT_GT(polyline_length(p), distance_between(p.front(), p.back()));

  // the same on stdout
  const Result r = run("path '" + elephant + "' --source 0 --target 1500");
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, read_text(path("p.txt")));
  EXPECT_EQ(r.err, "");
}

TEST_F(Tool, path_is_the_same_with_every_algorithm)
{
  const std::string args = "path '" + elephant + "' --source 0,f:7:0.2:0.5:0.3 --target 1500";
  const std::vector<Point> fwp = path_points(args + " --algorithm fwp-mmp");
  EXPECT_EQ(path_points(args), path_points(args + " --algorithm " + tool::default_vertex_solver))
    << "the default is not " << tool::default_vertex_solver;
  const double length = polyline_length(fwp);
  for(const char* algorithm : {"mmp", "pmmp", "vtp", "pvtp"}) {
    const std::vector<Point> p = path_points(args + " --algorithm " + algorithm);
    EXPECT_NEAR(polyline_length(p), length, 1e-9 * length) << algorithm;
    EXPECT_EQ(p.front(), fwp.front()) << algorithm;
    EXPECT_EQ(p.back(), fwp.back()) << algorithm;
  }
  path_points(args + " --algorithm pmmp --threads 1", "one.txt");
  path_points(args + " --algorithm pmmp --threads 2", "two.txt");
  path_points(args + " --algorithm pmmp --threads 2 --batch-size 16", "batch.txt");
  EXPECT_EQ(read_text(path("two.txt")), read_text(path("one.txt")));
  const double batch_length = polyline_length(parse_points(read_text(path("batch.txt"))));
  EXPECT_NEAR(batch_length, length, 1e-9 * length);
}

TEST_F(Tool, path_obj_and_ply_hold_the_txt_points)
{
  const std::string args = "path '" + elephant + "' --source 0 --target f:40:0.6:0.3:0.1";
  const std::vector<Point> txt = path_points(args);
  ASSERT_GE(txt.size(), 3u);

  // OBJ: the points as `v` lines, then one `l` line through them in order
  ASSERT_EQ(run(args + " --output p.obj").exit_code, 0);
  expect_obj_polyline(read_text(path("p.obj")), txt);

  // PLY: ASCII, a vertex element and an edge element between consecutive points
  ASSERT_EQ(run(args + " --output p.ply").exit_code, 0);
  expect_ply_polyline(read_text(path("p.ply")), txt);
}

TEST_F(Tool, path_from_a_face_point_to_a_vertex)
{
  const Soup soup = read_soup(elephant);
  const std::vector<double> vtp = distances("distances '" + elephant + "' --source f:12:0.2:0.3:0.5 --algorithm vtp");
  const std::vector<Point> p = path_points("path '" + elephant + "' --source f:12:0.2:0.3:0.5 --target 1000");
  ASSERT_GE(p.size(), 3u);
  // the coordinates follow the file's order of the face's vertices, as for distances
  EXPECT_LT(distance_between(p.front(), face_point(soup, 12, {{0.2, 0.3, 0.5}})), 1e-12);
  EXPECT_EQ(p.back(), soup.points[1000]);
  EXPECT_NEAR(polyline_length(p), vtp[1000], 1e-9 * vtp[1000]);
}

TEST_F(Tool, path_from_a_vertex_to_a_face_point)
{
  const Soup soup = read_soup(elephant);
  const std::vector<double> vtp = distances("distances '" + elephant + "' --source 0 --algorithm vtp");
  const Point target = face_point(soup, 40, {{0.6, 0.3, 0.1}});
  const std::vector<Point> p = path_points("path '" + elephant + "' --source 0 --target f:40:0.6:0.3:0.1");
  ASSERT_GE(p.size(), 3u);
  EXPECT_EQ(p.front(), soup.points[0]);
  EXPECT_LT(distance_between(p.back(), target), 1e-12);
  // within the triangle inequality through each corner of the face
  const double length = polyline_length(p);
  for(std::size_t v : soup.polygons[40]) {
    const double corner = vtp[v], step = distance_between(soup.points[v], target);
    EXPECT_LE(length, corner + step + 1e-12) << "corner " << v;
    EXPECT_GE(length, corner - step - 1e-12) << "corner " << v;
  }
}

TEST_F(Tool, path_between_two_face_points_with_stats)
{
  const Soup soup = read_soup(elephant);
  const Result r = run("path '" + elephant +
                       "' --source f:12:0.2:0.3:0.5 --target f:40:0.6:0.3:0.1 --stats --output p.txt");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.out, "");
  const std::vector<Point> p = parse_points(read_text(path("p.txt")));
  ASSERT_GE(p.size(), 3u);
  EXPECT_LT(distance_between(p.front(), face_point(soup, 12, {{0.2, 0.3, 0.5}})), 1e-12);
  EXPECT_LT(distance_between(p.back(), face_point(soup, 40, {{0.6, 0.3, 0.1}})), 1e-12);
  const auto kv = parse_key_values(r.err);
  ASSERT_EQ(kv.count("length"), 1u) << r.err;
  ASSERT_EQ(kv.count("distance"), 1u) << r.err;
  const double length = std::stod(kv.at("length")), distance = std::stod(kv.at("distance"));
  EXPECT_NEAR(length, distance, 1e-9 * distance);
  EXPECT_NEAR(length, polyline_length(p), 1e-12 * length);
  EXPECT_EQ(kv.at("points"), std::to_string(p.size()));
  EXPECT_EQ(kv.at("nearest_source"), "0");
}

// A target at a source is a path of one point: an OBJ without a line, a PLY without edges.
TEST_F(Tool, path_to_a_source_is_one_point)
{
  const Soup soup = read_soup(elephant);
  const std::string args = "path '" + elephant + "' --source 3,5 --target 5";
  EXPECT_EQ(path_points(args), std::vector<Point>{soup.points[5]});
  ASSERT_EQ(run(args + " --output p.obj").exit_code, 0);
  const std::vector<std::string> obj = lines_of(read_text(path("p.obj")));
  EXPECT_EQ(std::count_if(obj.begin(), obj.end(), [](const std::string& l) { return l.rfind("v ", 0) == 0; }), 1);
  EXPECT_EQ(std::count_if(obj.begin(), obj.end(), [](const std::string& l) { return l.rfind("l", 0) == 0; }), 0);
  ASSERT_EQ(run(args + " --output p.ply").exit_code, 0);
  const std::string ply = read_text(path("p.ply"));
  EXPECT_NE(ply.find("element vertex 1\n"), std::string::npos) << ply;
  EXPECT_NE(ply.find("element edge 0\n"), std::string::npos) << ply;
}

} // namespace tool_test::paths
