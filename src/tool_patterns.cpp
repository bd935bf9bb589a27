// Copyright (c) 2026 The CGAL_ext geodesics developers.

#include "tool_patterns.h"

#include "tool_error.h"
#include "tool_options.h"
#include "tool_output.h"
#include "tool_solvers.h"
#include "tool_stats.h"
#include "tool_text.h"
#include "tool_threads.h"
#include "tool_voronoi.h"

#include <CGAL_ext/detect_repetitive_patterns.h>

#include <CGAL/Point_set_3.h>
#include <CGAL/Point_set_3/IO/PLY.h>
#include <CGAL/property_map.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <fstream>
#include <iostream>
#include <sstream>

namespace geodesic_tool {

void add_patterns_command(CLI::App& app, Patterns_options& options)
{
  CLI::App* cmd = app.add_subcommand(
    "patterns", "Repetitive pattern detection (thesis chapter 5): from one marked instance, all the others, with a "
                "correspondence to each and their arrangement");
  add_mesh_argument(*cmd, options.mesh);
  CLI::Option* center = cmd->add_option(
    "--patch-center", options.patch_center,
    "The centre of the marked instance: a vertex id (a face point F:a,b,c is taken at its nearest corner)");
  CLI::Option* radius = cmd->add_option("--patch-radius", options.patch_radius,
                                        "The geodesic radius of the marked instance around --patch-center");
  CLI::Option* list = cmd->add_option(
    "--patch-vertices", options.patch_vertices,
    "Instead of a disk: a text file of the marked instance's vertex ids, one per line (any connected shape)");
  CLI::Option* property = cmd->add_option(
    "--patch-property", options.patch_property,
    "Instead of a disk: the name of a per-vertex property of a .ply MESH, the marked instance being the vertices "
    "where it is not 0 (a selection saved by MeshLab, for example)");
  center->needs(radius);
  radius->needs(center);
  list->excludes(center)->excludes(radius);
  property->excludes(center)->excludes(radius)->excludes(list);
  cmd->add_option("--scales", options.scales,
                  "A:B, the sizes of instances sought relative to the marked one (adaptive patterns); default 1:1");
  cmd->add_option("--stroke", options.stroke,
                  "With --scales: vertex ids of a path from the marked instance across instances whose size changes "
                  "along it, comma-separated; each part is matched near the scale the stroke gives it")
    ->delimiter(',');
  cmd->add_option("--sample-spacing", options.sample_spacing,
                  "Covering radius of the samples, relative to the patch's size; default 1/3");
  cmd->add_option("--match-tolerance", options.match_tolerance,
                  "How far two signatures may differ to match, relative to the patch's; default 0.35");
  cmd->add_option("--consistency-cutoff", options.consistency_cutoff,
                  "c0: how well matched distances must agree, in [0, 1); default 0.7");
  cmd->add_option("--lambda", options.lambda,
                  "Approximate local rows (AVTP, the wavefront reset every lambda mean edge lengths): faster on "
                  "meshes that make many windows (a golf ball), distances never below the exact ones; the sampling "
                  "and the arrangement stay exact; default: exact");
  cmd->add_option("--threads", options.threads, "Number of threads; default: all cores");
  cmd->add_option("--output", options.output,
                  "The instances, .json: {\"instances\": [{\"center\", \"center_vertex\", \"scale\", \"energy\", "
                  "\"vertices\", \"correspondence\"}, ...], \"arrangement\": {...}}, the marked one first")
    ->required();
  cmd->add_option("--labels", options.labels,
                  "The instance of every vertex: .ply (per-vertex 'instance', -1 outside any, a colour per "
                  "instance) or .txt (one per line)");
  cmd->add_option("--arrangement", options.arrangement,
                  "The arrangement, .obj: the instance centres and a line between neighbouring instances (the dual of "
                  "the geodesic Voronoi diagram of the centres)");
  cmd->add_flag("--stats", options.stats, "Print key=value statistics (the time of each step) on the standard error");
}

std::pair<double, double> parse_scale_range(const std::string& text)
{
  const std::size_t colon = text.find(':');
  double a = 0, b = 0;
  bool ok = colon != std::string::npos;
  if(ok) {
    std::istringstream first(text.substr(0, colon)), second(text.substr(colon + 1));
    ok = bool(first >> a) && first.eof() && bool(second >> b) && second.eof();
  }
  if(!ok)
    throw Tool_error("--scales '" + text + "': expected A:B, two positive numbers");
  if(!(a > 0) || !(b > 0) || !std::isfinite(a) || !std::isfinite(b))
    throw Tool_error("--scales '" + text + "': the scales must be positive");
  if(a > b)
    throw Tool_error("--scales '" + text + "': empty scale range (A must not exceed B)");
  return {a, b};
}

std::vector<std::size_t> read_vertex_list(std::istream& in, std::size_t number_of_vertices, const std::string& name)
{
  std::vector<std::size_t> ids;
  std::string line;
  for(std::size_t number = 1; std::getline(in, line); ++number) {
    const std::size_t start = line.find_first_not_of(" \t\r");
    if(start == std::string::npos || line[start] == '#')
      continue;
    std::istringstream s(line);
    long long id = -1;
    std::string rest;
    if(!(s >> id) || (s >> rest))
      throw Tool_error(name + " line " + std::to_string(number) + ": expected one vertex id, got '" + line + "'");
    if(id < 0 || std::size_t(id) >= number_of_vertices)
      throw Tool_error(name + " line " + std::to_string(number) + ": vertex " + std::to_string(id) +
                       " is out of range (the mesh has " + std::to_string(number_of_vertices) + " vertices)");
    ids.push_back(std::size_t(id));
  }
  if(ids.empty())
    throw Tool_error(name + ": no vertex id");
  return ids;
}

std::vector<std::size_t> read_selected_vertices_ply(const std::string& path, const std::string& name,
                                                    std::size_t number_of_points)
{
  CGAL::Point_set_3<Point> points;
  std::ifstream in(path, std::ios::binary);
  if(!in || !CGAL::IO::read_PLY(in, points))
    throw Tool_error("cannot read the vertex properties of '" + path + "'");
  if(points.size() != number_of_points)
    throw Tool_error("'" + path + "' has " + std::to_string(points.size()) + " vertices with properties, the mesh " +
                     std::to_string(number_of_points));
  std::vector<std::size_t> selected;
  bool found = false;
  const auto take = [&](auto zero) {
    typedef decltype(zero) Number;
    const auto [map, exists] = points.template property_map<Number>(name);
    if(!exists || found)
      return;
    found = true;
    std::size_t id = 0;
    for(auto it = points.begin(); it != points.end(); ++it, ++id)
      if(get(map, *it) != zero)
        selected.push_back(id);
  };
  take(std::int8_t(0));
  take(std::uint8_t(0));
  take(std::int16_t(0));
  take(std::uint16_t(0));
  take(std::int32_t(0));
  take(std::uint32_t(0));
  take(float(0));
  take(double(0));
  if(!found)
    throw Tool_error("'" + path + "' has no per-vertex property '" + name + "'");
  if(selected.empty())
    throw Tool_error("no vertex of '" + path + "' has a non-zero '" + name + "'");
  return selected;
}

bool write_instances_json(std::ostream& os, const std::vector<Found_instance>& instances,
                          const std::vector<std::pair<std::size_t, std::size_t>>& edges,
                          const std::vector<std::array<std::size_t, 3>>& triangles)
{
  const auto number = [](double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
  };
  os << "{\n  \"instances\": [";
  for(std::size_t i = 0; i < instances.size(); ++i) {
    const Found_instance& f = instances[i];
    os << (i ? ",\n" : "\n") << "    {\"center\": [" << number(f.center.x()) << ", " << number(f.center.y()) << ", "
       << number(f.center.z()) << "], \"center_vertex\": " << f.center_vertex << ", \"scale\": " << number(f.scale)
       << ", \"energy\": " << number(f.energy) << ",\n     \"vertices\": [";
    for(std::size_t k = 0; k < f.vertices.size(); ++k)
      os << (k ? ", " : "") << f.vertices[k];
    os << "],\n     \"correspondence\": [";
    for(std::size_t k = 0; k < f.correspondence.size(); ++k)
      os << (k ? ", " : "") << "[" << f.correspondence[k].first << ", " << f.correspondence[k].second << "]";
    os << "]}";
  }
  os << "\n  ],\n  \"arrangement\": {\"edges\": [";
  for(std::size_t k = 0; k < edges.size(); ++k)
    os << (k ? ", " : "") << "[" << edges[k].first << ", " << edges[k].second << "]";
  os << "], \"triangles\": [";
  for(std::size_t k = 0; k < triangles.size(); ++k)
    os << (k ? ", " : "") << "[" << triangles[k][0] << ", " << triangles[k][1] << ", " << triangles[k][2] << "]";
  os << "]}\n}\n";
  return bool(os);
}

Patterns_found detect_patterns(const Mesh_file& file, const CGAL_ext::Pattern_patch<Mesh>& patch,
                               const Patterns_options& o, std::pair<double, double> scales,
                               const std::vector<Vertex_index>& stroke, const std::function<bool(double)>& callback)
{
  const Thread_allowance allowance(o.threads);
  Progress_line progress;
  const std::function<bool(double)> show_progress = callback ? callback : [&progress](double done) {
    progress.show_percent("patterns", done);
    return true;
  };
  std::vector<long> label_of_vertex(file.mesh.number_of_vertices(), -1);
  CGAL_ext::Pattern_statistics statistics;
  const auto np = CGAL_ext::parameters::scale_range(scales)
                    .vertex_instance_map(CGAL::make_property_map(label_of_vertex))
                    .statistics(statistics)
                    .callback(show_progress)
                    .sample_spacing(o.sample_spacing)
                    .match_tolerance(o.match_tolerance)
                    .consistency_cutoff(o.consistency_cutoff)
                    .approximation(o.lambda)
                    .number_of_threads(o.threads);
  const auto found =
    stroke.empty()
      ? CGAL_ext::detect_repetitive_patterns<CGAL::Parallel_if_available_tag>(file.mesh, patch, np)
      : CGAL_ext::detect_repetitive_patterns<CGAL::Parallel_if_available_tag>(file.mesh, patch, np.stroke(stroke));
  const std::vector<std::size_t> point = point_of_vertex(file);
  Patterns_found out;
  for(const auto& instance : found.instances) {
    Found_instance f;
    f.center = instance.center;
    f.center_vertex = point[instance.center_vertex.idx()];
    f.scale = instance.scale;
    f.energy = instance.energy;
    for(Vertex_index v : instance.vertices)
      f.vertices.push_back(point[v.idx()]);
    std::sort(f.vertices.begin(), f.vertices.end());
    f.vertices.erase(std::unique(f.vertices.begin(), f.vertices.end()), f.vertices.end());
    for(const auto& [p, q] : instance.correspondence)
      f.correspondence.emplace_back(point[p.idx()], point[q.idx()]);
    out.instances.push_back(std::move(f));
  }
  for(Vertex_index v : file.vertex_of_point)
    out.labels.push_back(label_of_vertex[v.idx()]);
  out.edges = found.arrangement_edges;
  out.triangles = found.arrangement_triangles;
  out.stats = statistics;
  return out;
}

int run_patterns(const Patterns_options& options)
{
  // Validate the command line before the (possibly long) reading and detection.
  if(options.patch_center.empty() && options.patch_vertices.empty() && options.patch_property.empty())
    throw Tool_error("mark the pattern: --patch-center S --patch-radius R, --patch-vertices FILE or --patch-property NAME");
  if(!options.patch_property.empty() &&
     (options.mesh.size() < 4 || options.mesh.compare(options.mesh.size() - 4, 4, ".ply") != 0))
    throw Tool_error("--patch-property reads a per-vertex property of a .ply mesh, not of '" + options.mesh + "'");
  const std::pair<double, double> scales =
    options.scales.empty() ? std::make_pair(1.0, 1.0) : parse_scale_range(options.scales);
  std::optional<Surface_point> center;
  if(!options.patch_center.empty()) {
    center = parse_surface_point(options.patch_center, "patch centre");
    if(!(options.patch_radius > 0) || !std::isfinite(options.patch_radius))
      throw Tool_error("--patch-radius must be positive, got " + std::to_string(options.patch_radius));
  }
  if(options.output.size() < 5 || options.output.compare(options.output.size() - 5, 5, ".json") != 0)
    throw Tool_error("--output '" + options.output + "': the instances are written as .json");
  const Output_format labels_format = options.labels.empty() ? Output_format::txt : output_format(options.labels);
  if(!options.arrangement.empty() && output_format(options.arrangement, true) != Output_format::obj)
    throw Tool_error("--arrangement '" + options.arrangement + "': the arrangement is written as .obj");
  check_distinct_outputs(
    {{"--output", options.output}, {"--labels", options.labels}, {"--arrangement", options.arrangement}});

  const Stopwatch read_watch;
  const Mesh_file file = read_mesh_file(options.mesh);
  const double seconds_read = read_watch.seconds();
  CGAL_ext::Pattern_patch<Mesh> patch;
  if(center) {
    check_surface_point_range(*center, file.soup.points.size(), file.soup.polygons.size(), "patch centre");
    std::size_t vertex = center->vertex ? *center->vertex : 0;
    if(!center->vertex) { // the corner with the largest barycentric coordinate
      const Polygons::Polygon polygon = file.soup.polygons[center->face];
      std::size_t best = 0;
      for(std::size_t k = 1; k < 3 && k < polygon.size(); ++k)
        if(center->barycentric[k] > center->barycentric[best])
          best = k;
      vertex = polygon[best];
    }
    patch = CGAL_ext::Pattern_patch<Mesh>::disk(file.vertex_of_point[vertex], options.patch_radius);
  } else if(!options.patch_property.empty()) {
    std::vector<Vertex_index> vertices;
    for(std::size_t id : read_selected_vertices_ply(options.mesh, options.patch_property, file.soup.points.size()))
      vertices.push_back(file.vertex_of_point[id]);
    patch = CGAL_ext::Pattern_patch<Mesh>::of_vertices(vertices);
  } else {
    std::ifstream in(options.patch_vertices);
    if(!in)
      throw Tool_error("cannot read --patch-vertices '" + options.patch_vertices + "'");
    std::vector<Vertex_index> vertices;
    for(std::size_t id : read_vertex_list(in, file.soup.points.size(), options.patch_vertices))
      vertices.push_back(file.vertex_of_point[id]);
    patch = CGAL_ext::Pattern_patch<Mesh>::of_vertices(vertices);
  }

  std::vector<Vertex_index> stroke;
  for(long long id : options.stroke) {
    if(id < 0 || std::size_t(id) >= file.soup.points.size())
      throw Tool_error("--stroke vertex " + std::to_string(id) + " is out of range (the mesh has " +
                       std::to_string(file.soup.points.size()) + " vertices)");
    stroke.push_back(file.vertex_of_point[std::size_t(id)]);
  }

  const Stopwatch detect_watch;
  const Patterns_found found = detect_patterns(file, patch, options, scales, stroke, {});
  const double seconds_detect = detect_watch.seconds();

  std::vector<Output_file> outputs{{options.output, [&](std::ostream& os) {
                                      return write_instances_json(os, found.instances, found.edges, found.triangles);
                                    }}};
  if(!options.labels.empty())
    outputs.push_back({options.labels, [&](std::ostream& os) {
                         return labels_format == Output_format::ply ? write_instances_ply(os, file.soup, found.labels)
                                                                    : write_labels_txt(os, found.labels);
                       }});
  if(!options.arrangement.empty()) {
    std::vector<Point> centres;
    for(const Found_instance& f : found.instances)
      centres.push_back(f.center);
    outputs.push_back({options.arrangement, [&, centres](std::ostream& os) {
                         return write_dual_obj(os, centres, found.edges, found.triangles);
                       }});
  }
  write_outputs(outputs);

  if(!file.repairs.summary().empty())
    std::cerr << "note: " << file.repairs.summary() << std::endl;
  if(options.stats) {
    const CGAL_ext::Pattern_statistics& st = found.stats;
    std::ostringstream s;
    s << "points=" << file.soup.points.size() << "\n"
      << "polygons=" << file.soup.polygons.size() << "\n"
      << "seconds_read=" << seconds_read << "\n"
      << "patch_radius=" << st.patch_radius << "\n"
      << "samples=" << st.samples << "\n"
      << "patch_samples=" << st.patch_samples << "\n"
      << "matches=" << st.matches << "\n"
      << "clusters=" << st.clusters << "\n"
      << "searches=" << st.searches << "\n"
      << "distance_rows=" << st.distance_rows << "\n"
      << "instances=" << found.instances.size() << "\n"
      << "arrangement_edges=" << found.edges.size() << "\n"
      << "seconds_sampling=" << st.seconds_sampling << "\n"
      << "seconds_signatures=" << st.seconds_signatures << "\n"
      << "seconds_matching=" << st.seconds_matching << "\n"
      << "seconds_clustering=" << st.seconds_clustering << "\n"
      << "seconds_optimization=" << st.seconds_optimization << "\n"
      << "seconds_arrangement=" << st.seconds_arrangement << "\n"
      << "seconds_detection=" << seconds_detect << "\n"
      << "peak_rss_mb=" << peak_rss_mb() << "\n";
    std::cerr << s.str() << std::flush;
  }
  return 0;
}

} // namespace geodesic_tool
