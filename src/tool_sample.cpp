// Copyright (c) 2026 The CGAL_ext geodesics developers.

#include "tool_sample.h"

#include "tool_error.h"
#include "tool_mesh.h"
#include "tool_output.h"
#include "tool_solvers.h"
#include "tool_stats.h"
#include "tool_text.h"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

namespace geodesic_tool {

void add_sample_command(CLI::App& app, Sample_options& options)
{
  CLI::App* cmd = app.add_subcommand(
    "sample", "Farthest-point sampling with exact geodesic distances: each sample is the vertex farthest from the "
              "samples before it");
  add_mesh_argument(*cmd, options.mesh);
  cmd->add_option("--count", options.count, "How many samples (at most, with --radius)");
  cmd->add_option("--radius", options.radius,
                  "Stop once every vertex is within this geodesic distance of a sample (with --count: whichever "
                  "comes first)");
  cmd->add_option("--first", options.first,
                  "The first sample, a vertex id; default: the vertex farthest from vertex 0. Several, "
                  "comma-separated: the first samples, taken as given, from one propagation (faster than as many "
                  "farthest points when vertices far apart are known); the sampling goes on from them")
    ->delimiter(',')
    ->allow_extra_args(false);
  cmd->add_option("--algorithm", options.solver.algorithm,
                  "Solver of each sample's propagation: vtp (exact), pvtp (exact, parallel), avtp or pavtp "
                  "(approximate); default: " + std::string(default_vertex_solver));
  cmd->add_option("--lambda", options.solver.lambda, "avtp and pavtp: as for distances");
  cmd->add_option("--threads", options.solver.threads, "pvtp and pavtp: number of threads; default: all cores");
  cmd->add_option("--batch-size", options.solver.batch_size, "pvtp, avtp and pavtp: as for distances");
  cmd->add_option("--output", options.output,
                  "Output file (.txt): one line per sample in order, its vertex id then the covering radius after "
                  "it; default: the standard output");
  cmd->add_option("--labels", options.labels,
                  "Also write the nearest sample of every vertex (its geodesic Voronoi cell), as distances --labels "
                  "does: .txt or .ply");
  cmd->add_flag("--stats", options.stats, "Print key=value statistics on the standard error");
}

bool write_samples_txt(std::ostream& os, const std::vector<std::size_t>& samples, const std::vector<double>& radii)
{
  char line[64];
  for(std::size_t i = 0; i < samples.size(); ++i) {
    std::snprintf(line, sizeof(line), "%zu %.17g\n", samples[i], radii[i]);
    os << line;
  }
  return bool(os);
}

int run_sample(const Sample_options& options)
{
  // Validate the command line before the (possibly long) reading and solving.
  if(!options.count && !options.radius)
    throw Tool_error("give --count, --radius, or both");
  if(options.count && *options.count < 1)
    throw Tool_error("--count must be at least 1, got " + std::to_string(*options.count));
  if(options.radius && !(*options.radius > 0))
    throw Tool_error("--radius must be positive, got " + number_text(*options.radius));
  const Solver_choice choice = solver_choice(options.solver, false);
  if(is_mmp_family(*choice.algorithm))
    throw Tool_error(std::string("--algorithm ") + choice.algorithm->name +
                     ": sampling runs vtp, pvtp, avtp or pavtp");
  if(!options.output.empty() && output_format(options.output) != Output_format::txt)
    throw Tool_error("--output '" + options.output + "': the samples are written as .txt");
  const Output_format labels_format = options.labels.empty() ? Output_format::txt : output_format(options.labels);
  check_distinct_outputs({{"--output", options.output}, {"--labels", options.labels}});
  std::vector<Surface_point> first;
  std::set<std::size_t> first_vertices;
  for(const std::string& text : options.first) {
    first.push_back(parse_surface_point(text, "first sample"));
    if(!first.back().vertex)
      throw Tool_error("first sample '" + text + "': give a vertex id");
    if(!first_vertices.insert(*first.back().vertex).second)
      throw Tool_error("first sample '" + text + "' is given twice");
  }
  if(options.count && first.size() > std::size_t(*options.count))
    throw Tool_error("--first gives " + std::to_string(first.size()) + " samples, more than --count " +
                     std::to_string(*options.count));

  const Stopwatch read_watch;
  const Mesh_file file = read_mesh_file(options.mesh);
  const double seconds_read = read_watch.seconds();
  const std::size_t points = file.soup.points.size();
  std::map<std::size_t, std::string> first_of_vertex; // two points merged into one vertex are one sample
  for(const Surface_point& point : first) {
    check_surface_point_range(point, points, file.soup.polygons.size(), "first sample");
    const auto [at, added] = first_of_vertex.emplace(std::size_t(file.vertex_of_point[*point.vertex]), point.text);
    if(!added)
      throw Tool_error("first samples '" + at->second + "' and '" + point.text +
                       "' are one vertex of the mesh (the file repeats the point)");
  }
  Sampling_request request;
  request.count = options.count ? std::size_t(*options.count) : points;
  if(request.count > points)
    throw Tool_error("--count " + std::to_string(request.count) + " is more than the " + std::to_string(points) +
                     " vertices of the file");
  request.radius = options.radius.value_or(0.);
  for(const Surface_point& point : first)
    request.first.push_back(*point.vertex);

  const Stopwatch solve_watch;
  const Sampling_result result = compute_samples(file, request, choice);
  const double seconds_sampling = solve_watch.seconds();

  std::vector<Output_file> outputs{
    {options.output, [&](std::ostream& os) { return write_samples_txt(os, result.samples, result.radii); }}};
  if(!options.labels.empty())
    outputs.push_back({options.labels, [&](std::ostream& os) {
                         return labels_format == Output_format::ply
                                  ? write_labels_ply(os, file.soup, result.distances, result.labels)
                                  : write_labels_txt(os, result.labels);
                       }});
  write_outputs(outputs);

  if(!file.repairs.summary().empty())
    std::cerr << "note: " << file.repairs.summary() << std::endl;
  if(options.stats) {
    std::ostringstream s;
    write_input_stats(s, choice, file, result.samples.size(), seconds_read); // the samples are the sources
    s << "samples=" << result.samples.size() << "\n"
      << "covering_radius=" << number_text(result.radii.back()) << "\n"
      << "seconds_sampling=" << seconds_sampling << "\n"
      << "seconds_solve=" << result.stats.seconds_solve << "\n"
      << "seconds_selection=" << result.stats.seconds_selection << "\n"
      << "seconds_propagation=" << result.stats.seconds_propagation << "\n"
      << "seconds_merge=" << result.stats.seconds_merge << "\n"
      << "windows_created=" << result.stats.windows_created << "\n"
      << "windows_per_sample=" << double(result.stats.windows_created) / double(result.samples.size()) << "\n"
      << "peak_windows=" << result.stats.peak_windows << "\n"
      << "batched_runs_kept=" << result.stats.batched_runs_kept << "\n"
      << "batched_runs_undone=" << result.stats.batched_runs_undone << "\n"
      << "peak_rss_mb=" << peak_rss_mb() << "\n";
    std::cerr << s.str() << std::flush;
  }
  return 0;
}

} // namespace geodesic_tool
