// Copyright (c) 2026 The CGAL_ext geodesics developers.
// geodesic: the command-line front end of the package.
//
//   geodesic distances MESH --source S[,S...] [--algorithm vtp|pvtp|avtp|pavtp|mmp|fwp-mmp|pmmp]
//                      [--lambda L] [--threads N] [--batch-size K] [--max-distance D]
//                      [--output FILE.txt|FILE.ply] [--stats]
//   geodesic path MESH --source S[,S...] --target T [--algorithm fwp-mmp|mmp|pmmp] [--threads N]
//                 [--batch-size K] [--max-distance D] [--output FILE.txt|FILE.obj|FILE.ply] [--stats]
//
// S and T are a vertex id or a face point f:FACE:b0:b1:b2 (barycentric coordinates in the order
// of the face's vertices in the file). Vertex and face ids are those of the file (its order of
// vertices and faces). `path` writes the shortest path from the nearest source to T as a
// polyline, the source first. Every error is one line `error: ...` on stderr, exit code 1 (2 for
// a bad command line), and no output file.

#include <CGAL_ext/Surface_mesh_geodesic_paths.h>
#include <CGAL_ext/geodesic_distances.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/Color.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <CLI/CLI.hpp>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Mesh;
typedef Mesh::Vertex_index Vertex_index;
typedef Mesh::Face_index Face_index;
typedef std::pair<Face_index, std::array<double, 3>> Face_location;
typedef std::vector<std::vector<std::size_t>> Polygons;

const double infinity = std::numeric_limits<double>::infinity();

/// An error in the input of the tool (file, source, option); its message is printed as is.
struct Tool_error : std::runtime_error
{
  explicit Tool_error(const std::string& what) : std::runtime_error(what) {}
};

class Stopwatch
{
public:
  double seconds() const { return std::chrono::duration<double>(Clock::now() - m_start).count(); }

private:
  typedef std::chrono::steady_clock Clock;
  Clock::time_point m_start = Clock::now();
};

