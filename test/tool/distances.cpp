// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of the tool `geodesic`: `geodesic distances`, its outputs (text, PLY, --labels) against
// the library called directly, face points, several sources, --max-distance, unreachable parts.

#include "tool_test_support.h"

#include "tool_output.h"

#include <CGAL_ext/geodesic_distances.h>

namespace tool_test::distances {

/// The library called directly, on the mesh the tool makes of the file; the distances of the
/// file's points.
template <class Sources>
std::vector<double> library_distances(const Mesh_file& file, const Sources& sources)
{
  auto distance = get(CGAL::dynamic_vertex_property_t<double>(), file.mesh);
  CGAL_ext::geodesic_distances(file.mesh, distance, sources);
  std::vector<double> d;
  for(Vertex_index v : file.vertex_of_point)
    d.push_back(get(distance, v));
  return d;
}

TEST_F(Tool, txt_output_on_the_elephant)
{
  const std::vector<double> d = distances("distances '" + elephant + "' --source 0");
  ASSERT_EQ(d.size(), 2775u);
  EXPECT_EQ(lines_of(read_text(path("d.txt")))[0], "0");
  for(std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_TRUE(std::isfinite(d[i])) << "vertex " << i;
    EXPECT_GE(d[i], 0.) << "vertex " << i;
  }
  EXPECT_GT(*std::max_element(d.begin(), d.end()), 0.5);

  // the same on stdout, and the same as the library
  const Result r = run("distances '" + elephant + "' --source 0");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, read_text(path("d.txt")));
  EXPECT_EQ(r.err, "");
  const Mesh_file file = read_mesh_file(elephant);
  expect_same_distances(d, library_distances(file, file.vertex_of_point[0]));
}

TEST_F(Tool, ply_output_holds_the_txt_distances)
{
  const std::vector<double> d = distances("distances '" + elephant + "' --source 17");
  ASSERT_EQ(run("distances '" + elephant + "' --source 17 --output d.ply").exit_code, 0);
  Distances_ply ply;
  ASSERT_NO_FATAL_FAILURE(read_distances_ply(path("d.ply"), ply));
  ASSERT_EQ(ply.mesh.number_of_vertices(), 2775u);
  ASSERT_EQ(ply.mesh.number_of_faces(), 5558u);
  expect_same_distances(ply.distances, d);

  // the geometry is the file's, and the ramp goes from blue (near) to red (far)
  EXPECT_EQ(ply.points, read_soup(elephant).points);
  EXPECT_EQ(ply.colors[17], CGAL::IO::Color(0, 0, 255));
  const std::size_t far = std::max_element(d.begin(), d.end()) - d.begin();
  EXPECT_EQ(ply.colors[far], CGAL::IO::Color(255, 0, 0));
}

// Barycentric coordinates on the command line follow the file's order of the face's vertices,
// which is not the library's order (source(halfedge(f)) first).
TEST_F(Tool, face_point_coordinates_follow_the_file_order)
{
  // the elephant's mesh has the file's ids (see the_mesh_of_a_clean_file_keeps_the_file_order)
  const Mesh_file file = read_mesh_file(elephant);
  const Soup& soup = file.soup;
  const std::size_t face = 12;
  const std::array<double, 3> b{{0.2, 0.3, 0.5}};
  const auto polygon = soup.polygons[face];
  const std::array<std::size_t, 3> corners = library_corners(file.mesh, Face_index(face));
  ASSERT_NE(corners[0], polygon[0]) << "this face does not tell the two orders apart";

  const std::vector<double> d = distances("distances '" + elephant + "' --source f:12:0.2:0.3:0.5");
  ASSERT_EQ(d.size(), 2775u);

  // Inside its face the point sees the face's corners in a straight line.
  const Point p = CGAL::barycenter(soup.points[polygon[0]], b[0], soup.points[polygon[1]], b[1],
                                   soup.points[polygon[2]], b[2]);
  for(std::size_t v : polygon)
    EXPECT_NEAR(d[v], std::sqrt(CGAL::squared_distance(p, soup.points[v])), 1e-12) << "corner " << v;
  // (and the coordinates taken in the library's order would be a different point)
  const Point q = CGAL::barycenter(soup.points[corners[0]], b[0], soup.points[corners[1]], b[1],
                                   soup.points[corners[2]], b[2]);
  EXPECT_GT(std::sqrt(CGAL::squared_distance(p, q)), 1e-3);

  // The library given the same point in its own order.
  std::array<double, 3> library_b{};
  for(int k = 0; k < 3; ++k)
    library_b[k] = b[std::find(polygon.begin(), polygon.end(), corners[k]) - polygon.begin()];
  expect_same_distances(d, library_distances(file, std::make_pair(Face_index(face), library_b)));
}

