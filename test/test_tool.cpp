// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of the command-line tool `geodesic`: its parts called directly (the checking of the
// command line, the writers), and the tool run as a separate process. Each test of the tool, or
// of its writers, works in its own folder under the build directory (kept when the test fails,
// for inspection).

#include "tool_error.h"
#include "tool_matrix.h"
#include "tool_mesh.h"
#include "tool_options.h"
#include "tool_output.h"
#include "tool_patterns.h"
#include "tool_text.h"

#include <CGAL_ext/Geodesics_3/Tolerances.h>
#include <CGAL_ext/Geodesics_3/polyline_length.h>
#include <CGAL_ext/geodesic_distances.h>

#include <CGAL/IO/PLY.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <CLI/CLI.hpp>

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

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

const std::string elephant = std::string(CGAL_EXT_DATA_DIR) + "/elephant.off";
const std::string mushroom = std::string(CGAL_EXT_DATA_DIR) + "/mushroom.off";
const double infinity = std::numeric_limits<double>::infinity();

struct Result
{
  int exit_code;
  std::string out;
  std::string err;
};

std::string read_text(const fs::path& path)
{
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  for(std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

/// Parses the tool's txt output: one number (or `inf`) per line, nothing else.
std::vector<double> parse_distances(const std::string& text)
{
  std::vector<double> d;
  for(const std::string& line : lines_of(text)) {
    char* end = nullptr;
    d.push_back(std::strtod(line.c_str(), &end));
    EXPECT_TRUE(!line.empty() && *end == '\0') << "not a number: '" << line << "'";
  }
  return d;
}

std::map<std::string, std::string> parse_key_values(const std::string& text)
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

/// Expects each of `keys` once in the --stats output `stats` parsed as `kv`, with a finite,
/// non-negative number.
void expect_non_negative_numbers(const std::map<std::string, std::string>& kv, const std::vector<std::string>& keys,
                                 const std::string& stats)
{
  for(const std::string& key : keys) {
    ASSERT_EQ(kv.count(key), 1u) << "missing " << key << " in:\n" << stats;
    char* end = nullptr;
    const double value = std::strtod(kv.at(key).c_str(), &end);
    EXPECT_TRUE(*end == '\0' && std::isfinite(value) && value >= 0) << key << "=" << kv.at(key);
  }
}

/// Parses a polyline of the tool: one `x y z` line per point, nothing else.
std::vector<Point> parse_points(const std::string& text)
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

void read_distances_ply(const fs::path& file, Distances_ply& ply)
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
void expect_obj_polyline(const std::string& text, const std::vector<Point>& points)
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
void expect_ply_polyline(const std::string& text, const std::vector<Point>& points)
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

double distance_between(const Point& a, const Point& b) { return std::sqrt(CGAL::squared_distance(a, b)); }

double bbox_diagonal(const Soup& soup)
{
  const CGAL::Bbox_3 box = CGAL::bbox_3(soup.points.begin(), soup.points.end());
  return std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                   CGAL::square(box.zmax() - box.zmin()));
}

/// The point of face `face` at barycentric coordinates `b` in the file's order of its vertices.
Point face_point(const Soup& soup, std::size_t face, const std::array<double, 3>& b)
{
  const auto p = soup.polygons[face];
  return CGAL::barycenter(soup.points[p[0]], b[0], soup.points[p[1]], b[1], soup.points[p[2]], b[2]);
}

/// The vertices of face f in the order of the library's barycentric coordinates.
std::array<std::size_t, 3> library_corners(const Mesh& mesh, Face_index f)
{
  std::array<std::size_t, 3> corners{};
  int k = 0;
  for(auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
    corners[k++] = mesh.source(h);
  return corners;
}

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

void expect_same_distances(const std::vector<double>& a, const std::vector<double>& b, double tolerance = 0)
{
  ASSERT_EQ(a.size(), b.size());
  for(std::size_t i = 0; i < a.size(); ++i) {
    if(std::isinf(a[i]) || std::isinf(b[i]))
      EXPECT_EQ(a[i], b[i]) << "vertex " << i;
    else
      EXPECT_NEAR(a[i], b[i], tolerance) << "vertex " << i;
  }
}

/// Equal within `relative` times the larger magnitude (so exactly equal at 0 and at infinity).
void expect_relatively_close(const std::vector<double>& a, const std::vector<double>& b, double relative)
{
  ASSERT_EQ(a.size(), b.size());
  for(std::size_t i = 0; i < a.size(); ++i) {
    if(std::isinf(a[i]) || std::isinf(b[i]))
      EXPECT_EQ(a[i], b[i]) << "vertex " << i;
    else
      EXPECT_NEAR(a[i], b[i], relative * std::max(std::abs(a[i]), std::abs(b[i]))) << "vertex " << i;
  }
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

// ---------------------------------------------------------------------------------------------
// The command line, checked without running the tool

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

TEST(Tool_options, surface_points_are_vertices_or_face_points)
{
  const tool::Surface_point v = tool::parse_surface_point("2774");
  ASSERT_TRUE(v.vertex);
  EXPECT_EQ(*v.vertex, 2774u);
  EXPECT_EQ(v.text, "2774");
  const tool::Surface_point f = tool::parse_surface_point("f:12:0.2:0.3:0.5", "target");
  EXPECT_FALSE(f.vertex);
  EXPECT_EQ(f.face, 12u);
  EXPECT_EQ(f.barycentric, (std::array<double, 3>{{0.2, 0.3, 0.5}}));
  EXPECT_EQ(f.text, "f:12:0.2:0.3:0.5");

  // several sources, in command-line order; a corner is a face point too
  const std::vector<tool::Surface_point> sources = tool::parse_sources({"7", "f:3:0:1:0", "0"});
  ASSERT_EQ(sources.size(), 3u);
  EXPECT_EQ(sources[0].vertex, std::optional<std::size_t>(7));
  EXPECT_EQ(sources[1].vertex, std::nullopt);
  EXPECT_EQ(sources[1].face, 3u);
  EXPECT_EQ(sources[1].barycentric, (std::array<double, 3>{{0., 1., 0.}}));
  EXPECT_EQ(sources[2].vertex, std::optional<std::size_t>(0));
}

// The tool refuses the face points the library would refuse, and no others.
TEST(Tool_options, barycentric_coordinates_sum_to_1_within_the_library_tolerance)
{
  const double tolerance = CGAL_ext::Geodesics_3::barycentric_sum_tolerance;
  const auto last_coordinate = [](double last) { return "f:0:0.25:0.25:" + tool::number_text(last); };
  for(const double off : {0.5 * tolerance, -0.5 * tolerance}) {
    const std::string text = last_coordinate(0.5 + off);
    EXPECT_EQ(tool_error_of([&] { tool::parse_surface_point(text); }), "") << text;
  }
  for(const double off : {2 * tolerance, -2 * tolerance}) {
    const std::string text = last_coordinate(0.5 + off);
    const std::string error = tool_error_of([&] { tool::parse_surface_point(text); });
    EXPECT_EQ(error.rfind("source '" + text + "': barycentric coordinates sum to " +
                            (off > 0 ? "1.000000002" : "0.999999998"),
                          0),
              0u)
      << error;
    const std::string end = ", not 1";
    EXPECT_TRUE(error.size() > end.size() && error.compare(error.size() - end.size(), end.size(), end) == 0)
      << error;
  }
}

struct Bad_point
{
  const char* text;
  const char* role;
  const char* message; // the whole error message
};

const Bad_point bad_points[] = {
  {"12x", "source", "source '12x': expected a vertex id or f:FACE:b0:b1:b2"},
  {"-1", "target", "target '-1': expected a vertex id or f:FACE:b0:b1:b2"},
  {"", "source", "source '': expected a vertex id or f:FACE:b0:b1:b2"},
  {"1.5", "source", "source '1.5': expected a vertex id or f:FACE:b0:b1:b2"},
  {"f:1:0.5:0.5", "source", "source 'f:1:0.5:0.5': expected f:FACE:b0:b1:b2"},
  {"f:1:0.2:0.3:0.5:", "target", "target 'f:1:0.2:0.3:0.5:': expected f:FACE:b0:b1:b2"},
  {"f:x:0.2:0.3:0.5", "source", "source 'f:x:0.2:0.3:0.5': expected f:FACE:b0:b1:b2"},
  {"f:-1:0.2:0.3:0.5", "source", "source 'f:-1:0.2:0.3:0.5': expected f:FACE:b0:b1:b2"},
  {"f:1:0.5:x:0.5", "source", "source 'f:1:0.5:x:0.5': barycentric coordinate 'x' is not a number"},
  {"f:1::0.5:0.5", "target", "target 'f:1::0.5:0.5': barycentric coordinate '' is not a number"},
  {"f:1:nan:0.5:0.5", "target", "target 'f:1:nan:0.5:0.5': barycentric coordinate 'nan' is not a number"},
  {"f:1:inf:0:0", "source", "source 'f:1:inf:0:0': barycentric coordinate 'inf' is not a number"},
  {"f:1:1.5:-0.5:0", "source", "source 'f:1:1.5:-0.5:0': barycentric coordinates must be non-negative"},
  {"f:1:0.5:0.5:0.5", "target", "target 'f:1:0.5:0.5:0.5': barycentric coordinates sum to 1.5, not 1"},
  {"f:1:0:0:0", "source", "source 'f:1:0:0:0': barycentric coordinates sum to 0, not 1"},
};

TEST(Tool_options, bad_surface_points_are_named)
{
  for(const Bad_point& c : bad_points)
    EXPECT_EQ(tool_error_of([&] { tool::parse_surface_point(c.text, c.role); }), c.message);
  EXPECT_EQ(tool_error_of([] { tool::parse_sources({"0", "f:1:0.5:0.5:0.5", "12x"}); }),
            "source 'f:1:0.5:0.5:0.5': barycentric coordinates sum to 1.5, not 1")
    << "the first bad source is named";
}

TEST(Tool_options, points_out_of_the_mesh_are_named)
{
  // the elephant's counts
  const auto error = [](const std::string& text, const char* role) {
    return tool_error_of(
      [&] { tool::check_surface_point_range(tool::parse_surface_point(text, role), 2775, 5558, role); });
  };
  EXPECT_EQ(error("2774", "source"), "");
  EXPECT_EQ(error("f:5557:1:0:0", "target"), "");
  EXPECT_EQ(error("2775", "source"), "source '2775': vertex 2775 is out of range (the mesh has 2775 vertices)");
  EXPECT_EQ(error("f:5558:0.2:0.3:0.5", "target"),
            "target 'f:5558:0.2:0.3:0.5': face 5558 is out of range (the mesh has 5558 faces)");
}

TEST(Tool_options, solver_defaults)
{
  const tool::Solver_choice distances = tool::solver_choice(tool::Distances_options().solver, false);
  // the exact parallel solver (this build has TBB): the same distances on any number of threads
  EXPECT_STREQ(distances.algorithm->name, tool::default_vertex_solver);
  EXPECT_STREQ(tool::default_vertex_solver, "pvtp");
  EXPECT_EQ(distances.lambda, tool::default_lambda);
  EXPECT_EQ(distances.threads, 0);
  EXPECT_EQ(distances.batch_size, CGAL_ext::default_batch_size);
  EXPECT_EQ(distances.max_distance, infinity);

  const tool::Solver_choice path = tool::solver_choice(tool::Path_options().solver, true);
  EXPECT_STREQ(path.algorithm->name, "pvtp");
  EXPECT_EQ(path.batch_size, CGAL_ext::default_batch_size);

  // the batch of PMMP is windows, that of the other batched solvers window lists
  tool::Solver_options pmmp;
  pmmp.algorithm = "pmmp";
  EXPECT_EQ(tool::solver_choice(pmmp, false).batch_size, CGAL_ext::default_window_batch_size);
  tool::Solver_options pvtp;
  pvtp.algorithm = "pvtp";
  EXPECT_EQ(tool::solver_choice(pvtp, false).batch_size, CGAL_ext::default_batch_size);
}

TEST(Tool_options, solver_options_are_taken_as_given)
{
  tool::Solver_options options;
  options.algorithm = "pavtp";
  options.lambda = 0.5;
  options.threads = 3;
  options.batch_size = 16;
  options.max_distance = 0;
  const tool::Solver_choice choice = tool::solver_choice(options, false);
  EXPECT_STREQ(choice.algorithm->name, "pavtp");
  EXPECT_TRUE(choice.algorithm->parallel);
  EXPECT_TRUE(choice.algorithm->approximate);
  EXPECT_EQ(choice.algorithm->library, CGAL_ext::VTP);
  EXPECT_EQ(choice.lambda, 0.5);
  EXPECT_EQ(choice.threads, 3);
  EXPECT_EQ(choice.batch_size, 16u);
  EXPECT_EQ(choice.max_distance, 0.);

  options = tool::Solver_options();
  options.algorithm = "pmmp";
  options.threads = 1;
  options.batch_size = 7;
  const tool::Solver_choice path = tool::solver_choice(options, true);
  EXPECT_STREQ(path.algorithm->name, "pmmp");
  EXPECT_EQ(path.algorithm->library, CGAL_ext::FWP_MMP);
  EXPECT_EQ(path.threads, 1);
  EXPECT_EQ(path.batch_size, 7u);
}

struct Bad_solver
{
  bool for_paths;
  tool::Solver_options options; // {algorithm, lambda, threads, batch_size, max_distance}
  const char* message;          // the whole error message
};

const double not_a_number = std::numeric_limits<double>::quiet_NaN();

const Bad_solver bad_solvers[] = {
  {false, {"dijkstra"}, "unknown algorithm 'dijkstra' (use vtp, pvtp, avtp, pavtp, fwp-mmp, mmp or pmmp)"},
  {true, {"dijkstra"}, "unknown algorithm 'dijkstra' (use vtp, pvtp, fwp-mmp, mmp or pmmp)"},
  {false, {"VTP"}, "unknown algorithm 'VTP' (use vtp, pvtp, avtp, pavtp, fwp-mmp, mmp or pmmp)"},
  {true, {"avtp"}, "--algorithm avtp is approximate: paths and Voronoi diagrams are exact (use vtp, pvtp, fwp-mmp, mmp or pmmp)"},
  {true, {"pavtp"}, "--algorithm pavtp is approximate: paths and Voronoi diagrams are exact (use vtp, pvtp, fwp-mmp, mmp or pmmp)"},
  {false, {"vtp", 8.}, "--lambda applies to avtp and pavtp only"},
  {false, {"pmmp", 8.}, "--lambda applies to avtp and pavtp only"},
  {false, {"avtp", 0.}, "--lambda must be a positive, finite number, got 0"},
  {false, {"pavtp", -1.}, "--lambda must be a positive, finite number, got -1"},
  {false, {"avtp", infinity}, "--lambda must be a positive, finite number, got inf"},
  {false, {"avtp", not_a_number}, "--lambda must be a positive, finite number, got nan"},
  {false, {"vtp", {}, 2}, "--threads applies to pvtp, pavtp and pmmp only"},
  {false, {"avtp", {}, 2}, "--threads applies to pvtp, pavtp and pmmp only"},
  {true, {"fwp-mmp", {}, 2}, "--threads applies to pvtp and pmmp only"},
  {false, {"pvtp", {}, 0}, "--threads must be a positive integer, got 0"},
  {true, {"pmmp", {}, -2}, "--threads must be a positive integer, got -2"},
  {false, {"mmp", {}, {}, 8}, "--batch-size applies to pvtp, avtp, pavtp and pmmp only"},
  {true, {"mmp", {}, {}, 8}, "--batch-size applies to pvtp and pmmp only"},
  {false, {"avtp", {}, {}, 0}, "--batch-size must be a positive integer, got 0"},
  {true, {"pmmp", {}, {}, -5}, "--batch-size must be a positive integer, got -5"},
  {false, {"vtp", {}, {}, {}, -1.}, "--max-distance must be a non-negative number, got -1"},
  {true, {"fwp-mmp", {}, {}, {}, not_a_number}, "--max-distance must be a non-negative number, got nan"},
};

TEST(Tool_options, bad_solver_options_are_named)
{
  for(const Bad_solver& c : bad_solvers)
    EXPECT_EQ(tool_error_of([&] { tool::solver_choice(c.options, c.for_paths); }), c.message)
      << (c.for_paths ? "path " : "distances ") << c.options.algorithm;
}

TEST(Tool_options, output_format_by_extension)
{
  EXPECT_EQ(tool::output_format("d.txt"), tool::Output_format::txt);
  EXPECT_EQ(tool::output_format("out/D.PLY"), tool::Output_format::ply);
  EXPECT_EQ(tool::output_format("p.txt", true), tool::Output_format::txt);
  EXPECT_EQ(tool::output_format("p.Obj", true), tool::Output_format::obj);
  EXPECT_EQ(tool::output_format("p.ply", true), tool::Output_format::ply);
  const auto error = [](const std::string& file, bool obj_allowed) {
    return tool_error_of([&] { tool::output_format(file, obj_allowed); });
  };
  EXPECT_EQ(error("d.obj", false), "unknown output format 'd.obj' (use .txt or .ply)");
  EXPECT_EQ(error("distances", false), "unknown output format 'distances' (use .txt or .ply)");
  EXPECT_EQ(error("d.txt.gz", false), "unknown output format 'd.txt.gz' (use .txt or .ply)");
  EXPECT_EQ(error("p.vtk", true), "unknown output format 'p.vtk' (use .txt, .obj or .ply)");
}

/// The subcommands declared as main() declares them, to parse a command line.
struct Command_line
{
  Command_line()
  {
    app.require_subcommand(0, 1);
    tool::add_distances_command(app, distances);
    tool::add_path_command(app, path);
  }

  /// CLI11's error for `arguments` (without the program name); "" if they parse.
  std::string parse(const std::string& arguments)
  {
    try {
      app.parse(arguments, false);
    } catch(const CLI::ParseError& e) {
      return e.what();
    }
    return "";
  }

  CLI::App app{"", "geodesic"};
  tool::Distances_options distances;
  tool::Path_options path;
};

TEST(Tool_command_line, distances_fills_its_options)
{
  Command_line defaults;
  ASSERT_EQ(defaults.parse("distances m.off --source 0"), "");
  const tool::Distances_options& d = defaults.distances;
  EXPECT_EQ(d.mesh, "m.off");
  EXPECT_EQ(d.sources, std::vector<std::string>{"0"});
  EXPECT_EQ(d.solver.algorithm, tool::default_vertex_solver);
  EXPECT_EQ(d.solver.lambda, std::nullopt);
  EXPECT_EQ(d.solver.threads, std::nullopt);
  EXPECT_EQ(d.solver.batch_size, std::nullopt);
  EXPECT_EQ(d.solver.max_distance, infinity);
  EXPECT_EQ(d.output, "");
  EXPECT_FALSE(d.stats);

  Command_line all;
  ASSERT_EQ(all.parse("distances m.off --source 0,f:1:0.2:0.3:0.5 --source 7 --algorithm pavtp --lambda 2 "
                      "--threads 3 --batch-size 16 --max-distance 0.5 --output d.ply --stats"),
            "");
  const tool::Distances_options& o = all.distances;
  EXPECT_EQ(o.sources, (std::vector<std::string>{"0", "f:1:0.2:0.3:0.5", "7"}));
  EXPECT_EQ(o.solver.algorithm, "pavtp");
  EXPECT_EQ(o.solver.lambda, std::optional<double>(2));
  EXPECT_EQ(o.solver.threads, std::optional<int>(3));
  EXPECT_EQ(o.solver.batch_size, std::optional<long long>(16));
  EXPECT_EQ(o.solver.max_distance, 0.5);
  EXPECT_EQ(o.output, "d.ply");
  EXPECT_TRUE(o.stats);
  EXPECT_EQ(all.path.mesh, "") << "the other subcommand's options are left alone";
}

TEST(Tool_command_line, path_fills_its_options)
{
  Command_line defaults;
  ASSERT_EQ(defaults.parse("path m.off --source 0 --target f:2:1:0:0"), "");
  EXPECT_EQ(defaults.path.mesh, "m.off");
  EXPECT_EQ(defaults.path.sources, std::vector<std::string>{"0"});
  EXPECT_EQ(defaults.path.target, "f:2:1:0:0");
  EXPECT_EQ(defaults.path.solver.algorithm, tool::default_vertex_solver);
  EXPECT_EQ(defaults.path.output, "");
  EXPECT_FALSE(defaults.path.stats);

  Command_line all;
  ASSERT_EQ(all.parse("path m.off --source 1,2 --target 5 --algorithm pmmp --threads 2 --batch-size 64 "
                      "--max-distance 3 --output p.obj --stats"),
            "");
  const tool::Path_options& p = all.path;
  EXPECT_EQ(p.sources, (std::vector<std::string>{"1", "2"}));
  EXPECT_EQ(p.target, "5");
  EXPECT_EQ(p.solver.algorithm, "pmmp");
  EXPECT_EQ(p.solver.threads, std::optional<int>(2));
  EXPECT_EQ(p.solver.batch_size, std::optional<long long>(64));
  EXPECT_EQ(p.solver.max_distance, 3.);
  EXPECT_EQ(p.output, "p.obj");
  EXPECT_TRUE(p.stats);
}

TEST(Tool_command_line, bad_command_lines_name_the_argument)
{
  const std::pair<const char*, const char*> bad[] = {
    // the command line, and what its error must name
    {"distances m.off --source 0 --threads 1.5", "--threads"},
    {"distances m.off --source 0 --batch-size many", "--batch-size"},
    {"distances m.off --source 0 --max-distance far", "--max-distance"},
    {"distances m.off --source 0 --lambda coarse", "--lambda"},
    {"distances m.off", "--source"},
    {"distances --source 0", "MESH"},
    {"distances m.off --source 0 --colour", "--colour"},
    {"distance m.off --source 0", "distance"},
    {"path m.off --source 0", "--target"},
    {"path m.off --target 1", "--source"},
    {"path m.off --source 0 --target 1 --target 2", "--target"},
    {"path m.off --source 0 --target 1 --lambda 8", "--lambda"},
  };
  for(const auto& [arguments, named] : bad) {
    const std::string error = Command_line().parse(arguments);
    EXPECT_NE(error.find(named), std::string::npos) << arguments << ": '" << error << "'";
  }
}

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

// ---------------------------------------------------------------------------------------------
// Results

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

// --stats for each solver: the common keys, and the solver's own.
struct Algorithm_case
{
  const char* name;
  std::string args;      // the solver options
  const char* algorithm; // the expected algorithm=
  const char* threads;   // the expected threads=, "" if absent, "*" for any positive count
  const char* lambda;    // the expected lambda=, "" if absent
};

void PrintTo(const Algorithm_case& c, std::ostream* os) { *os << c.name; }

const Algorithm_case algorithm_cases[] = {
  {"default", "", "pvtp", "*", ""},
  {"vtp", "--algorithm vtp", "vtp", "", ""},
  {"pvtp", "--algorithm pvtp --threads 2", "pvtp", "2", ""},
  {"pvtp_all_cores", "--algorithm pvtp --batch-size 64", "pvtp", "*", ""},
  {"avtp_default_lambda", "--algorithm avtp", "avtp", "", "8"},
  {"avtp", "--algorithm avtp --lambda 0.5", "avtp", "", "0.5"},
  {"pavtp", "--algorithm pavtp --lambda 2 --threads 3", "pavtp", "3", "2"},
  {"mmp", "--algorithm mmp", "mmp", "", ""},
  {"fwp_mmp", "--algorithm fwp-mmp", "fwp-mmp", "", ""},
  {"pmmp", "--algorithm pmmp --threads 2", "pmmp", "2", ""},
  {"pmmp_all_cores", "--algorithm pmmp --batch-size 64", "pmmp", "*", ""},
};

/// The solvers that keep their windows on the edges, and report on them.
bool is_mmp(const std::string& algorithm) { return algorithm == "mmp" || algorithm == "fwp-mmp" || algorithm == "pmmp"; }

/// The keys of the MMP family's statistics.
const std::vector<std::string> mmp_keys = {"windows_propagated", "windows_deferred", "windows_stored", "stored_window_bytes",
                                           "seconds_organization", "seconds_clipping", "seconds_pushing"};

/// The keys of what was repaired to make the file a mesh (all 0 for a clean file).
const std::vector<std::string> repair_keys = {"merged_points",     "removed_polygons",  "split_polygons",
                                              "triangulated_polygons", "reversed_polygons", "duplicated_points", "non_manifold_edges",
                                              "isolated_points"};

/// Expects every key of `repair_keys` to be 0 in the --stats output parsed as `kv`.
void expect_no_repair(const std::map<std::string, std::string>& kv)
{
  for(const std::string& key : repair_keys)
    EXPECT_EQ(kv.count(key) ? kv.at(key) : "missing", "0") << key;
}

class Stats : public Tool, public ::testing::WithParamInterface<Algorithm_case> {};

TEST_P(Stats, on_stderr)
{
  const Algorithm_case& c = GetParam();
  const Result r =
    run("distances '" + elephant + "' --source 0,f:3:0.2:0.2:0.6 " + c.args + " --stats --output d.txt");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::vector<double> d = parse_distances(read_text(path("d.txt")));
  const auto kv = parse_key_values(r.err);
  std::vector<std::string> keys = {"vertices", "faces", "sources", "seconds_read", "seconds_setup",
                                   "seconds_solve", "seconds_selection", "seconds_propagation",
                                   "seconds_merge", "windows_created", "peak_windows", "lists_propagated",
                                   "wavefront_resets", "peak_rss_mb", "max_distance"};
  if(*c.threads)
    keys.push_back("threads");
  if(*c.lambda)
    keys.push_back("lambda");
  if(is_mmp(c.algorithm))
    keys.insert(keys.end(), mmp_keys.begin(), mmp_keys.end());
  keys.insert(keys.end(), repair_keys.begin(), repair_keys.end());
  ASSERT_NO_FATAL_FAILURE(expect_non_negative_numbers(kv, keys, r.err));
  expect_no_repair(kv);
  ASSERT_EQ(kv.count("algorithm"), 1u) << r.err;
  EXPECT_EQ(kv.at("algorithm"), c.algorithm);
  EXPECT_EQ(kv.size(), keys.size() + 1) << r.err;
  EXPECT_EQ(kv.at("vertices"), "2775");
  EXPECT_EQ(kv.at("faces"), "5558");
  EXPECT_EQ(kv.at("sources"), "2");
  EXPECT_GT(std::stod(kv.at("windows_created")), 0);
  EXPECT_GT(std::stod(kv.at("peak_windows")), 0);
  if(is_mmp(c.algorithm)) {
    // the windows are kept for queries: all of those alive at the end, some of them clipped
    EXPECT_GT(std::stod(kv.at("windows_propagated")), 0);
    EXPECT_GT(std::stod(kv.at("windows_stored")), 0);
    EXPECT_LE(std::stod(kv.at("windows_stored")), std::stod(kv.at("windows_created")));
    EXPECT_GT(std::stod(kv.at("stored_window_bytes")), 0);
  } else {
    EXPECT_GT(std::stod(kv.at("lists_propagated")), 0);
  }
  EXPECT_GT(std::stod(kv.at("peak_rss_mb")), 1);
  EXPECT_EQ(std::stod(kv.at("max_distance")), *std::max_element(d.begin(), d.end()));
  if(std::string(c.threads) == "*")
    EXPECT_GE(std::stoi(kv.at("threads")), 1);
  else if(*c.threads)
    EXPECT_EQ(kv.at("threads"), c.threads);
  if(*c.lambda) {
    EXPECT_EQ(kv.at("lambda"), c.lambda);
    EXPECT_GT(std::stod(kv.at("wavefront_resets")), 0); // the elephant is many lambdas across
  } else {
    EXPECT_EQ(kv.at("wavefront_resets"), "0");
  }
}

INSTANTIATE_TEST_SUITE_P(Tool, Stats, ::testing::ValuesIn(algorithm_cases),
                         [](const ::testing::TestParamInfo<Algorithm_case>& info) { return info.param.name; });

// ---------------------------------------------------------------------------------------------
// The parallel and approximate solvers against the exact sequential one, on each mesh

class Solvers : public Tool, public ::testing::WithParamInterface<std::string>
{
protected:
  /// The distances from two sources (a vertex and a face point) with the solver options `args`.
  std::vector<double> solve(const std::string& args, const std::string& output = "d.txt") const
  {
    return distances("distances '" + GetParam() + "' --source 0,f:7:0.2:0.5:0.3 " + args, output);
  }

  /// The same, and the text of the output file.
  std::string solve_text(const std::string& args) const
  {
    solve(args, "t.txt");
    return read_text(path("t.txt"));
  }
};

TEST_P(Solvers, pvtp_is_vtp_on_any_number_of_threads)
{
  const std::vector<double> vtp = solve("--algorithm vtp");
  const std::string one = solve_text("--algorithm pvtp --threads 1");
  EXPECT_EQ(solve_text("--algorithm pvtp --threads 2"), one);
  EXPECT_EQ(solve_text("--algorithm pvtp --threads 4"), one);
  expect_relatively_close(parse_distances(one), vtp, 1e-12);
  expect_relatively_close(solve("--algorithm pvtp --threads 2 --batch-size 7"), vtp, 1e-12);
  expect_relatively_close(solve("--algorithm pvtp"), vtp, 1e-12);
}

TEST_P(Solvers, avtp_is_pavtp_and_never_below_vtp)
{
  const std::vector<double> vtp = solve("--algorithm vtp");
  const std::string avtp = solve_text("--algorithm avtp --lambda 8");
  EXPECT_EQ(solve_text("--algorithm pavtp --lambda 8 --threads 2"), avtp);
  EXPECT_EQ(solve_text("--algorithm avtp"), avtp) << "the default lambda is not 8";
  const std::vector<double> d = parse_distances(avtp);
  ASSERT_EQ(d.size(), vtp.size());
  std::size_t above = 0;
  for(std::size_t i = 0; i < d.size(); ++i) {
    EXPECT_GE(d[i], vtp[i] - 1e-12) << "vertex " << i;
    above += d[i] > vtp[i] + 1e-9;
  }
  EXPECT_GT(above, 0u) << "lambda 8 did not approximate anything";
}

TEST_P(Solvers, avtp_with_a_huge_lambda_is_vtp)
{
  const std::vector<double> vtp = solve("--algorithm vtp");
  expect_relatively_close(solve("--algorithm avtp --lambda 1e12"), vtp, 1e-12);
  expect_relatively_close(solve("--algorithm pavtp --lambda 1e12 --threads 2"), vtp, 1e-12);
}

// MMP, FWP-MMP and PMMP keep windows for paths; their distances are VTP's up to round-off.
TEST_P(Solvers, mmp_family_is_vtp)
{
  const std::vector<double> vtp = solve("--algorithm vtp");
  const double tolerance = 1e-12 * bbox_diagonal(read_soup(GetParam()));
  for(const char* args : {"--algorithm mmp", "--algorithm fwp-mmp", "--algorithm pmmp",
                          "--algorithm pmmp --threads 2 --batch-size 7"}) {
    SCOPED_TRACE(args);
    expect_same_distances(solve(args), vtp, tolerance);
  }
}

TEST_P(Solvers, pmmp_is_the_same_on_any_number_of_threads)
{
  const std::string one = solve_text("--algorithm pmmp --threads 1");
  EXPECT_EQ(solve_text("--algorithm pmmp --threads 2"), one);
  // the batch size orders the windows, hence the round-off (batch 7 differs in the last digits
  // on both meshes today): 1024 is the default
  EXPECT_EQ(solve_text("--algorithm pmmp --threads 2 --batch-size 1024"), one);
}

INSTANTIATE_TEST_SUITE_P(Tool, Solvers, ::testing::Values(elephant, mushroom),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           return fs::path(info.param).stem().string();
                         });

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

TEST_F(Tool, path_stats_on_stderr)
{
  const Soup soup = read_soup(elephant);
  const std::vector<double> from_0 = distances("distances '" + elephant + "' --source 0");
  const std::vector<double> from_2000 = distances("distances '" + elephant + "' --source 2000");
  ASSERT_LT(from_2000[1000], from_0[1000]) << "the test wants the second source to be the nearest";
  for(const std::string& algorithm : {"fwp-mmp", "mmp", "pmmp", "vtp", "pvtp"}) {
    SCOPED_TRACE(algorithm);
    const bool parallel = algorithm == "pmmp" || algorithm == "pvtp";
    const Result r = run("path '" + elephant + "' --source 0 --source 2000 --target 1000 --algorithm " + algorithm +
                         (parallel ? " --threads 2" : "") + " --stats --output p.txt");
    ASSERT_EQ(r.exit_code, 0) << r.err;
    const std::vector<Point> p = parse_points(read_text(path("p.txt")));
    ASSERT_GE(p.size(), 2u);
    EXPECT_EQ(p.front(), soup.points[2000]);
    EXPECT_EQ(p.back(), soup.points[1000]);

    const auto kv = parse_key_values(r.err);
    std::vector<std::string> keys = {"vertices", "faces", "sources", "seconds_read", "seconds_build",
                                     "seconds_query", "seconds_setup", "seconds_solve", "seconds_selection",
                                     "seconds_propagation", "seconds_merge", "windows_created", "peak_windows",
                                     "lists_propagated", "wavefront_resets", "peak_rss_mb", "length",
                                     "distance", "points", "nearest_source"};
    if(is_mmp(algorithm))
      keys.insert(keys.end(), mmp_keys.begin(), mmp_keys.end());
    else // VTP's windows are kept too, and reported so
      keys.insert(keys.end(), {"windows_stored", "stored_window_bytes"});
    keys.insert(keys.end(), repair_keys.begin(), repair_keys.end());
    if(parallel)
      keys.push_back("threads");
    ASSERT_NO_FATAL_FAILURE(expect_non_negative_numbers(kv, keys, r.err));
    expect_no_repair(kv);
    EXPECT_EQ(kv.size(), keys.size() + 1) << r.err;
    EXPECT_EQ(kv.at("algorithm"), algorithm);
    if(parallel)
      EXPECT_EQ(kv.at("threads"), "2");
    EXPECT_EQ(kv.at("vertices"), "2775");
    EXPECT_EQ(kv.at("faces"), "5558");
    EXPECT_EQ(kv.at("sources"), "2");
    EXPECT_EQ(kv.at("nearest_source"), "1");
    EXPECT_EQ(kv.at("points"), std::to_string(p.size()));
    const double length = std::stod(kv.at("length")), distance = std::stod(kv.at("distance"));
    EXPECT_NEAR(length, distance, 1e-9 * distance);
    EXPECT_NEAR(distance, from_2000[1000], 1e-9 * distance);
    EXPECT_NEAR(length, polyline_length(p), 1e-12 * length);
    EXPECT_GT(std::stod(kv.at("windows_stored")), 0);
  }
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

TEST_F(Tool, path_failed_write_leaves_no_file)
{
  expect_failed_write("path '" + elephant + "' --source 0 --target 5 --output p.obj", "p.obj");
}

TEST_F(Tool, no_arguments)
{
  const Result r = run("");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_EQ(r.err, "error: a subcommand is required (see geodesic --help)\n");
}

TEST_F(Tool, help)
{
  for(const std::string& args : {"--help", "distances --help", "path --help"}) {
    const Result r = run(args);
    EXPECT_EQ(r.exit_code, 0) << args;
    EXPECT_NE(r.out.find(args == "path --help" ? "path" : "distances"), std::string::npos) << args;
    EXPECT_NE(r.out.find(args == "--help" ? "SUBCOMMAND" : "--max-distance"), std::string::npos) << r.out;
  }
  const std::string help = run("distances --help").out;
  for(const char* piece : {"--algorithm", "pavtp", "--lambda", "default: 8", "--threads", "--batch-size"})
    EXPECT_NE(help.find(piece), std::string::npos) << piece << " not in:\n" << help;
  const std::string path_help = run("path --help").out;
  for(const char* piece : {"--source", "--target", "--algorithm", "fwp-mmp", "pmmp", "--threads", "--batch-size",
                           "1024", "--max-distance", ".obj", "--stats"})
    EXPECT_NE(path_help.find(piece), std::string::npos) << piece << " not in:\n" << path_help;
  EXPECT_EQ(path_help.find("--lambda"), std::string::npos) << path_help;
  EXPECT_NE(run("--help").out.find("path"), std::string::npos);
}

// An error while writing (here the target is a folder) leaves no temporary file behind.
TEST_F(Tool, failed_write_leaves_no_file)
{
  expect_failed_write("distances '" + elephant + "' --source 0 --output d.txt", "d.txt");
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

// ---------------------------------------------------------------------------------------------
// Bad input: one line `error: ...` on stderr, a non-zero exit code, and no output file.

struct Bad_case
{
  const char* name;
  std::string args;   // the output option is appended
  const char* output; // the output file, which must not appear
  const char* message; // a piece of the expected error message
};

void PrintTo(const Bad_case& c, std::ostream* os) { *os << c.name; }

std::string binary_ply_with_nan()
{
  std::string ply = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\n"
                    "property double y\nproperty double z\nelement face 1\n"
                    "property list uchar int vertex_indices\nend_header\n";
  const double xyz[9] = {0, 0, 0, 1, 0, 0, 0, std::nan(""), 0};
  ply.append(reinterpret_cast<const char*>(xyz), sizeof(xyz));
  const unsigned char n = 3;
  const std::int32_t ids[3] = {0, 1, 2};
  ply.append(reinterpret_cast<const char*>(&n), 1);
  ply.append(reinterpret_cast<const char*>(ids), sizeof(ids));
  return ply;
}

const std::string triangle_points = "0 0 0\n1 0 0\n0 1 0\n";

const std::vector<std::pair<std::string, std::string>> bad_files = {
  {"tri.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
              "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"},
  {"far.txt", "0\n99999\n"},
  {"apart.txt", "# two vertices far apart\n0\n1500\n"},
  {"quad.off", "OFF\n4 1 0\n" + triangle_points + "1 1 0\n4 0 1 3 2\n"},
  {"nan.ply", binary_ply_with_nan()},
  {"nan.off", "OFF\n3 1 0\n0 0 0\n1 0 nan\n0 1 0\n3 0 1 2\n"},
  {"empty.off", ""},
  {"no_faces.off", "OFF\n3 0 0\n" + triangle_points},
  {"flat.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 1 2\n"},
  {"flat_quad.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n4 0 1 2 3\n"},
  // point 3 is point 0 again: the only triangle has 2 distinct points
  {"segment.off", "OFF\n4 1 0\n" + triangle_points + "0 0 0\n3 0 1 3\n"},
  {"with_segment.off", "OFF\n4 2 0\n" + triangle_points + "0 0 0\n3 0 1 3\n3 0 1 2\n"},
  {"out_of_range.off", "OFF\n3 1 0\n" + triangle_points + "3 0 1 7\n"},
  {"empty.stl", "solid x\nendsolid x\n"},
  {"mesh.vtk", "# vtk DataFile Version 2.0\n"},
  {"triangle.off", "OFF\n3 1 0\n" + triangle_points + "3 0 1 2\n"},
  // point 3 in no face
  {"isolated.off", "OFF\n4 1 0\n" + triangle_points + "5 5 5\n3 0 1 2\n"},
  // two triangles that share nothing: two connected components
  {"two.off", "OFF\n6 2 0\n" + triangle_points + "10 0 0\n11 0 0\n10 1 0\n3 0 1 2\n3 3 4 5\n"},
  // a unit square and point 4 = point 2, joined by a zero-length edge: 5 vertices, 4 distinct points
  {"needle.off", "OFF\n5 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n1 1 0\n3 0 1 2\n3 0 2 3\n3 1 4 2\n"},
  // a soup of two triangles: points 3 and 4 repeat points 0 and 2, and are merged with them
  {"soup.off", "OFF\n6 2 0\n0 0 0\n1 0 0\n1 1 0\n0 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 3 4 5\n"},
};

const std::string E = "distances '" + elephant + "'";
const std::string P = "path '" + elephant + "'";
const std::string S = "sample '" + elephant + "'";
const std::string V = "voronoi '" + elephant + "'";

const Bad_case bad_cases[] = {
  {"face_point_on_a_quad", "distances quad.off --source f:0:0.2:0.3:0.5", "d.txt",
   "error: source 'f:0:0.2:0.3:0.5': face 0 of the file is not a triangle of the surface (it has 4 vertices)"},
  {"nan_coordinate", "distances nan.ply --source 0", "d.ply", "error: point 2 has a non-finite coordinate (0, nan, 0)"},
  {"nan_text", "distances nan.off --source 0", "d.txt", "cannot read mesh 'nan.off'"},
  {"empty_file", "distances empty.off --source 0", "d.txt", "empty.off"},
  {"point_cloud", "distances no_faces.off --source 0", "d.txt",
   "error: no faces: the soup has 3 points and no polygon (a point cloud)"},
  {"empty_stl", "distances empty.stl --source 0", "d.txt", "error: no faces: the soup is empty"},
  {"nothing_left", "distances segment.off --source 0", "d.ply",
   "error: no faces left: the only polygon has fewer than 3 distinct points"},
  {"index_out_of_range", "distances out_of_range.off --source 0", "d.txt", "cannot read mesh 'out_of_range.off'"},
  {"degenerate_triangle", "distances flat.off --source 0", "d.txt", "degenerate"},
  {"flat_quad", "distances flat_quad.off --source 0", "d.txt",
   "error: polygon 0 (4 points) cannot be triangulated without new points"},
  {"isolated_source", "distances isolated.off --source 3", "d.txt",
   "error: source '3': vertex 3 is in no face of the mesh, so it reaches no other vertex"},
  {"isolated_sources", "distances isolated.off --source 3,3", "d.ply", "error: every source is a vertex in no face"},
  {"isolated_source_with_a_face_point", "distances isolated.off --source 3,f:0:1:0:0", "d.txt",
   "source '3': an isolated vertex cannot be mixed with face-point sources"},
  {"missing_file", "distances missing.off --source 0", "d.txt", "cannot read mesh 'missing.off'"},
  {"unknown_mesh_format", "distances mesh.vtk --source 0", "d.txt", "cannot read mesh 'mesh.vtk'"},
  {"unknown_output_format", "distances triangle.off --source 0", "d.vtk", "unknown output format"},
  {"vertex_out_of_range", E + " --source 0,2775", "d.txt", "source '2775'"},
  {"face_out_of_range", E + " --source f:5558:0.2:0.3:0.5", "d.ply", "source 'f:5558:0.2:0.3:0.5'"},
  {"negative_vertex", E + " --source=-1", "d.txt", "source '-1'"},
  {"malformed_vertex", E + " --source 12x", "d.txt", "source '12x'"},
  {"face_point_too_short", E + " --source f:1:0.5:0.5", "d.txt", "source 'f:1:0.5:0.5'"},
  {"face_point_not_a_number", E + " --source f:1:0.5:x:0.5", "d.txt", "source 'f:1:0.5:x:0.5'"},
  {"face_point_nan", E + " --source f:1:nan:0.5:0.5", "d.txt", "source 'f:1:nan:0.5:0.5'"},
  {"face_point_negative", E + " --source f:1:1.5:-0.5:0", "d.txt", "source 'f:1:1.5:-0.5:0'"},
  {"face_point_bad_sum", E + " --source f:1:0.5:0.5:0.5", "d.txt", "source 'f:1:0.5:0.5:0.5'"},
  {"negative_max_distance", E + " --source 0 --max-distance=-1", "d.txt", "max-distance"},
  {"non_numeric_max_distance", E + " --source 0 --max-distance far", "d.txt", "max-distance"},
  {"unknown_option", E + " --source 0 --colour", "d.txt", "--colour"},
  {"unknown_subcommand", "distance '" + elephant + "' --source 0", "d.txt", "distance"},
  {"no_subcommand", "", "d.txt", "not expected"},
  {"missing_source", E, "d.txt", "--source"},
  {"missing_mesh", "distances --source 0", "d.txt", "MESH"},
  {"unknown_algorithm", E + " --source 0 --algorithm dijkstra", "d.txt", "unknown algorithm 'dijkstra'"},
  {"lambda_zero", E + " --source 0 --algorithm avtp --lambda 0", "d.txt", "--lambda must be a positive"},
  {"lambda_negative", E + " --source 0 --algorithm pavtp --lambda -1", "d.txt", "got -1"},
  {"lambda_nan", E + " --source 0 --algorithm avtp --lambda nan", "d.txt", "got nan"},
  {"lambda_infinite", E + " --source 0 --algorithm avtp --lambda inf", "d.ply", "got inf"},
  {"lambda_not_a_number", E + " --source 0 --algorithm avtp --lambda coarse", "d.txt", "--lambda"},
  {"lambda_with_vtp", E + " --source 0 --lambda 8 --algorithm vtp", "d.txt", "error: --lambda applies to avtp and pavtp only"},
  {"lambda_with_pvtp", E + " --source 0 --algorithm pvtp --lambda 8", "d.txt", "--lambda applies to"},
  {"threads_zero", E + " --source 0 --algorithm pvtp --threads 0", "d.txt", "--threads must be a positive integer"},
  {"threads_negative", E + " --source 0 --algorithm pavtp --threads -2", "d.txt", "got -2"},
  {"threads_not_a_number", E + " --source 0 --algorithm pvtp --threads x", "d.txt", "--threads"},
  {"threads_fraction", E + " --source 0 --algorithm pvtp --threads 1.5", "d.txt", "--threads"},
  {"threads_with_vtp", E + " --source 0 --threads 2 --algorithm vtp", "d.txt", "error: --threads applies to pvtp, pavtp and pmmp only"},
  {"threads_with_avtp", E + " --source 0 --algorithm avtp --threads 2", "d.ply", "--threads applies to"},
  {"batch_size_zero", E + " --source 0 --algorithm pvtp --batch-size 0", "d.txt", "--batch-size must be a positive integer"},
  {"batch_size_negative", E + " --source 0 --algorithm pvtp --batch-size=-5", "d.txt", "got -5"},
  {"batch_size_with_vtp", E + " --source 0 --batch-size 8 --algorithm vtp", "d.txt", "--batch-size applies to pvtp, avtp, pavtp and pmmp only"},
  {"lambda_with_mmp", E + " --source 0 --algorithm mmp --lambda 8", "d.txt", "error: --lambda applies to avtp and pavtp only"},
  {"lambda_with_fwp_mmp", E + " --source 0 --algorithm fwp-mmp --lambda 8", "d.txt", "--lambda applies to"},
  {"lambda_with_pmmp", E + " --source 0 --algorithm pmmp --lambda 8", "d.ply", "--lambda applies to"},
  {"threads_with_mmp", E + " --source 0 --algorithm mmp --threads 2", "d.txt", "--threads applies to"},
  {"threads_with_fwp_mmp", E + " --source 0 --algorithm fwp-mmp --threads 2", "d.txt", "--threads applies to"},
  {"pmmp_threads_zero", E + " --source 0 --algorithm pmmp --threads 0", "d.txt", "--threads must be a positive integer"},
  {"batch_size_with_mmp", E + " --source 0 --algorithm mmp --batch-size 8", "d.txt", "--batch-size applies to"},
  {"batch_size_with_fwp_mmp", E + " --source 0 --algorithm fwp-mmp --batch-size 8", "d.txt", "--batch-size applies to"},
  {"pmmp_batch_size_zero", E + " --source 0 --algorithm pmmp --batch-size 0", "d.txt", "--batch-size must be a positive integer"},
  {"unknown_algorithm_lists_mmp", E + " --source 0 --algorithm MMP", "d.txt", "(use vtp, pvtp, avtp, pavtp, fwp-mmp, mmp or pmmp)"},
  {"obj_distances", "distances triangle.off --source 0", "d.obj", "unknown output format 'd.obj' (use .txt or .ply)"},
  // geodesic path
  {"path_unreachable_vertex", "path two.off --source 0 --target 4", "p.txt", "error: target '4' is not reached by any source"},
  {"path_unreachable_face_point", "path two.off --source f:0:0.2:0.3:0.5,1 --target f:1:0.2:0.3:0.5", "p.obj",
   "target 'f:1:0.2:0.3:0.5' is not reached by any source"},
  {"path_unreachable_with_pmmp", "path two.off --source 3 --target 2 --algorithm pmmp --threads 2", "p.ply", "is not reached"},
  {"path_beyond_max_distance", P + " --source 0 --target 1500 --max-distance 0.1", "p.txt", "beyond --max-distance"},
  {"path_target_out_of_range", P + " --source 0 --target 2775", "p.txt", "target '2775': vertex 2775 is out of range"},
  {"path_target_face_out_of_range", P + " --source 0 --target f:5558:0.2:0.3:0.5", "p.ply", "target 'f:5558:0.2:0.3:0.5'"},
  {"path_target_bad_sum", P + " --source 0 --target f:1:0.5:0.5:0.5", "p.txt", "target 'f:1:0.5:0.5:0.5': barycentric coordinates sum to"},
  {"path_target_negative", P + " --source 0 --target f:1:1.5:-0.5:0", "p.obj", "target 'f:1:1.5:-0.5:0'"},
  {"path_target_nan", P + " --source 0 --target f:1:nan:0.5:0.5", "p.txt", "target 'f:1:nan:0.5:0.5'"},
  {"path_target_too_short", P + " --source 0 --target f:1:0.5:0.5", "p.txt", "target 'f:1:0.5:0.5'"},
  {"path_target_malformed", P + " --source 0 --target 12x", "p.txt", "target '12x'"},
  {"path_target_negative_vertex", P + " --source 0 --target=-1", "p.txt", "target '-1'"},
  {"path_missing_target", P + " --source 0", "p.txt", "--target"},
  {"path_two_targets", P + " --source 0 --target 1 --target 2", "p.txt", "--target"},
  {"path_missing_source", P + " --target 5", "p.txt", "--source"},
  {"path_source_out_of_range", P + " --source 0,2775 --target 5", "p.txt", "source '2775'"},
  {"path_source_bad_barycentric", P + " --source f:1:0.5:0.5:0.5 --target 5", "p.txt", "source 'f:1:0.5:0.5:0.5'"},
  {"path_missing_mesh", "path --source 0 --target 5", "p.txt", "MESH"},
  {"path_with_avtp", P + " --source 0 --target 5 --algorithm avtp", "p.txt", "--algorithm avtp is approximate"},
  {"path_with_pavtp", P + " --source 0 --target 5 --algorithm pavtp", "p.txt",
   "paths and Voronoi diagrams are exact (use vtp, pvtp, fwp-mmp, mmp or pmmp)"},
  {"path_unknown_algorithm", P + " --source 0 --target 5 --algorithm dijkstra", "p.txt",
   "unknown algorithm 'dijkstra' (use vtp, pvtp, fwp-mmp, mmp or pmmp)"},
  {"path_lambda", P + " --source 0 --target 5 --lambda 8", "p.txt", "--lambda"},
  {"path_lambda_with_mmp", P + " --source 0 --target 5 --algorithm mmp --lambda 8", "p.txt", "--lambda"},
  {"path_threads_with_fwp_mmp", P + " --source 0 --target 5 --algorithm fwp-mmp --threads 2", "p.txt", "error: --threads applies to pvtp and pmmp only"},
  {"path_threads_zero", P + " --source 0 --target 5 --algorithm pmmp --threads 0", "p.txt", "--threads must be a positive integer"},
  {"path_batch_size_with_mmp", P + " --source 0 --target 5 --algorithm mmp --batch-size 8", "p.txt",
   "error: --batch-size applies to pvtp and pmmp only"},
  {"path_batch_size_zero", P + " --source 0 --target 5 --algorithm pmmp --batch-size 0", "p.txt", "--batch-size must be"},
  {"path_negative_max_distance", P + " --source 0 --target 5 --max-distance=-1", "p.txt", "max-distance"},
  {"path_unknown_output_format", P + " --source 0 --target 5", "p.vtk", "unknown output format 'p.vtk' (use .txt, .obj or .ply)"},
  {"path_face_point_on_a_quad", "path quad.off --source 0 --target f:0:1:0:0", "p.txt",
   "error: target 'f:0:1:0:0': face 0 of the file is not a triangle of the surface (it has 4 vertices)"},
  {"path_source_on_a_quad", "path quad.off --source f:0:1:0:0 --target 2", "p.obj", "source 'f:0:1:0:0': face 0"},
  {"path_isolated_target", "path isolated.off --source 0 --target 3", "p.txt", "target '3' is not reached"},
  {"path_point_cloud", "path no_faces.off --source 0 --target 1", "p.txt", "a point cloud"},
  {"path_nan_coordinate", "path nan.ply --source 0 --target 1", "p.ply", "point 2 has a non-finite coordinate"},
  {"path_degenerate_triangle", "path flat.off --source 0 --target 1", "p.txt", "degenerate"},
  {"path_missing_file", "path missing.off --source 0 --target 1", "p.txt", "cannot read mesh 'missing.off'"},
  {"labels_obj", E + " --source 0 --labels l.obj", "d.txt", "unknown output format 'l.obj'"},
  {"labels_same_file", E + " --source 0 --labels d.txt", "d.txt", "--output and --labels name the same file 'd.txt'"},
  {"sample_no_count", S, "s.txt", "give --count, --radius, or both"},
  {"sample_count_zero", S + " --count 0", "s.txt", "--count must be at least 1, got 0"},
  {"sample_count_above_vertices", S + " --count 2776", "s.txt", "--count 2776 is more than the 2775 vertices"},
  {"sample_radius_zero", S + " --radius 0", "s.txt", "--radius must be positive, got 0"},
  {"sample_first_out_of_range", S + " --count 3 --first 2775", "s.txt", "first sample '2775'"},
  {"sample_first_face_point", S + " --count 3 --first f:1:0.2:0.3:0.5", "s.txt", "give a vertex id"},
  {"sample_first_twice", S + " --count 3 --first 4,9,4", "s.txt", "first sample '4' is given twice"},
  {"sample_first_more_than_count", S + " --count 2 --first 4,9,5", "s.txt", "--first gives 3 samples, more than --count 2"},
  {"sample_initial_out_of_range", S + " --count 3 --first 4,2775", "s.txt", "first sample '2775'"},
  {"sample_initial_one_point", "sample needle.off --count 3 --first 2,4", "s.txt", "2 and 4"},
  {"sample_initial_merged_points", "sample soup.off --count 3 --first 0,3", "s.txt",
   "first samples '0' and '3' are one vertex of the mesh"},
  {"sample_with_mmp", S + " --count 3 --algorithm fwp-mmp", "s.txt", "sampling runs vtp, pvtp, avtp or pavtp"},
  {"sample_ply_output", S + " --count 3", "s.ply", "the samples are written as .txt"},
  {"sample_labels_same_file", S + " --count 3 --labels s.txt", "s.txt", "name the same file 's.txt'"},
  {"sample_more_than_distinct", "sample needle.off --count 5", "s.txt", "after 4 every vertex is a sample or at distance 0"},
  {"sample_point_cloud", "sample no_faces.off --count 1", "s.txt", "a point cloud"},
  {"voronoi_cells_obj", V + " --source 0,100", "c.obj", "unknown output format 'c.obj'"},
  {"voronoi_bisectors_ply", V + " --source 0,100 --bisectors b.ply", "c.txt", "--bisectors 'b.ply': use .obj or .txt"},
  {"voronoi_dual_txt", V + " --source 0,100 --dual d.txt", "c.txt", "the dual graph is written as .obj"},
  {"voronoi_with_avtp", V + " --source 0,100 --algorithm avtp", "c.txt",
   "--algorithm avtp is approximate: paths and Voronoi diagrams are exact (use vtp, pvtp, fwp-mmp, mmp or pmmp)"},
  {"voronoi_same_files", V + " --source 0,100 --bisectors c.txt", "c.txt", "name the same file 'c.txt'"},
  {"voronoi_source_out_of_range", V + " --source 0,2775", "c.txt", "source '2775'"},
  {"voronoi_missing_source", V, "c.txt", "--source"},
  {"patterns_no_patch", "patterns '" + elephant + "'", "p.json", "mark the pattern"},
  {"patterns_radius_zero", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0", "p.json",
   "--patch-radius must be positive"},
  {"patterns_center_out_of_range", "patterns '" + elephant + "' --patch-center 2775 --patch-radius 0.1", "p.json",
   "patch centre '2775'"},
  {"patterns_empty_scales", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0.1 --scales 2:1", "p.json",
   "empty scale range"},
  {"patterns_bad_scales", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0.1 --scales 2", "p.json",
   "expected A:B"},
  {"patterns_txt_output", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0.1", "p.txt",
   "the instances are written as .json"},
  {"patterns_missing_list", "patterns '" + elephant + "' --patch-vertices missing.txt", "p.json",
   "cannot read --patch-vertices 'missing.txt'"},
  {"patterns_list_out_of_range", "patterns '" + elephant + "' --patch-vertices far.txt", "p.json",
   "far.txt line 2: vertex 99999 is out of range"},
  {"patterns_list_not_connected", "patterns '" + elephant + "' --patch-vertices apart.txt", "p.json",
   "not connected"},
  {"patterns_stroke_out_of_range", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0.1 --scales 1:2 --stroke 0,9999",
   "p.json", "--stroke vertex 9999 is out of range"},
  {"patterns_stroke_outside_the_patch", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0.05 --scales 1:2 --stroke 2000,1000",
   "p.json", "the stroke must start in the marked instance"},
  {"patterns_property_of_an_off", "patterns '" + elephant + "' --patch-property selected", "p.json",
   "--patch-property reads a per-vertex property of a .ply mesh"},
  {"patterns_property_missing", "patterns tri.ply --patch-property selected", "p.json",
   "'tri.ply' has no per-vertex property 'selected'"},
  {"patterns_radius_beyond_the_mesh", "patterns '" + elephant + "' --patch-center 0 --patch-radius 100", "p.json",
   "larger than the mesh"},
  {"patterns_negative_lambda", "patterns '" + elephant + "' --patch-center 0 --patch-radius 0.1 --lambda -1", "p.json",
   "approximation must be 0 (exact) or positive"},
};

class Bad_input : public Tool, public ::testing::WithParamInterface<Bad_case>
{
protected:
  void SetUp() override
  {
    Tool::SetUp();
    for(const auto& [name, content] : bad_files)
      write(name, content);
  }

  void expect_error(const Result& r) const
  {
    const Bad_case& c = GetParam();
    EXPECT_NE(r.exit_code, 0);
    EXPECT_EQ(r.err.rfind("error: ", 0), 0u) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "not one line: " << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << "expected '" << c.message << "' in: " << r.err;
    EXPECT_EQ(r.out, "");
  }
};

TEST_P(Bad_input, fails_cleanly)
{
  const Bad_case& c = GetParam();
  const std::set<std::string> before = files();
  const std::string args = c.args + " --output " + c.output;
  expect_error(run(args));
  EXPECT_EQ(files(), before) << "the output file or a temporary file was left behind";

  // an existing output file is not touched
  write(c.output, "previous content\n");
  expect_error(run(args));
  EXPECT_EQ(read_text(path(c.output)), "previous content\n");
  std::set<std::string> with_output = before;
  with_output.insert(c.output);
  EXPECT_EQ(files(), with_output);
}

INSTANTIATE_TEST_SUITE_P(Tool, Bad_input, ::testing::ValuesIn(bad_cases),
                         [](const ::testing::TestParamInfo<Bad_case>& info) { return info.param.name; });

// The control case of the table above: the same small files do work when they are good.
TEST_F(Tool, a_good_triangle_works)
{
  write("triangle.off", "OFF\n3 1 0\n" + triangle_points + "3 0 1 2\n");
  const std::vector<double> d = distances("distances triangle.off --source f:0:0:0.5:0.5");
  ASSERT_EQ(d.size(), 3u);
  EXPECT_NEAR(d[0], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(d[1], std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(d[2], std::sqrt(0.5), 1e-15);
}

// ---------------------------------------------------------------------------------------------
// geodesic sample

/// The lines `id radius` of a samples file.
std::vector<std::pair<std::size_t, double>> parse_samples(const std::string& text)
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

// With no --algorithm, distances and sample run the exact parallel solver: the same output for
// every number of threads (the file's bytes), and VTP's distances and samples to round-off.
TEST_F(Tool, default_solver_is_exact_and_the_same_on_any_number_of_threads)
{
  const std::string mesh = "distances '" + elephant + "' --source 100,f:40:0.6:0.3:0.1 --output d.txt";
  ASSERT_EQ(run(mesh).exit_code, 0);
  const std::string by_default = read_text(path("d.txt"));
  for(const char* threads : {"1", "2", "4"}) {
    ASSERT_EQ(run(mesh + " --threads " + threads).exit_code, 0) << threads;
    EXPECT_EQ(read_text(path("d.txt")), by_default) << threads << " threads";
  }
  const std::vector<double> vtp = distances("distances '" + elephant + "' --source 100,f:40:0.6:0.3:0.1 --algorithm vtp");
  const double largest = *std::max_element(vtp.begin(), vtp.end());
  expect_same_distances(parse_distances(by_default), vtp, 1e-12 * largest);

  const std::string sample = "sample '" + elephant + "' --count 30";
  const std::string samples = output_of(sample + " --threads 2", "s.txt");
  EXPECT_EQ(output_of(sample + " --threads 1", "s.txt"), samples);
  EXPECT_EQ(output_of(sample, "s.txt"), samples);
  const auto parallel = parse_samples(samples), sequential = parse_samples(output_of(sample + " --algorithm vtp", "s.txt"));
  ASSERT_EQ(parallel.size(), sequential.size());
  for(std::size_t k = 0; k < parallel.size(); ++k) {
    EXPECT_EQ(parallel[k].first, sequential[k].first) << "sample " << k;
    EXPECT_NEAR(parallel[k].second, sequential[k].second, 1e-12 * largest) << "radius after sample " << k;
  }
}

// Each sample is the vertex farthest from those before it (checked with the tool's own
// distances), the radius after it is the largest distance left; --radius stops there; --labels
// gives each vertex its nearest sample.
TEST_F(Tool, sample_gives_the_farthest_vertices_and_their_radii)
{
  const auto samples = parse_samples(output_of("sample '" + elephant + "' --count 6", "s.txt"));
  ASSERT_EQ(samples.size(), 6u);
  const std::vector<double> from_0 = distances("distances '" + elephant + "' --source 0");
  EXPECT_EQ(from_0[samples[0].first], *std::max_element(from_0.begin(), from_0.end()));
  std::string so_far;
  for(std::size_t k = 0; k < samples.size(); ++k) {
    so_far += (k ? "," : "") + std::to_string(samples[k].first);
    const std::vector<double> d = distances("distances '" + elephant + "' --source " + so_far);
    const double farthest = *std::max_element(d.begin(), d.end());
    EXPECT_NEAR(samples[k].second, farthest, 1e-12 * farthest) << "radius after sample " << k;
    if(k + 1 < samples.size())
      EXPECT_NEAR(d[samples[k + 1].first], farthest, 1e-12 * farthest) << "sample " << k + 1;
  }

  // --first, --radius, --labels, in parallel
  const auto from_7 =
    parse_samples(output_of("sample '" + elephant + "' --first 7 --radius " + tool::number_text(samples[3].second) +
                              " --count 100 --algorithm pvtp --threads 2 --labels l.txt",
                            "s.txt"));
  ASSERT_GE(from_7.size(), 2u);
  EXPECT_EQ(from_7[0].first, 7u);
  EXPECT_LE(from_7.back().second, samples[3].second);
  EXPECT_GT(from_7[from_7.size() - 2].second, samples[3].second);
  const std::vector<std::string> labels = lines_of(read_text(path("l.txt")));
  ASSERT_EQ(labels.size(), 2775u);
  for(std::size_t k = 0; k < from_7.size(); ++k)
    EXPECT_EQ(labels[from_7[k].first], std::to_string(k));

  // several --first: those, in order, each with the radius after all of them; then the farthest
  const auto from_three = parse_samples(output_of("sample '" + elephant + "' --first 900,100,2000 --count 5", "s.txt"));
  ASSERT_EQ(from_three.size(), 5u);
  const std::vector<double> d = distances("distances '" + elephant + "' --source 900,100,2000");
  const double farthest = *std::max_element(d.begin(), d.end());
  for(std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(from_three[k].first, std::vector<std::size_t>({900, 100, 2000})[k]);
    EXPECT_NEAR(from_three[k].second, farthest, 1e-12 * farthest) << "radius after initial sample " << k;
  }
  EXPECT_NEAR(d[from_three[3].first], farthest, 1e-12 * farthest);
}

// ---------------------------------------------------------------------------------------------
// geodesic voronoi

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

// ---------------------------------------------------------------------------------------------
// geodesic patterns

// A plane of quads with round bumps laid out irregularly: every bump is found from one, the
// JSON lists them with the marked one first, the labels and the arrangement follow them.
TEST_F(Tool, patterns_finds_every_bump_of_a_plane)
{
  const int n = 81;
  const double h = 1.0 / (n - 1), radius = 0.08;
  const std::vector<std::array<double, 2>> bumps = {{0.2, 0.2}, {0.55, 0.25}, {0.8, 0.5}, {0.3, 0.6}, {0.65, 0.8}};
  std::ostringstream off;
  off << "OFF\n" << n * n << " " << (n - 1) * (n - 1) << " 0\n";
  off.precision(17);
  for(int j = 0; j < n; ++j)
    for(int i = 0; i < n; ++i) {
      double z = 0;
      for(const auto& b : bumps) {
        const double r2 = ((i * h - b[0]) * (i * h - b[0]) + (j * h - b[1]) * (j * h - b[1])) / (radius * radius);
        z += r2 < 1 ? 0.4 * radius * (1 - r2) * (1 - r2) : 0.0;
      }
      off << i * h << " " << j * h << " " << z << "\n";
    }
  for(int j = 0; j + 1 < n; ++j)
    for(int i = 0; i + 1 < n; ++i)
      off << "4 " << j * n + i << " " << j * n + i + 1 << " " << (j + 1) * n + i + 1 << " " << (j + 1) * n + i << "\n";
  write("bumps.off", off.str());
  const int centre = 16 * n + 16; // (0.2, 0.2)
  const Result r = run("patterns bumps.off --patch-center " + std::to_string(centre) +
                       " --patch-radius 0.08 --output p.json --labels p.ply --arrangement a.obj --stats");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string json = read_text(path("p.json"));
  std::size_t instances = 0;
  for(std::size_t at = json.find("\"center_vertex\""); at != std::string::npos;
      at = json.find("\"center_vertex\"", at + 1))
    ++instances;
  EXPECT_EQ(instances, bumps.size()) << json.substr(0, 400);
  EXPECT_NE(json.find("\"center_vertex\": " + std::to_string(centre)), std::string::npos);
  EXPECT_EQ(json.rfind("{\n  \"instances\": [", 0), 0u);
  EXPECT_NE(read_text(path("p.ply")).find("property int instance"), std::string::npos);
  std::size_t centres = 0, edges = 0;
  for(const std::string& line : lines_of(read_text(path("a.obj")))) {
    centres += line.rfind("v ", 0) == 0;
    edges += line.rfind("l ", 0) == 0;
  }
  EXPECT_EQ(centres, bumps.size());
  EXPECT_GE(edges, bumps.size() - 1);
  std::string stats_text; // without the line that notes the triangulated quads
  for(const std::string& line : lines_of(r.err))
    if(line.rfind("note: ", 0) != 0)
      stats_text += line + "\n";
  const auto stats = parse_key_values(stats_text);
  EXPECT_EQ(stats.at("instances"), std::to_string(bumps.size()));
  for(const char* key : {"seconds_sampling", "seconds_signatures", "seconds_matching", "seconds_clustering",
                         "seconds_optimization", "seconds_arrangement"})
    EXPECT_EQ(stats.count(key), 1u) << key;

  // the same bump marked by a per-vertex property of a PLY file (a selection saved by MeshLab)
  std::ostringstream ply;
  ply.precision(17);
  ply << "ply\nformat ascii 1.0\nelement vertex " << n * n
      << "\nproperty double x\nproperty double y\nproperty double z\nproperty uchar selected\nelement face "
      << (n - 1) * (n - 1) << "\nproperty list uchar int vertex_indices\nend_header\n";
  std::istringstream lines_of_off(off.str());
  std::string line;
  std::getline(lines_of_off, line);
  std::getline(lines_of_off, line);
  for(int v = 0; v < n * n; ++v) {
    std::getline(lines_of_off, line);
    const int i = v % n, j = v / n;
    const bool selected = std::hypot(i * h - 0.2, j * h - 0.2) < radius;
    ply << line << " " << (selected ? 1 : 0) << "\n";
  }
  while(std::getline(lines_of_off, line))
    ply << line << "\n";
  write("bumps.ply", ply.str());
  const Result selected = run("patterns bumps.ply --patch-property selected --output s.json");
  ASSERT_EQ(selected.exit_code, 0) << selected.err;
  const std::string selected_json = read_text(path("s.json"));
  std::size_t found = 0;
  for(std::size_t at = selected_json.find("\"center_vertex\""); at != std::string::npos;
      at = selected_json.find("\"center_vertex\"", at + 1))
    ++found;
  EXPECT_EQ(found, bumps.size());
}

TEST(Tool_options, scale_ranges_and_vertex_lists)
{
  using geodesic_tool::parse_scale_range;
  using geodesic_tool::read_vertex_list;
  EXPECT_EQ(parse_scale_range("0.5:2"), std::make_pair(0.5, 2.0));
  EXPECT_EQ(parse_scale_range("1:1"), std::make_pair(1.0, 1.0));
  EXPECT_NE(tool_error_of([] { parse_scale_range("0:2"); }).find("positive"), std::string::npos);
  EXPECT_NE(tool_error_of([] { parse_scale_range("a:b"); }).find("expected A:B"), std::string::npos);
  std::istringstream list("# the patch\n3\n\n  7\n");
  EXPECT_EQ(read_vertex_list(list, 10, "l.txt"), (std::vector<std::size_t>{3, 7}));
  std::istringstream junk("3 4\n");
  EXPECT_NE(tool_error_of([&] { read_vertex_list(junk, 10, "l.txt"); }).find("l.txt line 1"), std::string::npos);
  std::istringstream empty("# nothing\n");
  EXPECT_NE(tool_error_of([&] { read_vertex_list(empty, 10, "l.txt"); }).find("no vertex id"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// geodesic matrix

/// The numbers of a text matrix, row by row.
std::vector<std::vector<double>> parse_rows(const std::string& text)
{
  std::vector<std::vector<double>> rows;
  for(const std::string& line : lines_of(text)) {
    std::istringstream in(line);
    rows.emplace_back();
    std::string word;
    while(in >> word)
      rows.back().push_back(std::strtod(word.c_str(), nullptr));
  }
  return rows;
}

TEST_F(Tool, matrix_rows_are_the_distances_of_each_source)
{
  const std::string args = "matrix '" + elephant + "' --source 0,10,f:5:0.2:0.3:0.5 --threads 2";
  const auto rows = parse_rows(output_of(args, "m.txt"));
  ASSERT_EQ(rows.size(), 3u);
  // each row is a VTP solve
  EXPECT_EQ(rows[0], distances("distances '" + elephant + "' --source 0 --algorithm vtp"));
  EXPECT_EQ(rows[1], distances("distances '" + elephant + "' --source 10 --algorithm vtp"));
  EXPECT_EQ(rows[2], distances("distances '" + elephant + "' --source f:5:0.2:0.3:0.5 --algorithm vtp"));
  // the same with one thread
  EXPECT_EQ(parse_rows(output_of("matrix '" + elephant + "' --source 0,10,f:5:0.2:0.3:0.5 --threads 1", "m1.txt")),
            rows);
}

TEST_F(Tool, matrix_square_npy_and_sparse_mtx)
{
  output_of("matrix '" + elephant + "' --source 0,10,100,1000 --target sources", "m.txt");
  const auto square = parse_rows(read_text(path("m.txt")));
  ASSERT_EQ(square.size(), 4u);
  for(std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(square[i][i], 0.);
    for(std::size_t j = 0; j < i; ++j)
      EXPECT_NEAR(square[i][j], square[j][i], 1e-12);
  }
  // .npy: NumPy's header (magic, version 1.0, a dict with the shape), then the rows as float64
  const std::string npy = output_of("matrix '" + elephant + "' --source 0,10,100,1000 --target sources", "m.npy");
  ASSERT_GE(npy.size(), 10u);
  EXPECT_EQ(npy.substr(0, 8), std::string("\x93NUMPY\x01\x00", 8));
  const std::size_t header = std::size_t((unsigned char)npy[8]) + 256 * std::size_t((unsigned char)npy[9]);
  EXPECT_EQ((10 + header) % 64, 0u);
  EXPECT_NE(npy.find("'descr': '<f8', 'fortran_order': False, 'shape': (4, 4)"), std::string::npos);
  ASSERT_EQ(npy.size(), 10 + header + 16 * sizeof(double));
  for(std::size_t k = 0; k < 16; ++k) {
    double x;
    std::memcpy(&x, npy.data() + 10 + header + k * sizeof(double), sizeof x);
    EXPECT_EQ(x, square[k / 4][k % 4]);
  }
  // .mtx within a radius: exactly the finite entries of the rows cut at that distance
  const double radius = 0.2;
  const auto full = parse_rows(output_of("matrix '" + elephant + "' --source 0,10", "full.txt"));
  const std::string mtx = output_of("matrix '" + elephant + "' --source 0,10 --max-distance 0.2", "m.mtx");
  const std::vector<std::string> lines = lines_of(mtx);
  ASSERT_GE(lines.size(), 3u);
  EXPECT_EQ(lines[0], "%%MatrixMarket matrix coordinate real general");
  std::size_t expected_entries = 0;
  for(const auto& row : full)
    for(double d : row)
      expected_entries += d <= radius;
  std::istringstream size_line(lines[2]);
  std::size_t rows = 0, columns = 0, entries = 0;
  size_line >> rows >> columns >> entries;
  EXPECT_EQ(rows, 2u);
  EXPECT_EQ(columns, full[0].size());
  EXPECT_EQ(entries, expected_entries);
  ASSERT_EQ(lines.size(), 3 + entries);
  for(std::size_t k = 3; k < lines.size(); ++k) {
    std::istringstream in(lines[k]);
    std::size_t i = 0, j = 0;
    double d = 0;
    in >> i >> j >> d;
    ASSERT_TRUE(i >= 1 && i <= 2 && j >= 1 && j <= columns) << lines[k];
    EXPECT_EQ(d, full[i - 1][j - 1]);
  }
}

// A local .mtx matrix is made of sparse rows (each costs its entries, not the number of
// columns): the same entries as the dense rows cut at the distance, with columns repeated, in
// any order, and on points that the reading merges (a duplicate) or copies (a non-manifold vertex).
TEST_F(Tool, local_mtx_matrix_equals_the_dense_rows_cut_at_the_distance)
{
  // a bowtie with a non-manifold vertex 0, and point 5 a duplicate of point 2
  write("bowtie.off", "OFF\n6 3 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n0 1 0\n3 0 1 2\n3 0 3 4\n3 0 5 3\n");
  const std::string targets = " --target 3,5,1,3,2,0,4";
  const double radius = 1.9;
  for(const std::string sources : {" --all", " --source 1,f:1:0.2:0.3:0.5"}) {
    const Result dense_run = run("matrix bowtie.off" + sources + targets + " --output m.txt");
    ASSERT_EQ(dense_run.exit_code, 0) << dense_run.err;
    const auto dense = parse_rows(read_text(path("m.txt")));
    const Result sparse_run = run("matrix bowtie.off" + sources + targets + " --max-distance 1.9 --output m.mtx");
    ASSERT_EQ(sparse_run.exit_code, 0) << sparse_run.err;
    const std::vector<std::string> lines = lines_of(read_text(path("m.mtx")));
    ASSERT_GE(lines.size(), 3u);
    std::istringstream size_line(lines[2]);
    std::size_t rows = 0, columns = 0, entries = 0;
    size_line >> rows >> columns >> entries;
    ASSERT_EQ(rows, dense.size());
    ASSERT_EQ(columns, 7u);
    std::vector<std::string> expected;
    for(std::size_t i = 0; i < dense.size(); ++i)
      for(std::size_t j = 0; j < dense[i].size(); ++j)
        if(dense[i][j] <= radius) {
          char line[96];
          std::snprintf(line, sizeof(line), "%zu %zu %.17g", i + 1, j + 1, dense[i][j]);
          expected.push_back(line);
        }
    EXPECT_EQ(entries, expected.size()) << sources;
    EXPECT_EQ(std::vector<std::string>(lines.begin() + 3, lines.end()), expected) << sources;
    EXPECT_GT(expected.size(), 2 * dense.size()) << "the rows reach beyond their sources";
  }
}

// A matrix that cannot be written says how much it needs and what to do instead.
TEST(Tool_matrix, a_matrix_too_large_is_refused_before_it_is_solved)
{
  const std::size_t mb = 1000000;
  const std::string mtx = tool_error_of([&] { tool::check_matrix_fits(tool::Matrix_format::mtx, 1000, 1000, false, mb, 0); });
  EXPECT_NE(mtx.find("holds up to 0.024 GB in memory, more than the 0.001 GB available"), std::string::npos) << mtx;
  EXPECT_NE(mtx.find("give --max-distance"), std::string::npos) << mtx;
  EXPECT_NO_THROW(tool::check_matrix_fits(tool::Matrix_format::mtx, 1000, 1000, true, mb, 0)) << "a local matrix";
  EXPECT_NO_THROW(tool::check_matrix_fits(tool::Matrix_format::mtx, 1000, 1000, false, 0, 0)) << "memory unknown";
  const std::string npy = tool_error_of([&] { tool::check_matrix_fits(tool::Matrix_format::npy, 1000, 1000, false, 0, mb); });
  EXPECT_NE(npy.find("needs about 0.008 GB on disk, more than the 0.001 GB free"), std::string::npos) << npy;
  EXPECT_NE(npy.find("write .mtx"), std::string::npos) << npy;
  EXPECT_NO_THROW(tool::check_matrix_fits(tool::Matrix_format::npy, 1000, 1000, false, 0, 100 * mb));
  EXPECT_GT(tool::available_memory_bytes(), 0u) << "/proc/meminfo is read";
}

TEST_F(Tool, matrix_bad_input_writes_no_file)
{
  const std::string mesh = "matrix '" + elephant + "'";
  const std::vector<std::pair<std::string, std::string>> cases = {
    {mesh + " --source 0 --output m.vtk", "unknown output format '.vtk' for a matrix"},
    {mesh + " --output m.npy", "give the sources with --source, or --all"},
    {mesh + " --source 0 --target f:1:0.2:0.3:0.5 --output m.npy", "the columns of a matrix are vertices"},
    {mesh + " --source f:1:0.2:0.3:0.5 --target sources --output m.npy", "is a face point"},
    {mesh + " --source 0 --target 99999 --output m.npy", "out of range"},
    {mesh + " --source 99999 --output m.npy", "out of range"},
    {mesh + " --source 0 --max-distance -1 --output m.npy", "--max-distance must be non-negative"},
  };
  for(const auto& [args, message] : cases) {
    const Result r = run(args);
    EXPECT_EQ(r.exit_code, 1) << args;
    EXPECT_NE(r.err.find("error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(message), std::string::npos) << "expected '" << message << "' in: " << r.err;
    EXPECT_FALSE(fs::exists(path("m.npy")) || fs::exists(path("m.vtk"))) << args;
  }
}

} // namespace
