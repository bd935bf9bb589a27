// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of the tool `geodesic`: `geodesic voronoi`, cells, bisectors and dual graph.

#include "tool_test_support.h"

namespace tool_test::voronoi {

// The cells are the labels of distances --labels; the bisectors' pairs are the dual graph's
// edges; the dual graph's vertices are the sources.
TEST_F(Tool, voronoi_cells_bisectors_and_dual_graph)
{
  const std::string sources = " --source 0,100,1000,f:40:0.6:0.3:0.1";
  ASSERT_EQ(run("voronoi '" + elephant + "'" + sources + " --output c.txt --bisectors b.txt --dual d.obj").exit_code, 0);
  distances("distances '" + elephant + "'" + sources + " --algorithm fwp-mmp --labels l.txt");
  EXPECT_EQ(read_text(path("c.txt")), read_text(path("l.txt")));

  std::set<std::pair<int, int>> bisector_pairs;
  std::size_t points = 0, polylines = 1;
  for(const std::string& line : lines_of(read_text(path("b.txt")))) {
    if(line.empty()) {
      ++polylines;
      continue;
    }
    std::istringstream in(line);
    double x, y, z;
    int a = -1, b = -1;
    ASSERT_TRUE(in >> x >> y >> z >> a >> b) << line;
    EXPECT_TRUE(0 <= a && a < b && b < 4) << line;
    bisector_pairs.insert({a, b});
    ++points;
  }
  EXPECT_GT(points, 20u);
  EXPECT_GE(polylines, bisector_pairs.size());

  std::set<std::pair<int, int>> dual_edges;
  std::size_t vertices = 0;
  for(const std::string& line : lines_of(read_text(path("d.obj")))) {
    std::istringstream in(line);
    std::string kind;
    in >> kind;
    vertices += kind == "v";
    if(kind == "l") {
      int a, b;
      in >> a >> b;
      dual_edges.insert({a - 1, b - 1});
    }
  }
  EXPECT_EQ(vertices, 4u);
  EXPECT_EQ(dual_edges, bisector_pairs);

  // read from the windows of VTP, of PVTP on one thread, of FWP-MMP and of PMMP: the same cells and dual graph
  for(const std::string algorithm : {"vtp", "pvtp --threads 1", "fwp-mmp", "pmmp --threads 2"}) {
    ASSERT_EQ(run("voronoi '" + elephant + "'" + sources + " --algorithm " + algorithm + " --output v.txt --dual v.obj")
                .exit_code,
              0)
      << algorithm;
    EXPECT_EQ(read_text(path("v.txt")), read_text(path("c.txt"))) << algorithm;
    EXPECT_EQ(read_text(path("v.obj")), read_text(path("d.obj"))) << algorithm;
  }
}

} // namespace tool_test::voronoi