TEST_F(Tool, several_sources_give_the_nearest_distance)
{
  const std::string mesh = "distances '" + elephant + "'";
  const std::vector<double> a = distances(mesh + " --source 100");
  const std::vector<double> b = distances(mesh + " --source f:40:0.6:0.3:0.1");
  const std::vector<double> both = distances(mesh + " --source 100,f:40:0.6:0.3:0.1");
  ASSERT_EQ(a.size(), 2775u);
  std::vector<double> nearest(a.size());
  for(std::size_t i = 0; i < a.size(); ++i)
    nearest[i] = std::min(a[i], b[i]);
  expect_same_distances(both, nearest, 1e-12);
  EXPECT_EQ(both[100], 0.);

  // repeated --source options and duplicates are accepted
  expect_same_distances(distances(mesh + " --source 100 --source f:40:0.6:0.3:0.1,100"), both, 1e-12);
  expect_same_distances(distances(mesh + " --source 100,100"), a);
}

// --labels: the nearest source of every vertex, as text and as PLY with a `source` property and
// a colour per cell; the label's single-source distance is the distance.
TEST_F(Tool, labels_name_the_nearest_source_of_every_vertex)
{
  const std::string mesh = "distances '" + elephant + "'";
  const std::vector<double> a = distances(mesh + " --source 100");
  const std::vector<double> b = distances(mesh + " --source f:40:0.6:0.3:0.1");
  const std::vector<double> c = distances(mesh + " --source 2000");
  for(const char* algorithm : {"vtp", "pvtp --threads 2", "fwp-mmp", "pmmp --threads 2"}) {
    const std::vector<double> all =
      distances(mesh + " --source 100,f:40:0.6:0.3:0.1,2000 --labels l.txt --algorithm " + algorithm);
    std::vector<long> labels;
    for(const std::string& line : lines_of(read_text(path("l.txt"))))
      labels.push_back(std::stol(line));
    ASSERT_EQ(labels.size(), a.size()) << algorithm;
    const double diagonal = *std::max_element(a.begin(), a.end()); // about the size of the mesh
    std::size_t clear = 0;
    for(std::size_t v = 0; v < a.size(); ++v) {
      const double single[3] = {a[v], b[v], c[v]};
      ASSERT_TRUE(labels[v] >= 0 && labels[v] <= 2) << algorithm << ": vertex " << v;
      EXPECT_NEAR(single[labels[v]], all[v], 1e-12 * diagonal) << algorithm << ": vertex " << v;
      const double second = std::min({single[(labels[v] + 1) % 3], single[(labels[v] + 2) % 3]});
      clear += second - all[v] > 1e-9;
    }
    EXPECT_GT(clear, a.size() * 9 / 10) << algorithm;
    EXPECT_EQ(labels[100], 0);
    EXPECT_EQ(labels[2000], 2);
  }

  // PLY: distance and source per vertex, a colour per cell, the file's polygons
  ASSERT_EQ(run(mesh + " --source 100,2000 --labels l.ply --output d.txt").exit_code, 0);
  std::ifstream in(path("l.ply"), std::ios::binary);
  Mesh ply;
  ASSERT_TRUE(CGAL::IO::read_PLY(in, ply));
  const auto [source, has_source] = ply.property_map<Vertex_index, int>("v:source");
  ASSERT_TRUE(has_source) << "no vertex property 'source' in the PLY file";
  const auto [color, has_color] = ply.property_map<Vertex_index, CGAL::IO::Color>("v:color");
  ASSERT_TRUE(has_color);
  EXPECT_EQ(ply.number_of_vertices(), a.size());
  EXPECT_EQ(ply.number_of_faces(), 5558u);
  std::size_t in_cell[2] = {0, 0};
  for(Vertex_index v : ply.vertices()) {
    ASSERT_TRUE(source[v] == 0 || source[v] == 1);
    ++in_cell[source[v]];
    EXPECT_EQ(color[v], tool::label_color(source[v]));
  }
  EXPECT_GT(in_cell[0], 100u);
  EXPECT_GT(in_cell[1], 100u);
  EXPECT_NE(tool::label_color(0), tool::label_color(1));
  EXPECT_EQ(tool::label_color(-1), CGAL::IO::Color(128, 128, 128));
}

