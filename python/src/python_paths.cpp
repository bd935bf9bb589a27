// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The Python `GeodesicPaths`: the exact windows from a set of sources, built once, then
// distances, nearest sources and shortest paths to any vertex or face point.

#include "python_support.h"

#include "tool_error.h"
#include "tool_solvers.h"
#include "tool_threads.h"

#include <CGAL_ext/Surface_mesh_geodesic_paths.h>

#include <CGAL/boost/graph/iterator.h>

#include <cmath>
#include <limits>

namespace cgal_ext_python {

using geodesic_tool::Face_index;
using geodesic_tool::Face_location;
using geodesic_tool::Mesh;
using geodesic_tool::Vertex_index;

namespace {

typedef std::shared_ptr<Python_mesh> Mesh_ptr;

#ifdef CGAL_LINKED_WITH_TBB
typedef CGAL::Parallel_tag Parallel_tag;
#else
typedef CGAL::Sequential_tag Parallel_tag; // solver_choice() never chooses a parallel solver then
#endif

/// A point of a path as an input face and barycentric coordinates in the order of its vertices:
/// the inverse of the tool's `library_location`, for the faces that are input triangles.
class Input_faces
{
public:
  explicit Input_faces(const Mesh_file& file) : m_file(file), m_polygon_of_face(file.mesh.number_of_faces(), -1)
  {
    for(std::size_t p = 0; p < file.face_of_polygon.size(); ++p)
      if(file.face_of_polygon[p] != Mesh::null_face())
        m_polygon_of_face[file.face_of_polygon[p].idx()] = static_cast<long long>(p);
  }

  /// (face, barycentric) of the input; face -1 and NaN coordinates where the mesh face is not an
  /// input triangle (a part of a triangulated polygon).
  std::pair<long long, std::array<double, 3>> location(const Face_location& l) const
  {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const long long p = m_polygon_of_face[l.first.idx()];
    if(p < 0)
      return {-1, {{nan, nan, nan}}};
    const std::array<int, 3> point_of_corner = geodesic_tool::polygon_corners(m_file, std::size_t(p), l.first);
    std::array<double, 3> b{{0., 0., 0.}};
    for(std::size_t c = 0; c < 3; ++c)
      if(point_of_corner[c] >= 0)
        b[std::size_t(point_of_corner[c])] = l.second[c];
    return {p, b};
  }

private:
  const Mesh_file& m_file;
  std::vector<long long> m_polygon_of_face;
};

/// The queries of the paths object, whichever concurrency it was built with.
class Paths_queries
{
public:
  virtual ~Paths_queries() = default;
  virtual double distance(const Surface_point& target) const = 0;
  virtual long long nearest_source(const Surface_point& target) const = 0;
  virtual void distances(double* out) const = 0;
  virtual void nearest_sources(long long* out) const = 0;
  /// The points of the path and where each lies, as face locations of the mesh.
  virtual void path(const Surface_point& target, std::vector<geodesic_tool::Point>& points,
                    std::vector<Face_location>& locations) const = 0;
};

template <class ConcurrencyTag>
class Paths_of : public Paths_queries
{
  typedef CGAL_ext::Surface_mesh_geodesic_paths<Mesh, ConcurrencyTag> Paths;

public:
  Paths_of(const Mesh_file& file, const std::vector<Surface_point>& sources,
           const geodesic_tool::Solver_choice& choice)
    : m_file(file), m_paths(file.mesh, CGAL_ext::parameters::glued_vertices(file.glued_vertices))
  {
    for(const Surface_point& s : sources)
      with_point(s, "source", [&](const auto& p) { m_paths.add_source(p); });
    m_paths.build(CGAL_ext::parameters::max_distance(choice.max_distance)
                    .callback(choice.callback)
                    .batch_size(choice.batch_size)
                    .number_of_threads(choice.threads)
                    .algorithm(choice.algorithm->library));
  }

