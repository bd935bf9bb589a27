// Copyright (c) 2026 The CGAL_ext geodesics developers.
// `geodesic sample`: exact farthest-point sampling of the vertices of a mesh, written as one
// line per sample (its vertex id and the covering radius after it).

#ifndef GEODESIC_TOOL_SAMPLE_H
#define GEODESIC_TOOL_SAMPLE_H

#include "tool_options.h"

#include <cstddef>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace geodesic_tool {

struct Sample_options
{
  std::string mesh;
  std::optional<long long> count;
  std::optional<double> radius;
  std::vector<std::string> first; // one vertex id, or several (the initial samples)
  Solver_options solver{default_vertex_solver};
  std::string output;
  std::string labels;
  bool stats = false;
};

void add_sample_command(CLI::App& app, Sample_options& options);

/// One line per sample: its vertex id, then the covering radius after it (17 digits, `inf`
/// while a component has no sample).
bool write_samples_txt(std::ostream& os, const std::vector<std::size_t>& samples, const std::vector<double>& radii);

int run_sample(const Sample_options& options);

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_SAMPLE_H
