// Copyright (c) 2026 The CGAL_ext geodesics developers.

#include "tool_voronoi.h"

#include "tool_error.h"
#include "tool_mesh.h"
#include "tool_output.h"
#include "tool_stats.h"
#include "tool_text.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <sstream>

namespace geodesic_tool {

void add_voronoi_command(CLI::App& app, Voronoi_options& options)
{
  CLI::App* cmd = app.add_subcommand(
    "voronoi", "The exact geodesic Voronoi diagram of the sources: cells, bisectors across faces, dual graph");
  add_mesh_and_sources(*cmd, options.mesh, options.sources);
  cmd->add_option("--algorithm", options.solver.algorithm,
                  "Solver of the one multi-source propagation, whose windows the diagram is read from: vtp, pvtp "
                  "(parallel), fwp-mmp, mmp or pmmp (parallel); all exact, the same cells; default: " +
                    std::string(default_vertex_solver));
  cmd->add_option("--threads", options.solver.threads, "pvtp and pmmp: number of threads; default: all cores");
  cmd->add_option("--output", options.output,
                  "The cell of every vertex, as distances --labels writes it: .txt (one source index per line, "
                  "vertex order, -1 where unreached) or .ply (per-vertex 'distance' and 'source', a colour per "
                  "cell)")
    ->required();
  cmd->add_option("--bisectors", options.bisectors,
                  "The bisectors cut across faces: .obj (polylines) or .txt (one 'x y z a b' line per point, a and "
                  "b the two sources, a blank line between polylines)");
  cmd->add_option("--dual", options.dual,
                  "The dual graph (geodesic Delaunay), .obj: the sources, a line between neighbouring cells, a "
                  "triangle where three cells meet");
  cmd->add_flag("--stats", options.stats, "Print key=value statistics on the standard error");
}

bool write_bisectors_txt(std::ostream& os, const std::vector<Voronoi_result::Curve>& bisectors)
{
  for(std::size_t i = 0; i < bisectors.size(); ++i) {
    if(i > 0)
      os << "\n";
    for(const Point& p : bisectors[i].points)
      os << point_text(p) << " " << bisectors[i].first_source << " " << bisectors[i].second_source << "\n";
  }
  return bool(os);
}

bool write_bisectors_obj(std::ostream& os, const std::vector<Voronoi_result::Curve>& bisectors)
{
  os << "# geodesic Voronoi bisectors from the geodesic tool: one polyline per bisector\n";
  for(const auto& b : bisectors)
    for(const Point& p : b.points)
      os << "v " << point_text(p) << "\n";
  std::size_t first = 1;
  for(const auto& b : bisectors) {
    os << "# sources " << b.first_source << " " << b.second_source << "\nl";
    for(std::size_t k = 0; k < b.points.size(); ++k)
      os << " " << first + k;
    os << "\n";
    first += b.points.size();
  }
  return bool(os);
}

bool write_dual_obj(std::ostream& os, const std::vector<Point>& sources,
                    const std::vector<std::pair<std::size_t, std::size_t>>& edges,
                    const std::vector<std::array<std::size_t, 3>>& triangles)
{
  os << "# geodesic Delaunay graph from the geodesic tool: the sources, neighbouring cells, cells meeting at a "
        "Voronoi vertex\n";
  for(const Point& p : sources)
    os << "v " << point_text(p) << "\n";
  for(const auto& e : edges)
    os << "l " << e.first + 1 << " " << e.second + 1 << "\n";
  for(const auto& t : triangles)
    os << "f " << t[0] + 1 << " " << t[1] + 1 << " " << t[2] + 1 << "\n";
  return bool(os);
}

int run_voronoi(const Voronoi_options& options)
{
  // Validate the command line before the (possibly long) reading and solving.
  const Solver_choice choice = solver_choice(options.solver, true);
  const std::vector<Surface_point> sources = parse_sources(options.sources);
  const Output_format cells_format = output_format(options.output);
  const Output_format bisectors_format =
    options.bisectors.empty() ? Output_format::txt : output_format(options.bisectors, true);
  if(bisectors_format == Output_format::ply)
    throw Tool_error("--bisectors '" + options.bisectors + "': use .obj or .txt");
  if(!options.dual.empty() && output_format(options.dual, true) != Output_format::obj)
    throw Tool_error("--dual '" + options.dual + "': the dual graph is written as .obj");
  check_distinct_outputs({{"--output", options.output}, {"--bisectors", options.bisectors}, {"--dual", options.dual}});

  const Stopwatch read_watch;
  const Mesh_file file = read_mesh_file(options.mesh);
  const double seconds_read = read_watch.seconds();
  for(const Surface_point& s : sources)
    check_surface_point_range(s, file.soup.points.size(), file.soup.polygons.size());

  const Stopwatch solve_watch;
  const Voronoi_result diagram = compute_voronoi(file, sources, choice);
  const double seconds_diagram = solve_watch.seconds();

  std::vector<Output_file> outputs{{options.output, [&](std::ostream& os) {
                                      return cells_format == Output_format::ply
                                               ? write_labels_ply(os, file.soup, diagram.distances, diagram.cells)
                                               : write_labels_txt(os, diagram.cells);
                                    }}};
  if(!options.bisectors.empty())
    outputs.push_back({options.bisectors, [&](std::ostream& os) {
                         return bisectors_format == Output_format::obj ? write_bisectors_obj(os, diagram.bisectors)
                                                                       : write_bisectors_txt(os, diagram.bisectors);
                       }});
  if(!options.dual.empty()) {
    std::vector<Point> positions;
    for(const Surface_point& s : sources)
      positions.push_back(surface_point_position(file, s));
    outputs.push_back({options.dual, [&, positions](std::ostream& os) {
                         return write_dual_obj(os, positions, diagram.dual_edges, diagram.dual_triangles);
                       }});
  }
  write_outputs(outputs);

  if(!file.repairs.summary().empty())
    std::cerr << "note: " << file.repairs.summary() << std::endl;
  if(options.stats) {
    std::size_t points = 0;
    for(const auto& b : diagram.bisectors)
      points += b.points.size();
    std::ostringstream s;
    write_input_stats(s, choice, file, sources.size(), seconds_read);
    s << "bisectors=" << diagram.bisectors.size() << "\n"
      << "bisector_points=" << points << "\n"
      << "voronoi_vertices=" << diagram.vertex_points.size() << "\n"
      << "dual_edges=" << diagram.dual_edges.size() << "\n"
      << "dual_triangles=" << diagram.dual_triangles.size() << "\n"
      << "unresolved_parts=" << diagram.unresolved_parts << "\n"
      << "seconds_diagram=" << seconds_diagram << "\n"
      << "peak_rss_mb=" << peak_rss_mb() << "\n";
    std::cerr << s.str() << std::flush;
  }
  return 0;
}

} // namespace geodesic_tool
