// Copyright (c) 2026 The CGAL_ext geodesics developers.
// geodesic: the command-line front end of the package.
//
//   geodesic distances MESH --source S[,S...] [--algorithm vtp|pvtp|avtp|pavtp|mmp|fwp-mmp|pmmp]
//                      [--lambda L] [--threads N] [--batch-size K] [--max-distance D]
//                      [--output FILE.txt|FILE.ply] [--labels FILE.txt|FILE.ply] [--stats]
//   geodesic path MESH --source S[,S...] --target T [--algorithm vtp|pvtp|fwp-mmp|mmp|pmmp] [--threads N]
//                 [--batch-size K] [--max-distance D] [--output FILE.txt|FILE.obj|FILE.ply] [--stats]
//   geodesic matrix MESH (--source S[,S...] | --all) [--target T[,T...]|sources] [--max-distance D]
//                   [--threads N] --output FILE.npy|FILE.mtx|FILE.txt [--stats]
//   geodesic sample MESH (--count N | --radius R) [--first V[,V...]] [--algorithm vtp|pvtp|avtp|pavtp]
//                   [--threads N] [--output FILE.txt] [--labels FILE.txt|FILE.ply] [--stats]
//   geodesic voronoi MESH --source S[,S...] [--algorithm vtp|pvtp|fwp-mmp|mmp|pmmp] [--threads N]
//                    --output CELLS.txt|CELLS.ply [--bisectors FILE.obj|FILE.txt] [--dual FILE.obj] [--stats]
//   geodesic patterns MESH (--patch-center V --patch-radius R | --patch-vertices FILE | --patch-property NAME)
//                     [--scales A:B]
//                     [--threads N] --output FILE.json [--labels FILE.ply|FILE.txt] [--arrangement FILE.obj]
//                     [--stats]
//
// MESH is an OFF, OBJ, PLY or STL file: triangles, quads, polygons, soups and non-manifold meshes
// are made into the triangle mesh the library takes (CGAL_ext::polygon_soup_to_geodesic_mesh),
// and one line `note: ...` on stderr says what was repaired. S and T are a vertex id or a face
// point f:FACE:b0:b1:b2 (barycentric coordinates in the order of the face's vertices in the
// file). Vertex and face ids, and the distances written, are those of the file (its order of
// vertices and faces; for STL, each distinct point in the order of its first appearance). `path`
// writes the shortest path from the nearest source to T as a polyline, the source first. Every
// error is one line `error: ...` on stderr, exit code 1 (2 for a bad command line), and no output
// file.
//
// This file runs the subcommands; their parts are in the tool_*.h files beside it: the options
// and their checking, reading the mesh, calling the library, writing the output, --stats.

#include "tool_matrix.h"
#include "tool_mesh.h"
#include "tool_options.h"
#include "tool_output.h"
#include "tool_patterns.h"
#include "tool_sample.h"
#include "tool_solvers.h"
#include "tool_stats.h"
#include "tool_text.h"
#include "tool_voronoi.h"

#include <CGAL_ext/Geodesics_3/polyline_length.h>

