// Copyright (c) 2026 The CGAL_ext geodesics developers.
// The applications of the Python `Mesh`: geodesic Voronoi diagrams, farthest-point sampling and
// repetitive pattern detection, their results as dictionaries of NumPy arrays.

#include "python_support.h"

#include "tool_error.h"
#include "tool_patterns.h"
#include "tool_solvers.h"

#include <cmath>

namespace cgal_ext_python {

using geodesic_tool::Tool_error;

namespace {

typedef std::shared_ptr<Python_mesh> Mesh_ptr;

/// Pairs or triples of ids as an (k, N) int64 array.
template <class Tuples>
py::array_t<long long> ids_array(const Tuples& tuples, py::ssize_t width)
{
  std::vector<long long> ids;
  for(const auto& t : tuples) {
    if constexpr(std::is_same<std::decay_t<decltype(t)>, std::pair<std::size_t, std::size_t>>::value) {
      ids.push_back(static_cast<long long>(t.first));
      ids.push_back(static_cast<long long>(t.second));
    } else {
      for(std::size_t id : t)
        ids.push_back(static_cast<long long>(id));
    }
  }
  const py::ssize_t rows = py::ssize_t(ids.size()) / width;
  return to_array(std::move(ids), {rows, width});
}

template <class T>
py::array_t<long long> int64_array(const std::vector<T>& values)
{
  return to_array(std::vector<long long>(values.begin(), values.end()));
}

py::dict voronoi(const Mesh_ptr& mesh, py::handle sources, const std::optional<std::string>& algorithm,
                 std::optional<int> threads,
                 py::object progress)
{
  geodesic_tool::Solver_choice choice = solver_choice(algorithm, threads, std::nullopt, std::nullopt, true);
  const std::vector<Surface_point> points = read_points(*mesh, sources, "source");
  if(points.empty())
    throw Tool_error("no source was given");
  Python_callback callback(std::move(progress));
  choice.callback = callback.function();
  geodesic_tool::Voronoi_result r =
    without_gil(callback, [&] { return geodesic_tool::compute_voronoi(mesh->file, points, choice); });
  py::list bisectors, vertex_sources;
  for(const auto& b : r.bisectors) {
    py::dict curve;
    curve["sources"] = py::make_tuple(b.first_source, b.second_source);
    curve["points"] = points_array(b.points);
    bisectors.append(curve);
  }
  for(const auto& s : r.vertex_sources)
    vertex_sources.append(py::tuple(py::cast(s)));
  py::dict d;
  d["cells"] = int64_array(r.cells);
  d["distances"] = to_array(std::move(r.distances));
  d["bisectors"] = bisectors;
  d["vertices"] = points_array(r.vertex_points);
  d["vertex_sources"] = vertex_sources;
  d["dual_edges"] = ids_array(r.dual_edges, 2);
  d["dual_triangles"] = ids_array(r.dual_triangles, 3);
  d["unresolved_parts"] = r.unresolved_parts;
  return d;
}

py::dict farthest_point_sampling(const Mesh_ptr& mesh, std::size_t count, std::optional<double> radius,
                                 py::handle first, std::optional<int> threads, std::optional<double> lam,
                                 py::object progress)
{
  geodesic_tool::Solver_choice choice = vtp_family_choice(threads, lam, std::nullopt);
  geodesic_tool::Sampling_request request;
  request.count = count;
  if(radius) {
    if(!(*radius > 0) || !std::isfinite(*radius))
      throw Tool_error("radius must be a positive number, got " + std::to_string(*radius));
    request.radius = *radius;
  }
  if(!first.is_none())
    request.first = read_vertex_ids(*mesh, first, "first sample");
  Python_callback callback(std::move(progress));
  choice.callback = callback.function();
  geodesic_tool::Sampling_result r =
    without_gil(callback, [&] { return geodesic_tool::compute_samples(mesh->file, request, choice); });
  py::dict d;
  d["samples"] = int64_array(r.samples);
  d["radii"] = to_array(std::move(r.radii));
  d["distances"] = to_array(std::move(r.distances));
  d["nearest_samples"] = int64_array(r.labels);
  return d;
}

py::dict detect_patterns(const Mesh_ptr& mesh, py::handle center, std::optional<double> radius, py::handle vertices,
                         std::optional<std::pair<double, double>> scales, py::handle stroke, double sample_spacing,
                         double match_tolerance, double consistency_cutoff, std::optional<double> lam,
                         std::optional<int> threads, py::object progress)
{
  typedef CGAL_ext::Pattern_patch<geodesic_tool::Mesh> Patch;
  const Mesh_file& file = mesh->file;
  Patch patch;
  if(!center.is_none()) {
    if(!vertices.is_none())
      throw Tool_error("mark the pattern with center and radius, or with vertices, not both");
    if(!radius || !(*radius > 0) || !std::isfinite(*radius))
      throw Tool_error("radius: the marked instance's geodesic radius, a positive number, is needed with center");
    const std::vector<std::size_t> c = read_vertex_ids(*mesh, center, "center");
    if(c.size() != 1)
      throw Tool_error("center: one vertex id");
    patch = Patch::disk(file.vertex_of_point[c[0]], *radius);
  } else if(!vertices.is_none()) {
    std::vector<geodesic_tool::Vertex_index> marked;
    for(std::size_t id : read_vertex_ids(*mesh, vertices, "marked vertex"))
      marked.push_back(file.vertex_of_point[id]);
    patch = Patch::of_vertices(marked);
  } else {
    throw Tool_error("mark the pattern: center=vertex and radius=r, or vertices=[ids]");
  }
  std::vector<geodesic_tool::Vertex_index> stroke_vertices;
  if(!stroke.is_none())
    for(std::size_t id : read_vertex_ids(*mesh, stroke, "stroke vertex"))
      stroke_vertices.push_back(file.vertex_of_point[id]);
  check_threads(threads);
  if(lam && !(*lam > 0))
    throw Tool_error("lam must be a positive number, got " + std::to_string(*lam));
  geodesic_tool::Patterns_options options;
  options.sample_spacing = sample_spacing;
  options.match_tolerance = match_tolerance;
  options.consistency_cutoff = consistency_cutoff;
  options.lambda = lam ? *lam : 0.;
  options.threads = threads ? *threads : 0;
  const std::pair<double, double> scale_range = scales ? *scales : std::make_pair(1.0, 1.0);
  Python_callback callback(std::move(progress));
  const geodesic_tool::Patterns_found found = without_gil(callback, [&] {
    return geodesic_tool::detect_patterns(file, patch, options, scale_range, stroke_vertices, callback.function());
  });
  py::list instances;
  for(const geodesic_tool::Found_instance& f : found.instances) {
    py::dict instance;
    instance["center"] = points_array(std::vector<geodesic_tool::Point>{f.center}).attr("reshape")(3);
    instance["center_vertex"] = f.center_vertex;
    instance["scale"] = f.scale;
    instance["energy"] = f.energy;
    instance["vertices"] = int64_array(f.vertices);
    instance["correspondence"] = ids_array(f.correspondence, 2);
    instances.append(instance);
  }
  py::dict d;
  d["instances"] = instances;
  d["labels"] = int64_array(found.labels);
  d["arrangement_edges"] = ids_array(found.edges, 2);
  d["arrangement_triangles"] = ids_array(found.triangles, 3);
  return d;
}

} // namespace

void bind_applications(py::module_& m)
{
  m.def("_voronoi", &voronoi, py::arg("mesh"), py::arg("sources"), py::arg("algorithm") = py::none(),
        py::arg("threads") = py::none(), py::arg("progress") = py::none(),
        "The geodesic Voronoi diagram as a dict of arrays; see cgal_ext_geodesics.Mesh.voronoi.");
  m.def("_farthest_point_sampling", &farthest_point_sampling, py::arg("mesh"), py::arg("count"),
        py::arg("radius") = py::none(), py::arg("first") = py::none(), py::arg("threads") = py::none(),
        py::arg("lam") = py::none(), py::arg("progress") = py::none(),
        "Farthest-point samples as a dict of arrays; see cgal_ext_geodesics.Mesh.farthest_point_sampling.");
  m.def("_detect_patterns", &detect_patterns, py::arg("mesh"), py::arg("center") = py::none(),
        py::arg("radius") = py::none(), py::arg("vertices") = py::none(), py::arg("scales") = py::none(),
        py::arg("stroke") = py::none(), py::arg("sample_spacing") = 1.0 / 3, py::arg("match_tolerance") = 0.35,
        py::arg("consistency_cutoff") = 0.7, py::arg("lam") = py::none(), py::arg("threads") = py::none(),
        py::arg("progress") = py::none(),
        "Instances of a repetitive pattern as a dict; see cgal_ext_geodesics.Mesh.detect_patterns.");
}

} // namespace cgal_ext_python
