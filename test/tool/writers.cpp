// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of the tool `geodesic`: its writers, called directly (distances as text and PLY, paths
// as text, OBJ and PLY, writing through a temporary file).

#include "tool_test_support.h"

#include "tool_output.h"

#include <stdexcept>

namespace tool_test::writers {

// ---------------------------------------------------------------------------------------------
// The writers, called directly

/// A tetrahedron's points and triangles as a file holds them, and a distance for each point.
class Tool_output : public Tool
{
protected:
  Tool_output()
  {
    soup.points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)};
    soup.polygons = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  }

  /// The PLY `name` read back as a soup with CGAL: its points and polygons.
  Soup read_ply_soup(const std::string& name) const
  {
    Soup read;
    std::vector<std::vector<std::size_t>> polygons;
    std::ifstream in(path(name), std::ios::binary);
    EXPECT_TRUE(CGAL::IO::read_PLY(in, read.points, polygons));
    read.polygons = tool::Polygons(polygons);
    return read;
  }

  const std::vector<double> d = {0., 0.1, 1. / 3, infinity}; // vertex 3 unreached
  Soup soup;
};

TEST_F(Tool_output, distances_txt_reads_back_exactly)
{
  std::ostringstream os;
  ASSERT_TRUE(tool::write_distances_txt(os, d));
  EXPECT_EQ(os.str(), "0\n0.10000000000000001\n0.33333333333333331\ninf\n");
  EXPECT_EQ(parse_distances(os.str()), d);
}

TEST_F(Tool_output, distances_ply_reads_back_with_cgal)
{
  tool::write_output(path("d.ply").string(), [&](std::ostream& os) { return tool::write_distances_ply(os, soup, d); });
  EXPECT_EQ(files(), std::set<std::string>{"d.ply"});
  Distances_ply ply;
  ASSERT_NO_FATAL_FAILURE(read_distances_ply(path("d.ply"), ply));
  ASSERT_EQ(ply.mesh.number_of_faces(), 4u);
  EXPECT_EQ(ply.points, soup.points);
  EXPECT_EQ(ply.distances, d);
  ASSERT_EQ(ply.colors.size(), d.size());
  for(std::size_t v = 0; v < d.size(); ++v)
    EXPECT_EQ(ply.colors[v], tool::distance_color(d[v], 1. / 3)) << "vertex " << v;
  // blue at the source, red at the farthest reached vertex, grey where unreached
  EXPECT_EQ(ply.colors[0], CGAL::IO::Color(0, 0, 255));
  EXPECT_EQ(ply.colors[2], CGAL::IO::Color(255, 0, 0));
  EXPECT_EQ(ply.colors[3], CGAL::IO::Color(128, 128, 128));
  EXPECT_EQ(tool::farthest_finite(d), 1. / 3);
  EXPECT_EQ(read_ply_soup("d.ply").polygons, soup.polygons);
}

// The PLY holds the file's polygons as they are, whatever their size, and no mesh is made of them.
TEST_F(Tool_output, distances_ply_keeps_the_file_polygons)
{
  // three triangles on edge (0, 1), a quad, and a polygon of 300 points (more than a uchar counts)
  soup.points.push_back(Point(1, 1, 0));
  soup.polygons = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}, {0, 1, 4, 2}};
  std::vector<std::size_t> large;
  for(std::size_t i = 0; i < 300; ++i) {
    large.push_back(soup.points.size());
    soup.points.push_back(Point(std::cos(i * 0.02), std::sin(i * 0.02), 5));
  }
  soup.polygons.push_back(large);
  const std::vector<double> distances(soup.points.size(), 0.5);
  tool::write_output(path("d.ply").string(),
                     [&](std::ostream& os) { return tool::write_distances_ply(os, soup, distances); });
  const Soup read = read_ply_soup("d.ply");
  EXPECT_EQ(read.points, soup.points);
  EXPECT_EQ(read.polygons, soup.polygons);
}

TEST_F(Tool_output, paths_read_back_exactly)
{
  const std::vector<Point> points = {Point(0.1, 1. / 3, -2.5e-300), Point(1e300, 2, 3), Point(-1, 0, 0.7)};
  for(const std::vector<Point>& polyline : {points, std::vector<Point>{points[1]}}) {
    SCOPED_TRACE(std::to_string(polyline.size()) + " points");
    std::ostringstream txt, obj, ply;
    ASSERT_TRUE(tool::write_path_txt(txt, polyline));
    EXPECT_EQ(parse_points(txt.str()), polyline);
    ASSERT_TRUE(tool::write_path_obj(obj, polyline));
    expect_obj_polyline(obj.str(), polyline);
    ASSERT_TRUE(tool::write_path_ply(ply, polyline));
    expect_ply_polyline(ply.str(), polyline);
  }
}

// Writing through a temporary file: an error leaves no file behind, and an existing file as it was.
TEST_F(Tool_output, a_failed_write_leaves_no_partial_file)
{
  const auto complete = [](std::ostream& os) { return bool(os << "new content\n"); };
  const auto fails_half_way = [](std::ostream& os) {
    os << "partial";
    os.setstate(std::ios::badbit);
    return bool(os);
  };
  const auto throws_half_way = [](std::ostream& os) -> bool {
    os << "partial";
    throw std::runtime_error("stop");
  };
  const std::string file = path("d.txt").string();
  write("d.txt", "previous content\n");
  tool::write_output(file, complete);
  EXPECT_EQ(read_text(file), "new content\n");
  EXPECT_EQ(files(), std::set<std::string>{"d.txt"});

  EXPECT_EQ(tool_error_of([&] { tool::write_output(file, fails_half_way); }), "cannot write '" + file + "'");
  EXPECT_THROW(tool::write_output(file, throws_half_way), std::runtime_error);
  EXPECT_EQ(read_text(file), "new content\n");
  const std::string other = path("e.txt").string();
  EXPECT_EQ(tool_error_of([&] { tool::write_output(other, fails_half_way); }), "cannot write '" + other + "'");
  EXPECT_THROW(tool::write_output(other, throws_half_way), std::runtime_error);
  EXPECT_EQ(files(), std::set<std::string>{"d.txt"});

  // a folder in the way, a missing folder
  fs::create_directory(path("folder.txt"));
  const std::string folder = path("folder.txt").string(), missing = path("missing/m.txt").string();
  EXPECT_EQ(tool_error_of([&] { tool::write_output(folder, complete); }), "cannot write '" + folder + "'");
  EXPECT_EQ(tool_error_of([&] { tool::write_output(missing, complete); }), "cannot write '" + missing + "'");
  EXPECT_EQ(files(), (std::set<std::string>{"d.txt", "folder.txt"}));
  EXPECT_TRUE(fs::is_empty(path("folder.txt")));
}

} // namespace tool_test::writers