  double distance(const Surface_point& target) const override
  {
    double d = 0;
    with_point(target, "target", [&](const auto& p) { d = m_paths.distance(p); });
    return d;
  }
  long long nearest_source(const Surface_point& target) const override
  {
    std::size_t s = 0;
    with_point(target, "target", [&](const auto& p) { s = m_paths.nearest_source(p); });
    return s == Paths::no_source ? -1 : static_cast<long long>(s);
  }
  void distances(double* out) const override
  {
    std::vector<double> by_vertex(m_file.mesh.number_of_vertices());
    m_paths.vertex_distances(CGAL::make_property_map(by_vertex));
    std::size_t p = 0;
    for(Vertex_index v : m_file.vertex_of_point)
      out[p++] = by_vertex[v.idx()];
  }
  void nearest_sources(long long* out) const override
  {
    std::vector<long long> by_vertex(m_file.mesh.number_of_vertices());
    m_paths.vertex_sources(CGAL::make_property_map(by_vertex));
    std::size_t p = 0;
    for(Vertex_index v : m_file.vertex_of_point)
      out[p++] = by_vertex[v.idx()];
  }
  void path(const Surface_point& target, std::vector<geodesic_tool::Point>& points,
            std::vector<Face_location>& locations) const override
  {
    std::vector<typename Paths::Path_point> path;
    with_point(target, "target", [&](const auto& p) { m_paths.shortest_path_surface_points(p, std::back_inserter(path)); });
    for(const auto& p : path) {
      points.push_back(p.point);
      locations.push_back(face_location(p));
    }
  }

private:
  template <class Function>
  void with_point(const Surface_point& s, const char* role, Function f) const
  {
    if(s.vertex)
      f(geodesic_tool::mesh_vertex(m_file, s));
    else
      f(geodesic_tool::library_location(m_file, s, role));
  }

  /// A point of a path as a face and barycentric coordinates in the mesh's corner order.
  Face_location face_location(const typename Paths::Path_point& p) const
  {
    const Mesh& mesh = m_file.mesh;
    typedef typename Paths::Path_point Point;
    if(p.kind == Point::FACE)
      return Face_location(p.face, {{p.barycentric[0], p.barycentric[1], p.barycentric[2]}});
    auto h = p.kind == Point::EDGE ? p.halfedge : mesh.halfedge(p.vertex);
    double t = p.kind == Point::EDGE ? double(p.t) : 1.; // at target(h)
    if(p.kind == Point::VERTEX) {
      for(auto g : CGAL::halfedges_around_target(p.vertex, mesh))
        if(!mesh.is_border(g)) {
          h = g;
          break;
        }
    }
    if(mesh.is_border(h)) {
      h = mesh.opposite(h);
      t = 1 - t;
    }
    if(mesh.is_border(h)) // an isolated vertex: no face
      return Face_location(Face_index(), {{0., 0., 0.}});
    Face_location l(mesh.face(h), {{0., 0., 0.}});
    int k = 0;
    for(auto g : CGAL::halfedges_around_face(mesh.halfedge(l.first), mesh)) {
      if(mesh.source(g) == mesh.source(h))
        l.second[std::size_t(k)] = 1 - t;
      else if(mesh.source(g) == mesh.target(h))
        l.second[std::size_t(k)] = t;
      ++k;
    }
    return l;
  }

  const Mesh_file& m_file;
  Paths m_paths;
};

/// The Python object: the mesh it was built on (kept alive), the sources, the windows.
struct Python_paths
{
  Mesh_ptr mesh;
  std::size_t number_of_sources = 0;
  std::unique_ptr<Paths_queries> queries;
  std::unique_ptr<Input_faces> input_faces;

