// Copyright (c) 2026 The CGAL_ext geodesics developers.
// `geodesic voronoi`: the exact geodesic Voronoi diagram of the sources: the cell of every
// vertex, the bisectors cut across faces, and the dual graph.

#ifndef GEODESIC_TOOL_VORONOI_H
#define GEODESIC_TOOL_VORONOI_H

#include "tool_options.h"
#include "tool_solvers.h"

#include <ostream>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace geodesic_tool {

struct Voronoi_options
{
  std::string mesh;
  std::vector<std::string> sources;
  Solver_options solver{default_vertex_solver};
  std::string output;    // the cells, .txt or .ply
  std::string bisectors; // .obj or .txt
  std::string dual;      // .obj
  bool stats = false;
};

void add_voronoi_command(CLI::App& app, Voronoi_options& options);

/// One line per bisector point, `x y z a b` (a < b the sources it separates), a blank line
/// between polylines.
bool write_bisectors_txt(std::ostream& os, const std::vector<Voronoi_result::Curve>& bisectors);

/// The points as `v` lines and each polyline as one `l` line.
bool write_bisectors_obj(std::ostream& os, const std::vector<Voronoi_result::Curve>& bisectors);

/// The sources as `v` lines (in order), an `l` line for each pair of neighbouring cells and an
/// `f` line for each triple meeting at a Voronoi vertex.
bool write_dual_obj(std::ostream& os, const std::vector<Point>& sources,
                    const std::vector<std::pair<std::size_t, std::size_t>>& edges,
                    const std::vector<std::array<std::size_t, 3>>& triangles);

int run_voronoi(const Voronoi_options& options);

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_VORONOI_H
