// Copyright (c) 2026 The CGAL_ext geodesics developers.

#include "tool_options.h"

#include "tool_error.h"
#include "tool_text.h"

#include <CGAL_ext/Geodesics_3/Tolerances.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <iterator>
#include <sstream>

namespace geodesic_tool {

namespace {

/// The names of the algorithms that satisfy `wanted` (and are exact, with `exact_only`), as
/// "a, b and c" (`conjunction` "and" or "or").
template <class Predicate>
std::string algorithm_names(Predicate wanted, bool exact_only, const char* conjunction)
{
  std::vector<std::string> names;
  for(const Algorithm& a : algorithms)
    if(wanted(a) && (!exact_only || !a.approximate))
      names.push_back(a.name);
  std::string text;
  for(std::size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : (i + 1 == names.size() ? std::string(" ") + conjunction + " " : ", ")) + names[i];
  return text;
}

template <class T>
bool parse_number(const std::string& s, T& value)
{
  const char* end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, value);
  return ec == std::errc() && ptr == end;
}

std::vector<std::string> split(const std::string& s, char delimiter)
{
  std::vector<std::string> parts;
  std::string part;
  std::istringstream in(s);
  while(std::getline(in, part, delimiter))
    parts.push_back(part);
  if(!s.empty() && s.back() == delimiter)
    parts.emplace_back();
  return parts;
}

const char* const point_help = "a vertex id, or f:FACE:b0:b1:b2 (barycentric coordinates in the order of the "
                               "face's vertices in the file)";

} // namespace

void add_mesh_argument(CLI::App& cmd, std::string& mesh)
{
  cmd.add_option("MESH", mesh,
                 "Mesh (.off, .obj, .ply or .stl): triangles, polygons, soups, non-manifold meshes; vertex ids "
                 "are the file order (.stl: each distinct point where it first appears)")
    ->required();
}

void add_mesh_and_sources(CLI::App& cmd, std::string& mesh, std::vector<std::string>& sources)
{
  add_mesh_argument(cmd, mesh);
  cmd.add_option("--source", sources, std::string("Sources, comma-separated: ") + point_help)
    ->required()
    ->delimiter(',')
    ->allow_extra_args(false);
}

// ---------------------------------------------------------------------------------------------
// The options as given

void add_distances_command(CLI::App& app, Distances_options& options)
{
  CLI::App* cmd = app.add_subcommand("distances", "Geodesic distance from the nearest source to every vertex");
  add_mesh_and_sources(*cmd, options.mesh, options.sources);
  cmd->add_option("--algorithm", options.solver.algorithm,
                  "Solver: vtp (exact), pvtp (exact, parallel), avtp (approximate), pavtp (approximate, "
                  "parallel), mmp (exact, windows in exact order), fwp-mmp (exact, windows bucket by bucket), "
                  "pmmp (fwp-mmp in parallel); default: " + std::string(default_vertex_solver));
  cmd->add_option("--lambda", options.solver.lambda,
                  "avtp and pavtp: the wavefront is reset every lambda mean edge lengths; smaller is faster "
                  "and coarser, distances are never below the exact ones; positive; default: " +
                    number_text(default_lambda));
  cmd->add_option("--threads", options.solver.threads,
                  "pvtp, pavtp and pmmp: number of threads, at least 1; default: all cores");
  cmd->add_option("--batch-size", options.solver.batch_size,
                  "pvtp, avtp and pavtp: window lists propagated together, at least 1 (avtp and pavtp "
                  "give the same distances for the same batch size); default: " +
                    std::to_string(CGAL_ext::default_batch_size) +
                    "; pmmp: windows propagated together; default: " +
                    std::to_string(CGAL_ext::default_window_batch_size));
  cmd->add_option("--max-distance", options.solver.max_distance,
                  "Stop the propagation at this distance; farther vertices get inf");
  cmd->add_option("--output", options.output,
                  "Output file: .txt (one distance per line, vertex order) or .ply (the file's vertices and faces "
                  "with a per-vertex 'distance' and a colour ramp); default: txt on the standard output");
  cmd->add_option("--labels", options.labels,
                  "Also write the nearest source of every vertex (its geodesic Voronoi cell), the index of the "
                  "source in the order given, -1 where none reaches: .txt (one per line, vertex order) or .ply "
                  "(the file's vertices and faces with per-vertex 'distance' and 'source' and a colour per cell)");
  cmd->add_flag("--stats", options.stats, "Print key=value statistics on the standard error");
}