  /// The path to `target` (read with the GIL held), its points and their face locations, traced
  /// without the GIL; `also(locations)` runs there too.
  template <class Also>
  std::vector<geodesic_tool::Point> path(py::handle target, Also also) const
  {
    const Surface_point t = read_point(*mesh, target, "target");
    std::vector<geodesic_tool::Point> points;
    std::vector<Face_location> locations;
    py::gil_scoped_release release;
    queries->path(t, points, locations);
    also(locations);
    return points;
  }
};

std::shared_ptr<Python_paths> make_paths(const Mesh_ptr& mesh, py::handle sources,
                                         const std::optional<std::string>& algorithm,
                                         std::optional<int> threads, std::optional<double> max_distance,
                                         py::object progress)
{
  geodesic_tool::Solver_choice choice = solver_choice(algorithm, threads, std::nullopt, max_distance, true);
  const std::vector<Surface_point> points = read_points(*mesh, sources, "source");
  if(points.empty())
    throw geodesic_tool::Tool_error("no source was given");
  auto paths = std::make_shared<Python_paths>();
  paths->mesh = mesh;
  paths->number_of_sources = points.size();
  Python_callback callback(std::move(progress));
  choice.callback = callback.function();
  without_gil(callback, [&] {
    geodesic_tool::check_a_source_is_on_a_face(mesh->file, points);
    if(choice.algorithm->parallel)
      paths->queries = std::make_unique<Paths_of<Parallel_tag>>(mesh->file, points, choice);
    else
      paths->queries = std::make_unique<Paths_of<CGAL::Sequential_tag>>(mesh->file, points, choice);
    paths->input_faces = std::make_unique<Input_faces>(mesh->file);
  });
  return paths;
}

/// A query of one target (a vertex id or a face point), answered without the GIL.
template <class Result>
auto target_query(Result (Paths_queries::*query)(const Surface_point&) const)
{
  return [query](const Python_paths& p, py::handle target) {
    const Surface_point t = read_point(*p.mesh, target, "target");
    py::gil_scoped_release release;
    return (p.queries.get()->*query)(t);
  };
}

} // namespace

void bind_paths(py::module_& m)
{
  py::class_<Python_paths, std::shared_ptr<Python_paths>>(m, "GeodesicPaths", R"doc(
Exact shortest paths from a set of sources, built once and queried many times.

GeodesicPaths(mesh, sources, algorithm=None, threads=None, max_distance=None,
progress=None) keeps the windows of an exact propagation ('pvtp', the default,
'vtp', 'pmmp', 'fwp_mmp' or 'mmp', as for Mesh.distances); then the distance, the nearest source and the shortest path of any
vertex or face point are queries. Targets are vertex ids or face points
``(face, (b0, b1, b2))``, as sources are.
)doc")
    .def(py::init(&make_paths), py::arg("mesh"), py::arg("sources"), py::arg("algorithm") = py::none(),
         py::arg("threads") = py::none(), py::arg("max_distance") = py::none(), py::arg("progress") = py::none(),
         "GeodesicPaths(mesh, sources, algorithm=None, threads=None, max_distance=None, progress=None): one exact "
         "propagation from the sources (vertex ids or face points), whose windows answer every later query.")
    .def_property_readonly(
      "n_sources", [](const Python_paths& p) { return p.number_of_sources; }, "The number of sources.")
    .def_property_readonly(
      "mesh", [](const Python_paths& p) { return p.mesh; }, "The mesh the paths were built on.")
    .def(
      "distance", target_query(&Paths_queries::distance), py::arg("target"), "The geodesic distance from the nearest source to a vertex or face point (inf if none reaches it).")
    .def(
      "nearest_source", target_query(&Paths_queries::nearest_source), py::arg("target"), "The index of the nearest source of a vertex or face point, in the order given; -1 if none reaches it.")
    .def(
      "distances",
      [](const Python_paths& p) {
        py::array_t<double> out(py::ssize_t(p.mesh->number_of_points()));
        double* d = out.mutable_data();
        py::gil_scoped_release release;
        p.queries->distances(d);
        return out;
      },
      "The distance of every vertex, (n,) float64.")
    .def(
      "nearest_sources",
      [](const Python_paths& p) {
        py::array_t<long long> out(py::ssize_t(p.mesh->number_of_points()));
        long long* s = out.mutable_data();
        py::gil_scoped_release release;
        p.queries->nearest_sources(s);
        return out;
      },
      "The nearest source of every vertex, (n,) int64, -1 where none reaches.")
    .def(
      "path",
      [](const Python_paths& p, py::handle target) {
        return points_array(p.path(target, [](const std::vector<Face_location>&) {}));
      },
      py::arg("target"),
      "The shortest path from the nearest source to a vertex or face point, (k, 3) float64, the source first; "
      "empty when no source reaches the target.")
    .def(
      "path_locations",
      [](const Python_paths& p, py::handle target) {
        std::vector<long long> faces;
        std::vector<double> barycentric;
        p.path(target, [&](const std::vector<Face_location>& locations) {
          for(const Face_location& l : locations) {
            const auto [face, b] = l.first == Face_index() ? std::make_pair(-1LL, std::array<double, 3>{{0., 0., 0.}})
                                                           : p.input_faces->location(l);
            faces.push_back(face);
            barycentric.insert(barycentric.end(), b.begin(), b.end());
          }
        });
        const py::ssize_t k = py::ssize_t(faces.size());
        return py::make_tuple(to_array(std::move(faces)), to_array(std::move(barycentric), {k, 3}));
      },
      py::arg("target"), R"doc(
The shortest path as face points of the input: (faces (k,) int64, barycentric
(k, 3) float64), barycentric coordinates in the order of each face's vertices.
A point on an edge or at a vertex is given in one of its faces. Where the face
is part of a polygon the input did not give as a triangle, the face is -1 and
the coordinates NaN (the point itself is in `path`).
)doc");
}

} // namespace cgal_ext_python
