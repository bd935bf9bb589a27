// Copyright (c) 2026 The CGAL_ext geodesics developers.
// Tests of the tool `geodesic`: `geodesic patterns`, repetitive pattern detection.

#include "tool_test_support.h"

namespace tool_test::patterns {

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

} // namespace tool_test::patterns