void add_path_command(CLI::App& app, Path_options& options)
{
  CLI::App* cmd = app.add_subcommand("path", "Shortest geodesic path from the nearest source to a target point");
  add_mesh_and_sources(*cmd, options.mesh, options.sources);
  cmd->add_option("--target", options.target, std::string("The end of the path: ") + point_help)->required();
  cmd->add_option("--algorithm", options.solver.algorithm,
                  "Solver: vtp or pvtp (parallel; the windows VTP propagates across each face), fwp-mmp "
                  "(windows bucket by bucket), mmp (windows in exact order), pmmp (fwp-mmp in parallel); all "
                  "exact; default: " + std::string(default_vertex_solver));
  cmd->add_option("--threads", options.solver.threads, "pvtp and pmmp: number of threads, at least 1; default: all cores");
  cmd->add_option("--batch-size", options.solver.batch_size,
                  "pvtp: lists, pmmp: windows propagated together, at least 1; default: " +
                    std::to_string(CGAL_ext::default_batch_size) + " and " +
                    std::to_string(CGAL_ext::default_window_batch_size));
  cmd->add_option("--max-distance", options.solver.max_distance,
                  "Stop the propagation at this distance; a farther target is an error");
  cmd->add_option("--output", options.output,
                  "Output file, the polyline from the source to the target: .txt (one 'x y z' line per point), "
                  ".obj (v lines and one l line) or .ply (ASCII, vertices and edges); default: txt on the "
                  "standard output");
  cmd->add_flag("--stats", options.stats,
                "Print key=value statistics on the standard error (length, distance, points, nearest_source "
                "among the sources in command-line order from 0, seconds, windows)");
}

// ---------------------------------------------------------------------------------------------
// The solver

Solver_choice solver_choice(const Solver_options& options, bool exact_only)
{
  const auto any = [](const Algorithm&) { return true; };
  Solver_choice choice;
  const auto found = std::find_if(std::begin(algorithms), std::end(algorithms),
                                  [&](const Algorithm& a) { return options.algorithm == a.name; });
  if(found == std::end(algorithms))
    throw Tool_error("unknown algorithm '" + options.algorithm + "' (use " + algorithm_names(any, exact_only, "or") +
                     ")");
  if(exact_only && found->approximate)
    throw Tool_error(std::string("--algorithm ") + found->name +
                     " is approximate: paths and Voronoi diagrams are exact (use " + algorithm_names(any, true, "or") +
                     ")");
  choice.algorithm = found;
  if(found->parallel && !parallel_available)
    throw Tool_error(std::string("--algorithm ") + found->name + " needs TBB; this geodesic was built without it");
  choice.batch_size = is_mmp_family(*found) ? CGAL_ext::default_window_batch_size : CGAL_ext::default_batch_size;

  const auto invalid = [](const char* option, const char* expected, auto value) {
    return Tool_error(std::string(option) + " must be " + expected + ", got " + number_text(value));
  };
  const auto applies_to = [&](const char* option, auto wanted) {
    return Tool_error(std::string(option) + " applies to " + algorithm_names(wanted, exact_only, "and") + " only");
  };
  if(!(options.max_distance >= 0))
    throw invalid("--max-distance", "a non-negative number", options.max_distance);
  choice.max_distance = options.max_distance;
  if(options.lambda) {
    if(!found->approximate)
      throw applies_to("--lambda", [](const Algorithm& a) { return a.approximate; });
    if(!(*options.lambda > 0) || !std::isfinite(*options.lambda))
      throw invalid("--lambda", "a positive, finite number", *options.lambda);
    choice.lambda = *options.lambda;
  }
  if(options.threads) {
    if(!found->parallel)
      throw applies_to("--threads", [](const Algorithm& a) { return a.parallel; });
    if(*options.threads < 1)
      throw invalid("--threads", "a positive integer", *options.threads);
    if(*options.threads > max_threads)
      throw invalid("--threads", ("at most " + std::to_string(max_threads)).c_str(), *options.threads);
    choice.threads = *options.threads;
  }
  if(options.batch_size) {
    // the sequential MMP solvers take their windows one at a time
    if(!found->parallel && !found->approximate)
      throw applies_to("--batch-size", [](const Algorithm& a) { return a.parallel || a.approximate; });
    if(*options.batch_size < 1)
      throw invalid("--batch-size", "a positive integer", *options.batch_size);
    choice.batch_size = static_cast<std::size_t>(*options.batch_size);
  }
  return choice;
}