#include <CLI/CLI.hpp>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <exception>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace geodesic_tool {
namespace {

/// The file at `path` and its mesh, and how long reading and making it took.
Mesh_file read_mesh(const std::string& path, double& seconds)
{
  const Stopwatch read_watch;
  Mesh_file file = read_mesh_file(path);
  seconds = read_watch.seconds();
  return file;
}

void check_range(const Surface_point& point, const Mesh_file& file, const char* role = "source")
{
  check_surface_point_range(point, file.soup.points.size(), file.soup.polygons.size(), role);
}

void check_ranges(const std::vector<Surface_point>& sources, const Mesh_file& file)
{
  for(const Surface_point& s : sources)
    check_range(s, file);
}

/// After a successful run (an error stays the one line on stderr): what was repaired.
void print_note(const Mesh_file& file)
{
  const std::string summary = file.repairs.summary();
  if(!summary.empty())
    std::cerr << "note: " << summary << std::endl;
}

int run_distances(const Distances_options& options)
{
  // Validate the command line before the (possibly long) reading and solving.
  const Solver_choice choice = solver_choice(options.solver, false);
  const std::vector<Surface_point> sources = parse_sources(options.sources);
  const Output_format format = options.output.empty() ? Output_format::txt : output_format(options.output);
  const Output_format labels_format = options.labels.empty() ? Output_format::txt : output_format(options.labels);
  check_distinct_outputs({{"--output", options.output}, {"--labels", options.labels}});

  double seconds_read = 0;
  Mesh_file file = read_mesh(options.mesh, seconds_read);
  check_ranges(sources, file);

  CGAL_ext::Geodesic_statistics stats;
  std::vector<long> labels;
  std::vector<long>* wanted_labels = options.labels.empty() ? nullptr : &labels;
  const std::vector<double> distances = compute_distances(file, sources, choice, stats, wanted_labels);

  std::vector<Output_file> outputs{{options.output, [&](std::ostream& os) {
                                      return format == Output_format::ply ? write_distances_ply(os, file.soup, distances)
                                                                          : write_distances_txt(os, distances);
                                    }}};
  if(!options.labels.empty())
    outputs.push_back({options.labels, [&](std::ostream& os) {
                         return labels_format == Output_format::ply ? write_labels_ply(os, file.soup, distances, labels)
                                                                    : write_labels_txt(os, labels);
                       }});
  write_outputs(outputs);

  print_note(file);
  if(options.stats) {
    std::ostringstream s;
    write_input_stats(s, choice, file, sources.size(), seconds_read);
    write_solver_stats(s, choice, stats);
    s << "peak_rss_mb=" << peak_rss_mb() << "\n"
      << "max_distance=" << std::setprecision(17) << farthest_finite(distances) << "\n";
    std::cerr << s.str() << std::flush;
  }
  return 0;
}

int run_path(const Path_options& options)
{
  // Validate the command line before the (possibly long) reading and building.
  const Solver_choice choice = solver_choice(options.solver, true);
  const std::vector<Surface_point> sources = parse_sources(options.sources);
  const Surface_point target = parse_surface_point(options.target, "target");
  const Output_format format = options.output.empty() ? Output_format::txt : output_format(options.output, true);

  double seconds_read = 0;
  const Mesh_file file = read_mesh(options.mesh, seconds_read);
  check_ranges(sources, file);
  check_range(target, file, "target");

  const Path_result path = trace_path(file, sources, target, choice);

  write_output(options.output, [&](std::ostream& os) {
    switch(format) {
    case Output_format::txt:
      return write_path_txt(os, path.points);
    case Output_format::obj:
      return write_path_obj(os, path.points);
    case Output_format::ply:
      return write_path_ply(os, path.points);
    }
    return false;
  });

  print_note(file);
  if(options.stats) {
    std::ostringstream s;
    write_input_stats(s, choice, file, sources.size(), seconds_read);
    s << "seconds_build=" << path.seconds_build << "\n"
      << "seconds_query=" << path.seconds_query << "\n";
    write_solver_stats(s, choice, path.stats);
    s << "peak_rss_mb=" << peak_rss_mb() << "\n"
      << "length=" << number_text(CGAL_ext::polyline_length(path.points)) << "\n"
      << "distance=" << number_text(path.distance) << "\n"
      << "points=" << path.points.size() << "\n"
      << "nearest_source=" << path.nearest_source << "\n";
    std::cerr << s.str() << std::flush;
  }
  return 0;
}

} // namespace
} // namespace geodesic_tool

int main(int argc, char** argv)
{
  using namespace geodesic_tool;
#if defined(__GLIBC__)
  // Arrays of a megabyte or more each in pages of their own, given back when freed: glibc
  // otherwise raises this threshold to the size of the largest array freed, and the arrays of
  // the solve that come after it stay in the heap beside the freed ones (the peak memory).
  mallopt(M_MMAP_THRESHOLD, 1 << 20);
#endif
  CLI::App app{"Geodesic distances and shortest paths on triangle meshes", "geodesic"};
  // At most one subcommand: CLI11 then reports an unknown one as unexpected, not as missing.
  app.require_subcommand(0, 1);
  Distances_options distances;
  add_distances_command(app, distances);
  Path_options path;
  add_path_command(app, path);
  Matrix_options matrix;
  add_matrix_command(app, matrix);
  Sample_options sample;
  add_sample_command(app, sample);
  Voronoi_options voronoi;
  add_voronoi_command(app, voronoi);
  Patterns_options patterns;
  add_patterns_command(app, patterns);

  try {
    app.parse(argc, argv);
  } catch(const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch(const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch(const CLI::ParseError& e) {
    std::cerr << "error: " << e.what() << std::endl;
    return 2;
  }

  if(app.get_subcommands().empty()) {
    std::cerr << "error: a subcommand is required (see geodesic --help)" << std::endl;
    return 2;
  }
  try {
    if(app.got_subcommand("distances"))
      return run_distances(distances);
    if(app.got_subcommand("path"))
      return run_path(path);
    if(app.got_subcommand("matrix"))
      return run_matrix(matrix);
    if(app.got_subcommand("sample"))
      return run_sample(sample);
    if(app.got_subcommand("voronoi"))
      return run_voronoi(voronoi);
    if(app.got_subcommand("patterns"))
      return run_patterns(patterns);
  } catch(const std::exception& e) { // Tool_error, and the library's Geodesic_error
    std::cerr << "error: " << e.what() << std::endl;
  }
  return 1;
}