// Unreached vertices are labelled -1; a labels file that cannot be written leaves no file at all
// (not the distances either); --labels must be .txt or .ply, and not the --output file.
TEST_F(Tool, labels_of_unreached_vertices_and_bad_labels_files)
{
  const std::string mesh = "distances '" + elephant + "' --source 0";
  const std::vector<double> d = distances(mesh + " --max-distance 0.2 --labels l.txt");
  const std::vector<std::string> labels = lines_of(read_text(path("l.txt")));
  ASSERT_EQ(labels.size(), d.size());
  for(std::size_t v = 0; v < d.size(); ++v)
    EXPECT_EQ(labels[v], std::isfinite(d[v]) ? "0" : "-1") << "vertex " << v;

  fs::remove(path("d.txt"));
  fs::remove(path("l.txt"));
  expect_failed_write(mesh + " --output d.txt --labels l.txt", "l.txt");
  fs::remove(path("l.txt"));
  for(const std::string& bad : {std::string(" --labels l.obj"), std::string(" --labels d.txt --output d.txt")}) {
    const Result r = run(mesh + bad);
    EXPECT_NE(r.exit_code, 0) << bad;
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_TRUE(files().empty()) << bad;
  }
}

TEST_F(Tool, max_distance_leaves_far_vertices_at_infinity)
{
  const std::vector<double> full = distances("distances '" + elephant + "' --source 0");
  const double limit = 0.3;
  const std::vector<double> near = distances("distances '" + elephant + "' --source 0 --max-distance 0.3");
  ASSERT_EQ(near.size(), full.size());
  std::size_t far = 0;
  for(std::size_t i = 0; i < full.size(); ++i) {
    if(full[i] > limit) {
      ++far;
      EXPECT_EQ(near[i], infinity) << "vertex " << i;
    } else {
      EXPECT_EQ(near[i], full[i]) << "vertex " << i;
    }
  }
  EXPECT_GT(far, 100u);
  EXPECT_LT(far, full.size() - 100);
  const std::vector<std::string> lines = lines_of(read_text(path("d.txt")));
  EXPECT_NE(std::find(lines.begin(), lines.end(), "inf"), lines.end());
}

// Two tetrahedra: a source on one leaves the other at infinity, which is not an error.
TEST_F(Tool, other_component_is_unreachable)
{
  std::string off = "OFF\n8 8 0\n";
  for(double x : {0., 10.})
    off += std::to_string(x) + " 0 0\n" + std::to_string(x + 1) + " 0 0\n" + std::to_string(x) + " 1 0\n" +
           std::to_string(x) + " 0 1\n";
  for(int o : {0, 4})
    for(const auto& t : {std::array<int, 3>{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}})
      off += "3 " + std::to_string(t[0] + o) + " " + std::to_string(t[1] + o) + " " + std::to_string(t[2] + o) + "\n";
  write("two.off", off);
  const std::vector<double> d = distances("distances two.off --source 0");
  ASSERT_EQ(d.size(), 8u);
  EXPECT_EQ(d[0], 0.);
  EXPECT_NEAR(d[1], 1., 1e-15);
  EXPECT_NEAR(d[2], 1., 1e-15);
  EXPECT_NEAR(d[3], 1., 1e-15);
  for(int v = 4; v < 8; ++v)
    EXPECT_EQ(d[v], infinity) << "vertex " << v;
  EXPECT_EQ(lines_of(read_text(path("d.txt")))[4], "inf");
}

} // namespace tool_test::distances
