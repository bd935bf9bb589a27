// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The command line of the geodesic tool: the options of each subcommand, and their checking
// (solver options, sources and targets, output file names). Every check throws Tool_error
// naming the option or the point and what is wrong with it.

#ifndef GEODESIC_TOOL_OPTIONS_H
#define GEODESIC_TOOL_OPTIONS_H

#include <CGAL_ext/Geodesics_3/Geodesic_algorithm.h>

#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace geodesic_tool {

// ---------------------------------------------------------------------------------------------
// The options as given

/// Whether the tool was built with TBB, which the parallel solvers need.
#ifdef CGAL_LINKED_WITH_TBB
inline constexpr bool parallel_available = true;
#else
inline constexpr bool parallel_available = false;
#endif

/// The solver of `distances` and `sample` when none is asked for: the exact parallel one, which
/// gives the same distances for every number of threads (and on one thread costs a few percent
/// more than VTP), when the tool has TBB.
inline constexpr const char* default_vertex_solver = parallel_available ? "pvtp" : "vtp";

/// The solver options of both subcommands.
struct Solver_options
{
  std::string algorithm;
  std::optional<double> lambda; // distances only
  std::optional<int> threads;
  std::optional<long long> batch_size;
  double max_distance = std::numeric_limits<double>::infinity();
};

struct Distances_options
{
  std::string mesh;
  std::vector<std::string> sources;
  Solver_options solver{default_vertex_solver};
  std::string output;
  std::string labels; // nearest sources, when not empty
  bool stats = false;
};

struct Path_options
{
  std::string mesh;
  std::vector<std::string> sources;
  std::string target;
  Solver_options solver{default_vertex_solver};
  std::string output;
  bool stats = false;
};

/// The MESH argument of a sub-command.
void add_mesh_argument(CLI::App& cmd, std::string& mesh);

/// Declares the arguments the subcommands start with: the mesh and the sources (required).
void add_mesh_and_sources(CLI::App& cmd, std::string& mesh, std::vector<std::string>& sources);

/// Declares the subcommand `distances` of `app`, which fills `options`.
void add_distances_command(CLI::App& app, Distances_options& options);

/// Declares the subcommand `path` of `app`, which fills `options`.
void add_path_command(CLI::App& app, Path_options& options);

// ---------------------------------------------------------------------------------------------
// The solver

/// The solvers of the library, as named on the command line.
struct Algorithm
{
  const char* name;
  bool parallel;                        // CGAL::Parallel_tag
  bool approximate;                     // the named parameter approximation(lambda)
  CGAL_ext::Geodesic_algorithm library; // the named parameter algorithm()
};

inline const Algorithm algorithms[] = {
  {"vtp", false, false, CGAL_ext::VTP},      {"pvtp", true, false, CGAL_ext::VTP},
  {"avtp", false, true, CGAL_ext::VTP},      {"pavtp", true, true, CGAL_ext::VTP},
  {"fwp-mmp", false, false, CGAL_ext::FWP_MMP}, {"mmp", false, false, CGAL_ext::MMP},
  {"pmmp", true, false, CGAL_ext::FWP_MMP}};

/// Whether the solver is of the MMP family, which keeps every window on the edges: its batch is
/// of windows (not of lists) and it reports its store and queue in the statistics.
inline bool is_mmp_family(const Algorithm& a) { return a.library != CGAL_ext::VTP; }

constexpr double default_lambda = 8;
/// More threads than this are refused: TBB's arenas fail far below what an int holds.
constexpr int max_threads = 1024;

/// The validated choice of solver and its parameters.
struct Solver_choice
{
  const Algorithm* algorithm = &algorithms[0];
  double lambda = default_lambda; // approximate solvers only
  int threads = 0;                // parallel solvers only; 0: TBB's default
  std::size_t batch_size = CGAL_ext::default_batch_size;
  double max_distance = std::numeric_limits<double>::infinity();
  /// The library's `callback`: told the fraction done, false cancels (the tool shows its own
  /// progress lines without one; the Python module passes Ctrl-C and the caller's callback).
  std::function<bool(double)> callback;
};

/// Checks the solver options of `distances`, or of `path` and `voronoi` (`exact_only`: every
/// solver but the approximate ones; their windows are read anywhere on the surface).
Solver_choice solver_choice(const Solver_options& options, bool exact_only);

// ---------------------------------------------------------------------------------------------
// Sources and targets

/// A source or a target as written on the command line: a vertex id, or a face id and
/// barycentric coordinates in the order of the face's vertices in the file.
struct Surface_point
{
  std::string text;
  std::optional<std::size_t> vertex;
  std::size_t face = 0;
  std::array<double, 3> barycentric{{0., 0., 0.}};
};

/// `role` ("source" or "target") names the point in error messages.
Surface_point parse_surface_point(const std::string& text, const char* role = "source");
/// Throws Tool_error, naming the point as written, unless its barycentric coordinates are
/// finite, non-negative and sum to 1 (within the library's tolerance).
void check_barycentric(const Surface_point& point, const char* role);

std::vector<Surface_point> parse_sources(const std::vector<std::string>& texts);

/// Checks the vertex or face id of `point` against a mesh of that many vertices and faces.
void check_surface_point_range(const Surface_point& point, std::size_t number_of_vertices,
                               std::size_t number_of_faces, const char* role = "source");

// ---------------------------------------------------------------------------------------------
// Output files

enum class Output_format { txt, obj, ply };

/// The format of an output file, by its extension; .obj only where `obj_allowed` (paths).
Output_format output_format(const std::string& path, bool obj_allowed = false);

/// Throws Tool_error when two of the output files (option name, path; an empty path is the
/// standard output, or no file) name the same file.
void check_distinct_outputs(const std::vector<std::pair<std::string, std::string>>& outputs);

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_OPTIONS_H