std::string lowercase_extension(const std::string& path)
{
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

/// The shortest text that reads back as `value` (nan and inf as such).
template <class T>
std::string number_text(T value)
{
  char text[64];
  const auto result = std::to_chars(text, text + sizeof(text), value);
  return std::string(text, result.ptr);
}

// ---------------------------------------------------------------------------------------------
// Command line

/// The solver options of both subcommands.
struct Solver_options
{
  std::string algorithm;
  std::optional<double> lambda; // distances only
  std::optional<int> threads;
  std::optional<long long> batch_size;
  double max_distance = infinity;
};

struct Distances_options
{
  std::string mesh;
  std::vector<std::string> sources;
  Solver_options solver{"vtp"};
  std::string output;
  bool stats = false;
};

struct Path_options
{
  std::string mesh;
  std::vector<std::string> sources;
  std::string target;
  Solver_options solver{"fwp-mmp"};
  std::string output;
  bool stats = false;
};

/// The solvers of the library, as named on the command line.
struct Algorithm
{
  const char* name;
  bool parallel;                        // CGAL::Parallel_tag
  bool approximate;                     // the named parameter approximation(lambda)
  CGAL_ext::Geodesic_algorithm library; // the named parameter algorithm()
};

const Algorithm algorithms[] = {
  {"vtp", false, false, CGAL_ext::VTP},      {"pvtp", true, false, CGAL_ext::VTP},
  {"avtp", false, true, CGAL_ext::VTP},      {"pavtp", true, true, CGAL_ext::VTP},
  {"fwp-mmp", false, false, CGAL_ext::FWP_MMP}, {"mmp", false, false, CGAL_ext::MMP},
  {"pmmp", true, false, CGAL_ext::FWP_MMP}};

/// Whether the solver keeps its windows on the edges (the MMP family), which paths need.
bool keeps_windows(const Algorithm& a) { return a.library != CGAL_ext::VTP; }

/// The names of the algorithms that satisfy `wanted` (and keep windows, for paths), as
/// "a, b and c" (`conjunction` "and" or "or").
template <class Predicate>
std::string algorithm_names(Predicate wanted, bool for_paths, const char* conjunction)
{
  std::vector<std::string> names;
  for(const Algorithm& a : algorithms)
    if(wanted(a) && (!for_paths || keeps_windows(a)))
      names.push_back(a.name);
  std::string text;
  for(std::size_t i = 0; i < names.size(); ++i)
    text += (i == 0 ? "" : (i + 1 == names.size() ? std::string(" ") + conjunction + " " : ", ")) + names[i];
  return text;
}

const double default_lambda = 8;

#ifdef CGAL_LINKED_WITH_TBB
typedef CGAL::Parallel_tag Parallel_tag;
const bool parallel_available = true;
#else
typedef CGAL::Sequential_tag Parallel_tag; // never run: solver_choice() refuses pvtp and pavtp
const bool parallel_available = false;
#endif

/// While alive, lets the library's arena of `threads` threads (0: TBB's default) have them all.
/// Otherwise TBB caps its workers at the number of cores minus one and, asked for more, prints a
/// warning on the standard error. The tool owns its process, so a process-wide limit is fine here.
class Thread_allowance
{
public:
  explicit Thread_allowance(int threads)
  {
#ifdef CGAL_LINKED_WITH_TBB
    if(threads > 0)
      m_control.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#else
    (void)threads;
#endif
  }

private:
#ifdef CGAL_LINKED_WITH_TBB
  std::optional<tbb::global_control> m_control;
#endif
};

/// The validated choice of solver and its parameters.
struct Solver_choice
{
  const Algorithm* algorithm = &algorithms[0];
  double lambda = default_lambda; // approximate solvers only
  int threads = 0;                // parallel solvers only; 0: TBB's default
  std::size_t batch_size = CGAL_ext::default_batch_size;
  double max_distance = infinity;
};

/// Checks the solver options of `distances`, or of `path` (`for_paths`: the MMP family only).
Solver_choice solver_choice(const Solver_options& options, bool for_paths)
{
  const auto any = [](const Algorithm&) { return true; };
  Solver_choice choice;
  const auto found = std::find_if(std::begin(algorithms), std::end(algorithms),
                                  [&](const Algorithm& a) { return options.algorithm == a.name; });
  if(found == std::end(algorithms))
    throw Tool_error("unknown algorithm '" + options.algorithm + "' (use " + algorithm_names(any, for_paths, "or") +
                     ")");
  if(for_paths && !keeps_windows(*found))
    throw Tool_error(std::string("--algorithm ") + found->name + " keeps no windows and cannot trace paths (use " +
                     algorithm_names(any, true, "or") + ")");
  choice.algorithm = found;
  if(found->parallel && !parallel_available)
    throw Tool_error(std::string("--algorithm ") + found->name + " needs TBB; this geodesic was built without it");
  choice.batch_size = keeps_windows(*found) ? CGAL_ext::default_window_batch_size : CGAL_ext::default_batch_size;

  const auto invalid = [](const char* option, const char* expected, auto value) {
    return Tool_error(std::string(option) + " must be " + expected + ", got " + number_text(value));
  };
  const auto applies_to = [&](const char* option, auto wanted) {
    return Tool_error(std::string(option) + " applies to " + algorithm_names(wanted, for_paths, "and") + " only");
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

/// The number of threads a parallel solver runs on.
int effective_threads(const Solver_choice& choice)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(choice.threads == 0)
    return tbb::this_task_arena::max_concurrency(); // what the library's automatic arena gets
#endif
  return choice.threads;
}

/// A source or a target as written on the command line: a vertex id, or a face id and
/// barycentric coordinates in the order of the face's vertices in the file.
struct Source
{
  std::string text;
  std::optional<std::size_t> vertex;
  std::size_t face = 0;
  std::array<double, 3> barycentric{{0., 0., 0.}};
};

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

/// `role` ("source" or "target") names the point in error messages.
Source parse_source(const std::string& text, const char* role = "source")
{
  const auto bad = [&](const std::string& why) {
    return Tool_error(std::string(role) + " '" + text + "': " + why);
  };
  Source s;
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
  const auto& b = s.barycentric;
  if(b[0] < 0 || b[1] < 0 || b[2] < 0)
    throw bad("barycentric coordinates must be non-negative");
  const double sum = b[0] + b[1] + b[2];
  if(std::abs(sum - 1.) > 1e-9) { // the library's tolerance
    std::ostringstream msg;
    msg.precision(17);
    msg << "barycentric coordinates sum to " << sum << ", not 1";
    throw bad(msg.str());
  }
  return s;
}

enum class Output_format { txt, obj, ply };

/// The format of an output file, by its extension; .obj only where `obj_allowed` (paths).
Output_format output_format(const std::string& path, bool obj_allowed = false)
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

// ---------------------------------------------------------------------------------------------
// Mesh reading

struct Soup
{
  std::vector<Point> points;
  Polygons polygons;
};

Soup read_soup(const std::string& path)
{
  const std::string ext = lowercase_extension(path);
  Soup soup;
  if((ext != ".off" && ext != ".obj" && ext != ".ply") || !std::filesystem::is_regular_file(path) ||
     !CGAL::IO::read_polygon_soup(path, soup.points, soup.polygons))
    throw Tool_error("cannot read mesh '" + path + "'");
  if(soup.polygons.empty())
    throw Tool_error("mesh '" + path + "' has no faces");
  return soup;
}

// Corner c of the soup is corner c % 3 of triangle c / 3.
class Union_find
{
public:
  explicit Union_find(std::size_t n) : m_parent(n) { std::iota(m_parent.begin(), m_parent.end(), 0); }
  std::size_t find(std::size_t i)
  {
    while(m_parent[i] != i)
      i = m_parent[i] = m_parent[m_parent[i]];
    return i;
  }
  void unite(std::size_t i, std::size_t j) { m_parent[find(i)] = find(j); }

private:
  std::vector<std::size_t> m_parent;
};

std::size_t corner_of(const Polygons& triangles, std::size_t f, std::size_t v)
{
  const auto& t = triangles[f];
  return 3 * f + std::size_t(std::find(t.begin(), t.end(), v) - t.begin());
}

std::string edge_text(std::size_t a, std::size_t b)
{
  return "(" + std::to_string(a) + ", " + std::to_string(b) + ")";
}

/// Names what keeps a triangle soup from being a manifold, oriented mesh, for the error message.
std::string describe_non_manifold(const Polygons& triangles, std::size_t number_of_points)
{
  // the faces around each undirected edge (smaller id first), in file order
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> edge_faces;
  for(std::size_t f = 0; f < triangles.size(); ++f) {
    const auto& t = triangles[f];
    if(t[0] == t[1] || t[1] == t[2] || t[2] == t[0])
      return "face " + std::to_string(f) + " uses a vertex twice";
    for(int k = 0; k < 3; ++k)
      edge_faces[std::minmax(t[k], t[(k + 1) % 3])].push_back(f);
  }
  Union_find fans(3 * triangles.size());
  for(const auto& [edge, faces] : edge_faces) {
    const auto [a, b] = edge;
    if(faces.size() > 2)
      return "non-manifold edge " + edge_text(a, b) + ": shared by " + std::to_string(faces.size()) +
             " faces";
    if(faces.size() < 2)
      continue;
    // consistently oriented neighbours run along the edge in opposite directions
    const std::size_t ca = corner_of(triangles, faces[0], a), cb = corner_of(triangles, faces[0], b);
    const std::size_t da = corner_of(triangles, faces[1], a), db = corner_of(triangles, faces[1], b);
    if((cb % 3 == (ca + 1) % 3) == (db % 3 == (da + 1) % 3))
      return "faces " + std::to_string(faces[0]) + " and " + std::to_string(faces[1]) +
             " are inconsistently oriented across edge " + edge_text(a, b);
    fans.unite(ca, da);
    fans.unite(cb, db);
  }
  // a vertex is manifold when the corners around it form a single fan
  std::vector<std::size_t> fan_of(number_of_points, std::size_t(-1));
  for(std::size_t c = 0; c < 3 * triangles.size(); ++c) {
    const std::size_t v = triangles[c / 3][c % 3];
    const std::size_t fan = fans.find(c);
    if(fan_of[v] == std::size_t(-1))
      fan_of[v] = fan;
    else if(fan_of[v] != fan)
      return "non-manifold vertex " + std::to_string(v) + ": its faces form more than one fan";
  }
  return "the mesh is not a manifold triangle mesh";
}

void check_soup(const Soup& soup)
{
  for(std::size_t v = 0; v < soup.points.size(); ++v) {
    const Point& p = soup.points[v];
    if(!std::isfinite(p.x()) || !std::isfinite(p.y()) || !std::isfinite(p.z())) {
      std::ostringstream msg;
      msg << "vertex " << v << " has a non-finite coordinate (" << p << ")";
      throw Tool_error(msg.str());
    }
  }
  for(std::size_t f = 0; f < soup.polygons.size(); ++f) {
    const auto& polygon = soup.polygons[f];
    if(polygon.size() != 3)
      throw Tool_error("face " + std::to_string(f) + " has " + std::to_string(polygon.size()) +
                       " vertices; only triangle meshes are supported");
    for(std::size_t v : polygon)
      if(v >= soup.points.size())
        throw Tool_error("face " + std::to_string(f) + " uses vertex " + std::to_string(v) +
                         " but the mesh has " + std::to_string(soup.points.size()) + " vertices");
  }
  if(!CGAL::Polygon_mesh_processing::is_polygon_soup_a_polygon_mesh(soup.polygons))
    throw Tool_error(describe_non_manifold(soup.polygons, soup.points.size()));
}

/// Vertex i of the mesh is point i of the soup and face j is polygon j (isolated points are kept).
Mesh soup_to_mesh(const Soup& soup)
{
  Mesh mesh;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(soup.points, soup.polygons, mesh);
  if(mesh.number_of_vertices() != soup.points.size() || mesh.number_of_faces() != soup.polygons.size())
    throw Tool_error("the mesh is not a manifold triangle mesh");
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// Sources

void check_source_range(const Source& s, const Mesh& mesh, const char* role = "source")
{
  const auto out_of_range = [&](const char* what, std::size_t i, std::size_t n, const char* plural) {
    return Tool_error(std::string(role) + " '" + s.text + "': " + what + " " + std::to_string(i) +
                      " is out of range (the mesh has " + std::to_string(n) + " " + plural + ")");
  };
  if(s.vertex && *s.vertex >= mesh.number_of_vertices())
    throw out_of_range("vertex", *s.vertex, mesh.number_of_vertices(), "vertices");
  if(!s.vertex && s.face >= mesh.number_of_faces())
    throw out_of_range("face", s.face, mesh.number_of_faces(), "faces");
}

/// The library orders barycentric coordinates from source(halfedge(f)); Euler::add_face() does
/// not make that the polygon's first vertex, so the file order is mapped corner by corner.
Face_location library_location(const Mesh& mesh, const std::vector<std::size_t>& polygon, Face_index f,
                               const std::array<double, 3>& file_barycentric)
{
  Face_location location(f, {{0., 0., 0.}});
  int k = 0;
  for(auto h : CGAL::halfedges_around_face(mesh.halfedge(f), mesh)) {
    const std::size_t v = mesh.source(h);
    location.second[k++] = file_barycentric[std::find(polygon.begin(), polygon.end(), v) - polygon.begin()];
  }
  return location;
}

/// A vertex source as a corner of one of its faces, so that it can join face-point sources.
Face_location vertex_location(const Mesh& mesh, const Source& s)
{
  const Vertex_index v(static_cast<Mesh::size_type>(*s.vertex));
  for(auto h : CGAL::halfedges_around_target(v, mesh)) {
    if(mesh.is_border(h))
      continue;
    const Face_index f = mesh.face(h);
    std::array<double, 3> barycentric{{0., 0., 0.}};
    int k = 0;
    for(auto g : CGAL::halfedges_around_face(mesh.halfedge(f), mesh))
      barycentric[k++] = mesh.source(g) == v ? 1. : 0.;
    return Face_location(f, barycentric);
  }
  throw Tool_error("source '" + s.text + "': an isolated vertex cannot be mixed with face-point sources");
}

typedef Mesh::Property_map<Vertex_index, double> Distance_map;

/// The library call for one concurrency tag; `approximation` is a named parameter that is
/// either present or absent, so it is chosen here rather than given a neutral value.
template <class ConcurrencyTag, class LibrarySources, class NamedParameters>
void solve_with(const Mesh& mesh, Distance_map distance, const LibrarySources& sources,
                const Solver_choice& choice, const NamedParameters& np)
{
  if(choice.algorithm->approximate)
    CGAL_ext::geodesic_distances<ConcurrencyTag>(mesh, distance, sources, np.approximation(choice.lambda));
  else
    CGAL_ext::geodesic_distances<ConcurrencyTag>(mesh, distance, sources, np);
}

/// The one place that maps the algorithm choice to the library call.
template <class LibrarySources>
void solve(const Mesh& mesh, Distance_map distance, const LibrarySources& sources, const Solver_choice& choice,
           CGAL_ext::Geodesic_statistics& stats)
{
  const auto np = CGAL_ext::parameters::max_distance(choice.max_distance)
                    .statistics(stats)
                    .batch_size(choice.batch_size)
                    .algorithm(choice.algorithm->library);
  if(choice.algorithm->parallel) {
    const Thread_allowance allowance(choice.threads);
    solve_with<Parallel_tag>(mesh, distance, sources, choice, np.number_of_threads(choice.threads));
  } else {
    solve_with<CGAL::Sequential_tag>(mesh, distance, sources, choice, np);
  }
}

/// Runs the library and stores the distances in the vertex property "v:distance".
Distance_map compute_distances(Mesh& mesh, const Polygons& polygons, const std::vector<Source>& sources,
                               const Solver_choice& choice, CGAL_ext::Geodesic_statistics& stats)
{
  auto distance = mesh.add_property_map<Vertex_index, double>("v:distance", infinity).first;
  // The library takes a range of one kind of source: vertices, or face locations.
  const bool only_vertices =
    std::all_of(sources.begin(), sources.end(), [](const Source& s) { return bool(s.vertex); });
  if(only_vertices) {
    std::vector<Vertex_index> vertices;
    for(const Source& s : sources)
      vertices.emplace_back(static_cast<Mesh::size_type>(*s.vertex));
    solve(mesh, distance, vertices, choice, stats);
  } else {
    std::vector<Face_location> locations;
    for(const Source& s : sources) {
      const Face_index f(static_cast<Mesh::size_type>(s.face));
      locations.push_back(s.vertex ? vertex_location(mesh, s)
                                   : library_location(mesh, polygons[s.face], f, s.barycentric));
    }
    solve(mesh, distance, locations, choice, stats);
  }
  return distance;
}

// ---------------------------------------------------------------------------------------------
// Paths

/// A shortest path and what it took.
struct Path_result
{
  std::vector<Point> points; // from the source to the target
  double distance = infinity; // the library's distance of the target
  std::size_t nearest_source = 0; // among the sources, in command-line order
  CGAL_ext::Geodesic_statistics stats;
  double seconds_build = 0; // preparing the mesh, adding the sources and building the windows
  double seconds_query = 0; // the distance, the nearest source and the path of the target
};

/// Builds the windows from `sources` with the chosen MMP solver and traces the path to `target`.
template <class ConcurrencyTag>
Path_result trace_path(const Mesh& mesh, const Polygons& polygons, const std::vector<Source>& sources,
                       const Source& target, const Solver_choice& choice)
{
  typedef CGAL_ext::Surface_mesh_geodesic_paths<Mesh, ConcurrencyTag> Paths;
  const auto location = [&](const Source& s) {
    const Face_index f(static_cast<Mesh::size_type>(s.face));
    return library_location(mesh, polygons[s.face], f, s.barycentric);
  };
  Path_result result;
  const Stopwatch build_watch;
  Paths paths(mesh);
  for(const Source& s : sources) {
    if(s.vertex)
      paths.add_source(Vertex_index(static_cast<Mesh::size_type>(*s.vertex)));
    else
      paths.add_source(location(s));
  }
  {
    const Thread_allowance allowance(choice.algorithm->parallel ? choice.threads : 0);
    paths.build(CGAL_ext::parameters::max_distance(choice.max_distance)
                  .statistics(result.stats)
                  .batch_size(choice.batch_size)
                  .number_of_threads(choice.algorithm->parallel ? choice.threads : 0)
                  .algorithm(choice.algorithm->library));
  }
  result.seconds_build = build_watch.seconds();

  const Stopwatch query_watch;
  const auto query = [&](const auto& point) {
    result.distance = paths.distance(point);
    if(!(result.distance < infinity))
      throw Tool_error("target '" + target.text +
                       "' is not reached by any source (it lies in another connected component" +
                       (choice.max_distance < infinity ? " or beyond --max-distance)" : ")"));
    result.nearest_source = paths.nearest_source(point);
    paths.shortest_path_points(point, std::back_inserter(result.points));
  };
  if(target.vertex)
    query(Vertex_index(static_cast<Mesh::size_type>(*target.vertex)));
  else
    query(location(target));
  result.seconds_query = query_watch.seconds();
  if(result.points.empty() || result.nearest_source >= sources.size())
    throw Tool_error("internal error: no path to target '" + target.text + "' at distance " +
                     number_text(result.distance) + "; please report it");
  return result;
}

double polyline_length(const std::vector<Point>& points)
{
  double length = 0;
  for(std::size_t i = 1; i < points.size(); ++i)
    length += std::sqrt(CGAL::squared_distance(points[i - 1], points[i]));
  return length;
}

// ---------------------------------------------------------------------------------------------
// Output

/// Writes through a temporary file next to `path`, renamed over it only once complete, so that an
/// error never leaves a partial file behind nor clobbers an existing one.
void write_atomically(const std::string& path, const std::function<bool(std::ostream&)>& write)
{
  const std::string temporary = path + ".tmp" + std::to_string(::getpid());
  try {
    std::ofstream os(temporary, std::ios::binary);
    if(!os || !write(os) || !os.flush())
      throw Tool_error("cannot write '" + path + "'");
    os.close();
    if(std::rename(temporary.c_str(), path.c_str()) != 0)
      throw Tool_error("cannot write '" + path + "'");
  } catch(...) {
    std::remove(temporary.c_str());
    throw;
  }
}

bool write_txt(std::ostream& os, const Mesh& mesh, Mesh::Property_map<Vertex_index, double> distance)
{
  char line[64];
  for(Vertex_index v : mesh.vertices()) {
    std::snprintf(line, sizeof(line), "%.17g\n", distance[v]); // prints inf for +infinity
    os << line;
  }
  return bool(os);
}

CGAL::IO::Color ramp_color(double d, double farthest)
{
  if(!std::isfinite(d))
    return CGAL::IO::Color(128, 128, 128);
  const double t = farthest > 0 ? d / farthest : 0.;
  const auto level = [](double x) { return static_cast<unsigned char>(std::lround(255 * x)); };
  return CGAL::IO::Color(level(t), 0, level(1 - t)); // blue near, red far
}

double farthest_finite(const Mesh& mesh, Mesh::Property_map<Vertex_index, double> distance)
{
  double farthest = 0;
  for(Vertex_index v : mesh.vertices())
    if(std::isfinite(distance[v]))
      farthest = std::max(farthest, distance[v]);
  return farthest;
}

/// Binary PLY: the vertex property "v:distance" becomes the PLY property `distance`, exactly.
bool write_ply(std::ostream& os, Mesh& mesh, Mesh::Property_map<Vertex_index, double> distance)
{
  const double farthest = farthest_finite(mesh, distance);
  auto color = mesh.add_property_map<Vertex_index, CGAL::IO::Color>("v:color").first;
  for(Vertex_index v : mesh.vertices())
    color[v] = ramp_color(distance[v], farthest);
  CGAL::IO::set_mode(os, CGAL::IO::BINARY);
  return CGAL::IO::write_PLY(os, mesh, "geodesic distances from the geodesic tool");
}

double peak_rss_mb()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.; // kilobytes on Linux
}

/// One point of a polyline, full precision.
std::string point_text(const Point& p)
{
  char text[96];
  std::snprintf(text, sizeof(text), "%.17g %.17g %.17g", p.x(), p.y(), p.z());
  return text;
}

/// One `x y z` line per point.
bool write_path_txt(std::ostream& os, const std::vector<Point>& points)
{
  for(const Point& p : points)
    os << point_text(p) << "\n";
  return bool(os);
}

/// `v` lines and one `l` line through them (none for a single point: a line needs two).
bool write_path_obj(std::ostream& os, const std::vector<Point>& points)
{
  os << "# geodesic path from the geodesic tool, from the source to the target\n";
  for(const Point& p : points)
    os << "v " << point_text(p) << "\n";
  if(points.size() >= 2) {
    os << "l";
    for(std::size_t i = 1; i <= points.size(); ++i)
      os << " " << i;
    os << "\n";
  }
  return bool(os);
}

/// ASCII PLY: the points, and an edge between consecutive ones.
bool write_path_ply(std::ostream& os, const std::vector<Point>& points)
{
  const std::size_t edges = points.empty() ? 0 : points.size() - 1;
  os << "ply\n"
     << "format ascii 1.0\n"
     << "comment geodesic path from the geodesic tool, from the source to the target\n"
     << "element vertex " << points.size() << "\n"
     << "property double x\n"
     << "property double y\n"
     << "property double z\n"
     << "element edge " << edges << "\n"
     << "property int vertex1\n"
     << "property int vertex2\n"
     << "end_header\n";
  for(const Point& p : points)
    os << point_text(p) << "\n";
  for(std::size_t i = 0; i < edges; ++i)
    os << i << " " << i + 1 << "\n";
  return bool(os);
}

// ---------------------------------------------------------------------------------------------
// Statistics

/// What the library reports of a solver run, as `key=value` lines; the MMP family adds its own.
void write_solver_stats(std::ostream& s, const Solver_choice& choice, const CGAL_ext::Geodesic_statistics& stats)
{
  s << "seconds_setup=" << stats.seconds_setup << "\n"
    << "seconds_solve=" << stats.seconds_solve << "\n"
    << "seconds_selection=" << stats.seconds_selection << "\n"
    << "seconds_propagation=" << stats.seconds_propagation << "\n"
    << "seconds_merge=" << stats.seconds_merge << "\n"
    << "windows_created=" << stats.windows_created << "\n"
    << "peak_windows=" << stats.peak_windows << "\n"
    << "lists_propagated=" << stats.lists_propagated << "\n"
    << "wavefront_resets=" << stats.wavefront_resets << "\n";
  if(keeps_windows(*choice.algorithm))
    s << "windows_propagated=" << stats.windows_propagated << "\n"
      << "windows_stored=" << stats.windows_stored << "\n"
      << "stored_window_bytes=" << stats.stored_window_bytes << "\n"
      << "seconds_organization=" << stats.seconds_organization << "\n"
      << "seconds_clipping=" << stats.seconds_clipping << "\n"
      << "seconds_pushing=" << stats.seconds_pushing << "\n";
}

/// The first lines of --stats: the solver, the mesh and the reading.
void write_input_stats(std::ostream& s, const Solver_choice& choice, const Mesh& mesh, std::size_t sources,
                       double seconds_read)
{
  s << "algorithm=" << choice.algorithm->name << "\n";
  if(choice.algorithm->parallel)
    s << "threads=" << effective_threads(choice) << "\n";
  if(choice.algorithm->approximate)
    s << "lambda=" << number_text(choice.lambda) << "\n";
  s << "vertices=" << mesh.number_of_vertices() << "\n"
    << "faces=" << mesh.number_of_faces() << "\n"
    << "sources=" << sources << "\n"
    << "seconds_read=" << seconds_read << "\n";
}

// ---------------------------------------------------------------------------------------------
// The subcommands

/// The mesh of the file, checked, and how long reading it took.
Mesh read_mesh(const std::string& path, Soup& soup, double& seconds)
{
  const Stopwatch read_watch;
  soup = read_soup(path);
  check_soup(soup);
  Mesh mesh = soup_to_mesh(soup);
  seconds = read_watch.seconds();
  return mesh;
}

std::vector<Source> parse_sources(const std::vector<std::string>& texts)
{
  std::vector<Source> sources;
  for(const std::string& text : texts)
    sources.push_back(parse_source(text));
  return sources;
}

/// Writes with `write` to the file `path`, atomically, or to the standard output when there is
/// no path.
void write_output(const std::string& path, const std::function<bool(std::ostream&)>& write)
{
  if(path.empty()) {
    if(!write(std::cout) || !std::cout.flush())
      throw Tool_error("cannot write to the standard output");
  } else {
    write_atomically(path, write);
  }
}

int run_distances(const Distances_options& options)
{
  // Validate the command line before the (possibly long) reading and solving.
  const Solver_choice choice = solver_choice(options.solver, false);
  const std::vector<Source> sources = parse_sources(options.sources);
  const Output_format format = options.output.empty() ? Output_format::txt : output_format(options.output);

  Soup soup;
  double seconds_read = 0;
  Mesh mesh = read_mesh(options.mesh, soup, seconds_read);
  for(const Source& s : sources)
    check_source_range(s, mesh);

  CGAL_ext::Geodesic_statistics stats;
  const auto distance = compute_distances(mesh, soup.polygons, sources, choice, stats);

  write_output(options.output, [&](std::ostream& os) {
    return format == Output_format::ply ? write_ply(os, mesh, distance) : write_txt(os, mesh, distance);
  });

  if(options.stats) {
    std::ostringstream s;
    write_input_stats(s, choice, mesh, sources.size(), seconds_read);
    write_solver_stats(s, choice, stats);
    s << "peak_rss_mb=" << peak_rss_mb() << "\n"
      << "max_distance=" << std::setprecision(17) << farthest_finite(mesh, distance) << "\n";
    std::cerr << s.str() << std::flush;
  }
  return 0;
}

int run_path(const Path_options& options)
{
  // Validate the command line before the (possibly long) reading and building.
  const Solver_choice choice = solver_choice(options.solver, true);
  const std::vector<Source> sources = parse_sources(options.sources);
  const Source target = parse_source(options.target, "target");
  const Output_format format = options.output.empty() ? Output_format::txt : output_format(options.output, true);

  Soup soup;
  double seconds_read = 0;
  const Mesh mesh = read_mesh(options.mesh, soup, seconds_read);
  for(const Source& s : sources)
    check_source_range(s, mesh);
  check_source_range(target, mesh, "target");

  const Path_result path = choice.algorithm->parallel
                             ? trace_path<Parallel_tag>(mesh, soup.polygons, sources, target, choice)
                             : trace_path<CGAL::Sequential_tag>(mesh, soup.polygons, sources, target, choice);

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

  if(options.stats) {
    std::ostringstream s;
    write_input_stats(s, choice, mesh, sources.size(), seconds_read);
    s << "seconds_build=" << path.seconds_build << "\n"
      << "seconds_query=" << path.seconds_query << "\n";
    write_solver_stats(s, choice, path.stats);
    s << "peak_rss_mb=" << peak_rss_mb() << "\n"
      << "length=" << number_text(polyline_length(path.points)) << "\n"
      << "distance=" << number_text(path.distance) << "\n"
      << "points=" << path.points.size() << "\n"
      << "nearest_source=" << path.nearest_source << "\n";
    std::cerr << s.str() << std::flush;
  }
  return 0;
}

const char* const point_help = "a vertex id, or f:FACE:b0:b1:b2 (barycentric coordinates in the order of the "
                               "face's vertices in the file)";

// The arguments every subcommand starts with: the mesh and the sources.
template <class Sources>
void add_mesh_and_sources(CLI::App& cmd, std::string& mesh, Sources& sources)
{
  cmd.add_option("MESH", mesh, "Triangle mesh (.off, .obj or .ply); vertex ids are the file order")->required();
  cmd.add_option("--source", sources, std::string("Sources, comma-separated: ") + point_help)
    ->required()
    ->delimiter(',')
    ->allow_extra_args(false);
}

void add_distances_command(CLI::App& app, Distances_options& options)
{
  CLI::App* cmd = app.add_subcommand("distances", "Geodesic distance from the nearest source to every vertex");
  add_mesh_and_sources(*cmd, options.mesh, options.sources);
  cmd->add_option("--algorithm", options.solver.algorithm,
                  "Solver: vtp (exact), pvtp (exact, parallel), avtp (approximate), pavtp (approximate, "
                  "parallel), mmp (exact, windows in exact order), fwp-mmp (exact, windows bucket by bucket), "
                  "pmmp (fwp-mmp in parallel); default: vtp");
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
                  "Output file: .txt (one distance per line, vertex order) or .ply (mesh with a per-vertex "
                  "'distance' and a colour ramp); default: txt on the standard output");
  cmd->add_flag("--stats", options.stats, "Print key=value statistics on the standard error");
}

void add_path_command(CLI::App& app, Path_options& options)
{
  CLI::App* cmd = app.add_subcommand("path", "Shortest geodesic path from the nearest source to a target point");
  add_mesh_and_sources(*cmd, options.mesh, options.sources);
  cmd->add_option("--target", options.target, std::string("The end of the path: ") + point_help)->required();
  cmd->add_option("--algorithm", options.solver.algorithm,
                  "Solver: fwp-mmp (windows bucket by bucket), mmp (windows in exact order), pmmp (fwp-mmp in "
                  "parallel); all exact; default: fwp-mmp");
  cmd->add_option("--threads", options.solver.threads, "pmmp: number of threads, at least 1; default: all cores");
  cmd->add_option("--batch-size", options.solver.batch_size,
                  "pmmp: windows propagated together, at least 1; default: " +
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

} // namespace

int main(int argc, char** argv)
{
  CLI::App app{"Geodesic distances and shortest paths on triangle meshes", "geodesic"};
  // At most one subcommand: CLI11 then reports an unknown one as unexpected, not as missing.
  app.require_subcommand(0, 1);
  Distances_options distances;
  add_distances_command(app, distances);
  Path_options path;
  add_path_command(app, path);

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
  } catch(const CGAL_ext::Geodesic_error& e) {
    std::cerr << "error: " << e.what() << std::endl;
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << std::endl;
  }
  return 1;
}
