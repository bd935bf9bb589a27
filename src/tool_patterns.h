// Copyright (c) 2026 The CGAL_ext geodesics developers.
// `geodesic patterns`: the instances of a repetitive pattern from one marked instance, their
// correspondences and their arrangement (thesis chapter 5).

#ifndef GEODESIC_TOOL_PATTERNS_H
#define GEODESIC_TOOL_PATTERNS_H

#include "tool_mesh.h"

#include <CGAL_ext/detect_repetitive_patterns.h>

#include <array>
#include <cstddef>
#include <functional>
#include <istream>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace CLI {
class App;
}

namespace geodesic_tool {

struct Patterns_options
{
  std::string mesh;
  std::string patch_center;   // a vertex id (a face point is taken at its nearest corner)
  double patch_radius = 0;
  std::string patch_vertices; // a file of vertex ids
  std::string patch_property; // a per-vertex property of a PLY mesh: the vertices where it is not 0
  std::string scales;         // "A:B"
  std::vector<long long> stroke; // vertex ids of the user's stroke across instances of changing size
  double sample_spacing = 1.0 / 3;
  double match_tolerance = 0.35;
  double consistency_cutoff = 0.7;
  double lambda = 0; // AVTP for the local rows; 0: exact
  int threads = 0;
  std::string output;      // .json
  std::string labels;      // .ply or .txt
  std::string arrangement; // .obj
  bool stats = false;
};

/// An instance as the tool writes it, in the file's ids.
struct Found_instance
{
  Point center;
  std::size_t center_vertex = 0;
  double scale = 1;
  double energy = 0;
  std::vector<std::size_t> vertices;
  std::vector<std::pair<std::size_t, std::size_t>> correspondence;
};

/// What the detection found, in the file's ids: the instances, the instance of each point of the
/// file (-1: none), and the arrangement's edges and triangles between instances.
struct Patterns_found
{
  std::vector<Found_instance> instances;
  std::vector<long> labels; // per point of the file
  std::vector<std::pair<std::size_t, std::size_t>> edges;
  std::vector<std::array<std::size_t, 3>> triangles;
  CGAL_ext::Pattern_statistics stats;
};

/// Runs the library's detection of the pattern `patch` marks; `callback` (when not empty) is
/// told the fraction done and may cancel, otherwise a progress line is shown on a terminal.
Patterns_found detect_patterns(const Mesh_file& file, const CGAL_ext::Pattern_patch<Mesh>& patch,
                               const Patterns_options& options, std::pair<double, double> scales,
                               const std::vector<Vertex_index>& stroke, const std::function<bool(double)>& callback);

void add_patterns_command(CLI::App& app, Patterns_options& options);

/// "A:B" with 0 < A <= B; throws Tool_error otherwise.
std::pair<double, double> parse_scale_range(const std::string& text);

/// Vertex ids, one per line (blank lines and lines starting with '#' skipped), each below
/// `number_of_vertices`; throws Tool_error naming the line otherwise.
std::vector<std::size_t> read_vertex_list(std::istream& in, std::size_t number_of_vertices, const std::string& name);

/// The vertices of the PLY file at `path` whose per-vertex property `name` (any PLY number type)
/// is not 0, in the file's ids; throws Tool_error when the file has no such property, when no
/// vertex has it, or when its vertices are not the `number_of_points` of the mesh read.
std::vector<std::size_t> read_selected_vertices_ply(const std::string& path, const std::string& name,
                                                    std::size_t number_of_points);

/// `{"instances": [...], "arrangement": {"edges": [...], "triangles": [...]}}`, the marked patch
/// first; each instance has "center", "center_vertex", "scale", "energy", "vertices" and
/// "correspondence" (pairs of vertex ids: a patch sample and its image).
bool write_instances_json(std::ostream& os, const std::vector<Found_instance>& instances,
                          const std::vector<std::pair<std::size_t, std::size_t>>& edges,
                          const std::vector<std::array<std::size_t, 3>>& triangles);

int run_patterns(const Patterns_options& options);

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_PATTERNS_H