// ---------------------------------------------------------------------------------------------
// Sources and targets

Surface_point parse_surface_point(const std::string& text, const char* role)
{
  const auto bad = [&](const std::string& why) {
    return Tool_error(std::string(role) + " '" + text + "': " + why);
  };
  Surface_point s;
  s.text = text;
  if(text.rfind("f:", 0) != 0) {
    std::size_t v;
    if(!parse_number(text, v))
      throw bad("expected a vertex id or f:FACE:b0:b1:b2");
    s.vertex = v;
    return s;
  }
  const std::vector<std::string> fields = split(text.substr(2), ':');
  if(fields.size() != 4 || !parse_number(fields[0], s.face))
    throw bad("expected f:FACE:b0:b1:b2");
  for(int k = 0; k < 3; ++k)
    if(!parse_number(fields[k + 1], s.barycentric[k]) || !std::isfinite(s.barycentric[k]))
      throw bad("barycentric coordinate '" + fields[k + 1] + "' is not a number");
  check_barycentric(s, role);
  return s;
}

void check_barycentric(const Surface_point& s, const char* role)
{
  const auto bad = [&](const std::string& why) {
    return Tool_error(std::string(role) + " '" + s.text + "': " + why);
  };
  const auto& b = s.barycentric;
  for(int k = 0; k < 3; ++k)
    if(!std::isfinite(b[k]))
      throw bad("barycentric coordinates must be finite numbers");
  if(b[0] < 0 || b[1] < 0 || b[2] < 0)
    throw bad("barycentric coordinates must be non-negative");
  const double sum = b[0] + b[1] + b[2];
  // the library would refuse the point otherwise; refusing it here names it as written
  if(std::abs(sum - 1.) > CGAL_ext::Geodesics_3::barycentric_sum_tolerance) {
    std::ostringstream msg;
    msg.precision(17);
    msg << "barycentric coordinates sum to " << sum << ", not 1";
    throw bad(msg.str());
  }
}

std::vector<Surface_point> parse_sources(const std::vector<std::string>& texts)
{
  std::vector<Surface_point> sources;
  for(const std::string& text : texts)
    sources.push_back(parse_surface_point(text));
  return sources;
}

void check_surface_point_range(const Surface_point& point, std::size_t number_of_vertices,
                               std::size_t number_of_faces, const char* role)
{
  const auto out_of_range = [&](const char* what, std::size_t i, std::size_t n, const char* plural) {
    return Tool_error(std::string(role) + " '" + point.text + "': " + what + " " + std::to_string(i) +
                      " is out of range (the mesh has " + std::to_string(n) + " " + plural + ")");
  };
  if(point.vertex && *point.vertex >= number_of_vertices)
    throw out_of_range("vertex", *point.vertex, number_of_vertices, "vertices");
  if(!point.vertex && point.face >= number_of_faces)
    throw out_of_range("face", point.face, number_of_faces, "faces");
}

// ---------------------------------------------------------------------------------------------
// Output files

Output_format output_format(const std::string& path, bool obj_allowed)
{
  const std::string ext = lowercase_extension(path);
  if(ext == ".txt")
    return Output_format::txt;
  if(ext == ".obj" && obj_allowed)
    return Output_format::obj;
  if(ext == ".ply")
    return Output_format::ply;
  throw Tool_error("unknown output format '" + path + "' (use " + (obj_allowed ? ".txt, .obj or .ply" : ".txt or .ply") +
                   ")");
}

void check_distinct_outputs(const std::vector<std::pair<std::string, std::string>>& outputs)
{
  for(std::size_t i = 0; i < outputs.size(); ++i)
    for(std::size_t j = 0; j < i; ++j)
      if(!outputs[i].second.empty() && outputs[i].second == outputs[j].second)
        throw Tool_error(outputs[j].first + " and " + outputs[i].first + " name the same file '" + outputs[i].second +
                         "'");
}

} // namespace geodesic_tool
