// Copyright (c) 2026 The CGAL_ext geodesics developers.

#include "tool_solvers.h"

#include "tool_error.h"
#include "tool_stats.h"
#include "tool_text.h"
#include "tool_threads.h"

#include <CGAL_ext/Surface_mesh_geodesic_paths.h>
#include <CGAL_ext/farthest_point_sampling.h>
#include <CGAL_ext/geodesic_distance_matrix.h>
#include <CGAL_ext/geodesic_distances.h>
#include <CGAL_ext/geodesic_voronoi_diagram.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

#include <boost/iterator/function_output_iterator.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <iterator>
#include <optional>

namespace geodesic_tool {

namespace {

const double infinity = std::numeric_limits<double>::infinity();
typedef decltype(CGAL::make_property_map(std::declval<std::vector<double>&>())) Distance_map;
/// The nearest source of each vertex, by vertex index, where the caller wants it; nothing
/// otherwise (a map per vertex less during the solve), with one instantiation of the library
/// call for both.
struct Label_map
{
  typedef Vertex_index key_type;
  typedef long value_type;
  typedef long reference;
  typedef boost::writable_property_map_tag category;
  std::vector<long>* labels = nullptr;
  friend void put(const Label_map& map, Vertex_index v, long label)
  {
    if(map.labels)
      (*map.labels)[v.idx()] = label;
  }
};

#ifdef CGAL_LINKED_WITH_TBB
typedef CGAL::Parallel_tag Parallel_tag;
#else
typedef CGAL::Sequential_tag Parallel_tag; // never run: solver_choice() refuses the parallel solvers
#endif

} // namespace

/// The vertex of the mesh of a vertex id of the file.
Vertex_index mesh_vertex(const Mesh_file& file, const Surface_point& s) { return file.vertex_of_point[*s.vertex]; }

std::array<int, 3> polygon_corners(const Mesh_file& file, std::size_t polygon_id, Face_index f)
{
  // The face may start at another corner, and run the other way if the face was reversed to
  // orient the surface. Its corners are the polygon's points' vertices, or copies of them (made
  // at non-manifold points), found then by position.
  const Polygons::Polygon polygon = file.soup.polygons[polygon_id];
  std::array<Vertex_index, 3> corners;
  int k = 0;
  for(auto h : CGAL::halfedges_around_face(file.mesh.halfedge(f), file.mesh))
    corners[std::size_t(k++)] = file.mesh.source(h);
  std::array<int, 3> point_of_corner{{-1, -1, -1}};
  std::array<bool, 3> taken{{false, false, false}};
  for(int pass = 0; pass < 2; ++pass)
    for(std::size_t c = 0; c < 3; ++c)
      for(std::size_t j = 0; j < 3 && point_of_corner[c] < 0; ++j) {
        const bool same = pass == 0 ? file.vertex_of_point[polygon[j]] == corners[c]
                                    : file.soup.points[polygon[j]] == file.mesh.point(corners[c]);
        if(!taken[j] && same) {
          point_of_corner[c] = int(j);
          taken[j] = true;
        }
      }
  return point_of_corner;
}

/// A face point of the command line (barycentric coordinates in the file's order of the face's
/// vertices) in the library's order of the corners of its face of the mesh.
Face_location library_location(const Mesh_file& file, const Surface_point& s, const char* role)
{
  const Face_index f = file.face_of_polygon[s.face];
  const Polygons::Polygon polygon = file.soup.polygons[s.face];
  if(f == Mesh::null_face())
    throw Tool_error(std::string(role) + " '" + s.text + "': face " + std::to_string(s.face) +
                     " of the file is not a triangle of the surface (" +
                     (polygon.size() == 3 ? std::string("its 3 vertices are not distinct points")
                                          : "it has " + std::to_string(polygon.size()) + " vertices") +
                     ")");
  const std::array<int, 3> point_of_corner = polygon_corners(file, s.face, f);
  Face_location location(f, {{0., 0., 0.}});
  for(std::size_t c = 0; c < 3; ++c)
    location.second[c] = point_of_corner[c] >= 0 ? s.barycentric[std::size_t(point_of_corner[c])] : 0.;
  return location;
}

/// A vertex source as a corner of one of its faces, so that it can join face-point sources.
Face_location vertex_location(const Mesh_file& file, const Surface_point& s)
{
  const Mesh& mesh = file.mesh;
  const Vertex_index v = mesh_vertex(file, s);
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

/// A source or target in the library's terms: a vertex, or a face location.
template <class Function>
void with_library_point(const Mesh_file& file, const Surface_point& s, const char* role, Function f)
{
  if(s.vertex)
    f(mesh_vertex(file, s));
  else
    f(library_location(file, s, role));
}

/// Throws Tool_error when every source is a vertex in no face: no other vertex would be reached.
void check_a_source_is_on_a_face(const Mesh_file& file, const std::vector<Surface_point>& sources)
{
  for(const Surface_point& s : sources)
    if(!s.vertex || !file.mesh.is_isolated(mesh_vertex(file, s)))
      return;
  throw Tool_error(sources.size() == 1
                     ? "source '" + sources[0].text + "': vertex " + sources[0].text +
                         " is in no face of the mesh, so it reaches no other vertex"
                     : std::string("every source is a vertex in no face of the mesh, so they reach no other vertex"));
}

namespace {

/// Calls `f` with the sources as the library takes them: a range of one kind, vertices when all
/// are vertices, face locations otherwise (a vertex as a corner of one of its faces).
template <class Function>
void with_library_sources(const Mesh_file& file, const std::vector<Surface_point>& sources, Function f)
{
  if(std::all_of(sources.begin(), sources.end(), [](const Surface_point& s) { return bool(s.vertex); })) {
    std::vector<Vertex_index> vertices;
    for(const Surface_point& s : sources)
      vertices.push_back(mesh_vertex(file, s));
    f(vertices);
  } else {
    std::vector<Face_location> locations;
    for(const Surface_point& s : sources)
      locations.push_back(s.vertex ? vertex_location(file, s) : library_location(file, s, "source"));
    f(locations);
  }
}

/// Calls `f(tag, np)` with the concurrency tag of `choice` and its parameters added to `np`:
/// the threads, and `approximation`, a named parameter that is either present or absent (so it
/// is chosen here rather than given a neutral value).
template <class NamedParameters, class Function>
void with_solver(const Solver_choice& choice, const NamedParameters& np, Function f)
{
  const auto with_approximation = [&](auto tag, const auto& p) {
    if(choice.algorithm->approximate)
      f(tag, p.approximation(choice.lambda));
    else
      f(tag, p);
  };
  const auto batched = np.batch_size(choice.batch_size).callback(choice.callback);
  if(choice.algorithm->parallel) {
    const Thread_allowance allowance(choice.threads);
    with_approximation(Parallel_tag(), batched.number_of_threads(choice.threads));
  } else {
    with_approximation(CGAL::Sequential_tag(), batched);
  }
}

/// The one place that maps the algorithm choice to the library call.
template <class LibrarySources>
void solve(const Mesh_file& file, Distance_map distance, Label_map label, const LibrarySources& sources,
           const Solver_choice& choice, CGAL_ext::Geodesic_statistics& stats)
{
  const auto np = CGAL_ext::parameters::glued_vertices(file.glued_vertices)
                    .vertex_source_map(label)
                    .max_distance(choice.max_distance)
                    .statistics(stats)
                    .algorithm(choice.algorithm->library);
  with_solver(choice, np, [&](auto tag, const auto& p) {
    CGAL_ext::geodesic_distances<decltype(tag)>(file.mesh, distance, sources, p);
  });
}

template <class ConcurrencyTag>
Path_result trace_path_with(const Mesh_file& file, const std::vector<Surface_point>& sources,
                            const Surface_point& target, const Solver_choice& choice)
{
  typedef CGAL_ext::Surface_mesh_geodesic_paths<Mesh, ConcurrencyTag> Paths;
  Path_result result;
  const Stopwatch build_watch;
  Paths paths(file.mesh, CGAL_ext::parameters::glued_vertices(file.glued_vertices));
  for(const Surface_point& s : sources)
    with_library_point(file, s, "source", [&](const auto& point) { paths.add_source(point); });
  {
    const Thread_allowance allowance(choice.algorithm->parallel ? choice.threads : 0);
    paths.build(CGAL_ext::parameters::max_distance(choice.max_distance)
                  .callback(choice.callback)
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
  with_library_point(file, target, "target", query);
  result.seconds_query = query_watch.seconds();
  if(result.points.empty() || result.nearest_source >= sources.size())
    throw Tool_error("internal error: no path to target '" + target.text + "' at distance " +
                     number_text(result.distance) + "; please report it");
  return result;
}

} // namespace

int effective_threads(const Solver_choice& choice)
{
#ifdef CGAL_LINKED_WITH_TBB
  if(choice.threads == 0)
    return tbb::this_task_arena::max_concurrency(); // what the library's automatic arena gets
#endif
  return choice.threads;
}

std::vector<double> compute_distances(const Mesh_file& file, const std::vector<Surface_point>& sources,
                                      const Solver_choice& choice, CGAL_ext::Geodesic_statistics& stats,
                                      std::vector<long>* nearest_source)
{
  check_a_source_is_on_a_face(file, sources);
  const Mesh& mesh = file.mesh;
  std::vector<double> distance_of_vertex(mesh.num_vertices(), infinity);
  const Distance_map distance = CGAL::make_property_map(distance_of_vertex);
  std::vector<long> label_of_vertex(nearest_source ? mesh.num_vertices() : 0, -1);
  const Label_map label{nearest_source ? &label_of_vertex : nullptr};
  with_library_sources(file, sources, [&](const auto& library_sources) {
    solve(file, distance, label, library_sources, choice, stats);
  });
  std::vector<double> distance_of_point;
  distance_of_point.reserve(file.vertex_of_point.size());
  for(Vertex_index v : file.vertex_of_point)
    distance_of_point.push_back(distance_of_vertex[v.idx()]);
  if(nearest_source) {
    nearest_source->clear();
    for(Vertex_index v : file.vertex_of_point)
      nearest_source->push_back(label_of_vertex[v.idx()]);
  }
  return distance_of_point;
}

Path_result trace_path(const Mesh_file& file, const std::vector<Surface_point>& sources,
                       const Surface_point& target, const Solver_choice& choice)
{
  return choice.algorithm->parallel ? trace_path_with<Parallel_tag>(file, sources, target, choice)
                                    : trace_path_with<CGAL::Sequential_tag>(file, sources, target, choice);
}

namespace {

/// Calls `f(library_sources, np)` with the named parameters of the rows of a matrix, once the
/// sources are checked, on `threads` threads (0: all cores).
template <class Function>
void with_matrix_rows(const Mesh_file& file, const std::vector<Surface_point>& sources, double max_distance,
                      int threads, Function f)
{
  check_a_source_is_on_a_face(file, sources);
  const auto np = CGAL_ext::parameters::glued_vertices(file.glued_vertices)
                    .max_distance(max_distance)
                    .number_of_threads(threads);
  const Thread_allowance allowance(threads);
  with_library_sources(file, sources, [&](const auto& library_sources) { f(library_sources, np); });
}

} // namespace

void compute_distance_rows(const Mesh_file& file, const std::vector<Surface_point>& sources, double max_distance,
                           int threads, const std::function<void(std::size_t, const std::vector<double>&)>& row)
{
  std::vector<double> in_file_order(file.vertex_of_point.size());
  const auto to_file_order = [&](std::size_t i, const std::vector<double>& by_vertex) {
    for(std::size_t p = 0; p < in_file_order.size(); ++p)
      in_file_order[p] = by_vertex[file.vertex_of_point[p].idx()];
    row(i, in_file_order);
  };
  with_matrix_rows(file, sources, max_distance, threads, [&](const auto& library_sources, const auto& np) {
    CGAL_ext::geodesic_distance_rows<Parallel_tag>(file.mesh, library_sources, to_file_order, np);
  });
}

void compute_sparse_distance_rows(
  const Mesh_file& file, const std::vector<Surface_point>& sources, double max_distance, int threads,
  const std::function<void(std::size_t, const std::vector<std::pair<std::size_t, double>>&)>& row)
{
  with_matrix_rows(file, sources, max_distance, threads, [&](const auto& library_sources, const auto& np) {
    CGAL_ext::geodesic_sparse_distance_rows<Parallel_tag>(file.mesh, library_sources, row, np);
  });
}

std::vector<std::size_t> point_of_vertex(const Mesh_file& file)
{
  const std::size_t none = std::size_t(-1);
  std::vector<std::size_t> point(file.mesh.number_of_vertices(), none);
  for(std::size_t p = file.vertex_of_point.size(); p-- > 0;)
    point[file.vertex_of_point[p].idx()] = p;
  // the copies the repair made of a point: that point
  for(const std::vector<Vertex_index>& group : file.glued_vertices) {
    std::size_t p = none;
    for(Vertex_index v : group)
      p = std::min(p, point[v.idx()]);
    for(Vertex_index v : group)
      if(point[v.idx()] == none)
        point[v.idx()] = p;
  }
  return point;
}

Sampling_result compute_samples(const Mesh_file& file, const Sampling_request& request, const Solver_choice& choice)
{
  const std::vector<std::size_t> point = point_of_vertex(file);
  Sampling_result result;
  Progress_line progress;
  auto on_sample = boost::make_function_output_iterator([&](Vertex_index v) {
    result.samples.push_back(point[v.idx()]);
    if(!choice.callback)
      progress.show("sample", result.samples.size(), request.count);
  });
  const Mesh& mesh = file.mesh;
  auto distance = get(CGAL::dynamic_vertex_property_t<double>(), mesh);
  auto label = get(CGAL::dynamic_vertex_property_t<long>(), mesh);
  const auto np = CGAL_ext::parameters::glued_vertices(file.glued_vertices)
                    .vertex_distance_map(distance)
                    .vertex_source_map(label)
                    .covering_radius_output_iterator(std::back_inserter(result.radii))
                    .statistics(result.stats);
  const auto sample = [&](const auto& first_and_radius) {
    with_solver(choice, first_and_radius, [&](auto tag, const auto& p) {
      CGAL_ext::farthest_point_sampling<decltype(tag)>(mesh, request.count, on_sample, p);
    });
  };
  // `initial_samples` (one of them: the first sample) and `covering_radius` are present or absent
  const auto with_radius = [&](const auto& p) {
    if(request.radius > 0)
      sample(p.covering_radius(request.radius));
    else
      sample(p);
  };
  std::vector<Vertex_index> first;
  for(std::size_t point : request.first)
    first.push_back(file.vertex_of_point[point]);
  if(!first.empty())
    with_radius(np.initial_samples(first));
  else
    with_radius(np);
  progress.clear();
  for(Vertex_index v : file.vertex_of_point) {
    result.distances.push_back(get(distance, v));
    result.labels.push_back(get(label, v));
  }
  return result;
}

Voronoi_result compute_voronoi(const Mesh_file& file, const std::vector<Surface_point>& sources,
                               const Solver_choice& choice)
{
  check_a_source_is_on_a_face(file, sources);
  Voronoi_result result;
  std::vector<long> cell(file.mesh.number_of_vertices(), -1);
  std::vector<double> distance(file.mesh.number_of_vertices());
  const auto np = CGAL_ext::parameters::glued_vertices(file.glued_vertices)
                    .batch_size(choice.batch_size)
                    .callback(choice.callback)
                    .algorithm(choice.algorithm->library)
                    .vertex_source_map(CGAL::make_property_map(cell))
                    .vertex_distance_map(CGAL::make_property_map(distance));
  const auto take = [&](const auto& diagram) {
    for(Vertex_index v : file.vertex_of_point) {
      result.cells.push_back(cell[v.idx()]);
      result.distances.push_back(distance[v.idx()]);
    }
    for(const auto& b : diagram.bisectors) {
      Voronoi_result::Curve curve{b.first_source, b.second_source, {}};
      for(const auto& p : b.points)
        curve.points.push_back(p.point);
      result.bisectors.push_back(std::move(curve));
    }
    for(const auto& v : diagram.vertices) {
      result.vertex_points.push_back(v.point.point);
      result.vertex_sources.push_back(v.sources);
    }
    result.dual_edges = diagram.dual_edges;
    result.dual_triangles = diagram.dual_triangles;
    result.unresolved_parts = diagram.unresolved_parts;
  };
  with_library_sources(file, sources, [&](const auto& library_sources) {
    if(choice.algorithm->parallel) {
      const Thread_allowance allowance(choice.threads);
      take(CGAL_ext::geodesic_voronoi_diagram<Parallel_tag>(file.mesh, library_sources,
                                                            np.number_of_threads(choice.threads)));
    } else {
      take(CGAL_ext::geodesic_voronoi_diagram(file.mesh, library_sources, np));
    }
  });
  return result;
}

Point surface_point_position(const Mesh_file& file, const Surface_point& s)
{
  if(s.vertex)
    return file.soup.points[*s.vertex];
  const Polygons::Polygon polygon = file.soup.polygons[s.face];
  double x[3] = {0, 0, 0};
  for(std::size_t k = 0; k < 3; ++k)
    for(int i = 0; i < 3; ++i)
      x[i] += s.barycentric[k] * file.soup.points[polygon[k]][i];
  return Point(x[0], x[1], x[2]);
}

} // namespace geodesic_tool
