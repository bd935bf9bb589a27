// Copyright (c) 2026 The CGAL_ext geodesics developers.
// geodesic: the command-line front end of the package.
//
//   geodesic distances MESH --source S[,S...] [--algorithm vtp|pvtp|avtp|pavtp] [--lambda L]
//                      [--threads N] [--batch-size K] [--max-distance D] [--output FILE] [--stats]
//
// Vertex and face ids are those of the file (its order of vertices and faces). Every error is
// one line `error: ...` on stderr, exit code 1 (2 for a bad command line), and no output file.

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

struct Distances_options
{
  std::string mesh;
  std::vector<std::string> sources;
  std::string algorithm = "vtp";
  std::optional<double> lambda;
  std::optional<int> threads;
  std::optional<long long> batch_size;
  double max_distance = infinity;
  std::string output;
  bool stats = false;
};

/// The solvers of the library, as named on the command line.
struct Algorithm
{
  const char* name;
  bool parallel;    // CGAL::Parallel_tag
  bool approximate; // the named parameter approximation(lambda)
};

const Algorithm algorithms[] = {
  {"vtp", false, false}, {"pvtp", true, false}, {"avtp", false, true}, {"pavtp", true, true}};

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

Solver_choice solver_choice(const Distances_options& options)
{
  Solver_choice choice;
  const auto found = std::find_if(std::begin(algorithms), std::end(algorithms),
                                  [&](const Algorithm& a) { return options.algorithm == a.name; });
  if(found == std::end(algorithms))
    throw Tool_error("unknown algorithm '" + options.algorithm + "' (use vtp, pvtp, avtp or pavtp)");
  choice.algorithm = found;
  if(found->parallel && !parallel_available)
    throw Tool_error(std::string("--algorithm ") + found->name + " needs TBB; this geodesic was built without it");

  const auto invalid = [](const char* option, const char* expected, auto value) {
    return Tool_error(std::string(option) + " must be " + expected + ", got " + number_text(value));
  };
  if(!(options.max_distance >= 0))
    throw invalid("--max-distance", "a non-negative number", options.max_distance);
  choice.max_distance = options.max_distance;
  if(options.lambda) {
    if(!found->approximate)
      throw Tool_error("--lambda applies to avtp and pavtp only");
    if(!(*options.lambda > 0) || !std::isfinite(*options.lambda))
      throw invalid("--lambda", "a positive, finite number", *options.lambda);
    choice.lambda = *options.lambda;
  }
  if(options.threads) {
    if(!found->parallel)
      throw Tool_error("--threads applies to pvtp and pavtp only");
    if(*options.threads < 1)
      throw invalid("--threads", "a positive integer", *options.threads);
    choice.threads = *options.threads;
  }
  if(options.batch_size) {
    if(!found->parallel && !found->approximate)
      throw Tool_error("--batch-size applies to pvtp, avtp and pavtp only");
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

/// A source as written on the command line: a vertex id, or a face id and barycentric
/// coordinates in the order of the face's vertices in the file.
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

Source parse_source(const std::string& text)
{
  const auto bad = [&](const std::string& why) {
    return Tool_error("source '" + text + "': " + why);
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

enum class Output_format { txt, ply };

Output_format output_format(const std::string& path)
{
  const std::string ext = lowercase_extension(path);
  if(ext == ".txt")
    return Output_format::txt;
  if(ext == ".ply")
    return Output_format::ply;
  throw Tool_error("unknown output format '" + path + "' (use .txt or .ply)");
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

void check_source_range(const Source& s, const Mesh& mesh)
{
  const auto out_of_range = [&](const char* what, std::size_t i, std::size_t n, const char* plural) {
    return Tool_error("source '" + s.text + "': " + what + " " + std::to_string(i) +
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
  const auto np =
    CGAL_ext::parameters::max_distance(choice.max_distance).statistics(stats).batch_size(choice.batch_size);
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

// ---------------------------------------------------------------------------------------------
// The subcommand

int run_distances(const Distances_options& options)
{
  // Validate the command line before the (possibly long) reading and solving.
  const Solver_choice choice = solver_choice(options);
  std::vector<Source> sources;
  for(const std::string& text : options.sources)
    sources.push_back(parse_source(text));
  std::optional<Output_format> format;
  if(!options.output.empty())
    format = output_format(options.output);

  const Stopwatch read_watch;
  const Soup soup = read_soup(options.mesh);
  check_soup(soup);
  Mesh mesh = soup_to_mesh(soup);
  const double seconds_read = read_watch.seconds();
  for(const Source& s : sources)
    check_source_range(s, mesh);

  CGAL_ext::Geodesic_statistics stats;
  const auto distance = compute_distances(mesh, soup.polygons, sources, choice, stats);

  if(!format) {
    if(!write_txt(std::cout, mesh, distance) || !std::cout.flush())
      throw Tool_error("cannot write to the standard output");
  } else if(*format == Output_format::txt) {
    write_atomically(options.output, [&](std::ostream& os) { return write_txt(os, mesh, distance); });
  } else {
    write_atomically(options.output, [&](std::ostream& os) { return write_ply(os, mesh, distance); });
  }

  if(options.stats) {
    std::ostringstream s;
    s << "algorithm=" << choice.algorithm->name << "\n";
    if(choice.algorithm->parallel)
      s << "threads=" << effective_threads(choice) << "\n";
    if(choice.algorithm->approximate)
      s << "lambda=" << number_text(choice.lambda) << "\n";
    s << "vertices=" << mesh.number_of_vertices() << "\n"
      << "faces=" << mesh.number_of_faces() << "\n"
      << "sources=" << sources.size() << "\n"
      << "seconds_read=" << seconds_read << "\n"
      << "seconds_setup=" << stats.seconds_setup << "\n"
      << "seconds_solve=" << stats.seconds_solve << "\n"
      << "seconds_selection=" << stats.seconds_selection << "\n"
      << "seconds_propagation=" << stats.seconds_propagation << "\n"
      << "seconds_merge=" << stats.seconds_merge << "\n"
      << "windows_created=" << stats.windows_created << "\n"
      << "peak_windows=" << stats.peak_windows << "\n"
      << "lists_propagated=" << stats.lists_propagated << "\n"
      << "wavefront_resets=" << stats.wavefront_resets << "\n"
      << "peak_rss_mb=" << peak_rss_mb() << "\n"
      << "max_distance=" << std::setprecision(17) << farthest_finite(mesh, distance) << "\n";
    std::cerr << s.str() << std::flush;
  }
  return 0;
}

void add_distances_command(CLI::App& app, Distances_options& options)
{
  CLI::App* cmd = app.add_subcommand("distances", "Geodesic distance from the nearest source to every vertex");
  cmd->add_option("MESH", options.mesh, "Triangle mesh (.off, .obj or .ply); vertex ids are the file order")
    ->required();
  cmd->add_option("--source", options.sources,
                  "Sources, comma-separated: a vertex id, or f:FACE:b0:b1:b2 (barycentric coordinates in "
                  "the order of the face's vertices in the file)")
    ->required()
    ->delimiter(',')
    ->allow_extra_args(false);
  cmd->add_option("--algorithm", options.algorithm,
                  "Solver: vtp (exact), pvtp (exact, parallel), avtp (approximate), pavtp (approximate, "
                  "parallel); default: vtp");
  cmd->add_option("--lambda", options.lambda,
                  "avtp and pavtp: the wavefront is reset every lambda mean edge lengths; smaller is faster "
                  "and coarser, distances are never below the exact ones; positive; default: " +
                    number_text(default_lambda));
  cmd->add_option("--threads", options.threads,
                  "pvtp and pavtp: number of threads, at least 1; default: all cores");
  cmd->add_option("--batch-size", options.batch_size,
                  "pvtp, avtp and pavtp: window lists propagated together, at least 1 (avtp and pavtp "
                  "give the same distances for the same batch size); default: " +
                    std::to_string(CGAL_ext::default_batch_size));
  cmd->add_option("--max-distance", options.max_distance,
                  "Stop the propagation at this distance; farther vertices get inf");
  cmd->add_option("--output", options.output,
                  "Output file: .txt (one distance per line, vertex order) or .ply (mesh with a per-vertex "
                  "'distance' and a colour ramp); default: txt on the standard output");
  cmd->add_flag("--stats", options.stats, "Print key=value statistics on the standard error");
}

} // namespace

int main(int argc, char** argv)
{
  CLI::App app{"Geodesic distances on triangle meshes, exact or approximate", "geodesic"};
  // At most one subcommand: CLI11 then reports an unknown one as unexpected, not as missing.
  app.require_subcommand(0, 1);
  Distances_options distances;
  add_distances_command(app, distances);

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
  } catch(const CGAL_ext::Geodesic_error& e) {
    std::cerr << "error: " << e.what() << std::endl;
  } catch(const std::exception& e) {
    std::cerr << "error: " << e.what() << std::endl;
  }
  return 1;
}
