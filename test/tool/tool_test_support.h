// Copyright (c) 2026 The CGAL_ext geodesics developers.
// What the tests of the command-line tool `geodesic` share: the test meshes, the fixture `Tool`
// that runs the tool as a separate process in a folder of its own under the build directory
// (kept when the test fails, for inspection), and the readers and checks of the tool's outputs.
// The helpers of one source stay in that source, in a namespace named after it.
#ifndef CGAL_EXT_TEST_TOOL_TOOL_TEST_SUPPORT_H
#define CGAL_EXT_TEST_TOOL_TOOL_TEST_SUPPORT_H

#include "tool_error.h"
#include "tool_mesh.h"

#include <CGAL_ext/Geodesics_3/polyline_length.h>

#include <CGAL/IO/PLY.h>

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace tool_test {

namespace fs = std::filesystem;
namespace tool = geodesic_tool;
using CGAL_ext::polyline_length;
// the tool's mesh, read and built the tool's way
using tool::Face_index;
using tool::Mesh;
using tool::Mesh_file;
using tool::Point;
using tool::read_mesh_file;
using tool::read_soup;
using tool::Soup;
using tool::Vertex_index;

inline const std::string elephant = std::string(CGAL_EXT_DATA_DIR) + "/elephant.off";
inline const std::string mushroom = std::string(CGAL_EXT_DATA_DIR) + "/mushroom.off";
inline const double infinity = std::numeric_limits<double>::infinity();

struct Result
{
  int exit_code;
  std::string out;
  std::string err;
};

inline std::string read_text(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

inline std::vector<std::string> lines_of(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  for(std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

/// Parses the tool's txt output: one number (or `inf`) per line, nothing else.
inline std::vector<double> parse_distances(const std::string& text)
{
  std::vector<double> d;
  for(const std::string& line : lines_of(text)) {
    char* end = nullptr;
    d.push_back(std::strtod(line.c_str(), &end));
    EXPECT_TRUE(!line.empty() && *end == '\0') << "not a number: '" << line << "'";
  }
  return d;
}

inline std::map<std::string, std::string> parse_key_values(const std::string& text)
{
  std::map<std::string, std::string> kv;
  for(const std::string& line : lines_of(text)) {
    const auto eq = line.find('=');
    EXPECT_NE(eq, std::string::npos) << "not key=value: '" << line << "'";
    if(eq != std::string::npos)
      kv[line.substr(0, eq)] = line.substr(eq + 1);
  }
  return kv;
}

/// Parses a polyline of the tool: one `x y z` line per point, nothing else.
inline std::vector<Point> parse_points(const std::string& text)
{
  std::vector<Point> points;
  for(const std::string& line : lines_of(text)) {
    std::istringstream in(line);
    double x, y, z;
    std::string rest;
    EXPECT_TRUE(in >> x >> y >> z && !(in >> rest)) << "not 'x y z': '" << line << "'";
    points.emplace_back(x, y, z);
  }
  return points;
}

/// A distances PLY of the tool, read back with CGAL: the mesh and, in vertex order, its points,
/// distances and colours.
struct Distances_ply
{
  Mesh mesh;
  std::vector<Point> points;
  std::vector<double> distances;
  std::vector<CGAL::IO::Color> colors;
};

inline void read_distances_ply(const fs::path& file, Distances_ply& ply)
{
  std::ifstream in(file, std::ios::binary);
  ASSERT_TRUE(CGAL::IO::read_PLY(in, ply.mesh));
  const auto [distance, has_distance] = ply.mesh.property_map<Vertex_index, double>("v:distance");
  ASSERT_TRUE(has_distance) << "no vertex property 'distance' in the PLY file";
  const auto [color, has_color] = ply.mesh.property_map<Vertex_index, CGAL::IO::Color>("v:color");
  ASSERT_TRUE(has_color);
  for(Vertex_index v : ply.mesh.vertices()) {
    ply.points.push_back(ply.mesh.point(v));
    ply.distances.push_back(distance[v]);
    ply.colors.push_back(color[v]);
  }
}

/// Checks a polyline in the tool's OBJ: the points as `v` lines, then one `l` line through them in
/// order (none for a single point), and comments.
inline void expect_obj_polyline(const std::string& text, const std::vector<Point>& points)
{
  std::vector<Point> obj;
  std::vector<std::string> polylines;
  for(const std::string& line : lines_of(text)) {
    std::istringstream in(line);
    std::string tag;
    in >> tag;
    if(tag == "v") {
      double x, y, z;
      ASSERT_TRUE(in >> x >> y >> z) << line;
      obj.emplace_back(x, y, z);
    } else if(tag == "l") {
      polylines.push_back(line);
    } else {
      EXPECT_EQ(tag, "#") << line;
    }
  }
  EXPECT_EQ(obj, points);
  std::string expected = "l";
  for(std::size_t i = 1; i <= points.size(); ++i)
    expected += " " + std::to_string(i);
  EXPECT_EQ(polylines, points.size() >= 2 ? std::vector<std::string>{expected} : std::vector<std::string>{});
}

/// Checks a polyline in the tool's PLY: ASCII, a vertex element with the points and an edge
/// element between consecutive points.
inline void expect_ply_polyline(const std::string& text, const std::vector<Point>& points)
{
  const std::size_t n = points.size();
  ASSERT_GE(n, 1u);
  const std::vector<std::string> lines = lines_of(text);
  const auto end = std::find(lines.begin(), lines.end(), "end_header");
  ASSERT_NE(end, lines.end());
  const std::vector<std::string> header(lines.begin(), end);
  ASSERT_GE(header.size(), 2u);
  EXPECT_EQ(header[0], "ply");
  EXPECT_EQ(header[1], "format ascii 1.0");
  const auto has = [&](const std::string& line) {
    return std::find(header.begin(), header.end(), line) != header.end();
  };
  EXPECT_TRUE(has("element vertex " + std::to_string(n)));
  EXPECT_TRUE(has("element edge " + std::to_string(n - 1)));
  for(const char* property : {"property double x", "property double y", "property double z",
                              "property int vertex1", "property int vertex2"})
    EXPECT_TRUE(has(property)) << property;
  const std::vector<std::string> body(end + 1, lines.end());
  ASSERT_EQ(body.size(), n + n - 1);
  std::string points_text;
  for(std::size_t i = 0; i < n; ++i)
    points_text += body[i] + "\n";
  EXPECT_EQ(parse_points(points_text), points);
  for(std::size_t i = 0; i + 1 < n; ++i)
    EXPECT_EQ(body[n + i], std::to_string(i) + " " + std::to_string(i + 1));
}

inline double distance_between(const Point& a, const Point& b) { return std::sqrt(CGAL::squared_distance(a, b)); }

/// The point of face `face` at barycentric coordinates `b` in the file's order of its vertices.
inline Point face_point(const Soup& soup, std::size_t face, const std::array<double, 3>& b)
{
  const auto p = soup.polygons[face];
  return CGAL::barycenter(soup.points[p[0]], b[0], soup.points[p[1]], b[1], soup.points[p[2]], b[2]);
}

/// The vertices of face f in the order of the library's barycentric coordinates.
inline std::array<std::size_t, 3> library_corners(const Mesh& mesh, Face_index f)
{
  std::array<std::size_t, 3> corners{};
  int k = 0;
  for(auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
    corners[k++] = mesh.source(h);
  return corners;
}

inline void expect_same_distances(const std::vector<double>& a, const std::vector<double>& b, double tolerance = 0)
{
  ASSERT_EQ(a.size(), b.size());
  for(std::size_t i = 0; i < a.size(); ++i) {
    if(std::isinf(a[i]) || std::isinf(b[i]))
      EXPECT_EQ(a[i], b[i]) << "vertex " << i;
    else
      EXPECT_NEAR(a[i], b[i], tolerance) << "vertex " << i;
  }
}

/// The message of the Tool_error that `f` throws; "" if it throws none.
template <class F>
std::string tool_error_of(F f)
{
  try {
    f();
  } catch(const tool::Tool_error& e) {
    return e.what();
  }
  return "";
}

/// The lines `id radius` of a samples file.
inline std::vector<std::pair<std::size_t, double>> parse_samples(const std::string& text)
{
  std::vector<std::pair<std::size_t, double>> samples;
  for(const std::string& line : lines_of(text)) {
    std::istringstream in(line);
    std::pair<std::size_t, double> s;
    std::string radius;
    in >> s.first >> radius;
    s.second = std::stod(radius);
    samples.push_back(s);
  }
  return samples;
}

class Tool : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name = std::string(info->test_suite_name()) + "." + info->name();
    std::replace(name.begin(), name.end(), '/', '_');
    m_dir = fs::canonical("/proc/self/exe").parent_path() / "test_tool_tmp" / name;
    fs::remove_all(m_dir);
    fs::create_directories(m_dir);
  }

  void TearDown() override
  {
    if(!HasFailure())
      fs::remove_all(m_dir);
  }

  fs::path path(const std::string& name) const { return m_dir / name; }

  void write(const std::string& name, const std::string& content) const
  {
    std::ofstream(path(name), std::ios::binary) << content;
  }

  /// Runs the tool with `args` (a shell fragment) inside the test's folder.
  Result run(const std::string& args) const
  {
    const std::string command = "cd '" + m_dir.string() + "' && '" + GEODESIC_TOOL + "' " + args +
                                " >.stdout 2>.stderr";
    const int status = std::system(command.c_str());
    Result r;
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = read_text(path(".stdout"));
    r.err = read_text(path(".stderr"));
    fs::remove(path(".stdout"));
    fs::remove(path(".stderr"));
    return r;
  }

  /// Runs the tool with `--output output` and expects success, with nothing on stdout and
  /// `err` on stderr; returns the text of `output`.
  std::string output_of(const std::string& args, const std::string& output, const std::string& err = "") const
  {
    const Result r = run(args + " --output " + output);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    EXPECT_EQ(r.out, "");
    EXPECT_EQ(r.err, err);
    return read_text(path(output));
  }

  /// Runs the tool on a mesh it repairs, as `output_of` does, expecting the line `note: <note>`
  /// on stderr; returns the distances of `output`.
  std::vector<double> repaired_distances(const std::string& args, const std::string& note,
                                         const std::string& output = "d.txt") const
  {
    return parse_distances(output_of(args, output, "note: " + note + "\n"));
  }

  /// Runs the tool as `output_of` does; returns the distances of `output`.
  std::vector<double> distances(const std::string& args, const std::string& output = "d.txt") const
  {
    return parse_distances(output_of(args, output));
  }

  /// Runs `geodesic path` as `output_of` does; returns the polyline of `output` (txt).
  std::vector<Point> path_points(const std::string& args, const std::string& output = "p.txt") const
  {
    return parse_points(output_of(args, output));
  }

  /// Makes the output `name` a folder, so that writing it fails: the tool must fail with an
  /// error and leave nothing but that folder.
  void expect_failed_write(const std::string& args, const std::string& name) const
  {
    fs::create_directory(path(name));
    const Result r = run(args);
    EXPECT_NE(r.exit_code, 0);
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_EQ(files(), std::set<std::string>{name});
    EXPECT_TRUE(fs::is_directory(path(name)));
  }

  std::set<std::string> files() const
  {
    std::set<std::string> names;
    for(const auto& entry : fs::directory_iterator(m_dir))
      names.insert(entry.path().filename().string());
    return names;
  }

  fs::path m_dir;
};

} // namespace tool_test

#endif // CGAL_EXT_TEST_TOOL_TOOL_TEST_SUPPORT_H
