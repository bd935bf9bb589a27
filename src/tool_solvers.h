// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The library called for the geodesic tool: distances to every vertex, and a shortest path,
// with the chosen solver, from the sources and the target as written on the command line.

#ifndef GEODESIC_TOOL_SOLVERS_H
#define GEODESIC_TOOL_SOLVERS_H

#include "tool_mesh.h"
#include "tool_options.h"

#include <CGAL_ext/Geodesics_3/Geodesic_statistics.h>

#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace geodesic_tool {

/// The vertex of the mesh of a vertex id of the file.
Vertex_index mesh_vertex(const Mesh_file& file, const Surface_point& s);

/// Which of the 3 points of triangle `polygon` of the file (0, 1, 2) is each corner of face `f`
/// of the mesh made of it, in the mesh's order of the corners; -1 for none.
std::array<int, 3> polygon_corners(const Mesh_file& file, std::size_t polygon, Face_index f);

/// A face point of the file (barycentric coordinates in the file's order of the face's
/// vertices) in the library's order of the corners of its face of the mesh; throws Tool_error,
/// naming `role`, when the face is not a triangle of the mesh.
Face_location library_location(const Mesh_file& file, const Surface_point& s, const char* role);

/// A vertex source as a corner of one of its faces, so that it can join face-point sources;
/// throws Tool_error for a vertex in no face.
Face_location vertex_location(const Mesh_file& file, const Surface_point& s);

/// Throws Tool_error when every source is a vertex in no face: no other vertex would be reached.
void check_a_source_is_on_a_face(const Mesh_file& file, const std::vector<Surface_point>& sources);

/// The number of threads a parallel solver runs on.
int effective_threads(const Solver_choice& choice);

/// Runs the library; returns the distance of each point of the file (merged points share theirs)
/// and, unless `nearest_source` is null, fills it with the index of each point's nearest source
/// (-1 where none reaches). Throws Tool_error when a face point's face is not a triangle of the
/// mesh, or when every source is a vertex in no face.
std::vector<double> compute_distances(const Mesh_file& file, const std::vector<Surface_point>& sources,
                                      const Solver_choice& choice, CGAL_ext::Geodesic_statistics& stats,
                                      std::vector<long>* nearest_source);

/// A shortest path and what it took.
struct Path_result
{
  std::vector<Point> points;                                      // from the source to the target
  double distance = std::numeric_limits<double>::infinity();      // the library's distance of the target
  std::size_t nearest_source = 0;                                 // among the sources, in command-line order
  CGAL_ext::Geodesic_statistics stats;
  double seconds_build = 0; // preparing the mesh, adding the sources and building the windows
  double seconds_query = 0; // the distance, the nearest source and the path of the target
};

/// Builds the windows from `sources` with the chosen MMP solver and traces the path to `target`;
/// throws Tool_error if no source reaches the target, or for a face point as compute_distances().
Path_result trace_path(const Mesh_file& file, const std::vector<Surface_point>& sources,
                       const Surface_point& target, const Solver_choice& choice);

/// The distances from each source alone to every point of the file (file order), one row per
/// source handed to `row` in the order of `sources`; the sources are solved in parallel on
/// `threads` threads (0: all cores).
void compute_distance_rows(const Mesh_file& file, const std::vector<Surface_point>& sources, double max_distance,
                           int threads, const std::function<void(std::size_t, const std::vector<double>&)>& row);

/// The same within `max_distance` (finite), each row sparse: the pairs (mesh vertex index,
/// distance) of the vertices reached, by increasing index; a row costs what its propagation
/// sweeps, not the size of the mesh.
void compute_sparse_distance_rows(
  const Mesh_file& file, const std::vector<Surface_point>& sources, double max_distance, int threads,
  const std::function<void(std::size_t, const std::vector<std::pair<std::size_t, double>>&)>& row);

/// The point of the file of each vertex of the mesh (of merged points the first; a copy the
/// repair made of a point: that point).
std::vector<std::size_t> point_of_vertex(const Mesh_file& file);

/// What `geodesic sample` asks for.
struct Sampling_request
{
  std::size_t count = 0;            // at most this many samples, at least 1
  double radius = 0;                // stop once every vertex is this close to a sample; 0: none
  std::vector<std::size_t> first;   // the first sample, or the initial samples, points of the file
};

/// Farthest-point samples, as points of the file, with the covering radius after each, and the
/// distance and nearest sample of each point of the file.
struct Sampling_result
{
  std::vector<std::size_t> samples;
  std::vector<double> radii;
  std::vector<double> distances;
  std::vector<long> labels;
  CGAL_ext::Geodesic_statistics stats;
};

/// Runs the library's farthest_point_sampling (the VTP family of `choice`), with a progress line.
Sampling_result compute_samples(const Mesh_file& file, const Sampling_request& request, const Solver_choice& choice);

/// The geodesic Voronoi diagram of the sources, in the file's terms.
struct Voronoi_result
{
  std::vector<long> cells;       // per point of the file: its nearest source, -1 if none
  std::vector<double> distances; // per point of the file
  struct Curve
  {
    std::size_t first_source, second_source;
    std::vector<Point> points;
  };
  std::vector<Curve> bisectors;
  std::vector<Point> vertex_points;
  std::vector<std::vector<std::size_t>> vertex_sources;
  std::vector<std::pair<std::size_t, std::size_t>> dual_edges;
  std::vector<std::array<std::size_t, 3>> dual_triangles;
  std::size_t unresolved_parts = 0;
};

/// Runs the library's geodesic_voronoi_diagram with the chosen MMP solver.
Voronoi_result compute_voronoi(const Mesh_file& file, const std::vector<Surface_point>& sources,
                               const Solver_choice& choice);

/// The position of a source or target in space (a vertex's point, or the face point's).
Point surface_point_position(const Mesh_file& file, const Surface_point& s);

} // namespace geodesic_tool

#endif // GEODESIC_TOOL_SOLVERS_H
